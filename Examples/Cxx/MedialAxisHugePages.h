// SPDX-License-Identifier: BSD-3-Clause
/**
 * medialaxis::RestartWithHugePages: run once more, at once, with glibc's malloc asking
 * for transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1).
 *
 * VTK allocates its arrays (a reader's points and cells, every filter's output) with
 * malloc, which maps large blocks in 4 kB pages. Where the system gives transparent
 * huge pages only on request (the default "madvise" setting), each 4 kB page costs a
 * fault on first touch: on this project's 2-core virtual machine about 15 us, so reading
 * a 68 MB surface took 0.3 to 0.5 s instead of 0.05 s (issue 18). The tunable can only
 * be set before the program starts, hence the restart. It is skipped when
 * GLIBC_TUNABLES is already set (by the user, or by the restart itself: set it to
 * anything, e.g. empty, to opt out), outside Linux and glibc, and when the program
 * cannot be executed again (then it goes on as it is). Only the CLI and the benchmark
 * programs do this; a library never restarts its host.
 */
#ifndef MedialAxisHugePages_h
#define MedialAxisHugePages_h

#include <cstdlib> // first: it defines __GLIBC__
#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace medialaxis
{
inline void RestartWithHugePages(char* argv[])
{
#if defined(__linux__) && defined(__GLIBC__)
  if (std::getenv("GLIBC_TUNABLES") || setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) != 0)
  {
    return;
  }
  execv("/proc/self/exe", argv); // returns only on failure
#else
  (void)argv;
#endif
}
}

#endif
