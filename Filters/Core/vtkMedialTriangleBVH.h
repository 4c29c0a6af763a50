// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialTriangleBVH
 * @brief Internal: a bounding volume hierarchy over a vtkMedialTriangleMesh for
 * rays and for the medial-ball queries that a fixed-sphere point query cannot cull well.
 *
 * Used only by vtkMedialSurfaceQuery (and by the mesh's nesting test). A generic
 * point query tests a fixed sphere against axis-aligned boxes. The medial queries
 * need more:
 *  - the ball tangent at P shrinks *and moves* (its centre is P + r n), so the
 *    culling sphere must follow the current radius;
 *  - contacts within the separation angle theta of P never count, so whole
 *    subtrees outside the cone n.(q - P) > sin(theta / 2) |q - P| can be skipped,
 *    and subtrees below the plane n.(q - P) = r (1 - cos theta) of the current
 *    ball's cap are set aside until the ball has shrunk past them;
 *  - near the medial axis a smooth surface lies all around the ball at almost
 *    the same distance. A box around a curved patch bulges into the ball; a slab
 *    along the patch's mean normal does not, so the nodes also keep one.
 *
 * Build: top-down binned SAH (16 bins on the widest centroid axis), leaves of at
 * most 4 triangles, children stored next to each other. The top levels are built
 * first; the subtrees below them are built in parallel (OpenMP) and appended as they
 * finish: the tree, its leaf order and the 4-wide tree do not depend on the thread
 * count, only where a subtree's binary nodes are stored does. Each node has its box.
 * Triangle vertices are copied in leaf order so a leaf is read contiguously. The
 * tree depends only on the mesh: deterministic.
 * A last pass collapses the binary tree into a 4-wide one (WideNode: four child
 * boxes and slabs side by side) that MaximalTangentBall walks, testing four
 * children at once with SSE2; the other queries walk it too, and the binary tree
 * for far points or without SSE2. Each binary node that a wide node holds gets a
 * slab [SlabLo, SlabHi] of m.x over its vertices, m the normalised sum of its
 * triangles' area vectors, measured from the leaf-order copies; the nodes that the
 * collapse opens have none (a quarter of the nodes on the 1.55 M horse, the inner
 * ones whose slabs cost the most to measure; only the binary walk misses them).
 *
 * Every decision is made in double precision on the mesh's own coordinates. The
 * leaf-order copy of the corners is kept in single precision when every coordinate of
 * the mesh is a float (as read from PLY, STL or OBJ files): the same values, read back
 * into doubles, in half the memory (36 instead of 72 bytes a triangle: 56 MB less on
 * the 1.55M-triangle horse) and half the cache lines per leaf.
 * Node bounds are stored in single precision relative to the bounding-box
 * centre and rounded outward, so they only ever cull what cannot block. Queries are const and keep their
 * scratch space per thread, so any number of threads may query after Build().
 */
#ifndef vtkMedialTriangleBVH_h
#define vtkMedialTriangleBVH_h

#include "vtkMedialBuffer.h"
#include "vtkType.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h> // for the corners' conversion
#endif

class vtkMedialTriangleMesh;

class vtkMedialTriangleBVH
{
public:
  /**
   * The triangles whose blocking shrank a tangent ball, in the order they did (the
   * first brought it down from the ray's bound, the last is its contact). When full,
   * the last entry follows the latest blocker.
   */
  struct BlockerChain
  {
    static constexpr int Capacity = 16;
    vtkIdType Triangles[Capacity];
    int Count = 0;
    // In: where a nearby ball's cap entered it deepest (-1: none), looked at first when
    // this ball's cap is searched. Out: this ball's, else the same.
    vtkIdType Deepest = -1;
    void Add(vtkIdType triangle)
    {
      if (this->Count > 0 && this->Triangles[this->Count - 1] == triangle)
      {
        return;
      }
      this->Triangles[this->Count < Capacity ? this->Count++ : Capacity - 1] = triangle;
    }
  };

  struct TangentBall
  {
    double Radius = 0.0;
    double Contact[3] = { 0, 0, 0 }; // the surface point that stopped the ball
    vtkIdType ContactTriangle = -1;
    vtkIdType HintTriangle = -1; // in: where the contact is likely; changes the speed only
    // In: a nearby ball's blockers (e.g. the previous sample's), shrunk on first;
    // changes the speed only. Out: this ball's.
    BlockerChain Blockers;
    int Steps = 0;       // radius updates
    // Out: the triangles the search looked at (its cost; the ball does not depend on it).
    int Visited = 0;
    bool Capped = false; // a triangle needed more than the per-triangle step cap
    // Out, when a protrusion is allowed: the surface of the cap around p (which the
    // angle rule ignores) enters the ball deeper than that; the ball about the same
    // centre that it only touches, at InscribedContact on InscribedTriangle.
    bool Shrunk = false;
    double InscribedRadius = 0.0;
    double InscribedContact[3] = { 0, 0, 0 };
    vtkIdType InscribedTriangle = -1;
    // With MeasureProtrusion (and cosMinAngle < 1): in, LargestProtrusion is the largest
    // protrusion measured so far (a running maximum over earlier balls, 0 at first);
    // out, it is raised to this ball's protrusion r - d(c) (the returned ball's radius
    // minus the distance from its centre to the surface) where that is larger. Balls
    // that protrude no more are not measured, so the running maximum ends exact
    // whatever the order of the balls. The ball itself is the same with or without.
    bool MeasureProtrusion = false;
    double LargestProtrusion = 0.0;
  };

  /// Builds the tree. Returns false when the mesh is empty or too large, or when
  /// `aborted` (polled between subtrees) returns true.
  bool Build(const vtkMedialTriangleMesh& mesh, const std::function<bool()>& aborted = {});

  /**
   * Largest ball tangent at p with centre p + r n (n the unit inward normal),
   * r <= result.Radius on entry, that no admissible surface point enters by more
   * than `slack`. On entry `result` holds the known upper bound and its contact
   * (the ray's far hit). A point q is admissible for radius r when
   * n.(q - p) >= r (1 - cosMinAngle), i.e. it lies on the far side of the plane
   * through the circle at angle theta from p (vtkMedialSurfaceQuery's rule).
   * Every blocking point q found shrinks the ball to the one through q,
   * r = |q - p|^2 / (2 n.(q - p)) (Ma et al. 2012), within a single traversal.
   * Each step moves only through radii that the triangle blocks, so the result is
   * the largest unblocked radius below the bound whichever triangles come first:
   * hints (HintTriangle, Blockers) change the speed, not the ball, except within
   * the slack where contacts tie (a few times `slack` in the radius: a point that
   * enters by less than the slack does not block, and which radius a tie is met at
   * depends on the order). The order is fixed per query, so the answer does not
   * depend on the thread count.
   * With cosMinAngle < 1 and a finite `allowed` depth, the cap's surface that the
   * traversal set aside is then searched for points deeper than `allowed` inside the
   * final ball (result.Shrunk and the inscribed ball about the same centre), starting
   * with Blockers.Deepest (a nearby ball's deepest cap triangle): a deep point found
   * first culls the rest of the search. Like the other hints it changes the speed,
   * not the inscribed radius; of cap points at exactly the same distance (two
   * triangles that share the deepest vertex or edge) it decides which is reported.
   * With result.MeasureProtrusion the same search reaches up to the running maximum
   * (result.LargestProtrusion) instead of `allowed` below the sphere, and the deepest
   * cap point it finds gives the ball's protrusion: away from the cap no surface
   * enters the ball by more than the slack, and a ball shrunk to be inscribed only
   * touches. The search visits the same triangles in the same order, only further,
   * so the ball and its inscribed contact do not change.
   */
  void MaximalTangentBall(const double p[3], const double n[3], vtkIdType ownTriangle,
    double cosMinAngle, double slack, double allowed, TangentBall& result) const;

  /**
   * Closest point of the mesh to x within upperBound, skipping ownTriangle; with
   * cosMinAngle < 1, only the part of each triangle where (q - x).(s - x) <=
   * |s - x|^2 cosMinAngle counts (s = samplePoint), or with capOnly the rest of it (the
   * cap around s, which the first rule ignores). False when none.
   */
  bool ClosestPoint(const double x[3], double upperBound, vtkIdType ownTriangle,
    const double samplePoint[3], double cosMinAngle, bool capOnly, double point[3],
    double& distance, vtkIdType& triangle) const;

  /// True when no admissible point (same rule as ClosestPoint) is closer to x than radius.
  bool ContainsBall(const double x[3], double radius, vtkIdType ownTriangle,
    const double samplePoint[3], double cosMinAngle, bool capOnly) const;

  /// Calls visit(triangle) for every triangle whose node box meets the box [lo, hi]
  /// (a superset of the triangles whose own box meets it: boxes are padded outward),
  /// until visit returns false. For diagnostics (contacts, ray parity) and the crossing
  /// tests of vtkMedialSurfaceQuery::CrossesSurface, not per sample.
  void VisitBox(const double lo[3], const double hi[3], const std::function<bool(vtkIdType)>& visit) const;

  /**
   * Pairs of mesh triangles (a < b, sorted) that may intersect other than along the
   * edge or at the corner they share: the tree walked against itself, boxes padded by
   * `tolerance`, then each close pair tested in double precision with margins of
   * `tolerance` (an absolute length). Every pair that intersects is listed (touching
   * counts, as in CGAL's self_intersections), and so are pairs too close to tell apart
   * at that precision, slivers and coplanar neighbours that may overlap: an exact test
   * decides those (vtkMedialRepairFilter). Corners are shared when they are the same
   * point of `mesh` (the one the tree was built on, whose merge made equal coordinates
   * one point). OpenMP over `threads`; the list does not depend on them. In
   * vtkMedialTriangleBVHPairs.cxx.
   */
  /// What FindIntersectingPairs' normal-cone culling did (for benchmarks and tests).
  struct PairSearchStatistics
  {
    std::int64_t CullingTests = 0;  // patches tested
    std::int64_t Culled = 0;        // patches whose self-tests were skipped
    std::int64_t PinchedCulled = 0; // of those, patches whose boundary is pinched at a corner
  };
  void FindIntersectingPairs(const vtkMedialTriangleMesh& mesh, double tolerance, int threads,
    std::vector<std::pair<vtkIdType, vtkIdType>>& pairs, PairSearchStatistics* statistics = nullptr) const;

  /**
   * First triangle other than ignoreTriangle met by the ray origin + t direction,
   * tMin < t < tMax: its t (in units of direction) and mesh id. Watertight in double
   * precision (Woop, Benthin and Wald 2013): a ray through an edge or a vertex meets
   * at least one triangle around it. Ties go to the lower mesh id, so the answer
   * does not depend on the walk: the four-lane nodes in float on padded boxes for a
   * direction of about unit length from within a few extents of the mesh (every
   * ray the sampler casts), the binary nodes in double otherwise. False when the
   * ray meets nothing.
   */
  bool IntersectRay(const double origin[3], const double direction[3], double tMin, double tMax,
    vtkIdType ignoreTriangle, double& t, vtkIdType& triangle) const;

  /// A triangle that a ray meets (RayCrossings): at T, or, where the ray runs in the
  /// triangle's plane (InPlane), anywhere along [T, End]; End = T otherwise.
  struct RayCrossing
  {
    double T, End;
    std::int32_t Triangle;
    bool InPlane;
  };

  /**
   * Every triangle other than ignoreTriangle that the ray origin + t direction meets
   * by IntersectRay's test beyond tMin, in no set order (replaces `crossings`): one
   * walk over the whole ray, for callers that would restart IntersectRay past each
   * hit. FirstCrossing(crossings, s, tMax) is then IntersectRay(origin, direction, s,
   * tMax, ignoreTriangle) for every s >= tMin, the same t and triangle: both walks
   * cull only what cannot be met, and the hit test is the same.
   */
  void RayCrossings(const double origin[3], const double direction[3], double tMin, vtkIdType ignoreTriangle,
    std::vector<RayCrossing>& crossings) const;
  /// IntersectRay's answer from RayCrossings' list: the nearest hit in (tMin, tMax),
  /// ties to the lower mesh id. False when there is none.
  static bool FirstCrossing(
    const std::vector<RayCrossing>& crossings, double tMin, double tMax, double& t, vtkIdType& triangle);

  /**
   * The triangles near a point, for many queries about it (the seam solver's
   * bisections, whose balls differ by less and less): every triangle whose closest
   * point to Centre is within Distance, in leaf order. Given to VisitWithin (without
   * a cap) or VisitWithinIfEmpty, a list that covers the query is read instead of
   * walking the tree: the same leaf tests on every triangle the walk could reach, so
   * the same answers and visits (in leaf order); a list that does not cover it is
   * ignored.
   */
  struct Nearby
  {
    double Centre[3] = { 0, 0, 0 };
    double Distance = -1.0; // below zero: holds nothing, covers no query
    std::vector<std::int32_t> Slots;
  };
  /**
   * Every triangle whose closest point to x is at most `distance` away: visit(d2, q,
   * triangle) gets the squared distance, that closest point and the mesh triangle
   * id, in traversal order (deterministic for a given mesh). With cosMinAngle < 1
   * only the admissible part of each triangle counts (same rule as ClosestPoint).
   */
  void VisitWithin(const double x[3], double distance, const double samplePoint[3], double cosMinAngle,
    const std::function<void(double, const double*, vtkIdType)>& visit, const Nearby* nearby = nullptr) const;

  /**
   * VisitWithin(x, distance) without a cap, in one walk, when ContainsBall(x,
   * emptyRadius) with no own triangle and no cap holds (true); false as soon as it is
   * known not to hold, and then visit may have seen only some triangles. The same
   * answers as the two queries (the visits in the same order), for emptyRadius <=
   * distance; saves the contains-ball walk for the balls that are empty. When false and
   * `nearestBound` is given, it gets an upper bound on the distance of x's closest
   * point, with room for rounding: ClosestPoint(x, *nearestBound) finds the same point
   * as from any larger bound, and its walk prunes from the start. When false and
   * `nearest` is given, the walk (if it is the tree's wide walk) goes on as that
   * ClosestPoint walk and leaves its answer there (nearest->Triangle >= 0), else
   * nearest->Triangle = -1: the same point, without a second walk from the root.
   */
  struct NearestPoint
  {
    double Point[3] = { 0, 0, 0 };
    double Distance = 0.0;
    vtkIdType Triangle = -1;
  };
  bool VisitWithinIfEmpty(const double x[3], double distance, double emptyRadius,
    const std::function<void(double, const double*, vtkIdType)>& visit, double* nearestBound = nullptr,
    const Nearby* nearby = nullptr, NearestPoint* nearest = nullptr) const;

  void GatherNearby(const double centre[3], double distance, Nearby& out) const;
  /// Whether `nearby` holds every triangle within `distance` of x, with room for rounding.
  bool Covers(const Nearby& nearby, const double x[3], double distance) const;

  /**
   * Whether the searches may drop a lane on its subtree's inner sphere (WideSphere), on
   * by default. The balls are the same either way (the lanes dropped hold nothing that
   * could change them); off, a search visits what it did before the spheres, which the
   * tests compare against. Not thread-safe: set it before querying.
   */
  void SetInnerSpheres(bool use) { this->UseInnerSpheres = use; }
  bool GetInnerSpheres() const { return this->UseInnerSpheres; }

  /// For tests: the number of wide nodes whose inner sphere claims more room than it
  /// has (a triangle under the node comes closer to its centre than its Reach, by an
  /// exact closest point); 0 when every bound holds. Slow: every subtree's triangles.
  vtkIdType CountInnerSphereViolations() const;

  /// Mesh triangle t's unit outward normal and offset (n.x = offset on its plane): the
  /// tree's copy of the mesh's normal, the same bits.
  const double* GetPlane(vtkIdType t) const { return this->LeafTriangles[this->LeafRank[t]].Plane; }

  /// Mesh triangle t's three vertices, 9 doubles in the mesh's vertex order: the tree's
  /// leaf-order copy, the same bits as the mesh's points. The pointer is into the tree,
  /// or into `scratch` when the tree keeps them as floats.
  const double* GetTriangleVertices(vtkIdType t, double scratch[9]) const
  {
    return this->Corners(this->LeafRank[t], scratch);
  }

  /// Position of each mesh triangle in leaf order: nearby triangles get nearby ranks.
  const vtkMedialBuffer<std::int32_t>& GetLeafRanks() const { return this->LeafRank; }
  vtkIdType GetNumberOfNodes() const { return static_cast<vtkIdType>(this->Nodes.size()); }

  // 64 bytes: one cache line. Single precision, relative to Origin, rounded outward,
  // so every bound still holds for the mesh's double coordinates.
  struct alignas(64) Node
  {
    float Lo[3], Hi[3]; // axis-aligned box
    float Axis[3];      // slab normal, about unit; zero when there is no slab
    float SlabLo, SlabHi; // range of Axis.(x - Origin) over the node's vertices
    std::int32_t Start; // leaf: first triangle in leaf order; inner: left child (right is Start + 1)
    std::int32_t Count; // leaf: number of triangles; inner: 0
    std::int32_t Begin, End; // its triangles, in leaf order
  };

  // Four nodes of the binary tree side by side (structure of arrays), for the tangent
  // search to test at once: a binary node and its descendants two levels down or so,
  // collapsed by opening the largest inner one first. Lane bounds are the binary nodes'
  // own floats. An empty lane has an inverted box and misses every ball.
  struct alignas(64) WideNode
  {
    float Lo[3][4], Hi[3][4];
    float Axis[3][4];
    float SlabLo[4], SlabHi[4];
    // >= 0: the wide node below; < 0: a leaf, ~(start * 8 + count) in leaf order.
    std::int32_t Child[4];
  };

  // The inner sphere of a wide node's subtree (the one its parent's lane points at):
  // no triangle under it comes closer than Reach to Centre (relative to Origin; Reach
  // rounded down; -inf: none). The centre is the sphere fitted to some of its corners.
  // With the lane's box it bounds from below the distance from a ball's centre x to
  // the subtree: |q - x|^2 = |q - s|^2 - 2 (q - s).(x - s) + |x - s|^2 and (q - s).(x - s)
  // is at most its largest value over the box. Inside a finely tessellated sphere a
  // ball lies within rounding of every facet, and no box or slab keeps a curved patch
  // out of it; this bound does, unless the patch is within rounding of the ball too.
  struct WideSphere
  {
    float Centre[3];
    float Reach;
  };

  // What the searches read of a triangle before its vertices, in one cache line (one
  // stream per leaf instead of three: plane, box and mesh id were separate arrays).
  struct alignas(64) LeafTriangle
  {
    double Plane[4];    // unit outward normal, offset: the mesh's normal, the same bits
    float Lo[3], Hi[3]; // box like a node's; Hi is read four floats at a time (EdgeThird is lane 4)
    float EdgeThird;    // its longest edge's square / 3, rounded up: TriangleDistance2Below's term
    std::int32_t Triangle; // mesh triangle id
  };

  // Build only: a node's box and the box of its triangles' centroids, in double.
  struct BuildBounds
  {
    double Lo[3], Hi[3], CLo[3], CHi[3];
  };

private:
  class TangentSearch; // the passes of MaximalTangentBall

  // A leaf lane holds ~(start * LeafCodeScale + count): starts below 2^28 fit.
  static constexpr std::int32_t LeafCodeScale = 8;
  // The leaf-order slots [Start, End) of a leaf lane, from its child code.
  struct LeafSlots
  {
    std::int32_t Start, End;
    explicit LeafSlots(std::int32_t child)
    {
      const std::uint32_t code = ~static_cast<std::uint32_t>(child);
      this->Start = static_cast<std::int32_t>(code / static_cast<std::uint32_t>(LeafCodeScale));
      this->End = this->Start + static_cast<std::int32_t>(code % static_cast<std::uint32_t>(LeafCodeScale));
    }
  };

  // The corners of the triangle at leaf-order `slot`, 9 doubles: a pointer into the
  // double copy, or the float copy read into `scratch`.
  const double* Corners(std::int32_t slot, double scratch[9]) const
  {
    if (!this->FloatCorners)
    {
      return &this->Vertices[9 * static_cast<size_t>(slot)];
    }
    const float* f = reinterpret_cast<const float*>(this->Vertices.data()) + 9 * static_cast<size_t>(slot);
#if defined(__SSE2__)
    // Two at a time (exact, as one by one, which took 7% of the sampling's
    // instructions on the 1.55M-triangle horse).
    const __m128 first = _mm_loadu_ps(f), second = _mm_loadu_ps(f + 4);
    _mm_storeu_pd(scratch, _mm_cvtps_pd(first));
    _mm_storeu_pd(scratch + 2, _mm_cvtps_pd(_mm_movehl_ps(first, first)));
    _mm_storeu_pd(scratch + 4, _mm_cvtps_pd(second));
    _mm_storeu_pd(scratch + 6, _mm_cvtps_pd(_mm_movehl_ps(second, second)));
    scratch[8] = static_cast<double>(f[8]);
#else
    for (int k = 0; k < 9; ++k)
    {
      scratch[k] = static_cast<double>(f[k]);
    }
#endif
    return scratch;
  }

  struct Subtree
  {
    std::int32_t Node, Begin, End;
    BuildBounds Bounds;
  };
  // Build only: each triangle's box and centroid, and the order being partitioned.
  struct BuildState;
  // FindIntersectingPairs' normal-cone culling (vtkMedialTriangleBVHPairs.cxx).
  class PatchCulling;
  // The nodes (Build's first pass), then from the build items the leaf order
  // (LeafTriangles' ids and boxes) and LeafRank. False when aborted.
  bool BuildNodes(const vtkMedialTriangleMesh& mesh, const std::function<bool()>& aborted);
  // Build's second pass: Vertices and LeafTriangles' planes and edges, gathered from
  // the mesh in leaf order.
  void CopyInLeafOrder(const vtkMedialTriangleMesh& mesh);
  // Build's last pass: WideNodes and LeafLane from the binary tree, and the slabs of
  // the binary nodes that they hold. False when the mesh is too large for the leaf
  // encoding.
  bool BuildWideNodes(const vtkMedialTriangleMesh& mesh);
  // Build's very last pass: WideSpheres (in vtkMedialTriangleBVHSpheres.cxx).
  void MeasureWideSpheres();
  // The leaf slots [first, last) under each wide node, and its parent (when asked).
  void WideSlotRanges(std::int32_t* first, std::int32_t* last, std::int32_t* parent) const;
  // A lower bound of the squared distance from x (relative to Origin) to every triangle
  // under lane `lane` of `holder`, whose child is wide node `child` (> 0), with room for
  // the rounding of the bound itself; -inf when the child has no sphere.
  double SphereDistance2Below(const WideNode& holder, int lane, std::int32_t child, const double x[3]) const
  {
    const WideSphere& sphere = this->WideSpheres[child];
    if (!(sphere.Reach > 0.0f))
    {
      return -HUGE_VAL;
    }
    double d2 = 0.0, h = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double s = sphere.Centre[k];
      const double d = x[k] - s;
      d2 += d * d;
      // The largest (q - s).(x - s) over the lane's box: its corner along d.
      h += d * ((d >= 0.0 ? static_cast<double>(holder.Hi[k][lane]) : static_cast<double>(holder.Lo[k][lane])) - s);
    }
    const double reach2 = static_cast<double>(sphere.Reach) * static_cast<double>(sphere.Reach);
    return reach2 - 2.0 * h + d2 - 1e-12 * (reach2 + 2.0 * std::fabs(h) + d2);
  }
  // The binary nodes that the wide node over `binary` holds (its children, opened two
  // levels down or so; `root`: wide node 0, the binary root alone); returns how many.
  int WideLanes(std::int32_t binary, bool root, std::int32_t lanes[4]) const;
  // Wide node `index` over the binary nodes `lanes` (whose slabs it measures first),
  // and LeafLane for its leaves.
  void WriteWideNode(std::int32_t index, const std::int32_t lanes[4], int count, const vtkMedialTriangleMesh& mesh);
  // The wide subtree over inner binary node `binary`, numbered from `first`: its size,
  // and with `write` its nodes (the root's parent lane is left to the caller).
  std::int32_t WideSubtree(std::int32_t binary, std::int32_t first, const vtkMedialTriangleMesh& mesh, bool write);
  // Builds the subtree of triangles order[begin, end), whose bounds are `bounds`,
  // into nodes[node]. With `later`, ranges of at most `grain` triangles are only
  // recorded there, to be built in parallel.
  void BuildNode(BuildState& state, vtkMedialBuffer<Node>& nodes, std::int32_t node, std::int32_t begin,
    std::int32_t end, const BuildBounds& bounds, std::vector<Subtree>* later, std::int32_t grain) const;
  // The node over order[begin, end) with the given bounds: its float box, no slab yet.
  Node BoundNode(std::int32_t begin, std::int32_t end, const BuildBounds& bounds) const;
  // The node's slab [SlabLo, SlabHi] along its triangles' area-weighted mean normal,
  // from the leaf-order vertices and planes (after CopyInLeafOrder); left empty (Axis
  // zero) above SlabMaximumTriangles or where the normals cancel out.
  void MeasureSlab(Node& node, const vtkMedialTriangleMesh& mesh) const;
  // The bounds of order[begin, end), by a pass over its triangles.
  static BuildBounds MeasureBounds(const BuildState& state, std::int32_t begin, std::int32_t end);
  // Partitions order[begin, end) for the two children (binned SAH, else the median);
  // returns where the right child starts, and the children's bounds.
  static std::int32_t SplitNode(BuildState& state, std::int32_t begin, std::int32_t end,
    const BuildBounds& bounds, BuildBounds& left, BuildBounds& right);

  // Depth first, nearer child first, over the triangles other than ownTriangle
  // whose admissible part may lie within sqrt(reach2) of x. visit(d2, q, triangle)
  // gets each one's closest admissible point q and returns false to stop; it may
  // lower reach2 to narrow the search. Used by ClosestPoint and ContainsBall.
  // The largest coordinate of the root's box relative to Origin: the scale of the
  // float bounds' rounding.
  double Extent() const;

  template <class Visit>
  void VisitAdmissible(const double x[3], vtkIdType ownTriangle, const double samplePoint[3],
    double cosMinAngle, bool capOnly, double& reach2, Visit visit) const;
  // VisitAdmissible without a cap or an own triangle, over a Nearby list instead of the tree.
  template <class Visit>
  void VisitListed(const Nearby& nearby, const double x[3], double reach2, Visit visit) const;

  vtkMedialBuffer<Node> Nodes;
  // The tangent search's tree. A lane is named by its reference, wide node * 4 + lane;
  // wide node 0 holds the binary root in lane 0 and nothing else.
  vtkMedialBuffer<WideNode> WideNodes;
  vtkMedialBuffer<WideSphere> WideSpheres; // one per wide node
  bool UseInnerSpheres = true;
  double Origin[3] = { 0, 0, 0 };          // the bounding-box centre: node bounds are relative to it
  double RoundingPad = 0.0;                // absolute padding of the float bounds
  vtkMedialBuffer<double> Vertices;        // 9 per triangle, leaf order (as floats with FloatCorners)
  bool FloatCorners = false;               // every mesh coordinate is a float: Vertices holds floats
  vtkMedialBuffer<LeafTriangle> LeafTriangles; // leaf order
  vtkMedialBuffer<std::int32_t> LeafRank; // position of each mesh triangle in leaf order
  // One bit per leaf-order slot: its triangle is a sliver (vtkMedialGeometry::IsSliver on
  // its corners). Marked in CopyInLeafOrder, where the corners are at hand, for
  // FindIntersectingPairs (a pass of its own over every slot's corners was a quarter of
  // the solid check on a smooth 1.55M-triangle mesh); rare, so bits, not bytes.
  vtkMedialBuffer<std::uint64_t> SliverBits;
  bool IsSliverSlot(std::int32_t slot) const { return (this->SliverBits[slot >> 6] >> (slot & 63)) & 1u; }
  vtkMedialBuffer<std::int32_t> LeafLane;  // the lane of the leaf holding each leaf-order slot
};

#endif
