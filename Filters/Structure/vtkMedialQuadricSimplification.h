// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialQuadricSimplification
 * @brief Internal: Q-MAT's simplification of a medial mesh (Li et al. 2015) to a given
 * number of balls, by edge collapses under the spherical quadric error. Used by
 * vtkMedialSimplifyFilter.
 *
 * A ball m = (c, r) is a point of R^4. A plane n.x = d (n unit, pointing out of the
 * shape) that the ball should touch from inside gives the error (n.c + r - d)^2, a
 * quadric in m. Each ball starts with the tangent planes of its primitives: both
 * tangent planes of every triangle's slab (vtkMedialEnvelope::SlabTangentPlanes),
 * weighted by the triangle's area (a slab that is the union of its cones, where radii
 * change faster than centres: planes all around its sides' cones, a third of its area
 * each), and, for edges of no triangle, planes tangent to the cone all around its axis,
 * weighted by its lateral area.
 *
 * Rim planes: the slab planes do not see a sheet's rim pulled in along the sheet (a ball
 * moved along a crease's bisector stays tangent to both faces), so a box's edges were
 * rounded off (envelope Hausdorff 9.8% of the diagonal at K = 20, from 10,000 samples).
 * Each rim edge (one triangle) adds, on its two balls' centres, the plane through it perpendicular to its
 * triangle, weighted by RimWeight x |ab|^2 x (1 - cos(phi / 2))^2 x |ab| / (|ab| + r),
 * where phi is the angle between its slab's tangent planes (how far the envelope moves
 * per unit of retreat) and r the edge's mean radius (full weight at creases, where the
 * radii go to 0; little on the rims of large balls, whose envelope the slab planes
 * hold). The same box at K = 20: 1.8%.
 *
 * Collapses: an edge (a, b) becomes one ball at the minimiser of the summed quadric
 * (a 4 x 4 solve; when it is singular, or the minimiser leaves the segment's
 * neighbourhood or has a negative radius, the best of a, b and their midpoint), and
 * costs the quadric's value there. The cheapest collapse goes first. A collapse that
 * would change the Euler characteristic waits until its neighbourhood changes; the
 * components and the Euler characteristic never change. Collapses that keep the
 * Euler characteristic but not the homotopy type (the link condition fails: the common
 * neighbours of a and b are not exactly the third corners of the triangles on ab, or an
 * edge xy has triangles on both a and b; Dey et al. 1999) are allowed: the medial mesh
 * of a sampled surface has many small cycles bounding small cavities, and such a
 * collapse removes one of each. Under the link condition alone, collapses ran out at
 * 795 of rocker-arm's 11391 balls, after the only collapsible region left, the tube
 * around its bore, had been flattened to a triangle (envelope Hausdorff 6.5% of the
 * diagonal for any K below 850; 0.9% at K = 500 with these collapses allowed).
 *
 * Guard (GuardPoints, GuardTolerance): the quadric is a sum of squares, and what it
 * lets go first are collapses that pull a corner or a thin tip in by a little each,
 * until a few surface vertices are far from the envelope (fandisk at K = 100: 2.88%
 * of the diagonal, at a corner). With guard points (the
 * surface's vertices), each point belongs to the ball nearest to it (|p - c| - r
 * least; the balls binned by radius on grids of their centres), and each ball carries
 * its points' largest distance |g| from the envelope around it (its ball, edges and
 * triangles; vtkMedialEnvelope's fields). When a collapse comes off the queue, the
 * points of its two balls are measured against the envelope around the merged ball;
 * if one lies farther than both the tolerance and the two balls' own largest, the
 * collapse goes back into the queue behind every unguarded one, ordered by that
 * distance, so that once no collapse keeps within the tolerance, the one that moves
 * the surface least goes first. The merged ball takes its two balls' points. Points
 * of the neighbours are not measured again (their envelope changes too, a little).
 * The guard is evaluated lazily, when a collapse comes off the queue: a collapse is
 * measured about once instead of each time its neighbourhood changes.
 *
 * Stops at the target number of balls, or earlier when no collapse is allowed.
 *
 * RunKeeping connects chosen balls instead (vtkMedialSimplifyFilter's COVERAGE method):
 * only balls not kept go, each into a neighbour that stays where it is (a kept ball, or
 * the one of two balls not kept whose removal costs less), cheapest first under the same
 * quadric and the same topology rules, until only the kept balls are left. When a ball
 * not kept cannot go and `release` is set, kept balls may go too (still into a
 * neighbour that stays where it is), so that as many balls are left as were kept.
 */
#ifndef vtkMedialQuadricSimplification_h
#define vtkMedialQuadricSimplification_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

class vtkMedialSimplicialComplex;

class vtkMedialQuadricSimplification
{
public:
  /// Collapses edges until `target` balls are left (or none can go). Returns false
  /// when `aborted` returns true.
  bool Run(const vtkMedialSimplicialComplex& complex, vtkIdType target, const std::function<bool()>& aborted = {});

  /// Collapses every ball whose `kept` flag is 0 into the kept ones (see the class
  /// comment); with `release`, kept balls go too when the others are stuck (otherwise
  /// they stay, and Source tells which balls not kept are left).
  bool RunKeeping(const vtkMedialSimplicialComplex& complex, const std::vector<char>& kept, bool release,
    const std::function<bool()>& aborted = {});

  /// Weight of the rim planes (see the class comment); 0: Q-MAT's quadric alone.
  double RimWeight = 10.0;
  /// Points of the surface (x, y, z each) that guard the collapses, and the guard's
  /// tolerance (a distance; see the class comment). No points: no guard.
  std::vector<double> GuardPoints;
  double GuardTolerance = 0.0;
  /// Threads of the guard's set-up (at least 1).
  int NumberOfThreads = 1;

  /// The result: balls (centres and radii), edges with their triangle counts, triangles.
  std::vector<double> Points;
  std::vector<double> Radii;
  std::vector<std::array<vtkIdType, 2>> Edges;
  std::vector<int> EdgeTriangles;
  std::vector<std::array<vtkIdType, 3>> Triangles;
  /// Per result ball, the input ball it was last merged into (its id in the input).
  std::vector<vtkIdType> Source;
  /// Collapses refused by the link condition at the end (0 when the target was reached).
  vtkIdType BlockedCollapses = 0;

private:
  struct Quadric
  {
    double A[10] = { 0 }; // symmetric 4 x 4, upper triangle by rows
    double B[4] = { 0 };
    double C = 0.0;
    void AddPlane(const double n[3], double d, double weight);
    /// A plane n.c = d on the centre alone (the radius is free).
    void AddCentrePlane(const double n[3], double d, double weight);
    /// The error (v.m - d)^2 of the ball m = (c, r), weighted.
    void AddLinearForm(const double v[4], double d, double weight);
    void Add(const Quadric& q);
    double Evaluate(const double m[4]) const;
    bool Minimise(double m[4]) const;
  };
  struct Candidate
  {
    double Cost;
    vtkIdType A, B;
    unsigned Version; // sum of the two balls' versions when it was queued
    int Tier;
    double Error;
    bool operator>(const Candidate& o) const
    {
      if (Tier != o.Tier)
      {
        return Tier > o.Tier;
      }
      return Cost != o.Cost ? Cost > o.Cost : (A != o.A ? A > o.A : B > o.B);
    }
  };

  // Planes that hold each rim edge of a sheet where it is (see the class comment).
  void AddRimPlanes(const vtkMedialSimplicialComplex& complex, std::vector<double>& weight);
  void InitialQuadrics(const vtkMedialSimplicialComplex& complex);
  // Planes all around the cone of ab, `area` spread over them.
  void AddConePlanes(const vtkMedialSimplicialComplex& complex, vtkIdType a, vtkIdType b, double area,
    std::vector<double>& weight);
  double CollapseCost(vtkIdType a, vtkIdType b, double m[4]) const;
  enum LinkVerdict
  {
    LINK_HOLDS = 0,   // the collapse keeps the homotopy type
    KEEPS_EULER = 1,  // it does not, but keeps the Euler characteristic: allowed
    CHANGES_EULER = 2 // refused
  };
  int LinkCondition(vtkIdType a, vtkIdType b) const;
  // Orders the ends of edge ab as (the ball that stays, the ball that goes); false when
  // neither may go.
  bool Orient(vtkIdType& a, vtkIdType& b) const;
  void Collapse(vtkIdType a, vtkIdType b, const double m[4]);
  void Extract();
  // The guard: each point goes to the ball nearest to it, and each ball's error is its
  // points' largest distance from the envelope around it.
  void AssignGuardPoints();
  // The largest |field| of the points of a and b against the envelope around the ball m
  // that replaces them (their edges and triangles, with b's moved to m); b < 0: a's own.
  double MergedError(vtkIdType a, vtkIdType b, const double m[4]) const;
  std::vector<std::vector<vtkIdType>> Owned; // the guard points of each ball
  std::vector<double> LocalError;            // and their distance from its envelope

  std::vector<std::array<double, 4>> Balls;
  std::vector<Quadric> Quadrics;
  std::vector<unsigned> Versions;
  std::vector<char> Alive;
  std::vector<std::vector<vtkIdType>> Neighbours;        // sorted
  std::vector<std::vector<vtkIdType>> VertexTriangles;   // may hold dead triangles
  std::vector<std::array<vtkIdType, 3>> AllTriangles;
  std::vector<char> TriangleAlive;
  double Scale = 1.0; // the balls' extent, for the regularisation
  std::vector<char> Kept; // RunKeeping: the balls that stay (empty: Run)
  bool ReleaseKept = false;
};

#endif
