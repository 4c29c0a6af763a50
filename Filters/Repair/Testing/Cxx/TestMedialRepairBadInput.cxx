// SPDX-License-Identifier: BSD-3-Clause
// Input with no volume gets a clear error that says why, or with WRAP a thin solid and
// a warning; never a crash, never a silent wrong answer. A flat sheet, a line soup, no
// points, a NaN coordinate; and through the filters that repair (the medial mesh, the
// thickness; the sampler takes a planar sheet in its 2D mode, as before). A curved open
// sheet (a bowl: a solid whose hole is too large to fill) is wrapped, with a warning.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialThickness.h"
#include "vtkMedialTriangleMesh.h"

namespace
{
using medialtest::defects::Point;

vtkSmartPointer<vtkPolyData> Grid(bool bowl)
{
  std::vector<Point> x;
  std::vector<std::array<vtkIdType, 3>> t;
  const int n = 12;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      const double u = -1.0 + 2.0 * i / n, v = -1.0 + 2.0 * j / n;
      x.push_back({ u, v, bowl ? 0.5 * (u * u + v * v) : 0.0 });
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const vtkIdType a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      t.push_back({ a, c, d });
      t.push_back({ a, d, b });
    }
  }
  return medialtest::defects::Mesh(x, t);
}

vtkSmartPointer<vtkPolyData> LineSoup()
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int i = 0; i < 40; ++i)
  {
    const double t = 0.3 * i;
    points->InsertNextPoint(std::cos(t), std::sin(t), 0.1 * t);
  }
  for (vtkIdType i = 0; i + 1 < 40; ++i)
  {
    const vtkIdType ids[2] = { i, i + 1 };
    lines->InsertNextCell(2, ids);
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  return pd;
}

// Runs the repair; returns its error text (empty when it succeeded).
std::string RepairError(vtkPolyData* input, int mode, vtkSmartPointer<vtkMedialRepairFilter>& repair,
  medialtest::EventLog& log)
{
  repair = vtkSmartPointer<vtkMedialRepairFilter>::New();
  log.Watch(repair);
  repair->SetInputData(input);
  repair->SetMode(mode);
  repair->Update();
  return log.Errors > 0 ? log.LineWith("Cannot repair") : std::string();
}
}

int TestMedialRepairBadInput(int, char*[])
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    const char* Why; // the error must say this
    bool Wraps;      // WRAP makes a solid of it
  };
  vtkNew<vtkPolyData> empty;
  auto nan = medialtest::defects::Shape(vtkMedialShapeSource::SPHERE, 2);
  nan->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  const std::vector<Case> cases = {
    { "flat sheet", Grid(false), "bounds no volume", true },
    { "line soup", LineSoup(), "no polygons", true },
    { "no points", empty.Get(), "no points", false },
    { "NaN coordinate", nan, "NaN", false },
  };
  for (const Case& c : cases)
  {
    medialtest::EventLog log;
    vtkSmartPointer<vtkMedialRepairFilter> repair;
    const std::string error = RepairError(c.Input, vtkMedialRepairFilter::AUTO, repair, log);
    std::printf("%-15s AUTO: %s\n", c.Name, error.c_str());
    MEDIAL_CHECK(!error.empty() && error.find(c.Why) != std::string::npos, "%s: no clear error ('%s')", c.Name,
      error.c_str());
    MEDIAL_CHECK(repair->GetOutput()->GetNumberOfCells() == 0, "%s: an output despite the error", c.Name);
    if (!c.Wraps)
    {
      continue;
    }
    MEDIAL_CHECK(error.find("WRAP") != std::string::npos, "%s: the error does not say how to wrap", c.Name);
    medialtest::EventLog wrapLog;
    const std::string wrapError = RepairError(c.Input, vtkMedialRepairFilter::WRAP, repair, wrapLog);
    MEDIAL_CHECK(wrapError.empty() && repair->GetWrapped(), "%s: WRAP failed: %s", c.Name, wrapError.c_str());
    MEDIAL_CHECK(wrapLog.Warnings > 0 && !wrapLog.LineWith("wrap").empty(), "%s: WRAP says nothing", c.Name);
    vtkMedialTriangleMesh mesh;
    std::string meshError;
    MEDIAL_CHECK(mesh.Build(repair->GetOutput(), meshError) && mesh.BoundaryEdges == 0 &&
        mesh.NonManifoldEdges == 0 && mesh.Volume > 0.0,
      "%s: the wrap is not a closed solid", c.Name);
    std::printf("%-15s WRAP: a thin solid of %lld triangles, volume %.3g\n", c.Name,
      static_cast<long long>(mesh.GetNumberOfTriangles()), mesh.Volume);
  }
  // A bowl: wrapped in AUTO, with the warning that says so.
  {
    medialtest::EventLog log;
    vtkSmartPointer<vtkMedialRepairFilter> repair;
    const std::string error = RepairError(Grid(true), vtkMedialRepairFilter::AUTO, repair, log);
    MEDIAL_CHECK(error.empty() && repair->GetWrapped() && !log.LineWith("nothing closed was left").empty(),
      "the bowl is not wrapped with a warning: %s", log.Text.c_str());
  }
  // Two parallel squares: nothing closed and no hole either, so the warning must not
  // blame holes too large to fill.
  {
    auto square = Grid(false);
    auto both = medialtest::defects::Append(square, medialtest::defects::Translated(square, 0, 0, 1));
    medialtest::EventLog log;
    vtkSmartPointer<vtkMedialRepairFilter> repair;
    const std::string error = RepairError(both, vtkMedialRepairFilter::AUTO, repair, log);
    const std::string line = log.LineWith("nothing closed was left");
    MEDIAL_CHECK(error.empty() && repair->GetWrapped() && !line.empty() &&
        line.find("holes too large") == std::string::npos && line.find("bound no volume") != std::string::npos,
      "two parallel squares: '%s'", log.Text.c_str());
  }
  // Through the filters: the medial mesh and the thickness refuse a flat sheet with the
  // same reason; the sampler samples a planar sheet in 2D (as before) and, with WRAP,
  // the wrap of a bowl.
  {
    medialtest::EventLog log;
    vtkNew<vtkMedialMeshFilter> mesh;
    log.Watch(mesh);
    mesh->SetInputData(Grid(false));
    mesh->Update();
    MEDIAL_CHECK(!log.LineWith("bounds no volume").empty(), "the medial mesh does not say why: %s", log.Text.c_str());
  }
  {
    medialtest::EventLog log;
    vtkNew<vtkMedialThickness> thickness;
    log.Watch(thickness);
    thickness->SetInputData(Grid(false));
    thickness->Update();
    MEDIAL_CHECK(!log.LineWith("bounds no volume").empty(), "the thickness does not say why: %s", log.Text.c_str());
  }
  {
    medialtest::EventLog log;
    vtkNew<vtkMedialAxisSampler> sampler;
    log.Watch(sampler);
    sampler->SetInputData(Grid(true));
    sampler->SetNumberOfSamples(500);
    sampler->SetRepairMode(vtkMedialRepairFilter::WRAP);
    sampler->Update();
    MEDIAL_CHECK(log.Errors == 0 && sampler->GetSurfaceRepaired() && sampler->GetOutput()->GetNumberOfPoints() > 0 &&
        sampler->GetDiscardedSamples() == 0,
      "the sampler does not sample a wrapped bowl: %s", log.Text.c_str());
  }
  return EXIT_SUCCESS;
}
