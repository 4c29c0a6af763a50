// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshFilter
 * @brief The medial mesh of a closed surface: medial balls joined by edges and
 * triangles into a connected complex with the topology of the solid.
 *
 * Algorithm:
 *  1. Balls: the ones on input port 1 when it is connected, otherwise the output of
 *     the Sampler (a vtkMedialAxisSampler; all its settings apply: theta, method,
 *     strategy, seed, number of samples, threads) run on the surface of port 0.
 *     Then, unless the Classifier is null, vtkMedialBallClassifier gives each ball
 *     its GovernorCount and MedialPointType, and its exact seam points and junction
 *     vertices join the balls (so that the mesh's junction vertices are the exact
 *     ones where they could be solved). The classifier runs on this filter's prepared
 *     surface (the one steps 2 to 4 query), not a second preparation of it. When this filter samples, the classifier
 *     takes the sampler's MinimumSeparationAngle (balls and governors must share it;
 *     with balls on port 1, set the classifier's to theirs), and always this filter's
 *     NumberOfThreads.
 *  2. Inscribed balls: each radius is lowered to the distance from its centre to the
 *     surface (an exact closest-point query), so every ball is inside the shape
 *     (sampler balls with a MinimumSeparationAngle above 0 may cross it slightly). On
 *     a closed surface, balls whose centre is outside are dropped with a warning.
 *  3. The regular (weighted Delaunay) triangulation of the centres with weights r^2
 *     and the dual complex of the union of balls (the alpha complex at alpha = 0),
 *     with CGAL (vtkMedialPowerComplex). Balls covered by the others are no vertex.
 *  4. The complex (vtkMedialMeshComplex): the nerve of the power cells restricted to
 *     the solid (which, unlike the union of balls, covers the solid without gaps),
 *     minus every simplex that crosses the surface; then voids are filled,
 *     components joined by edges inside the shape, triangles inside the shape
 *     spanning three edges of the complex added, and pieces that no edge inside the
 *     shape can join dropped (DetachedBalls); then tetrahedra are collapsed through
 *     free triangles, which keeps the homotopy type, and fins whose interpolated balls
 *     cross the surface by more than ProtrusionTolerance are pruned from their free
 *     sides (collapses too).
 *  4b. Envelope refinement (vtkMedialEnvelopeRefinement): edges whose cones and slabs
 *     cross the surface by more than EnvelopeTolerance are split with new inscribed
 *     balls at their midpoints (a subdivision: the topology does not change).
 *  5. Output assembly and classification.
 *
 * Guarantees:
 *  - No edge or triangle crosses the surface: each one lies in the union of its own
 *    (inscribed) balls or was tested against the surface triangles in double
 *    precision (vtkMedialSurfaceQuery; touching does not count).
 *  - Every vertex's ball is inscribed (step 2), exactly up to rounding.
 *  - Topology: the complex lies in the solid, so each of its components lies in one
 *    component of the solid, and steps 4's repairs only remove homology the solid
 *    does not have (voids, when the solid has no cavity, and short loops that
 *    bound inside it). It is homotopy equivalent to the solid when the restricted
 *    power cells form a good cover (their nonempty intersections contractible),
 *    which holds when the balls sample the medial axis densely against the local
 *    feature size. This is checked on every run rather than assumed: for a closed,
 *    manifold surface the solid's Euler characteristic is half the surface's, and
 *    EulerCharacteristic, NumberOfComponents, SolidEulerCharacteristic and
 *    SolidComponents are reported (a warning when they differ); a cavity counts with
 *    the body around it (a hollow sphere is one solid of characteristic 2). Measured
 *    equal on the four closed shared meshes and on generated solids of genus 0 to 3
 *    and a hollow sphere with the sampler's defaults (see docs/how-it-works/medial-mesh.md).
 *    Open surfaces have no solid: the result is built the same way (inside tests by
 *    ray parity are then unreliable near the holes) and nothing is promised.
 *
 * Pieces (vtkMedialPieces): first piece. The filter asks for the whole surface and
 * every ball, piece 0 builds the whole mesh, the other pieces stay empty.
 *
 * Input 0: vtkPolyData, a closed triangle surface (the sampler's rules apply).
 * Input 1 (optional): any vtkPointSet of balls with a point-data array `Radius`
 * (e.g. a vtkMedialAxisSampler's output, or balls read from a file).
 *
 * Output: vtkPolyData with double-precision points (the kept ball centres) and
 *  - point data: every array of the balls (Radius lowered as in step 2; on the exact
 *    points, arrays they do not have are NaN, or -1 for integers), with
 *    GovernorCount and MedialPointType (0 rim, 1 sheet, 2 seam, 3 junction) from the
 *    classifier. Without a classifier (and when the balls do not carry it),
 *    MedialPointType is read from the mesh instead: junction where three or more
 *    seam edges meet, seam on a seam edge (one with three or more triangles), rim on
 *    a rim edge (one triangle) or at the free end of a curve, sheet otherwise;
 *  - cells: a vertex for each isolated ball, lines for the 1D parts (edges of no
 *    triangle: tubes, where the medial surface degenerates to a curve) and for the
 *    seam edges, triangles for the sheets; cell data MedialCellType (0 isolated
 *    ball, 1 curve edge, 2 seam edge, 3 sheet triangle). Every edge of the complex
 *    is a line or a triangle side, so V - E + F counts each distinct edge once
 *    (vtkMedialMeshWriter writes them that way);
 *  - field data: EulerCharacteristic, Components, and for a closed manifold surface
 *    SolidEulerCharacteristic and SolidComponents.
 *
 * @sa vtkMedialAxisSampler vtkMedialMeshWriter vtkMedialBallUnion
 */
#ifndef vtkMedialMeshFilter_h
#define vtkMedialMeshFilter_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkDataArray;
class vtkMedialAxisSampler;
class vtkMedialBallClassifier;
class vtkMedialMeshComplex;
class vtkMedialRepairFilter;
class vtkMedialSurfaceQuery;
class vtkPointSet;

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialMeshFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialMeshFilter* New();
  vtkTypeMacro(vtkMedialMeshFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The codes of the cell-data array MedialCellType.
  enum CellTypes
  {
    ISOLATED_BALL = 0, ///< a vertex cell: a ball in no edge or triangle
    CURVE_EDGE = 1,    ///< a line of a medial curve (in no triangle)
    SEAM_EDGE = 2,     ///< a line where three or more sheets meet
    SHEET_TRIANGLE = 3 ///< a triangle of a medial sheet
  };

  ///@{
  /// The sampler run on input 0 when no balls are given on input 1 (default: a
  /// vtkMedialAxisSampler with its defaults). This filter sets its input.
  virtual void SetSampler(vtkMedialAxisSampler*);
  vtkGetObjectMacro(Sampler, vtkMedialAxisSampler);
  ///@}

  ///@{
  /// The classifier of the balls (default: a vtkMedialBallClassifier with its
  /// defaults); nullptr: no classification. This filter sets its inputs.
  virtual void SetClassifier(vtkMedialBallClassifier*);
  vtkGetObjectMacro(Classifier, vtkMedialBallClassifier);
  ///@}

  ///@{
  /// What the preparation does with a surface that is not a valid solid
  /// (vtkMedialRepairFilter's modes): AUTO (default) checks it and builds the mesh in
  /// the solid its repair (GetRepair) makes of it when it is not one (a valid solid is
  /// used as it is); NONE neither checks nor repairs; WRAP uses its alpha wrap. The
  /// sampler run by this filter samples the surface prepared here (its own RepairMode
  /// is not used); balls given on input 1 must come from that surface.
  vtkSetClampMacro(RepairMode, int, 0, 2);
  vtkGetMacro(RepairMode, int);
  virtual void SetRepair(vtkMedialRepairFilter*);
  vtkGetObjectMacro(Repair, vtkMedialRepairFilter);
  /// True when the last update built the mesh in the repaired surface (the repair's
  /// output, whose report joins this filter's field data).
  vtkGetMacro(SurfaceRepaired, bool);
  ///@}

  ///@{
  /// Balls on input 1 (optional); when set, the sampler is not run.
  void SetBallsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetBallsData(vtkDataObject* balls) { this->SetInputData(1, balls); }
  ///@}

  ///@{
  /// OpenMP threads for the mesh passes; 0 means all cores (default 0). The output does
  /// not depend on it. The sampler has its own setting.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Fins whose interpolated balls cross the surface by more than this (relative to the
  /// diagonal; default 1e-3) are pruned by collapses from their free sides (step 4);
  /// negative: no pruning.
  vtkSetClampMacro(ProtrusionTolerance, double, -1.0, 1.0);
  vtkGetMacro(ProtrusionTolerance, double);
  ///@}

  ///@{
  /// Edges whose envelope (the balls interpolated along them and their triangles)
  /// crosses the surface by more than this (relative to the diagonal; default 1e-3)
  /// are split at their midpoint with a new inscribed ball, until none does (step 4b,
  /// vtkMedialEnvelopeRefinement; at most as many new balls as there were); negative:
  /// no refinement. New balls have NaN (or -1) in the balls' arrays and their
  /// MedialPointType from the mesh.
  vtkSetClampMacro(EnvelopeTolerance, double, -1.0, 1.0);
  vtkGetMacro(EnvelopeTolerance, double);
  ///@}

  ///@{
  /// Figures from the last execution (see the class comment). The solid's figures are
  /// known (HasSolidTopology) only for a closed, manifold surface.
  vtkGetMacro(EulerCharacteristic, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  vtkGetMacro(NumberOfEdges, vtkIdType);
  vtkGetMacro(HasSolidTopology, bool);
  vtkGetMacro(SolidEulerCharacteristic, vtkIdType);
  vtkGetMacro(SolidComponents, vtkIdType);
  /// Balls dropped because their centre was outside the surface.
  vtkGetMacro(DroppedBalls, vtkIdType);
  /// Balls dropped because no edge inside the shape joined them to the rest of
  /// their solid component (see vtkMedialMeshComplex).
  vtkGetMacro(DetachedBalls, vtkIdType);
  /// Largest radius reduction of step 2, relative to the surface's diagonal.
  vtkGetMacro(MaximumRadiusReduction, double);
  /// Tetrahedra that could not be collapsed (dropped; 0 on every shape measured).
  vtkGetMacro(RemainingTetrahedra, vtkIdType);
  /// Triangles removed by the protrusion pruning.
  vtkGetMacro(PrunedTriangles, vtkIdType);
  /// Balls added by the envelope refinement, and the largest protrusion of the
  /// envelope through the surface left (relative to the diagonal).
  vtkGetMacro(RefinementBalls, vtkIdType);
  vtkGetMacro(EnvelopeProtrusion, double);
  ///@}

  /// Includes the sampler's, the classifier's and the repair's modification times.
  vtkMTimeType GetMTime() override;

protected:
  vtkMedialMeshFilter();
  ~vtkMedialMeshFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  struct BallSet;
  // Runs the sampler on a copy of the surface; null (after an error) when it fails.
  vtkSmartPointer<vtkPointSet> RunSampler(vtkPolyData* surface);
  // Governors and point types, and the exact seam and junction balls appended; null
  // (after an error) when the classifier fails. The classifier borrows `query`, this
  // filter's queries on `surface`, instead of preparing the surface again.
  vtkSmartPointer<vtkPointSet> Classify(
    vtkPointSet* balls, vtkPolyData* surface, const vtkMedialSurfaceQuery& query, bool sampled);
  // Runs a sub-filter (sampler, classifier) as the current stage: its progress is the
  // stage's and this filter's abort is passed on; false when it failed.
  bool RunStage(vtkAlgorithm* stage);
  // Step 2: radii lowered to the distance to the surface, outside centres dropped.
  bool InscribeBalls(vtkPointSet* balls, vtkDataArray* radius, const vtkMedialSurfaceQuery& query,
    bool closed, int threads, BallSet& set);
  // Step 5: points, point data, cells and their types.
  void WriteMesh(vtkPointSet* balls, const BallSet& set, const vtkMedialMeshComplex& complex,
    vtkPolyData* output);

  vtkMedialAxisSampler* Sampler = nullptr;
  vtkMedialBallClassifier* Classifier = nullptr;
  vtkMedialRepairFilter* Repair = nullptr;
  int RepairMode = 0;
  bool SurfaceRepaired = false;
  int NumberOfThreads = 0;
  double ProtrusionTolerance = 1e-3;
  double EnvelopeTolerance = 1e-3;

  vtkIdType EulerCharacteristic = 0;
  vtkIdType NumberOfComponents = 0;
  vtkIdType NumberOfEdges = 0;
  bool HasSolidTopology = false;
  vtkIdType SolidEulerCharacteristic = 0;
  vtkIdType SolidComponents = 0;
  vtkIdType DroppedBalls = 0;
  vtkIdType DetachedBalls = 0;
  double MaximumRadiusReduction = 0.0;
  vtkIdType RemainingTetrahedra = 0;
  vtkIdType PrunedTriangles = 0;
  vtkIdType RefinementBalls = 0;
  double EnvelopeProtrusion = 0.0;

private:
  vtkMedialMeshFilter(const vtkMedialMeshFilter&) = delete;
  void operator=(const vtkMedialMeshFilter&) = delete;
};

#endif
