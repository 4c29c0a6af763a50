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
 * README's noisy-horse table). Low-passing the surface first gives the large balls
 * back; the scale axis (vtkMedialScaleAxisFilter) then removes the noise left.
 *
 * It is vtkWindowedSincPolyDataFilter with other defaults: 20 iterations, pass band
 * 0.03, coordinates normalized (so the pass band means the same at any scale),
 * boundary vertices fixed (an open rim stays where it is), no feature-edge treatment
 * (noise would make every edge a feature), non-manifold vertices smoothed. It also
 * checks its input (polygons, finite coordinates), drops the input's point normals
 * (they no longer fit the moved points), and reports the largest vertex move.
 * Smoothing rounds sharp edges and corners: leave it out for clean CAD meshes.
 *
 * Input: a polygon (triangle) surface. Output: the same cells and point and cell
 * data (less the point normals), the points moved.
 *
 * @sa vtkMedialAxisSampler vtkMedialScaleAxisFilter
 */
#ifndef vtkMedialDenoiseFilter_h
#define vtkMedialDenoiseFilter_h

#include "vtkMedialAxisSamplingModule.h" // for export macro
#include "vtkWindowedSincPolyDataFilter.h"

class VTKMEDIALAXISSAMPLING_EXPORT vtkMedialDenoiseFilter : public vtkWindowedSincPolyDataFilter
{
public:
  static vtkMedialDenoiseFilter* New();
  vtkTypeMacro(vtkMedialDenoiseFilter, vtkWindowedSincPolyDataFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The largest distance a vertex moved in the last execution, relative to the
  /// input's bounding-box diagonal.
  vtkGetMacro(MaximumDisplacement, double);

protected:
  vtkMedialDenoiseFilter();
  ~vtkMedialDenoiseFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MaximumDisplacement = 0.0;

private:
  vtkMedialDenoiseFilter(const vtkMedialDenoiseFilter&) = delete;
  void operator=(const vtkMedialDenoiseFilter&) = delete;
};

#endif
