// SPDX-License-Identifier: BSD-3-Clause
// A capsule along z: its medial axis is the axis segment. With the default theta
// every centre lies on the axis and every ball on the cylindrical part has the
// capsule's radius, up to the tessellation: a ball tangent to a facet is offset
// by the facet's tilt from the smooth normal. The offsets scale with the facet
// width w = 2 pi R / (4 Resolution) (measured with the default theta of 45
// degrees: 1.74 w off the axis, 1.21 w in radius, at Resolution 32 and 64 alike),
// so the bounds are 2 w and 1.5 w.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerCapsule(int, char*[])
{
  const double R = 0.5, length = 2.0;
  const int resolution = 32;
  vtkNew<vtkMedialShapeSource> capsule;
  capsule->SetShapeToCapsule();
  capsule->SetRadius(R);
  capsule->SetLength(length);
  capsule->SetResolution(resolution);
  for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputConnection(capsule->GetOutputPort());
    sampler->SetNumberOfSamples(3000);
    sampler->SetMethod(method);
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    MEDIAL_CHECK(out->GetNumberOfPoints() == 3000, "kept %lld", static_cast<long long>(out->GetNumberOfPoints()));
    const double facet = 2 * 3.14159265358979323846 * R / (4 * resolution);
    double worstAxis = 0.0, worstRadius = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double c[3];
      out->GetPoint(i, c);
      worstAxis = std::max(worstAxis, std::hypot(c[0], c[1]));
      if (std::fabs(Value(out, "SurfacePoint", i, 2)) < 0.5 * length)
      {
        worstRadius = std::max(worstRadius, std::fabs(Value(out, "Radius", i) - R));
      }
    }
    std::printf("%s: max distance to the axis %.4g, max |r - R| on the body %.3g (facet width %.4g)\n",
      vtkMedialAxisSampler::GetMethodName(method), worstAxis, worstRadius, facet);
    MEDIAL_CHECK(worstAxis <= 2 * facet, "centre %.4g off the axis", worstAxis);
    MEDIAL_CHECK(worstRadius <= 1.5 * facet, "body radius off by %.4g", worstRadius);
  }
  return EXIT_SUCCESS;
}
