// SPDX-License-Identifier: BSD-3-Clause
// Brute-force helpers of the sampling-strategy tests: the coverage gap of a surface
// point to the union of the output balls, and bit-for-bit comparison of two outputs.
#ifndef MedialStrategyTestUtilities_h
#define MedialStrategyTestUtilities_h

#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkMedialShapeSource.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"


namespace medialtest
{
/// A vtkMedialShapeSource shape (default settings), triangulated.
inline vtkSmartPointer<vtkPolyData> TriangulatedShape(int shape)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

/// min_i (|x - c_i| - r_i) over every ball of `balls`, by brute force.
inline double CoverageGap(vtkPolyData* balls, const double x[3])
{
  vtkDataArray* radius = balls->GetPointData()->GetArray("Radius");
  double best = HUGE_VAL;
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    double c[3];
    balls->GetPoint(i, c);
    const double d = std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
      (x[2] - c[2]) * (x[2] - c[2]));
    best = std::min(best, d - radius->GetTuple1(i));
  }
  return best;
}

/// Largest coverage gap over the vertices and centroids of a triangle surface.
inline double MaxFaceGap(vtkPolyData* triangles, vtkPolyData* balls)
{
  double worst = -HUGE_VAL;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = triangles->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    double centroid[3] = { 0, 0, 0 };
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double p[3];
      triangles->GetPoint(ids[k], p);
      worst = std::max(worst, CoverageGap(balls, p));
      for (int a = 0; a < 3; ++a)
      {
        centroid[a] += p[a] / npts;
      }
    }
    worst = std::max(worst, CoverageGap(balls, centroid));
  }
  return worst;
}

}

#endif
