// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshComplex
 * @brief Internal: the simplicial complex of the medial mesh, chosen on the regular
 * triangulation of the balls (vtkMedialPowerComplex) and collapsed to triangles and
 * edges. Used by vtkMedialMeshFilter.
 *
 * Passes (each a private method):
 *  1. SelectCandidates: the nerve of the power cells restricted to the solid. A
 *     simplex is a candidate when its dual power face meets the solid or the union
 *     of the balls: a tetrahedron whose power centre is inside (IsInside, or in the
 *     union), a triangle whose dual segment (a ray on the convex hull) meets the solid
 *     (an inside end or a surface crossing), an edge with a candidate triangle or in
 *     the union. The restricted cells cover the solid, gaps between the balls
 *     included, so this nerve has the solid's topology where they are convex; near
 *     the surface they are not (a cell that leaves the solid may enter it again far
 *     off), so it may not: loops, voids and pieces the next passes mend.
 *  2. KeepContained: a candidate outside the union of balls is kept only when it
 *     does not cross the surface (vtkMedialSurfaceQuery::CrossesSurface decided by
 *     vtkMedialExactPredicates: exact signs, touching does not count; a tetrahedron
 *     through its faces). Simplices in the union lie in the union of their balls, so
 *     inside the solid when the balls are inscribed. From here on the complex K lies
 *     in the solid.
 *  3. FillVoids: tetrahedra that the outside cannot reach through triangles not in
 *     K form voids; each is filled (tetrahedra, faces, edges) when none of its
 *     simplices crosses the surface. A solid without cavities has no void, and a
 *     sphere of triangles inside it bounds a region inside it.
 *  4. ConnectComponents: edges of the triangulation that do not cross the surface,
 *     shortest first, join the components of K that they connect.
 *  5. FillEmptyTriangles: triangles of the triangulation whose three edges are in K
 *     and that do not cross the surface are added (then voids are filled again),
 *     until none is left.
 *  6. DropDetachedComponents: each component of K lies in one component of the
 *     solid (given per ball); in each solid component only the component of K with
 *     the most balls is kept. The others (balls that no edge inside the shape could
 *     join, e.g. a tiny ball at a crease whose every edge leaves the shape) are
 *     dropped and counted.
 *  7. FillLoops: a loop of K that a disk of triangles inside the solid would fill,
 *     but no single triangle (step 5), e.g. one closed by an edge between two balls
 *     that the rest of K already joins. Where the loops are: the balls on the edges
 *     of no triangle that collapses (tetrahedra through free triangles, triangles
 *     through free edges, edges through free ends) cannot remove, the true loops of
 *     the solid and the extra ones. Around them (the tetrahedra on those balls) K is
 *     closed under the additions inside the solid that never add homology: a
 *     triangle whose sides are in K, a triangle with two sides in K added with its
 *     third (an expansion), a tetrahedron whose faces are in K, or whose faces but one
 *     are, added with it; then voids are filled. The closure is unique (each addition
 *     only enables others), so the order does not matter.
 *     Steps 3 to 7 only add simplices inside the solid, so they can only remove
 *     homology that the solid does not have: a loop or void of K they fill bounds in
 *     the solid.
 *  8. Collapse: tetrahedra are removed with a free face (a triangle of exactly one
 *     of them), oldest first, until none has one. Collapses keep the homotopy type.
 *     Then TrimAdded collapses the triangles step 7 added through their free sides.
 *  9. PruneProtrusions: the triangles left are faces of thin layers of tetrahedra,
 *     some of them fins standing out of the sheet, whose interpolated balls (the
 *     envelope's) cross the surface. A triangle with a free side (an edge of no other
 *     triangle) is removed with that side when a ball interpolated at its centroid or
 *     a side's midpoint protrudes through the surface by more than the tolerance; an
 *     edge of no triangle with a free end, with that end, likewise. These are
 *     collapses too; they go on as long as any applies. The vertex balls bound most
 *     protrusions within the tolerance without a surface query
 *     (vtkMedialEnvelope::ProtrusionBound).
 * The result: the vertices (ball ids), every edge (triangle sides included) and the
 * triangles; tetrahedra left without a free face (none on every shape measured) are
 * counted and dropped.
 */
#ifndef vtkMedialMeshComplex_h
#define vtkMedialMeshComplex_h

#include "vtkType.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

class vtkMedialPowerComplex;
class vtkMedialSurfaceQuery;

class vtkMedialMeshComplex
{
public:
  struct Statistics
  {
    vtkIdType RejectedSimplices = 0; // candidates that crossed the surface
    vtkIdType FilledTetrahedra = 0;  // by FillVoids
    vtkIdType ConnectingEdges = 0;   // by ConnectComponents
    vtkIdType EmptyTriangles = 0;    // by FillEmptyTriangles and FillLoops
    vtkIdType DetachedBalls = 0;     // dropped by DropDetachedComponents
    vtkIdType PrunedTriangles = 0;   // by PruneProtrusions
    vtkIdType PrunedEdges = 0;       // edges of no triangle, by PruneProtrusions
    vtkIdType RemainingTetrahedra = 0; // not collapsible, dropped
  };

  /// The balls: 3 coordinates per centre, radii, and the component of the solid each
  /// lies in.
  struct Balls
  {
    const std::vector<double>* Centres = nullptr;
    const std::vector<double>* Radii = nullptr;
    const std::vector<vtkIdType>* SolidComponents = nullptr;
  };

  /// Runs the passes; `protrusionTolerance` (absolute; negative: no pruning) is that of
  /// PruneProtrusions. Returns false when `aborted` (polled between passes) returns true.
  bool Build(const vtkMedialPowerComplex& power, const vtkMedialSurfaceQuery& query, const Balls& balls,
    double protrusionTolerance, int threads, const std::function<bool()>& aborted = {});

  std::vector<vtkIdType> Vertices;                 // ball ids, increasing
  std::vector<std::array<vtkIdType, 2>> Edges;     // ball ids; every edge, triangle sides too
  std::vector<int> EdgeTriangles;                  // triangles on each edge
  std::vector<std::array<vtkIdType, 3>> Triangles; // ball ids
  Statistics Stats;

  /// V - E + F of the result.
  vtkIdType GetEulerCharacteristic() const
  {
    return static_cast<vtkIdType>(this->Vertices.size()) - static_cast<vtkIdType>(this->Edges.size()) +
      static_cast<vtkIdType>(this->Triangles.size());
  }
  /// Connected components of the result.
  vtkIdType GetNumberOfComponents() const { return this->Components; }
  /// Counts the components again from Vertices and Edges (after a refinement changed them).
  void CountComponents();

private:
  void SelectCandidates();
  void KeepContained();
  vtkIdType FillVoids();
  void ConnectComponents();
  void FillEmptyTriangles();
  void DropDetachedComponents(const std::vector<vtkIdType>& solidComponents);
  void FillLoops();
  // The balls on the edges of no triangle that collapses cannot remove (tetrahedra
  // through free triangles, triangles through free edges, edges through free ends):
  // where every loop of K is.
  std::vector<vtkIdType> LoopBalls() const;
  // Collapses the triangles FillLoops added through their free sides, once the
  // tetrahedra are gone.
  void TrimAdded();
  std::vector<vtkIdType> TriangleAdded;
  void Collapse();
  // How many of each triangle's tetrahedra, and of each edge's triangles, the flags
  // mark (counted per triangle and per edge, so in parallel).
  std::vector<int> TetsOnTriangles(const std::vector<char>& tetIn) const;
  std::vector<int> TrianglesOnEdges(const std::vector<char>& triangleIn) const;
  void PruneProtrusions(double tolerance);
  // Protrusion through the surface of the ball interpolated at the given barycentric
  // weights over the balls `ids`, for deciding whether it exceeds `tolerance`: where the
  // vertex balls bound it within (vtkMedialEnvelope::ProtrusionBound), that bound without
  // a query; otherwise the protrusion when beyond, or the tolerance standing for it
  // (vtkMedialEnvelope::ProtrusionBeyond).
  double Protrusion(const vtkIdType* ids, const double* weights, int n, double tolerance) const;
  class ProtrusionMemo;
  void Extract();

  // Containment tests, memoised: 0 unknown, 1 inside, 2 crosses the surface.
  bool EdgeInside(vtkIdType e);
  bool TriangleInside(vtkIdType t);
  const double* Centre(vtkIdType ball) const { return &(*this->BallData.Centres)[3 * ball]; }

  const vtkMedialPowerComplex* Power = nullptr;
  const vtkMedialSurfaceQuery* Query = nullptr;
  Balls BallData;
  int Threads = 1;
  vtkIdType Components = 0;

  std::vector<char> TetIn, TriangleIn, EdgeIn, VertexIn;
  std::vector<char> TetCandidate, TriangleCandidate;
  std::vector<char> EdgeState, TriangleState;
  std::vector<vtkIdType> BallRanks; // each ball's rank in the spatial order (vtkMedialSpatialOrder.h)
};

#endif
