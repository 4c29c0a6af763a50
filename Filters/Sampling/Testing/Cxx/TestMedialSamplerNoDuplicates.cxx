// SPDX-License-Identifier: BSD-3-Clause
// FaceDistance re-queues a face whenever a new ball lowers its gap and leaves the
// old heap entry behind (lazy deletion). Stale entries must never give a second
// sample: no two output balls share a SurfacePoint, and none is repeated across
// discarded ones either (EvaluatedSamples - DiscardedSamples = output points).
// Run long on a small box (most faces are re-queued many times) and on the jack,
// with theta 0 and 45, for FaceDistance and ClosestNeighbor.
#include "MedialStrategyTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <array>
#include <cstdlib>
#include <set>

using namespace medialtest;

int TestMedialSamplerNoDuplicates(int, char*[])
{
  for (int shape : { vtkMedialShapeSource::BOX, vtkMedialShapeSource::JACK })
  {
    vtkNew<vtkMedialShapeSource> source;
    source->SetShape(shape);
    source->SetResolution(shape == vtkMedialShapeSource::BOX ? 3 : 8);
    for (int strategy : { vtkMedialAxisSampler::FACE_DISTANCE, vtkMedialAxisSampler::CLOSEST_NEIGHBOR })
    {
      for (double theta : { 0.0, 45.0 })
      {
        vtkNew<vtkMedialAxisSampler> sampler;
        sampler->SetInputConnection(source->GetOutputPort());
        sampler->SetNumberOfSamples(6000);
        sampler->SetSeedFraction(0.02);
        sampler->SetMinimumSeparationAngle(theta);
        sampler->SetSamplingStrategy(strategy);
        sampler->Update();
        vtkPolyData* out = sampler->GetOutput();
        std::set<std::array<double, 3>> unique;
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          unique.insert({ Value(out, "SurfacePoint", i, 0), Value(out, "SurfacePoint", i, 1),
            Value(out, "SurfacePoint", i, 2) });
        }
        const char* name = vtkMedialAxisSampler::GetSamplingStrategyName(strategy);
        std::printf("shape %d, %s, theta %g: %lld evaluated, %lld balls, %zu unique surface points\n", shape,
          name, theta, static_cast<long long>(sampler->GetEvaluatedSamples()),
          static_cast<long long>(out->GetNumberOfPoints()), unique.size());
        MEDIAL_CHECK(static_cast<vtkIdType>(unique.size()) == out->GetNumberOfPoints(),
          "%s: %lld balls but %zu distinct surface points", name,
          static_cast<long long>(out->GetNumberOfPoints()), unique.size());
        MEDIAL_CHECK(sampler->GetEvaluatedSamples() - sampler->GetDiscardedSamples() == out->GetNumberOfPoints(),
          "%s: evaluated %lld, discarded %lld, output %lld", name,
          static_cast<long long>(sampler->GetEvaluatedSamples()),
          static_cast<long long>(sampler->GetDiscardedSamples()), static_cast<long long>(out->GetNumberOfPoints()));
        if (strategy == vtkMedialAxisSampler::FACE_DISTANCE)
        {
          // Most samples come from re-queued faces, whose older entries went stale.
          MEDIAL_CHECK(sampler->GetEvaluatedSamples() >= 4 * sampler->GetSeedSamples(),
            "%s: too short a run to re-queue faces (%lld evaluated, %lld seeds)", name,
            static_cast<long long>(sampler->GetEvaluatedSamples()), static_cast<long long>(sampler->GetSeedSamples()));
        }
      }
    }
  }
  return EXIT_SUCCESS;
}
