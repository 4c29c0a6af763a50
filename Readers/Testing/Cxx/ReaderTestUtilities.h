// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the reader tests: a temporary folder and file writing, a read
// through vtkMedialFileReader, cells as id lists (error capture
// and MEDIAL_CHECK come from Testing/Cxx/MedialTestSupport.h).
#ifndef ReaderTestUtilities_h
#define ReaderTestUtilities_h

#include "MedialTestSupport.h"

#include "vtkMedialFileReader.h"

#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace readertest
{
/// A fresh folder under the system temporary folder, removed with its files at exit.
class TempDir
{
public:
  TempDir()
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "medial-readers-XXXXXX").string();
    if (mkdtemp(pattern.data()))
    {
      this->Path = pattern;
    }
  }
  ~TempDir()
  {
    if (!this->Path.empty())
    {
      std::error_code ignored;
      std::filesystem::remove_all(this->Path, ignored);
    }
  }
  bool Valid() const { return !this->Path.empty(); }
  /// Writes `content` byte for byte into a file of the folder and returns its path.
  std::string Write(const std::string& name, const std::string& content) const
  {
    const std::string path = this->Path + "/" + name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }
  std::string File(const std::string& name) const { return this->Path + "/" + name; }
  std::string Path;
};

/// Error capture shared with the other modules' tests.
using medialtest::EventLog;

/// One run of vtkMedialFileReader: whether the update succeeded, its output, its messages.
struct Read
{
  bool Ok = false;
  vtkSmartPointer<vtkPolyData> Output;
  EventLog Log;
};

inline void ReadFile(const std::string& path, int content, Read& result)
{
  vtkNew<vtkMedialFileReader> reader;
  result.Log.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetContent(content);
  result.Ok = reader->GetExecutive()->Update() == 1;
  result.Output = reader->GetOutput();
}

/// The cells of a cell array as lists of point ids, for exact comparisons.
using Cells = std::vector<std::vector<vtkIdType>>;
inline Cells CellsOf(vtkCellArray* cells)
{
  Cells out;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    out.emplace_back(ids, ids + n);
  }
  return out;
}
}

#endif
