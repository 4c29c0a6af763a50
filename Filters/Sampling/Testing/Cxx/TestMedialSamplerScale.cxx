// SPDX-License-Identifier: BSD-3-Clause
// Results scale with the input: the demo shape at 1e12 and at 1e-12 gives the same
// balls as at unit size, scaled, for both methods (relative difference 1e-6 of the
// diagonal at most, the bisection tolerance). Also a huge sample count is refused up
// front with an error instead of allocating until the machine dies.
#include "MedialTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerScale(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(12);
  jack->Update();
  const double diagonal = Diagonal(jack->GetOutput());
  for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    vtkNew<vtkMedialAxisSampler> unit;
    unit->SetInputConnection(jack->GetOutputPort());
    unit->SetNumberOfSamples(2000);
    unit->SetMethod(method);
    unit->Update();
    for (double scale : { 1e12, 1e-12 })
    {
      vtkNew<vtkTransform> transform;
      transform->Translate(3 * scale, -2 * scale, scale); // off the origin too
      transform->Scale(scale, scale, scale);
      vtkNew<vtkTransformPolyDataFilter> scaled;
      scaled->SetInputConnection(jack->GetOutputPort());
      scaled->SetTransform(transform);
      scaled->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputConnection(scaled->GetOutputPort());
      sampler->SetNumberOfSamples(2000);
      sampler->SetMethod(method);
      sampler->Update();
      vtkPolyData* a = unit->GetOutput();
      vtkPolyData* b = sampler->GetOutput();
      MEDIAL_CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints(), "scale %g: %lld vs %lld points", scale,
        static_cast<long long>(a->GetNumberOfPoints()), static_cast<long long>(b->GetNumberOfPoints()));
      double worst = 0.0;
      for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
      {
        worst = std::max(worst, std::fabs(Value(b, "Radius", i) / scale - Value(a, "Radius", i)) / diagonal);
      }
      std::printf("%s, scale %g: max relative radius difference %.3g of the diagonal\n",
        vtkMedialAxisSampler::GetMethodName(method), scale, worst);
      MEDIAL_CHECK(worst <= 1e-6, "scale %g: radii differ by %g of the diagonal", scale, worst);
    }
  }

  EventLog log;
  vtkNew<vtkMedialAxisSampler> huge;
  log.Watch(huge);
  huge->SetInputConnection(jack->GetOutputPort());
  huge->SetNumberOfSamples(static_cast<vtkIdType>(1) << 40);
  const int ok = huge->GetExecutive()->Update();
  const bool refused = !ok && log.Text.find("more than this machine's memory allows") != std::string::npos;
  std::printf("2^40 samples refused up front: %s\n", refused ? "yes" : "no");
  MEDIAL_CHECK(refused, "a huge sample count was not refused");
  return EXIT_SUCCESS;
}
