// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the reader tests: a temporary folder, file writing, error capture.
#ifndef ReaderTestUtilities_h
#define ReaderTestUtilities_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

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

/// Counts error and warning events of the watched objects, keeping their texts.
/// Observed events are not printed, so no "ERROR: " line reaches ctest.
struct EventLog
{
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  EventLog()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long event, void* client, void* data) {
      auto* self = static_cast<EventLog*>(client);
      (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)++;
      self->Text += data ? static_cast<const char*>(data) : "";
      self->Text += "\n";
    });
  }
  /// Watches an algorithm and its executive (which reports a failed request).
  void Watch(vtkAlgorithm* a)
  {
    a->AddObserver(vtkCommand::ErrorEvent, this->Command);
    a->AddObserver(vtkCommand::WarningEvent, this->Command);
    a->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
  /// The first logged line that contains `needle`, or an empty string.
  std::string LineWith(const std::string& needle) const
  {
    const size_t at = this->Text.find(needle);
    if (at == std::string::npos)
    {
      return std::string();
    }
    const size_t begin = this->Text.rfind('\n', at);
    const size_t end = this->Text.find('\n', at);
    const size_t from = begin == std::string::npos ? 0 : begin + 1;
    return this->Text.substr(from, end == std::string::npos ? std::string::npos : end - from);
  }
};

#define READER_CHECK(cond, ...)                                                                    \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::printf("FAILED %s:%d: %s: ", __FILE__, __LINE__, #cond);                                 \
      std::printf(__VA_ARGS__);                                                                    \
      std::printf("\n");                                                                           \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (0)
}

#endif
