// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialReconstructionError
 * @brief How far a reconstruction lies from the original shape, in both directions.
 *
 * Input 0: the original shape (vtkPolyData): a surface, or planar loops (2D).
 * Input 1: the reconstruction (vtkPolyData), e.g. vtkMedialBallUnion's output 0.
 *
 * Two measures, each in both directions (reconstruction to original, original to
 * reconstruction), as the largest and the mean distance, relative to the diagonal of
 * the original's bounding box:
 *  - vertex: from every point of one shape to the other's boundary. Between its
 *    vertices a surface may stray further, by at most its edge length;
 *  - area: from NumberOfAreaSamples points spread uniformly over one boundary (by
 *    area; by length for curves) to the other's. Point i comes from the random
 *    stream (RandomSeed, i): the same points for any thread count.
 * The two-sided (Hausdorff) figures are the larger of the two directions.
 *
 * The boundary is the original's polygons and strips, triangulated; when the original
 * is planar loops (the 2D mode of vtkMedialAxisSampler), it is the edges of both
 * inputs' polygons and polylines instead, so a point inside a polygon is not at
 * distance 0. Distances are exact (double precision) closest-point distances: to
 * triangles through the project's own BVH (vtkMedialSurfaceQuery; DistanceEngine
 * BVH, the default) or through vtkStaticCellLocator over the inputs' cells as they
 * are (CELL_LOCATOR: about 8 times slower per query on a 97k-triangle mesh, cheaper to
 * build), to segments through vtkStaticCellLocator. Computed in parallel
 * (NumberOfThreads); the results do not depend on the thread count.
 *
 * Output 0: the reconstruction, with point data `SurfaceDistance` (each vertex's
 * distance to the original, in model units, to colour it by error) and field data
 * `VertexMaxError`, `VertexMeanError`, `AreaMaxError`, `AreaMeanError` (two
 * components each: reconstruction to original, original to reconstruction; relative
 * to the diagonal). Output 1: the original, with point data `SurfaceDistance` (each
 * vertex's distance to the reconstruction). The same figures come from the getters
 * after an update (NaN after a failed one).
 *
 * An input without points or cells, or with non-finite coordinates, is an error.
 *
 * Pieces (see vtkMedialPieces.h): distances need entire shapes, so every piece asks
 * for both whole inputs and piece 0 measures; the other pieces are empty. Upstream
 * filters then run whole on every process.
 *
 * @sa vtkMedialBallUnion vtkMedialBallProtrusion
 */
#ifndef vtkMedialReconstructionError_h
#define vtkMedialReconstructionError_h

#include "vtkMedialAxisReconstructionModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISRECONSTRUCTION_EXPORT vtkMedialReconstructionError : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialReconstructionError* New();
  vtkTypeMacro(vtkMedialReconstructionError, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// Index of the direction in the two-component results.
  enum Directions
  {
    RECONSTRUCTION_TO_ORIGINAL = 0, ///< from the reconstruction's points to the original
    ORIGINAL_TO_RECONSTRUCTION = 1  ///< from the original's points to the reconstruction
  };

  ///@{
  /// The inputs: the original shape (port 0) and its reconstruction (port 1).
  void SetOriginalConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetOriginalData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetReconstructionConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetReconstructionData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

  /// What answers the closest-point queries on surfaces.
  enum DistanceEngines
  {
    BVH = 0,         ///< the project's own BVH (vtkMedialSurfaceQuery)
    CELL_LOCATOR = 1 ///< vtkStaticCellLocator over the inputs' cells
  };

  ///@{
  /// The engine of the distances to a surface (default BVH). Planar loops always use
  /// vtkStaticCellLocator over their edges.
  vtkSetClampMacro(DistanceEngine, int, BVH, CELL_LOCATOR);
  vtkGetMacro(DistanceEngine, int);
  void SetDistanceEngineToBVH() { this->SetDistanceEngine(BVH); }
  void SetDistanceEngineToCellLocator() { this->SetDistanceEngine(CELL_LOCATOR); }
  ///@}

  ///@{
  /// Points spread over each boundary for the area measure (default 100000; 0 skips it).
  vtkSetClampMacro(NumberOfAreaSamples, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfAreaSamples, vtkIdType);
  ///@}

  ///@{
  /// Seed of the area samples' random streams (default 1). Signed, as the sampler's:
  /// ParaView's client-server wrapping cannot pass an unsigned 64-bit argument.
  vtkSetClampMacro(RandomSeed, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(RandomSeed, vtkTypeInt64);
  ///@}

  ///@{
  /// OpenMP threads; 0 (default) uses every core.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Results per direction (index by Directions), relative to the original's diagonal.
  vtkGetVector2Macro(VertexMaxError, double);
  vtkGetVector2Macro(VertexMeanError, double);
  vtkGetVector2Macro(AreaMaxError, double);
  vtkGetVector2Macro(AreaMeanError, double);
  ///@}

  ///@{
  /// Two-sided results: the larger of the two directions.
  double GetVertexHausdorff() const { return Larger(this->VertexMaxError); }
  double GetVertexMeanHausdorff() const { return Larger(this->VertexMeanError); }
  double GetAreaHausdorff() const { return Larger(this->AreaMaxError); }
  double GetAreaMeanHausdorff() const { return Larger(this->AreaMeanError); }
  ///@}

  /// The diagonal of the original's bounding box that the results are relative to.
  vtkGetMacro(Diagonal, double);

protected:
  vtkMedialReconstructionError();
  ~vtkMedialReconstructionError() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int DistanceEngine = BVH;
  vtkIdType NumberOfAreaSamples = 100000;
  vtkTypeInt64 RandomSeed = 1;
  int NumberOfThreads = 0;

  double VertexMaxError[2];
  double VertexMeanError[2];
  double AreaMaxError[2];
  double AreaMeanError[2];
  double Diagonal = 0.0;

private:
  vtkMedialReconstructionError(const vtkMedialReconstructionError&) = delete;
  void operator=(const vtkMedialReconstructionError&) = delete;

  static double Larger(const double pair[2]) { return pair[0] > pair[1] ? pair[0] : pair[1]; }
  void ResetResults();
};

#endif
