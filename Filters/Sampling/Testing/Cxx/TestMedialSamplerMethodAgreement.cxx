// SPDX-License-Identifier: BSD-3-Clause
// Accuracy contract: on the same seed every method agrees with BISECTION within
// 1e-5 of the diagonal on at least 99.5% of the samples, for theta = 0 and for the
// default theta. Checked on the demo shape and, when present, on the horse.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
int CheckAgreement(vtkPolyData* surface, const char* label, double diagonal)
{
  vtkNew<vtkMedialAxisSampler> defaults;
  for (double theta : { 0.0, defaults->GetMinimumSeparationAngle() })
  {
    vtkNew<vtkMedialAxisSampler> reference;
    reference->SetInputData(surface);
    reference->SetNumberOfSamples(4000);
    reference->SetRandomSeed(11);
    reference->SetMinimumSeparationAngle(theta);
    reference->SetMethodToBisection();
    reference->Update();
    for (int method = vtkMedialAxisSampler::BISECTION + 1; method <= vtkMedialAxisSampler::ONE_PASS; ++method)
    {
      vtkNew<vtkMedialAxisSampler> other;
      other->SetInputData(surface);
      other->SetNumberOfSamples(4000);
      other->SetRandomSeed(11);
      other->SetMinimumSeparationAngle(theta);
      other->SetMethod(method);
      other->Update();
      vtkPolyData* a = reference->GetOutput();
      vtkPolyData* b = other->GetOutput();
      MEDIAL_CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints(), "%s: point counts differ", label);
      vtkIdType agree = 0;
      for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
      {
        agree += std::fabs(Value(a, "Radius", i) - Value(b, "Radius", i)) <= 1e-5 * diagonal ? 1 : 0;
      }
      const double fraction = static_cast<double>(agree) / a->GetNumberOfPoints();
      std::printf("%s, theta %.0f: %s agrees with bisection on %.2f%% of %lld samples (%lld capped)\n",
        label, theta, vtkMedialAxisSampler::GetMethodName(method), 100 * fraction,
        static_cast<long long>(a->GetNumberOfPoints()), static_cast<long long>(other->GetCappedSamples()));
      MEDIAL_CHECK(fraction >= 0.995, "%s theta %g: only %.2f%% agree", label, theta, 100 * fraction);
    }
  }
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerMethodAgreement(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->Update();
  if (CheckAgreement(jack->GetOutput(), "demo shape", Diagonal(jack->GetOutput())) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkPolyData> horse = ReadSharedPLY("horse.ply");
  return horse ? CheckAgreement(horse, "horse", Diagonal(horse)) : EXIT_SUCCESS;
}
