// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPlane.h"

#include "vtkMedialGeometry.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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

// True when some four of up to 64 evenly spread points span a tetrahedron wider than
// 4 * tolerance in every direction: then no plane has every point within tolerance of
// it (four points within t of a plane make a tetrahedron at most 2 t wide across it),
// the least-squares plane included. A tetrahedron's least width is its least height or
// the least distance between opposite edges: 3 V / (largest face) and 6 V / (largest
// |u x v| of opposite edges u, v). Costs nothing next to the fit, which a large 3D mesh
// (every sampler run checks whether its input is planar) otherwise pays twice.
template <class PointOf>
bool SurelyNotPlanar(vtkIdType n, PointOf&& point, double tolerance)
{
  namespace G = vtkMedialGeometry;
  const vtkIdType count = std::min<vtkIdType>(n, 64);
  std::vector<std::array<double, 3>> x(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    point(i * (n / count), x[i].data());
  }
  // A wide tetrahedron from the spread points: the farthest from the first, the
  // farthest from that line, the farthest from that plane.
  auto farthest = [&](auto measure) {
    vtkIdType best = 0;
    double bestValue = -1.0;
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double v = measure(x[i].data());
      if (v > bestValue)
      {
        bestValue = v;
        best = i;
      }
    }
    return x[best];
  };
  const std::array<double, 3> a = x[0];
  const std::array<double, 3> b = farthest([&](const double* q) { return G::Distance2(q, a.data()); });
  double ab[3];
  G::Sub(b.data(), a.data(), ab);
  const std::array<double, 3> c = farthest([&](const double* q) {
    double aq[3], cross[3];
    G::Sub(q, a.data(), aq);
    G::Cross(ab, aq, cross);
    return G::Dot(cross, cross);
  });
  double ac[3], normal[3];
  G::Sub(c.data(), a.data(), ac);
  G::Cross(ab, ac, normal);
  const std::array<double, 3> d = farthest([&](const double* q) {
    double aq[3];
    G::Sub(q, a.data(), aq);
    return std::fabs(G::Dot(normal, aq));
  });
  const double* v[4] = { a.data(), b.data(), c.data(), d.data() };
  double e[4][4][3];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      G::Sub(v[j], v[i], e[i][j]);
    }
  }
  double cross[3];
  G::Cross(e[0][1], e[0][2], cross);
  const double volume6 = std::fabs(G::Dot(cross, e[0][3])); // 6 V
  double largestFace2 = 0.0; // (2 area)^2
  const int faces[4][3] = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } };
  for (const auto& f : faces)
  {
    G::Cross(e[f[0]][f[1]], e[f[0]][f[2]], cross);
    largestFace2 = std::max(largestFace2, G::Dot(cross, cross));
  }
  double largestPair2 = 0.0; // |u x v|^2 of opposite edges
  const int pairs[3][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 } };
  for (const auto& p : pairs)
  {
    G::Cross(e[p[0]][p[1]], e[p[2]][p[3]], cross);
    largestPair2 = std::max(largestPair2, G::Dot(cross, cross));
  }
  // Heights 3 V / area = 6 V / (2 area); edge distances 6 V / |u x v|.
  const double largest = std::sqrt(std::max(largestFace2, largestPair2));
  return largest > 0.0 && volume6 > 4.0 * tolerance * largest * (1.0 + 1e-6);
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
  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) + (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  if (!wantPlane && !lines && SurelyNotPlanar(n, point, 1e-6 * diagonal))
  {
    return false;
  }
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
  const double line[3] = { axes[0][0], axes[1][0], axes[2][0] };
  return MaxDistance(n, point, c, plane) <= 1e-6 * diagonal &&
    MaxDistanceFromLine(n, point, c, line) > 1e-6 * diagonal;
}
