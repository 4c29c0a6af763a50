// SPDX-License-Identifier: BSD-3-Clause
// Shared by every C++ test of the project: error capture and the check macro.
#ifndef MedialTestSupport_h
#define MedialTestSupport_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace medialtest
{
/// Counts error and warning events of the watched algorithms, keeping their texts,
/// one per line. Observed events are not printed, so no "ERROR: " line reaches ctest.
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
}

#define MEDIAL_CHECK(cond, ...)                                                                    \
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

#endif
