// SPDX-License-Identifier: BSD-3-Clause
// The protrusion pruning of vtkMedialMeshFilter: it removes fins (fewer triangles than
// without it) and keeps the topology; every triangle left with a free side has its
// interpolated balls (at the centroid and the sides' midpoints) within the tolerance
// of the surface, measured here with vtkStaticCellLocator; and the interpolated
// envelope of the pruned mesh (vtkMedialBallUnion, MEDIAL_MESH) rebuilds the shape
// closer, on average, than the union of the same balls.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialMeshFilter.h"


#include <cstdio>
#include <map>

namespace
{
// Mean distance from the vertices of `from` to the surface `to`.
double MeanDistance(vtkPolyData* from, vtkStaticCellLocator* to)
{
  double sum = 0.0;
  for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
  {
    double x[3];
    from->GetPoint(i, x);
    sum += medialtest::SurfaceDistance(to, x);
  }
  return from->GetNumberOfPoints() ? sum / from->GetNumberOfPoints() : HUGE_VAL;
}
}

int TestMedialMeshPruning(int, char*[])
{
  vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(vtkMedialShapeSource::JACK);
  const double diagonal = solid->GetLength();
  vtkNew<vtkMedialMeshFilter> unpruned, pruned;
  unpruned->SetProtrusionTolerance(-1.0);
  for (vtkMedialMeshFilter* f : { unpruned.Get(), pruned.Get() })
  {
    f->SetInputData(solid);
    f->Update();
  }
  vtkPolyData* mesh = pruned->GetOutput();
  std::printf("jack: %lld triangles unpruned, %lld pruned (%lld removed)\n",
    static_cast<long long>(unpruned->GetOutput()->GetNumberOfPolys()),
    static_cast<long long>(mesh->GetNumberOfPolys()), static_cast<long long>(pruned->GetPrunedTriangles()));
  MEDIAL_CHECK(pruned->GetPrunedTriangles() > 0 &&
      mesh->GetNumberOfPolys() < unpruned->GetOutput()->GetNumberOfPolys(),
    "nothing pruned");
  const medialtest::MeshTopology t = medialtest::CountTopology(mesh);
  MEDIAL_CHECK(t.Euler() == 1 && t.Components == 1, "pruning changed the topology: chi %lld, %lld components",
    static_cast<long long>(t.Euler()), static_cast<long long>(t.Components));

  // Triangles with a free side: their interpolated balls within the tolerance.
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(solid);
  locator->BuildLocator();
  vtkDataArray* radius = mesh->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  std::map<std::pair<vtkIdType, vtkIdType>, int> sides;
  auto side = [](vtkIdType a, vtkIdType b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  auto triangles = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (triangles->GoToFirstCell(); !triangles->IsDoneWithTraversal(); triangles->GoToNextCell())
  {
    vtkIdList* ids = triangles->GetCurrentCell();
    for (int k = 0; k < 3; ++k)
    {
      ++sides[side(ids->GetId(k), ids->GetId((k + 1) % 3))];
    }
  }
  auto protrusion = [&](const std::vector<vtkIdType>& ids) {
    double c[3] = { 0, 0, 0 }, r = 0.0;
    for (vtkIdType id : ids)
    {
      double x[3];
      mesh->GetPoint(id, x);
      for (int k = 0; k < 3; ++k)
      {
        c[k] += x[k] / ids.size();
      }
      r += radius->GetTuple1(id) / ids.size();
    }
    return (r - medialtest::SurfaceDistance(locator, c)) / diagonal;
  };
  double worst = 0.0;
  vtkIdType free = 0;
  for (triangles->GoToFirstCell(); !triangles->IsDoneWithTraversal(); triangles->GoToNextCell())
  {
    vtkIdList* ids = triangles->GetCurrentCell();
    const vtkIdType v[3] = { ids->GetId(0), ids->GetId(1), ids->GetId(2) };
    bool hasFreeSide = false;
    for (int k = 0; k < 3; ++k)
    {
      hasFreeSide = hasFreeSide || sides[side(v[k], v[(k + 1) % 3])] == 1;
    }
    if (!hasFreeSide)
    {
      continue;
    }
    ++free;
    worst = std::max({ worst, protrusion({ v[0], v[1], v[2] }), protrusion({ v[0], v[1] }),
      protrusion({ v[1], v[2] }), protrusion({ v[0], v[2] }) });
  }
  std::printf("%lld triangles with a free side: worst protrusion %.2g of the diagonal (tolerance %g)\n",
    static_cast<long long>(free), worst, pruned->GetProtrusionTolerance());
  MEDIAL_CHECK(worst <= pruned->GetProtrusionTolerance() * (1.0 + 1e-6) + 1e-12,
    "a fin that crosses the surface by %g of the diagonal was left", worst);

  // The envelope against the union of the same balls, vertex to surface on average.
  double mean[2];
  for (int primitives : { vtkMedialBallUnion::MEDIAL_MESH, vtkMedialBallUnion::BALLS })
  {
    vtkNew<vtkMedialBallUnion> rebuild;
    rebuild->SetInputData(mesh);
    rebuild->SetPrimitives(primitives);
    rebuild->SetSampleDimensions(96, 96, 96);
    rebuild->Update();
    mean[primitives == vtkMedialBallUnion::BALLS] = MeanDistance(rebuild->GetOutput(), locator) / diagonal;
  }
  std::printf("mean distance to the jack: envelope %.4f%%, union of balls %.4f%% of the diagonal\n",
    100 * mean[0], 100 * mean[1]);
  MEDIAL_CHECK(mean[0] < mean[1], "the envelope is not closer than the balls");
  return EXIT_SUCCESS;
}
