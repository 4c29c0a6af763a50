// SPDX-License-Identifier: BSD-3-Clause
// Pruning and simplification of the 3D medial mesh (vtkMedialMeshFilter's output) on
// generated solids of genus 0, 1 and 2 (3000 balls), counted from the output cells:
//  - vtkMedialPruneFilter, every measure at its default threshold and at a high one,
//    keeps the Euler characteristic and the components; thresholding the Significance
//    of the unpruned output (threshold 0) keeps as many triangles as the filter;
//  - vtkMedialSimplifyFilter, both methods (QUADRIC, and COVERAGE with the solid as its
//    surface), leaves exactly K vertices (K = 200, 60, 25) with the same Euler
//    characteristic and components, every radius positive, no blocked collapse.
#include "MedialMeshTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialPruneFilter.h"
#include "vtkMedialSimplifyFilter.h"
#include "vtkPointData.h"

#include <cstdio>

namespace
{
using medialtest::CountTopology;
using medialtest::MeshTopology;

int CheckPruning(const char* name, vtkPolyData* mesh, const MeshTopology& before)
{
  for (int m = vtkMedialPruneFilter::EROSION_THICKNESS; m <= vtkMedialPruneFilter::SCALE_AXIS; ++m)
  {
    vtkNew<vtkMedialPruneFilter> all;
    all->SetInputData(mesh);
    all->SetMeasure(m);
    all->SetThreshold(0.0);
    all->Update();
    vtkPolyData* unpruned = all->GetOutput();
    vtkDataArray* level = unpruned->GetCellData()->GetArray("Significance");
    MEDIAL_CHECK(level && level->GetNumberOfTuples() == unpruned->GetNumberOfCells(), "%s: no Significance", name);
    MEDIAL_CHECK(unpruned->GetNumberOfPolys() == mesh->GetNumberOfPolys(), "%s: threshold 0 removed triangles",
      name);
    const double top = vtkMedialPruneFilter::GetMeasureUpperBound(m);
    for (double t : { vtkMedialPruneFilter::GetDefaultThreshold(m), 0.3 * top })
    {
      vtkNew<vtkMedialPruneFilter> prune;
      medialtest::EventLog log;
      log.Watch(prune);
      prune->SetInputData(mesh);
      prune->SetMeasure(m);
      prune->SetThreshold(t);
      prune->Update();
      vtkPolyData* pruned = prune->GetOutput();
      const MeshTopology after = CountTopology(pruned);
      std::printf("%-10s %-18s t %-8g V %5lld -> %5lld, F %5lld -> %5lld, chi %lld -> %lld, components "
                  "%lld -> %lld\n",
        name, vtkMedialPruneFilter::GetMeasureName(m), t, static_cast<long long>(before.Vertices),
        static_cast<long long>(after.Vertices), static_cast<long long>(before.Faces),
        static_cast<long long>(after.Faces), static_cast<long long>(before.Euler()),
        static_cast<long long>(after.Euler()), static_cast<long long>(before.Components),
        static_cast<long long>(after.Components));
      MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", name, log.Text.c_str());
      MEDIAL_CHECK(after.Euler() == before.Euler() && after.Components == before.Components,
        "%s, %s at %g: topology changed", name, vtkMedialPruneFilter::GetMeasureName(m), t);
      vtkIdType keptTriangles = 0;
      const vtkIdType firstPoly = unpruned->GetNumberOfVerts() + unpruned->GetNumberOfLines();
      for (vtkIdType c = firstPoly; c < unpruned->GetNumberOfCells(); ++c)
      {
        keptTriangles += level->GetTuple1(c) >= t ? 1 : 0;
      }
      MEDIAL_CHECK(keptTriangles == pruned->GetNumberOfPolys(),
        "%s, %s at %g: thresholding Significance keeps %lld triangles, the filter %lld", name,
        vtkMedialPruneFilter::GetMeasureName(m), t, static_cast<long long>(keptTriangles),
        static_cast<long long>(pruned->GetNumberOfPolys()));
    }
  }
  return EXIT_SUCCESS;
}

int CheckSimplification(
  const char* name, vtkPolyData* mesh, vtkPolyData* surface, int method, const MeshTopology& before)
{
  for (vtkIdType k : { 200, 60, 25 })
  {
    vtkNew<vtkMedialSimplifyFilter> simplify;
    medialtest::EventLog log;
    log.Watch(simplify);
    simplify->SetInputData(mesh);
    simplify->SetSurfaceData(surface);
    simplify->SetMethod(method);
    simplify->SetNumberOfBalls(k);
    simplify->Update();
    vtkPolyData* out = simplify->GetOutput();
    const MeshTopology after = CountTopology(out);
    std::printf("%-10s simplify %-8s K %3lld: V %lld E %lld F %lld chi %lld components %lld\n", name,
      vtkMedialSimplifyFilter::GetMethodName(method), static_cast<long long>(k),
      static_cast<long long>(after.Vertices), static_cast<long long>(after.Edges),
      static_cast<long long>(after.Faces), static_cast<long long>(after.Euler()),
      static_cast<long long>(after.Components));
    MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s K %lld: %s", name, static_cast<long long>(k),
      log.Text.c_str());
    MEDIAL_CHECK(out->GetNumberOfPoints() == k && after.Vertices == k, "%s: %lld points (%lld used), expected %lld",
      name, static_cast<long long>(out->GetNumberOfPoints()), static_cast<long long>(after.Vertices),
      static_cast<long long>(k));
    MEDIAL_CHECK(after.Euler() == before.Euler() && after.Components == before.Components,
      "%s K %lld: topology changed (chi %lld -> %lld, components %lld -> %lld)", name, static_cast<long long>(k),
      static_cast<long long>(before.Euler()), static_cast<long long>(after.Euler()),
      static_cast<long long>(before.Components), static_cast<long long>(after.Components));
    MEDIAL_CHECK(simplify->GetEulerCharacteristic() == after.Euler() &&
        simplify->GetNumberOfComponents() == after.Components && simplify->GetNumberOfBlockedCollapses() == 0,
      "%s K %lld: the filter's figures disagree with its cells", name, static_cast<long long>(k));
    vtkDataArray* radius = out->GetPointData()->GetArray("Radius");
    MEDIAL_CHECK(radius && radius->GetNumberOfTuples() == k, "%s: no Radius", name);
    for (vtkIdType i = 0; i < k; ++i)
    {
      MEDIAL_CHECK(radius->GetTuple1(i) > 0.0, "%s K %lld: ball %lld has radius %g", name,
        static_cast<long long>(k), static_cast<long long>(i), radius->GetTuple1(i));
    }
  }
  return EXIT_SUCCESS;
}
}

int TestMedialPruneSimplifyMesh(int, char*[])
{
  struct Case
  {
    const char* Name;
    int Shape;
    int Genus;
  };
  const Case cases[] = { { "jack", vtkMedialShapeSource::JACK, 0 }, { "ring", vtkMedialShapeSource::RINGS, 1 },
    { "two rings", vtkMedialShapeSource::RINGS, 2 } };
  int status = EXIT_SUCCESS;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(c.Shape, c.Genus);
    vtkSmartPointer<vtkPolyData> mesh = medialtest::MedialMeshOf(solid);
    const MeshTopology before = CountTopology(mesh);
    MEDIAL_CHECK(before.Euler() == 1 - c.Genus && before.Components == 1, "%s: the medial mesh is not as expected",
      c.Name);
    if (CheckPruning(c.Name, mesh, before) != EXIT_SUCCESS ||
      CheckSimplification(c.Name, mesh, solid, vtkMedialSimplifyFilter::QUADRIC, before) != EXIT_SUCCESS ||
      CheckSimplification(c.Name, mesh, solid, vtkMedialSimplifyFilter::COVERAGE, before) != EXIT_SUCCESS)
    {
      status = EXIT_FAILURE;
    }
  }
  return status;
}
