// SPDX-License-Identifier: BSD-3-Clause
// An open mesh, a sphere with a hole cut in it: one warning with the boundary-edge
// count, DiscardedSamples > 0, and every kept ball inside the sphere. The iterative
// strategies warn the same way, and face-distance says why it stopped short of its
// budget when a part of the surface cannot be covered (faces given up, where the
// largest gap is). The bunny and the non-manifold case are rows of
// Testing/BadInput/cases.tsv.
#include "MedialTestUtilities.h"

#include "vtkMedialRepairFilter.h"
#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkPoints.h"

#include <cmath>
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
  sampler->SetRepairMode(vtkMedialRepairFilter::NONE); // the open surface as it is
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


  // The iterative strategies: the same warning (they used to say nothing).
  for (int strategy : { vtkMedialAxisSampler::FACE_DISTANCE, vtkMedialAxisSampler::CLOSEST_NEIGHBOR })
  {
    EventLog iterative;
    vtkNew<vtkMedialAxisSampler> s;
    iterative.Watch(s);
    s->SetInputData(open);
    s->SetRepairMode(vtkMedialRepairFilter::NONE);
    s->SetNumberOfSamples(3000);
    s->SetSamplingStrategy(strategy);
    s->Update();
    const std::string warning = iterative.LineWith("Input surface is open (68 boundary edges)");
    std::printf("%s: %s\n", vtkMedialAxisSampler::GetSamplingStrategyName(strategy), warning.c_str());
    MEDIAL_CHECK(s->GetDiscardedSamples() > 0 && !warning.empty() &&
        warning.find(std::to_string(s->GetDiscardedSamples()) + " of " + std::to_string(s->GetEvaluatedSamples())) !=
          std::string::npos,
      "%s: %s", vtkMedialAxisSampler::GetSamplingStrategyName(strategy), iterative.Text.c_str());
  }
  // Face-distance with a coverage it cannot reach: the sphere with a hole and, beside
  // and above it, an open square that no ball reaches (its rays all escape). Once the
  // sphere is covered, further layers of seeds cover no more faces (seeds on the sphere
  // bring the square's gap down by parts in 1e5): it stops early and says why, naming
  // a place on the square.
  vtkNew<vtkPolyData> unreachable;
  {
    vtkNew<vtkPoints> points;
    points->DeepCopy(open->GetPoints());
    vtkNew<vtkCellArray> polys;
    polys->DeepCopy(open->GetPolys());
    constexpr int Side = 8;
    const vtkIdType first = points->GetNumberOfPoints();
    for (int j = 0; j <= Side; ++j)
    {
      for (int i = 0; i <= Side; ++i)
      {
        points->InsertNextPoint(3.0, -0.5 + i / double(Side), 4.5 + j / double(Side));
      }
    }
    for (int j = 0; j < Side; ++j)
    {
      for (int i = 0; i < Side; ++i)
      {
        const vtkIdType a = first + j * (Side + 1) + i, b = a + 1, c = a + Side + 1, d = c + 1;
        const vtkIdType lower[3] = { a, b, d }, upper[3] = { a, d, c };
        polys->InsertNextCell(3, lower);
        polys->InsertNextCell(3, upper);
      }
    }
    unreachable->SetPoints(points);
    unreachable->SetPolys(polys);
  }
  EventLog early;
  vtkNew<vtkMedialAxisSampler> s;
  early.Watch(s);
  s->SetInputData(unreachable);
  s->SetRepairMode(vtkMedialRepairFilter::NONE);
  s->SetNumberOfSamples(200000);
  s->SetSamplingStrategyToFaceDistance();
  s->SetCoverageTolerance(0.002);
  s->Update();
  const std::string stopped = early.LineWith("face-distance stopped after");
  std::printf("%s\n", stopped.c_str());
  MEDIAL_CHECK(s->GetEvaluatedSamples() < 200000 && !s->GetCoverageReached(), "evaluated %lld",
    static_cast<long long>(s->GetEvaluatedSamples()));
  MEDIAL_CHECK(stopped.find("face-distance stopped after " + std::to_string(s->GetEvaluatedSamples()) +
                 " of 200000 samples without reaching the coverage: ") != std::string::npos &&
      stopped.find(" faces were given up") != std::string::npos && stopped.find(" faces were given up") != 0 &&
      stopped.find("further layers of seeds") != std::string::npos &&
      stopped.find("The largest gap, ") != std::string::npos,
    "message: %s", early.Text.c_str());
  // The place it names is on the square.
  double where[3];
  const size_t at = stopped.find(" is at (");
  MEDIAL_CHECK(at != std::string::npos &&
      std::sscanf(stopped.c_str() + at, " is at (%lf, %lf, %lf)", where, where + 1, where + 2) == 3,
    "no place in: %s", stopped.c_str());
  MEDIAL_CHECK(std::fabs(where[0] - 3.0) < 1e-5 && std::fabs(where[1]) <= 0.5 + 1e-5 &&
      std::fabs(where[2] - 5.0) <= 0.5 + 1e-5,
    "the worst gap at (%g, %g, %g) is not on the square", where[0], where[1], where[2]);
  return EXIT_SUCCESS;
}
