// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSurfaceQuery
 * @brief Internal: ray, bounded closest-point and contains-ball queries on a
 * vtkMedialTriangleMesh, all answered by the internal vtkMedialTriangleBVH.
 *
 * Build() builds the tree over the mesh's double coordinates. Rays use its watertight
 * double-precision test (vtkMedialTriangleBVH::IntersectRay); hit distances are
 * taken against the hit triangle's plane. Point queries and MaximalTangentBall use
 * the same tree, whose culling sphere moves with a shrinking ball. The crossing
 * tests of segments and triangles (SegmentCrossesSurface, TriangleCrossesSurface)
 * take their candidates from it (VisitWithin) and decide in double precision.
 * (Rays used to go through an Embree scene: the own tree measured within 2x of
 * Embree's rays, and saves Embree's build time and memory.)
 *
 * Queries are const and keep their state on the stack, so any number of threads
 * may call them at once (e.g. from an OpenMP loop) after Build(). After Build() they
 * read the tree's own copies of the triangles (vertices and normals) and only the
 * mesh's Bounds, so a caller done with the mesh's arrays may release them
 * (vtkMedialTriangleMesh::ReleaseGeometry).
 *
 * A ContactFilter describes which surface points may block a ball tangent to the
 * surface at a sample point P on triangle OwnTriangle:
 *  - OwnTriangle never blocks (the ball is tangent to its plane at P);
 *  - with CosMinAngle < 1, points of the cap around P are ignored: a point q
 *    blocks a ball (c, r) only where (q - c).(P - c) <= r^2 cos(theta). On the
 *    sphere this is exactly "the angle P-c-q is at least theta" (Foskey et al.
 *    2003, theta-simplified medial axis); inside the ball it is a plane cut, so
 *    surface deep inside the ball always blocks;
 *  - with CapOnly, the reverse: only the cap counts (ClosestPoint and ContainsBall),
 *    to find where a ball found with the rule above crosses the surface there.
 */
#ifndef vtkMedialSurfaceQuery_h
#define vtkMedialSurfaceQuery_h

#include "vtkMedialTriangleBVH.h"
#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class vtkMedialTriangleMesh;

class vtkMedialSurfaceQuery
{
public:
  struct ContactFilter
  {
    vtkIdType OwnTriangle = -1;
    double SamplePoint[3] = { 0, 0, 0 };
    double CosMinAngle = 1.0; // 1: theta = 0, nothing but OwnTriangle is ignored
    bool CapOnly = false;     // true: only the cap around SamplePoint counts
  };
  struct RayHit
  {
    double Distance = 0.0;
    vtkIdType Triangle = -1;
  };
  struct ClosestHit
  {
    double Point[3] = { 0, 0, 0 };
    double Distance = 0.0;
    vtkIdType Triangle = -1;
  };

  using TangentBall = vtkMedialTriangleBVH::TangentBall;
  using Nearby = vtkMedialTriangleBVH::Nearby;

  vtkMedialSurfaceQuery() = default;
  vtkMedialSurfaceQuery(const vtkMedialSurfaceQuery&) = delete;
  vtkMedialSurfaceQuery& operator=(const vtkMedialSurfaceQuery&) = delete;

  /// Builds the tree. The mesh must outlive this object. Returns false with a reason
  /// ("aborted" when `aborted`, polled between stages, returns true).
  bool Build(const vtkMedialTriangleMesh* mesh, std::string& error,
    const std::function<bool()>& aborted = {});

  /// First hit of the ray origin + t * direction (unit), t in (tMin, tMax), skipping `ignoreTriangle`.
  bool Intersect(const double origin[3], const double direction[3], double tMin, double tMax,
    vtkIdType ignoreTriangle, RayHit& hit) const;

  /// First hit of the ray from inside the solid, tMin < t: the face met must face along
  /// the ray (its outward normal). False when the ray escapes (open surface) or first
  /// meets a face from outside (self-intersection). A ray that meets a face from
  /// outside first (through a vertex or an edge) is tried again, nudged sideways by a
  /// tiny padding.
  bool IntersectFromInside(const double origin[3], const double direction[3], double tMin,
    vtkIdType ignoreTriangle, RayHit& hit) const;

  /// Closest admissible surface point to x with distance < upperBound (finite). False when none.
  bool ClosestPoint(
    const double x[3], double upperBound, ClosestHit& hit, const ContactFilter* filter = nullptr) const;

  /// True when no admissible surface point lies strictly inside the ball. Stops at the first one found.
  bool ContainsBall(const double centre[3], double radius, const ContactFilter* filter = nullptr) const;

  /**
   * Every triangle whose closest admissible point to x is at most `distance` away,
   * with that point and its distance, sorted by triangle id (replaces the contents
   * of `hits`). The filter's OwnTriangle is not skipped here; with its CosMinAngle
   * < 1 only each triangle's part outside the cap counts. Used by the medial
   * structure filters to read every contact of a ball. Always answered by the
   * internal tree.
   */
  void TrianglesWithin(const double x[3], double distance, std::vector<ClosestHit>& hits,
    const ContactFilter* filter = nullptr, const Nearby* nearby = nullptr) const;

  /**
   * ContainsBall(x, emptyRadius) && TrianglesWithin(x, distance, hits), in one walk
   * (for emptyRadius <= distance): the same answer and, when true, the same hits.
   * When false, `hits` holds only some of them, and `nearestBound` (if given) an upper
   * bound on the distance of x's closest point (vtkMedialTriangleBVH::VisitWithinIfEmpty):
   * ClosestPoint from there finds what it finds from any larger bound, sooner. No filter.
   * When false and `nearest` is given, it may hold that ClosestPoint's answer, found in
   * the same walk (nearest->Triangle >= 0; else -1, and ClosestPoint must be asked).
   */
  bool TrianglesWithinIfEmpty(const double x[3], double distance, double emptyRadius,
    std::vector<ClosestHit>& hits, double* nearestBound = nullptr, const Nearby* nearby = nullptr,
    ClosestHit* nearest = nullptr) const;

  /// The triangles within `distance` of `centre`, for TrianglesWithin and
  /// TrianglesWithinIfEmpty to read instead of walking the tree when they are asked
  /// about balls inside that reach (vtkMedialTriangleBVH::Nearby): the same answers.
  void GatherNearby(const double centre[3], double distance, Nearby& out) const
  {
    this->Tree.GatherNearby(centre, distance, out);
  }
  bool Covers(const Nearby& nearby, const double x[3], double distance) const
  {
    return this->Tree.Covers(nearby, x, distance);
  }

  /**
   * Largest admissible ball tangent at p with centre p + r n (n unit, inward),
   * found in one traversal that shrinks the ball at every blocking point (see
   * vtkMedialTriangleBVH). On entry `ball` holds an upper bound and its contact. With
   * a finite `allowed` depth, also tells whether the cap's surface enters the ball
   * deeper than that, and the inscribed ball about the same centre (ball.Shrunk).
   */
  void MaximalTangentBall(const double p[3], const double n[3], const ContactFilter& filter,
    double allowed, TangentBall& ball) const;

  /**
   * Number of surface crossings of the ray origin + t * direction (unit), t in
   * (0, tMax): hits counted one after the other (a hit on an edge shared by
   * two triangles counts once): Intersect() from 0, restarted CrossingStep() past
   * each hit's distance, counts the same (answered from one walk over the ray).
   */
  int CountCrossings(const double origin[3], const double direction[3], double tMax) const;

  /// How far past a hit CountCrossings restarts: hits closer together count once.
  double CrossingStep() const { return 4.0 * this->RayPad; }

  /**
   * True when x lies inside the closed surface: the parity of the crossings along
   * fixed, non-axis directions, two out of three (the third ray only when the first
   * two disagree), so that a ray grazing an edge cannot decide alone. Outside the
   * bounding box, false at once. Meaningless for open surfaces.
   */
  bool IsInside(const double x[3]) const;

  /// True when the segment [p, q] passes through the interior of a surface triangle
  /// (vtkMedialGeometry::SegmentCrossesTriangle; touching does not count).
  bool SegmentCrossesSurface(const double p[3], const double q[3]) const;

  /// True when the triangle (a, b, c) crosses a surface triangle
  /// (vtkMedialGeometry::TrianglesCross; touching does not count).
  bool TriangleCrossesSurface(const double a[3], const double b[3], const double c[3]) const;

  /// Whether a segment (n = 2 points) or a triangle (n = 3) crosses surface triangle
  /// `corners`: the decision of the two tests above, which callers may replace (e.g. by
  /// exact predicates: the double-precision signs are noise where a simplex is coplanar
  /// with a surface edge, as medial sheets are with the convex edges they end at).
  using CrossingTest = bool (*)(const double* const points[], int n, const double* const corners[3]);
  /// SegmentCrossesSurface (n = 2) or TriangleCrossesSurface (n = 3) with `test`
  /// deciding each surface triangle near the points. `test` must be exact (say yes only
  /// where the simplices meet): only the triangles whose box meets the points' are tested.
  bool CrossesSurface(const double* const points[], int n, CrossingTest test) const;

  /// Calls visit(corners) for the surface triangles that may meet the segment (n = 2
  /// points) or triangle (n = 3): those within the smallest ball about the points'
  /// centroid that holds them. Stops when visit returns true.
  void VisitNear(const double* const points[], int n, const std::function<bool(const double* const corners[3])>& visit) const;

  /// Pairs of triangles that may intersect other than where they share an edge or a
  /// corner (vtkMedialTriangleBVH::FindIntersectingPairs, tolerance 1e-9 of the
  /// diagonal plus the coordinates' rounding).
  void FindIntersectingPairs(int threads, std::vector<std::pair<vtkIdType, vtkIdType>>& pairs,
    vtkMedialTriangleBVH::PairSearchStatistics* statistics = nullptr) const;

  /// Unit outward normal of mesh triangle t, from the tree (the same values as the
  /// mesh's, which a caller that only queries may then release: ReleaseNormals).
  const double* GetNormal(vtkIdType t) const { return this->Tree.GetPlane(t); }

  /// Mesh triangle t's three vertices, 9 doubles in the mesh's vertex order (the tree's
  /// copy; the pointer is into the tree, or into `scratch` when it keeps floats).
  const double* GetTriangleVertices(vtkIdType t, double scratch[9]) const
  {
    return this->Tree.GetTriangleVertices(t, scratch);
  }

  /// Rank of each triangle in the internal tree's leaf order (spatially coherent).
  const vtkMedialBuffer<std::int32_t>& GetLeafRanks() const { return this->Tree.GetLeafRanks(); }

  /// Whether the searches may drop a subtree on its inner sphere (on by default; the
  /// same answers either way, see vtkMedialTriangleBVH::SetInnerSpheres). For tests.
  void SetInnerSpheres(bool use) { this->Tree.SetInnerSpheres(use); }
  vtkIdType CountInnerSphereViolations() const { return this->Tree.CountInnerSphereViolations(); }

  /// Frees the tree; no query may run afterwards. For callers done with querying that
  /// build a large output next (the tree is about 150 bytes per triangle).
  void ReleaseTree() { this->Tree = vtkMedialTriangleBVH(); }

  /// Absolute slack: a point blocks a ball only when closer than radius - Slack. Tiny and unbiased.
  double GetSlack() const { return this->Slack; }
  const vtkMedialTriangleMesh* GetMesh() const { return this->Mesh; }

private:
  template <class FirstHit>
  bool FirstHitFrom(
    const double origin[3], const double direction[3], double tMin, FirstHit first, RayHit& hit) const;
  bool IntersectFrom(const double rayOrigin[3], const double origin[3], const double direction[3],
    double tMin, double tMax, vtkIdType ignoreTriangle, RayHit& hit) const;

  vtkMedialTriangleBVH Tree;
  double RayPad = 0.0; // a ray restarts this far past a hit at its origin; the sideways nudge
  const vtkMedialTriangleMesh* Mesh = nullptr;
  double Slack = 0.0;
};

#endif
