// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the medial mesh tests: generated solids, and the mesh's topology counted
// from its cells, independently of the filter's own figures.
#ifndef MedialMeshTestUtilities_h
#define MedialMeshTestUtilities_h

#include "MedialShapeTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkGenericCell.h"
#include "vtkStaticCellLocator.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialDisjointSets.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialFileReader.h"
#include "vtkPolyData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkIdList.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace medialtest
{
/// A closed test solid from vtkMedialShapeSource.
inline vtkSmartPointer<vtkPolyData> MakeSolid(int shape, int genus = 1, int resolution = 16)
{
  return MakeShape(shape, resolution, [genus](vtkMedialShapeSource* s) { s->SetGenus(genus); });
}

/// The medial mesh of a solid from `samples` of the sampler's balls (3000 keep a test
/// quick; the mesh is the same kind of complex).
inline vtkSmartPointer<vtkPolyData> MedialMeshOf(vtkPolyData* solid, vtkIdType samples = 3000)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(solid);
  sampler->SetNumberOfSamples(samples);
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(solid);
  filter->SetBallsConnection(sampler->GetOutputPort());
  filter->Update();
  return filter->GetOutput();
}

/// A shared mesh by name, or null when ../shared is absent.
inline vtkSmartPointer<vtkPolyData> ReadSharedMesh(const std::string& name)
{
  const std::string path = SharedMesh(name.c_str());
  if (path.empty())
  {
    std::printf("shared meshes absent: %s part skipped\n", name.c_str());
    return nullptr;
  }
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Distance from x to the surface of `locator`'s dataset.
inline double SurfaceDistance(vtkStaticCellLocator* locator, const double x[3])
{
  vtkNew<vtkGenericCell> cell;
  double closest[3], d2;
  vtkIdType id;
  int sub;
  locator->FindClosestPoint(x, closest, cell, id, sub, d2);
  return std::sqrt(d2);
}

/// The envelope of a medial mesh (vtkMedialBallUnion MEDIAL_MESH at 96^3) against the solid:
/// vtkMedialReconstructionError's vertex Hausdorff (the larger direction), relative to the diagonal.
inline double EnvelopeHausdorff(vtkPolyData* mesh, vtkPolyData* solid)
{
  vtkNew<vtkMedialBallUnion> rebuild;
  rebuild->SetInputData(mesh);
  rebuild->SetPrimitives(vtkMedialBallUnion::MEDIAL_MESH);
  rebuild->SetSampleDimensions(96, 96, 96);
  vtkNew<vtkMedialReconstructionError> measure;
  measure->SetOriginalData(solid);
  measure->SetReconstructionConnection(rebuild->GetOutputPort());
  measure->Update();
  return measure->GetVertexHausdorff();
}

/// The same points, radii and cells, bit for bit.
inline bool SameMesh(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  vtkDataArray* ra = a->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  vtkDataArray* rb = b->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    const double r = ra->GetTuple1(i), s = rb->GetTuple1(i);
    if (std::memcmp(p, q, sizeof(p)) != 0 || std::memcmp(&r, &s, sizeof(r)) != 0)
    {
      return false;
    }
  }
  vtkNew<vtkIdList> u, v;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, u);
    b->GetCellPoints(c, v);
    if (u->GetNumberOfIds() != v->GetNumberOfIds() ||
      !std::equal(u->begin(), u->end(), v->begin()))
    {
      return false;
    }
  }
  return true;
}

struct MeshTopology
{
  vtkIdType Vertices = 0, Edges = 0, Faces = 0, Components = 0;
  vtkIdType Euler() const { return this->Vertices - this->Edges + this->Faces; }
};

/// V (points used by a cell), E (distinct edges of lines and triangle sides), F
/// (triangles) and the connected components, from the cells alone.
inline MeshTopology CountTopology(vtkPolyData* mesh)
{
  const vtkIdType np = mesh->GetNumberOfPoints();
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  std::vector<char> used(np, 0);
  MeshTopology t;
  auto visit = [&](vtkCellArray* cells, bool closed) {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        used[ids[k]] = 1;
        if (n > 1 && (closed || k + 1 < n))
        {
          const vtkIdType a = ids[k], b = ids[(k + 1) % n];
          edges.emplace(std::min(a, b), std::max(a, b));
        }
      }
      t.Faces += closed ? 1 : 0;
    }
  };
  visit(mesh->GetVerts(), false);
  visit(mesh->GetLines(), false);
  visit(mesh->GetPolys(), true);
  vtkMedialDisjointSets sets(np);
  for (const auto& e : edges)
  {
    sets.Join(e.first, e.second);
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    t.Vertices += used[i];
    t.Components += used[i] && sets.Find(i) == i;
  }
  t.Edges = static_cast<vtkIdType>(edges.size());
  return t;
}
}

#endif
