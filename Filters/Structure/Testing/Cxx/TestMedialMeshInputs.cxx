// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialMeshFilter's inputs and outputs: balls on port 1 give the same mesh as the
// internal sampler with the same settings; any thread count gives the same mesh; the
// sampler's settings take effect and re-execute the filter; the balls' arrays are
// carried over (Radius never grows; the other vertices are the classifier's exact
// seam and junction balls); cell types match the cells; and bad input gives
// one clear error (or a warning for an open surface or balls outside the shape).
#include "MedialMeshTestUtilities.h"

#include "vtkMedialRepairFilter.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace
{
// Same points, radii and cells, bit for bit.

vtkSmartPointer<vtkPolyData> BallsOf(const std::vector<std::array<double, 4>>& list)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  for (const auto& b : list)
  {
    points->InsertNextPoint(b[0], b[1], b[2]);
    radius->InsertNextValue(b[3]);
  }
  auto balls = vtkSmartPointer<vtkPolyData>::New();
  balls->SetPoints(points);
  balls->GetPointData()->AddArray(radius);
  return balls;
}

// Runs the filter on (surface, balls) and returns the log. The surfaces are taken as they
// are (RepairMode NONE): these are the messages about them.
std::string Run(vtkPolyData* surface, vtkPolyData* balls, int& errors, int& warnings)
{
  vtkNew<vtkMedialMeshFilter> filter;
  medialtest::EventLog log;
  log.Watch(filter);
  filter->SetInputData(surface);
  filter->SetRepairMode(vtkMedialRepairFilter::NONE);
  if (balls)
  {
    filter->SetBallsData(balls);
  }
  filter->Update();
  errors = log.Errors;
  warnings = log.Warnings;
  return log.Text;
}

int CheckBadInput(vtkPolyData* solid)
{
  struct Case
  {
    const char* What;
    vtkSmartPointer<vtkPolyData> Surface, Balls;
    const char* Expected;
  };
  vtkNew<vtkPolyData> empty;
  auto noRadius = BallsOf({ { 0, 0, 0, 0.1 }, { 0.1, 0, 0, 0.1 }, { 0, 0.1, 0, 0.1 }, { 0, 0, 0.1, 0.1 } });
  noRadius->GetPointData()->RemoveArray(vtkMedialArrayNames::Radius);
  const Case cases[] = {
    { "empty surface", empty, nullptr, "input 0 has no surface" },
    { "no Radius", solid, noRadius, "no one-component point-data array named 'Radius'" },
    { "NaN radius",
      solid, BallsOf({ { 0, 0, 0, std::nan("") }, { 0.1, 0, 0, 0.1 }, { 0, 0.1, 0, 0.1 }, { 0, 0, 0.1, 0.1 } }),
      "NaN, infinite or negative" },
    { "three balls", solid, BallsOf({ { 0, 0, 0, 0.1 }, { 0.1, 0, 0, 0.1 }, { 0, 0.1, 0, 0.1 } }),
      "fewer than four balls" },
    { "coplanar balls",
      solid, BallsOf({ { 0, 0, 0, 0.1 }, { 0.1, 0, 0, 0.1 }, { 0, 0.1, 0, 0.1 }, { 0.1, 0.1, 0, 0.1 } }),
      "coplanar" },
  };
  for (const Case& c : cases)
  {
    int errors = 0, warnings = 0;
    const std::string text = Run(c.Surface, c.Balls, errors, warnings);
    MEDIAL_CHECK(errors >= 1 && text.find(c.Expected) != std::string::npos, "%s: got '%s'", c.What,
      text.c_str());
  }
  // Balls outside the shape are dropped with a warning; the rest is meshed.
  {
    int errors = 0, warnings = 0;
    const std::string text = Run(solid,
      BallsOf({ { 0, 0, 0, 0.3 }, { 0.2, 0, 0, 0.3 }, { 0, 0.1, 0.05, 0.3 }, { 0.1, 0.05, 0.1, 0.3 },
        { 9, 9, 9, 0.1 } }),
      errors, warnings);
    MEDIAL_CHECK(errors == 0 && text.find("1 ball(s) with a centre outside") != std::string::npos,
      "outside ball: got '%s'", text.c_str());
  }
  // An open surface: a warning, and a mesh all the same.
  {
    vtkNew<vtkPolyData> open;
    open->DeepCopy(solid);
    open->BuildCells();
    open->DeleteCell(0);
    open->RemoveDeletedCells();
    int errors = 0, warnings = 0;
    const std::string text = Run(open, nullptr, errors, warnings);
    MEDIAL_CHECK(errors == 0 && text.find("boundary edges") != std::string::npos, "open surface: got '%s'",
      text.c_str());
  }
  // Two overlapping spheres in one surface: no valid solid (their triangles intersect),
  // so the surface's topology (two bodies) is not the shape's. With balls in one of
  // them only, the mesh is one piece: the warning names the cause, and does not ask for
  // more samples.
  {
    vtkSmartPointer<vtkPolyData> a = medialtest::MakeSolid(vtkMedialShapeSource::SPHERE, 1, 2);
    vtkSmartPointer<vtkPolyData> b = medialtest::MakeSolid(vtkMedialShapeSource::SPHERE, 1, 2);
    vtkNew<vtkPoints> moved;
    moved->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
    {
      double x[3];
      b->GetPoint(i, x);
      moved->InsertNextPoint(x[0] + 0.8, x[1], x[2]);
    }
    b->SetPoints(moved);
    vtkNew<vtkAppendPolyData> both;
    both->AddInputData(a);
    both->AddInputData(b);
    both->Update();
    int errors = 0, warnings = 0;
    const std::string text = Run(both->GetOutput(),
      BallsOf({ { -0.6, 0, 0, 0.3 }, { -0.6, 0.2, 0, 0.3 }, { -0.6, 0, 0.2, 0.3 }, { -0.7, 0.1, 0.1, 0.2 },
        { -0.5, -0.1, -0.1, 0.3 } }),
      errors, warnings);
    MEDIAL_CHECK(errors == 0 && text.find("not a valid solid") != std::string::npos &&
        text.find("of its triangles intersect") != std::string::npos &&
        text.find("try more samples") == std::string::npos,
      "overlapping spheres: got '%s'", text.c_str());
  }
  return EXIT_SUCCESS;
}
}

int TestMedialMeshInputs(int, char*[])
{
  vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(vtkMedialShapeSource::JACK, 1, 12);

  // Port 1 versus the internal sampler with the same settings; 1 versus 2 threads.
  vtkNew<vtkMedialMeshFilter> internal;
  internal->SetInputData(solid);
  internal->GetSampler()->SetNumberOfSamples(3000);
  internal->GetSampler()->SetRandomSeed(7);
  internal->SetNumberOfThreads(1);
  internal->Update();
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(solid);
  sampler->SetNumberOfSamples(3000);
  sampler->SetRandomSeed(7);
  vtkNew<vtkMedialMeshFilter> external;
  external->SetInputData(solid);
  external->SetBallsConnection(sampler->GetOutputPort());
  external->SetNumberOfThreads(2);
  external->Update();
  vtkPolyData* mesh = internal->GetOutput();
  MEDIAL_CHECK(mesh->GetNumberOfPolys() > 0, "no triangles");
  MEDIAL_CHECK(medialtest::SameMesh(mesh, external->GetOutput()), "port 1 or 2 threads give another mesh");

  // Arrays carried over; radii never grow; cell types in step with the cells.
  vtkPointData* pd = mesh->GetPointData();
  for (const char* name : { vtkMedialArrayNames::SurfacePoint, vtkMedialArrayNames::SourceCellId,
         vtkMedialArrayNames::MedialPointType, vtkMedialArrayNames::GovernorCount })
  {
    MEDIAL_CHECK(pd->GetArray(name) != nullptr, "no point array %s", name);
  }
  vtkPolyData* balls = sampler->GetOutput();
  vtkDataArray* surfacePoint = pd->GetArray(vtkMedialArrayNames::SurfacePoint);
  vtkIdType exact = 0, refined = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    // The sample P identifies the ball: its radius may only have been lowered. The
    // classifier's exact seam and junction balls have none.
    double p[3];
    surfacePoint->GetTuple(i, p);
    if (std::isnan(p[0]) && medialtest::Value(mesh, vtkMedialArrayNames::GovernorCount, i) < 0)
    {
      ++refined; // a ball of the envelope refinement: no array of the balls
      continue;
    }
    if (std::isnan(p[0]))
    {
      const int type = static_cast<int>(medialtest::Value(mesh, vtkMedialArrayNames::MedialPointType, i));
      MEDIAL_CHECK(type >= 2 && medialtest::Value(mesh, vtkMedialArrayNames::GovernorCount, i) >= 3,
        "vertex %lld: no sample point, yet not an exact seam or junction ball", static_cast<long long>(i));
      ++exact;
      continue;
    }
    bool found = false;
    for (vtkIdType j = 0; j < balls->GetNumberOfPoints() && !found; ++j)
    {
      double q[3];
      balls->GetPointData()->GetArray(vtkMedialArrayNames::SurfacePoint)->GetTuple(j, q);
      found = std::memcmp(p, q, sizeof(p)) == 0;
      MEDIAL_CHECK(!found ||
          medialtest::Value(mesh, vtkMedialArrayNames::Radius, i) <=
            medialtest::Value(balls, vtkMedialArrayNames::Radius, j),
        "vertex %lld: the radius grew", static_cast<long long>(i));
    }
    MEDIAL_CHECK(found, "vertex %lld is no input ball", static_cast<long long>(i));
  }
  MEDIAL_CHECK(refined == internal->GetRefinementBalls(), "%lld balls without arrays, %lld refinement balls",
    static_cast<long long>(refined), static_cast<long long>(internal->GetRefinementBalls()));
  std::printf("%lld vertices, %lld of them exact seam or junction balls, %lld of the envelope refinement\n",
    static_cast<long long>(mesh->GetNumberOfPoints()), static_cast<long long>(exact),
    static_cast<long long>(refined));
  vtkDataArray* cellTypes = mesh->GetCellData()->GetArray(vtkMedialArrayNames::MedialCellType);
  MEDIAL_CHECK(cellTypes && cellTypes->GetNumberOfTuples() == mesh->GetNumberOfCells(), "MedialCellType size");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const int type = static_cast<int>(cellTypes->GetTuple1(c));
    const int points = static_cast<int>(mesh->GetCell(c)->GetNumberOfPoints());
    MEDIAL_CHECK((type == vtkMedialMeshFilter::SHEET_TRIANGLE) == (points == 3) &&
        (type == vtkMedialMeshFilter::ISOLATED_BALL) == (points == 1),
      "cell %lld: type %d with %d points", static_cast<long long>(c), type, points);
  }
  for (const char* name : { vtkMedialArrayNames::EulerCharacteristic, vtkMedialArrayNames::Components,
         vtkMedialArrayNames::SolidEulerCharacteristic, vtkMedialArrayNames::SolidComponents })
  {
    MEDIAL_CHECK(medialtest::FieldValue(mesh, name) == 1.0, "field data %s is not 1", name);
  }

  // A sampler setting re-executes the filter and changes the mesh.
  const vtkIdType before = mesh->GetNumberOfPoints();
  internal->GetSampler()->SetNumberOfSamples(2000);
  internal->Update();
  MEDIAL_CHECK(internal->GetOutput()->GetNumberOfPoints() != before &&
      internal->GetOutput()->GetNumberOfPoints() < before,
    "the sampler's settings were not used");
  // Without a classifier: only the sampled balls (and the envelope refinement's), types
  // from the mesh, no governors.
  internal->SetClassifier(nullptr);
  internal->Update();
  MEDIAL_CHECK(internal->GetOutput()->GetNumberOfPoints() <= 2000 + internal->GetRefinementBalls() &&
      internal->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType) &&
      !internal->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::GovernorCount),
    "without a classifier");
  std::ostringstream print;
  internal->Print(print);
  MEDIAL_CHECK(print.str().find("EulerCharacteristic") != std::string::npos, "PrintSelf");

  return CheckBadInput(solid);
}
