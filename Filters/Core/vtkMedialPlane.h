// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialPlane.h
 * @brief Internal: the plane fits of the engines, in one place.
 *
 *  - FitPoints: the least-squares plane of a point set (centroid, and the
 *    eigenvectors of the scatter matrix by vtkMath::Jacobi: the normal is the
 *    direction of least variance). Decides planarity: the 2D mode of the sampler
 *    (IsPlanarLoops), the dimension of vtkMedialBallUnion.
 *  - NewellNormal: the oriented normal of one closed loop (twice its vector area);
 *    vtkMedialPolygon takes its plane from its largest loop, so that a loop's
 *    winding survives.
 *  - MaxDistance, CanonicalSign and LeastAxis: the checks and conventions those
 *    share (a plane's distance test, a reproducible sign, the world axis from which
 *    in-plane axes are built).
 *  - IsPlanarLoops: whether vtkPolyData is planar loops (the 2D mode); the public
 *    vtkMedialAxisSampler::IsPlanarInput.
 *
 * Points are given by a callable point(i, x) that writes point i into x[3].
 */
#ifndef vtkMedialPlane_h
#define vtkMedialPlane_h

#include "vtkMath.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>

class vtkPolyData;

namespace vtkMedialPlane
{
/// Centroid, and the scatter matrix's eigenvalues (decreasing) and eigenvectors
/// (columns: axes[k][0] the major axis, axes[k][2] the normal) of points 0 .. n - 1.
template <class PointOf>
void FitPoints(vtkIdType n, PointOf&& point, double centroid[3], double values[3], double axes[3][3])
{
  centroid[0] = centroid[1] = centroid[2] = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    point(i, p);
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += p[k] / static_cast<double>(n);
    }
  }
  double cov[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    point(i, p);
    const double d[3] = { p[0] - centroid[0], p[1] - centroid[1], p[2] - centroid[2] };
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        cov[r][c] += d[r] * d[c];
      }
    }
  }
  double* rows[3] = { cov[0], cov[1], cov[2] };
  double* vectors[3] = { axes[0], axes[1], axes[2] };
  vtkMath::Jacobi(rows, values, vectors);
}

/// Largest measure(d) over points 0 .. n - 1, d being the point less `origin`.
template <class PointOf, class Measure>
double MaxOffset(vtkIdType n, PointOf&& point, const double origin[3], Measure&& measure)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    point(i, p);
    const double d[3] = { p[0] - origin[0], p[1] - origin[1], p[2] - origin[2] };
    worst = std::max(worst, measure(d));
  }
  return worst;
}

/// Largest distance of points 0 .. n - 1 from the plane through `origin` with unit `normal`.
template <class PointOf>
double MaxDistance(vtkIdType n, PointOf&& point, const double origin[3], const double normal[3])
{
  return MaxOffset(n, point, origin,
    [normal](const double d[3]) { return std::fabs(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]); });
}

/// Largest distance of points 0 .. n - 1 from the line through `origin` along the
/// unit `direction`.
template <class PointOf>
double MaxDistanceFromLine(vtkIdType n, PointOf&& point, const double origin[3], const double direction[3])
{
  return MaxOffset(n, point, origin, [direction](const double d[3]) {
    const double along = d[0] * direction[0] + d[1] * direction[1] + d[2] * direction[2];
    return std::sqrt(std::max(0.0, d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - along * along));
  });
}

/// Newell normal of the closed loop of points 0 .. n - 1 (twice its vector area, not
/// normalised): it points to the side from which the loop turns counter-clockwise.
template <class PointOf>
void NewellNormal(vtkIdType n, PointOf&& point, double normal[3])
{
  normal[0] = normal[1] = normal[2] = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    point(i, p);
    point((i + 1) % n, q);
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
}

/// Flips `normal` so that its largest component (the first one on ties) is
/// positive: reversed loops or reflected point sets give the same plane frame.
inline void CanonicalSign(double normal[3])
{
  int major = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::fabs(normal[k]) > std::fabs(normal[major]))
    {
      major = k;
    }
  }
  if (normal[major] < 0)
  {
    for (int k = 0; k < 3; ++k)
    {
      normal[k] = -normal[k];
    }
  }
}

/// The world axis most perpendicular to `normal`: its smallest component (the first
/// one on ties). In-plane axes are built from it.
inline int LeastAxis(const double normal[3])
{
  int least = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::fabs(normal[k]) < std::fabs(normal[least]))
    {
      least = k;
    }
  }
  return least;
}

/// True when `input` is planar loops, the 2D mode of vtkMedialAxisSampler:
///  - polylines only (no polygons, no strips), of which one is closed or which come
///    in 3 or more pieces (they may chain into loops); or
///  - polygons only (no lines, no strips), whose points all lie within 1e-6 of the
///    bounding-box diagonal from their least-squares plane (a closed surface never
///    does) but not all within that of one line (collinear points bound no area).
/// At least 3 points. vtkMedialPolygon::Build then validates the loops. When
/// `centre` and `normal` are given they receive that plane (for polylines too).
bool IsPlanarLoops(vtkPolyData* input, double centre[3] = nullptr, double normal[3] = nullptr);
}

#endif
