// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSolidPreparation.h"

#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkFieldData.h"
#include "vtkPolyData.h"

bool vtkMedialSolidPreparation::Prepare(vtkPolyData* input, int mode, const Repairer& repair, int threads,
  vtkMedialTriangleMesh& mesh, vtkMedialSurfaceQuery& query, std::string& error,
  const std::function<bool()>& aborted, const std::function<void(int)>& stage)
{
  auto begin = [&](int s) {
    if (stage)
    {
      stage(s);
    }
  };
  *this = vtkMedialSolidPreparation();
  this->Surface = input;
  auto build = [&](vtkPolyData* surface) {
    begin(MESH);
    if (!mesh.Build(surface, error, aborted))
    {
      return false;
    }
    begin(QUERIES);
    if (!query.Build(&mesh, error, aborted))
    {
      return false;
    }
    this->Surface = surface;
    return true;
  };
  auto runRepair = [&](bool wrap, const Checked& checked, Repair& result) {
    begin(REPAIR);
    if (!repair)
    {
      error = "no repair is available";
      return false;
    }
    if (!repair(input, wrap, checked, result, error))
    {
      return false;
    }
    this->Messages = result.Messages;
    this->Report = result.Report;
    return true;
  };

  if (mode == WRAP)
  {
    Repair result;
    if (!runRepair(true, Checked(), result) || !build(result.Surface))
    {
      return false;
    }
    this->Repaired = true;
    return true;
  }
  if (!build(input))
  {
    return false;
  }
  if (mode != AUTO)
  {
    mesh.FreeEdgeNeighbours(); // only the check reads them
    this->Messages = mesh.Warnings();
    return true;
  }
  vtkMedialSolidCheck check;
  check.Run(mesh, query, threads);
  mesh.FreeEdgeNeighbours(); // read by the check only: 12 bytes a triangle off the peak
  auto sayKeptPinches = [&]() {
    if (check.PinchedVertices > 0)
    {
      // Not repaired: a split point is the same point to the preparation, which merges
      // equal points, and the balls are the same; said, since the medial mesh's topology
      // is then the inside's (open there), not the one the surface gives.
      this->Messages.push_back(check.PinchedClause() +
        ": kept (vtkMedialRepairFilter splits it in its output); the solid's inside is open there");
    }
  };
  if (check.IsValid())
  {
    this->Messages = mesh.Warnings();
    sayKeptPinches();
    return true;
  }
  if (aborted && aborted())
  {
    error = "aborted";
    return false;
  }
  Repair result;
  Checked checked;
  checked.Mesh = &mesh;
  checked.Query = &query;
  checked.Check = &check;
  if (!runRepair(false, checked, result))
  {
    return false;
  }
  if (!result.Changed)
  {
    // A valid solid to the filters after all: the mesh already built is the one. The
    // repair's lines, when it has any, say why (shells that only touch) instead of the
    // mesh's warnings. The check counts pinches only where it searched pairs.
    if (result.Messages.empty())
    {
      this->Messages = mesh.Warnings();
    }
    if (!check.PairsSearched)
    {
      check.CountPinches(mesh);
    }
    sayKeptPinches();
    this->Report = nullptr;
    return true;
  }
  this->Repaired = true;
  return build(result.Surface);
}
