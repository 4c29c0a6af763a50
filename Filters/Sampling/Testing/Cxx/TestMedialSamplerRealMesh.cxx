// SPDX-License-Identifier: BSD-3-Clause
// Generic checks on a real closed mesh with theta = 0 (horse.ply, stored with
// inward normals), using VTK's own cell locator as the independent distance:
//  - inscribed: distance from the centre to the surface equals Radius within the tolerance;
//  - maximal: the ball of radius rho = Radius (1 + 1e-3) tangent at P (centre
//    P + rho n) is not empty. Where 1e-3 Radius is below the bisection bracket,
//    rho = Radius + 4 tolerance is used instead.
#include "MedialTestUtilities.h"

#include "vtkGenericCell.h"
#include "vtkMedialAxisSampler.h"
#include "vtkPLYReader.h"
#include "vtkStaticCellLocator.h"
#include "vtkTriangleFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerRealMesh(int, char*[])
{
  const std::string horse = SharedMesh("horse.ply");
  if (horse.empty())
  {
    std::printf("shared meshes absent: skipped\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(horse.c_str());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->Update();
  vtkPolyData* surface = triangles->GetOutput();
  const double diagonal = Diagonal(surface);
  const double tolerance = 1e-6;

  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;

  for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(surface);
    sampler->SetNumberOfSamples(2000);
    sampler->SetMinimumSeparationAngle(0.0);
    sampler->SetTolerance(tolerance);
    sampler->SetMethod(method);
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    const char* m = vtkMedialAxisSampler::GetMethodName(method);
    MEDIAL_CHECK(out->GetNumberOfPoints() == 2000, "%s: kept %lld of 2000", m,
      static_cast<long long>(out->GetNumberOfPoints()));

    double worstInscribed = 0.0, smallestIntrusion = HUGE_VAL;
    int notMaximal = 0;
    std::vector<double> radii;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double c[3], closest[3], d2;
      vtkIdType cellId;
      int subId;
      out->GetPoint(i, c);
      const double r = Value(out, "Radius", i);
      radii.push_back(r / diagonal);
      locator->FindClosestPoint(c, closest, cell, cellId, subId, d2);
      worstInscribed = std::max(worstInscribed, std::fabs(std::sqrt(d2) - r) / diagonal);

      const double p[3] = { Value(out, "SurfacePoint", i, 0), Value(out, "SurfacePoint", i, 1),
        Value(out, "SurfacePoint", i, 2) };
      double n[3];
      for (int k = 0; k < 3; ++k)
      {
        n[k] = (c[k] - p[k]) / r;
      }
      const double rho = std::max(r * (1 + 1e-3), r + 4 * tolerance * diagonal);
      double bigger[3];
      for (int k = 0; k < 3; ++k)
      {
        bigger[k] = p[k] + rho * n[k];
      }
      locator->FindClosestPoint(bigger, closest, cell, cellId, subId, d2);
      const double intrusion = (rho - std::sqrt(d2)) / diagonal;
      smallestIntrusion = std::min(smallestIntrusion, intrusion);
      notMaximal += intrusion <= 1e-12 ? 1 : 0;
    }
    std::printf("horse, %s, theta 0: max |dist - r| = %.3g of the diagonal; grown balls not "
                "empty: %d of %lld (smallest intrusion %.3g); median r = %.4g of the diagonal; "
                "mean iterations %.2f\n",
      m, worstInscribed, static_cast<int>(out->GetNumberOfPoints()) - notMaximal,
      static_cast<long long>(out->GetNumberOfPoints()), smallestIntrusion, Median(radii),
      sampler->GetMeanIterations());
    MEDIAL_CHECK(worstInscribed <= tolerance, "%s: a ball is not inscribed (%g)", m, worstInscribed);
    MEDIAL_CHECK(notMaximal == 0, "%s: %d balls are not maximal", m, notMaximal);
  }
  return EXIT_SUCCESS;
}
