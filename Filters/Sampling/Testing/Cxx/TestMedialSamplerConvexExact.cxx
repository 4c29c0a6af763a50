// SPDX-License-Identifier: BSD-3-Clause
// Convex polyhedra with theta = 0: the maximal radius at P along the inward normal n
// has a closed form, min over facets j with n_j.n < 1 of s_j(P) / (1 - n_j.n), where
// s_j(P) >= 0 is P's distance to facet j's plane and n_j its inward normal. Both
// methods must match it within the tolerance (1e-6 of the diagonal).
#include "MedialPolyhedronTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cstdlib>
#include <map>
#include <random>

using namespace medialtest;

namespace
{
int CheckConvex(vtkPolyData* shape, const char* label)
{
  // Inward unit normals and plane offsets of every facet, oriented towards the centroid.
  double centroid[3] = { 0, 0, 0 };
  for (vtkIdType i = 0; i < shape->GetNumberOfPoints(); ++i)
  {
    double x[3];
    shape->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += x[k] / shape->GetNumberOfPoints();
    }
  }
  const vtkIdType nf = shape->GetNumberOfCells();
  std::vector<std::array<double, 3>> normal(nf), anchor(nf);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    shape->GetCellPoints(f, npts, pts);
    double a[3], b[3], c[3], u[3], v[3], n[3];
    shape->GetPoint(pts[0], a);
    shape->GetPoint(pts[1], b);
    shape->GetPoint(pts[2], c);
    for (int k = 0; k < 3; ++k)
    {
      u[k] = b[k] - a[k];
      v[k] = c[k] - a[k];
    }
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double side = (centroid[0] - a[0]) * n[0] + (centroid[1] - a[1]) * n[1] + (centroid[2] - a[2]) * n[2];
    for (int k = 0; k < 3; ++k)
    {
      normal[f][k] = (side > 0 ? 1 : -1) * n[k] / len;
      anchor[f][k] = a[k];
    }
  }
  const double diagonal = Diagonal(shape);
  for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(shape);
    sampler->SetNumberOfSamples(2000);
    sampler->SetMinimumSeparationAngle(0.0);
    sampler->SetMethod(method);
    sampler->SetRandomSeed(7);
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    MEDIAL_CHECK(out->GetNumberOfPoints() == 2000, "%s: %lld of 2000 samples kept", label,
      static_cast<long long>(out->GetNumberOfPoints()));
    double worst = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const vtkIdType f = static_cast<vtkIdType>(Value(out, "SourceCellId", i));
      const double p[3] = { Value(out, "SurfacePoint", i, 0), Value(out, "SurfacePoint", i, 1),
        Value(out, "SurfacePoint", i, 2) };
      const auto& n = normal[f];
      double exact = HUGE_VAL;
      for (vtkIdType j = 0; j < nf; ++j)
      {
        const auto& nj = normal[j];
        const double cosine = nj[0] * n[0] + nj[1] * n[1] + nj[2] * n[2];
        if (1.0 - cosine <= 1e-12)
        {
          continue;
        }
        const double s = (p[0] - anchor[j][0]) * nj[0] + (p[1] - anchor[j][1]) * nj[1] + (p[2] - anchor[j][2]) * nj[2];
        exact = std::min(exact, std::max(0.0, s) / (1.0 - cosine));
      }
      worst = std::max(worst, std::fabs(Value(out, "Radius", i) - exact) / diagonal);
    }
    std::printf("%s, %s: max |r - exact| = %.3g of the diagonal over %lld samples\n", label,
      vtkMedialAxisSampler::GetMethodName(method), worst, static_cast<long long>(out->GetNumberOfPoints()));
    MEDIAL_CHECK(worst <= 1e-6, "%s %s: radius off by %g of the diagonal", label,
      vtkMedialAxisSampler::GetMethodName(method), worst);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerConvexExact(int, char*[])
{
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(3);
  sphere->Update();
  if (CheckConvex(sphere->GetOutput(), "geodesic sphere (1280 triangles)") != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  // Convex hull of random points on an ellipsoid, built here in double precision
  // (vtkDelaunay3D's surface of such points is not exactly convex).
  std::mt19937_64 random(12345);
  std::normal_distribution<double> gauss;
  std::vector<std::array<double, 3>> cloud;
  for (int i = 0; i < 300; ++i)
  {
    double v[3] = { gauss(random), gauss(random), gauss(random) };
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    cloud.push_back({ 2.0 * v[0] / l, 1.2 * v[1] / l, 0.7 * v[2] / l });
  }
  vtkSmartPointer<vtkPolyData> hull = ConvexHull(cloud);
  MEDIAL_CHECK(hull, "convex hull construction failed");
  return CheckConvex(hull, "convex hull of 300 random points");
}
