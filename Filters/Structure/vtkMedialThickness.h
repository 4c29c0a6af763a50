// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialThickness
 * @brief Wall thickness on a closed surface: at every vertex, the diameter of the
 * largest inscribed ball that touches the surface there.
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
 *  3. VertexBalls: the maximal ball tangent at each vertex along its inward normal,
 *     by the sampler's one-pass solver and its rules (MinimumSeparationAngle theta, and
 *     MaximumProtrusion: a ball that crosses the surface around the vertex deeper is
 *     shrunk about its centre until inscribed; see vtkMedialAxisSampler). At a sharp vertex (spread above
 *     theta) the ball is solved along each adjacent triangle's normal and the smallest
 *     is kept; no ball fits at a convex sharp edge or corner, where the thickness is 0,
 *     nor on a closed surface's folds, where every direction leaves the solid at once.
 *     The same pass casts the ray along the inward normal for RayThickness.
 *  4. CellBalls (ComputeCellThickness, or ThinThreshold > 0): the same at the centroid
 *     of each cell's largest triangle, along that triangle's normal.
 *  5. ThinRegions (ThinThreshold > 0): the cells whose Thickness is below the
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
 *  - Thickness (double): the ball's diameter, 2 MedialRadius;
 *  - MedialRadius (double) and MedialCentre (double x3): the ball;
 *  - RayThickness (double): the distance along the inward normal to the surface
 *    beyond, the usual "ray" (shape-diameter style) thickness; at least Thickness.
 * NaN where no value exists (ray escaped; a point that no cell uses). With
 * ThinThreshold > 0, field data ThinAreaFraction and ThinRegionCount.
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

  /// A ball and the ray along its direction, per prepared vertex or per cell.
  struct Measure
  {
    double Radius;
    double Centre[3];
    double Ray;
  };

  // Pass 2: unit inward normals and sharpness of the prepared mesh's vertices.
  void VertexNormals(const vtkMedialTriangleMesh& mesh, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, std::vector<double>& normals, std::vector<char>& sharp);
  // Pass 3: one Measure per prepared vertex. False when aborted.
  bool VertexBalls(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialBallParameters& param, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, const std::vector<double>& normals,
    const std::vector<char>& sharp, std::vector<Measure>& measures);
  // Pass 4: one Measure per input cell (NaN for cells without a triangle). False when aborted.
  bool CellBalls(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialBallParameters& param, vtkIdType cells, std::vector<Measure>& measures);
  // The measures as point data (input points mapped to prepared vertices by their
  // coordinates) and cell data; counts MissingPoints.
  void WriteArrays(vtkPolyData* output, const vtkMedialTriangleMesh& mesh,
    const std::vector<Measure>& vertices, const std::vector<Measure>& cells);
  // Pass 5: ThinAreaFraction and ThinRegionCount from the cells' thickness.
  void ThinRegions(const vtkMedialTriangleMesh& mesh, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around, const std::vector<Measure>& cells);

  double MinimumSeparationAngle = 45.0;
  double MaximumProtrusion = 1e-4;
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
