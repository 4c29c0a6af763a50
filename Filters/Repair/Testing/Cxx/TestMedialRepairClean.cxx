// SPDX-License-Identifier: BSD-3-Clause
// Clean input is not touched: on generated valid solids (sphere, box, torus, capsule, a
// hollow sphere, a genus-2 solid, the jack, a solid inside a cavity) the repair passes
// the input through (the same points object, InputWasValid, no report line); a sphere
// wound inward as a whole (every triangle turned) is only turned over; and the
// sampler's balls and the medial mesh with RepairMode AUTO (the default) are the same
// bits as with NONE, as are the thickness filter's arrays.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include <cstring>

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialThickness.h"
#include "vtkReverseSense.h"

int TestMedialRepairClean(int, char*[])
{
  using medialtest::defects::Shape;
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Surface;
    bool Inward = false; // every triangle faces into the solid
  };
  // The sphere with every triangle turned over: a valid solid wound inward as a whole.
  vtkNew<vtkReverseSense> turned;
  turned->SetInputData(Shape(vtkMedialShapeSource::SPHERE, 3));
  turned->ReverseCellsOn();
  turned->Update();
  vtkSmartPointer<vtkPolyData> inward = turned->GetOutput();
  const std::vector<Case> cases = {
    { "sphere", Shape(vtkMedialShapeSource::SPHERE, 4) },
    { "box", Shape(vtkMedialShapeSource::BOX, 8) },
    { "torus", Shape(vtkMedialShapeSource::TORUS, 16) },
    { "capsule", Shape(vtkMedialShapeSource::CAPSULE, 12) },
    { "hollow sphere", Shape(vtkMedialShapeSource::HOLLOW_SPHERE, 4) },
    { "rings of genus 2", Shape(vtkMedialShapeSource::RINGS, 12, [](vtkMedialShapeSource* s) { s->SetGenus(2); }) },
    { "jack", Shape(vtkMedialShapeSource::JACK, 16) },
    { "contoured torus", Shape(vtkMedialShapeSource::CONTOURED_TORUS, 40) },
    { "sphere wound inward", inward, true },
    { "solid in a cavity", medialtest::defects::SolidInCavity().Surface },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(c.Surface);
    repair->Update();
    if (c.Inward)
    {
      // A solid wound inward as a whole is turned over by the repair (its output faces
      // out), with one line and nothing else; the filters, which orient as they prepare,
      // take it as it is (below).
      MEDIAL_CHECK(!repair->GetInputWasValid() && repair->GetTurnedShells() > 0 &&
          repair->GetNumberOfReportLines() == 1 &&
          std::strstr(repair->GetReportLine(0), "wound inward turned over") != nullptr &&
          repair->GetMaximumDistance() < 1e-12 && !repair->GetWrapped() &&
          repair->GetOutput()->GetNumberOfPolys() == c.Surface->GetNumberOfPolys(),
        "%s: the repair does more than turn the inward solid over (%d report lines)", c.Name,
        repair->GetNumberOfReportLines());
    }
    else
    {
      MEDIAL_CHECK(repair->GetInputWasValid() && !repair->GetChanged() && repair->GetNumberOfReportLines() == 0,
        "%s: the repair does not pass a valid solid through (%d report lines)", c.Name,
        repair->GetNumberOfReportLines());
      MEDIAL_CHECK(repair->GetOutput()->GetPoints() == c.Surface->GetPoints() &&
          repair->GetOutput()->GetPolys() == c.Surface->GetPolys(),
        "%s: the output is not the input itself", c.Name);
    }

    vtkSmartPointer<vtkPolyData> balls[2], meshes[2], thickness[2];
    for (int mode : { vtkMedialRepairFilter::AUTO, vtkMedialRepairFilter::NONE })
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(c.Surface);
      sampler->SetNumberOfSamples(3000);
      sampler->SetRepairMode(mode);
      vtkNew<vtkMedialMeshFilter> mesh;
      mesh->SetInputData(c.Surface);
      mesh->SetBallsConnection(sampler->GetOutputPort());
      mesh->SetRepairMode(mode);
      mesh->Update();
      MEDIAL_CHECK(!sampler->GetSurfaceRepaired() && !mesh->GetSurfaceRepaired(), "%s: repaired", c.Name);
      balls[mode] = sampler->GetOutput();
      meshes[mode] = mesh->GetOutput();
      vtkNew<vtkMedialThickness> t;
      t->SetInputData(c.Surface);
      t->SetRepairMode(mode);
      t->Update();
      thickness[mode] = t->GetOutput();
    }
    MEDIAL_CHECK(medialtest::BitDifferences(balls[0], balls[1]) == 0, "%s: the balls differ with the check", c.Name);
    MEDIAL_CHECK(medialtest::BitDifferences(meshes[0], meshes[1]) == 0 &&
        meshes[0]->GetNumberOfPolys() == meshes[1]->GetNumberOfPolys(),
      "%s: the medial meshes differ with the check", c.Name);
    MEDIAL_CHECK(balls[0]->GetFieldData()->GetNumberOfArrays() == balls[1]->GetFieldData()->GetNumberOfArrays(),
      "%s: the check added field data", c.Name);
    vtkDataArray* t0 = thickness[0]->GetPointData()->GetArray("Thickness");
    vtkDataArray* t1 = thickness[1]->GetPointData()->GetArray("Thickness");
    bool same = t0 && t1 && t0->GetNumberOfTuples() == t1->GetNumberOfTuples();
    for (vtkIdType i = 0; same && i < t0->GetNumberOfTuples(); ++i)
    {
      const double a = t0->GetComponent(i, 0), b = t1->GetComponent(i, 0);
      same = std::memcmp(&a, &b, sizeof(a)) == 0;
    }
    MEDIAL_CHECK(same, "%s: the thickness differs with the check", c.Name);
    std::printf("%-18s untouched: %lld balls and %lld medial vertices, the same bits with and without the check\n",
      c.Name, static_cast<long long>(balls[0]->GetNumberOfPoints()),
      static_cast<long long>(meshes[0]->GetNumberOfPoints()));
  }
  return EXIT_SUCCESS;
}
