// SPDX-License-Identifier: BSD-3-Clause
// The medial mesh of the shared meshes at the sampler's defaults: one component with
// the solid's Euler characteristic (horse, fandisk, spot: 1; rocker-arm: 0), counted
// from the cells. stanford-bunny.obj is open (no solid): its figures are printed
// only. Skipped when the shared meshes are absent.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialRepairFilter.h"
#include "vtkMedialMeshFilter.h"

#include <cstdio>

int TestMedialMeshSharedMeshes(int, char*[])
{
  struct Case
  {
    const char* Name;
    int Genus; // -1: open surface, not checked
  };
  const Case cases[] = { { "horse.ply", 0 }, { "rocker-arm.obj", 1 }, { "fandisk.obj", 0 },
    { "spot.obj", 0 }, { "stanford-bunny.obj", -1 } };
  int found = 0;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> surface = medialtest::ReadSharedMesh(c.Name);
    if (!surface)
    {
      continue;
    }
    ++found;
    vtkNew<vtkMedialMeshFilter> filter;
    medialtest::EventLog log;
    log.Watch(filter);
    filter->SetInputData(surface);
    // The meshes as they are: horse.ply's 4 crossing triangle pairs are left alone here
    // (the repair's own test, TestMedialRepairSharedMeshes, repairs them).
    filter->SetRepairMode(vtkMedialRepairFilter::NONE);
    filter->Update();
    const medialtest::MeshTopology t = medialtest::CountTopology(filter->GetOutput());
    std::printf("%-20s V %lld E %lld F %lld chi %lld components %lld; detached balls %lld\n", c.Name,
      static_cast<long long>(t.Vertices), static_cast<long long>(t.Edges),
      static_cast<long long>(t.Faces), static_cast<long long>(t.Euler()),
      static_cast<long long>(t.Components), static_cast<long long>(filter->GetDetachedBalls()));
    MEDIAL_CHECK(log.Errors == 0, "%s: %s", c.Name, log.Text.c_str());
    if (c.Genus < 0)
    {
      MEDIAL_CHECK(!filter->GetHasSolidTopology(), "%s: an open surface has no solid", c.Name);
      continue;
    }
    MEDIAL_CHECK(log.Warnings == 0, "%s: %s", c.Name, log.Text.c_str());
    MEDIAL_CHECK(filter->GetSolidEulerCharacteristic() == 1 - c.Genus, "%s: the solid's chi is %lld",
      c.Name, static_cast<long long>(filter->GetSolidEulerCharacteristic()));
    MEDIAL_CHECK(t.Components == 1 && t.Euler() == 1 - c.Genus, "%s: chi %lld, %lld components",
      c.Name, static_cast<long long>(t.Euler()), static_cast<long long>(t.Components));
  }
  return found == 0 ? MEDIALAXIS_SKIP_RETURN_CODE : EXIT_SUCCESS;
}
