// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialGroupByKey.h
 * @brief Internal: items grouped by an integer key in linear time (a counting sort),
 * stable, in parallel for large inputs with the serial result (header only; the
 * including module links OpenMP).
 *
 * GroupByKey(n, keys, key, emit): items 0 .. n - 1, key(i) in [0, keys). Counts the items
 * of each key, turns the counts into offsets (a prefix sum) and calls emit(i, position)
 * once per item, the items of each key at consecutive positions in increasing i. Returns
 * where each key's items start (keys + 1 entries; the last is n). The caller stores the
 * item (or what it wants of it) at the position.
 *
 * Large inputs (2^16 items or more) are cut into at most 4 consecutive chunks, at most
 * `threads` (<= 0: omp_get_max_threads()), counted and placed in parallel; chunk c's
 * items of a key go after those of the chunks before it, so the result is the serial
 * one whatever the thread count. Each chunk keeps a count per key.
 * Used by the mesh preparation (point merging, edge uses, vertex links) and the seam
 * solver's neighbour pairs.
 */
#ifndef vtkMedialGroupByKey_h
#define vtkMedialGroupByKey_h

#include "vtkMedialBuffer.h"

#include "vtkType.h"

#include <omp.h>

#include <algorithm>
#include <vector>

template <class Key, class Emit>
vtkMedialBuffer<vtkIdType> vtkMedialGroupByKey(vtkIdType n, vtkIdType keys, Key key, Emit emit, int threads = 0)
{
  const int allowed = threads > 0 ? threads : omp_get_max_threads();
  const int chunks = n >= (1 << 16) ? std::max(1, std::min(4, allowed)) : 1;
  auto chunkBegin = [&](int c) { return static_cast<vtkIdType>(n * static_cast<double>(c) / chunks); };
  std::vector<vtkMedialBuffer<vtkIdType>> next(chunks); // per chunk: where its next item of each key goes
#pragma omp parallel for num_threads(chunks) schedule(static, 1)
  for (int c = 0; c < chunks; ++c)
  {
    next[c].assign(static_cast<size_t>(keys), 0);
    for (vtkIdType i = chunkBegin(c); i < chunkBegin(c + 1); ++i)
    {
      ++next[c][key(i)];
    }
  }
  vtkMedialBuffer<vtkIdType> offsets(static_cast<size_t>(keys) + 1);
  vtkIdType total = 0;
  for (vtkIdType k = 0; k < keys; ++k)
  {
    offsets[k] = total;
    for (int c = 0; c < chunks; ++c)
    {
      const vtkIdType count = next[c][k];
      next[c][k] = total;
      total += count;
    }
  }
  offsets[keys] = total;
#pragma omp parallel for num_threads(chunks) schedule(static, 1)
  for (int c = 0; c < chunks; ++c)
  {
    for (vtkIdType i = chunkBegin(c); i < chunkBegin(c + 1); ++i)
    {
      emit(i, next[c][key(i)]++);
    }
  }
  return offsets;
}

#endif
