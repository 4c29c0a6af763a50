// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSolidCheck.h"

#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>

void vtkMedialSolidCheck::Run(
  const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads, bool allPairs)
{
  *this = vtkMedialSolidCheck();
  this->BoundaryEdges = mesh.BoundaryEdges;
  this->NonManifoldEdges = mesh.NonManifoldEdges;
  this->NonOrientableShells = mesh.NonOrientableComponents;
  this->DegenerateTriangles = mesh.DegenerateTriangles;
  this->DuplicateTriangles = mesh.DuplicateTriangles;
  this->ShellContacts = static_cast<vtkIdType>(mesh.Contacts.size());
  // A closed surface enclosing less than a billionth of its box's cube: two sheets
  // on top of each other, or a flat closed surface.
  const double d = mesh.Diagonal;
  this->NoVolume = this->BoundaryEdges == 0 && !(std::fabs(mesh.Volume) > 1e-9 * d * d * d);
  // The pair search is the only pass that costs: skipped when the mesh is to be
  // repaired anyway (open or non-manifold input goes through the whole repair).
  if (allPairs || this->CountDefects() == 0)
  {
    vtkMedialTriangleBVH::PairSearchStatistics statistics;
    query.FindIntersectingPairs(threads, this->Pairs, &statistics);
    this->PairsSearched = true;
    this->PatchesTested = statistics.CullingTests;
    this->PatchesCulled = statistics.Culled;
    this->PinchedPatchesCulled = statistics.PinchedCulled;
    // Only where the pair search runs: on a mesh with other defects the repair runs
    // anyway (and the count is 0 on a mesh that is open or not edge-manifold).
    this->CountPinches(mesh);
  }
}

void vtkMedialSolidCheck::CountPinches(const vtkMedialTriangleMesh& mesh)
{
  vtkIdType example = -1;
  this->PinchedVertices = mesh.CountPinchedVertices(&example);
  if (example >= 0)
  {
    std::copy_n(mesh.GetPoint(example), 3, this->PinchedVertex);
  }
}

void vtkMedialSolidCheck::Decide(const vtkMedialTriangleMesh& mesh, const ExactTest& exact)
{
  this->Intersecting.clear();
  std::fill_n(this->IntersectionPoint, 3, 0.0);
  std::vector<std::array<double, 18>> corners(this->Pairs.size());
  std::vector<std::array<vtkIdType, 6>> ids(this->Pairs.size());
  for (size_t i = 0; i < this->Pairs.size(); ++i)
  {
    const vtkIdType tris[2] = { this->Pairs[i].first, this->Pairs[i].second };
    for (int j = 0; j < 2; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = mesh.GetTriangle(tris[j])[k];
        ids[i][3 * j + k] = v;
        std::copy_n(mesh.GetPoint(v), 3, &corners[i][9 * j + 3 * k]);
      }
    }
  }
  const std::vector<char> meet = this->Pairs.empty() ? std::vector<char>() : exact(corners, ids);
  for (size_t i = 0; i < this->Pairs.size(); ++i)
  {
    if (meet[i])
    {
      this->Intersecting.push_back(this->Pairs[i]);
    }
  }
  if (!this->Intersecting.empty())
  {
    const vtkIdType* v = mesh.GetTriangle(this->Intersecting.front().first);
    for (int k = 0; k < 3; ++k)
    {
      this->IntersectionPoint[k] = (mesh.GetPoint(v[0])[k] + mesh.GetPoint(v[1])[k] + mesh.GetPoint(v[2])[k]) / 3.0;
    }
  }
  this->Decided = true;
}

vtkIdType vtkMedialSolidCheck::CountDefects() const
{
  return this->BoundaryEdges + this->NonManifoldEdges + this->NonOrientableShells + this->DegenerateTriangles +
    this->DuplicateTriangles + this->ShellContacts + (this->NoVolume ? 1 : 0);
}

std::vector<std::string> vtkMedialSolidCheck::Problems() const
{
  std::vector<std::string> lines;
  auto add = [&](vtkIdType count, const char* what) {
    if (count > 0)
    {
      std::ostringstream os;
      os << count << " " << what;
      lines.push_back(os.str());
    }
  };
  add(this->BoundaryEdges, "boundary edges (the surface is open)");
  add(this->NonManifoldEdges, "non-manifold edges (more than two triangles on an edge)");
  add(this->NonOrientableShells, "shells that cannot be oriented consistently");
  add(this->DegenerateTriangles, "degenerate (zero-area) triangles");
  add(this->DuplicateTriangles, "duplicate triangles");
  add(this->ShellContacts, "pairs of shells that touch or intersect");
  add(static_cast<vtkIdType>(this->Pairs.size()), "pairs of triangles that intersect or touch (or too close to tell)");
  if (this->NoVolume)
  {
    lines.emplace_back("closed, but it encloses no volume");
  }
  return lines;
}

std::string vtkMedialSolidCheck::PinchedClause() const
{
  if (this->PinchedVertices == 0)
  {
    return std::string();
  }
  std::ostringstream os;
  os << this->PinchedVertices
     << (this->PinchedVertices == 1 ? " pinched vertex" : " pinched vertices")
     << " (the surface touches itself at a point, its triangles there form two or more fans), e.g. at ("
     << this->PinchedVertex[0] << ", " << this->PinchedVertex[1] << ", " << this->PinchedVertex[2] << ")";
  return os.str();
}

std::string vtkMedialSolidCheck::Cause() const
{
  std::ostringstream os;
  if (this->NonManifoldEdges > 0 || this->NonOrientableShells > 0)
  {
    os << "its triangles do not form a manifold, oriented surface";
    if (this->NonManifoldEdges > 0)
    {
      os << " (" << this->NonManifoldEdges << " non-manifold edge(s))";
    }
  }
  else if (!this->Intersecting.empty())
  {
    os << this->Intersecting.size() << " pair(s) of its triangles intersect, e.g. near (" << this->IntersectionPoint[0]
       << ", " << this->IntersectionPoint[1] << ", " << this->IntersectionPoint[2] << ")";
  }
  else if (this->BoundaryEdges > 0)
  {
    os << "it is open (" << this->BoundaryEdges << " boundary edge(s))";
  }
  else if (this->DegenerateTriangles > 0)
  {
    os << this->DegenerateTriangles << " of its triangles have collinear corners";
  }
  else if (this->DuplicateTriangles > 0)
  {
    os << this->DuplicateTriangles << " of its triangles are duplicates";
  }
  else if (this->ShellContacts > 0)
  {
    os << this->ShellContacts << " pair(s) of its shells touch";
  }
  else if (this->NoVolume)
  {
    os << "its shells are not oriented as the boundary of a volume (it encloses none)";
  }
  return os.str();
}
