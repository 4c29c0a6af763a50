// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialCoverageSelection.h"

#include "vtkMedialPointCloud.h"

#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include <omp.h>

namespace
{
// Steps of the bisection for the smallest dilation K balls cover.
constexpr int Bisections = 7;
}

void vtkMedialCoverageSelection::FindPairs(const std::vector<double>& centres, const std::vector<double>& radii,
  const std::vector<double>& samples, double dilation, int threads)
{
  const vtkIdType candidates = static_cast<vtkIdType>(radii.size());
  const vtkIdType count = static_cast<vtkIdType>(samples.size() / 3);
  const auto locator = vtkMedialPointCloud::Locator(samples.data(), count);

  std::vector<std::vector<std::pair<vtkIdType, float>>> rows(static_cast<size_t>(candidates));
#pragma omp parallel num_threads(threads)
  {
    vtkNew<vtkIdList> found;
#pragma omp for schedule(dynamic, 64)
    for (vtkIdType j = 0; j < candidates; ++j)
    {
      const double* c = &centres[3 * j];
      locator->FindPointsWithinRadius(radii[j] + dilation, c, found);
      auto& row = rows[j];
      row.reserve(static_cast<size_t>(found->GetNumberOfIds()));
      for (vtkIdType k = 0; k < found->GetNumberOfIds(); ++k)
      {
        const vtkIdType s = found->GetId(k);
        const double* p = &samples[3 * s];
        const double d = std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
          (p[2] - c[2]) * (p[2] - c[2]));
        row.emplace_back(s, static_cast<float>(d - radii[j]));
      }
    }
  }
  this->Offsets.assign(static_cast<size_t>(candidates) + 1, 0);
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    this->Offsets[j + 1] = this->Offsets[j] + static_cast<vtkIdType>(rows[j].size());
  }
  this->Samples.resize(static_cast<size_t>(this->Offsets[candidates]));
  this->Excess.resize(this->Samples.size());
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    vtkIdType at = this->Offsets[j];
    for (const auto& pair : rows[j])
    {
      this->Samples[at] = pair.first;
      this->Excess[at++] = pair.second;
    }
  }
}

vtkIdType vtkMedialCoverageSelection::Gain(
  vtkIdType candidate, double dilation, const std::vector<char>& covered) const
{
  vtkIdType gain = 0;
  for (vtkIdType k = this->Offsets[candidate]; k < this->Offsets[candidate + 1]; ++k)
  {
    const vtkIdType s = this->Samples[k];
    gain += !covered[s] && this->Excess[k] <= std::max<double>(dilation, this->Best[s]);
  }
  return gain;
}

void vtkMedialCoverageSelection::Cover(vtkIdType candidate, double dilation, std::vector<char>& covered) const
{
  for (vtkIdType k = this->Offsets[candidate]; k < this->Offsets[candidate + 1]; ++k)
  {
    const vtkIdType s = this->Samples[k];
    if (this->Excess[k] <= std::max<double>(dilation, this->Best[s]))
    {
      covered[s] = 1;
    }
  }
}

bool vtkMedialCoverageSelection::Stage(double dilation, vtkIdType count, std::vector<char>& covered)
{
  // The samples the balls chosen so far cover at this dilation.
  const vtkIdType candidates = static_cast<vtkIdType>(this->Chosen.size());
  vtkIdType chosen = 0;
  std::fill(covered.begin(), covered.end(), 0);
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    if (this->Chosen[j])
    {
      this->Cover(j, dilation, covered);
      ++chosen;
    }
  }
  // Lazy greedy: (gain, -id) upper bounds, the largest first.
  std::priority_queue<std::pair<vtkIdType, vtkIdType>> heap;
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    const vtkIdType gain = this->Chosen[j] ? 0 : this->Gain(j, dilation, covered);
    if (gain > 0)
    {
      heap.push({ gain, -j });
    }
  }
  while (!heap.empty())
  {
    const vtkIdType j = -heap.top().second;
    heap.pop();
    const vtkIdType gain = this->Gain(j, dilation, covered);
    if (gain == 0)
    {
      continue;
    }
    if (!heap.empty() && gain < heap.top().first)
    {
      heap.push({ gain, -j });
      continue;
    }
    if (chosen == count)
    {
      return false; // a sample is left uncovered
    }
    this->Chosen[j] = 1;
    this->Cover(j, dilation, covered);
    ++chosen;
  }
  return true;
}

void vtkMedialCoverageSelection::FarthestFirst(const std::vector<double>& centres, vtkIdType count)
{
  const vtkIdType candidates = static_cast<vtkIdType>(this->Chosen.size());
  std::vector<double> nearest(static_cast<size_t>(candidates), HUGE_VAL);
  auto update = [&](vtkIdType j) {
    for (vtkIdType i = 0; i < candidates; ++i)
    {
      double d2 = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        d2 += (centres[3 * i + k] - centres[3 * j + k]) * (centres[3 * i + k] - centres[3 * j + k]);
      }
      nearest[i] = std::min(nearest[i], d2);
    }
  };
  vtkIdType chosen = 0;
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    if (this->Chosen[j])
    {
      update(j);
      ++chosen;
    }
  }
  for (; chosen < count; ++chosen)
  {
    vtkIdType best = -1;
    for (vtkIdType i = 0; i < candidates; ++i)
    {
      if (!this->Chosen[i] && (best < 0 || nearest[i] > nearest[best]))
      {
        best = i;
      }
    }
    this->Chosen[best] = 1;
    update(best);
  }
}

void vtkMedialCoverageSelection::FarthestSamples(const std::vector<double>& centres,
  const std::vector<double>& radii, const std::vector<double>& samples, vtkIdType count, double dilation,
  std::vector<char>& covered)
{
  const vtkIdType candidates = static_cast<vtkIdType>(radii.size());
  const vtkIdType sampleCount = static_cast<vtkIdType>(samples.size() / 3);
  auto excess = [&](vtkIdType j, vtkIdType s) {
    const double* c = &centres[3 * j];
    const double* p = &samples[3 * s];
    return std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])) -
      radii[j];
  };
  this->Chosen = this->Forced;
  std::fill(covered.begin(), covered.end(), 0);
  std::vector<double> gap(static_cast<size_t>(sampleCount), HUGE_VAL);
  vtkIdType chosen = 0;
  for (vtkIdType j = 0; j < candidates; ++j)
  {
    if (this->Chosen[j])
    {
      this->Cover(j, dilation, covered);
      for (vtkIdType s = 0; s < sampleCount; ++s)
      {
        gap[s] = std::min(gap[s], excess(j, s));
      }
      ++chosen;
    }
  }
  for (; chosen < count; ++chosen)
  {
    // The sample farthest beyond what the candidates can do there (the first pick: any).
    vtkIdType far = -1;
    double shortfall = -HUGE_VAL;
    for (vtkIdType s = 0; s < sampleCount && chosen > 0; ++s)
    {
      if (this->Best[s] < HUGE_VALF && gap[s] - this->Best[s] > shortfall)
      {
        shortfall = gap[s] - this->Best[s];
        far = s;
      }
    }
    // Of the candidates that cover it, the one that covers the most samples not yet
    // covered; when none does, the nearest.
    vtkIdType pick = -1, gain = -1;
    double nearest = HUGE_VAL;
    for (vtkIdType j = 0; j < candidates; ++j)
    {
      if (this->Chosen[j])
      {
        continue;
      }
      const double e = far < 0 ? 0.0 : excess(j, far);
      if (e <= std::max<double>(dilation, far < 0 ? 0.0 : this->Best[far]))
      {
        const vtkIdType g = this->Gain(j, dilation, covered);
        if (g > gain)
        {
          gain = g;
          pick = j;
        }
      }
      else if (gain < 0 && e < nearest)
      {
        nearest = e;
        pick = j;
      }
    }
    if (pick < 0)
    {
      break;
    }
    this->Chosen[pick] = 1;
    this->Cover(pick, dilation, covered);
    for (vtkIdType s = 0; s < sampleCount; ++s)
    {
      gap[s] = std::min(gap[s], excess(pick, s));
    }
  }
}

bool vtkMedialCoverageSelection::Select(const std::vector<double>& centres, const std::vector<double>& radii,
  const std::vector<double>& samples, vtkIdType count, double dilation, int threads,
  const std::function<bool()>& aborted)
{
  const vtkIdType candidates = static_cast<vtkIdType>(radii.size());
  const vtkIdType sampleCount = static_cast<vtkIdType>(samples.size() / 3);
  count = std::min(count, candidates);
  this->Forced.resize(static_cast<size_t>(candidates), 0);
  this->FindPairs(centres, radii, samples, dilation, std::max(1, threads));
  this->Best.assign(static_cast<size_t>(sampleCount), HUGE_VALF);
  for (size_t k = 0; k < this->Samples.size(); ++k)
  {
    this->Best[this->Samples[k]] = std::min(this->Best[this->Samples[k]], this->Excess[k]);
  }
  this->UncoverableSamples = std::count(this->Best.begin(), this->Best.end(), HUGE_VALF);
  std::vector<char> covered(static_cast<size_t>(sampleCount), 0);

  // The smallest dilation that `count` balls cover, by bisection.
  this->Chosen = this->Forced;
  double reached = dilation;
  if (this->Stage(dilation, count, covered))
  {
    double below = 0.0;
    for (int step = 0; step < Bisections; ++step)
    {
      if (aborted && aborted())
      {
        return false;
      }
      const double middle = 0.5 * (below + reached);
      this->Chosen = this->Forced;
      (this->Stage(middle, count, covered) ? reached : below) = middle;
    }
    this->Chosen = this->Forced;
    this->Stage(reached, count, covered);
  }
  else
  {
    // Too few balls to cover at the start dilation: the farthest sample first.
    this->FarthestSamples(centres, radii, samples, count, dilation, covered);
  }
  this->FinalDilation = reached;
  this->CoveredSamples = std::count(covered.begin(), covered.end(), 1);
  // The balls left over refine the cover at half the dilation, and so on.
  vtkIdType chosen = std::count(this->Chosen.begin(), this->Chosen.end(), 1);
  for (double stage = 0.5 * reached; chosen < count && stage > reached / 1024.0; stage *= 0.5)
  {
    this->Stage(stage, count, covered);
    chosen = std::count(this->Chosen.begin(), this->Chosen.end(), 1);
  }
  if (chosen < count)
  {
    this->FarthestFirst(centres, count);
  }
  return true;
}
