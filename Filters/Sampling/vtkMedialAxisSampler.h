// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialAxisSampler
 * @brief Samples the medial axis transform of a closed triangle mesh as maximal inscribed balls.
 *
 * Algorithm (the sampling approach of the "Medial Axis Transform" report):
 *  1. The input surface is triangulated, coincident points are merged, and the
 *     triangles are oriented outward (consistent winding, then the sign of the
 *     enclosed volume), so a mesh with flipped normals gives the same answer.
 *  2. NumberOfSamples points P are drawn on the surface, each triangle with
 *     probability proportional to its area. Sample i uses its own random stream
 *     seeded by (RandomSeed, i): output is identical for any thread count.
 *     That is the RANDOM SamplingStrategy; CLOSEST_NEIGHBOR and FACE_DISTANCE
 *     choose the points iteratively from the balls found so far (see
 *     SetSamplingStrategy and vtkMedialIterativeSampling.h), and every strategy
 *     can stop early at a CoverageTolerance.
 *  3. From each P a ray along the inward normal n finds the far side Q. Every
 *     ball tangent at P has its centre P + r n; the one through Q has r = |PQ|/2,
 *     an upper bound.
 *  4. The largest empty ball is found by
 *     - BISECTION (the report): halve [0, |PQ|/2] with ContainsBall until the
 *       bracket is below Tolerance * diagonal; the output is the lower end, an
 *       empty ball; or
 *     - SHRINKING_BALL (Ma et al. 2012): from the ball through Q, repeatedly find
 *       the closest blocking surface point q and set r = |P - q|^2 / (2 n.(q - P)),
 *       until the ball is empty. Exact up to rounding; capped at MaximumIterations.
 *     - ONE_PASS (the default): the same shrinking-ball update applied to every
 *       blocking triangle met during a single BVH traversal whose culling ball
 *       follows the shrinking ball (vtkMedialTriangleBVH). A triangle settles the
 *       ball in closed form on its face, an edge or a vertex. Exact up to
 *       rounding, no tolerance, and 3 to 10 times faster than the others.
 *    Every blocking point q stops all radii between r(q) and the current one, so
 *    both shrinking methods return the largest empty ball below |PQ|/2. With
 *    theta > 0 emptiness is not always monotone in r, and bisection may stop at
 *    a smaller transition (0.3% of horse.ply's samples at 45 degrees).
 *  5. MinimumSeparationAngle theta: a surface point q blocks a ball only if the
 *     angle P-centre-q is at least theta (on the ball's sphere; see
 *     vtkMedialSurfaceQuery). A ball that the surface in the ignored cap enters
 *     deeper than MaximumProtrusion is then shrunk about its centre until it is
 *     inscribed. theta = 0 gives the exact medial axis of the
 *     polyhedron, whose balls on a finely tessellated smooth surface are mostly
 *     bounded by the facets next to P (median 0.29 R on a sphere). The default,
 *     45 degrees, was chosen by measurement (scripts/theta-table.py and
 *     scripts/protrusion-table.py, tables in docs/how-it-works/theta.md): on
 *     geodesic spheres the radius error falls linearly with the facet size and with
 *     1 - cos(theta) (1.4% of R at 327k triangles); shrinking the balls that cross the ignored
 *     cap's surface keeps them inscribed (the angle rule alone lets them cross it by
 *     0.5% (horse.ply) to 1.9% (the open bunny) of the diagonal).
 *     Features whose contacts are at least 45 degrees apart (a dihedral angle of
 *     135 degrees or sharper, e.g. a box's 90 degree edges) are kept.
 *
 * All ray, closest-point and contains-ball queries go through vtkMedialSurfaceQuery
 * (rays and point queries through its own BVH); decisions are made
 * in double precision. Samples are solved in the BVH's leaf order, for cache
 * locality, in hint chains (each sample hinted with the previous one's contact,
 * blockers and deepest cap triangle; 32 to 512 samples, set by NumberOfSamples
 * alone); each result keeps its own index, and the output depends neither on the
 * thread count nor on the piece.
 *
 * Input: vtkPolyData with polygons or strips (a closed surface). With RepairMode AUTO
 * (the default) the preparation checks that the surface is a valid solid (closed,
 * manifold, consistently oriented, without self-intersections) and, when it is not,
 * samples the solid that vtkMedialRepairFilter (GetRepair) makes of it: holes filled,
 * overlapping shells joined, stray sheets removed... (one warning per step;
 * GetSurfaceRepaired; the repair's report joins the output's field data). With
 * RepairMode NONE open meshes are accepted with a warning: samples whose ray escapes
 * through a hole are discarded and counted. SourceCellId then refers to the cells of
 * the surface sampled: the repaired one when it was repaired.
 *
 * Output: one vertex per accepted sample, at the ball centre, with point data
 *  - Radius (double), SurfacePoint (double x3, the sample P),
 *  - ContactPoint (double x3, the closest blocking surface point at convergence:
 *    the second touching point), SeparationAngle (double, degrees, P-centre-contact),
 *  - SourceCellId (vtkIdType, the input cell that P lies on);
 * and field data RequestedSamples, DiscardedSamples, MeanIterations, CappedSamples
 * (the iterative strategies add EvaluatedSamples, SeedSamples, CoverageReached and
 * MaxCoverageGap; CLOSEST_NEIGHBOR adds the links as line cells with cell data
 * InitialLink, -1 on the vertex cells).
 *
 * 2D mode: when the input is planar polygons or closed polylines (any plane; see
 * vtkMedialPolygon for what is accepted), samples are drawn on the edges with
 * probability proportional to length, the ray follows the inward edge normal in
 * the plane, and the largest empty disk is found by the same two methods and the
 * same separation-angle cap, on an exact 2D edge grid instead of the BVH. Output
 * arrays are the same; SourceCellId is the input polygon or polyline cell.
 * IsPlanarInput() tells which mode an input gets. Methods in 2D: ONE_PASS and
 * SHRINKING_BALL are one and the same method there, the exact shrinking ball on the
 * edge grid (the one-pass BVH traversal has no 2D counterpart to fuse with: each
 * step is already a single closest-edge query), and give bit-identical output;
 * BISECTION is bisection. No warning is given, since ONE_PASS is the default.
 *
 * Pieces (see vtkMedialPieces.h): every piece requests the whole input (rays need the
 * whole surface) and, with RANDOM, solves its share of the sample indices: the union
 * of the pieces is exactly the one-piece output, for any number of pieces (MPI ranks
 * under pvbatch), which is what makes the sampler scale. The iterative strategies
 * and a CoverageTolerance above 0 are sequential (each ball depends on the previous
 * ones): piece 0 computes them whole, the other pieces are empty and skip the
 * preparation.
 *
 * @sa vtkMedialShapeSource
 */
#ifndef vtkMedialAxisSampler_h
#define vtkMedialAxisSampler_h

#include "vtkMedialAxisSamplingModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkMedialRepairFilter;

class VTKMEDIALAXISSAMPLING_EXPORT vtkMedialAxisSampler : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialAxisSampler* New();
  vtkTypeMacro(vtkMedialAxisSampler, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// How each maximal ball is found (Method; step 4 of the algorithm above).
  enum Methods
  {
    BISECTION = 0,      ///< bisection on the radius with ContainsBall, to Tolerance
    SHRINKING_BALL = 1, ///< Ma et al.'s shrinking ball, to the closest blocking point
    ONE_PASS = 2        ///< the shrinking ball within one BVH traversal (the fastest)
  };

  /// Where the samples go (SamplingStrategy).
  enum SamplingStrategies
  {
    RANDOM = 0,           ///< uniform by area
    CLOSEST_NEIGHBOR = 1, ///< Poisson-disk seeds linked to their closest neighbours
    FACE_DISTANCE = 2     ///< Poisson-disk seeds, then the faces farthest from the balls
  };

  ///@{
  /// Number of random surface samples (default 10000).
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Ball search method (default ONE_PASS, the fastest; all three agree, see above).
  /// On 2D input ONE_PASS runs the shrinking ball (see the 2D mode above).
  vtkSetClampMacro(Method, int, BISECTION, ONE_PASS);
  vtkGetMacro(Method, int);
  void SetMethodToBisection() { this->SetMethod(BISECTION); }
  void SetMethodToShrinkingBall() { this->SetMethod(SHRINKING_BALL); }
  void SetMethodToOnePass() { this->SetMethod(ONE_PASS); }
  static const char* GetMethodName(int method);
  ///@}

  ///@{
  /// Where the surface samples go (3D input; 2D input always uses RANDOM):
  ///  - RANDOM (default): NumberOfSamples independent area-weighted random samples;
  ///  - CLOSEST_NEIGHBOR: Poisson-disk seeds chained to their closest non-overlapping
  ///    unlinked neighbour, the longest links split at the surface point between
  ///    their ends until consecutive balls overlap; the links are output as lines;
  ///  - FACE_DISTANCE: Poisson-disk seeds, then the faces farthest from the union of
  ///    balls are sampled next, round by round.
  /// The two iterative strategies stop at the budget (NumberOfSamples, seeds
  /// included), when CoverageTolerance is reached, or when they run out of work
  /// (CLOSEST_NEIGHBOR: every link's balls overlap; it then goes on with FACE_DISTANCE
  /// rounds, until the CoverageTolerance if one is set, else for a sixteenth more
  /// samples, which close the holes the links leave). See
  /// vtkMedialIterativeSampling.h for the details. They run in piece 0 only (other
  /// pieces are empty) and are deterministic for a seed, whatever the thread count.
  vtkSetClampMacro(SamplingStrategy, int, RANDOM, FACE_DISTANCE);
  vtkGetMacro(SamplingStrategy, int);
  void SetSamplingStrategyToRandom() { this->SetSamplingStrategy(RANDOM); }
  void SetSamplingStrategyToClosestNeighbor() { this->SetSamplingStrategy(CLOSEST_NEIGHBOR); }
  void SetSamplingStrategyToFaceDistance() { this->SetSamplingStrategy(FACE_DISTANCE); }
  static const char* GetSamplingStrategyName(int strategy);
  ///@}

  ///@{
  /// Coverage stopping tolerance, relative to the bounding-box diagonal (default 0:
  /// off, the whole budget is used). The surface is covered when every face's three
  /// vertices and centroid x satisfy min_i (|x - c_i| - r_i) <= tolerance, i.e. lie
  /// within the tolerance of the union of balls. The iterative strategies check it
  /// after every round; with it, NumberOfSamples is a cap, not their plan: they plan
  /// for 10,000 samples (or fewer, if so capped), double the plan whenever it is used
  /// up, and add a layer of seeds when the faces left have all been given up, so any
  /// budget of 10,000 or more that is not reached gives the same output.
  /// RANDOM (3D), when it is above 0, checks it after every block of 1024 samples and
  /// stops there: its output is then a prefix of the full run. With a tolerance above
  /// 0, the output's field data holds CoverageReached and MaxCoverageGap (the
  /// iterative strategies always add them).
  vtkSetClampMacro(CoverageTolerance, double, 0.0, 1.0);
  vtkGetMacro(CoverageTolerance, double);
  ///@}

  ///@{
  /// Share of NumberOfSamples spent on the Poisson-disk seeds of the iterative
  /// strategies (default 0.25), at most one seed per triangle; with a
  /// CoverageTolerance, the share of their plan (see there).
  vtkSetClampMacro(SeedFraction, double, 0.001, 1.0);
  vtkGetMacro(SeedFraction, double);
  ///@}

  ///@{
  /// Bisection stopping tolerance, relative to the bounding-box diagonal (default 1e-6).
  vtkSetClampMacro(Tolerance, double, 1e-15, 0.1);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Minimum separation angle theta in degrees, in [0, 179] (default 45). 0 is the exact
  /// medial axis of the polyhedron.
  vtkSetClampMacro(MinimumSeparationAngle, double, 0.0, 179.0);
  vtkGetMacro(MinimumSeparationAngle, double);
  ///@}

  ///@{
  /// Largest depth, relative to the bounding-box diagonal, by which a ball may cross
  /// the surface (default 1e-4; 3D input). The MinimumSeparationAngle ignores the
  /// surface in the cap around P, so a ball can cross it there, where the shape curves
  /// faster than the ball. A ball that this surface enters deeper than
  /// MaximumProtrusion is shrunk about its centre until it only touches it: it stays on
  /// the smooth axis and becomes inscribed (it then no longer touches P; ContactPoint
  /// is where it touches). 0 shrinks every ball that crosses at all; 1 never shrinks:
  /// the angle rule alone (the behaviour before), whose balls cross the surface by up
  /// to 0.47% (horse.ply) to 1.9% (the open bunny) of the diagonal. Chosen by
  /// measurement (docs/how-it-works/inscribed-balls.md).
  vtkSetClampMacro(MaximumProtrusion, double, 0.0, 1.0);
  vtkGetMacro(MaximumProtrusion, double);
  ///@}

  ///@{
  /// Measure how far the balls cross the surface while they are solved (default off;
  /// 3D input, RANDOM strategy). The output then gets field data MaxProtrusion, the
  /// largest protrusion r - d(c) of its balls (d(c): the distance from the centre to the
  /// surface) relative to the diagonal, 0 when none crosses (also GetMaxProtrusion()):
  /// the figure vtkMedialBallProtrusion computes, equal to it within the queries'
  /// slack (1e-12 of the diagonal), at a fraction of the cost. The one-pass method reads
  /// it from its own cap search (away from the cap its balls are empty by
  /// construction; a ball shrunk to be inscribed only touches): each chain of samples
  /// keeps a running maximum, and a ball is searched only as deep as the surface would
  /// have to enter to raise it, so the search is the one that decides the shrinking,
  /// reaching a little further. The other methods ask a closest-point query the same
  /// way. The balls do not change. In parallel pipelines each piece measures its own
  /// balls. The iterative strategies and 2D input leave it unmeasured.
  vtkSetMacro(MeasureProtrusion, vtkTypeBool);
  vtkGetMacro(MeasureProtrusion, vtkTypeBool);
  vtkBooleanMacro(MeasureProtrusion, vtkTypeBool);
  ///@}

  ///@{
  /// Seed of the per-sample random streams (default 1). Signed, because ParaView's
  /// client-server wrapping cannot pass an unsigned 64-bit argument.
  vtkSetClampMacro(RandomSeed, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(RandomSeed, vtkTypeInt64);
  ///@}

  ///@{
  /// OpenMP threads; 0 means all cores (default 0). The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// What the preparation does with a 3D surface that is not a valid solid:
  /// vtkMedialRepairFilter's modes. AUTO (default): it is checked (a valid solid is
  /// sampled as it is, bit for bit as with NONE) and repaired when it is not one; NONE:
  /// no check and no repair (warnings about the input instead); WRAP: the alpha wrap of
  /// the input is sampled. Planar input (the 2D mode) is never repaired.
  vtkSetClampMacro(RepairMode, int, 0, 2);
  vtkGetMacro(RepairMode, int);
  ///@}

  ///@{
  /// The repair run when RepairMode asks for it (default: a vtkMedialRepairFilter with
  /// its defaults; this filter sets its input, Mode, ReportSteps and NumberOfThreads).
  /// After an update, SurfaceRepaired tells whether the balls are those of its output.
  virtual void SetRepair(vtkMedialRepairFilter*);
  vtkGetObjectMacro(Repair, vtkMedialRepairFilter);
  vtkGetMacro(SurfaceRepaired, bool);
  ///@}

  ///@{
  /// Iteration cap of the shrinking ball (default 100). Capped samples are counted.
  vtkSetClampMacro(MaximumIterations, int, 1, 100000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /// True when `input` is sampled in the 2D mode (see above), which is also the input
  /// of vtkMedialJunctionFilter: polygons only, whose points all lie within 1e-6 of
  /// the bounding-box diagonal from their least-squares plane (and not all that close
  /// to one line), or polylines only, of
  /// which one is closed or which come in 3 or more pieces (they must then chain into
  /// coplanar loops, or the sampler reports why not). The second form also gives
  /// that plane: the points' centroid and unit normal.
  static bool IsPlanarInput(vtkPolyData* input);
  static bool IsPlanarInput(vtkPolyData* input, double centre[3], double normal[3]);
  ///@}

  ///@{
  /// Figures from the last execution.
  vtkGetMacro(DiscardedSamples, vtkIdType);
  vtkGetMacro(CappedSamples, vtkIdType);
  vtkGetMacro(MeanIterations, double);
  vtkGetMacro(BoundaryEdges, vtkIdType);
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  /// Samples whose ball was solved (the budget used; seeds included).
  vtkGetMacro(EvaluatedSamples, vtkIdType);
  /// Poisson-disk seeds among them (iterative strategies).
  vtkGetMacro(SeedSamples, vtkIdType);
  /// Coverage figures, when measured (see CoverageTolerance); the gap is relative
  /// to the diagonal, -1 when not measured.
  vtkGetMacro(CoverageReached, bool);
  vtkGetMacro(MaxCoverageGap, double);
  /// The largest protrusion relative to the diagonal, when measured (see
  /// MeasureProtrusion); -1 when not measured.
  vtkGetMacro(MaxProtrusion, double);
  ///@}

  /// Includes the repair's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkMedialAxisSampler();
  ~vtkMedialAxisSampler() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfSamples = 10000;
  int Method = ONE_PASS;
  double Tolerance = 1e-6;
  double MinimumSeparationAngle = 45.0;
  double MaximumProtrusion = 1e-4;
  vtkTypeInt64 RandomSeed = 1;
  int NumberOfThreads = 0;
  int MaximumIterations = 100;
  int SamplingStrategy = RANDOM;
  double CoverageTolerance = 0.0;
  double SeedFraction = 0.25;
  int RepairMode = 0;
  vtkMedialRepairFilter* Repair = nullptr;
  bool SurfaceRepaired = false;
  vtkTypeBool MeasureProtrusion = 0;

  vtkIdType DiscardedSamples = 0;
  vtkIdType CappedSamples = 0;
  double MeanIterations = 0.0;
  vtkIdType BoundaryEdges = 0;
  vtkIdType NumberOfTriangles = 0;
  vtkIdType EvaluatedSamples = 0;
  vtkIdType SeedSamples = 0;
  bool CoverageReached = false;
  double MaxCoverageGap = -1.0;
  double MaxProtrusion = -1.0;

private:
  // The passes of RequestData (vtkMedialAxisSamplerInternals.h; not installed).
  class vtkInternals;

  vtkMedialAxisSampler(const vtkMedialAxisSampler&) = delete;
  void operator=(const vtkMedialAxisSampler&) = delete;
};

#endif
