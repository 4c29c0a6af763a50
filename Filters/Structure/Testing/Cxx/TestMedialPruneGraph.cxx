// SPDX-License-Identifier: BSD-3-Clause
// Pruning of the 2D medial graph with the default measure and threshold: a finely
// polygonised ellipse keeps one segment with 2 end points, a rounded 3-armed star
// (vtkMedialShapeSource's TREFOIL) 3 branches at one junction, a rectangle its 4 corner spokes, a regular hexagon its 6;
// polygons with holes keep their cycles; components and cycles never change, for every
// measure. Thresholding the Significance array reproduces the filter's output.
#include "MedialPolygonTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellData.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialPruneFilter.h"
#include "vtkMedialShapeSource.h"

#include <cstdio>
#include <map>
#include <numeric>
#include <string>

using namespace medialtest;

namespace
{
struct GraphShape
{
  int Ends = 0;
  int Junctions = 0;
  int Components = 0;
  int Cycles = 0; // E - V + C
  vtkIdType Segments = 0;
};

GraphShape Describe(vtkPolyData* graph)
{
  const vtkIdType n = graph->GetNumberOfPoints();
  std::vector<int> degree(static_cast<size_t>(n), 0);
  std::vector<vtkIdType> parent(static_cast<size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](vtkIdType x) {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  GraphShape s;
  vtkCellArray* lines = graph->GetLines();
  vtkNew<vtkIdList> ids;
  for (lines->InitTraversal(); lines->GetNextCell(ids);)
  {
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType a = ids->GetId(k), b = ids->GetId(k + 1);
      ++degree[a];
      ++degree[b];
      ++s.Segments;
      parent[find(a)] = find(b);
    }
  }
  int used = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (degree[i] > 0)
    {
      ++used;
      s.Ends += degree[i] == 1 ? 1 : 0;
      s.Junctions += degree[i] >= 3 ? 1 : 0;
      s.Components += find(i) == i ? 1 : 0;
    }
  }
  s.Cycles = static_cast<int>(s.Segments) - used + s.Components;
  return s;
}

vtkSmartPointer<vtkPolyData> Graph(vtkPolyData* polygon)
{
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(polygon);
  junctions->SetNumberOfThreads(2);
  junctions->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(junctions->GetOutput());
  return out;
}

vtkSmartPointer<vtkPolyData> Prune(vtkPolyData* graph, int measure, double threshold, EventLog& log,
  vtkIdType* prunedBranches = nullptr)
{
  vtkNew<vtkMedialPruneFilter> prune;
  log.Watch(prune);
  prune->SetInputData(graph);
  prune->SetMeasure(measure);
  prune->SetThreshold(threshold);
  prune->Update();
  if (prunedBranches)
  {
    *prunedBranches = prune->GetNumberOfPrunedBranches();
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(prune->GetOutput());
  return out;
}

Loop2 Ellipse(int n, double a, double b, double phase)
{
  Loop2 l;
  for (int i = 0; i < n; ++i)
  {
    const double t = phase + 2.0 * 3.14159265358979323846 * i / n;
    l.push_back({ a * std::cos(t), b * std::sin(t) });
  }
  return l;
}

// vtkMedialShapeSource's ELLIPSE (semi-axes a, 1) or TREFOIL with 16 * resolution vertices.
vtkSmartPointer<vtkPolyData> Curve(int shape, int resolution, double a = 1.0)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->SetResolution(resolution);
  source->SetBoxLengths(2.0 * a, 2.0, 1.0);
  source->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(source->GetOutput());
  return out;
}

// The default pruning of a polygon's graph must give `ends` end points and `junctions`
// junctions, and keep components and cycles.
int CheckShape(const char* name, vtkPolyData* polygon, int ends, int junctions, int cycles)
{
  auto graph = Graph(polygon);
  const GraphShape before = Describe(graph);
  EventLog log;
  vtkIdType removed = 0;
  auto pruned = Prune(graph, vtkMedialPruneFilter::TUBULARITY, -1.0, log, &removed);
  const GraphShape after = Describe(pruned);
  std::printf("%-28s before: %4d ends %4d junctions %d cycles; after: %d ends %d junctions %d cycles "
              "(%lld branches pruned)\n",
    name, before.Ends, before.Junctions, before.Cycles, after.Ends, after.Junctions, after.Cycles,
    static_cast<long long>(removed));
  MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", name, log.Text.c_str());
  MEDIAL_CHECK(after.Ends == ends && after.Junctions == junctions, "%s: %d ends and %d junctions, expected %d and %d",
    name, after.Ends, after.Junctions, ends, junctions);
  MEDIAL_CHECK(after.Components == before.Components && after.Cycles == before.Cycles && after.Cycles == cycles,
    "%s: topology changed (components %d -> %d, cycles %d -> %d, expected %d)", name, before.Components,
    after.Components, before.Cycles, after.Cycles, cycles);
  vtkDataArray* types = pruned->GetPointData()->GetArray("MedialPointType");
  int typedEnds = 0;
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    typedEnds += types->GetTuple1(i) == vtkMedialJunctionFilter::END_POINT ? 1 : 0;
  }
  MEDIAL_CHECK(typedEnds == ends, "%s: MedialPointType says %d ends", name, typedEnds);
  return EXIT_SUCCESS;
}

// Every measure at every threshold keeps components and cycles; thresholding the
// Significance of the unpruned output gives the pruned output.
int CheckTopologyAndLevels(const char* name, vtkPolyData* polygon)
{
  auto graph = Graph(polygon);
  const GraphShape before = Describe(graph);
  for (int m = vtkMedialPruneFilter::EROSION_THICKNESS; m <= vtkMedialPruneFilter::SCALE_AXIS; ++m)
  {
    EventLog log;
    auto all = Prune(graph, m, 0.0, log);
    MEDIAL_CHECK(Describe(all).Segments == before.Segments, "%s: threshold 0 removed segments", name);
    vtkDataArray* level = all->GetCellData()->GetArray("Significance");
    MEDIAL_CHECK(level && level->GetNumberOfTuples() == all->GetNumberOfCells(), "%s: no Significance", name);
    const double top = vtkMedialPruneFilter::GetMeasureUpperBound(m);
    for (double fraction : { 0.001, 0.01, 0.05, 0.2, 0.5, 1.0 })
    {
      const double t = fraction * top;
      auto pruned = Prune(graph, m, t, log);
      const GraphShape after = Describe(pruned);
      MEDIAL_CHECK(after.Components == before.Components && after.Cycles == before.Cycles,
        "%s, %s at %g: components %d -> %d, cycles %d -> %d", name, vtkMedialPruneFilter::GetMeasureName(m), t,
        before.Components, after.Components, before.Cycles, after.Cycles);
      vtkIdType keptSegments = 0;
      for (vtkIdType c = 0; c < all->GetNumberOfCells(); ++c)
      {
        keptSegments += level->GetTuple1(c) >= t ? all->GetCell(c)->GetNumberOfPoints() - 1 : 0;
      }
      MEDIAL_CHECK(keptSegments == after.Segments, "%s, %s at %g: thresholding Significance keeps %lld segments, "
        "the filter %lld", name, vtkMedialPruneFilter::GetMeasureName(m), t, static_cast<long long>(keptSegments),
        static_cast<long long>(after.Segments));
    }
    MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", name, log.Text.c_str());
  }
  return EXIT_SUCCESS;
}
}

int TestMedialPruneGraph(int, char*[])
{
  int status = EXIT_SUCCESS;
  auto run = [&status](int result) { status = result == EXIT_SUCCESS ? status : EXIT_FAILURE; };
  // Smooth curves finely polygonised: only the smooth curve's branches stay.
  const int E = vtkMedialShapeSource::ELLIPSE, T = vtkMedialShapeSource::TREFOIL;
  run(CheckShape("ellipse 2:1, 208 vertices", Curve(E, 13, 2.0), 2, 0, 0));
  run(CheckShape("ellipse 2:1, shifted", MakePolygon({ Ellipse(200, 2.0, 1.0, 0.0123) }), 2, 0, 0));
  run(CheckShape("ellipse 3:1, 592 vertices", Curve(E, 37, 3.0), 2, 0, 0));
  run(CheckShape("trefoil, 256 vertices", Curve(T, 16), 3, 1, 0));
  run(CheckShape("trefoil, 608 vertices", Curve(T, 38), 3, 1, 0));
  // Exact polygon features stay.
  run(CheckShape("rectangle 2 x 1", MakePolygon({ Rectangle(0, 0, 2, 1) }), 4, 2, 0));
  run(CheckShape("rectangle 10 x 1", MakePolygon({ Rectangle(0, 0, 10, 1) }), 4, 2, 0));
  run(CheckShape("regular hexagon", MakePolygon({ RegularPolygon(6, 1.0, 0.1) }), 6, 1, 0));
  // A hole keeps its cycle; the exact frame keeps its 4 outer corner spokes (the hole's
  // corners are reflex: parabolic arcs, no spokes).
  run(CheckShape("square frame", MakePolygon({ Rectangle(-2, -2, 2, 2), Rectangle(-1, -1, 1, 1) }), 4, 4, 1));
  // Its tips curve faster (radius 1) than the ring is wide (1.5): a branch to each.
  auto ring = MakePolygon({ Ellipse(400, 4.0, 2.0, 0.01), RegularPolygon(200, 1.0, 0.02) });
  {
    auto graph = Graph(ring);
    EventLog log;
    const GraphShape after = Describe(Prune(graph, vtkMedialPruneFilter::TUBULARITY, -1.0, log));
    std::printf("%-28s after: %d ends %d junctions %d cycles %d components\n", "ellipse with a round hole",
      after.Ends, after.Junctions, after.Cycles, after.Components);
    MEDIAL_CHECK(after.Cycles == 1 && after.Components == 1, "ring: %d cycles, %d components", after.Cycles,
      after.Components);
    MEDIAL_CHECK(after.Ends == 2 && after.Junctions == 2, "ring: %d ends, %d junctions (expected the 2 branches "
      "to the ellipse's tips)", after.Ends, after.Junctions);
  }
  // Topology and the Significance levels, every measure.
  run(CheckTopologyAndLevels("ellipse", MakePolygon({ Ellipse(200, 2.0, 1.0, 0.0123) })));
  run(CheckTopologyAndLevels("trefoil", Curve(T, 38)));
  run(CheckTopologyAndLevels("frame", MakePolygon({ Rectangle(-2, -2, 2, 2), Rectangle(-1, -1, 1, 1) })));
  run(CheckTopologyAndLevels("ring", ring));
  run(CheckTopologyAndLevels("two holes",
    MakePolygon({ Ellipse(300, 4.0, 2.0, 0.0), RegularPolygon(40, 0.7, 0.0), Rectangle(1.5, -0.5, 2.5, 0.5) })));
  return status;
}
