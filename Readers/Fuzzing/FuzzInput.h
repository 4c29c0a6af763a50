// SPDX-License-Identifier: BSD-3-Clause
// Shared by the fuzz entry points: the readers take file names, so each input is
// written to a per-process temporary file first.
#ifndef FuzzInput_h
#define FuzzInput_h

#include "vtkExecutive.h"
#include "vtkObject.h"
#include "vtkPolyData.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace fuzzinput
{
/// A file in $TMPDIR (or /tmp) unique to this process and suffix, removed at exit.
inline const std::string& TempFile(const std::string& suffix)
{
  static std::map<std::string, std::string> paths;
  std::string& path = paths[suffix];
  if (path.empty())
  {
    const char* dir = std::getenv("TMPDIR");
    path = std::string(dir && *dir ? dir : "/tmp") + "/medialaxis-fuzz-" +
      std::to_string(static_cast<long>(getpid())) + suffix;
    if (paths.size() == 1)
    {
      std::atexit([] {
        for (const auto& entry : paths)
        {
          std::remove(entry.second.c_str());
        }
      });
    }
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

/// Runs the reader on the bytes, through a temporary file ending in `suffix`.
/// Returns its output after a successful read; after an error, checks that the
/// output is empty and returns null.
template <class Reader>
vtkPolyData* Read(Reader* reader, const char* suffix, const uint8_t* data, size_t size)
{
  const std::string& path = TempFile(suffix);
  if (!WriteFile(path, data, size))
  {
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  const int ok = reader->GetExecutive()->Update();
  vtkPolyData* mesh = reader->GetOutput();
  if (!ok)
  {
    Require(mesh->GetNumberOfPoints() == 0 && mesh->GetNumberOfCells() == 0, "empty output after an error");
    return nullptr;
  }
  return mesh;
}

/// Every point of the mesh has finite coordinates.
inline void RequireFinitePoints(vtkPolyData* mesh)
{
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    Require(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), "finite point");
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
