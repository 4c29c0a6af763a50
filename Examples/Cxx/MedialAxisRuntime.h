// SPDX-License-Identifier: BSD-3-Clause
/**
 * medialaxis::RestartWithRuntimeSettings: run once more, at once, with two settings that
 * can only be made before a program starts:
 *  - GLIBC_TUNABLES=glibc.malloc.hugetlb=1: glibc's malloc asks for transparent huge
 *    pages. VTK allocates its arrays (a reader's points and cells, every filter's
 *    output) with malloc, which maps large blocks in 4 kB pages. Where the system gives
 *    huge pages only on request (the default "madvise" setting), each 4 kB page costs a
 *    fault on first touch: on one of this project's 2-core virtual machines about 15 us,
 *    so reading a 68 MB surface took 0.3 to 0.5 s instead of 0.05 s (issue 18). Set only
 *    when vtkMedialBuffer uses huge pages (vtkMedialBufferHugePages: MEDIALAXIS_HUGE_PAGES,
 *    else a measurement): on a machine whose host backs huge pages slowly, 4 kB pages
 *    are faster. The restarted program gets that decision as MEDIALAXIS_HUGE_PAGES=0
 *    or 1, so that it does not measure again;
 *  - OMP_WAIT_POLICY=passive: an OpenMP thread that waits at a barrier sleeps instead of
 *    spinning for a while first. On a machine whose cores are shared, a spinning thread
 *    takes the core its late partner needs: at load 7 on 2 cores, the preparation (mesh
 *    and tree) of the 1.55M-triangle horse took a median 3.31 s with the default and
 *    2.62 s with this, over five alternating runs of each; at load 6 the wall times were
 *    alike and the spinning cost 0.4 CPU s more (issue 18). Alone on the machine the sleep
 *    costs a wake-up per barrier (microseconds).
 * Each is set only when the user has not set it (GLIBC_TUNABLES; OMP_WAIT_POLICY or
 * GOMP_SPINCOUNT: set either, e.g. empty, to keep libgomp's default), and the program
 * restarts only when it set one, so it restarts at most once. Skipped outside Linux and
 * glibc, and when the program cannot be executed again (then it goes on as it is). Only
 * the CLI and the benchmark programs do this; a library never restarts its host.
 */
#ifndef MedialAxisRuntime_h
#define MedialAxisRuntime_h

#include <cstdlib> // first: it defines __GLIBC__

#include "vtkMedialBuffer.h" // vtkMedialBufferHugePages: MEDIALAXIS_HUGE_PAGES read in one place
#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace medialaxis
{
inline void RestartWithRuntimeSettings(char* argv[])
{
#if defined(__linux__) && defined(__GLIBC__)
  bool changed = false;
  const bool hugePages = vtkMedialBufferHugePages();
  if (!std::getenv("GLIBC_TUNABLES") && hugePages)
  {
    changed = setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) == 0 || changed;
  }
  if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT"))
  {
    changed = setenv("OMP_WAIT_POLICY", "passive", 1) == 0 || changed;
  }
  if (changed)
  {
    setenv("MEDIALAXIS_HUGE_PAGES", hugePages ? "1" : "0", 1);
    execv("/proc/self/exe", argv); // returns only on failure
  }
#else
  (void)argv;
#endif
}
}

#endif
