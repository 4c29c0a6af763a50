// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialGeometry::TriangleDistance2Below, which lets the tangent search skip exact
// tests, is a lower bound of the squared distance from a point to a triangle, and is
// tight where it should be:
//  - on 200,000 random triangles (equilateral, acute, slivers, needles, degenerate) and
//    points (above the centroid, near, far), it never exceeds ClosestPointOnTriangle's
//    squared distance (beyond 1e-12 of it): a bound that subtracted less than a third
//    of the longest edge's square would break this above an equilateral triangle's
//    centroid;
//  - it is within a third of the longest edge's square below the distance, and above
//    an equilateral triangle's centroid it equals it, so a bound too weak to spare
//    tests (zero, or a whole edge's square subtracted) fails too.
#include "vtkMedialGeometry.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace G = vtkMedialGeometry;

int TestMedialTriangleDistanceBound(int, char*[])
{
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int failures = 0;
  double worstExcess = 0.0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    double v[3][3];
    const int kind = trial % 5;
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        v[i][k] = unit(random);
      }
    }
    if (kind == 0) // equilateral in the plane z = 0, side sqrt(3) * s
    {
      const double s = 0.01 + std::fabs(unit(random)), turn = 3.0 * unit(random);
      for (int i = 0; i < 3; ++i)
      {
        const double a = turn + 2.0943951023931953 * i;
        v[i][0] = s * std::cos(a);
        v[i][1] = s * std::sin(a);
        v[i][2] = 0.0;
      }
    }
    else if (kind == 1) // sliver: the third vertex near the first edge
    {
      for (int k = 0; k < 3; ++k)
      {
        v[2][k] = 0.5 * (v[0][k] + v[1][k]) + 1e-6 * unit(random);
      }
    }
    else if (kind == 2) // degenerate: two vertices equal
    {
      for (int k = 0; k < 3; ++k)
      {
        v[2][k] = v[1][k];
      }
    }
    double p[3];
    const double reach = kind == 3 ? 10.0 : 1.0;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = reach * unit(random);
    }
    if (kind == 0 && trial % 2 == 0) // above the centroid
    {
      p[0] = p[1] = 0.0;
    }
    double q[3];
    const double exact = G::ClosestPointOnTriangle(p, v[0], v[1], v[2], q);
    const double bound = G::TriangleDistance2Below(p, v[0], v[1], v[2]);
    const double longest2 =
      std::max({ G::Distance2(v[0], v[1]), G::Distance2(v[1], v[2]), G::Distance2(v[2], v[0]) });
    const double slack = 1e-12 * (exact + longest2) + 1e-300;
    worstExcess = std::max(worstExcess, (bound - exact) / (exact + longest2 + 1e-300));
    if (bound > exact + slack)
    {
      if (++failures <= 5)
      {
        std::printf("bound %.17g above the squared distance %.17g (trial %d, kind %d)\n", bound, exact, trial, kind);
      }
      continue;
    }
    const double gap = exact - bound;
    if (gap > longest2 / 3.0 + slack)
    {
      if (++failures <= 5)
      {
        std::printf("bound %.17g too far below %.17g (trial %d, kind %d)\n", bound, exact, trial, kind);
      }
    }
    if (kind == 0 && trial % 2 == 0 && std::fabs(gap) > 1e-12 * (exact + longest2))
    {
      if (++failures <= 5)
      {
        std::printf("above an equilateral centroid the bound %.17g is not the distance %.17g\n", bound, exact);
      }
    }
  }
  std::printf("worst excess of the bound over the squared distance, relative: %.3g\n", worstExcess);
  if (failures > 0)
  {
    std::printf("%d failures\n", failures);
    return 1;
  }
  return 0;
}
