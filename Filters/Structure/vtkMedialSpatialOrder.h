// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialSpatialOrder.h
 * @brief Internal: a spatially coherent order for loops of independent surface
 * queries (the Morton, or Z, order of the query points on a 2^21 grid over a box).
 *
 * Queries at nearby points visit the same nodes of the surface tree; run one after
 * the other (in the chunks of a parallel loop), they find those nodes in the cache.
 * Only the order in which independent queries run changes, never a result. Header
 * only; not installed. The keys are computed and sorted on `threads` threads (keyOf must
 * be safe to call from several); each (key, index) pair is distinct, so the order is the
 * same for any thread count.
 */
#ifndef vtkMedialSpatialOrder_h
#define vtkMedialSpatialOrder_h

#include "vtkMedialSort.h"
#include "vtkType.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace vtkMedialSpatialOrder
{
/// Morton key of x in the box (xmin, xmax, ymin, ymax, zmin, zmax); points outside are clamped.
inline std::uint64_t Key(const double x[3], const double bounds[6])
{
  std::uint64_t key = 0;
  std::uint64_t cell[3];
  for (int k = 0; k < 3; ++k)
  {
    const double extent = bounds[2 * k + 1] - bounds[2 * k];
    const double f = extent > 0.0 ? (x[k] - bounds[2 * k]) / extent : 0.0;
    cell[k] = static_cast<std::uint64_t>(std::min(std::max(f, 0.0), 1.0) * ((1 << 21) - 1));
  }
  for (int bit = 20; bit >= 0; --bit)
  {
    for (int k = 0; k < 3; ++k)
    {
      key = (key << 1) | ((cell[k] >> bit) & 1u);
    }
  }
  return key;
}

/// The indices 0 .. n-1 sorted by key(i) (ties by index).
template <class KeyOf>
std::vector<vtkIdType> Order(vtkIdType n, KeyOf keyOf, int threads = 1)
{
  threads = std::max(1, threads);
  std::vector<std::pair<std::uint64_t, vtkIdType>> keyed(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096) num_threads(threads) if (n > 4096)
  for (vtkIdType i = 0; i < n; ++i)
  {
    keyed[i] = { keyOf(i), i };
  }
  vtkMedialSort(keyed.begin(), keyed.end(), threads); // (key, index): distinct
  std::vector<vtkIdType> order(static_cast<size_t>(n));
#pragma omp parallel for schedule(static, 4096) num_threads(threads) if (n > 4096)
  for (vtkIdType i = 0; i < n; ++i)
  {
    order[i] = keyed[i].second;
  }
  return order;
}
}

#endif
