// SPDX-License-Identifier: BSD-3-Clause
// Shared by the fuzz entry points: the readers take file names, so each input is
// written to a per-process temporary file first.
#ifndef FuzzInput_h
#define FuzzInput_h

#include "vtkObject.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzzinput
{
/// A file in $TMPDIR (or /tmp) unique to this process, removed at exit.
inline const std::string& TempFile(const char* suffix)
{
  static std::string path;
  if (path.empty())
  {
    const char* dir = std::getenv("TMPDIR");
    path = std::string(dir && *dir ? dir : "/tmp") + "/medialaxis-fuzz-" +
      std::to_string(static_cast<long>(getpid())) + suffix;
    std::atexit([] { std::remove(path.c_str()); });
  }
  return path;
}

/// Writes the bytes to the file; false on failure.
inline bool WriteFile(const std::string& path, const uint8_t* data, size_t size)
{
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return false;
  }
  const bool ok = std::fwrite(data, 1, size, file) == size;
  return std::fclose(file) == 0 && ok;
}

/// Aborts so that libFuzzer records the input: an invariant of the reader broke.
inline void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
    std::abort();
  }
}
}

/// Malformed inputs are the point: keep their error messages quiet.
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff();
  return 0;
}

#endif
