// SPDX-License-Identifier: BSD-3-Clause
// The envelope refinement of vtkMedialMeshFilter (vtkMedialEnvelopeRefinement): on the
// jack from 3000 samples, without it some ball interpolated along an edge or a triangle
// crosses the surface by more than the tolerance; with it none does at the probe points
// (barycentric steps of 1/4), measured here independently with vtkStaticCellLocator.
// Splitting edges keeps the topology (V - E + F and the components, counted from the
// cells), every added ball is inscribed and has no sample arrays (GovernorCount -1),
// and 1 and 2 threads give the same mesh.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"

#include <cstdio>

namespace
{
// The largest protrusion through the surface of the balls interpolated over the mesh's
// triangles and lines at barycentric steps of 1/4 (corners excepted).
double WorstProtrusion(vtkPolyData* mesh, vtkStaticCellLocator* surface)
{
  vtkDataArray* radius = mesh->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  double worst = 0.0;
  auto probe = [&](const vtkIdType* ids, const int* steps, int n) {
    double c[3] = { 0, 0, 0 }, r = 0.0;
    for (int j = 0; j < n; ++j)
    {
      double x[3];
      mesh->GetPoint(ids[j], x);
      for (int k = 0; k < 3; ++k)
      {
        c[k] += steps[j] / 4.0 * x[k];
      }
      r += steps[j] / 4.0 * radius->GetTuple1(ids[j]);
    }
    worst = std::max(worst, r - medialtest::SurfaceDistance(surface, c));
  };
  vtkNew<vtkIdList> cell;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, cell);
    const vtkIdType* ids = cell->begin();
    if (cell->GetNumberOfIds() == 3 && mesh->GetCellType(c) == VTK_TRIANGLE)
    {
      for (int i = 0; i <= 4; ++i)
      {
        for (int j = 0; i + j <= 4; ++j)
        {
          const int steps[3] = { i, j, 4 - i - j };
          if (i < 4 && j < 4 && i + j > 0)
          {
            probe(ids, steps, 3);
          }
        }
      }
    }
    else
    {
      for (vtkIdType k = 0; k + 1 < cell->GetNumberOfIds(); ++k)
      {
        for (int i = 1; i < 4; ++i)
        {
          const int steps[2] = { 4 - i, i };
          probe(ids + k, steps, 2);
        }
      }
    }
  }
  return worst;
}
}

int TestMedialMeshEnvelopeRefinement(int, char*[])
{
  vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(vtkMedialShapeSource::JACK);
  const double diagonal = solid->GetLength();
  const double tolerance = 3e-4; // relative to the diagonal
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(solid);
  sampler->SetNumberOfSamples(3000);
  vtkNew<vtkMedialMeshFilter> plain, refined, oneThread;
  plain->SetEnvelopeTolerance(-1.0);
  refined->SetEnvelopeTolerance(tolerance);
  oneThread->SetEnvelopeTolerance(tolerance);
  refined->SetNumberOfThreads(2);
  oneThread->SetNumberOfThreads(1);
  for (vtkMedialMeshFilter* f : { plain.Get(), refined.Get(), oneThread.Get() })
  {
    f->SetInputData(solid);
    f->SetBallsConnection(sampler->GetOutputPort());
    f->Update();
  }
  vtkPolyData* mesh = refined->GetOutput();
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(solid);
  locator->BuildLocator();
  const double before = WorstProtrusion(plain->GetOutput(), locator) / diagonal;
  const double after = WorstProtrusion(mesh, locator) / diagonal;
  std::printf("jack, 3000 samples: %lld balls, %lld added; worst protrusion %.4f%% -> %.4f%% of the diagonal "
              "(filter: %.4f%%), tolerance %.4f%%\n",
    static_cast<long long>(plain->GetOutput()->GetNumberOfPoints()),
    static_cast<long long>(refined->GetRefinementBalls()), 100 * before, 100 * after,
    100 * refined->GetEnvelopeProtrusion(), 100 * tolerance);
  MEDIAL_CHECK(before > tolerance, "the unrefined envelope already within the tolerance (%g): no test", before);
  MEDIAL_CHECK(refined->GetRefinementBalls() > 0 &&
      mesh->GetNumberOfPoints() == plain->GetOutput()->GetNumberOfPoints() + refined->GetRefinementBalls(),
    "balls added: %lld, points %lld -> %lld", static_cast<long long>(refined->GetRefinementBalls()),
    static_cast<long long>(plain->GetOutput()->GetNumberOfPoints()), static_cast<long long>(mesh->GetNumberOfPoints()));
  MEDIAL_CHECK(after <= tolerance * (1.0 + 1e-9), "protrusion %g left above the tolerance %g", after, tolerance);
  MEDIAL_CHECK(refined->GetEnvelopeProtrusion() <= tolerance * (1.0 + 1e-9), "the filter reports %g",
    refined->GetEnvelopeProtrusion());

  // Topology unchanged.
  const medialtest::MeshTopology a = medialtest::CountTopology(plain->GetOutput());
  const medialtest::MeshTopology b = medialtest::CountTopology(mesh);
  MEDIAL_CHECK(a.Euler() == b.Euler() && a.Components == b.Components && b.Euler() == 1,
    "refinement changed the topology: chi %lld -> %lld, components %lld -> %lld", static_cast<long long>(a.Euler()),
    static_cast<long long>(b.Euler()), static_cast<long long>(a.Components), static_cast<long long>(b.Components));

  // The added balls: inscribed, without sample arrays.
  vtkDataArray* governors = mesh->GetPointData()->GetArray(vtkMedialArrayNames::GovernorCount);
  vtkDataArray* radius = mesh->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  MEDIAL_CHECK(governors && radius, "GovernorCount or Radius missing");
  vtkIdType added = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (governors->GetTuple1(i) >= 0)
    {
      continue;
    }
    ++added;
    double x[3];
    mesh->GetPoint(i, x);
    MEDIAL_CHECK(radius->GetTuple1(i) <= medialtest::SurfaceDistance(locator, x) + 1e-12 * diagonal,
      "added ball %lld is not inscribed", static_cast<long long>(i));
  }
  MEDIAL_CHECK(added == refined->GetRefinementBalls(), "%lld balls without governors, %lld added",
    static_cast<long long>(added), static_cast<long long>(refined->GetRefinementBalls()));
  MEDIAL_CHECK(medialtest::SameMesh(mesh, oneThread->GetOutput()), "1 and 2 threads give different meshes");
  return EXIT_SUCCESS;
}
