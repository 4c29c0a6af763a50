// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialBuffer advises its large blocks for transparent huge pages when the
// environment sets MEDIALAXIS_HUGE_PAGES=1, not when it sets 0, and otherwise when its
// probe found 4 kB pages dearer to touch first than huge pages, fresh or probed. The
// test runs three times (see CMakeLists.txt): as is, with 0 and with 1. It finds the
// mapping of a 16 MiB buffer in /proc/self/smaps and checks its "hg" flag (VM_HUGEPAGE,
// set by madvise) against the setting. Skipped where there is no /proc/self/smaps or
// the kernel has no transparent huge pages.
#include "vtkMedialBuffer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
// The VmFlags of the mapping that holds `address`; empty when not found.
std::string FlagsOfMapping(const void* address)
{
  std::ifstream smaps("/proc/self/smaps");
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(address);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line))
  {
    unsigned long long low = 0, high = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> low >> dash >> high && dash == '-')
    {
      inside = a >= low && a < high;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0)
    {
      return line.substr(8) + " ";
    }
  }
  return std::string();
}
}

int TestMedialBufferPages(int, char*[])
{
  const char* value = std::getenv("MEDIALAXIS_HUGE_PAGES");
  const std::string setting = value ? value : "";
  bool expected = setting == "1";
  if (setting != "0" && setting != "1")
  {
    // The probe decides: both costs measured (or huge pages off), and the rule applied.
    const vtkMedialFirstTouchCosts costs = vtkMedialFirstTouchProbe();
    std::printf("first touch: huge pages %.3f ms per MiB, 4 kB pages %.3f ms per MiB\n", costs.HugePages,
      costs.SmallPages);
    if (costs.HugePages >= 0.0 && !(costs.HugePages > 0.0 && costs.SmallPages > 0.0))
    {
      std::printf("the probe did not measure both page sizes\n");
      return 1;
    }
    expected = vtkMedialHugePagesAreCheaper(costs);
  }
  if (vtkMedialBufferHugePages() != expected)
  {
    std::printf("MEDIALAXIS_HUGE_PAGES=%s, but vtkMedialBufferHugePages() is %d\n", value ? value : "(unset)",
      vtkMedialBufferHugePages() ? 1 : 0);
    return 1;
  }
  if (!std::ifstream("/proc/self/smaps") || !std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
  {
    std::printf("skipped: no /proc/self/smaps or no transparent huge pages\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkMedialBuffer<double> large(std::size_t(1) << 21); // 16 MiB
  for (std::size_t i = 0; i < large.size(); i += 512)
  {
    large[i] = static_cast<double>(i);
  }
  const std::string flags = FlagsOfMapping(large.data() + large.size() / 2);
  if (flags.empty())
  {
    std::printf("the buffer's mapping is not in /proc/self/smaps\n");
    return 1;
  }
  const bool advised = flags.find(" hg ") != std::string::npos;
  std::printf("MEDIALAXIS_HUGE_PAGES=%s: VmFlags%s\n", value ? value : "(unset)", flags.c_str());
  if (advised != expected)
  {
    std::printf("the 16 MiB buffer is %sadvised for huge pages; expected %s\n", advised ? "" : "not ",
      expected ? "advised" : "not advised");
    return 1;
  }
  return 0;
}
