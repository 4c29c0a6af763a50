// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialScaleAxisFilter
 * @brief The scale axis transform of medial balls (Giesen et al. 2009): removes the
 * balls that another ball covers once every ball is scaled by ScaleFactor.
 *
 * Ball i (centre c_i, radius r_i) scaled by s lies in ball j scaled by s when
 * |c_i - c_j| + s r_i <= s r_j, that is s >= |c_i - c_j| / (r_j - r_i) with r_j > r_i.
 * Its covering scale s_i is the smallest such s over every other ball. The point array
 * Significance holds 1 - 1/s_i in [0, 1), like vtkMedialPruneFilter's SCALE_AXIS
 * measure on branches, and 1 for a ball that no ball covers up to MaximumScale. A
 * ball is removed when s_i <= ScaleFactor. With ScaleFactor 1 (only balls inside
 * another ball go), keeping Significance > 1 - 1/s by hand gives the output for s.
 *
 * Why on balls, before vtkMedialMeshFilter: on a noisy surface the medial axis grows a
 * branch toward every bump, and balls tangent to tilted facets sit off the clean axis.
 * Both are small next to a ball nearby, so a modest scale covers them, while the balls
 * that carry the shape (the largest locally, and thin parts with no larger ball near)
 * stay. Branch pruning on the mesh cannot remove them when they close cycles; the mesh
 * filter builds the kept balls' complex with the solid's topology and checks it.
 *
 * Search: a uniform grid of the centres. Around each centre, spheres of doubling
 * radius rho are searched until no ball farther than rho can do better than the best
 * scale found (a ball at distance d covers at a scale >= d / (r_max - r_i)), or until
 * that bound passes MaximumScale. Every ball's value depends on the input alone, so
 * the output is the same for any number of threads. The cost grows with the number
 * of balls within about s_i (r_max - r_i) of each centre: fine for the 10^4 - 10^5
 * balls a medial mesh is built from.
 *
 * Input: vtkPolyData of balls, points with a point-data radius (input array 0; by
 * default Radius), e.g. vtkMedialAxisSampler's output; its cells are ignored.
 * Output: the kept balls with every point-data array, one vertex cell each, and the
 * point array Significance; the input's field data.
 *
 * @sa vtkMedialPruneFilter vtkMedialMeshFilter
 */
#ifndef vtkMedialScaleAxisFilter_h
#define vtkMedialScaleAxisFilter_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialScaleAxisFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialScaleAxisFilter* New();
  vtkTypeMacro(vtkMedialScaleAxisFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// Covering scales above this are not resolved: such balls get Significance 1.
  static constexpr double MaximumScale = 16.0;

  ///@{
  /// Balls covered at this scale are removed (default 1.5; 1 removes only balls that
  /// lie inside another ball).
  vtkSetClampMacro(ScaleFactor, double, 1.0, MaximumScale);
  vtkGetMacro(ScaleFactor, double);
  ///@}

  /// The scale factor for the balls of a surface smoothed by vtkMedialDenoiseFilter
  /// (1.3, what medial-axis --denoise --prune uses): the smoothing removed most of the
  /// noise the default 1.5 is for, and a smaller scale keeps more of the shape.
  static double GetDenoisedScaleFactor() { return 1.3; }

  ///@{
  /// OpenMP threads; 0 (default) uses every core.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// Balls removed by the last execution.
  vtkGetMacro(NumberOfRemovedBalls, vtkIdType);

protected:
  vtkMedialScaleAxisFilter();
  ~vtkMedialScaleAxisFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ScaleFactor = 1.5;
  int NumberOfThreads = 0;
  vtkIdType NumberOfRemovedBalls = 0;

private:
  vtkMedialScaleAxisFilter(const vtkMedialScaleAxisFilter&) = delete;
  void operator=(const vtkMedialScaleAxisFilter&) = delete;
};

#endif
