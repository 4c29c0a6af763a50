// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSimplicialComplex.h"
#include "vtkMedialArrayNames.h"

#include "vtkMedialDisjointSets.h"
#include "vtkMedialMeshFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace
{
// Medial point type from the mesh around a vertex: junction where three or more seam
// (or curve) edges meet, seam on a seam edge, rim on a rim edge or at a curve's free end.
int MeshPointType(int seamEdges, int rimEdges, int curveEdges, int degree)
{
  if (seamEdges >= 3 || curveEdges >= 3)
  {
    return 3;
  }
  if (seamEdges >= 1)
  {
    return 2;
  }
  if (rimEdges >= 1 || degree <= 1)
  {
    return 0;
  }
  return 1;
}

std::array<vtkIdType, 2> Sorted(vtkIdType a, vtkIdType b)
{
  return { std::min(a, b), std::max(a, b) };
}
}

void vtkMedialSimplicialComplex::Assemble(vtkIdType vertices, const std::vector<std::array<vtkIdType, 2>>& segments,
  const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  std::map<std::array<vtkIdType, 2>, vtkIdType> edgeIds;
  this->Edges.clear();
  auto edge = [&](vtkIdType a, vtkIdType b) {
    const auto key = Sorted(a, b);
    auto found = edgeIds.find(key);
    if (found != edgeIds.end())
    {
      return found->second;
    }
    const vtkIdType id = static_cast<vtkIdType>(this->Edges.size());
    edgeIds.emplace(key, id);
    this->Edges.push_back(key);
    return id;
  };
  std::map<std::array<vtkIdType, 3>, bool> seen;
  this->Triangles.clear();
  this->TriangleEdges.clear();
  for (const auto& t : triangles)
  {
    std::array<vtkIdType, 3> key = t;
    std::sort(key.begin(), key.end());
    if (key[0] == key[1] || key[1] == key[2])
    {
      if (key[0] != key[2])
      {
        edge(key[0], key[2]);
      }
      continue;
    }
    if (!seen.emplace(key, true).second)
    {
      continue;
    }
    this->Triangles.push_back(t);
    this->TriangleEdges.push_back({ edge(t[0], t[1]), edge(t[1], t[2]), edge(t[2], t[0]) });
  }
  for (const auto& s : segments)
  {
    if (s[0] != s[1])
    {
      edge(s[0], s[1]);
    }
  }
  this->EdgeTriangles.assign(this->Edges.size(), {});
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(this->Triangles.size()); ++t)
  {
    for (vtkIdType e : this->TriangleEdges[t])
    {
      this->EdgeTriangles[e].push_back(t);
    }
  }
  this->VertexEdges.assign(static_cast<size_t>(vertices), {});
  for (vtkIdType e = 0; e < static_cast<vtkIdType>(this->Edges.size()); ++e)
  {
    this->VertexEdges[this->Edges[e][0]].push_back(e);
    this->VertexEdges[this->Edges[e][1]].push_back(e);
  }
}

bool vtkMedialSimplicialComplex::Read(vtkPolyData* mesh, vtkDataArray* radius, std::string& error)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  if (mesh->GetNumberOfStrips() > 0)
  {
    error = "triangle strips are not supported (triangulate the medial mesh first)";
    return false;
  }
  this->Points.resize(static_cast<size_t>(3 * n));
  this->Radii.resize(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, &this->Points[3 * i]);
    this->Radii[i] = radius->GetComponent(i, 0);
    if (!std::isfinite(this->Radii[i]) || this->Radii[i] < 0.0)
    {
      error = "point " + std::to_string(i) + " has radius " + std::to_string(this->Radii[i]) +
        " (radii must be finite and >= 0)";
      return false;
    }
  }
  std::vector<std::array<vtkIdType, 2>> segments;
  std::vector<std::array<vtkIdType, 3>> triangles;
  auto lines = vtk::TakeSmartPointer(mesh->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    lines->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k + 1 < count; ++k)
    {
      segments.push_back({ ids[k], ids[k + 1] });
    }
  }
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 1; k + 1 < count; ++k)
    {
      triangles.push_back({ ids[0], ids[k], ids[k + 1] });
    }
  }
  this->Assemble(n, segments, triangles);
  return true;
}

vtkIdType vtkMedialSimplicialComplex::EulerCharacteristic(
  const std::vector<char>& vertices, const std::vector<char>& edges, const std::vector<char>& triangles)
{
  auto count = [](const std::vector<char>& kept) {
    return static_cast<vtkIdType>(std::count(kept.begin(), kept.end(), 1));
  };
  return count(vertices) - count(edges) + count(triangles);
}

vtkIdType vtkMedialSimplicialComplex::CountComponents(
  const std::vector<char>& vertices, const std::vector<char>& edges) const
{
  const vtkIdType n = this->GetNumberOfVertices();
  vtkMedialDisjointSets sets(n);
  for (vtkIdType e = 0; e < static_cast<vtkIdType>(this->Edges.size()); ++e)
  {
    if (edges[e])
    {
      sets.Join(this->Edges[e][0], this->Edges[e][1]);
    }
  }
  vtkIdType components = 0;
  for (vtkIdType v = 0; v < n; ++v)
  {
    components += vertices[v] && sets.Find(v) == v ? 1 : 0;
  }
  return components;
}

vtkMedialSimplicialComplex::Cells vtkMedialSimplicialComplex::WriteCells(vtkIdType vertices,
  const std::vector<std::array<vtkIdType, 2>>& edges, const std::vector<int>& edgeTriangles,
  const std::vector<std::array<vtkIdType, 3>>& triangles, vtkPolyData* output)
{
  Cells cells;
  std::vector<int> seam(vertices, 0), rim(vertices, 0), curve(vertices, 0), degree(vertices, 0);
  vtkNew<vtkCellArray> lines;
  std::vector<int> lineTypes;
  for (size_t e = 0; e < edges.size(); ++e)
  {
    const int count = edgeTriangles[e];
    for (vtkIdType v : edges[e])
    {
      ++degree[v];
      seam[v] += count >= 3;
      rim[v] += count == 1;
      curve[v] += count == 0;
    }
    if (count == 0 || count >= 3)
    {
      lines->InsertNextCell(2, edges[e].data());
      lineTypes.push_back(count == 0 ? vtkMedialMeshFilter::CURVE_EDGE : vtkMedialMeshFilter::SEAM_EDGE);
      cells.LineEdges.push_back(static_cast<vtkIdType>(e));
    }
  }
  vtkNew<vtkCellArray> verts;
  for (vtkIdType k = 0; k < vertices; ++k)
  {
    if (degree[k] == 0)
    {
      verts->InsertNextCell(1, &k);
    }
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(triangles.size()), 3 * triangles.size());
  for (const auto& t : triangles)
  {
    polys->InsertNextCell(3, t.data());
  }
  output->SetVerts(verts);
  output->SetLines(lines);
  output->SetPolys(polys);

  // Cell data in VTK's cell order: vertices, lines, polygons.
  vtkNew<vtkIntArray> cellTypes;
  cellTypes->SetName(vtkMedialArrayNames::MedialCellType);
  cellTypes->Allocate(output->GetNumberOfCells());
  for (vtkIdType k = 0; k < verts->GetNumberOfCells(); ++k)
  {
    cellTypes->InsertNextValue(vtkMedialMeshFilter::ISOLATED_BALL);
  }
  for (int type : lineTypes)
  {
    cellTypes->InsertNextValue(type);
  }
  for (vtkIdType k = 0; k < polys->GetNumberOfCells(); ++k)
  {
    cellTypes->InsertNextValue(vtkMedialMeshFilter::SHEET_TRIANGLE);
  }
  output->GetCellData()->AddArray(cellTypes);
  cells.PointTypes.resize(static_cast<size_t>(vertices));
  for (vtkIdType k = 0; k < vertices; ++k)
  {
    cells.PointTypes[k] = MeshPointType(seam[k], rim[k], curve[k], degree[k]);
  }
  return cells;
}
