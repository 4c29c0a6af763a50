// SPDX-License-Identifier: BSD-3-Clause
// The 2D mode of vtkMedialAxisSampler: every disk must be maximal (its radius equal to
// the centre's distance to the boundary, a second contact at that distance) and its
// centre must lie on the medial graph computed independently by
// vtkMedialJunctionFilter (parabolic arcs sampled finely). Rectangle, L-shape and a
// square frame in a tilted plane; bisection and shrinking ball; theta = 0. The output
// must not depend on the thread count.
#include "MedialSampler2DTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialJunctionFilter.h"

#include <cstdio>
#include <cstdlib>

using namespace medialtest;

namespace
{
// Distance from p to the cells (lines or polygon loops) of pd.
double DistanceToCells(vtkPolyData* pd, const double p[3], bool closed)
{
  double best = HUGE_VAL;
  vtkCellArray* cells = closed ? pd->GetPolys() : pd->GetLines();
  vtkIdType npts;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
  {
    for (vtkIdType i = 0; i + (closed ? 0 : 1) < npts; ++i)
    {
      double a[3], b[3];
      pd->GetPoint(ids[i], a);
      pd->GetPoint(ids[(i + 1) % npts], b);
      best = std::min(best, PointSegmentDistance(p, a, b));
    }
  }
  return best;
}

int Check(const char* name, vtkPolyData* polygon, int method)
{
  const double diag = Diagonal(polygon);
  vtkNew<vtkMedialJunctionFilter> graph;
  graph->SetInputData(polygon);
  graph->SetArcResolution(400);
  graph->Update();

  vtkSmartPointer<vtkPolyData> runs[2];
  for (int threads = 1; threads <= 2; ++threads)
  {
    EventLog log;
    vtkNew<vtkMedialAxisSampler> sampler;
    log.Watch(sampler);
    sampler->SetInputData(polygon);
    sampler->SetNumberOfSamples(400);
    sampler->SetMethod(method);
    sampler->SetMinimumSeparationAngle(0.0);
    sampler->SetNumberOfThreads(threads);
    sampler->Update();
    MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", name, log.Text.c_str());
    runs[threads - 1] = vtkSmartPointer<vtkPolyData>::New();
    runs[threads - 1]->DeepCopy(sampler->GetOutput());
  }
  vtkPolyData* out = runs[0];
  MEDIAL_CHECK(out->GetNumberOfPoints() == 400, "%s: %lld samples kept", name,
    static_cast<long long>(out->GetNumberOfPoints()));
  MEDIAL_CHECK(FieldValue(out, "RequestedSamples") == 400 && FieldValue(out, "DiscardedSamples") == 0,
    "%s: field data", name);
  MEDIAL_CHECK(out->GetPointData()->GetArray("SourceCellId") && out->GetPointData()->GetArray("SeparationAngle"),
    "%s: arrays", name);
  double worstRadius = 0.0, worstContact = 0.0, worstAxis = 0.0, worstPlane = 0.0, thread = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[3], p[3], q[3], c2[3];
    out->GetPoint(i, c);
    runs[1]->GetPoint(i, c2);
    thread = std::max(thread, std::abs(c[0] - c2[0]) + std::abs(c[1] - c2[1]) + std::abs(c[2] - c2[2]));
    const double r = Value(out, "Radius", i);
    for (int k = 0; k < 3; ++k)
    {
      p[k] = Value(out, "SurfacePoint", i, k);
      q[k] = Value(out, "ContactPoint", i, k);
    }
    worstRadius = std::max(worstRadius, std::abs(DistanceToCells(polygon, c, true) - r));
    worstContact = std::max(worstContact,
      std::abs(std::sqrt((q[0] - c[0]) * (q[0] - c[0]) + (q[1] - c[1]) * (q[1] - c[1]) + (q[2] - c[2]) * (q[2] - c[2])) - r));
    worstPlane = std::max(worstPlane, DistanceToCells(polygon, p, true));
    worstAxis = std::max(worstAxis, DistanceToCells(graph->GetOutput(), c, false));
  }
  std::printf("%-16s %-14s radius error %.3g, contact error %.3g, off medial graph %.3g, surface "
              "point off boundary %.3g (diag), thread difference %g\n",
    name, vtkMedialAxisSampler::GetMethodName(method), worstRadius / diag, worstContact / diag,
    worstAxis / diag, worstPlane / diag, thread);
  MEDIAL_CHECK(worstRadius <= 1e-5 * diag, "%s: disk not maximal", name);
  MEDIAL_CHECK(worstContact <= 1e-5 * diag, "%s: contact not on the disk", name);
  MEDIAL_CHECK(worstAxis <= 1e-4 * diag, "%s: centre off the medial graph", name);
  MEDIAL_CHECK(worstPlane <= 1e-12 * diag, "%s: surface point off the boundary", name);
  MEDIAL_CHECK(thread == 0.0, "%s: output depends on the thread count", name);
  return EXIT_SUCCESS;
}
}

int TestMedialSampler2D(int, char*[])
{
  vtkNew<vtkTransform> tilt;
  auto frame = TiltedFrame(tilt);
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Polygon;
  };
  const Case cases[] = {
    { "rectangle", MakePolygon({ Rectangle(0, 0, 5, 2) }) },
    { "L-shape", MakePolygon({ { { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } } }) },
    { "tilted frame", frame },
  };
  for (const Case& c : cases)
  {
    for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
    {
      if (Check(c.Name, c.Polygon, method) != EXIT_SUCCESS)
      {
        return EXIT_FAILURE;
      }
    }
  }
  return EXIT_SUCCESS;
}
