// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBuffer
 * @brief Internal: std::vector for the large per-triangle and per-point arrays of the
 * surface preparation: no zero fill, and huge pages where the system offers them.
 *
 * vtkMedialBuffer<T> is std::vector<T, vtkMedialBufferAllocator<T>>. The allocator
 * differs from std::allocator in two ways, both for speed only:
 *  - resize(n) and the size constructor default-initialise instead of
 *    value-initialising: trivial elements are left as they are, not zeroed, because
 *    every one of these arrays is written by the pass that fills it. (A zero fill
 *    touched every page once more, serially, before the parallel pass wrote it.)
 *    Code that relies on zeros must say so (assign(n, 0) or resize(n, 0));
 *  - blocks of 2 MiB or more are aligned to 2 MiB and advised for transparent huge pages
 *    (Linux madvise MADV_HUGEPAGE): 512 times fewer page faults on first touch and
 *    fewer TLB misses in the random accesses of the tree build. Only whole huge pages
 *    inside the block are advised, so the resident size does not grow.
 * Measured on 1.55M triangles (issue 18): about a third of the preparation's CPU time
 * was page faults and zero fills.
 */
#ifndef vtkMedialBuffer_h
#define vtkMedialBuffer_h

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

template <class T>
class vtkMedialBufferAllocator
{
public:
  using value_type = T;

  vtkMedialBufferAllocator() noexcept = default;
  template <class U>
  vtkMedialBufferAllocator(const vtkMedialBufferAllocator<U>&) noexcept
  {
  }

  T* allocate(std::size_t n)
  {
    const std::size_t bytes = n * sizeof(T);
    if (n > static_cast<std::size_t>(-1) / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    if (bytes < HugePage)
    {
      return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    }
    void* p = nullptr;
    if (posix_memalign(&p, HugePage, bytes) != 0)
    {
      throw std::bad_alloc();
    }
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Advice only: ignored where transparent huge pages are off.
    madvise(p, bytes / HugePage * HugePage, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept
  {
    if (n * sizeof(T) < HugePage)
    {
      ::operator delete(p, std::align_val_t(alignof(T)));
    }
    else
    {
      std::free(p);
    }
  }

  /// Default-initialisation: resize(n) leaves trivial elements unset.
  template <class U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U))
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const vtkMedialBufferAllocator<U>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const vtkMedialBufferAllocator<U>&) const noexcept
  {
    return false;
  }

private:
  static constexpr std::size_t HugePage = std::size_t(1) << 21;
};

template <class T>
using vtkMedialBuffer = std::vector<T, vtkMedialBufferAllocator<T>>;

#endif
