// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialExactPredicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point P(const double* x)
{
  return Point(x[0], x[1], x[2]);
}

// The segment pq through the interior of triangle abc: p and q strictly on either side of
// its plane, and the line pq turning the same way around each of its edges.
bool SegmentCrossesTriangle(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c)
{
  const CGAL::Orientation sp = CGAL::orientation(a, b, c, p), sq = CGAL::orientation(a, b, c, q);
  if (sp == CGAL::COPLANAR || sq == CGAL::COPLANAR || sp == sq)
  {
    return false;
  }
  const CGAL::Orientation e0 = CGAL::orientation(p, q, a, b), e1 = CGAL::orientation(p, q, b, c),
                          e2 = CGAL::orientation(p, q, c, a);
  return e0 != CGAL::COPLANAR && e0 == e1 && e1 == e2;
}
}

bool vtkMedialExactPredicates::Crosses(const double* const points[], int n, const double* const corners[3])
{
  const Point u[3] = { P(corners[0]), P(corners[1]), P(corners[2]) };
  if (n == 2)
  {
    return SegmentCrossesTriangle(P(points[0]), P(points[1]), u[0], u[1], u[2]);
  }
  const Point t[3] = { P(points[0]), P(points[1]), P(points[2]) };
  for (int i = 0; i < 3; ++i)
  {
    if (SegmentCrossesTriangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2]) ||
      SegmentCrossesTriangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2]))
    {
      return true;
    }
  }
  return false;
}


bool vtkMedialExactPredicates::EdgesCrossTriangle(const double* const points[], int n, const double* const corners[3])
{
  if (n != 3)
  {
    return Crosses(points, n, corners);
  }
  const Point u[3] = { P(corners[0]), P(corners[1]), P(corners[2]) };
  const Point t[3] = { P(points[0]), P(points[1]), P(points[2]) };
  for (int i = 0; i < 3; ++i)
  {
    if (SegmentCrossesTriangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2]))
    {
      return true;
    }
  }
  return false;
}
