// SPDX-License-Identifier: BSD-3-Clause
// Generated defects whose solid is known (Testing/Cxx/MedialDefectTestUtilities.h), 20k
// samples each (at 10k the medial mesh of the repaired overlapping spheres has one void
// too many, a density limit of the medial mesh, not of the repair): a
// shell crossing itself, two overlapping spheres, a sphere with holes, a jittered soup,
// a torus with a fifth of its triangles turned over, a sphere with a stray sheet, a
// solid inside a cavity (a valid solid: untouched), two cubes sharing an edge and a box
// with windows too large for the hole filler (filled all the same: nothing is closed). With
// the repair (RepairMode AUTO, the default) the sampler discards no sample, every ball
// lies inside the true solid and none is stopped short of it (by a buried surface or a
// sheet), the largest ball is the true one within 1%, and the medial mesh has the
// solid's Euler characteristic. The repair's report names the step each defect needs.
// The filters' repair, which starts from the mesh, tree and check their preparation
// made (vtkMedialRepairFilter::SetCheckedInput), must give the surface the repair alone
// gives: the same points and triangles in the same order, bit for bit, on every defect
// (the union and the autorefinement included; TestMedialRepairRepeat repeats them).
// Run with the argument "none" the same checks run without the repair (RepairMode
// NONE) and fail: that is how the test shows it can fail.
#include "MedialRepairTestUtilities.h"
#include "MedialTestSupport.h"

#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPoints.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
// The step of the report each defect must show (empty: none, the input is valid).
const char* ExpectedStep(const std::string& name)
{
  if (name == "crossing shell")
  {
    return "self-intersections:";
  }
  if (name == "overlapping spheres")
  {
    return "union:";
  }
  if (name == "sphere with holes")
  {
    return "holes:";
  }
  if (name == "jittered soup")
  {
    return "weld:";
  }
  if (name == "flipped torus")
  {
    return "orient:";
  }
  if (name == "sphere with a sheet")
  {
    return "sheets:";
  }
  if (name == "cubes sharing an edge" || name == "cubes sharing a vertex")
  {
    return "touch:";
  }
  if (name == "box with windows")
  {
    return "holes:";
  }
  return "";
}

bool HasLine(vtkMedialRepairFilter* repair, const char* prefix)
{
  for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
  {
    if (std::strncmp(repair->GetReportLine(i), prefix, std::strlen(prefix)) == 0)
    {
      return true;
    }
  }
  return false;
}

// The repair of `surface` started from a preparation made outside (as a filter's is).
// The repair as a filter's preparation asks it, from the preparation's mesh, tree and
// check. `changed`: whether it says the preparation must prepare its output.
vtkSmartPointer<vtkPolyData> RepairFromChecked(vtkPolyData* surface, bool& changed)
{
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  if (!mesh.Build(surface, error) || !query.Build(&mesh, error))
  {
    return nullptr;
  }
  vtkMedialSolidCheck check;
  check.Run(mesh, query, 2);
  vtkNew<vtkMedialRepairFilter> repair;
  repair->SetInputData(surface);
  repair->SetReportSteps(false);
  repair->SetCheckedInput(&mesh, &query, &check);
  repair->Update();
  repair->ClearCheckedInput();
  changed = repair->GetChanged();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(repair->GetOutput());
  return out;
}

// The surface's points and triangles in their order, as numbers: the same bits for the
// same surface made the same way.
std::vector<double> Numbers(vtkPolyData* pd)
{
  std::vector<double> all;
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    all.insert(all.end(), x, x + 3);
  }
  vtkIdType n = 0;
  const vtkIdType* p = nullptr;
  auto cells = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(n, p);
    all.push_back(static_cast<double>(n));
    for (vtkIdType k = 0; k < n; ++k)
    {
      all.push_back(static_cast<double>(p[k]));
    }
  }
  return all;
}

bool SameSurface(vtkPolyData* a, vtkPolyData* b)
{
  return a && b && a->GetNumberOfPolys() > 0 && a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    Numbers(a) == Numbers(b);
}

// The mesh a filter's preparation makes of the surface (merged, oriented), as its
// oriented triangles by their corners' coordinates, each turned to start at its lowest
// corner, sorted: the same for the same solid whatever the point and triangle order.
std::vector<std::array<double, 9>> PreparedTriangles(vtkPolyData* pd)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  std::vector<std::array<double, 9>> all;
  if (!pd || !mesh.Build(pd, error))
  {
    return all;
  }
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    std::array<std::array<double, 3>, 3> c;
    for (int k = 0; k < 3; ++k)
    {
      std::copy_n(mesh.GetPoint(mesh.GetTriangle(t)[k]), 3, c[k].begin());
    }
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    std::array<double, 9> flat;
    for (int k = 0; k < 3; ++k)
    {
      std::copy_n(c[k].begin(), 3, flat.begin() + 3 * k);
    }
    all.push_back(flat);
  }
  std::sort(all.begin(), all.end());
  return all;
}
}

int TestMedialRepairDefects(int argc, char* argv[])
{
  const bool none = argc > 1 && std::string(argv[argc - 1]) == "none";
  const int mode = none ? vtkMedialRepairFilter::NONE : vtkMedialRepairFilter::AUTO;
  int failures = 0;
  for (const medialtest::Defect& d : medialtest::GeneratedDefects())
  {
    // The repair alone: its report.
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(d.Surface);
    repair->SetReportSteps(false);
    repair->Update();
    std::string report;
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      report += std::string(i ? "; " : "") + repair->GetReportLine(i);
    }
    const medialtest::DefectResult r = medialtest::MeasureDefect(d, mode);
    std::printf("%-22s balls %lld discarded %lld largest %.4f (true %.4f) outside %lld (worst %.3g) short %lld "
                "(worst %.3g) euler %lld (true %d) components %lld | %s\n",
      d.Name.c_str(), static_cast<long long>(r.Balls), static_cast<long long>(r.Discarded), r.LargestBall,
      d.LargestBall, static_cast<long long>(r.Outside), r.WorstOutside, static_cast<long long>(r.Short),
      r.WorstShort, static_cast<long long>(r.Euler), d.Euler, static_cast<long long>(r.Components),
      report.empty() ? "(valid solid: untouched)" : report.c_str());
    auto fail = [&](const char* what) {
      std::printf("  FAILED %s: %s\n", d.Name.c_str(), what);
      ++failures;
    };
    if (d.Clean != repair->GetInputWasValid())
    {
      fail(d.Clean ? "a valid solid was not passed through" : "a defect was taken for a valid solid");
    }
    if (d.Clean && repair->GetOutput()->GetPoints() != d.Surface->GetPoints())
    {
      fail("a valid solid's output is not the input itself");
    }
    const char* step = ExpectedStep(d.Name);
    if (*step && !HasLine(repair, step))
    {
      fail("the report does not show the step the defect needs");
    }
    if (repair->GetWrapped())
    {
      fail("the repair fell back to the wrap");
    }
    if (r.Discarded != 0)
    {
      fail("samples were discarded");
    }
    if (r.Outside != 0)
    {
      fail("balls cross the true solid's boundary");
    }
    if (r.Short != 0)
    {
      fail("balls are smaller than the true solid allows (stopped by a surface inside it)");
    }
    if (std::fabs(r.LargestBall - d.LargestBall) > 0.01 * d.LargestBall + d.Tolerance)
    {
      fail("the largest ball is not the true one within 1%");
    }
    if (r.Euler != d.Euler)
    {
      fail("the medial mesh's Euler characteristic is not the solid's");
    }
    // From a filter's preparation: the repair alone's surface, or, where that differs from
    // the input only in what the preparation does anyway (winding, a split pinch), the
    // input unchanged, which the preparation keeps.
    bool changed = true;
    const vtkSmartPointer<vtkPolyData> fromChecked = none ? nullptr : RepairFromChecked(d.Surface, changed);
    if (!none && changed && !SameSurface(fromChecked, repair->GetOutput()))
    {
      fail("the repair started from a filter's preparation differs from the repair alone");
    }
    if (!none && !changed &&
      (!fromChecked || fromChecked->GetPoints() != d.Surface->GetPoints() ||
        PreparedTriangles(d.Surface) != PreparedTriangles(repair->GetOutput())))
    {
      fail("the preparation keeps an input whose repair it would prepare into another mesh");
    }
    if (!none && !changed)
    {
      std::printf("  kept by a filter's preparation: the repair alone's surface prepares into the same triangles\n");
    }
  }
  std::printf("%d failures%s\n", failures, none ? " (without the repair, as expected)" : "");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
