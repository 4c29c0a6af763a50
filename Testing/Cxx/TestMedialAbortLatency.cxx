// SPDX-License-Identifier: BSD-3-Clause
// An abort is honoured promptly, during sampling and during preparation:
//  1. a run of the sampler that would take minutes (5 M samples on a generated shape)
//     gets SetAbortExecute(1) from another thread one second into its sampling blocks;
//  2. a run on a 1.3M-triangle sphere gets it a quarter into the preparation (the
//     mesh and the BVHs; timed first with a 1-sample run), while they are being built.
// Each time Update must return promptly, with an empty output. "Promptly" is 0.5 s on
// a quiet machine; on a loaded one every stage slows down alike, so the bound is also
// relative to the same run's own preparation time: 25% of it while sampling (without
// the abort checks the run would go on for minutes) and 40% of it during preparation
// (without the checks between stages it would be the remaining 75%).
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>

namespace
{
using Clock = std::chrono::steady_clock;

struct Watch
{
  std::atomic<bool> Sampling{ false };
  std::atomic<double> Fraction{ 0.0 };
  Clock::time_point FirstBlock;
};
}

namespace
{
// Part 2: an abort during preparation.
int AbortDuringPreparation()
{
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(8);
  sphere->Update();
  // The preparation time of this machine at its current load.
  vtkNew<vtkMedialAxisSampler> probe;
  probe->SetInputData(sphere->GetOutput());
  probe->SetNumberOfSamples(1);
  probe->SetNumberOfThreads(2);
  const Clock::time_point probeStart = Clock::now();
  probe->Update();
  const double preparation = std::chrono::duration<double>(Clock::now() - probeStart).count();

  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(sphere->GetOutput());
  sampler->SetNumberOfSamples(5000000);
  sampler->SetNumberOfThreads(2);
  std::atomic<bool> sampling{ false };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&sampling);
  progress->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    if (*static_cast<double*>(data) > 0.0)
    {
      *static_cast<std::atomic<bool>*>(client) = true;
    }
  });
  sampler->AddObserver(vtkCommand::ProgressEvent, progress);
  Clock::time_point abortAt;
  bool duringPreparation = false;
  std::thread aborter([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(0.25 * preparation));
    duringPreparation = !sampling;
    abortAt = Clock::now();
    sampler->SetAbortExecute(1);
  });
  sampler->Update();
  const Clock::time_point returned = Clock::now();
  aborter.join();
  const double latency = std::chrono::duration<double>(returned - abortAt).count();
  std::printf("%lld triangles, preparation %.3f s: aborted %s, Update returned %.3f s after the abort\n",
    static_cast<long long>(sphere->GetOutput()->GetNumberOfCells()), preparation,
    duringPreparation ? "during preparation" : "after preparation (fast machine)", latency);
  MEDIAL_CHECK(latency <= std::max(0.5, 0.4 * preparation),
    "abort during preparation took %.3f s of a %.3f s preparation", latency, preparation);
  MEDIAL_CHECK(sampler->GetOutput()->GetNumberOfPoints() == 0, "an aborted run left %lld points",
    static_cast<long long>(sampler->GetOutput()->GetNumberOfPoints()));
  return EXIT_SUCCESS;
}
}

int main()
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(16);
  jack->Update();
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(5000000);
  sampler->SetNumberOfThreads(2);

  Watch watch;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&watch);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    auto* w = static_cast<Watch*>(client);
    const double fraction = *static_cast<double*>(data);
    const char* stage = static_cast<vtkAlgorithm*>(caller)->GetProgressText();
    w->Fraction = fraction;
    // The sampling blocks begin with the stage "Sampling" (preparation reports its own stages).
    if (stage && std::string(stage) == "Sampling" && !w->Sampling)
    {
      w->FirstBlock = Clock::now();
      w->Sampling = true;
    }
  });
  sampler->AddObserver(vtkCommand::ProgressEvent, progress);

  Clock::time_point abortAt;
  double fractionAtAbort = 0.0;
  std::thread aborter([&] {
    while (!watch.Sampling)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
    fractionAtAbort = watch.Fraction;
    abortAt = Clock::now();
    sampler->SetAbortExecute(1);
  });
  const Clock::time_point start = Clock::now();
  sampler->Update();
  const Clock::time_point returned = Clock::now();
  aborter.join();

  const double preparation = std::chrono::duration<double>(watch.FirstBlock - start).count();
  const double latency = std::chrono::duration<double>(returned - abortAt).count();
  std::printf("preparation %.3f s, aborted at %.2f%% of its progress, Update returned %.3f s after the abort\n",
    preparation, 100.0 * fractionAtAbort, latency);
  MEDIAL_CHECK(fractionAtAbort < 0.5, "the run was too short to test an abort (%.2f done)", fractionAtAbort);
  MEDIAL_CHECK(latency <= std::max(0.5, 0.25 * preparation), "abort took %.3f s (preparation %.3f s)",
    latency, preparation);
  MEDIAL_CHECK(sampler->GetOutput()->GetNumberOfPoints() == 0, "an aborted run left %lld points",
    static_cast<long long>(sampler->GetOutput()->GetNumberOfPoints()));
  return AbortDuringPreparation();
}
