// SPDX-License-Identifier: BSD-3-Clause
// The shared meshes: the valid solids come out untouched (the sampler's balls with
// RepairMode AUTO are the bits of NONE), the others are repaired into valid solids (the
// open bunny's holes filled; horse.ply's four intersecting triangle pairs resolved) and
// then sampled without a discarded sample. Skips without ../shared/data/meshes.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

int TestMedialRepairSharedMeshes(int, char*[])
{
  struct Case
  {
    const char* Name;
    bool Valid;
  };
  const Case cases[] = { { "horse.ply", false }, { "stanford-bunny.obj", false }, { "fandisk.obj", true },
    { "spot.obj", true }, { "rocker-arm.obj", true } };
  int found = 0;
  for (const Case& c : cases)
  {
    const std::string path = medialtest::SharedMesh(c.Name);
    if (path.empty())
    {
      continue;
    }
    ++found;
    vtkNew<vtkMedialFileReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* surface = reader->GetOutput();
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(surface);
    repair->SetReportSteps(false);
    repair->Update();
    std::string report;
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      report += std::string(i ? "; " : "") + repair->GetReportLine(i);
    }
    std::printf("%-20s %s, %.2f s, largest distance %.3g, buried %.3g: %s\n", c.Name,
      repair->GetInputWasValid() ? "valid" : "repaired", repair->GetSeconds(), repair->GetMaximumDistance(),
      repair->GetBuriedArea(), report.c_str());
    MEDIAL_CHECK(repair->GetInputWasValid() == c.Valid, "%s: expected %s", c.Name, c.Valid ? "valid" : "a repair");
    MEDIAL_CHECK(!repair->GetWrapped(), "%s: wrapped", c.Name);
    if (!c.Valid)
    {
      // The repaired surface is a valid solid by the preparation's own check.
      vtkMedialTriangleMesh mesh;
      vtkMedialSurfaceQuery query;
      std::string error;
      MEDIAL_CHECK(mesh.Build(repair->GetOutput(), error) && query.Build(&mesh, error), "%s: %s", c.Name, error.c_str());
      vtkMedialSolidCheck check;
      check.Run(mesh, query, 2);
      MEDIAL_CHECK(check.IsValid() || check.OnlyPairs(), "%s: the repaired surface is not a solid", c.Name);
      MEDIAL_CHECK(repair->GetMaximumDistance() < 0.01, "%s: the repair moved the surface by %g of the diagonal",
        c.Name, repair->GetMaximumDistance());
    }
    vtkSmartPointer<vtkPolyData> balls[2];
    vtkIdType discarded[2] = { 0, 0 };
    for (int mode : { vtkMedialRepairFilter::AUTO, vtkMedialRepairFilter::NONE })
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(surface);
      sampler->SetNumberOfSamples(3000);
      sampler->SetRepairMode(mode);
      sampler->Update();
      balls[mode] = sampler->GetOutput();
      discarded[mode] = sampler->GetDiscardedSamples();
      MEDIAL_CHECK(sampler->GetSurfaceRepaired() == (mode == vtkMedialRepairFilter::AUTO && !c.Valid),
        "%s: SurfaceRepaired is wrong", c.Name);
    }
    MEDIAL_CHECK(discarded[vtkMedialRepairFilter::AUTO] == 0, "%s: %lld samples discarded after the repair", c.Name,
      static_cast<long long>(discarded[vtkMedialRepairFilter::AUTO]));
    if (c.Valid)
    {
      MEDIAL_CHECK(medialtest::BitDifferences(balls[0], balls[1]) == 0, "%s: the check changed the balls", c.Name);
    }
    std::printf("%-20s sampler: discarded %lld with the repair, %lld without\n", c.Name,
      static_cast<long long>(discarded[0]), static_cast<long long>(discarded[1]));
  }
  if (found == 0)
  {
    std::printf("shared meshes absent: skipped\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  return EXIT_SUCCESS;
}
