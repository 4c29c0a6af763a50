// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialCoverageSelection.h"

#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include <omp.h>

namespace
{
// Stages stop halving the dilation below the start value / 2^MaxHalvings.
constexpr int MaxHalvings = 10;
}

void vtkMedialCoverageSelection::FindPairs(const std::vector<double>& centres, const std::vector<double>& radii,
  const std::vector<double>& samples, double dilation, int threads)
{
  const vtkIdType candidates = static_cast<vtkIdType>(radii.size());
  const vtkIdType count = static_cast<vtkIdType>(samples.size() / 3);
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetArray(const_cast<double*>(samples.data()), 3 * count, 1); // not copied, not freed
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();

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
      std::sort(row.begin(), row.end());
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
    gain += !covered[this->Samples[k]] && this->Excess[k] <= dilation;
  }
  return gain;
}

void vtkMedialCoverageSelection::Cover(vtkIdType candidate, double dilation, std::vector<char>& covered) const
{
  for (vtkIdType k = this->Offsets[candidate]; k < this->Offsets[candidate + 1]; ++k)
  {
    if (this->Excess[k] <= dilation)
    {
      covered[this->Samples[k]] = 1;
    }
  }
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

bool vtkMedialCoverageSelection::Select(const std::vector<double>& centres, const std::vector<double>& radii,
  const std::vector<double>& samples, vtkIdType count, double dilation, int threads,
  const std::function<bool()>& aborted)
{
  const vtkIdType candidates = static_cast<vtkIdType>(radii.size());
  const vtkIdType sampleCount = static_cast<vtkIdType>(samples.size() / 3);
  count = std::min(count, candidates);
  this->Chosen.assign(static_cast<size_t>(candidates), 0);
  this->FindPairs(centres, radii, samples, dilation, std::max(1, threads));
  std::vector<char> covered(static_cast<size_t>(sampleCount), 0);
  {
    std::vector<char> coverable(static_cast<size_t>(sampleCount), 0);
    for (vtkIdType s : this->Samples)
    {
      coverable[s] = 1;
    }
    this->UncoverableSamples = sampleCount - std::count(coverable.begin(), coverable.end(), 1);
  }

  vtkIdType chosen = 0;
  double stage = dilation;
  for (int halvings = 0; chosen < count && halvings <= MaxHalvings; ++halvings, stage *= 0.5)
  {
    // Samples covered at this stage's dilation by the balls chosen so far.
    std::fill(covered.begin(), covered.end(), 0);
    for (vtkIdType j = 0; j < candidates; ++j)
    {
      if (this->Chosen[j])
      {
        this->Cover(j, stage, covered);
      }
    }
    // Lazy greedy: (gain, -id) upper bounds, the largest first.
    std::priority_queue<std::pair<vtkIdType, vtkIdType>> heap;
    for (vtkIdType j = 0; j < candidates; ++j)
    {
      const vtkIdType gain = this->Chosen[j] ? 0 : this->Gain(j, stage, covered);
      if (gain > 0)
      {
        heap.push({ gain, -j });
      }
    }
    while (chosen < count && !heap.empty())
    {
      const vtkIdType j = -heap.top().second;
      heap.pop();
      const vtkIdType gain = this->Gain(j, stage, covered);
      if (gain == 0)
      {
        continue;
      }
      if (!heap.empty() && gain < heap.top().first)
      {
        heap.push({ gain, -j });
        continue;
      }
      this->Chosen[j] = 1;
      this->Cover(j, stage, covered);
      if ((++chosen & 255) == 0 && aborted && aborted())
      {
        return false;
      }
    }
    this->FinalDilation = stage;
  }
  this->CoveredSamples = std::count(covered.begin(), covered.end(), 1);
  if (chosen < count)
  {
    this->FarthestFirst(centres, count);
  }
  return true;
}
