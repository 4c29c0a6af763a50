// SPDX-License-Identifier: BSD-3-Clause
// medial-axis: what the program says on stderr while it works.
//  - Progress: every filter the program runs is watched; its VTK progress events
//    (value and progress text, the stage) become, on a terminal, a bar per stage
//    redrawn in place, and otherwise one plain line per finished stage with its time.
//    --quiet shows none of it.
//  - Messages: VTK errors and warnings of every object arrive in one output window;
//    warnings are printed on lines of their own (the bar is cleared first and drawn
//    again at the next event), the first error is kept as the reason for failing.
//  - Ctrl-C: while a stage that checks for an abort between blocks runs, the filter
//    is asked to abort and the program exits with 130 once it returns; anywhere else
//    it exits at once.
#ifndef MedialAxisConsole_h
#define MedialAxisConsole_h

#include "vtkOutputWindow.h"

#include <chrono>
#include <string>

class vtkAlgorithm;

namespace medialaxis
{
class Console
{
public:
  /// `quiet`: no progress. The bar is drawn only when stderr is a terminal.
  explicit Console(bool quiet);
  ~Console();

  /// Shows `algorithm`'s progress (the console must outlive it); Ctrl-C reaches it too.
  void Watch(vtkAlgorithm* algorithm);

  /// A stage the program does itself (writing, rendering): Begin, then End.
  void Begin(const std::string& stage);
  void End();

  /// The first error VTK reported since the last ClearError(), or "".
  const std::string& GetError() const;
  void ClearError();

  /// After a watched Update: exits with 130 when Ctrl-C aborted it.
  void ExitIfInterrupted();

  /// Called by the output window and the progress observer.
  void Warn(const std::string& text);
  void Progress(vtkAlgorithm* algorithm, double value);

private:
  void Finish(); // ends the current stage's line
  void Draw(double fraction, bool force);

  bool Quiet;
  bool Terminal;
  std::string Stage;
  vtkAlgorithm* StageOwner = nullptr;
  std::chrono::steady_clock::time_point StageStart;
  std::chrono::steady_clock::time_point LastDraw;
  double Fraction = 0.0;
  bool BarShown = false;
  struct Internals;
  Internals* Impl;
};
}

#endif
