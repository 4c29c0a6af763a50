// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialThickness
 * @brief Wall thickness on a closed surface that facets, ripples and sharp edges do
 * not spoil: at every vertex (and cell), the diameter of the largest inscribed ball
 * that touches the surface near it, or at a convex edge the thickness of the walls that
 * meet there.
 *
 * What is measured, at a point x of the surface of the solid:
 *  - Hildebrand and Rüegsegger's local thickness of a point of a solid is the diameter
 *    of the largest ball inside the solid that contains it; at x, of the largest
 *    inscribed ball that touches x (TangentThickness approximates it, as this filter
 *    did before). On a tessellated surface that ball is shrunk by any facet's tilt or
 *    ripple near x, while a slightly moved ball of the full size touches the surface a
 *    hair away. So Thickness takes it with a tolerance: the largest inscribed ball whose
 *    sphere comes within tau of x (|centre - x| - radius <= tau), tau = SurfaceTolerance
 *    times the local facet size (the longest edge at x; a cell's largest triangle's
 *    longest edge): the largest local thickness over the solid within tau of x.
 *  - Walls: the surface split along its creases, edges where adjacent faces' normals
 *    are more than CreaseAngle apart. Near a convex crease (an edge or a corner of a
 *    part), the balls that touch x only round the edge: they get smaller the nearer x
 *    is to it, down to 0 on it, whatever the thickness of the walls that meet there. A
 *    ball whose contacts lie on walls meeting along convex creases, and are less than
 *    120 degrees apart seen from its centre, is such a rounding ball; the filter lets it
 *    slide away from them (while it stays within its own radius of x) until it touches
 *    a wall across (contacts 120 degrees or more apart): its size is then the walls'. On
 *    a box every vertex, face, edge or corner gets the box's smallest dimension; a
 *    wedge whose faces meet at less than 60 degrees (a knife's edge) stays thin, as it is.
 * Only the solid's own surface bounds a ball: Thickness is never larger than a ball
 * that fits. The search below is local (an ascent from the tangent ball), so it finds
 * a local maximum of those definitions, as the sampler's balls are; it may miss a
 * larger ball within tau reached only by moving against a contact first.
 *
 * Algorithm, in passes:
 *  1. Preparation: the input becomes a solid (vtkMedialTriangleMesh: triangulated,
 *     coincident points merged, shells oriented by nesting so that the cavities of a
 *     hollow part and several bodies in one file count), and its surface queries are
 *     built (vtkMedialSurfaceQuery).
 *  2. VertexNormals: the mean of the adjacent triangles' normals with Max's weights
 *     (area vector over the product of the two edge lengths squared: exact for
 *     vertices on a sphere, so a tessellated sphere's balls are centred), and the
 *     spread, the largest angle between two adjacent triangles' normals.
 *  3. Walls: the triangles joined across every edge that is not a crease (union-find),
 *     and the pairs of walls that meet along a convex crease. A crease that fades out
 *     (its faces less than CreaseAngle apart at its end) leaves one wall on both its
 *     sides; for a wall with a crease inside it, whether two contacts lie on walls
 *     meeting along a convex crease is asked near the ball: the triangles joined to
 *     each across smooth edges within 2.5 radii of its centre, and a convex crease edge
 *     between them; answered by searches that stop at the other contact (at most 8192
 *     triangles each, beyond which the whole wall's answer stands).
 *  4. VertexBalls: the tangent ball, the maximal ball tangent at each vertex along its
 *     inward normal, by the sampler's one-pass solver and its rules
 *     (MinimumSeparationAngle theta, and MaximumProtrusion: a ball that crosses the
 *     surface around the vertex deeper is shrunk about its centre until inscribed; see
 *     vtkMedialAxisSampler). At a sharp vertex (spread above theta) it is solved along
 *     each adjacent triangle's normal and the smallest is kept (0 at a convex edge or
 *     corner, and on a closed surface's folds, where every direction leaves the solid
 *     at once). Then the grown ball (vtkMedialGrowBall): a tangent ball that was shrunk,
 *     or that a wall beside the vertex's stopped (its contact less than 120 degrees
 *     away, on a wall meeting the vertex's along a convex crease), moves its centre
 *     away from its contacts along the direction that increases its distance to all of
 *     them fastest, and grows while it stays inscribed and within tau of the vertex
 *     (one step of one ray and one closest-point query), or while it slides as above;
 *     at a sharp vertex it starts from a small ball in the wedge of the faces there.
 *     The same pass casts the ray along the inward normal for RayThickness.
 *  5. CellBalls (ComputeCellThickness, or ThinThreshold > 0): the same at the centroid
 *     of each cell's largest triangle, along that triangle's normal (the grown ball from
 *     the smooth surface's normal there); a corner's ball that comes as near the
 *     centroid as to its own vertex (or within tau) counts too.
 *  6. ThinRegions (ThinThreshold > 0): the cells whose Thickness is below the
 *     threshold, their share of the area and the number of regions they form
 *     (connected through shared vertices).
 *
 * Input: vtkPolyData with polygons or strips, a closed surface. With RepairMode AUTO
 * (the default) a surface that is not a valid solid is repaired first
 * (vtkMedialRepairFilter, GetRepair) and the output is then the repaired surface with
 * the arrays (SurfaceRepaired; the repair's report joins the field data). With NONE
 * an open surface is accepted with a warning; where the inward ray escapes, the
 * values are NaN.
 *
 * Output: the input (points, cells and their data) with point data and, with
 * ComputeCellThickness, cell data:
 *  - Thickness (double): the grown ball's diameter, 2 MedialRadius;
 *  - MedialRadius (double) and MedialCentre (double x3): that ball;
 *  - TangentThickness (double): the tangent ball's diameter (0 at convex edges);
 *  - RayThickness (double): the distance along the inward normal to the surface
 *    beyond, the usual "ray" (shape-diameter style) thickness; at least
 *    TangentThickness.
 * NaN where no value exists (ray escaped; a point that no cell uses). With
 * ThinThreshold > 0, field data ThinAreaFraction and ThinRegionCount (from the cells'
 * Thickness).
 *
 * Deterministic: the output does not depend on NumberOfThreads.
 *
 * Pieces (see vtkMedialPieces.h): rays need the whole surface, so every piece asks for
 * the whole input and piece 0 measures it all; the other pieces are empty.
 *
 * @sa vtkMedialAxisSampler
 */
#ifndef vtkMedialThickness_h
#define vtkMedialThickness_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <limits> // for std::numeric_limits
#include <vector> // for std::vector

class vtkMedialRepairFilter;
class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;
struct vtkMedialBallParameters;

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialThickness : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialThickness* New();
  vtkTypeMacro(vtkMedialThickness, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// Minimum separation angle theta in degrees, in [0, 179] (default 45, as the
  /// sampler's). Also the spread of the face normals above which a vertex is sharp.
  vtkSetClampMacro(MinimumSeparationAngle, double, 0.0, 179.0);
  vtkGetMacro(MinimumSeparationAngle, double);
  ///@}

  ///@{
  /// Largest depth, relative to the bounding-box diagonal, by which a ball may cross
  /// the surface (default 1e-4, as the sampler's): a ball that the surface around the
  /// vertex enters deeper is shrunk about its centre until inscribed (see
  /// vtkMedialAxisSampler). 1: never shrink.
  vtkSetClampMacro(MaximumProtrusion, double, 0.0, 1.0);
  vtkGetMacro(MaximumProtrusion, double);
  ///@}

  ///@{
  /// How near its vertex (or cell centre) a ball must come, relative to the local facet
  /// size (the longest edge at the vertex; the cell's largest triangle's longest edge),
  /// in [0, 10] (default 0.25). See the class comment.
  vtkSetClampMacro(SurfaceTolerance, double, 0.0, 10.0);
  vtkGetMacro(SurfaceTolerance, double);
  ///@}

  ///@{
  /// Angle between adjacent faces' normals, in degrees in [0, 90] (default 20), above
  /// which their common edge is a crease between two walls. See the class comment.
  vtkSetClampMacro(CreaseAngle, double, 0.0, 90.0);
  vtkGetMacro(CreaseAngle, double);
  ///@}

  ///@{
  /// Also compute the cell data (default on): one more ball per cell.
  vtkSetMacro(ComputeCellThickness, bool);
  vtkGetMacro(ComputeCellThickness, bool);
  vtkBooleanMacro(ComputeCellThickness, bool);
  ///@}

  ///@{
  /// Thickness below which a cell counts as thin, in the input's units (default 0:
  /// off). Above 0, the output's field data holds ThinAreaFraction and ThinRegionCount.
  vtkSetClampMacro(ThinThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ThinThreshold, double);
  ///@}

  ///@{
  /// OpenMP threads; 0 means all cores (default 0). The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// What is done with a surface that is not a valid solid (vtkMedialRepairFilter's
  /// modes): AUTO (default) checks it and measures the solid its repair makes of it
  /// when it is not one; NONE neither checks nor repairs; WRAP measures its alpha wrap.
  vtkSetClampMacro(RepairMode, int, 0, 2);
  vtkGetMacro(RepairMode, int);
  virtual void SetRepair(vtkMedialRepairFilter*);
  vtkGetObjectMacro(Repair, vtkMedialRepairFilter);
  /// True when the last update measured (and output) the repaired surface.
  vtkGetMacro(SurfaceRepaired, bool);
  ///@}

  /// Includes the repair's modification time.
  vtkMTimeType GetMTime() override;

  ///@{
  /// Figures from the last execution.
  /// Vertices whose adjacent face normals spread more than theta.
  vtkGetMacro(SharpVertices, vtkIdType);
  /// Input points without a value (NaN): the ray escaped, or no cell uses them.
  vtkGetMacro(MissingPoints, vtkIdType);
  /// Share of the area of the cells thinner than ThinThreshold, in [0, 1].
  vtkGetMacro(ThinAreaFraction, double);
  /// Vertex-connected regions of those cells.
  vtkGetMacro(ThinRegionCount, vtkIdType);
  ///@}

protected:
  vtkMedialThickness();
  ~vtkMedialThickness() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// A ball and the ray along its direction, per prepared vertex or per cell; every
  /// field NaN until measured (a cell without a triangle, a point no cell uses).
  struct Measure
  {
    static constexpr double Unmeasured = std::numeric_limits<double>::quiet_NaN();
    double Radius = Unmeasured;
    double Centre[3] = { Unmeasured, Unmeasured, Unmeasured };
    double Ray = Unmeasured;
    double TangentRadius = Unmeasured;
    // A vertex's ball by the plain ascent alone (vtkMedialGrowBall), where it slid: a
    // cell may take it from its corner when the larger ball lies too far from the cell.
    double PlainRadius = Unmeasured;
    double PlainCentre[3] = { Unmeasured, Unmeasured, Unmeasured };
    // Its ball without the ascent's robust rules (vtkMedialGrowBall's `kept`): a cell may
    // take that one too, where the robust ball went farther from it.
    double KeptRadius = Unmeasured;
    double KeptCentre[3] = { Unmeasured, Unmeasured, Unmeasured };
    // Its ball without the ascent's thorough rules (vtkMedialGrowBall's `prior`): where
    // those moved the vertex's ball farther from a cell, that cell may take this one.
    double PriorRadius = Unmeasured;
    double PriorCentre[3] = { Unmeasured, Unmeasured, Unmeasured };
  };
  // The surface split along its creases, and which parts meet along a convex one.
  struct Walls;

  // Pass 2: unit inward normals and sharpness of the prepared mesh's vertices.
  void VertexNormals(const vtkMedialTriangleMesh& mesh, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, std::vector<double>& normals, std::vector<char>& sharp);
  // Pass 3: one Measure per prepared vertex. False when aborted.
  bool VertexBalls(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialBallParameters& param, const Walls& walls, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, const std::vector<double>& normals,
    const std::vector<char>& sharp, std::vector<Measure>& measures);
  // Pass 4: one Measure per input cell (NaN for cells without a triangle). False when aborted.
  bool CellBalls(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialBallParameters& param, const Walls& walls, vtkIdType cells,
    const std::vector<Measure>& corners, std::vector<Measure>& measures);
  // The measures as point data (input points mapped to prepared vertices by their
  // coordinates) and cell data; counts MissingPoints.
  void WriteArrays(vtkPolyData* output, const vtkMedialTriangleMesh& mesh,
    const std::vector<Measure>& vertices, const std::vector<Measure>& cells);
  // Pass 5: ThinAreaFraction and ThinRegionCount from the cells' thickness.
  void ThinRegions(const vtkMedialTriangleMesh& mesh, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, const std::vector<Measure>& cells);

  double MinimumSeparationAngle = 45.0;
  double MaximumProtrusion = 1e-4;
  double SurfaceTolerance = 0.25;
  double CreaseAngle = 20.0;
  bool ComputeCellThickness = true;
  double ThinThreshold = 0.0;
  int NumberOfThreads = 0;
  int RepairMode = 0;
  vtkMedialRepairFilter* Repair = nullptr;
  bool SurfaceRepaired = false;

  vtkIdType SharpVertices = 0;
  vtkIdType MissingPoints = 0;
  double ThinAreaFraction = 0.0;
  vtkIdType ThinRegionCount = 0;

private:
  vtkMedialThickness(const vtkMedialThickness&) = delete;
  void operator=(const vtkMedialThickness&) = delete;
};

#endif
