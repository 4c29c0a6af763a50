// SPDX-License-Identifier: BSD-3-Clause
// Shared by the tree query tests (TestMedialRayWalk, TestMedialClosestPointWalk): a
// generated shape's triangle mesh and the box of its points.
#ifndef MedialTreeTestUtilities_h
#define MedialTreeTestUtilities_h

#include "vtkMedialShapeSource.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace medialtest
{
// vtkMedialShapeSource's `shape` at `resolution` as a mesh, and its points' box; false
// (with the mesh's error) when the mesh cannot be built.
inline bool BuildShapeMesh(
  int shape, int resolution, vtkMedialTriangleMesh& mesh, double lo[3], double hi[3], std::string& error)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->SetResolution(resolution);
  source->Update();
  if (!mesh.Build(source->GetOutput(), error))
  {
    return false;
  }
  std::fill(lo, lo + 3, HUGE_VAL);
  std::fill(hi, hi + 3, -HUGE_VAL);
  for (vtkIdType i = 0; i < mesh.GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], mesh.GetPoint(i)[k]);
      hi[k] = std::max(hi[k], mesh.GetPoint(i)[k]);
    }
  }
  return true;
}
}

#endif
