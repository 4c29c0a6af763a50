// SPDX-License-Identifier: BSD-3-Clause
// The grid's contract: ModelBounds makes two reconstructions of different balls share
// one grid (and their fields stay exact there), RequestInformation publishes output
// 1's extent, origin and spacing when they do not depend on the balls (and they match
// the data), SampleDimensions are clamped to 8 visibly, and the radius comes through
// SetInputArrayToProcess.
#include "MedialBallUnionTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMedialBallUnion.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
// Voxels whose value differs from clamp(brute-force field, -B, B).
vtkIdType WrongVoxels(vtkMedialBallUnion* ballUnion, const std::vector<BallSpec>& balls)
{
  vtkImageData* image = ballUnion->GetFieldOutput();
  const double band = ballUnion->GetBandWidth() * ballUnion->GetVoxelSize();
  vtkDataArray* values = image->GetPointData()->GetScalars();
  vtkIdType wrong = 0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    const double expected = std::max(-band, std::min(band, UnionField(balls, x)));
    wrong += std::fabs(values->GetTuple1(i) - expected) > 1e-12 ? 1 : 0;
  }
  return wrong;
}

bool SameGrid(vtkImageData* a, vtkImageData* b)
{
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  bool same = true;
  for (int k = 0; k < 3; ++k)
  {
    same = same && da[k] == db[k] && a->GetOrigin()[k] == b->GetOrigin()[k] &&
      a->GetSpacing()[k] == b->GetSpacing()[k];
  }
  return same;
}

int CheckSharedGrid()
{
  const std::vector<BallSpec> first = { { 0, 0, 0, 0.5 }, { 0.6, 0.1, 0, 0.4 } };
  const std::vector<BallSpec> second = { { -0.2, 0.3, 0.2, 0.3 }, { 0.5, -0.4, -0.1, 0.35 }, { 0, 0, 0.4, 0.2 } };
  const double bounds[6] = { -1.0, 1.5, -1.0, 1.0, -0.8, 0.9 };
  vtkNew<vtkMedialBallUnion> a, b;
  int index = 0;
  for (vtkMedialBallUnion* u : { a.Get(), b.Get() })
  {
    u->SetInputData(MakeBalls(index++ == 0 ? first : second));
    u->SetDimension(vtkMedialBallUnion::DIMENSION_3D);
    u->SetModelBounds(bounds);
    u->SetSampleDimensions(36, 30, 26);
    u->SetNumberOfThreads(2);
    // Published before any data is computed.
    u->UpdateInformation();
    vtkInformation* info = u->GetOutputInformation(1);
    MEDIAL_CHECK(info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()) &&
        info->Has(vtkDataObject::ORIGIN()) && info->Has(vtkDataObject::SPACING()),
      "ModelBounds in 3D: extent, origin and spacing not published");
    int extent[6];
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    double origin[3], spacing[3];
    info->Get(vtkDataObject::ORIGIN(), origin);
    info->Get(vtkDataObject::SPACING(), spacing);
    u->Update();
    vtkImageData* image = u->GetFieldOutput();
    int dims[3];
    image->GetDimensions(dims);
    for (int k = 0; k < 3; ++k)
    {
      MEDIAL_CHECK(extent[2 * k] == 0 && extent[2 * k + 1] == dims[k] - 1 && origin[k] == image->GetOrigin()[k] &&
          spacing[k] == image->GetSpacing()[k],
        "axis %d: published extent %d..%d, origin %g, spacing %g; data %d points, origin %g, spacing %g", k,
        extent[2 * k], extent[2 * k + 1], origin[k], spacing[k], dims[k], image->GetOrigin()[k],
        image->GetSpacing()[k]);
      // The grid spans ModelBounds exactly.
      MEDIAL_CHECK(origin[k] == bounds[2 * k] &&
          std::fabs(origin[k] + extent[2 * k + 1] * spacing[k] - bounds[2 * k + 1]) < 1e-12,
        "axis %d: grid %g .. %g, ModelBounds %g .. %g", k, origin[k], origin[k] + extent[2 * k + 1] * spacing[k],
        bounds[2 * k], bounds[2 * k + 1]);
    }
    MEDIAL_CHECK(u->GetOutput()->GetNumberOfPoints() > 0 && OpenEdges(u->GetOutput()) == 0,
      "no closed surface inside ModelBounds");
  }
  MEDIAL_CHECK(SameGrid(a->GetFieldOutput(), b->GetFieldOutput()), "two reconstructions, two grids");
  const vtkIdType wrongA = WrongVoxels(a, first), wrongB = WrongVoxels(b, second);
  std::printf("shared grid: %lld and %lld voxels differ from the exact clamped field\n",
    static_cast<long long>(wrongA), static_cast<long long>(wrongB));
  MEDIAL_CHECK(wrongA == 0 && wrongB == 0, "field not exact on the shared grid");

  // Without ModelBounds the two grids differ (each fits its own union).
  vtkNew<vtkMedialBallUnion> c;
  c->SetInputData(MakeBalls(second));
  c->SetSampleDimensions(36, 30, 26);
  c->Update();
  MEDIAL_CHECK(!SameGrid(a->GetFieldOutput(), c->GetFieldOutput()), "ModelBounds ignored");

  // A union reaching beyond ModelBounds is cut, with a warning.
  EventLog log;
  vtkNew<vtkMedialBallUnion> cut;
  log.Watch(cut);
  cut->SetInputData(MakeBalls(first));
  const double small[6] = { -0.2, 0.2, -0.2, 0.2, -0.2, 0.2 };
  cut->SetModelBounds(small);
  cut->SetSampleDimensions(16, 16, 16);
  cut->Update();
  MEDIAL_CHECK(log.Warnings == 1 && log.Text.find("beyond ModelBounds") != std::string::npos,
    "no warning for a union cut by ModelBounds (%d warnings)", log.Warnings);
  return EXIT_SUCCESS;
}

int CheckPublishedExtent()
{
  // Balls in the z = 0.5 plane: a 2D union.
  const std::vector<BallSpec> disks = { { 0, 0, 0.5, 0.4 }, { 0.7, 0.2, 0.5, 0.3 }, { 0.2, 0.8, 0.5, 0.25 } };
  vtkNew<vtkMedialBallUnion> u;
  u->SetInputData(MakeBalls(disks));
  u->SetSampleDimensions(40, 30, 20);
  u->UpdateInformation();
  // Unknown: absent, or the executive's empty default.
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (u->GetOutputInformation(1)->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    u->GetOutputInformation(1)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  }
  MEDIAL_CHECK(extent[1] < extent[0], "DIMENSION_AUTOMATIC: an extent (0..%d) was published before the balls were seen",
    extent[1]);
  u->Update();
  u->GetOutputInformation(1)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  MEDIAL_CHECK(extent[1] == 39 && extent[3] == 29 && extent[5] == 0, "2D extent %d %d %d after the update",
    extent[1], extent[3], extent[5]);

  for (int dimension : { 2, 3 })
  {
    u->SetDimension(dimension);
    u->UpdateInformation();
    MEDIAL_CHECK(u->GetOutputInformation(1)->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
      "%dD with SampleDimensions: no extent published", dimension);
    u->GetOutputInformation(1)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
    MEDIAL_CHECK(!u->GetOutputInformation(1)->Has(vtkDataObject::ORIGIN()),
      "%dD: an origin was published that depends on the balls", dimension);
    u->Update();
    int dims[3];
    u->GetFieldOutput()->GetDimensions(dims);
    MEDIAL_CHECK(extent[1] == dims[0] - 1 && extent[3] == dims[1] - 1 && extent[5] == dims[2] - 1 &&
        dims[2] == (dimension == 2 ? 1 : 20),
      "%dD: published extent %d %d %d, data %d %d %d", dimension, extent[1], extent[3], extent[5], dims[0],
      dims[1], dims[2]);
  }

  // 2D with ModelBounds: the grid spans the box's projection onto the plane (x, y here).
  vtkNew<vtkMedialBallUnion> flat;
  flat->SetInputData(MakeBalls(disks));
  flat->SetModelBounds(-0.6, 1.2, -0.5, 1.3, 0.5, 0.5);
  flat->SetSampleDimensions(37, 37, 8);
  flat->Update();
  vtkImageData* image = flat->GetFieldOutput();
  MEDIAL_CHECK(flat->GetOutputDimension() == 2 && image->GetOrigin()[0] == -0.6 && image->GetOrigin()[1] == -0.5 &&
      std::fabs(image->GetSpacing()[0] - 0.05) < 1e-15 && std::fabs(image->GetSpacing()[1] - 0.05) < 1e-15,
    "2D ModelBounds: origin %g %g, spacing %g %g", image->GetOrigin()[0], image->GetOrigin()[1],
    image->GetSpacing()[0], image->GetSpacing()[1]);
  MEDIAL_CHECK(WrongVoxels(flat, disks) == 0, "2D ModelBounds: field not exact");
  return EXIT_SUCCESS;
}

int CheckSampleDimensionsAndRadiusArray()
{
  vtkNew<vtkMedialBallUnion> u;
  u->SetSampleDimensions(4, 100, 7);
  MEDIAL_CHECK(u->GetSampleDimensions()[0] == 8 && u->GetSampleDimensions()[1] == 100 &&
      u->GetSampleDimensions()[2] == 8,
    "SampleDimensions not clamped to 8: %d %d %d", u->GetSampleDimensions()[0], u->GetSampleDimensions()[1],
    u->GetSampleDimensions()[2]);

  // The radius under another name, chosen with SetInputArrayToProcess: the same union.
  const std::vector<BallSpec> balls = { { 0, 0, 0, 0.5 }, { 0.6, 0.1, 0.2, 0.4 } };
  vtkNew<vtkMedialBallUnion> byDefault;
  byDefault->SetInputData(MakeBalls(balls));
  byDefault->SetSampleDimensions(24, 24, 24);
  byDefault->Update();
  auto renamed = MakeBalls(balls);
  renamed->GetPointData()->GetArray("Radius")->SetName("Size");
  vtkNew<vtkDoubleArray> decoy; // a wrong Radius must not be used
  decoy->SetName("Radius");
  decoy->SetNumberOfTuples(2);
  decoy->FillValue(5.0);
  renamed->GetPointData()->AddArray(decoy);
  vtkNew<vtkMedialBallUnion> chosen;
  chosen->SetInputData(renamed);
  chosen->SetSampleDimensions(24, 24, 24);
  chosen->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Size");
  chosen->Update();
  vtkDataArray* expected = byDefault->GetFieldOutput()->GetPointData()->GetScalars();
  vtkDataArray* got = chosen->GetFieldOutput()->GetPointData()->GetScalars();
  vtkIdType differ = expected->GetNumberOfTuples() == got->GetNumberOfTuples() ? 0 : -1;
  for (vtkIdType i = 0; differ >= 0 && i < expected->GetNumberOfTuples(); ++i)
  {
    differ += expected->GetTuple1(i) != got->GetTuple1(i) ? 1 : 0;
  }
  MEDIAL_CHECK(differ == 0 && SameGrid(byDefault->GetFieldOutput(), chosen->GetFieldOutput()) &&
      byDefault->GetOutput()->GetNumberOfPoints() == chosen->GetOutput()->GetNumberOfPoints(),
    "SetInputArrayToProcess(Size): not the same union (%lld voxels differ)", static_cast<long long>(differ));

  // A missing array and cell data are errors that name the array.
  struct Case
  {
    int Association;
    const char* Name;
    const char* Expected;
  };
  for (const Case& c : { Case{ vtkDataObject::FIELD_ASSOCIATION_POINTS, "Missing", "'Missing'" },
         Case{ vtkDataObject::FIELD_ASSOCIATION_CELLS, "Radius", "not point data" } })
  {
    auto input = MakeBalls(balls);
    if (c.Association == vtkDataObject::FIELD_ASSOCIATION_CELLS)
    {
      vtkNew<vtkCellArray> verts;
      const vtkIdType ids[2] = { 0, 1 };
      verts->InsertNextCell(2, ids);
      input->SetVerts(verts);
      vtkNew<vtkDoubleArray> perCell;
      perCell->SetName("Radius");
      perCell->InsertNextValue(0.5);
      input->GetCellData()->AddArray(perCell);
    }
    EventLog log;
    vtkNew<vtkMedialBallUnion> bad;
    log.Watch(bad);
    bad->SetInputData(input);
    bad->SetSampleDimensions(16, 16, 16);
    bad->SetInputArrayToProcess(0, 0, 0, c.Association, c.Name);
    const int ok = bad->GetExecutive()->Update();
    std::printf("%s: %s\n", c.Name, log.LineWith("Cannot build").c_str());
    MEDIAL_CHECK(!ok && log.Text.find(c.Expected) != std::string::npos, "%s: message lacks '%s'", c.Name,
      c.Expected);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialBallUnionGrid(int, char*[])
{
  if (CheckSharedGrid() != EXIT_SUCCESS || CheckPublishedExtent() != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return CheckSampleDimensionsAndRadiusArray();
}
