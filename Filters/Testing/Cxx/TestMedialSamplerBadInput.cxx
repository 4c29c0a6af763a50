// SPDX-License-Identifier: BSD-3-Clause
// Bad input gets a clear error and an empty output, never a crash: empty input,
// NaN coordinates, lines only, zero area. Degenerate triangles mixed into a good
// mesh are tolerated. Zero samples give an empty output without error.
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkPoints.h"

#include "vtkExecutive.h"
#include <array>
#include <cstdlib>
#include <functional>
#include <limits>

using namespace medialtest;

namespace
{
vtkSmartPointer<vtkPolyData> Triangles(const std::vector<std::array<double, 3>>& pts,
  const std::vector<std::array<vtkIdType, 3>>& tris)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const auto& p : pts)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : tris)
  {
    cells->InsertNextCell(3, t.data());
  }
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}
}

int TestMedialSamplerBadInput(int, char*[])
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    const char* Expected; // substring of the error
  };
  std::vector<Case> cases;
  cases.push_back({ "empty", vtkSmartPointer<vtkPolyData>::New(), "no points" });
  const double nan = std::numeric_limits<double>::quiet_NaN();
  cases.push_back({ "NaN", Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, nan, 0 }, { 0, 0, 1 } },
                             { { 0, 1, 2 }, { 0, 1, 3 } }),
    "NaN" });
  cases.push_back({ "infinite", Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, HUGE_VAL, 0 } }, { { 0, 1, 2 } }), "NaN or infinite" });
  {
    auto lines = Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, {});
    vtkNew<vtkCellArray> l;
    const vtkIdType seg[2] = { 0, 1 };
    l->InsertNextCell(2, seg);
    lines->SetLines(l);
    cases.push_back({ "lines only", lines, "no polygons" });
  }
  cases.push_back({ "zero area", Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } },
                                   { { 0, 1, 2 }, { 1, 2, 3 } }),
    "no area" });
  cases.push_back({ "single point triangle", Triangles({ { 1, 1, 1 } }, { { 0, 0, 0 } }), "no" });

  for (const Case& c : cases)
  {
    EventLog log;
    vtkNew<vtkMedialAxisSampler> sampler;
    log.Watch(sampler);
    sampler->SetInputData(c.Input);
    sampler->SetNumberOfSamples(100);
    const int ok = sampler->GetExecutive()->Update();
    // Print the filter's own message only: ctest fails on lines starting "ERROR: ".
    const size_t from = log.Text.find("Cannot sample");
    const std::string message = log.Text.substr(from == std::string::npos ? 0 : from);
    std::printf("%s: update %d, %d error(s): %s\n", c.Name, ok, log.Errors,
      message.substr(0, message.find('\n')).c_str());
    MEDIAL_CHECK(!ok && log.Errors >= 1, "%s: no error reported", c.Name);
    MEDIAL_CHECK(log.Text.find(c.Expected) != std::string::npos, "%s: message lacks '%s'", c.Name, c.Expected);
    MEDIAL_CHECK(sampler->GetOutput()->GetNumberOfPoints() == 0, "%s: output not empty", c.Name);
  }

  // Degenerate triangles inside a good closed mesh: tolerated, never sampled.
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(3);
  sphere->Update();
  vtkNew<vtkPolyData> withDegenerate;
  withDegenerate->DeepCopy(sphere->GetOutput());
  const vtkIdType sliver[3] = { 0, 0, 1 }, collinear[3] = { 0, 1, 1 };
  withDegenerate->GetPolys()->InsertNextCell(3, sliver);
  withDegenerate->GetPolys()->InsertNextCell(3, collinear);
  {
    EventLog log;
    vtkNew<vtkMedialAxisSampler> sampler;
    log.Watch(sampler);
    sampler->SetInputData(withDegenerate);
    sampler->SetNumberOfSamples(500);
    sampler->Update();
    std::printf("degenerate triangles: %d errors, %lld points\n", log.Errors,
      static_cast<long long>(sampler->GetOutput()->GetNumberOfPoints()));
    MEDIAL_CHECK(log.Errors == 0 && sampler->GetOutput()->GetNumberOfPoints() == 500, "degenerate case");
  }
  {
    EventLog log;
    vtkNew<vtkMedialAxisSampler> sampler;
    log.Watch(sampler);
    sampler->SetInputData(sphere->GetOutput());
    sampler->SetNumberOfSamples(0);
    sampler->Update();
    MEDIAL_CHECK(log.Errors == 0 && sampler->GetOutput()->GetNumberOfPoints() == 0, "zero samples");
  }
  return EXIT_SUCCESS;
}
