// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialScaleAxisFilter:
//  - closed forms: a ball of radius 0.5 at distance 2 from a ball of radius 1 is covered
//    at scale 4 exactly (Significance 0.75; kept at 3.9, removed at 4.1); the largest
//    ball is never covered (Significance 1); a ball inside another goes at scale 1;
//  - on 2,000 random balls, the kept set and every Significance equal a brute-force
//    search over all pairs, bit for bit, on 1 and 2 threads;
//  - a noisy sphere (radius 1, Gaussian noise of 0.2% of the diagonal per coordinate;
//    at 0.1% the balls along the smooth surface's normals no longer grow noise branches):
//    the sampler's balls reach 0.5 or more from the centre (the noise's branches), the
//    default scale keeps only balls within 0.1 of it; the clean sphere's within 0.01;
//  - topology: the medial mesh of the balls kept at the default scale has the solid's
//    Euler characteristic and one component (rings of genus 1 to 3, the jack);
//  - bad input: no radius array, a negative or NaN radius: an error, no output.
#include "MedialMeshTestUtilities.h"
#include "MedialTestSupport.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialScaleAxisFilter.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> Balls(const std::vector<double>& centres, const std::vector<double>& radii)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (size_t i = 0; i < radii.size(); ++i)
  {
    points->InsertNextPoint(&centres[3 * i]);
    radius->InsertNextValue(radii[i]);
  }
  auto balls = vtkSmartPointer<vtkPolyData>::New();
  balls->SetPoints(points);
  balls->GetPointData()->AddArray(radius);
  return balls;
}

vtkSmartPointer<vtkPolyData> ScaleAxis(
  vtkPolyData* balls, double scale, int threads = 2, bool* ok = nullptr, medialtest::EventLog* log = nullptr)
{
  vtkNew<vtkMedialScaleAxisFilter> filter;
  if (log)
  {
    log->Watch(filter);
  }
  filter->SetInputData(balls);
  if (scale > 0.0)
  {
    filter->SetScaleFactor(scale);
  }
  filter->SetNumberOfThreads(threads);
  const int status = filter->GetExecutive()->Update();
  if (ok)
  {
    *ok = status != 0;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

double SignificanceOf(vtkPolyData* out, vtkIdType k)
{
  return out->GetPointData()->GetArray("Significance")->GetTuple1(k);
}

int ClosedForms()
{
  // Ball 0: radius 1 at the origin; ball 1: radius 0.5 at x = 2; ball 2 inside ball 0.
  const std::vector<double> centres = { 0, 0, 0, 2, 0, 0, 0.2, 0, 0 };
  const std::vector<double> radii = { 1.0, 0.5, 0.5 };
  vtkSmartPointer<vtkPolyData> balls = Balls(centres, radii);
  vtkSmartPointer<vtkPolyData> at1 = ScaleAxis(balls, 1.0);
  MEDIAL_CHECK(at1->GetNumberOfPoints() == 2, "scale 1: %lld balls kept, expected 2 (ball 2 lies in ball 0)",
    static_cast<long long>(at1->GetNumberOfPoints()));
  MEDIAL_CHECK(SignificanceOf(at1, 0) == 1.0, "the largest ball: Significance %g, expected 1", SignificanceOf(at1, 0));
  MEDIAL_CHECK(std::fabs(SignificanceOf(at1, 1) - 0.75) < 1e-15, "ball 1: Significance %.17g, expected 0.75",
    SignificanceOf(at1, 1));
  MEDIAL_CHECK(ScaleAxis(balls, 3.9)->GetNumberOfPoints() == 2, "scale 3.9 removed ball 1 (covered at 4)");
  MEDIAL_CHECK(ScaleAxis(balls, 4.1)->GetNumberOfPoints() == 1, "scale 4.1 kept ball 1 (covered at 4)");
  MEDIAL_CHECK(at1->GetVerts()->GetNumberOfCells() == 2, "one vertex cell per kept ball");
  return 0;
}

int AgainstBruteForce()
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 2000;
  std::vector<double> centres(3 * n), radii(n);
  for (int i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      centres[3 * i + k] = unit(random);
    }
    radii[i] = 0.2 * std::pow(unit(random), 3.0); // many small balls, a few large ones
  }
  vtkSmartPointer<vtkPolyData> balls = Balls(centres, radii);
  const double scale = 1.5;
  std::vector<double> expected; // Significance of the kept balls, in order
  for (int i = 0; i < n; ++i)
  {
    double best = HUGE_VAL;
    for (int j = 0; j < n; ++j)
    {
      const double gap = radii[j] - radii[i];
      if (gap > 0.0)
      {
        best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(&centres[3 * i], &centres[3 * j])) / gap);
      }
    }
    best = best <= vtkMedialScaleAxisFilter::MaximumScale ? best : HUGE_VAL;
    if (best > scale)
    {
      expected.push_back(std::isfinite(best) ? std::max(0.0, 1.0 - 1.0 / best) : 1.0);
    }
  }
  for (int threads : { 1, 2 })
  {
    vtkSmartPointer<vtkPolyData> out = ScaleAxis(balls, scale, threads);
    MEDIAL_CHECK(out->GetNumberOfPoints() == static_cast<vtkIdType>(expected.size()),
      "%d threads: %lld balls kept, brute force %zu", threads, static_cast<long long>(out->GetNumberOfPoints()),
      expected.size());
    for (vtkIdType k = 0; k < out->GetNumberOfPoints(); ++k)
    {
      MEDIAL_CHECK(SignificanceOf(out, k) == expected[k], "%d threads: kept ball %lld: Significance %.17g, brute force %.17g",
        threads, static_cast<long long>(k), SignificanceOf(out, k), expected[k]);
    }
  }
  std::printf("random balls: %zu of %d kept at scale %g, equal to the brute force on 1 and 2 threads\n",
    expected.size(), n, scale);
  return 0;
}

// The largest distance from a kept centre to the sphere's centre (the origin).
double FarthestCentre(vtkPolyData* balls)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    double c[3];
    balls->GetPoint(i, c);
    worst = std::max(worst, std::sqrt(vtkMath::Dot(c, c)));
  }
  return worst;
}

int NoisySphere()
{
  for (double noise : { 0.0, 0.002 })
  {
    vtkNew<vtkMedialShapeSource> source;
    source->SetShapeToSphere(); // radius 1 at the origin
    source->SetResolution(4);
    source->Update();
    vtkSmartPointer<vtkPolyData> sphere =
      noise > 0.0 ? medialtest::WithGaussianNoise(source->GetOutput(), noise, 3)
                  : vtkSmartPointer<vtkPolyData>(source->GetOutput());
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(sphere);
    sampler->SetNumberOfSamples(3000);
    sampler->Update();
    vtkSmartPointer<vtkPolyData> kept = ScaleAxis(sampler->GetOutput(), 0.0); // the default scale
    const double before = FarthestCentre(sampler->GetOutput()), after = FarthestCentre(kept);
    std::printf("sphere, noise %g of the diagonal: centres reach %.4f from the centre, %.4f after (%lld of %lld "
                "balls kept)\n",
      noise, before, after, static_cast<long long>(kept->GetNumberOfPoints()),
      static_cast<long long>(sampler->GetOutput()->GetNumberOfPoints()));
    MEDIAL_CHECK(kept->GetNumberOfPoints() > 0, "noise %g: no ball kept", noise);
    if (noise > 0.0)
    {
      MEDIAL_CHECK(before >= 0.5, "noise %g: the unpruned balls reach only %g from the centre: the test has no noise "
                                  "branches to remove", noise, before);
    }
    const double bound = noise > 0.0 ? 0.1 : 0.01;
    MEDIAL_CHECK(after <= bound, "noise %g: a kept ball's centre is %g from the sphere's centre (bound %g)", noise,
      after, bound);
  }
  return 0;
}

int Topology()
{
  struct Solid
  {
    int Shape, Genus, Euler;
  };
  for (const Solid& solid : { Solid{ vtkMedialShapeSource::RINGS, 1, 0 }, Solid{ vtkMedialShapeSource::RINGS, 2, -1 },
         Solid{ vtkMedialShapeSource::RINGS, 3, -2 }, Solid{ vtkMedialShapeSource::JACK, 1, 1 } })
  {
    vtkSmartPointer<vtkPolyData> surface = medialtest::MakeSolid(solid.Shape, solid.Genus);
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(surface);
    sampler->SetNumberOfSamples(3000);
    vtkNew<vtkMedialScaleAxisFilter> scaleAxis;
    scaleAxis->SetInputConnection(sampler->GetOutputPort());
    vtkNew<vtkMedialMeshFilter> mesh;
    mesh->SetInputData(surface);
    mesh->SetBallsConnection(scaleAxis->GetOutputPort());
    mesh->Update();
    const medialtest::MeshTopology t = medialtest::CountTopology(mesh->GetOutput());
    const long long euler = static_cast<long long>(t.Vertices - t.Edges + t.Faces);
    std::printf("shape %d genus %d: %lld of 3000 balls kept, medial mesh V %lld E %lld F %lld, Euler "
                "characteristic %lld, %lld component(s)\n",
      solid.Shape, solid.Genus, static_cast<long long>(scaleAxis->GetOutput()->GetNumberOfPoints()),
      static_cast<long long>(t.Vertices), static_cast<long long>(t.Edges), static_cast<long long>(t.Faces), euler,
      static_cast<long long>(t.Components));
    MEDIAL_CHECK(euler == solid.Euler && t.Components == 1,
      "shape %d genus %d: Euler characteristic %lld, %lld components; the solid has %d and 1", solid.Shape,
      solid.Genus, euler, static_cast<long long>(t.Components), solid.Euler);
  }
  return 0;
}

int BadInput()
{
  struct Case
  {
    const char* Name;
    std::vector<double> Radii;
    bool RemoveRadius;
    const char* Expected;
  };
  const Case cases[] = { { "a negative radius", { 1.0, -0.5 }, false, "negative or non-finite radius" },
    { "a NaN radius", { 1.0, std::nan("") }, false, "negative or non-finite radius" },
    { "no radius array", { 1.0, 0.5 }, true, "need a point data array of one radius" } };
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> balls = Balls({ 0, 0, 0, 1, 0, 0 }, c.Radii);
    if (c.RemoveRadius)
    {
      balls->GetPointData()->RemoveArray("Radius");
    }
    medialtest::EventLog log;
    bool ok = true;
    vtkSmartPointer<vtkPolyData> out = ScaleAxis(balls, 1.5, 2, &ok, &log);
    MEDIAL_CHECK(!ok && out->GetNumberOfPoints() == 0 && !log.LineWith(c.Expected).empty(),
      "%s: accepted, or not the expected error (log: %s)", c.Name, log.Text.c_str());
  }
  vtkNew<vtkPolyData> empty;
  medialtest::EventLog log;
  bool ok = false;
  vtkSmartPointer<vtkPolyData> out = ScaleAxis(empty, 1.5, 2, &ok, &log);
  MEDIAL_CHECK(ok && out->GetNumberOfPoints() == 0 && log.Errors == 0, "no balls must be no error");
  return 0;
}
}

int TestMedialScaleAxis(int, char*[])
{
  int failed = ClosedForms();
  failed |= AgainstBruteForce();
  failed |= NoisySphere();
  failed |= Topology();
  failed |= BadInput();
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
