// SPDX-License-Identifier: BSD-3-Clause
#include "MedialAxisConsole.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
volatile std::sig_atomic_t Interrupted = 0;
// Set while a stage runs that checks for an abort between blocks.
volatile std::sig_atomic_t AbortWatched = 0;
volatile std::sig_atomic_t BarOnScreen = 0;

// Ctrl-C: in a stage that checks for an abort, ask it to abort (the progress
// observer does); anywhere else nothing would notice, so leave at once.
void OnInterrupt(int)
{
  Interrupted = 1;
  if (!AbortWatched)
  {
    const char clear[] = "\r\033[K", message[] = "medial-axis: interrupted\n";
    if (BarOnScreen)
    {
      [[maybe_unused]] const ssize_t cleared = write(STDERR_FILENO, clear, sizeof(clear) - 1);
    }
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message, sizeof(message) - 1);
    _exit(130);
  }
}

// Stages that check for an abort between their blocks (the filters' progress texts).
bool Abortable(const std::string& stage)
{
  return stage.rfind("Sampling", 0) == 0 || stage == "Drawing the samples" || stage == "Solving the boundary disks" ||
    stage == "Finding the junctions" || stage == "Filling the distance field" ||
    stage.rfind("Measuring the thickness", 0) == 0;
}

// VTK writes "ERROR: In file, line N\nClass (0x...): message"; keep the message.
std::string OneLine(const char* raw)
{
  std::string text = raw ? raw : "";
  const size_t colon = text.find("): ");
  if (colon != std::string::npos)
  {
    text = text.substr(colon + 3);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.pop_back();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// Receives every VTK error and warning (readers' internal helpers included): warnings
// go to the console, the first error is kept as the reason for failing.
class MessageSink : public vtkOutputWindow
{
public:
  static MessageSink* New();
  vtkTypeMacro(MessageSink, vtkOutputWindow);

  medialaxis::Console* Owner = nullptr;
  std::string LastError;

  void DisplayErrorText(const char* raw) override
  {
    const std::string text = OneLine(raw);
    // The executive's "returned failure" follows the real reason; use it only alone.
    const bool pipelineNote = text.find("returned failure for request") != std::string::npos;
    if (this->LastError.empty() || this->ReasonIsFallback)
    {
      if (!pipelineNote)
      {
        this->LastError = text;
        this->ReasonIsFallback = false;
      }
      else if (this->LastError.empty())
      {
        this->LastError = this->LastWarning.empty() ? text.substr(0, text.find(" for request")) : this->LastWarning;
        this->ReasonIsFallback = true;
      }
    }
  }
  void DisplayWarningText(const char* raw) override
  {
    this->LastWarning = OneLine(raw);
    this->Owner->Warn(this->LastWarning);
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { std::fputs(text, stderr); }
  void DisplayDebugText(const char*) override {}

private:
  std::string LastWarning;
  bool ReasonIsFallback = false;
};
vtkStandardNewMacro(MessageSink);
}

namespace medialaxis
{
struct Console::Internals
{
  vtkSmartPointer<MessageSink> Sink;
  vtkNew<vtkCallbackCommand> OnProgress;
  vtkNew<vtkCallbackCommand> OnEnd;
};

Console::Console(bool quiet)
  : Quiet(quiet)
  , Terminal(isatty(STDERR_FILENO) != 0)
  , Impl(new Internals)
{
  this->Impl->Sink = vtkSmartPointer<MessageSink>::New();
  this->Impl->Sink->Owner = this;
  vtkOutputWindow::SetInstance(this->Impl->Sink);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the sink prints instead
  this->Impl->OnProgress->SetClientData(this);
  this->Impl->OnProgress->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    static_cast<Console*>(client)->Progress(static_cast<vtkAlgorithm*>(caller), *static_cast<double*>(data));
  });
  this->Impl->OnEnd->SetClientData(this);
  this->Impl->OnEnd->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* self = static_cast<Console*>(client);
    if (self->StageOwner == caller)
    {
      self->Finish();
    }
  });
  std::signal(SIGINT, OnInterrupt);
}

Console::~Console()
{
  this->Finish();
  vtkOutputWindow::SetInstance(nullptr);
  delete this->Impl;
}

void Console::Watch(vtkAlgorithm* algorithm)
{
  algorithm->AddObserver(vtkCommand::ProgressEvent, this->Impl->OnProgress);
  algorithm->AddObserver(vtkCommand::EndEvent, this->Impl->OnEnd);
}

const std::string& Console::GetError() const
{
  return this->Impl->Sink->LastError;
}

void Console::ClearError()
{
  this->Impl->Sink->LastError.clear();
}

void Console::Warn(const std::string& text)
{
  if (this->BarShown)
  {
    std::fputs("\r\033[K", stderr); // the warning gets a line of its own
    this->BarShown = false;
    BarOnScreen = 0;
  }
  std::fprintf(stderr, "medial-axis: warning: %s\n", text.c_str());
}

void Console::Progress(vtkAlgorithm* algorithm, double value)
{
  const char* text = algorithm->GetProgressText();
  if (!text || !*text)
  {
    return; // the pipeline's opening event, before the filter names its stage
  }
  const bool fresh = this->Stage != text || this->StageOwner != algorithm;
  if (fresh)
  {
    this->Finish();
    this->Stage = text;
    this->StageOwner = algorithm;
    this->StageStart = std::chrono::steady_clock::now();
  }
  // The stage's own fraction: the filters map it into their range by shift and scale.
  const double scale = algorithm->GetProgressScale();
  const double fraction = fresh ? 0.0 : (scale > 0.0 ? (value - algorithm->GetProgressShift()) / scale : value);
  this->Fraction = std::min(1.0, std::max(this->Fraction, fraction));
  AbortWatched = Abortable(this->Stage) ? 1 : 0;
  if (Interrupted)
  {
    algorithm->SetAbortExecute(1);
  }
  this->Draw(this->Fraction, fresh);
}

void Console::Begin(const std::string& stage)
{
  this->Finish();
  this->Stage = stage;
  this->StageOwner = nullptr;
  this->StageStart = std::chrono::steady_clock::now();
  this->Draw(0.0, true);
}

void Console::End()
{
  this->Fraction = 1.0;
  this->Finish();
}

// A terminal line: stage, bar, percent and time, redrawn at most ten times a second.
void Console::Draw(double fraction, bool force)
{
  if (this->Quiet || !this->Terminal)
  {
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - this->LastDraw < std::chrono::milliseconds(100))
  {
    return;
  }
  this->LastDraw = now;
  const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
  const double seconds = std::chrono::duration<double>(now - this->StageStart).count();
  std::fprintf(stderr, "\r%-32.32s [%s%s] %3d%% %6.1f s\033[K", this->Stage.c_str(), std::string(filled, '#').c_str(),
    std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100 + 0.5), seconds);
  std::fflush(stderr);
  this->BarShown = true;
  BarOnScreen = 1;
}

// Ends the current stage: its bar stays on its own line (terminal), or one line
// names it with its time (otherwise).
void Console::Finish()
{
  if (this->Stage.empty())
  {
    return;
  }
  const bool completed = !Interrupted && this->GetError().empty();
  if (completed)
  {
    this->Fraction = 1.0;
  }
  if (!this->Quiet && this->Terminal)
  {
    this->Draw(this->Fraction, true);
    std::fputs("\n", stderr);
  }
  else if (!this->Quiet)
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - this->StageStart).count();
    std::fprintf(stderr, "medial-axis: %s: %s (%.2f s)\n", this->Stage.c_str(),
      completed ? "done" : "stopped", seconds);
  }
  this->BarShown = false;
  BarOnScreen = 0;
  AbortWatched = 0;
  this->Stage.clear();
  this->StageOwner = nullptr;
  this->Fraction = 0.0;
}

void Console::ExitIfInterrupted()
{
  if (Interrupted)
  {
    this->Finish();
    std::fputs("medial-axis: interrupted\n", stderr);
    std::exit(130);
  }
}
}
