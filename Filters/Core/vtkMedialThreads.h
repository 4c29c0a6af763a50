// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialThreads.h
 * @brief Internal: the thread count of a filter's OpenMP loops (header only; the
 * including module links OpenMP).
 */
#ifndef vtkMedialThreads_h
#define vtkMedialThreads_h

#include <omp.h>

/// A filter's NumberOfThreads, or every processor when it is 0 (the filters' default).
inline int vtkMedialThreadCount(int requested)
{
  return requested > 0 ? requested : omp_get_num_procs();
}

#endif
