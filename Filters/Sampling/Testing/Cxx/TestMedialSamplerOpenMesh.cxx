// SPDX-License-Identifier: BSD-3-Clause
// An open mesh, a sphere with a hole cut in it: one warning with the boundary-edge
// count, DiscardedSamples > 0, and every kept ball inside the sphere. The bunny and the
// non-manifold case are rows of Testing/BadInput/cases.tsv.
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerOpenMesh(int, char*[])
{
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(4);
  sphere->Update();
  // Remove the triangles of a polar cap (z > 0.8).
  vtkNew<vtkPolyData> open;
  open->SetPoints(sphere->GetOutput()->GetPoints());
  vtkNew<vtkCellArray> kept;
  vtkPolyData* closed = sphere->GetOutput();
  for (vtkIdType c = 0; c < closed->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* pts;
    closed->GetCellPoints(c, n, pts);
    double z = 0;
    for (int k = 0; k < 3; ++k)
    {
      z += closed->GetPoint(pts[k])[2] / 3.0;
    }
    if (z <= 0.8)
    {
      kept->InsertNextCell(n, pts);
    }
  }
  open->SetPolys(kept);

  EventLog log;
  vtkNew<vtkMedialAxisSampler> sampler;
  log.Watch(sampler);
  sampler->SetInputData(open);
  sampler->SetNumberOfSamples(2000);
  sampler->SetMinimumSeparationAngle(0.0); // balls strictly inside the polyhedron
  sampler->Update();
  vtkPolyData* out = sampler->GetOutput();
  const double discarded = FieldValue(out, "DiscardedSamples");
  std::printf("sphere with a hole: %d warning(s), %g of 2000 discarded, %lld kept\n", log.Warnings,
    discarded, static_cast<long long>(out->GetNumberOfPoints()));
  MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 1, "errors %d warnings %d", log.Errors, log.Warnings);
  MEDIAL_CHECK(log.Text.find("boundary edges") != std::string::npos, "warning text: %s", log.Text.c_str());
  MEDIAL_CHECK(discarded > 0 && discarded + out->GetNumberOfPoints() == 2000, "discarded %g", discarded);
  // Balls may leave through the hole (nothing blocks them there), but every centre
  // is inside and no radius exceeds the sphere's.
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[3];
    out->GetPoint(i, c);
    const double centre = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    MEDIAL_CHECK(centre < 1.0 && Value(out, "Radius", i) <= 1.0, "ball %lld: |c| %g r %g",
      static_cast<long long>(i), centre, Value(out, "Radius", i));
  }

  return EXIT_SUCCESS;
}
