// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialRepairWeld
 * @brief Internal (MedialAxis::Repair): the repair's weld (step 1 of
 * vtkMedialRepairFilter): the points of a triangle soup closer than a tolerance are
 * merged, and the triangles that collapse are dropped.
 *
 * Algorithm: the clusters are the connected components of the graph whose edges join
 * every two points at most `tolerance` apart (single linkage), found by union-find:
 * a vtkStaticPointLocator lists, for each point, the points within `tolerance` of it,
 * and each pair is united. The merge is therefore transitive (a chain of points each
 * just under the tolerance from the next is one cluster, whatever its length), and the
 * clusters depend on the points' coordinates alone: not on their order, not on the
 * order in which threads visit the locator's buckets, not on the number of threads.
 * (vtkStaticCleanPolyData, used before, merges each point into the first unmerged point
 * within the tolerance, on VTK's SMP threads: its clusters depended on the scheduling,
 * and two equal points could end in different clusters.) Each cluster becomes its
 * lowest-numbered point, with that point's coordinates. The triangles are mapped onto
 * the clusters in their order; those with two corners in one cluster are dropped; the
 * points are renumbered in order of first use by the triangles kept.
 *
 * Cost: O(n) expected for n points (one locator build and one radius query per point,
 * each over a bucket or a few, as the tolerance is far smaller than the buckets), with
 * a near-constant union-find per pair found.
 */
#ifndef vtkMedialRepairWeld_h
#define vtkMedialRepairWeld_h

#include "vtkMedialSurfaceRepair.h"

namespace vtkMedialRepairWeld
{
/// What Weld changed.
struct Counts
{
  vtkIdType MergedPoints = 0;    // points merged into another: points - clusters (never negative)
  vtkIdType DroppedTriangles = 0; // triangles with two corners in one cluster
};

/// Welds `soup` in place: points at most `tolerance` apart (an absolute distance) are
/// merged, transitively; see the class comment.
void Weld(vtkMedialSurfaceRepair::Soup& soup, double tolerance, Counts& counts);
}

#endif
