// SPDX-License-Identifier: BSD-3-Clause
// Open meshes: a sphere with a hole cut in it, and the Stanford bunny when the
// shared data is present. Both must warn with the boundary-edge count and report
// DiscardedSamples > 0.
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkOBJReader.h"
#include "vtkPoints.h"

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

  // Non-manifold: two boxes sharing one edge (4 triangles meet there). Warned, not fatal.
  {
    vtkNew<vtkMedialShapeSource> box;
    box->SetShapeToBox();
    box->SetBoxLengths(1, 1, 1);
    box->SetResolution(1);
    box->Update();
    vtkPolyData* b = box->GetOutput();
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    for (int copy = 0; copy < 2; ++copy)
    {
      for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
      {
        double x[3];
        b->GetPoint(i, x);
        // The second box sits diagonally, touching the first along its edge x = y = 0.5.
        points->InsertNextPoint(x[0] + copy, x[1] + copy, x[2]);
      }
      for (vtkIdType c = 0; c < b->GetNumberOfCells(); ++c)
      {
        vtkIdType n;
        const vtkIdType* pts;
        b->GetCellPoints(c, n, pts);
        vtkIdType shifted[3];
        for (int k = 0; k < 3; ++k)
        {
          shifted[k] = pts[k] + copy * b->GetNumberOfPoints();
        }
        cells->InsertNextCell(3, shifted);
      }
    }
    vtkNew<vtkPolyData> pair;
    pair->SetPoints(points);
    pair->SetPolys(cells);
    EventLog pairLog;
    vtkNew<vtkMedialAxisSampler> pairSampler;
    pairLog.Watch(pairSampler);
    pairSampler->SetInputData(pair);
    pairSampler->SetNumberOfSamples(1000);
    pairSampler->Update();
    std::printf("two boxes sharing an edge: %d warning(s), %d error(s), %lld points\n", pairLog.Warnings,
      pairLog.Errors, static_cast<long long>(pairSampler->GetOutput()->GetNumberOfPoints()));
    MEDIAL_CHECK(pairLog.Errors == 0 && pairLog.Text.find("1 non-manifold edges") != std::string::npos,
      "non-manifold warning missing: %s", pairLog.Text.c_str());
    MEDIAL_CHECK(pairSampler->GetOutput()->GetNumberOfPoints() == 1000, "non-manifold pair lost samples");
  }

  const std::string bunny = SharedMesh("stanford-bunny.obj");
  if (bunny.empty())
  {
    std::printf("shared meshes absent: bunny part skipped\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(bunny.c_str());
  EventLog bunnyLog;
  vtkNew<vtkMedialAxisSampler> bunnySampler;
  bunnyLog.Watch(bunnySampler);
  bunnySampler->SetInputConnection(reader->GetOutputPort());
  bunnySampler->SetNumberOfSamples(5000);
  bunnySampler->Update();
  const double bunnyDiscarded = FieldValue(bunnySampler->GetOutput(), "DiscardedSamples");
  std::printf("bunny: %d warning(s), %g of 5000 discarded, %lld boundary edges\n", bunnyLog.Warnings,
    bunnyDiscarded, static_cast<long long>(bunnySampler->GetBoundaryEdges()));
  MEDIAL_CHECK(bunnyLog.Warnings >= 1 && bunnyDiscarded > 0, "bunny: warnings %d discarded %g",
    bunnyLog.Warnings, bunnyDiscarded);
  return EXIT_SUCCESS;
}
