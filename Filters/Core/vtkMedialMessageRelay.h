// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMessageRelay
 * @brief Internal: reports the errors and warnings of an object a class runs inside
 * (a stock reader, a PNG writer) again as that class's own.
 *
 * VTK's message text "Class (0x...): message" keeps only the message, so an observer
 * of the outer object, or the output window, reads the inner object's words, and the
 * outer object fails in its own name. Errors are counted. Mute() swallows (and counts)
 * an object's errors that only repeat another's, such as an executive's "returned
 * failure for request". RelayProgress() reports an inner algorithm's progress as
 * the outer algorithm's, mapped into a share of its range. Header only; not installed.
 */
#ifndef vtkMedialMessageRelay_h
#define vtkMedialMessageRelay_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkSetGet.h"

#include <cctype>
#include <string>

class vtkMedialMessageRelay : public vtkCommand
{
public:
  static vtkMedialMessageRelay* New() { return new vtkMedialMessageRelay; }
  vtkBaseTypeMacro(vtkMedialMessageRelay, vtkCommand);

  /// The object that reports the messages (not referenced: it owns the relay).
  vtkObject* Outer = nullptr;
  /// Errors seen, relayed or muted.
  int Errors = 0;

  /// Relays `inner`'s errors and warnings.
  void Relay(vtkObject* inner)
  {
    inner->AddObserver(vtkCommand::ErrorEvent, this);
    inner->AddObserver(vtkCommand::WarningEvent, this);
  }

  /// Reports `inner`'s progress p as the outer algorithm's start + share * p (Outer
  /// must then be a vtkAlgorithm).
  void RelayProgress(vtkAlgorithm* inner, double start = 0.0, double share = 1.0)
  {
    this->ProgressStart = start;
    this->ProgressShare = share;
    inner->AddObserver(vtkCommand::ProgressEvent, this->Progress);
  }

  /// Counts `source`'s errors without reporting them.
  void Mute(vtkObject* source) { source->AddObserver(vtkCommand::ErrorEvent, this->Muted); }

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    std::string text = callData ? static_cast<const char*>(callData) : "";
    const size_t colon = text.find("): ");
    if (colon != std::string::npos)
    {
      text.erase(0, colon + 3);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      vtkErrorWithObjectMacro(this->Outer, << text);
    }
    else
    {
      vtkWarningWithObjectMacro(this->Outer, << text);
    }
  }

protected:
  vtkMedialMessageRelay()
  {
    this->Muted->SetClientData(this);
    this->Muted->SetCallback(
      [](vtkObject*, unsigned long, void* client, void*) { ++static_cast<vtkMedialMessageRelay*>(client)->Errors; });
    this->Progress->SetClientData(this);
    this->Progress->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
      auto* self = static_cast<vtkMedialMessageRelay*>(client);
      if (auto* outer = vtkAlgorithm::SafeDownCast(self->Outer))
      {
        outer->UpdateProgress(self->ProgressStart + self->ProgressShare * *static_cast<double*>(data));
      }
    });
  }
  ~vtkMedialMessageRelay() override = default;

private:
  vtkNew<vtkCallbackCommand> Muted;
  vtkNew<vtkCallbackCommand> Progress;
  double ProgressStart = 0.0;
  double ProgressShare = 1.0;
};

#endif
