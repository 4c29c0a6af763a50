// SPDX-License-Identifier: BSD-3-Clause
// The repair reports progress between its steps (never going back, ending at 1, under
// each step's own text) and honours an abort: aborted at its first progress event, it
// stops without an error and leaves an empty output, and the same filter repairs the
// same input in full once the abort is lifted.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkMedialRepairFilter.h"

#include <string>
#include <utility>
#include <vector>

int TestMedialRepairProgress(int, char*[])
{
  // A sphere with holes: several steps run (check, holes, orient, measure).
  const medialtest::Defect defect = medialtest::defects::SphereWithHoles();
  vtkNew<vtkMedialRepairFilter> repair;
  repair->SetInputData(defect.Surface);
  repair->SetReportSteps(false);
  struct Log
  {
    std::vector<std::pair<std::string, double>> Events;
    bool AbortFirst = false;
  } log;
  vtkNew<vtkCallbackCommand> command;
  command->SetClientData(&log);
  command->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    auto* l = static_cast<Log*>(client);
    auto* filter = static_cast<vtkMedialRepairFilter*>(caller);
    const char* text = filter->GetProgressText();
    l->Events.emplace_back(text ? text : "", *static_cast<double*>(data));
    if (l->AbortFirst)
    {
      filter->SetAbortExecute(1);
    }
  });
  repair->AddObserver(vtkCommand::ProgressEvent, command);
  medialtest::EventLog errors;
  errors.Watch(repair);

  log.AbortFirst = true;
  repair->Update();
  std::printf("aborted: %zu progress events, %d errors, %lld output triangles\n", log.Events.size(), errors.Errors,
    static_cast<long long>(repair->GetOutput()->GetNumberOfPolys()));
  MEDIAL_CHECK(errors.Errors == 0, "an abort is reported as an error: %s", errors.Text.c_str());
  MEDIAL_CHECK(repair->GetOutput()->GetNumberOfPoints() == 0, "an aborted repair left an output");
  MEDIAL_CHECK(log.Events.size() <= 3, "the repair went on after the abort (%zu progress events)", log.Events.size());

  log.AbortFirst = false;
  log.Events.clear();
  repair->SetAbortExecute(0);
  repair->Modified();
  repair->Update();
  std::string last = "\x01";
  for (const auto& e : log.Events)
  {
    if (e.first != last)
    {
      std::printf(" [%s] %.3f", e.first.c_str(), e.second);
      last = e.first;
    }
  }
  std::printf("\n");
  MEDIAL_CHECK(repair->GetOutput()->GetNumberOfPolys() > 0, "no output after the abort was lifted");
  MEDIAL_CHECK(!log.Events.empty() && log.Events.back().second == 1.0, "the run does not end at 1");
  for (size_t i = 1; i < log.Events.size(); ++i)
  {
    MEDIAL_CHECK(log.Events[i].second >= log.Events[i - 1].second, "progress goes back at '%s'",
      log.Events[i].first.c_str());
  }
  for (const char* step : { "Checking the surface", "Filling holes", "Measuring the change" })
  {
    bool seen = false;
    for (const auto& e : log.Events)
    {
      seen = seen || e.first == step;
    }
    MEDIAL_CHECK(seen, "no progress under '%s'", step);
  }
  return EXIT_SUCCESS;
}
