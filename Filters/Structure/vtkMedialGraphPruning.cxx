// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialGraphPruning.h"
#include "vtkMedialPruneFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <tuple>

namespace
{
constexpr double Degrees = 180.0 / 3.14159265358979323846;

double Distance(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}
}

int vtkMedialGraphPruning::NodeDegree(vtkIdType point) const
{
  return static_cast<int>(this->Incident[point].size());
}

void vtkMedialGraphPruning::BuildBranches()
{
  const auto& segments = *this->Input.Segments;
  const vtkIdType n = static_cast<vtkIdType>(this->Input.Radii->size());
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>> adjacent(static_cast<size_t>(n));
  for (vtkIdType s = 0; s < static_cast<vtkIdType>(segments.size()); ++s)
  {
    adjacent[segments[s][0]].push_back({ segments[s][1], s });
    adjacent[segments[s][1]].push_back({ segments[s][0], s });
  }
  std::vector<char> used(segments.size(), 0);
  this->Incident.assign(static_cast<size_t>(n), {});
  // Walks from `start` through `segment` until a node; the degree-2 points are inner points.
  auto walk = [&](vtkIdType start, vtkIdType next, vtkIdType segment) {
    Branch b;
    b.Points.push_back(start);
    vtkIdType previousSegment = segment;
    vtkIdType current = next;
    used[segment] = 1;
    b.Segments.push_back(segment);
    b.Points.push_back(current);
    while (adjacent[current].size() == 2 && current != start)
    {
      const auto& a = adjacent[current];
      const auto& step = a[0].second == previousSegment ? a[1] : a[0];
      if (used[step.second])
      {
        break;
      }
      used[step.second] = 1;
      previousSegment = step.second;
      current = step.first;
      b.Segments.push_back(step.second);
      b.Points.push_back(current);
    }
    const int id = static_cast<int>(this->Branches.size());
    this->Incident[b.Points.front()].push_back(id);
    this->Incident[b.Points.back()].push_back(id);
    this->Branches.push_back(std::move(b));
  };
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (adjacent[p].size() != 2)
    {
      for (const auto& step : adjacent[p])
      {
        if (!used[step.second])
        {
          walk(p, step.first, step.second);
        }
      }
    }
  }
  // Cycles without a node: one branch from a point back to itself (never a leaf).
  for (vtkIdType p = 0; p < n; ++p)
  {
    for (const auto& step : adjacent[p])
    {
      if (!used[step.second])
      {
        walk(p, step.first, step.second);
      }
    }
  }
}

vtkIdType vtkMedialGraphPruning::LeafEnd(int branch) const
{
  const Branch& b = this->Branches[branch];
  const vtkIdType front = b.Points.front();
  const vtkIdType back = b.Points.back();
  if (!b.Alive || front == back)
  {
    return -1;
  }
  if (this->NodeDegree(front) == 1 && this->NodeDegree(back) >= 3)
  {
    return front;
  }
  if (this->NodeDegree(back) == 1 && this->NodeDegree(front) >= 3)
  {
    return back;
  }
  return -1;
}

// Smallest scale s at which every ball of the path (except the junction's) lies in a scaled
// ball near the junction: the junction's own or one on its other branches within 2 radii.
double vtkMedialGraphPruning::ScaleAxisCover(
  int branch, vtkIdType junction, const std::vector<vtkIdType>& path) const
{
  std::vector<vtkIdType> covers{ junction };
  const double reach = 2.0 * this->Radius(junction);
  for (int other : this->Incident[junction])
  {
    if (other == branch)
    {
      continue;
    }
    const auto& points = this->Branches[other].Points;
    const bool forward = points.front() == junction;
    for (size_t k = 1; k < points.size() && k <= 256; ++k)
    {
      const vtkIdType q = forward ? points[k] : points[points.size() - 1 - k];
      if (Distance(this->Point(q), this->Point(junction)) > reach)
      {
        break;
      }
      covers.push_back(q);
    }
  }
  double worst = 1.0;
  for (size_t i = 0; i + 1 < path.size(); ++i)
  {
    double best = std::numeric_limits<double>::infinity();
    for (vtkIdType q : covers)
    {
      const double gain = this->Radius(q) - this->Radius(path[i]);
      if (gain > 0.0)
      {
        best = std::min(best, Distance(this->Point(path[i]), this->Point(q)) / gain);
      }
    }
    worst = std::max(worst, best);
  }
  return worst;
}

double vtkMedialGraphPruning::Significance(int branch, vtkIdType end) const
{
  const Branch& b = this->Branches[branch];
  std::vector<vtkIdType> path = b.Points;
  if (path.front() != end)
  {
    std::reverse(path.begin(), path.end());
  }
  double burn = this->Radius(end);
  double lambda = 0.0;
  double angle = 0.0;
  for (size_t i = 0; i + 1 < path.size(); ++i)
  {
    const vtkIdType p = path[i], q = path[i + 1];
    const double length = Distance(this->Point(p), this->Point(q));
    burn += length;
    if (i + 2 < path.size())
    {
      burn = std::max(burn, this->Floor[q]);
    }
    if (length > 0.0)
    {
      // On the medial axis |dR/ds| = cos(theta / 2), theta the angle between the two contacts
      // seen from the centre; lambda = R sin(theta / 2) is the radius of their enclosing ball.
      const double slope = std::min(1.0, std::abs(this->Radius(q) - this->Radius(p)) / length);
      const double half = std::acos(slope);
      angle = std::max(angle, 2.0 * half * Degrees);
      lambda = std::max(lambda, std::max(this->Radius(p), this->Radius(q)) * std::sin(half));
    }
  }
  const double erosion = std::max(0.0, burn - this->Radius(path.back()));
  switch (this->Measure)
  {
    case vtkMedialPruneFilter::EROSION_THICKNESS:
      return std::min(1.0, erosion / this->Diagonal);
    case vtkMedialPruneFilter::TUBULARITY:
      return burn > 0.0 ? erosion / burn : 0.0;
    case vtkMedialPruneFilter::LAMBDA:
      return std::min(1.0, lambda / this->Diagonal);
    case vtkMedialPruneFilter::SEPARATION_ANGLE:
      return angle;
    default:
      return std::max(0.0, 1.0 - 1.0 / this->ScaleAxisCover(branch, path.back(), path));
  }
}

int vtkMedialGraphPruning::Merge(vtkIdType junction)
{
  const int a = this->Incident[junction][0];
  const int b = this->Incident[junction][1];
  if (a == b)
  {
    return -1; // a cycle through this point: it stays as it is
  }
  Branch merged;
  Branch& first = this->Branches[a];
  Branch& second = this->Branches[b];
  // first: ... -> junction, second: junction -> ...
  if (first.Points.back() != junction)
  {
    std::reverse(first.Points.begin(), first.Points.end());
    std::reverse(first.Segments.begin(), first.Segments.end());
  }
  if (second.Points.front() != junction)
  {
    std::reverse(second.Points.begin(), second.Points.end());
    std::reverse(second.Segments.begin(), second.Segments.end());
  }
  merged.Points = first.Points;
  merged.Points.insert(merged.Points.end(), second.Points.begin() + 1, second.Points.end());
  merged.Segments = first.Segments;
  merged.Segments.insert(merged.Segments.end(), second.Segments.begin(), second.Segments.end());
  first.Alive = second.Alive = false;
  const int id = static_cast<int>(this->Branches.size());
  for (vtkIdType node : { merged.Points.front(), merged.Points.back() })
  {
    auto& incident = this->Incident[node];
    incident.erase(std::remove_if(incident.begin(), incident.end(), [&](int x) { return x == a || x == b; }),
      incident.end());
  }
  this->Incident[junction].clear();
  this->Incident[merged.Points.front()].push_back(id);
  this->Incident[merged.Points.back()].push_back(id);
  this->Branches.push_back(std::move(merged));
  return id;
}

int vtkMedialGraphPruning::RemoveLeaf(int branch, vtkIdType end, double level)
{
  Branch& b = this->Branches[branch];
  const vtkIdType junction = b.Points.front() == end ? b.Points.back() : b.Points.front();
  double arrival = this->Radius(end);
  const std::vector<vtkIdType>& points = b.Points;
  for (size_t i = 0; i + 1 < points.size(); ++i)
  {
    arrival += Distance(this->Point(points[i]), this->Point(points[i + 1]));
  }
  for (vtkIdType s : b.Segments)
  {
    this->SegmentLevels[s] = level;
  }
  b.Alive = false;
  for (vtkIdType node : { end, junction })
  {
    auto& incident = this->Incident[node];
    incident.erase(std::find(incident.begin(), incident.end(), branch));
  }
  this->Floor[junction] = std::max(this->Floor[junction], arrival);
  return this->NodeDegree(junction) == 2 ? this->Merge(junction) : -1;
}

bool vtkMedialGraphPruning::Run(
  const Graph& graph, int measure, double diagonal, const std::function<bool()>& aborted)
{
  this->Input = graph;
  this->Measure = measure;
  this->Diagonal = diagonal > 0.0 ? diagonal : 1.0;
  this->Branches.clear();
  this->RemovalLevels.clear();
  this->Floor.assign(graph.Radii->size(), 0.0);
  this->SegmentLevels.assign(graph.Segments->size(), vtkMedialPruneFilter::GetMeasureUpperBound(measure));
  this->BuildBranches();

  // Min-heap of (significance, branch); a branch is never re-queued, only replaced.
  using Entry = std::tuple<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  auto push = [&](int branch) {
    const vtkIdType end = branch >= 0 ? this->LeafEnd(branch) : -1;
    if (end >= 0)
    {
      heap.emplace(this->Significance(branch, end), branch);
    }
  };
  for (int b = 0; b < static_cast<int>(this->Branches.size()); ++b)
  {
    push(b);
  }
  double level = 0.0;
  vtkIdType removals = 0;
  while (!heap.empty())
  {
    const auto [significance, branch] = heap.top();
    heap.pop();
    const vtkIdType end = this->LeafEnd(branch);
    if (end < 0)
    {
      continue; // merged away, or its junction lost branches meanwhile: no longer a leaf
    }
    if ((++removals & 255) == 0 && aborted && aborted())
    {
      return false;
    }
    level = std::max(level, significance);
    this->RemovalLevels.push_back(level);
    push(this->RemoveLeaf(branch, end, level));
  }
  return true;
}

vtkIdType vtkMedialGraphPruning::CountRemovedBelow(double threshold) const
{
  return static_cast<vtkIdType>(
    std::lower_bound(this->RemovalLevels.begin(), this->RemovalLevels.end(), threshold) -
    this->RemovalLevels.begin());
}
