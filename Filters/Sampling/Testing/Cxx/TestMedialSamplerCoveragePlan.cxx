// SPDX-License-Identifier: BSD-3-Clause
// With a coverage stop the budget is a cap, not a plan. On the jack (default, inscribed
// balls), face-distance and closest-neighbor asked for 0.001 of the diagonal with a
// budget of 30,000 and of 60,000 samples must both reach it, with the same samples and
// the same output bit for bit (BitDifferences: balls, their arrays, the links): the
// seeds and rounds follow the run's own plan (2,500 seeds), not the budget. The faces' own samples cannot cover some of the jack's points (their balls
// are shrunk to stay inside and no longer touch them): before the seed layers, with 8
// tries a face, face-distance gave 37 faces up at 3,481 samples; only the layers added
// when faces are given up reach the stop. The reported gap is the brute-force one.
#include "MedialStrategyTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cmath>
#include <cstdlib>

using namespace medialtest;

namespace
{
vtkSmartPointer<vtkPolyData> Run(vtkPolyData* surface, int strategy, vtkIdType budget, double tolerance)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(budget);
  sampler->SetSamplingStrategy(strategy);
  sampler->SetCoverageTolerance(tolerance);
  sampler->SetNumberOfThreads(2);
  sampler->Update();
  return sampler->GetOutput();
}
}

int TestMedialSamplerCoveragePlan(int, char*[])
{
  const vtkSmartPointer<vtkPolyData> jack = TriangulatedShape(vtkMedialShapeSource::JACK);
  const double tolerance = 0.001;
  for (int strategy : { vtkMedialAxisSampler::FACE_DISTANCE, vtkMedialAxisSampler::CLOSEST_NEIGHBOR })
  {
    const char* name = vtkMedialAxisSampler::GetSamplingStrategyName(strategy);
    const vtkSmartPointer<vtkPolyData> small = Run(jack, strategy, 30000, tolerance);
    const vtkSmartPointer<vtkPolyData> large = Run(jack, strategy, 60000, tolerance);
    const double evaluated = FieldValue(small, "EvaluatedSamples");
    std::printf("%s: %g and %g samples evaluated, %g seeds, reached %g and %g, gap %.6g\n", name, evaluated,
      FieldValue(large, "EvaluatedSamples"), FieldValue(small, "SeedSamples"), FieldValue(small, "CoverageReached"),
      FieldValue(large, "CoverageReached"), FieldValue(small, "MaxCoverageGap"));
    MEDIAL_CHECK(FieldValue(small, "CoverageReached") == 1.0 && FieldValue(large, "CoverageReached") == 1.0,
      "%s: the coverage was not reached", name);
    MEDIAL_CHECK(evaluated < 30000 && evaluated == FieldValue(large, "EvaluatedSamples"),
      "%s: %g and %g samples", name, evaluated, FieldValue(large, "EvaluatedSamples"));
    MEDIAL_CHECK(FieldValue(small, "SeedSamples") == 2500, "%s: %g seeds, not a quarter of the first plan", name,
      FieldValue(small, "SeedSamples"));
    MEDIAL_CHECK(BitDifferences(small, large) == 0, "%s: the budget changed the balls (%lld values differ)", name,
      BitDifferences(small, large));
    if (strategy == vtkMedialAxisSampler::FACE_DISTANCE)
    {
      const double brute = MaxFaceGap(jack, small) / Diagonal(jack);
      MEDIAL_CHECK(brute <= tolerance && std::fabs(brute - FieldValue(small, "MaxCoverageGap")) <= 1e-12,
        "%s: reported gap %g, brute force %g", name, FieldValue(small, "MaxCoverageGap"), brute);
    }
  }
  return EXIT_SUCCESS;
}
