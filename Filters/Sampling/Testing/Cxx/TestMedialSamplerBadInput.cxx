// SPDX-License-Identifier: BSD-3-Clause
// Bad input built in memory gets a clear error and an empty output, never a crash:
// empty input, zero area, a triangle on one point. The cases read from files (NaN and
// Inf coordinates, lines only, degenerate and duplicate triangles, zero samples, ...)
// are rows of Testing/BadInput/cases.tsv.
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkPoints.h"

#include "vtkExecutive.h"
#include <array>
#include <cstdlib>

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

  return EXIT_SUCCESS;
}
