// SPDX-License-Identifier: BSD-3-Clause
// Bad input gets a clear error and a failed update, never a crash: no points, no
// Radius array, NaN, infinite or negative radii, NaN centres, a 3-component Radius,
// a union with no extent, 2D requested for centres that are not in one plane.
#include "MedialBallUnionTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkMedialBallUnion.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialBallUnionBadInput(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    const char* Expected; // substring of the error
    int Dimension;
  };
  std::vector<Case> cases;
  cases.push_back({ "no points", vtkSmartPointer<vtkPolyData>::New(), "no points", 0 });
  {
    auto noRadius = MakeBalls({ { 0, 0, 0, 1 } });
    noRadius->GetPointData()->RemoveArray("Radius");
    cases.push_back({ "no Radius", noRadius, "'Radius'", 0 });
  }
  {
    auto vectorRadius = MakeBalls({ { 0, 0, 0, 1 } });
    vtkNew<vtkDoubleArray> r;
    r->SetName("Radius");
    r->SetNumberOfComponents(3);
    r->InsertNextTuple3(1, 1, 1);
    vectorRadius->GetPointData()->AddArray(r);
    cases.push_back({ "3-component Radius", vectorRadius, "components", 0 });
  }
  cases.push_back({ "NaN radius", MakeBalls({ { 0, 0, 0, 1 }, { 1, 0, 0, nan } }), "NaN", 0 });
  cases.push_back({ "infinite radius", MakeBalls({ { 0, 0, 0, HUGE_VAL } }), "infinite", 0 });
  cases.push_back({ "negative radius", MakeBalls({ { 0, 0, 0, 1 }, { 1, 0, 0, -0.5 } }), "negative", 0 });
  cases.push_back({ "NaN centre", MakeBalls({ { 0, nan, 0, 1 } }), "coordinates", 0 });
  cases.push_back({ "no extent", MakeBalls({ { 1, 2, 3, 0 }, { 1, 2, 3, 0 } }), "no extent", 0 });
  cases.push_back({ "2D not planar",
    MakeBalls({ { 0, 0, 0, 1 }, { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 } }), "one plane",
    vtkMedialBallUnion::DIMENSION_2D });

  for (const Case& c : cases)
  {
    EventLog log;
    vtkNew<vtkMedialBallUnion> ballUnion;
    log.Watch(ballUnion);
    ballUnion->SetInputData(c.Input);
    ballUnion->SetDimension(c.Dimension);
    ballUnion->SetSampleDimensions(16, 16, 16);
    const int ok = ballUnion->GetExecutive()->Update();
    // Print the filter's own message only: ctest fails on lines starting "ERROR: ".
    const size_t from = log.Text.find("Cannot build");
    const std::string message = log.Text.substr(from == std::string::npos ? 0 : from);
    std::printf("%s: update %d, %d error(s): %s\n", c.Name, ok, log.Errors,
      message.substr(0, message.find('\n')).c_str());
    MEDIAL_CHECK(!ok && log.Errors >= 1, "%s: no error reported", c.Name);
    MEDIAL_CHECK(log.Text.find(c.Expected) != std::string::npos, "%s: message lacks '%s'", c.Name, c.Expected);
    MEDIAL_CHECK(ballUnion->GetOutput()->GetNumberOfPoints() == 0, "%s: output not empty", c.Name);
  }

  // A grid too large for MaximumNumberOfVoxels is refused; zero radii beside a real
  // ball are fine (points of the union).
  {
    EventLog log;
    vtkNew<vtkMedialBallUnion> ballUnion;
    log.Watch(ballUnion);
    ballUnion->SetInputData(MakeBalls({ { 0, 0, 0, 1 } }));
    ballUnion->SetMaximumNumberOfVoxels(1000);
    const int ok = ballUnion->GetExecutive()->Update();
    MEDIAL_CHECK(!ok && log.Text.find("MaximumNumberOfVoxels") != std::string::npos, "voxel cap not enforced");
  }
  {
    EventLog log;
    vtkNew<vtkMedialBallUnion> ballUnion;
    log.Watch(ballUnion);
    ballUnion->SetInputData(MakeBalls({ { 0, 0, 0, 1 }, { 3, 0, 0, 0 } }));
    ballUnion->SetSampleDimensions(32, 16, 16);
    ballUnion->Update();
    MEDIAL_CHECK(log.Errors == 0 && ballUnion->GetOutput()->GetNumberOfPoints() > 0, "zero radius rejected");
  }
  return EXIT_SUCCESS;
}
