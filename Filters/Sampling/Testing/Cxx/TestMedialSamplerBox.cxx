// SPDX-License-Identifier: BSD-3-Clause
// A rotated box with unequal sides: every maximal ball touches its own face and
// one other, so the two smallest distances from the centre to the six face planes
// are equal, and equal to the radius. Checked for both methods, theta 0 and default.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerBox(int, char*[])
{
  const double L[3] = { 3.0, 2.0, 1.0 };
  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->SetBoxLengths(L[0], L[1], L[2]);
  box->SetResolution(4);
  vtkNew<vtkTransform> rotation;
  rotation->RotateWXYZ(37.0, 1.0, 2.0, 3.0);
  vtkNew<vtkTransformPolyDataFilter> rotate;
  rotate->SetInputConnection(box->GetOutputPort());
  rotate->SetTransform(rotation);
  rotate->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  rotate->Update();
  const double diagonal = Diagonal(rotate->GetOutput());

  for (double theta : { 0.0, 45.0, 60.0 })
  {
    for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputConnection(rotate->GetOutputPort());
      sampler->SetNumberOfSamples(3000);
      sampler->SetMinimumSeparationAngle(theta);
      sampler->SetMethod(method);
      sampler->Update();
      vtkPolyData* out = sampler->GetOutput();
      MEDIAL_CHECK(out->GetNumberOfPoints() == 3000, "kept %lld", static_cast<long long>(out->GetNumberOfPoints()));
      double worstGap = 0.0, worstRadius = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double c[3], local[3];
        out->GetPoint(i, c);
        rotation->GetInverse()->TransformPoint(c, local);
        std::vector<double> d;
        for (int k = 0; k < 3; ++k)
        {
          d.push_back(0.5 * L[k] - local[k]);
          d.push_back(0.5 * L[k] + local[k]);
        }
        std::sort(d.begin(), d.end());
        worstGap = std::max(worstGap, (d[1] - d[0]) / diagonal);
        worstRadius = std::max(worstRadius, std::fabs(Value(out, "Radius", i) - d[0]) / diagonal);
      }
      std::printf("theta %.0f, %s: max gap of the two nearest planes %.3g, max |r - d| %.3g (of the diagonal)\n",
        theta, vtkMedialAxisSampler::GetMethodName(method), worstGap, worstRadius);
      MEDIAL_CHECK(worstGap <= 1e-4, "two nearest planes differ by %g of the diagonal", worstGap);
      MEDIAL_CHECK(worstRadius <= 1e-4, "radius differs from the plane distance by %g", worstRadius);
    }
  }
  return EXIT_SUCCESS;
}
