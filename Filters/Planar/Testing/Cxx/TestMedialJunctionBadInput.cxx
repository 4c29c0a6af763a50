// SPDX-License-Identifier: BSD-3-Clause
// Bad 2D input gets a clear error and an empty output from both 2D filters: open
// polyline, self-intersecting loop, loops crossing each other, non-coplanar loop,
// fewer than 3 distinct vertices. (Loops outside each other are several polygons:
// TestMedialJunctionPolygons.)
#include "MedialPolygonTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialJunctionFilter.h"

#include <cstdio>
#include <cstdlib>
#include <functional>

using namespace medialtest;

int TestMedialJunctionBadInput(int, char*[])
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    const char* Expected; // substring of the error
  };
  std::vector<Case> cases;
  cases.push_back({ "open polyline", MakePolylines({ { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } } }), "open polyline" });
  cases.push_back({ "bow tie", MakePolygon({ { { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } } }), "intersect" });
  cases.push_back({ "crossing loops", MakePolygon({ Rectangle(0, 0, 4, 4), Rectangle(3, 1, 5, 2) }), "intersect" });
  cases.push_back({ "touching hole", MakePolygon({ Rectangle(0, 0, 4, 4), Rectangle(1, 1, 4, 2) }), "intersect" });
  cases.push_back({ "not coplanar",
    MakePolylines({ { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.3 }, { 0, 1, 0 }, { 0, 0, 0 } } }), "not coplanar" });
  cases.push_back({ "two vertices", MakePolygon({ { { 0, 0 }, { 1, 0 } } }), "fewer than 3" });
  cases.push_back({ "repeated points", MakePolygon({ { { 0, 0 }, { 1, 0 }, { 1, 0 }, { 0, 0 } } }), "fewer than 3" });
  cases.push_back({ "collinear", MakePolygon({ { { 0, 0 }, { 1, 0 }, { 2, 0 } } }), "" });
  cases.push_back({ "empty", vtkSmartPointer<vtkPolyData>::New(), "no points" });

  for (const Case& c : cases)
  {
    for (int which = 0; which < 2; ++which)
    {
      EventLog log;
      vtkSmartPointer<vtkPolyDataAlgorithm> filter;
      if (which == 0)
      {
        filter = vtkSmartPointer<vtkMedialJunctionFilter>::New();
      }
      else
      {
        auto sampler = vtkSmartPointer<vtkMedialAxisSampler>::New();
        sampler->SetNumberOfSamples(50);
        filter = sampler;
      }
      log.Watch(filter);
      filter->SetInputData(c.Input);
      const int ok = filter->GetExecutive()->Update();
      // Print the filter's own message only: ctest fails on lines starting "ERROR: ".
      size_t from = log.Text.find("Cannot ");
      const std::string message = log.Text.substr(from == std::string::npos ? 0 : from);
      std::printf("%s / %s: update %d, %d error(s): %s\n", c.Name, filter->GetClassName(), ok, log.Errors,
        message.substr(0, message.find('\n')).c_str());
      MEDIAL_CHECK(!ok && log.Errors >= 1, "%s: no error reported", c.Name);
      MEDIAL_CHECK(which == 1 || log.Text.find(c.Expected) != std::string::npos, "%s: message lacks '%s'",
        c.Name, c.Expected);
      MEDIAL_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0, "%s: output not empty", c.Name);
    }
  }
  return EXIT_SUCCESS;
}
