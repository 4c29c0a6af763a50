// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the vtkMedialBallUnion tests: ball sets, the exact field, closedness.
#ifndef MedialBallUnionTestUtilities_h
#define MedialBallUnionTestUtilities_h

#include "MedialTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <array>
#include <limits>
#include <vector>

namespace medialtest
{
/// One ball: centre x, y, z and radius.
using BallSpec = std::array<double, 4>;

/// Points with a Radius array (no cells: the filter only needs points).
inline vtkSmartPointer<vtkPolyData> MakeBalls(const std::vector<BallSpec>& balls)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (const BallSpec& b : balls)
  {
    points->InsertNextPoint(b[0], b[1], b[2]);
    radius->InsertNextValue(b[3]);
  }
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(radius);
  return pd;
}

/// f(x) = min_i (|x - c_i| - r_i), by brute force.
inline double UnionField(const std::vector<BallSpec>& balls, const double x[3])
{
  double best = std::numeric_limits<double>::infinity();
  for (const BallSpec& b : balls)
  {
    const double dx = x[0] - b[0], dy = x[1] - b[1], dz = x[2] - b[2];
    best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz) - b[3]);
  }
  return best;
}

/// Number of boundary and non-manifold edges: 0 for a closed manifold surface.
inline vtkIdType OpenEdges(vtkPolyData* surface)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}
}

#endif
