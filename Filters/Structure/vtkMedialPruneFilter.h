// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPruneFilter
 * @brief Removes the insignificant branches of a medial axis without changing its
 * topology: the 2D medial graph (vtkMedialJunctionFilter) or the 3D medial mesh
 * (vtkMedialMeshFilter).
 *
 * Measures (Measure; every one is stored, per cell, in the output array Significance):
 *  - EROSION_THICKNESS (Liu et al. 2011; Yan et al. 2016): the medial axis burns from
 *    its boundary, which starts at its radius, at unit speed along the axis, a junction
 *    (a seam in 3D) burning once all but one of its branches (sheets) have burnt. The
 *    erosion thickness B - R says how much the shape loses when the part is removed;
 *    relative to the diagonal of the balls' bounding box.
 *  - TUBULARITY: the erosion thickness relative to the burn time, (B - R) / B, in
 *    [0, 1] (Liu et al.'s shape tubularity): scale-free.
 *  - LAMBDA (Chazal and Lieutier's lambda-medial axis): the radius of the smallest ball
 *    enclosing a point's contacts, R sin(theta / 2), relative to the diagonal. From the
 *    slope of the radius (|grad R| = cos(theta / 2) on the medial axis).
 *  - SEPARATION_ANGLE: the angle theta between the contacts, in degrees: scale-free.
 *  - SCALE_AXIS (Giesen et al.'s scale axis transform): with s the smallest factor at
 *    which the part's balls, scaled by s, are covered by the scaled balls next to it,
 *    1 - 1 / s in [0, 1]: scale-free.
 *
 * Algorithm, 2D (and any input without triangles: a graph of lines with a radius per
 * point): whole branches are removed (vtkMedialGraphPruning): the least significant leaf
 * (a branch from an end to a junction), one at a time, a junction left with two branches
 * joining them, measured along the branch from its end to its junction, until no leaf
 * is left. Branches between junctions and cycles are never removed.
 *
 * Algorithm, 3D (input with triangles: a medial mesh): elementary collapses
 * (vtkMedialComplexPruning), a triangle with its free edge or an edge with its free
 * end, least significant first; the burn time comes from the same collapses made in
 * order of time (the extended grassfire). A collapse is worth the largest value of the
 * measure over the simplex's balls (the angle measures: the simplex's own slope).
 *
 * Each cell's Significance is the threshold from which pruning removes it (the running
 * maximum of the removals), so thresholding Significance at t (keep >= t) gives the same
 * result as this filter with Threshold t. Cells that pruning never removes get the
 * measure's upper bound (GetMeasureUpperBound: 180 for the angle, 1 otherwise).
 *
 * Topology: only simplices with a free face are removed (a leaf at a junction of three
 * or more branches, in 2D), so components, cycles and (in 3D) the Euler characteristic
 * stay as they are.
 *
 * Input: vtkPolyData with a point-data radius (input array 0; default Radius), lines
 * (2D) and optionally triangles (3D). Output: the kept cells and the points they use,
 * with every input point array and the field data. 2D: the kept runs of each line with
 * its cell data, and MedialPointType (when present) from the kept lines (0 end, 1
 * regular, 2 junction). 3D: the layout of vtkMedialMeshFilter (vertex cells, curve and
 * seam lines, triangles; MedialCellType) and MedialPointType from the kept mesh (0 rim,
 * 1 sheet, 2 seam, 3 junction). Cell data Significance in both.
 *
 * @sa vtkMedialJunctionFilter vtkMedialMeshFilter vtkMedialSimplifyFilter
 */
#ifndef vtkMedialPruneFilter_h
#define vtkMedialPruneFilter_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialPruneFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialPruneFilter* New();
  vtkTypeMacro(vtkMedialPruneFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The significance measures (Measure; each is described in the class comment).
  enum Measures
  {
    EROSION_THICKNESS = 0, ///< B - R relative to the diagonal (Liu et al. 2011)
    TUBULARITY = 1,        ///< (B - R) / B, scale-free
    LAMBDA = 2,            ///< R sin(theta / 2) relative to the diagonal (Chazal and Lieutier)
    SEPARATION_ANGLE = 3,  ///< the angle theta between the contacts, in degrees
    SCALE_AXIS = 4         ///< 1 - 1 / s, s the covering scale (Giesen et al.)
  };

  ///@{
  /// The significance measure (default TUBULARITY).
  vtkSetClampMacro(Measure, int, EROSION_THICKNESS, SCALE_AXIS);
  vtkGetMacro(Measure, int);
  void SetMeasureToErosionThickness() { this->SetMeasure(EROSION_THICKNESS); }
  void SetMeasureToTubularity() { this->SetMeasure(TUBULARITY); }
  void SetMeasureToLambda() { this->SetMeasure(LAMBDA); }
  void SetMeasureToSeparationAngle() { this->SetMeasure(SEPARATION_ANGLE); }
  void SetMeasureToScaleAxis() { this->SetMeasure(SCALE_AXIS); }
  static const char* GetMeasureName(int measure);
  ///@}

  ///@{
  /// Cells whose Significance is below Threshold are removed. Negative (the default):
  /// the measure's default, GetDefaultThreshold(Measure). 0 removes nothing (the output
  /// is the input with its Significance).
  vtkSetMacro(Threshold, double);
  vtkGetMacro(Threshold, double);
  static double GetDefaultThreshold(int measure);
  /// The threshold used: Threshold, or the measure's default when Threshold is negative.
  double GetEffectiveThreshold() const;
  ///@}

  /// The largest value of a measure, given to the cells that pruning never removes.
  static double GetMeasureUpperBound(int measure);

  ///@{
  /// Figures from the last execution: removed branches (2D: leaves; 3D: connected
  /// pieces, simplices joined through the balls removed with them) and removed cells
  /// (2D: lines; 3D: triangles and edges).
  vtkGetMacro(NumberOfPrunedBranches, vtkIdType);
  vtkGetMacro(NumberOfPrunedCells, vtkIdType);
  ///@}

protected:
  vtkMedialPruneFilter();
  ~vtkMedialPruneFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // 2D (no triangles): levels per line segment, then the kept runs of each line.
  int PruneGraph(vtkPolyData* input, vtkDataArray* radius, double diagonal, vtkPolyData* output);
  // 3D (triangles): levels per simplex, then the kept medial mesh.
  int PruneMesh(vtkPolyData* input, vtkDataArray* radius, double diagonal, vtkPolyData* output);

  int Measure = TUBULARITY;
  double Threshold = -1.0;

  vtkIdType NumberOfPrunedBranches = 0;
  vtkIdType NumberOfPrunedCells = 0;

private:
  vtkMedialPruneFilter(const vtkMedialPruneFilter&) = delete;
  void operator=(const vtkMedialPruneFilter&) = delete;
};

#endif
