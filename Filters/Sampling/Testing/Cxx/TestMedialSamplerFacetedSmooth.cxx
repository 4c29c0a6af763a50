// SPDX-License-Identifier: BSD-3-Clause
// Default balls on faceted smooth surfaces (issue 39): with the default theta and
// protrusion the sampler's balls follow the smooth surface's normals, so that a facet's
// tilt no longer pushes them off the axis and the protrusion rule no longer shrinks them.
// Families with known answers, 1000 samples each:
//  - geodesic spheres of radius 1 with 1280, 5120 and 20480 triangles, as generated and
//    turned: every ball within 2%, 1% and 0.5% of R and centred within as much of the
//    centre, median radius at least 0.99 R (the facets' normals gave 26%, 12% and 6% at
//    worst, and 0.945 R on median at 5120 triangles);
//  - tori (1, 0.3) of 2432 and 9728 triangles: every ball's radius within 6.5% and 1.5%
//    of the tube's, its centre within as much of the ring (tube radius units); the
//    facets' normals gave 50% and 23% at worst.
// The balls still cross the surface by at most MaximumProtrusion (checked by
// TestMedialSamplerOnePassBruteForce); theta = 0 is unchanged (TestMedialSamplerSphere).
#include "MedialTestUtilities.h"
#include "MedialShapeTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution, double turn)
{
  return Turned(MakeShape(shape, resolution, [](vtkMedialShapeSource* s) {
    s->SetRadius(1.0);
    s->SetTubeRadius(0.3);
  }), turn);
}

vtkPolyData* Balls(vtkMedialAxisSampler* sampler, vtkPolyData* surface)
{
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(1000);
  sampler->SetRandomSeed(3);
  sampler->SetNumberOfThreads(2);
  sampler->Update();
  return sampler->GetOutput();
}
}

int TestMedialSamplerFacetedSmooth(int, char*[])
{
  const double bounds[3] = { 0.02, 0.01, 0.005 };
  for (int level = 3; level <= 5; ++level)
  {
    for (double turn : { 0.0, 37.0 })
    {
      vtkSmartPointer<vtkPolyData> sphere = Shape(vtkMedialShapeSource::SPHERE, level, turn);
      vtkNew<vtkMedialAxisSampler> sampler;
      vtkPolyData* out = Balls(sampler, sphere);
      std::vector<double> radii;
      double worstRadius = 0.0, worstCentre = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double c[3];
        out->GetPoint(i, c);
        radii.push_back(Value(out, "Radius", i));
        worstRadius = std::max(worstRadius, std::fabs(radii.back() - 1.0));
        worstCentre = std::max(worstCentre, std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
      }
      const double median = Median(radii);
      const long long triangles = sphere->GetNumberOfCells();
      std::printf("sphere R = 1, %lld triangles, turned %g: median r %.5f, max |r - R| %.5f, max |centre| %.5f\n",
        triangles, turn, median, worstRadius, worstCentre);
      MEDIAL_CHECK(out->GetNumberOfPoints() == 1000, "sphere %lld: %lld balls", triangles,
        static_cast<long long>(out->GetNumberOfPoints()));
      MEDIAL_CHECK(median >= 0.99, "sphere %lld: median radius %.5f below 0.99 R", triangles, median);
      MEDIAL_CHECK(worstRadius <= bounds[level - 3], "sphere %lld: a radius off by %.5f R", triangles, worstRadius);
      MEDIAL_CHECK(worstCentre <= bounds[level - 3], "sphere %lld: a centre off by %.5f R", triangles, worstCentre);
    }
  }
  const double torusBounds[2] = { 0.065, 0.015 };
  int k = 0;
  for (int resolution : { 16, 32 })
  {
    vtkSmartPointer<vtkPolyData> torus = Shape(vtkMedialShapeSource::TORUS, resolution, 0.0);
    vtkNew<vtkMedialAxisSampler> sampler;
    vtkPolyData* out = Balls(sampler, torus);
    double worstRadius = 0.0, worstCentre = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double c[3];
      out->GetPoint(i, c);
      worstRadius = std::max(worstRadius, std::fabs(Value(out, "Radius", i) - 0.3) / 0.3);
      worstCentre = std::max(worstCentre, std::hypot(std::hypot(c[0], c[1]) - 1.0, c[2]) / 0.3);
    }
    const long long triangles = torus->GetNumberOfCells();
    std::printf("torus (1, 0.3), %lld triangles: max |r - a| / a %.5f, max centre off the ring / a %.5f\n", triangles,
      worstRadius, worstCentre);
    MEDIAL_CHECK(worstRadius <= torusBounds[k], "torus %lld: a radius off by %.5f a", triangles, worstRadius);
    MEDIAL_CHECK(worstCentre <= torusBounds[k], "torus %lld: a centre off by %.5f a", triangles, worstCentre);
    ++k;
  }
  return EXIT_SUCCESS;
}
