// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialStages
 * @brief Internal: the stages of a filter's run as VTK progress, so that every
 * long stage reports its own progress and name to any observer (the command
 * line's bar, ParaView's progress bar).
 *
 * Begin(text, start, end) sets the algorithm's progress text, reports `start`, and
 * maps the stage's own UpdateProgress(f) calls (f from 0 to 1) to
 * start + f * (end - start) through vtkAlgorithm::SetProgressShiftScale, until the
 * next Begin(). The destructor restores the plain range, so the executive's
 * closing UpdateProgress(1.0) means 1 on every return path. Header only; not
 * installed.
 */
#ifndef vtkMedialProgress_h
#define vtkMedialProgress_h

#include "vtkAlgorithm.h"

class vtkMedialStages
{
public:
  explicit vtkMedialStages(vtkAlgorithm* algorithm)
    : Algorithm(algorithm)
  {
  }
  ~vtkMedialStages() { this->Algorithm->SetProgressShiftScale(0.0, 1.0); }
  vtkMedialStages(const vtkMedialStages&) = delete;
  vtkMedialStages& operator=(const vtkMedialStages&) = delete;

  /// Starts the stage `text` over [start, end] of the algorithm's progress.
  void Begin(const char* text, double start, double end)
  {
    this->Algorithm->SetProgressShiftScale(0.0, 1.0);
    this->Algorithm->SetProgressText(text);
    this->Algorithm->UpdateProgress(start);
    this->Algorithm->SetProgressShiftScale(start, end - start);
  }

private:
  vtkAlgorithm* Algorithm;
};

#endif
