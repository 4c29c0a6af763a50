// SPDX-License-Identifier: BSD-3-Clause
// The coverage bookkeeping of the iterative strategies without a coverage stop (the
// budget alone ends the run), where the bookkeeping's search bounds are refreshed
// only now and then and closest-neighbor ends with many rounds of a few samples:
// the reported MaxCoverageGap must be the brute-force maximum over every face's
// vertices and centroid, with 1 and 2 threads alike. A search that skips a row, a
// cell or a point it should not (a stale or too tight bound) reports a larger gap.
#include "MedialStrategyTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerCoverageGap(int, char*[])
{
  for (int shape : { vtkMedialShapeSource::JACK, vtkMedialShapeSource::CAPSULE })
  {
    const vtkSmartPointer<vtkPolyData> triangulated = TriangulatedShape(shape);
    vtkPolyData* surface = triangulated;
    const double diagonal = Diagonal(surface);
    const char* shapeName = shape == vtkMedialShapeSource::JACK ? "jack" : "capsule";
    for (int strategy : { vtkMedialAxisSampler::CLOSEST_NEIGHBOR, vtkMedialAxisSampler::FACE_DISTANCE })
    {
      const char* name = vtkMedialAxisSampler::GetSamplingStrategyName(strategy);
      double reported[2] = { 0.0, 0.0 };
      for (int threads : { 1, 2 })
      {
        vtkNew<vtkMedialAxisSampler> sampler;
        sampler->SetInputData(surface);
        sampler->SetNumberOfSamples(4000);
        sampler->SetSamplingStrategy(strategy);
        sampler->SetNumberOfThreads(threads);
        // Balls that are not shrunk: each one's surface point lies on its sphere, so
        // the gaps are those of the balls alone, as the brute force measures them.
        sampler->SetMaximumProtrusion(1.0);
        sampler->Update();
        vtkPolyData* out = sampler->GetOutput();
        const double brute = MaxFaceGap(surface, out) / diagonal;
        reported[threads - 1] = FieldValue(out, "MaxCoverageGap");
        std::printf("%s, %s, %d threads: %lld samples, %lld balls, reported gap %.9g, brute-force gap %.9g\n",
          shapeName, name, threads, static_cast<long long>(sampler->GetEvaluatedSamples()),
          static_cast<long long>(out->GetNumberOfPoints()), reported[threads - 1], brute);
        MEDIAL_CHECK(out->GetNumberOfPoints() > 500, "%s %s: only %lld balls", shapeName, name,
          static_cast<long long>(out->GetNumberOfPoints()));
        MEDIAL_CHECK(std::fabs(brute - reported[threads - 1]) <= 1e-12,
          "%s %s, %d threads: reported gap %.12g, brute force %.12g", shapeName, name, threads,
          reported[threads - 1], brute);
      }
      MEDIAL_CHECK(reported[0] == reported[1], "%s %s: 1 and 2 threads report %.17g and %.17g", shapeName, name,
        reported[0], reported[1]);
    }
  }
  return EXIT_SUCCESS;
}
