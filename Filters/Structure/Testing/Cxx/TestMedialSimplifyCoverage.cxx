// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialSimplifyFilter's COVERAGE method on generated solids (3000 balls):
//  - coverage: for K = 1000 and 60, every one of the filter's own surface samples (drawn
//    again here from the same stream) that some input ball covers at the start dilation
//    is covered by an output ball at the dilation the filter reports (CoveredDilation),
//    or as nearly as the nearest input ball;
//  - the output is the same bit for bit (points, radii, cells) on 1 and 2 threads;
//  - without a surface on input 1 it is an error (no output), and QUADRIC needs none.
// (Exactly K balls and the topology for both methods: TestMedialPruneSimplifyMesh.)
#include "MedialMeshTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSimplifyFilter.h"
#include "vtkMedialTriangleMesh.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> Simplify(
  vtkPolyData* mesh, vtkPolyData* surface, vtkIdType k, int threads, double* covered = nullptr)
{
  vtkNew<vtkMedialSimplifyFilter> simplify;
  simplify->SetInputData(mesh);
  simplify->SetSurfaceData(surface);
  simplify->SetMethodToCoverage();
  simplify->SetNumberOfBalls(k);
  simplify->SetNumberOfThreads(threads);
  simplify->Update();
  if (covered)
  {
    *covered = simplify->GetCoveredDilation();
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(simplify->GetOutput());
  return out;
}

// Smallest |s - c| - r over the balls of `balls`.
double Excess(vtkPolyData* balls, const double s[3])
{
  vtkDataArray* radius = balls->GetPointData()->GetArray("Radius");
  double best = HUGE_VAL;
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    double c[3];
    balls->GetPoint(i, c);
    best = std::min(best, std::sqrt(vtkMath::Distance2BetweenPoints(s, c)) - radius->GetTuple1(i));
  }
  return best;
}

int CheckCoverage(const char* name, vtkPolyData* mesh, vtkPolyData* surface, vtkIdType k)
{
  vtkNew<vtkMedialSimplifyFilter> defaults;
  double covered = 0.0;
  vtkSmartPointer<vtkPolyData> out = Simplify(mesh, surface, k, 2, &covered);
  MEDIAL_CHECK(out->GetNumberOfPoints() == k, "%s: %lld balls, expected %lld", name,
    static_cast<long long>(out->GetNumberOfPoints()), static_cast<long long>(k));
  vtkMedialTriangleMesh triangles;
  std::string error;
  MEDIAL_CHECK(triangles.Build(surface, error), "%s: %s", name, error.c_str());
  const double dilation = defaults->GetDilation() * triangles.Diagonal;
  const double reached = covered * triangles.Diagonal;
  MEDIAL_CHECK(reached > 0.0 && reached <= dilation, "%s K %lld: covered dilation %g", name,
    static_cast<long long>(k), covered);
  vtkIdType coverable = 0, missed = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < defaults->GetNumberOfSurfaceSamples(); ++i)
  {
    vtkIdType triangle;
    double s[3];
    vtkMedialDrawSurfacePoint(triangles, static_cast<std::uint64_t>(defaults->GetRandomSeed()), i, triangle, s);
    const double best = Excess(mesh, s);
    if (best > dilation)
    {
      continue;
    }
    ++coverable;
    const double e = Excess(out, s);
    worst = std::max(worst, e);
    missed += e > std::max(reached, best) + 1e-6 * dilation; // the filter compares in single precision
  }
  std::printf("%-10s K %lld: %lld of %lld samples coverable at %g, covered at %g, %lld missed, largest excess %g\n",
    name, static_cast<long long>(k), static_cast<long long>(coverable),
    static_cast<long long>(defaults->GetNumberOfSurfaceSamples()), dilation, reached, static_cast<long long>(missed),
    worst);
  MEDIAL_CHECK(coverable > defaults->GetNumberOfSurfaceSamples() / 2, "%s: few samples coverable", name);
  MEDIAL_CHECK(missed == 0, "%s: %lld coverable samples are not covered", name, static_cast<long long>(missed));
  return EXIT_SUCCESS;
}

// Points, radii and cell connectivity bit for bit.
bool Identical(vtkPolyData* a, vtkPolyData* b)
{
  if (medialtest::PointDifferences(a, b) != 0 || a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  vtkDataArray* ra = a->GetPointData()->GetArray("Radius");
  vtkDataArray* rb = b->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    const double x = ra->GetTuple1(i), y = rb->GetTuple1(i);
    if (std::memcmp(&x, &y, sizeof(double)) != 0)
    {
      return false;
    }
  }
  for (auto cells : { &vtkPolyData::GetVerts, &vtkPolyData::GetLines, &vtkPolyData::GetPolys })
  {
    vtkCellArray* ca = (a->*cells)();
    vtkCellArray* cb = (b->*cells)();
    vtkIdType na, nb;
    const vtkIdType *ia, *ib;
    ca->InitTraversal();
    cb->InitTraversal();
    while (ca->GetNextCell(na, ia))
    {
      if (!cb->GetNextCell(nb, ib) || na != nb || !std::equal(ia, ia + na, ib))
      {
        return false;
      }
    }
  }
  return true;
}

int CheckThreads(const char* name, vtkPolyData* mesh, vtkPolyData* surface)
{
  for (vtkIdType k : { 300, 40 })
  {
    vtkSmartPointer<vtkPolyData> one = Simplify(mesh, surface, k, 1);
    vtkSmartPointer<vtkPolyData> two = Simplify(mesh, surface, k, 2);
    MEDIAL_CHECK(one->GetNumberOfPoints() == k && Identical(one, two), "%s K %lld: 1 and 2 threads differ", name,
      static_cast<long long>(k));
  }
  return EXIT_SUCCESS;
}

int CheckNoSurface(vtkPolyData* mesh)
{
  vtkNew<vtkMedialSimplifyFilter> simplify;
  medialtest::EventLog log;
  log.Watch(simplify);
  simplify->SetInputData(mesh);
  simplify->SetMethodToCoverage();
  simplify->SetNumberOfBalls(50);
  simplify->Update();
  MEDIAL_CHECK(log.Errors >= 1 && log.LineWith("input 1") != "" && simplify->GetOutput()->GetNumberOfPoints() == 0,
    "coverage without a surface: %d errors, %lld points", log.Errors,
    static_cast<long long>(simplify->GetOutput()->GetNumberOfPoints()));
  const int errors = log.Errors;
  simplify->SetMethodToQuadric();
  simplify->Update();
  MEDIAL_CHECK(log.Errors == errors && simplify->GetOutput()->GetNumberOfPoints() == 50, "quadric without a surface failed");
  return EXIT_SUCCESS;
}
}

int TestMedialSimplifyCoverage(int, char*[])
{
  struct Case
  {
    const char* Name;
    int Shape;
    int Genus;
  };
  const Case cases[] = { { "jack", vtkMedialShapeSource::JACK, 0 }, { "two rings", vtkMedialShapeSource::RINGS, 2 } };
  int status = EXIT_SUCCESS;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(c.Shape, c.Genus);
    vtkSmartPointer<vtkPolyData> mesh = medialtest::MedialMeshOf(solid);
    if (CheckCoverage(c.Name, mesh, solid, 1000) != EXIT_SUCCESS ||
      CheckCoverage(c.Name, mesh, solid, 60) != EXIT_SUCCESS || CheckThreads(c.Name, mesh, solid) != EXIT_SUCCESS ||
      CheckNoSurface(mesh) != EXIT_SUCCESS)
    {
      status = EXIT_FAILURE;
    }
  }
  return status;
}
