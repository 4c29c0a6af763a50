// SPDX-License-Identifier: BSD-3-Clause
// An abort is honoured promptly: a run of the sampler that would take minutes (5 M
// samples on a generated shape) gets SetAbortExecute(1) from another thread one second
// into its sampling blocks; Update must return within 0.5 s of it, with an empty
// output. Prints the preparation time too (the abort is checked between blocks only).
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkPolyData.h"

#include <atomic>
#include <chrono>
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
  progress->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    auto* w = static_cast<Watch*>(client);
    const double fraction = *static_cast<double*>(data);
    w->Fraction = fraction;
    if (fraction > 0.0 && !w->Sampling) // the pipeline reports 0 before RequestData
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
  std::printf("preparation %.3f s, aborted at %.2f%% of the samples, Update returned %.3f s after the abort\n",
    preparation, 100.0 * fractionAtAbort, latency);
  MEDIAL_CHECK(fractionAtAbort < 0.5, "the run was too short to test an abort (%.2f done)", fractionAtAbort);
  MEDIAL_CHECK(latency <= 0.5, "abort took %.3f s", latency);
  MEDIAL_CHECK(sampler->GetOutput()->GetNumberOfPoints() == 0, "an aborted run left %lld points",
    static_cast<long long>(sampler->GetOutput()->GetNumberOfPoints()));
  return EXIT_SUCCESS;
}
