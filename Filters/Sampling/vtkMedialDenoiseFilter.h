// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialDenoiseFilter
 * @brief Smooths a noisy surface before its medial axis is sampled: a windowed sinc
 * low-pass filter (Taubin's smoothing, which does not shrink the surface) with the
 * settings measured on noisy meshes.
 *
 * Why: noise tilts the facets, and the sampler's ray starts inward along each facet's
 * normal, so a bumpy surface gives small balls tangent to the bumps where the clean
 * shape has large ones. No pruning brings back balls that were never sampled (see the
 * noisy-horse table in docs/how-it-works/pruning.md). Low-passing the surface first gives the large balls
 * back; the scale axis (vtkMedialScaleAxisFilter) then removes the noise left.
 *
 * Algorithm: points with exactly the same coordinates are welded first (OBJ and STL
 * files repeat a vertex for every face; smoothed apart, the copies would tear the
 * surface open), then vtkWindowedSincPolyDataFilter runs on the welded surface with
 * NumberOfIterations and PassBand, coordinates normalized (so the pass band means the
 * same at any scale), boundary vertices fixed (an open rim stays where it is), no
 * feature-edge treatment (noise would make every edge a feature) and non-manifold
 * vertices smoothed. Every input point then takes its welded point's new position.
 * Smoothing rounds sharp edges and corners: leave it out for clean CAD meshes.
 *
 * Input: a polygon (triangle) surface; triangle strips are smoothed as triangles.
 * Output: the input's points moved, and its cells, point data (less the point normals,
 * which no longer fit) and cell data. MaximumDisplacement reports the largest move.
 *
 * Pieces: smoothing needs every neighbour, so every piece asks for the whole surface and
 * piece 0 holds the result; the other pieces are empty (the sampler asks for piece 0 of
 * 1, so each MPI rank still gets all of it).
 *
 * @sa vtkMedialAxisSampler vtkMedialScaleAxisFilter vtkWindowedSincPolyDataFilter
 */
#ifndef vtkMedialDenoiseFilter_h
#define vtkMedialDenoiseFilter_h

#include "vtkMedialAxisSamplingModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISSAMPLING_EXPORT vtkMedialDenoiseFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialDenoiseFilter* New();
  vtkTypeMacro(vtkMedialDenoiseFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// Iterations of the windowed sinc filter, the degree of its polynomial (default 20).
  vtkSetClampMacro(NumberOfIterations, int, 1, 1000);
  vtkGetMacro(NumberOfIterations, int);
  ///@}

  ///@{
  /// Pass band in normalized frequency, in [0.001, 2]: lower smooths more (default
  /// 0.03, measured on the noisy horse at 0.1% and 0.5% Gaussian noise).
  vtkSetClampMacro(PassBand, double, 0.001, 2.0);
  vtkGetMacro(PassBand, double);
  ///@}

  /// The largest distance a point moved in the last execution, relative to the input's
  /// bounding-box diagonal.
  vtkGetMacro(MaximumDisplacement, double);

protected:
  vtkMedialDenoiseFilter() = default;
  ~vtkMedialDenoiseFilter() override = default;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfIterations = 20;
  double PassBand = 0.03;
  double MaximumDisplacement = 0.0;

private:
  vtkMedialDenoiseFilter(const vtkMedialDenoiseFilter&) = delete;
  void operator=(const vtkMedialDenoiseFilter&) = delete;
};

#endif
