// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallClassifier
 * @brief Governors and 3D medial point types of medial balls, and the exact seam
 * points and junction vertices between them.
 *
 * Algorithm:
 *  1. The surface (input 1) is prepared as by vtkMedialAxisSampler and split into
 *     features: planes (coplanar faces), lines (sharp edges) and points (vertices).
 *  2. Each ball (input 0: points with a Radius array; an optional SurfacePoint
 *     array gives the sample P the ball is tangent at) gets its governors: the
 *     connected regions of surface within Tolerance * diagonal of its sphere. A ball
 *     the sampler shrank to be inscribed (|C - P| > Radius) is read through its
 *     angle-rule sphere of radius |C - P|, whose contacts it stands for. With
 *     theta = MinimumSeparationAngle > 0 the sampler's rule applies: the contacts
 *     less than theta from P, seen from the centre, are one governor (P's cap; the
 *     surface the ball overlaps is there), and other regions less than theta apart
 *     count as one. At theta = 0 on a polyhedron a governor is a face, a reflex edge
 *     or a reflex vertex. GovernorCount is their number and
 *     MedialPointType the 3D code: 0 rim (at most one governor, or a radius within
 *     the tolerance: the free boundary of a sheet, where the radius goes to zero or
 *     the sheet ends at a convex edge or a ridge flatter than 180 - theta degrees),
 *     1 sheet (2), 2 seam (3), 3 junction (4 or more).
 *  3. With ComputeExactPoints, between the NumberOfNeighbors nearest balls whose
 *     governor sets differ, the balls tangent to three governors (seam points) and
 *     to four (junction vertices) are solved exactly: planes give linear equations,
 *     reflex edges and vertices quadratics (closed form when one quadratic is left,
 *     Newton's method from the neighbours otherwise), and every solution is checked
 *     to be empty and to touch its governors within 1e-9 of the diagonal. Junctions
 *     are also solved where two found seams share two governors, and every seam found
 *     is followed to its ends (MaximumTracedSeams), where the next junctions are
 *     solved and the seams that meet there are followed in turn. On a polyhedron at
 *     theta = 0 the junction vertices are exact up to rounding; on a convex one they
 *     are the vertices of its 3D straight skeleton. Governors made of several
 *     features (theta-merged regions of a tessellated smooth surface) have no exact
 *     equation; balls with one are not solved.
 *
 * Inputs: port 0, the balls (vtkPolyData points, e.g. vtkMedialAxisSampler's
 * output) with a radius array, chosen with SetInputArrayToProcess(0, ...) and by
 * default the point data array Radius (and optionally SurfacePoint); port 1, the closed
 * surface they were computed from (SetSurfaceConnection). Balls should come from the
 * same theta; with BISECTION balls use a Tolerance above the sampler's.
 *
 * Outputs: port 0, the balls (shallow copy) with point data GovernorCount (int) and
 * MedialPointType (int); port 1, the exact seam points and junction vertices as
 * vertices, merged within 1e-9 of the diagonal, with point data Radius (double),
 * MedialPointType (2 seam, 3 junction) and GovernorCount (int).
 *
 * Output is identical for any thread count.
 *
 * Pieces (see vtkMedialPieces.h): contacts need the whole surface and the exact
 * points neighbouring balls, so every piece asks for both whole inputs and piece 0
 * classifies every ball; the other pieces are empty.
 *
 * @sa vtkMedialAxisSampler vtkMedialJunctionFilter
 */
#ifndef vtkMedialBallClassifier_h
#define vtkMedialBallClassifier_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkMedialSurfaceQuery;

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialBallClassifier : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallClassifier* New();
  vtkTypeMacro(vtkMedialBallClassifier, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// MedialPointType's 3D codes.
  enum PointTypes
  {
    RIM = 0,     ///< at most one governor: a sheet's free boundary
    SHEET = 1,   ///< two governors
    SEAM = 2,    ///< three governors: where sheets meet
    JUNCTION = 3 ///< four or more governors: where seams meet
  };

  ///@{
  /// The surface the balls belong to (input port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSurfaceData(vtkDataObject* surface) { this->SetInputData(1, surface); }
  ///@}

  ///@{
  /// Contact tolerance relative to the bounding-box diagonal (default 1e-6).
  vtkSetClampMacro(Tolerance, double, 1e-15, 1e-2);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Minimum separation angle theta in degrees, in [0, 179] (default 45, the sampler's).
  vtkSetClampMacro(MinimumSeparationAngle, double, 0.0, 179.0);
  vtkGetMacro(MinimumSeparationAngle, double);
  ///@}

  ///@{
  /// Solve the exact seam points and junction vertices (output 1; default on).
  vtkSetMacro(ComputeExactPoints, bool);
  vtkGetMacro(ComputeExactPoints, bool);
  vtkBooleanMacro(ComputeExactPoints, bool);
  ///@}

  ///@{
  /// Neighbours of each ball compared for governor changes (default 12).
  vtkSetClampMacro(NumberOfNeighbors, int, 1, 1000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /// Seams followed to their ends at most (default 20000; 0: none). Tracing makes the
  /// junctions complete on polyhedra; on finely tessellated surfaces at theta = 0 the
  /// exact medial axis has as many seams as facet triples, and the budget bounds the
  /// work (a warning says when it was reached).
  vtkSetClampMacro(MaximumTracedSeams, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumTracedSeams, vtkIdType);
  ///@}

  ///@{
  /// OpenMP threads; 0 means all cores (default 0). The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Figures from the last execution: balls of each type (untouched balls, which
  /// touch no surface within the tolerance, are also rims), the exact points, and
  /// the seams traced.
  vtkGetMacro(NumberOfRimBalls, vtkIdType);
  vtkGetMacro(NumberOfSheetBalls, vtkIdType);
  vtkGetMacro(NumberOfSeamBalls, vtkIdType);
  vtkGetMacro(NumberOfJunctionBalls, vtkIdType);
  vtkGetMacro(NumberOfUntouchedBalls, vtkIdType);
  vtkGetMacro(NumberOfSeamPoints, vtkIdType);
  vtkGetMacro(NumberOfJunctionVertices, vtkIdType);
  vtkGetMacro(NumberOfTracedSeams, vtkIdType);
  ///@}

protected:
  vtkMedialBallClassifier();
  ~vtkMedialBallClassifier() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Tolerance = 1e-6;
  double MinimumSeparationAngle = 45.0;
  bool ComputeExactPoints = true;
  int NumberOfNeighbors = 12;
  vtkIdType MaximumTracedSeams = 20000;
  int NumberOfThreads = 0;

  vtkIdType NumberOfRimBalls = 0;
  vtkIdType NumberOfSheetBalls = 0;
  vtkIdType NumberOfSeamBalls = 0;
  vtkIdType NumberOfJunctionBalls = 0;
  vtkIdType NumberOfUntouchedBalls = 0;
  vtkIdType NumberOfSeamPoints = 0;
  vtkIdType NumberOfJunctionVertices = 0;
  vtkIdType NumberOfTracedSeams = 0;

  // vtkMedialMeshFilter runs this classifier on the surface it has just prepared and
  // lends it its queries for that execution (built by vtkMedialTriangleMesh and
  // vtkMedialSurfaceQuery from the same surface, as here), so that the surface is not
  // prepared twice. Null otherwise: the surface on input 1 is prepared here.
  friend class vtkMedialMeshFilter;
  const vtkMedialSurfaceQuery* PreparedSurface = nullptr;

private:
  vtkMedialBallClassifier(const vtkMedialBallClassifier&) = delete;
  void operator=(const vtkMedialBallClassifier&) = delete;
};

#endif
