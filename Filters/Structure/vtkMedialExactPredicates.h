// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialExactPredicates.h
 * @brief Internal: the crossing tests of vtkMedialGeometry (SegmentCrossesTriangle,
 * TrianglesCross: an edge of one simplex through the interior of the other; touching
 * and coplanar contact do not count) with exact orientation signs (CGAL's filtered
 * predicates on the input doubles).
 *
 * Why: a medial sheet of a polyhedron lies in the bisector plane of the two faces at a
 * convex edge, so the medial mesh's triangles are often coplanar with a surface edge
 * up to rounding; the double-precision signs there are noise, and a triangle that
 * does not meet the surface at all was found "crossing" it (coarse tori: the voids
 * such triangles kept unfilled and the loops their removal opened were the wrong
 * Euler characteristics). With exact signs every decision is the true one for the
 * given coordinates.
 */
#ifndef vtkMedialExactPredicates_h
#define vtkMedialExactPredicates_h

#include "vtkMedialAxisStructureModule.h" // for export macro (the tests call them)

namespace vtkMedialExactPredicates
{
/// A segment (n = 2 points) or triangle (n = 3) against a triangle, exactly; the
/// signature of vtkMedialSurfaceQuery::CrossingTest.
VTKMEDIALAXISSTRUCTURE_EXPORT bool Crosses(const double* const points[], int n, const double* const corners[3]);

/// Crosses for a triangle (n = 3) whose own edges are known to cross no surface
/// triangle: only the surface triangle's edges through its interior are left to test,
/// so the answer is Crosses' at half the predicates.
VTKMEDIALAXISSTRUCTURE_EXPORT bool EdgesCrossTriangle(
  const double* const points[], int n, const double* const corners[3]);
}

#endif
