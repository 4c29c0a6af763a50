// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialSort.h
 * @brief Internal: a sort on several threads whose output does not depend on them
 * (header only; the including module links OpenMP).
 *
 * libstdc++'s parallel mode (a multiway merge sort on OpenMP) on `threads` threads, or
 * std::sort on one. A sort's output is a function of its input alone when no two
 * different elements compare equivalent (keys made unique, e.g. with an index), so
 * the output is the same bytes for any thread count; use it only on such ranges.
 */
#ifndef vtkMedialSort_h
#define vtkMedialSort_h

#include <algorithm>
#include <parallel/algorithm>

template <class Iterator>
void vtkMedialSort(Iterator first, Iterator last, int threads)
{
  if (threads > 1 && last - first > 4096)
  {
    __gnu_parallel::sort(first, last, __gnu_parallel::multiway_mergesort_tag(threads));
  }
  else
  {
    std::sort(first, last);
  }
}

#endif
