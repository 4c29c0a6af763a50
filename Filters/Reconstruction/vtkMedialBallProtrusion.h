// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallProtrusion
 * @brief How far medial balls cross the surface they were sampled from.
 *
 * Input 0: the surface (vtkPolyData), or planar loops (2D).
 * Input 1: the balls (vtkPolyData): centres as points and a radius array, chosen with
 * SetInputArrayToProcess(0, ...) and by default the point data array `Radius`.
 *
 * A ball of centre c and radius r protrudes by r - d(c), d(c) the distance from c
 * to the boundary (the surface's triangles; in 2D the edges of the loops): positive
 * where the ball crosses the boundary, negative where it stays clear of it, 0 where
 * it touches. A sampler with MinimumSeparationAngle above 0 lets balls cross the
 * surface where it curves faster than the ball, and the union of the balls
 * (vtkMedialBallUnion) then leaves the shape by exactly the largest protrusion.
 * Distances are exact (double precision) closest-point distances, as in
 * vtkMedialReconstructionError, computed in parallel (NumberOfThreads); the results
 * do not depend on the thread count. Centres are assumed inside the shape.
 *
 * Output: the balls, with point data `Protrusion` (r - d(c), in model units) and field
 * data `MaxProtrusion`: the largest protrusion relative to the diagonal of the
 * surface's bounding box, 0 when no ball crosses (also from GetMaxProtrusion()).
 * No balls is no error: the output is empty and the largest protrusion 0.
 *
 * Each distance query starts bounded by the ball's radius (a ball that touches or
 * crosses the surface has d(c) <= r), and only a ball clear of the surface is asked
 * again without that bound. With MaximumOnly, only MaxProtrusion is computed (no
 * `Protrusion` array), still exactly but several times faster: a running maximum M
 * bounds each query to r - M, so a ball that cannot raise it costs little.
 *
 * Pieces (see vtkMedialPieces.h): every piece asks for both whole inputs and piece 0
 * measures every ball, so that MaxProtrusion is the largest over all of them; the
 * other pieces are empty.
 *
 * @sa vtkMedialReconstructionError vtkMedialAxisSampler
 */
#ifndef vtkMedialBallProtrusion_h
#define vtkMedialBallProtrusion_h

#include "vtkMedialAxisReconstructionModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISRECONSTRUCTION_EXPORT vtkMedialBallProtrusion : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallProtrusion* New();
  vtkTypeMacro(vtkMedialBallProtrusion, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The inputs: the surface (port 0) and the balls (port 1).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetSurfaceData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetBallsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetBallsData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

  ///@{
  /// Compute MaxProtrusion only, without the per-ball `Protrusion` array (default off).
  vtkSetMacro(MaximumOnly, vtkTypeBool);
  vtkGetMacro(MaximumOnly, vtkTypeBool);
  vtkBooleanMacro(MaximumOnly, vtkTypeBool);
  ///@}

  ///@{
  /// OpenMP threads; 0 (default) uses every core.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The largest protrusion relative to the surface's diagonal, 0 when no ball crosses
  /// the surface (NaN after a failed update).
  vtkGetMacro(MaxProtrusion, double);

protected:
  vtkMedialBallProtrusion();
  ~vtkMedialBallProtrusion() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfThreads = 0;
  vtkTypeBool MaximumOnly = 0;
  double MaxProtrusion = 0.0;

private:
  vtkMedialBallProtrusion(const vtkMedialBallProtrusion&) = delete;
  void operator=(const vtkMedialBallProtrusion&) = delete;
};

#endif
