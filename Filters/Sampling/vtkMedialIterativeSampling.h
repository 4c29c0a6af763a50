// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialIterativeSampling.h
 * @brief Internal: the iterative sampling strategies of vtkMedialAxisSampler (3D),
 * and the coverage measure they share. Not installed.
 *
 * Coverage. The gap of a surface point x is g(x) = min_i (|x - c_i| - r_i), its
 * distance to the union of the balls so far (negative inside a ball). A face is
 * covered when g <= CoverageTolerance at its three vertices and its centroid; the
 * face's gap is the largest of those four. vtkMedialCoverage keeps g at every vertex
 * and centroid, stored cell after cell of a uniform grid, and lowers it ball by
 * ball: a new ball (c, r) can only lower points with |x - c| < r + G, G being an
 * upper bound of every gap, so only the rows of cells within that distance are
 * visited, and of those only the rows, non-empty cells and blocks of up to 8 points
 * (a cell's points in a Morton order, each block with its box) that come within
 * r + (their largest gap; a row's bound is refreshed with the maximum, and stays
 * valid since gaps only fall).
 * Finding the points a ball lowers is read-only and runs for a round's balls in
 * parallel; applying them is a minimum, so the gaps do not depend on the order the
 * balls are added in; they are applied in sample order, in parallel, each thread on
 * its own range of points. It starts from the first balls (the seeds): any ball
 * bounds g(x) from above, so the gap to the balls of the seeds whose surface points
 * are nearest x is a valid start value (and a tight one, which keeps the seeds'
 * own searches short), and its maximum a valid G.
 *
 * Seeding (every strategy but Random). Poisson-disk dart throwing on the surface:
 * candidates are area-weighted random surface points from the stream
 * (seed ^ constant, k), accepted when no accepted seed lies within
 * rho = sqrt(0.5 A / S) (A the surface area, S = SeedFraction * plan, at most
 * one per triangle; the plan is the budget, see Stopping), found through a uniform
 * grid of cell size 2 rho. Blocks of candidates are drawn and tested against the
 * seeds before the block in parallel; the survivors are tested again in index
 * order, so the seeds are those of a one-by-one throw. It stops at S seeds or 30 S candidates.
 * The seeds touch every region of the surface, so regions without initial
 * samples (the drawback of both strategies in the report) cannot occur.
 *
 * FACE_DISTANCE. Each round computes every face's gap (in parallel) and takes the
 * worst faces first (ties: lower face id), but no two with a common vertex (a ball
 * covers around its face: a neighbour waits for a later round; at most 4 room faces
 * wait per round). A round takes half of the samples left, at least RoundSize: the
 * first rounds are large, so that their samples lie close together in the tree's
 * leaves and their solves share caches and hints; the last ones are small, where
 * the choice of the very worst faces matters most. It draws on each face a random
 * point from the stream (seed ^ constant, sample index), biased toward the face's
 * worst point w (P = w + t (u - w), u uniform on the face, t uniform in [0, 2^-a),
 * a the number of failed attempts), solves the balls in parallel (a hint chain's
 * first solve hinted with the contact triangle of the ball nearest to w) and adds
 * them in index order. A face whose own samples fail to lower its gap
 * MaximumFaceAttempts times (3 with a coverage stop; e.g. next to a hole, or a
 * vertex no admissible ball reaches) is given up.
 *
 * CLOSEST_NEIGHBOR. Step 1 chains the seeds: from the first unlinked seed, link to
 * the closest seed that has no link yet and whose ball does not overlap the
 * current one (|c_p - c_q| > r_p + r_q), move there and repeat; when no such seed
 * exists the chain ends and the next one starts at the first seed without a link.
 * The closest candidate is found by a ring search in a uniform grid of the seeds'
 * centres from which linked seeds are removed; a cell is skipped when all its seeds'
 * balls must overlap the current one (its farthest point within r_p + its smallest
 * radius) or when it lies beyond the best so far.
 * Step 2 pushes every link in a max-heap keyed by its length |c_p - c_q|. Step 3
 * pops up to RoundSize links per round; for each, the midpoint of the two surface
 * points is projected to the closest surface point (vtkMedialSurfaceQuery) and its
 * ball is solved (both in parallel; hinted with P's contact triangle); in index
 * order the link P-Q becomes P-M and M-Q,
 * and each half whose balls still do not overlap is pushed again. A link whose
 * midpoint projects onto an existing sample, or whose ball fails, stays as it is.
 * The output keeps every final link as a line cell, grouped by the step-1 link
 * they refine, in path order from P to Q.
 *
 * Rounds: RoundSize samples (by default plan / 64, at least 64; FACE_DISTANCE's
 * early rounds are larger, see above), so that a run has few parallel sections;
 * within a round the balls are solved in the leaf order of the tree (cache
 * locality), in runs of 32 consecutive solves on one thread, each hinted with the
 * previous one's contact, blockers and deepest cap triangle as in the Random strategy
 * (the runs do not depend on the thread count; a hint moves a ball only within the
 * query's slack, and a contact point only among equally deep ones).
 *
 * Stopping: the budget (NumberOfSamples, seeds included), no face or link left, or
 * coverage (checked after every round when CoverageTolerance > 0). With a coverage
 * stop the budget is only a cap: the plan (which sizes the seeds and the rounds)
 * starts at 10,000 samples, or the budget if smaller, and doubles whenever the
 * samples taken reach it. When FACE_DISTANCE (or CLOSEST_NEIGHBOR's closing rounds)
 * has given up every face still above the stop, it doubles the plan and adds a
 * layer of seeds: darts from the layer's own part of the stream, kept the new
 * spacing (for SeedFraction of the doubled plan) from every seed so far, solved and
 * added in rounds of an eighth of the layer (at least RoundSize, in dart order), each
 * checked for the stop; the faces given up get as many tries again (with a coverage
 * stop a face is given up after 3 failed samples: vtkMedialFaceAttempts). (Where a
 * ball shrunk to stay inside no longer touches the face's worst point, the face's own
 * samples cannot cover it, but balls from elsewhere can.) Three layers in a row
 * after which neither fewer faces are above the stop nor the largest gap is 1%
 * smaller end the run. So the output is the same for any budget of at least 10,000
 * that is not reached. Without a coverage stop CLOSEST_NEIGHBOR does not need the
 * gaps while it runs: its balls are added to the coverage once, at the end, in
 * parallel. When
 * CLOSEST_NEIGHBOR runs out of links (all consecutive balls overlap) before the
 * budget, it finishes with FACE_DISTANCE rounds (those samples are not linked): until
 * the coverage asked for, or with CoverageTolerance 0 for a sixteenth more samples
 * (the closing rounds: the links leave holes where no chain passes, the one place
 * where its largest gap could exceed Random's at the same count).
 *
 * Determinism: every choice (seeds, popped entries, sample indices, insertion order)
 * is made on one thread in a fixed order. What runs in parallel writes only its own
 * slot: a round's ball solves (with CLOSEST_NEIGHBOR's midpoint projections), the
 * points each new ball lowers (vtkMedialCoverage::FindLowered, against the gaps
 * before the round), the seeds' darts, and the coverage's start values and maximum.
 * The lowerings are then applied in sample order, by ranges of points (each range
 * in sample order), and FACE_DISTANCE's face gaps are computed face by face (the
 * worst faces are then sorted by a total order). CLOSEST_NEIGHBOR's step 1 runs on
 * the calling thread while the other threads start the coverage (its passes are
 * worksharing loops of one team). The result does not depend on the thread count.
 * No two samples share a surface point: exact duplicates are refused.
 */
#ifndef vtkMedialIterativeSampling_h
#define vtkMedialIterativeSampling_h

#include "vtkMedialBallSolver.h"
#include "vtkMedialSampleRecord.h"
#include "vtkType.h"

#include <functional>
#include <memory>
#include <vector>

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

/// Gap of the surface (vertices and face centroids) to a growing union of balls.
/// The points are stored cell after cell of the grid, so that the points of a row of
/// cells near a ball are one contiguous run. A ball is added in two steps: FindLowered
/// (const, so any number of balls of a round run in parallel against the same gaps)
/// and Apply (in sample order). The gaps are minima, so they do not depend on the
/// order the balls come in.
class vtkMedialCoverage
{
public:
  /// A point (by storage slot) that a ball lowers, and its gap to that ball.
  struct Lowering
  {
    vtkIdType Slot;
    double Gap;
  };

  /// `threads` run Initialize, AddBalls and MaxGap.
  explicit vtkMedialCoverage(const vtkMedialTriangleMesh& mesh, int threads = 1);
  ~vtkMedialCoverage();
  vtkMedialCoverage(const vtkMedialCoverage&) = delete;
  vtkMedialCoverage& operator=(const vtkMedialCoverage&) = delete;

  /// Starts from the valid records (their surface points bound the gaps), then adds their balls.
  /// `alongside`, if set, runs first on the calling thread while the other threads
  /// start on this work (the calling thread joins them when it is done).
  void Initialize(const std::vector<vtkMedialSampleRecord>& records, const std::function<void()>& alongside = {});
  /// The valid records' balls (numbered firstBall, firstBall + 1, ...), found in
  /// parallel and applied in order.
  void AddBalls(const vtkMedialSampleRecord* records, vtkIdType count, vtkIdType firstBall);
  /// The points ball (c, r) would lower below their current gaps (replaces `lowered`).
  /// Thread-safe while no Apply runs.
  void FindLowered(const double c[3], double r, std::vector<Lowering>& lowered) const;
  /// Applies FindLowered's result for ball number `ball` (points already lowered
  /// further are left).
  void Apply(const std::vector<Lowering>& lowered, vtkIdType ball);
  /// Applies a round's FindLowered results, lowered[j] as ball number balls[j] (none
  /// when negative), as if one by one in j order; in parallel, each thread on its own
  /// range of points.
  void ApplyRound(const std::vector<std::vector<Lowering>>& lowered, const std::vector<vtkIdType>& balls);
  /// Largest gap of the face's vertices and centroid.
  double FaceGap(vtkIdType face) const;
  /// The face's point (vertex or centroid) of largest gap; returns the ball that set
  /// its gap (the nearest one to it), or -1.
  vtkIdType WorstPoint(vtkIdType face, double x[3]) const;
  /// Largest gap over all faces (recomputed; also refreshes the internal bounds), on
  /// the `threads` of the constructor, or on the calling thread alone.
  double MaxGap(bool parallel = true);
  /// The face of largest gap (lowest id among ties).
  vtkIdType WorstFace() const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

struct vtkMedialIterativeSettings
{
  enum Strategies
  {
    CLOSEST_NEIGHBOR = 1,
    FACE_DISTANCE = 2
  };
  int Strategy = FACE_DISTANCE;
  vtkIdType Budget = 0;           // total samples, seeds included
  double SeedFraction = 0.25;     // of the plan (the budget without a coverage stop), for the Poisson-disk seeds
  double CoverageTolerance = 0.0; // absolute; 0: run to the budget
  vtkTypeUInt64 Seed = 1;
  int Threads = 1;
  int RoundSize = 0; // samples solved per round; 0: plan / 64, at least 64 (not the thread count)
  int MaximumFaceAttempts = 8;  // FACE_DISTANCE: failed samples of a face before giving it up
  vtkMedialBallParameters Ball;
};

struct vtkMedialIterativeResult
{
  std::vector<vtkMedialSampleRecord> Records; // in sample order; seeds first
  vtkIdType Seeds = 0;                        // records that are seeds
  /// CLOSEST_NEIGHBOR: final links as record index pairs, grouped by initial link.
  std::vector<vtkIdType> LinkEnds;    // 2 per link
  std::vector<vtkIdType> InitialLink; // 1 per link: the step-1 link it refines
  bool CoverageReached = false;
  double MaxGap = 0.0; // absolute
  vtkIdType WorstFace = -1;  // the face of MaxGap
  double WorstPoint[3] = { 0, 0, 0 }; // its least covered point (vertex or centroid)
  vtkIdType GivenUpFaces = 0; // FACE_DISTANCE: faces left uncovered after MaximumFaceAttempts
  bool Aborted = false;
};

/// Failed samples of a face before FACE_DISTANCE gives it up: MaximumFaceAttempts, or
/// with a coverage stop at most 3 (a seed layer then gives it as many again).
int vtkMedialFaceAttempts(const vtkMedialIterativeSettings& settings);

/// Runs a strategy. `progress(fraction)` is called on the calling thread between
/// rounds and returns true to abort.
void vtkMedialRunIterativeSampling(const vtkMedialTriangleMesh& mesh,
  const vtkMedialSurfaceQuery& query, const vtkMedialIterativeSettings& settings,
  const std::function<bool(double)>& progress, vtkMedialIterativeResult& result);

#endif
