// SPDX-License-Identifier: BSD-3-Clause
// Bad input to vtkMedialBallClassifier gets a clear error (or warning) and no crash:
// no surface, balls without a Radius array or with a 3-component one, an empty or a
// NaN surface; an open surface only warns; no balls give empty outputs without error.
#include "MedialStructureTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkMedialShapeSource.h"

#include <limits>

using namespace medialtest;

namespace
{
vtkSmartPointer<vtkPolyData> OneBall(const char* radiusName, int components)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(radiusName);
  radius->SetNumberOfComponents(components);
  radius->SetNumberOfTuples(1);
  radius->Fill(0.5);
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(radius);
  return pd;
}

struct Outcome
{
  int Ok;
  int Errors;
  int Warnings;
  std::string Text;
  vtkIdType Points;
};

Outcome Run(vtkPolyData* balls, vtkPolyData* surface)
{
  EventLog log;
  vtkNew<vtkMedialBallClassifier> classifier;
  log.Watch(classifier);
  classifier->SetInputData(balls);
  if (surface)
  {
    classifier->SetSurfaceData(surface);
  }
  const int ok = classifier->GetExecutive()->Update();
  const vtkIdType points = ok ? classifier->GetOutput()->GetNumberOfPoints() : 0;
  return { ok, log.Errors, log.Warnings, log.Text, points };
}
}

int TestMedialClassifierBadInput(int, char*[])
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShapeToBox();
  source->Update();
  vtkPolyData* box = source->GetOutput();

  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Balls;
    vtkSmartPointer<vtkPolyData> Surface;
    const char* Expected; // substring of the error; empty: must succeed
  };
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  auto nanSurface = vtkSmartPointer<vtkPolyData>::New();
  nanSurface->DeepCopy(box);
  nanSurface->GetPoints()->SetPoint(0, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  std::vector<Case> cases = {
    { "no surface", OneBall("Radius", 1), nullptr, "Input port 1" },
    { "no Radius", OneBall("Size", 1), box, "Radius" },
    { "Radius with 3 components", OneBall("Radius", 3), box, "Radius" },
    { "empty surface", OneBall("Radius", 1), empty, "Cannot classify" },
    { "NaN surface", OneBall("Radius", 1), nanSurface, "Cannot classify" },
  };
  for (const Case& c : cases)
  {
    const Outcome o = Run(c.Balls, c.Surface);
    const size_t from = o.Text.find(c.Expected);
    std::printf("%s: update %d, %d error(s): %s\n", c.Name, o.Ok, o.Errors,
      from == std::string::npos ? "(message not found)" : c.Expected);
    MEDIAL_CHECK(!o.Ok && o.Errors >= 1 && from != std::string::npos, "%s: no clear error", c.Name);
  }

  // No balls: empty outputs, no error.
  auto noBalls = vtkSmartPointer<vtkPolyData>::New();
  noBalls->SetPoints(vtkSmartPointer<vtkPoints>::New());
  const Outcome none = Run(noBalls, box);
  MEDIAL_CHECK(none.Ok && none.Errors == 0 && none.Points == 0, "no balls: update %d, %d errors", none.Ok, none.Errors);

  // An open surface (one face removed): a warning, and the balls are still classified.
  auto open = vtkSmartPointer<vtkPolyData>::New();
  open->SetPoints(box->GetPoints());
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 1; c < box->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    box->GetCellPoints(c, npts, pts);
    polys->InsertNextCell(npts, pts);
  }
  open->SetPolys(polys);
  const Outcome warned = Run(OneBall("Radius", 1), open);
  std::printf("open surface: update %d, %d warning(s)\n", warned.Ok, warned.Warnings);
  MEDIAL_CHECK(warned.Ok && warned.Errors == 0 && warned.Warnings >= 1 && warned.Points == 1,
    "open surface: update %d, %d errors, %d warnings", warned.Ok, warned.Errors, warned.Warnings);
  return EXIT_SUCCESS;
}
