// SPDX-License-Identifier: BSD-3-Clause
// CoverageTolerance: on a box and on a capsule, the iterative strategies (and Random
// with a tolerance) must stop with CoverageReached = 1, and a brute-force check over
// every ball must agree: each face's vertices and centroid lie within the tolerance
// of the union of balls, and the reported MaxCoverageGap is the brute-force maximum.
// FaceDistance must also reach it with fewer samples than Random.
#include "MedialStrategyTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkTriangleFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerCoverage(int, char*[])
{
  for (int shape : { vtkMedialShapeSource::BOX, vtkMedialShapeSource::CAPSULE })
  {
    // The capsule's smooth side is covered much sooner than the box's edges and corners.
    const double tolerance = shape == vtkMedialShapeSource::BOX ? 0.01 : 0.0005;
    vtkNew<vtkMedialShapeSource> source;
    source->SetShape(shape);
    source->SetBoxLengths(3.0, 2.0, 1.0);
    source->SetLength(2.0);
    source->SetResolution(shape == vtkMedialShapeSource::BOX ? 4 : 6);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(source->GetOutputPort());
    triangles->Update();
    vtkPolyData* surface = triangles->GetOutput();
    const double diagonal = Diagonal(surface);
    const char* shapeName = shape == vtkMedialShapeSource::BOX ? "box" : "capsule";

    vtkIdType randomUsed = 0, faceDistanceUsed = 0;
    for (int strategy : { vtkMedialAxisSampler::RANDOM, vtkMedialAxisSampler::FACE_DISTANCE,
           vtkMedialAxisSampler::CLOSEST_NEIGHBOR })
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(surface);
      sampler->SetNumberOfSamples(40000);
      sampler->SetSamplingStrategy(strategy);
      sampler->SetCoverageTolerance(tolerance);
      sampler->SetSeedFraction(0.005); // 200 seeds: the rest is driven by coverage
      // Balls that reach the surface: a ball shrunk to be inscribed (the default) leaves
      // the polygon's edges uncovered by up to the facets' sagitta, here above the tolerance.
      sampler->SetMaximumProtrusion(1.0);
      EventLog log;
      log.Watch(sampler);
      sampler->Update();
      vtkPolyData* out = sampler->GetOutput();
      const char* name = vtkMedialAxisSampler::GetSamplingStrategyName(strategy);
      MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s %s: %s", shapeName, name, log.Text.c_str());
      const double brute = MaxFaceGap(surface, out) / diagonal;
      std::printf("%s, %s: %lld samples, %lld balls, reached %g, reported gap %.6g, brute-force gap %.6g\n",
        shapeName, name, static_cast<long long>(sampler->GetEvaluatedSamples()),
        static_cast<long long>(out->GetNumberOfPoints()), FieldValue(out, "CoverageReached"),
        FieldValue(out, "MaxCoverageGap"), brute);
      MEDIAL_CHECK(FieldValue(out, "CoverageReached") == 1.0, "%s %s: coverage not reached", shapeName, name);
      MEDIAL_CHECK(sampler->GetEvaluatedSamples() < 40000, "%s %s: the whole budget was used", shapeName, name);
      MEDIAL_CHECK(brute <= tolerance, "%s %s: a face point is %g of the diagonal from the balls", shapeName,
        name, brute);
      MEDIAL_CHECK(std::fabs(brute - FieldValue(out, "MaxCoverageGap")) <= 1e-12,
        "%s %s: reported gap %g, brute force %g", shapeName, name, FieldValue(out, "MaxCoverageGap"), brute);
      if (strategy == vtkMedialAxisSampler::RANDOM)
      {
        randomUsed = sampler->GetEvaluatedSamples();
      }
      else if (strategy == vtkMedialAxisSampler::FACE_DISTANCE)
      {
        faceDistanceUsed = sampler->GetEvaluatedSamples();
      }
    }
    MEDIAL_CHECK(faceDistanceUsed < randomUsed, "%s: face-distance used %lld samples, random %lld", shapeName,
      static_cast<long long>(faceDistanceUsed), static_cast<long long>(randomUsed));
  }
  return EXIT_SUCCESS;
}
