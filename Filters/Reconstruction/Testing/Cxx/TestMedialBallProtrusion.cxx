// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialBallProtrusion on balls in a cube and disks in a square, where every
// protrusion has a closed form; the radius array chosen with SetInputArrayToProcess;
// no balls; balls without radii.
#include "MedialTestSupport.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialShapeSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <vector>

using medialtest::EventLog;

namespace
{
vtkSmartPointer<vtkPolyData> Balls(const std::vector<std::array<double, 4>>& balls, const char* name)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(name);
  for (const auto& b : balls)
  {
    points->InsertNextPoint(b[0], b[1], b[2]);
    radius->InsertNextValue(b[3]);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(radius);
  return pd;
}
}

int TestMedialBallProtrusion(int, char*[])
{
  // The cube [-1, 1]^3: a ball at x = 0.5 is 0.5 from the surface.
  vtkNew<vtkMedialShapeSource> cube;
  cube->SetShapeToBox();
  cube->SetBoxLengths(2, 2, 2);
  cube->SetResolution(4);
  const std::vector<std::array<double, 4>> balls = { { 0, 0, 0, 0.5 }, { 0.5, 0, 0, 0.7 }, { 0, 0.9, 0, 0.1 } };
  const double expected[3] = { -0.5, 0.2, 0.0 };
  const double diagonal = 2 * std::sqrt(3.0);
  {
    vtkNew<vtkMedialBallProtrusion> protrusion;
    protrusion->SetSurfaceConnection(cube->GetOutputPort());
    protrusion->SetBallsData(Balls(balls, vtkMedialArrayNames::Radius));
    protrusion->Update();
    vtkDataArray* values = protrusion->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::Protrusion);
    vtkDataArray* largest = protrusion->GetOutput()->GetFieldData()->GetArray(vtkMedialArrayNames::MaxProtrusion);
    MEDIAL_CHECK(values && values->GetNumberOfTuples() == 3, "no Protrusion array");
    for (int i = 0; i < 3; ++i)
    {
      std::printf("ball %d: protrusion %.12g, expected %g\n", i, values->GetTuple1(i), expected[i]);
      MEDIAL_CHECK(std::fabs(values->GetTuple1(i) - expected[i]) <= 1e-12, "ball %d", i);
    }
    MEDIAL_CHECK(std::fabs(protrusion->GetMaxProtrusion() - 0.2 / diagonal) <= 1e-12, "max protrusion %g",
      protrusion->GetMaxProtrusion());
    MEDIAL_CHECK(largest && largest->GetTuple1(0) == protrusion->GetMaxProtrusion(), "MaxProtrusion field data");
  }
  // Another radius array, chosen by name; balls that stay inside give 0.
  {
    vtkNew<vtkMedialBallProtrusion> protrusion;
    protrusion->SetSurfaceConnection(cube->GetOutputPort());
    protrusion->SetBallsData(Balls({ { 0, 0, 0, 0.5 } }, "Size"));
    protrusion->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Size");
    protrusion->Update();
    MEDIAL_CHECK(protrusion->GetMaxProtrusion() == 0.0, "inside balls: %g", protrusion->GetMaxProtrusion());
  }
  // 2D: disks in the square [-1, 1]^2 (a polygon): distances to its edges.
  {
    vtkNew<vtkMedialShapeSource> square;
    square->SetShapeToRectangle();
    square->Update();
    double bounds[6];
    square->GetOutput()->GetBounds(bounds);
    const double cx = 0.5 * (bounds[0] + bounds[1]), cy = 0.5 * (bounds[2] + bounds[3]);
    const double halfHeight = 0.5 * (bounds[3] - bounds[2]);
    vtkNew<vtkMedialBallProtrusion> protrusion;
    protrusion->SetSurfaceConnection(square->GetOutputPort());
    protrusion->SetBallsData(Balls({ { cx, cy, 0, halfHeight + 0.25 } }, vtkMedialArrayNames::Radius));
    protrusion->Update();
    const double p = protrusion->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::Protrusion)->GetTuple1(0);
    std::printf("disk in the rectangle: protrusion %.12g, expected 0.25\n", p);
    MEDIAL_CHECK(std::fabs(p - 0.25) <= 1e-12, "2D protrusion %g", p);
  }
  // No balls: empty output, no error. Balls without a radius: an error.
  {
    vtkNew<vtkMedialBallProtrusion> protrusion;
    EventLog log;
    log.Watch(protrusion);
    protrusion->SetSurfaceConnection(cube->GetOutputPort());
    protrusion->SetBallsData(vtkSmartPointer<vtkPolyData>::New());
    MEDIAL_CHECK(protrusion->GetExecutive()->Update() == 1 && log.Errors == 0 && protrusion->GetMaxProtrusion() == 0,
      "no balls: %s", log.Text.c_str());
    protrusion->SetBallsData(Balls({ { 0, 0, 0, 0.5 } }, "Size"));
    MEDIAL_CHECK(protrusion->GetExecutive()->Update() == 0, "balls without Radius are accepted");
    std::printf("no radius: %s\n", log.LineWith("Cannot measure").c_str());
    MEDIAL_CHECK(log.LineWith("one radius per point (by default 'Radius')") != "", "%s", log.Text.c_str());
  }
  return EXIT_SUCCESS;
}
