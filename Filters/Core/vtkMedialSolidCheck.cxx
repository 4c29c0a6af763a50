// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSolidCheck.h"

#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <cmath>
#include <sstream>

void vtkMedialSolidCheck::Run(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads)
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
  if (this->CountDefects() == 0)
  {
    query.FindIntersectingPairs(threads, this->Pairs);
  }
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
