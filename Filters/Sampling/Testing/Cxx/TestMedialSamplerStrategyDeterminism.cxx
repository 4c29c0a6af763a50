// SPDX-License-Identifier: BSD-3-Clause
// The iterative strategies give bit-identical output (points, arrays, links) with 1
// and 2 threads, and with 2 threads run twice; and a different seed gives another output.
#include "MedialStrategyTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerStrategyDeterminism(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->Update();
  for (int strategy : { vtkMedialAxisSampler::CLOSEST_NEIGHBOR, vtkMedialAxisSampler::FACE_DISTANCE })
  {
    for (double coverage : { 0.0, 0.005 })
    {
      vtkSmartPointer<vtkPolyData> runs[4];
      const int threads[4] = { 1, 2, 2, 2 };
      for (int r = 0; r < 4; ++r)
      {
        vtkNew<vtkMedialAxisSampler> sampler;
        sampler->SetInputData(jack->GetOutput());
        sampler->SetNumberOfSamples(5000);
        sampler->SetSamplingStrategy(strategy);
        sampler->SetCoverageTolerance(coverage);
        sampler->SetNumberOfThreads(threads[r]);
        sampler->SetRandomSeed(r == 3 ? 7 : 1);
        sampler->Update();
        runs[r] = sampler->GetOutput();
      }
      const char* name = vtkMedialAxisSampler::GetSamplingStrategyName(strategy);
      const long long oneTwo = BitDifferences(runs[0], runs[1]);
      const long long twoTwo = BitDifferences(runs[1], runs[2]);
      std::printf("%s, coverage %g: %lld points, %lld lines; differences 1 vs 2 threads %lld, 2 vs 2 %lld\n", name,
        coverage, static_cast<long long>(runs[0]->GetNumberOfPoints()),
        static_cast<long long>(runs[0]->GetNumberOfLines()), oneTwo, twoTwo);
      MEDIAL_CHECK(runs[0]->GetNumberOfPoints() > 1000, "%s: only %lld points", name,
        static_cast<long long>(runs[0]->GetNumberOfPoints()));
      MEDIAL_CHECK(oneTwo == 0, "%s: 1 and 2 threads differ (%lld)", name, oneTwo);
      MEDIAL_CHECK(twoTwo == 0, "%s: two runs differ (%lld)", name, twoTwo);
      MEDIAL_CHECK(BitDifferences(runs[0], runs[3]) != 0, "%s: the seed changes nothing", name);
    }
  }
  return EXIT_SUCCESS;
}
