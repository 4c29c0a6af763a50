// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialCoverageSelection
 * @brief Internal: chooses K of a medial mesh's balls that cover the surface (the idea of
 * Coverage Axis, Dou et al. 2022, and Coverage Axis++, Wang et al. 2024). Used by
 * vtkMedialSimplifyFilter's COVERAGE method.
 *
 * Candidates are balls (c_j, r_j); samples are points s on the surface. Candidate j covers
 * sample s at dilation d when |s - c_j| - r_j <= d: s lies in the ball grown by d.
 *
 * Selection, in stages: at dilation d (the start value, relative to nothing: model units),
 * the candidate that covers the most samples not yet covered is chosen, again and again
 * (lazy greedy: a candidate's count only falls, so a stale count is an upper bound). When
 * no candidate covers a new sample, every sample that can be covered is, and the next
 * stage halves d (a sample is covered again only when a chosen ball is within the new d).
 * This stops at K balls. Below 1/1024 of the start dilation the rest are taken farthest
 * first (the candidate whose centre is farthest from the chosen ones').
 *
 * The pairs (candidate, sample) within the start dilation are found once, in parallel,
 * through vtkStaticPointLocator; each candidate's list is sorted, and the greedy passes
 * break ties by the lower candidate id, so the choice does not depend on the thread count.
 */
#ifndef vtkMedialCoverageSelection_h
#define vtkMedialCoverageSelection_h

#include "vtkType.h"

#include <functional>
#include <vector>

class vtkMedialCoverageSelection
{
public:
  /// centres: 3 per candidate; radii: 1 per candidate; samples: 3 per sample. Chooses
  /// min(count, candidates) balls. Returns false when `aborted` returns true.
  bool Select(const std::vector<double>& centres, const std::vector<double>& radii,
    const std::vector<double>& samples, vtkIdType count, double dilation, int threads,
    const std::function<bool()>& aborted = {});

  /// Per candidate, 1 when chosen.
  std::vector<char> Chosen;
  /// The dilation of the last stage, and the samples covered at it when the selection
  /// stopped, and the samples no candidate covers at the start dilation.
  double FinalDilation = 0.0;
  vtkIdType CoveredSamples = 0;
  vtkIdType UncoverableSamples = 0;

private:
  void FindPairs(const std::vector<double>& centres, const std::vector<double>& radii,
    const std::vector<double>& samples, double dilation, int threads);
  vtkIdType Gain(vtkIdType candidate, double dilation, const std::vector<char>& covered) const;
  void Cover(vtkIdType candidate, double dilation, std::vector<char>& covered) const;
  void FarthestFirst(const std::vector<double>& centres, vtkIdType count);

  // Compressed rows: candidate j's samples are Samples[Offsets[j] .. Offsets[j + 1]), with
  // the excess |s - c_j| - r_j of each.
  std::vector<vtkIdType> Offsets;
  std::vector<vtkIdType> Samples;
  std::vector<float> Excess;
};

#endif
