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
 *  - on Linux, blocks of 1 MiB or more are mapped on their own (mmap), so that freeing
 *    one gives its memory back at once (malloc keeps freed blocks of up to 32 MiB for
 *    reuse, which showed as about 30 MB of resident garbage after the tree build);
 *  - blocks of 2 MiB or more are aligned to 2 MiB and advised for transparent huge pages
 *    (madvise MADV_HUGEPAGE): 512 times fewer page faults on first touch and fewer
 *    TLB misses in the random accesses of the tree build. Only whole huge pages
 *    inside the block are advised, so the resident size does not grow. The
 *    environment variable MEDIALAXIS_HUGE_PAGES=0 turns the advice off (read once).
 * Measured on 1.55M triangles (issue 18): about a third of the preparation's CPU time
 * was page faults and zero fills. Which page size is faster depends on the machine:
 * on one of this project's virtual machines a first touch cost about 15 us per 4 kB
 * page, 50 times a huge page's cost per byte; on another, a huge page that the host
 * had taken back cost about 6 ms and 512 fresh 4 kB pages 1.2 ms, and the preparation
 * was faster without the advice (README, "Huge pages"). Large buffers of the
 * preparation should all be vtkMedialBuffer, not std::vector, either way.
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

/// False when the environment sets MEDIALAXIS_HUGE_PAGES=0: large buffers are then
/// left in the system's default pages. Read once per process.
inline bool vtkMedialBufferHugePages()
{
  static const bool enabled = [] {
    const char* value = std::getenv("MEDIALAXIS_HUGE_PAGES");
    return !(value && value[0] == '0' && value[1] == '\0');
  }();
  return enabled;
}

template <class T, bool HugePages = true>
class vtkMedialBufferAllocator
{
public:
  using value_type = T;
  template <class U>
  struct rebind
  {
    using other = vtkMedialBufferAllocator<U, HugePages>;
  };

  vtkMedialBufferAllocator() noexcept = default;
  template <class U>
  vtkMedialBufferAllocator(const vtkMedialBufferAllocator<U, HugePages>&) noexcept
  {
  }

  T* allocate(std::size_t n)
  {
    if (n > static_cast<std::size_t>(-1) / sizeof(T) / 2)
    {
      throw std::bad_array_new_length();
    }
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
    if (bytes >= Mapped)
    {
      return static_cast<T*>(Map(bytes));
    }
#endif
    return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
  }

  void deallocate(T* p, std::size_t n) noexcept
  {
#if defined(__linux__)
    if (n * sizeof(T) >= Mapped)
    {
      munmap(p, RoundUp(n * sizeof(T), Page));
      return;
    }
#endif
    ::operator delete(p, std::align_val_t(alignof(T)));
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
  bool operator==(const vtkMedialBufferAllocator<U, HugePages>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const vtkMedialBufferAllocator<U, HugePages>&) const noexcept
  {
    return false;
  }

private:
  static constexpr std::size_t Page = std::size_t(1) << 12;
  static constexpr std::size_t HugePage = std::size_t(1) << 21;
  // Blocks from this size on are mapped on their own, so that freeing one returns its
  // memory at once (malloc may keep freed blocks of up to 32 MiB for reuse).
  static constexpr std::size_t Mapped = std::size_t(1) << 20;

  static std::size_t RoundUp(std::size_t bytes, std::size_t unit) { return (bytes + unit - 1) / unit * unit; }

#if defined(__linux__)
  // A private anonymous mapping of `bytes` (rounded up to whole pages). With huge
  // pages, at least 2 MiB, it starts on a 2 MiB boundary (over-mapped, then trimmed)
  // and its whole huge pages are advised.
  static void* Map(std::size_t bytes)
  {
    const std::size_t size = RoundUp(bytes, Page);
    const bool huge = HugePages && bytes >= HugePage && vtkMedialBufferHugePages();
    const std::size_t mapped = huge ? size + HugePage : size;
    void* p = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
    {
      throw std::bad_alloc();
    }
    if (!huge)
    {
      return p;
    }
    char* begin = static_cast<char*>(p);
    char* aligned = reinterpret_cast<char*>(RoundUp(reinterpret_cast<std::uintptr_t>(begin), HugePage));
    if (aligned > begin)
    {
      munmap(begin, static_cast<std::size_t>(aligned - begin));
    }
    const std::size_t tail = mapped - static_cast<std::size_t>(aligned - begin) - size;
    if (tail > 0)
    {
      munmap(aligned + size, tail);
    }
#if defined(MADV_HUGEPAGE)
    // Advice only: ignored where transparent huge pages are off.
    madvise(aligned, bytes / HugePage * HugePage, MADV_HUGEPAGE);
#endif
    return aligned;
  }
#endif
};

template <class T>
using vtkMedialBuffer = std::vector<T, vtkMedialBufferAllocator<T>>;

/// For a buffer shrunk in place (resize down keeps the block): gives the whole pages
/// past its size back to the system, so that they no longer count as resident. They
/// stay reserved, and read as zeros if the buffer grows into them again.
template <class T>
void vtkMedialReleaseSpareCapacity(vtkMedialBuffer<T>& buffer)
{
#if defined(__linux__) && defined(MADV_DONTNEED)
  const std::size_t page = std::size_t(1) << 12;
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(buffer.data() + buffer.size());
  const std::uintptr_t first = (end + page - 1) / page * page;
  const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(buffer.data() + buffer.capacity()) / page * page;
  if (last > first && buffer.capacity() * sizeof(T) >= (std::size_t(1) << 20)) // mapped on its own
  {
    madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
  }
#else
  (void)buffer;
#endif
}

#endif
