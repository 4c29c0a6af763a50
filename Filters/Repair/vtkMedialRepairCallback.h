// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialRepairCallback.h
 * @brief Internal (MedialAxis::Repair): the repair that a filter's preparation
 * (vtkMedialSolidPreparation, in Core) asks for, run by the filter's
 * vtkMedialRepairFilter. Header only, compiled into the filters that repair their
 * input (the sampler, the medial mesh, the thickness, the simplification): Core cannot
 * depend on this module, so the filters hand this callback to it.
 */
#ifndef vtkMedialRepairCallback_h
#define vtkMedialRepairCallback_h

#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidPreparation.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <string>

/// A Repairer that runs `repair` (its Mode, ReportSteps and NumberOfThreads are set
/// here; its other settings are the caller's). Its report lines become the
/// preparation's messages, its error the preparation's error.
inline vtkMedialSolidPreparation::Repairer vtkMedialMakeRepairer(vtkMedialRepairFilter* repair, int threads)
{
  return [repair, threads](vtkPolyData* input, bool wrap, const vtkMedialSolidPreparation::Checked& checked,
           vtkMedialSolidPreparation::Repair& result, std::string& error) {
    if (!repair)
    {
      error = "no repair filter is set (SetRepair)";
      return false;
    }
    // The repair's error becomes this error; the executive's echo of it is dropped.
    std::string caught;
    vtkNew<vtkCallbackCommand> catcher;
    catcher->SetClientData(&caught);
    catcher->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
      std::string text = data ? static_cast<const char*>(data) : "";
      const std::string prefix = "Cannot repair the surface: ";
      const size_t at = text.find(prefix);
      if (at != std::string::npos)
      {
        text = text.substr(at + prefix.size());
        while (!text.empty() && (text.back() == '\n' || text.back() == '.'))
        {
          text.pop_back();
        }
        *static_cast<std::string*>(client) = text;
      }
    });
    vtkNew<vtkCallbackCommand> mute;
    repair->SetInputData(input);
    repair->SetMode(wrap ? vtkMedialRepairFilter::WRAP : vtkMedialRepairFilter::AUTO);
    repair->SetReportSteps(false);
    repair->SetNumberOfThreads(threads);
    const unsigned long tag = repair->AddObserver(vtkCommand::ErrorEvent, catcher);
    const unsigned long muted = repair->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, mute);
    // Used only if the repair runs (an unchanged input keeps its last output).
    repair->SetCheckedInput(checked.Mesh, checked.Query, checked.Check);
    repair->Update();
    repair->ClearCheckedInput();
    repair->RemoveObserver(tag);
    repair->GetExecutive()->RemoveObserver(muted);
    vtkPolyData* output = repair->GetOutput();
    if (!caught.empty() || !output || output->GetNumberOfCells() == 0)
    {
      error = caught.empty() ? std::string("the repair gave no surface") : caught;
      return false;
    }
    result.Surface = output;
    result.Changed = repair->GetChanged();
    result.Messages.clear();
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      // A shell wound inward is no defect to a filter, which orients as it prepares.
      const std::string line = repair->GetReportLine(i);
      if (line.find("wound inward turned over") == std::string::npos)
      {
        result.Messages.push_back("Repair: " + line + ".");
      }
    }
    result.Report = vtkSmartPointer<vtkFieldData>::New();
    result.Report->ShallowCopy(output->GetFieldData());
    return true;
  };
}

#endif
