// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPlane.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

namespace
{
// A closed polyline, or several pieces that may chain into loops (a single open
// piece is not a 2D shape at all and gets the surface error).
bool LinesMayFormLoops(vtkPolyData* input)
{
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* lines = input->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(npts, ids);)
  {
    double a[3], b[3];
    if (npts >= 2)
    {
      input->GetPoint(ids[0], a);
      input->GetPoint(ids[npts - 1], b);
      if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2])
      {
        return true;
      }
    }
  }
  return input->GetNumberOfLines() >= 3;
}
}

bool vtkMedialPlane::IsPlanarLoops(vtkPolyData* input, double centre[3], double normal[3])
{
  if (!input || input->GetNumberOfPoints() < 3 || input->GetNumberOfStrips() > 0)
  {
    return false;
  }
  const bool lines = input->GetNumberOfLines() > 0, polygons = input->GetNumberOfPolys() > 0;
  if (lines == polygons)
  {
    return false; // nothing to sample, or a mixture that is neither loops nor a surface
  }
  const bool wantPlane = centre && normal;
  if (lines && !LinesMayFormLoops(input))
  {
    return false;
  }
  if (lines && !wantPlane)
  {
    return true; // vtkMedialPolygon::Build checks that they are coplanar
  }
  auto point = [input](vtkIdType i, double p[3]) { input->GetPoint(i, p); };
  const vtkIdType n = input->GetNumberOfPoints();
  double c[3], values[3], axes[3][3];
  FitPoints(n, point, c, values, axes);
  if (!std::isfinite(c[0] + c[1] + c[2]))
  {
    return false; // NaN or infinite coordinates: the 3D path names them
  }
  const double plane[3] = { axes[0][2], axes[1][2], axes[2][2] };
  if (wantPlane)
  {
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = c[k];
      normal[k] = plane[k];
    }
  }
  if (lines)
  {
    return true;
  }
  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double line[3] = { axes[0][0], axes[1][0], axes[2][0] };
  return MaxDistance(n, point, c, plane) <= 1e-6 * diagonal &&
    MaxDistanceFromLine(n, point, c, line) > 1e-6 * diagonal;
}
