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
 *    inside the block are advised, so the resident size does not grow. Whether they
 *    are is decided once per process (vtkMedialBufferHugePages): by the environment
 *    variable MEDIALAXIS_HUGE_PAGES (0 or 1), else by measuring what a first touch
 *    of a 4 kB page costs on this machine.
 * Measured on 1.55M triangles (issue 18): about a third of the preparation's CPU time
 * was page faults and zero fills. Which page size is faster depends on the machine:
 * on one of this project's virtual machines a first touch cost about 15 us per 4 kB
 * page, 50 times a huge page's cost per byte; on another, a huge page that the host
 * had taken back cost about 6 ms and 512 fresh 4 kB pages 1.2 ms, and the preparation
 * was faster without it (docs/performance.md, "Huge pages"). Large buffers of the
 * preparation should all be vtkMedialBuffer, not std::vector, either way.
 */
#ifndef vtkMedialBuffer_h
#define vtkMedialBuffer_h

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <new>
#include <string>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

/// What one process measured of the first touch of fresh memory, in milliseconds per
/// MiB, with and without the huge-page advice (vtkMedialFirstTouchProbe).
struct vtkMedialFirstTouchCosts
{
  double HugePages = 0.0; // -1 when not measured
  double SmallPages = 0.0;
};

#if defined(__linux__)
/// A private anonymous mapping of `size` bytes (a multiple of 4 kB) that starts on a
/// 2 MiB boundary, so that its whole huge pages can be advised: mapped 2 MiB larger,
/// then trimmed. Null when the system refuses the mapping.
inline char* vtkMedialMapOnHugePageBoundary(std::size_t size)
{
  const std::size_t hugePage = std::size_t(1) << 21;
  const std::size_t mapped = size + hugePage;
  void* p = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED)
  {
    return nullptr;
  }
  char* begin = static_cast<char*>(p);
  char* aligned =
    reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(begin) + hugePage - 1) / hugePage * hugePage);
  if (aligned > begin)
  {
    munmap(begin, static_cast<std::size_t>(aligned - begin));
  }
  const std::size_t tail = mapped - static_cast<std::size_t>(aligned - begin) - size;
  if (tail > 0)
  {
    munmap(aligned + size, tail);
  }
  return aligned;
}

/// Milliseconds per MiB to write fresh anonymous memory once: `bytes` (a multiple of
/// 4 kB) mapped on a 2 MiB boundary, advised for huge pages or kept in 4 kB pages, one
/// write per 4 kB.
inline double vtkMedialFirstTouchMilliseconds(std::size_t bytes, bool huge)
{
  char* aligned = vtkMedialMapOnHugePageBoundary(bytes);
  if (!aligned)
  {
    return -1.0;
  }
#if defined(MADV_HUGEPAGE) && defined(MADV_NOHUGEPAGE)
  madvise(aligned, bytes, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
#else
  (void)huge;
#endif
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < bytes; i += 4096)
  {
    static_cast<volatile char*>(aligned)[i] = 1;
  }
  const std::chrono::duration<double, std::milli> spent = std::chrono::steady_clock::now() - start;
  munmap(aligned, bytes);
  return spent.count() / (static_cast<double>(bytes) / (1 << 20));
}
#endif

/// Measures once per process what a first touch costs in huge pages (4 MiB advised)
/// and in 4 kB pages (2 MiB): 1 to 20 ms, paid at the first large buffer. The probe's
/// memory is freed at once, and the next buffers get it. HugePages is -1 where
/// transparent huge pages are off, or not on Linux.
inline vtkMedialFirstTouchCosts vtkMedialFirstTouchProbe()
{
  static const vtkMedialFirstTouchCosts costs = [] {
    vtkMedialFirstTouchCosts measured;
    measured.HugePages = -1.0;
#if defined(__linux__)
    std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(setting, modes);
    if (modes.empty() || modes.find("[never]") != std::string::npos)
    {
      return measured;
    }
    measured.SmallPages = vtkMedialFirstTouchMilliseconds(std::size_t(1) << 21, false);
    measured.HugePages = vtkMedialFirstTouchMilliseconds(std::size_t(1) << 22, true);
#endif
    return measured;
  }();
  return costs;
}

/// What a huge page costs, in milliseconds per MiB, when the host has to back it afresh:
/// 2 to 3 on both of this project's virtual machines that were measured (issue 18).
/// Such a host keeps a few recently freed huge pages backed (14 MiB on one), so a small
/// sample cannot see this cost, and a sample large enough to get past them costs
/// 50 ms; hence a constant, from those measurements.
constexpr double vtkMedialFreshHugePageCost = 2.0;

/// The rule for measured costs: huge pages when 4 kB pages cost more per byte on first
/// touch than a huge page that the host has to back afresh (vtkMedialFreshHugePageCost)
/// and than the huge pages the probe got.
inline bool vtkMedialHugePagesAreCheaper(const vtkMedialFirstTouchCosts& costs)
{
  return costs.HugePages >= 0.0 && costs.SmallPages > costs.HugePages &&
    costs.SmallPages > vtkMedialFreshHugePageCost;
}

/// Whether vtkMedialBuffer advises its large blocks for transparent huge pages, decided
/// once per process: MEDIALAXIS_HUGE_PAGES=0 says no, =1 says yes; otherwise (unset or
/// "auto") vtkMedialHugePagesAreCheaper on the probe's costs. Why: it goes both ways.
/// On one of this project's virtual machines a 4 kB page cost about 15 us (3.5 to 7.5
/// ms per MiB) and huge pages were the faster even when fresh; on another a 4 kB page
/// cost about 2 us (0.4 to 0.6 ms per MiB), and the preparation of the 1.55 M horse
/// took 0.8 to 1.0 s in 4 kB pages, 1.4 to 1.6 s in huge pages, most of which the host
/// backed afresh at 4.3 to 6.6 ms.
inline bool vtkMedialBufferHugePages()
{
  static const bool enabled = [] {
    const char* value = std::getenv("MEDIALAXIS_HUGE_PAGES");
    const std::string setting = value ? value : "";
    if (setting == "0" || setting == "1")
    {
      return setting == "1";
    }
    return vtkMedialHugePagesAreCheaper(vtkMedialFirstTouchProbe());
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
  // pages, at least 2 MiB, it starts on a 2 MiB boundary (vtkMedialMapOnHugePageBoundary)
  // and its whole huge pages are advised.
  static void* Map(std::size_t bytes)
  {
    const std::size_t size = RoundUp(bytes, Page);
    const bool huge = HugePages && bytes >= HugePage && vtkMedialBufferHugePages();
    if (!huge)
    {
      void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED)
      {
        throw std::bad_alloc();
      }
      return p;
    }
    char* aligned = vtkMedialMapOnHugePageBoundary(size);
    if (!aligned)
    {
      throw std::bad_alloc();
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
