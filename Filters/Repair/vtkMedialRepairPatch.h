// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialRepairPatch
 * @brief Internal (MedialAxis::Repair): the check and the distance queries of a closed
 * shell whose patch was replaced, without a mesh and a tree of the whole result.
 *
 * The repair's local self-intersection removal cuts a patch P out of a closed shell S,
 * lets CGAL mend it into P' and stitches P' back along P's border, which P' keeps bit for
 * bit (vtkMedialRepairFilter). The result S' = (S - P) + P' differs from S in P' only, so:
 *
 * Certify() decides whether S' is a valid solid (closed, manifold, consistently oriented,
 * no degenerate triangle, no two triangles that intersect other than along a shared edge
 * or corner: what vtkMedialRepairFilter's whole check asks of one shell) by looking at P'
 * and what touches it only. It is a sufficient test: true implies the whole check of S'
 * says valid, with S' one shell facing out; false says nothing (the caller then runs the
 * whole check). Given that S is closed, manifold, oriented and free of degenerate
 * triangles, and that every intersecting pair of S has both triangles in P:
 *  - topology: every point of P' has one closed fan of triangles, each edge at it used
 *    once in each direction. A point that is not a point of P' has the same triangles
 *    around it in S' as in S (a point of S - P on a triangle of P lies on P's border, and
 *    P' keeps every border point), so every edge and every fan of S' is manifold and
 *    oriented. P' is edge-connected, so S' is one shell (every piece of S - P meets P's
 *    border, which P' holds);
 *  - intersections: the pairs of S' are those of S - P with itself (pairs of S, which do
 *    not intersect, decided by the same exact predicates on the same points and ids) and
 *    the pairs with a triangle of P'. For each triangle of P' every triangle within its
 *    bounding ball (plus a margin for the rounding) is listed, from a tree of P' and from
 *    S's tree (leaving out P), and decided with CGAL's exact predicates on the stitched
 *    ids (vtkMedialSurfaceRepair::IntersectingPairs). Points of P' equal to another point
 *    (the whole check would merge them) make two triangles meet at a point with distinct
 *    ids, an intersection;
 *  - degenerate triangles: S' stays inside S's bounds (so its diagonal is not larger,
 *    and no triangle of S - P becomes degenerate) and no triangle of P' is below twice
 *    the preparation's degenerate area;
 *  - orientation: the signed volume of S', the sum over its triangles, is positive, so
 *    the preparation keeps every triangle's winding (no triangle rewound).
 *
 * Distance() and IsInside() answer for S' from S's tree (leaving out P) and trees of P and
 * P': the closest point is the closer of P' and of S - P; the crossings of a ray with S'
 * are those with S, minus those with P, plus those with P', so the parity is read from the
 * three trees, with the same three rays and two-of-three vote as
 * vtkMedialSurfaceQuery::IsInside (they differ only for a ray through P's border).
 */
#ifndef vtkMedialRepairPatch_h
#define vtkMedialRepairPatch_h

#include "vtkMedialAxisRepairModule.h" // for export macro
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialSurfaceRepair.h"
#include "vtkMedialTriangleMesh.h"
#include "vtkSmartPointer.h"

#include <array>
#include <map>
#include <string>
#include <vector>

class vtkPolyData;

class VTKMEDIALAXISREPAIR_EXPORT vtkMedialRepairPatch
{
public:
  using Soup = vtkMedialSurfaceRepair::Soup;

  /**
   * `shell`: S, closed, manifold, oriented (as its preparation oriented it) and free of
   * degenerate triangles, whose intersecting pairs all lie in the patch; `query`: the tree
   * of a mesh of S alone, built from `shell` (its triangle t is shell triangle t); `in`:
   * S's triangles in P; `before`: P (as Extract cuts it out); `stitched`: S' as Stitch made it
   * (S - P in order, then P''s triangles). True when S' is a valid solid (see above);
   * otherwise false with the reason in `why`. The object keeps `query` (which must
   * outlive it) for the queries below.
   */
  bool Certify(const Soup& shell, const vtkMedialSurfaceQuery& query, const std::vector<char>& in,
    const Soup& before, const Soup& stitched, std::string& why);

  /// The triangles of `soup` marked `in`, in order, over their own points (numbered as
  /// first met); `soupPoint` gives each of their points' id in `soup`. The repair cuts
  /// the patch P out of its shell with it, and Certify takes P' out of S'.
  static Soup Extract(const Soup& soup, const std::vector<char>& in, std::vector<vtkIdType>& soupPoint);

  /// Distance from x to S' (`bound` when none is closer); after Certify.
  double Distance(const double x[3], double bound) const;
  /// Whether x is inside S'; after Certify.
  bool IsInside(const double x[3]) const;
  /// Whether S's triangle t was in the patch.
  bool InPatch(vtkIdType t) const { return this->In[t] != 0; }
  /// Whether the point x of P is a point of S'.
  bool KeptPoint(const double x[3]) const;
  /// Whether the triangle of P with corners a, b, c is a triangle of S'.
  bool KeptTriangle(const double a[3], const double b[3], const double c[3]) const;
  /// P's points (the only points of S that S' may have dropped).
  const Soup& GetBefore() const { return this->Before; }

private:
  const vtkMedialSurfaceQuery* ShellQuery = nullptr;
  std::vector<char> In;
  Soup Before;
  vtkMedialTriangleMesh BeforeMesh, AfterMesh;
  vtkMedialSurfaceQuery BeforeQuery, AfterQuery;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::map<std::array<double, 3>, vtkIdType> AfterPoints;
  std::vector<std::array<vtkIdType, 3>> AfterTriangles; // sorted corners, sorted
};

namespace vtkMedialSurfaceRepair
{
/// The soup as polygon data (double points, one triangle cell each).
VTKMEDIALAXISREPAIR_EXPORT vtkSmartPointer<vtkPolyData> ToPolyData(const Soup& soup);
}

#endif
