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
// The parallel mode is libstdc++'s; with another standard library, or without OpenMP,
// the sort runs on one thread (same output).
#if defined(__GLIBCXX__) && defined(_OPENMP)
#include <parallel/algorithm>
#define VTK_MEDIAL_PARALLEL_SORT 1
#endif

template <class Iterator>
void vtkMedialSort(Iterator first, Iterator last, int threads)
{
#ifdef VTK_MEDIAL_PARALLEL_SORT
  if (threads > 1 && last - first > 4096)
  {
    __gnu_parallel::sort(first, last, __gnu_parallel::multiway_mergesort_tag(threads));
    return;
  }
#else
  (void)threads;
#endif
  std::sort(first, last);
}

#endif
