// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSeamSolver
 * @brief Internal: exact seam points and junction vertices of the 3D medial axis
 * of a polyhedron, between neighbouring balls whose governors differ.
 *
 * The 3D extension of vtkMedialJunctionFilter's triple solver. A ball (x, r)
 * tangent to a governor satisfies
 *  - PLANE (inward unit normal n through p): n.(x - p) = r, linear;
 *  - LINE (a reflex edge through p, unit direction u): |x - p|^2 - ((x - p).u)^2 = r^2;
 *  - POINT (a reflex vertex p): |x - p|^2 = r^2.
 * Quadratics with the same quadratic part (all points; lines with one direction)
 * differ by a linear equation, so a set of governors becomes linear rows plus one
 * quadratic per remaining group. The rows are reduced (full pivoting) to
 * X = X0 + N s, N an orthonormal null space of dimension d:
 *  - d = 0: the linear solution (planes only: the 3D straight skeleton);
 *  - d = 1: one quadratic in s, solved in closed form (e.g. three planes and an
 *    edge or a vertex: the parabolic paths; two vertices: the planar bisector);
 *  - d >= 2: Newton's method in s from the neighbouring balls (two or more
 *    independent quadratics: edges of different directions, the hyperbolic paths,
 *    or edges with vertices), with a damped step. Converges quadratically, to
 *    rounding, from a nearby seed.
 * A seam point (3 governors: a curve of solutions) gets one more linear row: the
 * hyperplane through the reference ball (x, r), e.g. the midpoint of the two
 * neighbours, perpendicular to the seam there (the null vector of the three
 * tangency gradients). For planes the seam is a line and this is the projection.
 *
 * Every solution is verified, with VerifyTolerance (1e-9 of the diagonal):
 * r above it, the ball empty (vtkMedialSurfaceQuery::ContainsBall at r - tolerance),
 * every solved feature touched (vtkMedialGovernors::Classify at that tolerance, so
 * a face is touched inside it, an edge inside its segment), and at least 3
 * governors in all (at the governors' theta): 3 is a seam point, 4 or more a
 * junction vertex. Sets holding a feature and one on its boundary (a face and its
 * edge or vertex, an edge and its end) are not solved: a ball touches both at one
 * point, a transition inside a sheet, not a seam.
 *
 * Candidates (Solve): for each neighbour pair (i, j) whose governor sets differ
 * and neither contains the other, with only simple governors: the union of 3 is
 * a seam candidate at the pair's midpoint; a union of 4 to 6 gives its 4-subsets
 * as junction candidates. A ball with 3 to 6 governors gives its own triples and
 * quadruples. Then every two accepted seam triples sharing two governors give the
 * quadruple of their union: a junction is the end of the seams that meet there, so
 * it is found when two of its seams are. A triple's solution that touches a fourth
 * governor gives that quadruple instead. Last, every seam found is traced to its
 * ends (predictor-corrector along the seam's tangent, doubling the step while the
 * ball stays empty and touches its three governors, then bisection): where a fourth
 * governor enters, its quadruple is solved (a junction, whose other seams are traced
 * in the next wave); where a contact leaves its face or edge for the edge or vertex
 * on its boundary, the seam goes on as the triple with that feature (a transition);
 * where the radius reaches zero it ends at the rim. On a polyhedron every junction
 * is the end of a seam, so tracing from any seam of a connected seam graph reaches
 * all its junctions; MaximumTracedSeams bounds the work. Results are merged within
 * MergeTolerance (1e-9 of the diagonal), a junction absorbing seam points there.
 * Output is deterministic for any thread count (tasks are solved into fixed slots
 * and merged in task order).
 *
 * API for the structure filters (e.g. the medial mesh passes its edges as pairs):
 * @code
 *   vtkMedialSeamSolver solver(governors);   // a built vtkMedialGovernors
 *   std::vector<vtkMedialSeamSolver::Ball> balls(n);  // Centre, Radius, Governors (Classify)
 *   auto pairs = vtkMedialSeamSolver::NearestPairs(centres, n, 12, threads); // or the mesh's edges
 *   vtkMedialSeamSolver::Result result;
 *   solver.Solve(balls, pairs, threads, aborted, result);
 *   // result.Points: Centre, Radius, Type (SEAM or JUNCTION), GovernorCount, Features
 *   // result.PairPoint[p]: the point found between the balls of pairs[p], or -1
 * @endcode
 */
#ifndef vtkMedialSeamSolver_h
#define vtkMedialSeamSolver_h

#include "vtkMedialGovernors.h"
#include "vtkType.h"

#include <array>
#include <functional>
#include <map>
#include <vector>

class vtkMedialSeamSolver
{
public:
  using Pair = std::array<vtkIdType, 2>;
  using BallVector = std::array<double, 4>; // (x, y, z, r)

  struct Ball
  {
    double Centre[3] = { 0, 0, 0 };
    double Radius = 0.0;
    vtkMedialGovernors::BallGovernors Governors;
  };

  struct ExactPoint
  {
    double Centre[3] = { 0, 0, 0 };
    double Radius = 0.0;
    int Type = vtkMedialGovernors::SEAM; // SEAM or JUNCTION
    int GovernorCount = 0;               // governors the exact ball touches
    std::vector<int> Features;           // the features it is tangent to (sorted)
  };

  struct Result
  {
    std::vector<ExactPoint> Points;   // merged
    std::vector<vtkIdType> PairPoint; // per input pair: index in Points, or -1
    vtkIdType SeamCandidates = 0;     // triples solved
    vtkIdType JunctionCandidates = 0; // distinct quadruples solved
    vtkIdType Verified = 0;           // solutions accepted (before merging)
    vtkIdType TracedSeams = 0;        // distinct seams followed to their ends
    bool TracingStopped = false;      // MaximumTracedSeams was reached: junctions may be missing
  };

  explicit vtkMedialSeamSolver(const vtkMedialGovernors& governors);

  ///@{
  /// Tolerances relative to the diagonal (defaults 1e-9).
  void SetVerifyTolerance(double t) { this->VerifyTolerance = t; }
  void SetMergeTolerance(double t) { this->MergeTolerance = t; }
  ///@}

  /// Seams followed to their ends at most (default 20000; 0: no tracing).
  void SetMaximumTracedSeams(vtkIdType n) { this->MaximumTracedSeams = n; }

  /**
   * Seam points and junction vertices between the given neighbour pairs (indices
   * into balls). Returns false when `aborted` (polled between blocks) returned true.
   * threads <= 0: all cores.
   */
  bool Solve(const std::vector<Ball>& balls, const std::vector<Pair>& pairs, int threads,
    const std::function<bool()>& aborted, Result& result) const;

  /// The k nearest other centres of each of n centres (3 per centre), as sorted unique (i < j) pairs,
  /// found on `threads` threads (the result does not depend on them). Nearest as in
  /// vtkMedialNearestPoints: ties at the k-th distance go to the smaller id.
  static std::vector<Pair> NearestPairs(const double* centres, vtkIdType n, int k, int threads);

  /**
   * Balls tangent to n = 3 or 4 features; with n = 3 `constraint` (w[4], k: w.(x, r) = k)
   * is required. Seeds (x, r) are used when Newton's method is needed. Appends the
   * solutions with r > 0 to `out`; unverified.
   */
  void TangentBalls(const int* features, int n, const double* constraint,
    const std::vector<BallVector>& seeds, std::vector<BallVector>& out) const;

  /// The seam constraint through `reference` for 3 features (false when degenerate).
  bool SeamConstraint(const int features[3], const BallVector& reference, double constraint[5]) const;

  /// Unit tangent (in (x, r) space) of the seam of 3 features at X (false when degenerate).
  bool SeamTangent(const int features[3], const BallVector& X, double tangent[4]) const;

  /// Verifies a solution for `features` (see the class comment) and fills `point`.
  bool Verify(const BallVector& ball, const int* features, int n, ExactPoint& point) const;

private:
  using Tagged = std::pair<std::array<int, 4>, BallVector>; // features (-1 padded) and a ball
  // Three features and a reference ball (a seam point), or four and seeds (a junction).
  struct Candidate
  {
    std::array<int, 4> Features{ { -1, -1, -1, -1 } };
    int N = 4;
    std::vector<BallVector> Seeds; // triples: Seeds[0] is the reference
    double Reach = 1e300;          // triples: largest distance of the solution from the reference
    std::vector<vtkIdType> Pairs;  // pairs that proposed it
    std::vector<ExactPoint> Found; // verified solutions
    std::vector<Tagged> Nearby;    // triples: junction candidates where a solution touched a fourth governor
    bool Solved = false;
  };
  // What tracing one seam found at its ends: junction candidates (4 features) and
  // the seams it turns into at transitions (3 features), each with a ball there.
  struct TraceEnds
  {
    std::vector<Tagged> Quadruples;
    std::vector<Tagged> Triples;
  };
  enum SeamStates
  {
    ON_SEAM,
    BLOCKED, // a fourth governor enters the ball
    LEFT,    // a contact left its face or edge, or the radius reached zero
  };

  struct Candidates
  {
    std::vector<Candidate> Triples;
    std::map<std::array<int, 4>, Candidate> Quadruples;
  };
  void AddTriple(Candidates& candidates, const std::array<int, 4>& features, const BallVector& reference,
    double reach, vtkIdType pair) const;
  void AddQuadruple(
    Candidates& candidates, const std::array<int, 4>& features, const BallVector& seed, vtkIdType pair) const;
  // Candidates from the neighbour pairs whose governors differ, and from balls with 3+ governors.
  void Propose(const std::vector<Ball>& balls, const std::vector<Pair>& pairs, Candidates& candidates) const;
  // Junction candidates from the seams solved: two sharing two governors, or one touching a fourth.
  void ProposeFromSeams(Candidates& candidates) const;
  void MergePoints(const std::vector<Ball>& balls, const std::vector<Pair>& pairs,
    const std::vector<Candidate>& quadruples, const std::vector<Candidate>& triples, Result& result) const;
  // True when two of the first n features lie one on the other's boundary (not solved).
  bool HasIncidentPair(const std::array<int, 4>& features, int n) const;
  void SolveCandidates(std::vector<Candidate>& candidates, int threads,
    const std::function<bool()>& aborted, bool& stopped) const;
  // The ball on the seam of `features` nearest to `guess` in the hyperplane through it
  // perpendicular to `tangent`.
  bool OnSeam(const int features[3], const BallVector& guess, const double tangent[4], BallVector& out) const;
  // Whether X is on the seam of `features`, LEFT it or is BLOCKED (not empty); `nearby`
  // (may be null): the triangles near X, read instead of walking the tree.
  int SeamState(const int features[3], const BallVector& X, double tolerance, std::vector<int>& touched,
    const vtkMedialTriangleBVH::Nearby* nearby = nullptr) const;
  // Follows the seam of `features` both ways from `start` (a verified seam point) to
  // its ends: marching with a predictor-corrector, then bisecting where it stops.
  void TraceSeam(const int features[3], const BallVector& start, TraceEnds& ends) const;
  // The ends found where the seam stops between `last` (on it) and `beyond`.
  void Ends(const int features[3], const BallVector& last, const BallVector& beyond, const double tangent[4],
    TraceEnds& ends) const;
  // Traces every seam reachable from the seam points and junctions found so far,
  // wave by wave, solving the junction candidates met on the way.
  bool TraceAll(
    Candidates& candidates, int threads, const std::function<bool()>& aborted, Result& result) const;

  const vtkMedialGovernors& Governors;
  double Origin[3] = { 0, 0, 0 }; // the algebra works in (x - Origin) / Scale
  double Scale = 1.0;
  double VerifyTolerance = 1e-9;
  double MergeTolerance = 1e-9;
  vtkIdType MaximumTracedSeams = 20000;
};

#endif
