// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialGraphPruning
 * @brief Internal: significance-ordered pruning of a medial graph (the 2D medial axis
 * of vtkMedialJunctionFilter, or any graph of segments with a radius per point),
 * whole branches at a time. Used by vtkMedialPruneFilter.
 *
 * Nodes are the points with one segment (ends) or three or more (junctions); a branch
 * is a maximal chain of segments between two nodes; a leaf joins an end to a junction.
 * Pruning is the extended grassfire of Liu et al. (2011) run as a greedy:
 *  1. Every leaf gets its significance (vtkMedialPruneFilter::Measures), computed along
 *     the leaf from its end to its junction with the burn time B (the end burns at its
 *     radius; fire runs along the graph at unit speed).
 *  2. The least significant leaf is removed. Its junction keeps the fire's arrival as a
 *     floor (fire goes on from a junction once all but one of its branches have burnt,
 *     i.e. at the latest of those arrivals). A junction left with two branches joins
 *     them into one, whose significance is computed afresh when it is a leaf.
 *  3. Repeat until no leaf is left: every tree is then a single path, and cycles are
 *     untouched.
 * A removed segment's level is the largest significance removed so far (a running
 * maximum), so pruning at a threshold t removes exactly the segments whose level is
 * below t, and the levels are what a user thresholds. Segments that are never removed
 * get the measure's upper bound (vtkMedialPruneFilter::GetMeasureUpperBound).
 *
 * Topology: only a leaf at a junction of three or more branches is ever removed, so no
 * component is disconnected or lost and no cycle is opened.
 */
#ifndef vtkMedialGraphPruning_h
#define vtkMedialGraphPruning_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

class vtkMedialGraphPruning
{
public:
  struct Graph
  {
    const std::vector<double>* Points = nullptr;                     // 3 coordinates each
    const std::vector<double>* Radii = nullptr;                      // one per point
    const std::vector<std::array<vtkIdType, 2>>* Segments = nullptr; // point ids
  };

  /// Runs the greedy to the end with the given measure; `diagonal` scales the absolute
  /// measures. Returns false when `aborted` (polled between removals) returns true.
  bool Run(const Graph& graph, int measure, double diagonal, const std::function<bool()>& aborted = {});

  /// Per segment: the threshold from which pruning removes it.
  std::vector<double> SegmentLevels;
  /// The levels of the removals, in order (non-decreasing).
  std::vector<double> RemovalLevels;

  /// Branches removed by pruning at `threshold`.
  vtkIdType CountRemovedBelow(double threshold) const;

private:
  struct Branch
  {
    std::vector<vtkIdType> Points;   // node to node
    std::vector<vtkIdType> Segments; // along Points
    bool Alive = true;
  };

  void BuildBranches();
  int NodeDegree(vtkIdType point) const;
  // The end of a leaf (its other end is a junction of three or more branches), or -1.
  vtkIdType LeafEnd(int branch) const;
  double Significance(int branch, vtkIdType end) const;
  double ScaleAxisCover(int branch, vtkIdType junction, const std::vector<vtkIdType>& path) const;
  // Removes a leaf; returns the branch that a merge at its junction made (or -1).
  int RemoveLeaf(int branch, vtkIdType end, double level);
  int Merge(vtkIdType junction);
  const double* Point(vtkIdType i) const { return &(*this->Input.Points)[3 * i]; }
  double Radius(vtkIdType i) const { return (*this->Input.Radii)[i]; }

  Graph Input;
  int Measure = 0;
  double Diagonal = 1.0;
  std::vector<Branch> Branches;
  std::vector<std::vector<int>> Incident; // per point: alive branches ending there (twice for a loop)
  std::vector<double> Floor;              // per point: burn floor left by removed leaves
};

#endif
