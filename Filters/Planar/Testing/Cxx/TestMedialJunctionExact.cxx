// SPDX-License-Identifier: BSD-3-Clause
// Closed-form 2D medial graphs: rectangle, square, L-shape (reflex vertex, parabolic
// arc), regular n-gons, square frame with a square hole, a tilted plane, and reversed
// loops. Junction positions must match within 1e-6 of the diagonal, with no extra
// or missing junctions and one end point per convex vertex.
#include "MedialPolygonTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellData.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace medialtest;

namespace
{
struct Expect
{
  std::vector<std::array<double, 3>> Junctions;
  std::vector<double> Radii; // same order; empty: not checked
  int Ends;
  int ParabolicArcs; // -1: not checked
};

vtkSmartPointer<vtkPolyData> RunFilter(vtkPolyData* input, EventLog& log)
{
  vtkNew<vtkMedialJunctionFilter> filter;
  log.Watch(filter);
  filter->SetInputData(input);
  filter->SetNumberOfThreads(2);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

int Check(const char* name, vtkPolyData* input, const Expect& expect)
{
  EventLog log;
  auto graph = RunFilter(input, log);
  const double diag = Diagonal(input);
  const auto junctions = NodesOfType(graph, vtkMedialJunctionFilter::JUNCTION_POINT);
  const auto ends = NodesOfType(graph, vtkMedialJunctionFilter::END_POINT);
  double worstRadius = 0.0;
  for (size_t i = 0; i < expect.Radii.size(); ++i)
  {
    for (const auto& j : junctions)
    {
      const auto& e = expect.Junctions[i];
      if (std::hypot(std::hypot(j.X[0] - e[0], j.X[1] - e[1]), j.X[2] - e[2]) < 1e-6 * diag)
      {
        worstRadius = std::max(worstRadius, std::abs(j.Radius - expect.Radii[i]));
      }
    }
  }
  int parabolic = 0;
  vtkDataArray* arcType = graph->GetCellData()->GetArray("ArcType");
  for (vtkIdType c = 0; arcType && c < arcType->GetNumberOfTuples(); ++c)
  {
    parabolic += arcType->GetTuple1(c) == vtkMedialJunctionFilter::PARABOLIC_ARC ? 1 : 0;
  }
  const double error = MatchError(junctions, expect.Junctions) / diag;
  std::printf("%-22s junctions %zu (expected %zu), ends %zu (expected %d), arcs %lld (parabolic %d), "
              "position error %.3g diag, radius error %.3g diag\n",
    name, junctions.size(), expect.Junctions.size(), ends.size(), expect.Ends,
    static_cast<long long>(graph->GetNumberOfLines()), parabolic, error, worstRadius / diag);
  MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", name, log.Text.c_str());
  MEDIAL_CHECK(junctions.size() == expect.Junctions.size(), "%s: junction count", name);
  MEDIAL_CHECK(error <= 1e-6, "%s: junction position error %g", name, error);
  MEDIAL_CHECK(worstRadius <= 1e-6 * diag, "%s: junction radius error %g", name, worstRadius);
  MEDIAL_CHECK(static_cast<int>(ends.size()) == expect.Ends, "%s: end count", name);
  MEDIAL_CHECK(expect.ParabolicArcs < 0 || parabolic == expect.ParabolicArcs, "%s: parabolic arcs %d",
    name, parabolic);
  for (const auto& e : ends)
  {
    MEDIAL_CHECK(e.Radius == 0.0, "%s: end radius %g", name, e.Radius);
  }
  // Every end has its branch: some arc starts or ends there.
  std::vector<int> degree(static_cast<size_t>(graph->GetNumberOfPoints()), 0);
  vtkIdType npts;
  const vtkIdType* ids;
  for (graph->GetLines()->InitTraversal(); graph->GetLines()->GetNextCell(npts, ids);)
  {
    degree[ids[0]]++;
    degree[ids[npts - 1]]++;
  }
  vtkDataArray* type = graph->GetPointData()->GetArray("MedialPointType");
  for (vtkIdType i = 0; i < graph->GetNumberOfPoints(); ++i)
  {
    const int t = static_cast<int>(type->GetTuple1(i));
    if (t == vtkMedialJunctionFilter::END_POINT)
    {
      MEDIAL_CHECK(degree[i] == 1, "%s: end point %lld has degree %d", name, static_cast<long long>(i), degree[i]);
    }
    if (t == vtkMedialJunctionFilter::JUNCTION_POINT)
    {
      MEDIAL_CHECK(degree[i] >= 3, "%s: junction %lld has degree %d", name, static_cast<long long>(i), degree[i]);
    }
  }
  return EXIT_SUCCESS;
}

vtkSmartPointer<vtkPolyData> Reversed(const std::vector<Loop2>& loops, bool asLines)
{
  std::vector<Loop2> r = loops;
  for (auto& l : r)
  {
    std::reverse(l.begin(), l.end());
  }
  return MakePolygon(r, asLines);
}
}

int TestMedialJunctionExact(int, char*[])
{
  int status = EXIT_SUCCESS;
  auto run = [&status](const char* name, vtkPolyData* input, const Expect& e) {
    if (Check(name, input, e) != EXIT_SUCCESS)
    {
      status = EXIT_FAILURE;
    }
  };
  {
    const double w = 5.0, h = 2.0;
    const std::vector<Loop2> loops = { Rectangle(0, 0, w, h) };
    const Expect e{ { { h / 2, h / 2, 0 }, { w - h / 2, h / 2, 0 } }, { h / 2, h / 2 }, 4, 0 };
    run("rectangle", MakePolygon(loops), e);
    run("rectangle reversed", Reversed(loops, false), e);
    run("rectangle polyline", Reversed(loops, true), e);
  }
  {
    const std::vector<Loop2> loops = { Rectangle(-1, -1, 1, 1) };
    run("square", MakePolygon(loops), { { { 0, 0, 0 } }, { 1.0 }, 4, 0 });
  }
  {
    // Unit arms: junction tangent to x = 0, y = 0 and the reflex vertex (1, 1).
    const std::vector<Loop2> loops = { { { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } } };
    const double r = 2.0 - std::sqrt(2.0);
    // The arm ends: x in [1,2] between y = 0 and y = 1 gives junctions at (1.5, 0.5) and (0.5, 1.5).
    const Expect e{ { { r, r, 0 }, { 1.5, 0.5, 0 }, { 0.5, 1.5, 0 } }, { r, 0.5, 0.5 }, 5, 2 };
    run("L-shape", MakePolygon(loops), e);
    run("L-shape reversed", Reversed(loops, true), e);
  }
  for (int n : { 3, 5, 6, 7, 12, 40 })
  {
    const double R = 1.5;
    const std::string name = "regular " + std::to_string(n) + "-gon";
    run(name.c_str(), MakePolygon({ RegularPolygon(n, R, 0.3) }),
      { { { 0, 0, 0 } }, { R * std::cos(3.14159265358979323846 / n) }, n, 0 });
  }
  {
    // Frame [0,4]^2 with hole [1,3]^2: junctions on the diagonals, tangent to two outer
    // edges and a hole corner: c = (4 + 3 sqrt2) / (1 + sqrt2), r = 4 - c.
    const std::vector<Loop2> loops = { Rectangle(0, 0, 4, 4), Rectangle(1, 1, 3, 3) };
    const double c = (4.0 + 3.0 * std::sqrt(2.0)) / (1.0 + std::sqrt(2.0)), r = 4.0 - c;
    const Expect e{ { { c, c, 0 }, { 4 - c, c, 0 }, { c, 4 - c, 0 }, { 4 - c, 4 - c, 0 } }, { r, r, r, r },
      4, 8 };
    run("square frame", MakePolygon(loops), e);
    run("square frame reversed", Reversed(loops, true), e);
    std::vector<Loop2> sameWinding = loops;
    std::reverse(sameWinding[1].begin(), sameWinding[1].end());
    run("square frame same winding", MakePolygon(sameWinding), e);

    // The same region as a planar mesh: 8 quads of a 3 x 3 grid without its centre.
    auto quads = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    const double xs[4] = { 0, 1, 3, 4 };
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        pts->InsertNextPoint(xs[i], xs[j], 0);
      }
    }
    vtkNew<vtkCellArray> cells;
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        if (i == 1 && j == 1)
        {
          continue;
        }
        const vtkIdType q[4] = { 4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i + 1, 4 * (j + 1) + i };
        cells->InsertNextCell(4, q);
      }
    }
    quads->SetPoints(pts);
    quads->SetPolys(cells);
    run("square frame as quads", quads, e);
  }
  {
    // The L-shape as loose 2-point segments in shuffled order (vtkCutter-like).
    const Loop2 l = { { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } };
    auto segments = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> lines;
    for (int k : { 3, 0, 5, 1, 4, 2 })
    {
      const auto& a = l[k];
      const auto& b = l[(k + 1) % l.size()];
      // Separate point ids for each segment: ends meet by coordinates only.
      const vtkIdType ids[2] = { pts->InsertNextPoint(a[0], a[1], 0), pts->InsertNextPoint(b[0], b[1], 0) };
      lines->InsertNextCell(2, ids);
    }
    segments->SetPoints(pts);
    segments->SetLines(lines);
    const double r = 2.0 - std::sqrt(2.0);
    run("L-shape as segments", segments, { { { r, r, 0 }, { 1.5, 0.5, 0 }, { 0.5, 1.5, 0 } }, { r, 0.5, 0.5 }, 5, 2 });
  }
  {
    // 4 governors at a square's centre and n at a regular n-gon's: one junction each.
    for (int n : { 4, 9 })
    {
      EventLog log;
      auto graph = RunFilter(MakePolygon({ RegularPolygon(n, 1.0, 0.1) }), log);
      const auto junctions = NodesOfType(graph, vtkMedialJunctionFilter::JUNCTION_POINT);
      std::printf("regular %d-gon: GovernorCount %d\n", n, junctions.empty() ? -1 : junctions[0].Governors);
      MEDIAL_CHECK(junctions.size() == 1 && junctions[0].Governors == n, "%d-gon governor count", n);
    }
  }
  {
    // The rectangle rotated into a tilted plane and moved away from the origin.
    const double w = 5.0, h = 2.0;
    vtkNew<vtkTransform> t;
    t->Translate(3, -2, 7);
    t->RotateWXYZ(37, 1, 2, 0.5);
    vtkNew<vtkTransformPolyDataFilter> move;
    move->SetTransform(t);
    move->SetInputData(MakePolygon({ Rectangle(0, 0, w, h) }));
    move->Update();
    double a[3], b[3];
    const double pa[3] = { h / 2, h / 2, 0 }, pb[3] = { w - h / 2, h / 2, 0 };
    t->TransformPoint(pa, a);
    t->TransformPoint(pb, b);
    run("tilted rectangle", move->GetOutput(), { { { a[0], a[1], a[2] }, { b[0], b[1], b[2] } }, { 1, 1 }, 4, 0 });
  }
  return status;
}
