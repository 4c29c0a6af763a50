// SPDX-License-Identifier: BSD-3-Clause
// Internal: a hint to fetch the cache line at p ahead of its use, for the loops that read
// the mesh's arrays at random (the tree's build, the solid check's culling). Nothing
// where the compiler has no such builtin. Header only; not installed.
#ifndef vtkMedialPrefetch_h
#define vtkMedialPrefetch_h

inline void vtkMedialPrefetch(const void* p)
{
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

#endif
