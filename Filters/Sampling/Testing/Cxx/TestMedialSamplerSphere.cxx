// SPDX-License-Identifier: BSD-3-Clause
// A finely tessellated sphere: with the default theta every ball is the sphere
// itself (radius and centre within 2% of R); with theta = 0 the exact polyhedral
// balls are mostly bounded by P's neighbouring facets (median about 0.29 R).
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerSphere(int, char*[])
{
  const double R = 2.5;
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetRadius(R);
  sphere->SetResolution(7); // 327680 triangles
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(sphere->GetOutputPort());
  sampler->SetNumberOfSamples(400);
  sampler->Update();
  vtkPolyData* out = sampler->GetOutput();
  MEDIAL_CHECK(out->GetNumberOfPoints() == 400, "kept %lld samples", static_cast<long long>(out->GetNumberOfPoints()));
  double worstRadius = 0.0, worstCentre = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[3];
    out->GetPoint(i, c);
    worstRadius = std::max(worstRadius, std::fabs(Value(out, "Radius", i) - R) / R);
    worstCentre = std::max(worstCentre, std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / R);
  }
  std::printf("default theta %.1f: max |r - R|/R = %.4f, max |centre|/R = %.4f\n",
    sampler->GetMinimumSeparationAngle(), worstRadius, worstCentre);
  MEDIAL_CHECK(worstRadius <= 0.02, "radius off by %.4f R", worstRadius);
  MEDIAL_CHECK(worstCentre <= 0.02, "centre off by %.4f R", worstCentre);

  sampler->SetMinimumSeparationAngle(0.0);
  sampler->SetNumberOfSamples(2000);
  sampler->Update();
  std::vector<double> radii;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    radii.push_back(Value(out, "Radius", i) / R);
  }
  const double median = Median(radii);
  std::printf("theta 0: median r/R = %.3f (theory for a random point and its nearest edge: 0.293)\n", median);
  MEDIAL_CHECK(median > 0.2 && median < 0.4, "theta 0 median r/R = %.3f", median);
  return EXIT_SUCCESS;
}
