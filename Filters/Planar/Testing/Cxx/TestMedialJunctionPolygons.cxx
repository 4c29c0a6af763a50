// SPDX-License-Identifier: BSD-3-Clause
// Several outer boundaries and islands: one medial graph per polygon in one output,
// with a PolygonId cell array.
//  1. Four squares of sides 3, 1, 2, 1.5 apart (given in that order): 4 polygons,
//     numbered by decreasing area; each square's graph is its two diagonals (one
//     junction of radius side / 2 at its centre, 4 end points, 4 arcs).
//  2. A frame (an 8 x 8 square with a 6 x 6 hole) with a 2 x 2 island in the hole,
//     and a nested island with its own hole (depth 3): 3 polygons.
//  3. Each polygon's graph in the joint output equals the graph of that polygon
//     given alone (same nodes within 1e-9 of the diagonal, same arc counts).
//  4. The sampler's 2D balls on the four squares lie each inside one square.
//  5. A slice through horse.ply's four legs (skipped without the shared meshes):
//     4 polygons, each with end points and arcs.
#include "MedialPolygonTestUtilities.h"
#include "MedialTestSupport.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialJunctionFilter.h"

#include "vtkCellData.h"
#include "vtkCutter.h"
#include "vtkDataArray.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
struct Graph
{
  bool Ok = false;
  vtkSmartPointer<vtkPolyData> Output;
  int Polygons = 0;
};

Graph Run(vtkPolyData* input)
{
  Graph g;
  vtkNew<vtkMedialJunctionFilter> junctions;
  EventLog log;
  log.Watch(junctions);
  junctions->SetInputData(input);
  g.Ok = junctions->GetExecutive()->Update() == 1 && log.Errors == 0;
  if (!g.Ok)
  {
    std::printf("junction filter failed: %s\n", log.Text.c_str());
  }
  g.Output = junctions->GetOutput();
  g.Polygons = junctions->GetNumberOfPolygons();
  return g;
}

// The nodes (junctions and end points) and the arc count of one polygon of a graph,
// nodes sorted for comparison.
struct Part
{
  std::vector<std::array<double, 4>> Nodes; // x, y, radius, type
  int Arcs = 0;
};

Part PartOf(vtkPolyData* graph, int polygon)
{
  Part part;
  vtkDataArray* ids = graph->GetCellData()->GetArray(vtkMedialArrayNames::PolygonId);
  vtkDataArray* type = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  vtkDataArray* radius = graph->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  std::map<vtkIdType, bool> ends;
  vtkIdType n;
  const vtkIdType* pts;
  vtkIdType cell = 0;
  for (graph->GetLines()->InitTraversal(); graph->GetLines()->GetNextCell(n, pts); ++cell)
  {
    if (ids && static_cast<int>(ids->GetTuple1(cell)) == polygon)
    {
      ++part.Arcs;
      ends[pts[0]] = ends[pts[n - 1]] = true;
    }
  }
  for (const auto& e : ends)
  {
    const double* p = graph->GetPoint(e.first);
    part.Nodes.push_back({ p[0], p[1], radius->GetTuple1(e.first), type->GetTuple1(e.first) });
  }
  std::sort(part.Nodes.begin(), part.Nodes.end());
  return part;
}

bool SameParts(const Part& a, const Part& b, double tolerance)
{
  if (a.Arcs != b.Arcs || a.Nodes.size() != b.Nodes.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.Nodes.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (std::abs(a.Nodes[i][k] - b.Nodes[i][k]) > tolerance)
      {
        return false;
      }
    }
    if (a.Nodes[i][3] != b.Nodes[i][3])
    {
      return false;
    }
  }
  return true;
}

int CountType(const Part& part, int type)
{
  return static_cast<int>(
    std::count_if(part.Nodes.begin(), part.Nodes.end(), [type](const auto& n) { return n[3] == type; }));
}

// Each polygon of `loops` (grouped as polygons, in the expected PolygonId order) gives
// the same graph within the whole as alone.
int CheckAgainstAlone(const char* name, const std::vector<Loop2>& loops, const std::vector<std::vector<int>>& polygons)
{
  const Graph whole = Run(MakePolygon(loops));
  MEDIAL_CHECK(whole.Ok && whole.Polygons == static_cast<int>(polygons.size()), "%s: %d polygons, expected %zu",
    name, whole.Polygons, polygons.size());
  int arcs = 0;
  for (size_t p = 0; p < polygons.size(); ++p)
  {
    std::vector<Loop2> own;
    for (int l : polygons[p])
    {
      own.push_back(loops[l]);
    }
    const Graph alone = Run(MakePolygon(own));
    MEDIAL_CHECK(alone.Ok && alone.Polygons == 1, "%s: polygon %zu alone", name, p);
    const Part inWhole = PartOf(whole.Output, static_cast<int>(p));
    const Part single = PartOf(alone.Output, 0);
    std::printf("%s: polygon %zu: %zu nodes (%d junctions), %d arcs\n", name, p, inWhole.Nodes.size(),
      CountType(inWhole, vtkMedialJunctionFilter::JUNCTION_POINT), inWhole.Arcs);
    MEDIAL_CHECK(inWhole.Arcs > 0 && SameParts(inWhole, single, 1e-9 * whole.Output->GetLength()),
      "%s: polygon %zu differs from its graph alone (%d arcs against %d)", name, p, inWhole.Arcs, single.Arcs);
    arcs += inWhole.Arcs;
  }
  MEDIAL_CHECK(arcs == whole.Output->GetNumberOfLines(), "%s: arcs without a polygon", name);
  return EXIT_SUCCESS;
}

int FourSquares()
{
  const double sides[4] = { 3.0, 1.0, 2.0, 1.5 };
  std::vector<Loop2> loops;
  double x = 0.0;
  for (double side : sides)
  {
    loops.push_back(Rectangle(x, 0.0, x + side, side));
    x += side + 0.5;
  }
  // PolygonId by decreasing area: the squares of sides 3, 2, 1.5, 1.
  if (CheckAgainstAlone("four squares", loops, { { 0 }, { 2 }, { 3 }, { 1 } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  const Graph g = Run(MakePolygon(loops));
  const int order[4] = { 0, 2, 3, 1 };
  double left = 0.0;
  std::vector<double> lefts;
  for (double side : sides)
  {
    lefts.push_back(left);
    left += side + 0.5;
  }
  for (int p = 0; p < 4; ++p)
  {
    const Part part = PartOf(g.Output, p);
    const double side = sides[order[p]], x0 = lefts[order[p]];
    MEDIAL_CHECK(part.Arcs == 4 && CountType(part, vtkMedialJunctionFilter::JUNCTION_POINT) == 1 &&
        CountType(part, vtkMedialJunctionFilter::END_POINT) == 4,
      "square %d: %d arcs", p, part.Arcs);
    for (const auto& node : part.Nodes)
    {
      if (node[3] == vtkMedialJunctionFilter::JUNCTION_POINT)
      {
        MEDIAL_CHECK(std::abs(node[0] - (x0 + side / 2)) < 1e-9 && std::abs(node[1] - side / 2) < 1e-9 &&
            std::abs(node[2] - side / 2) < 1e-9,
          "square %d: junction (%g, %g) radius %g", p, node[0], node[1], node[2]);
      }
    }
  }

  // The sampler's balls: each inside one square, within its inscribed radius.
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(MakePolygon(loops));
  sampler->SetNumberOfSamples(4000);
  sampler->Update();
  vtkPolyData* balls = sampler->GetOutput();
  vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  MEDIAL_CHECK(balls->GetNumberOfPoints() == 4000 && radius, "sampler: %lld balls",
    static_cast<long long>(balls->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    const double* c = balls->GetPoint(i);
    bool inside = false;
    for (int s = 0; s < 4; ++s)
    {
      const double gap = std::min({ c[0] - lefts[s], lefts[s] + sides[s] - c[0], c[1], sides[s] - c[1] });
      inside = inside || (gap >= -1e-9 && radius->GetTuple1(i) <= gap + 1e-9);
    }
    MEDIAL_CHECK(inside, "ball %lld at (%g, %g) radius %g is in no square", static_cast<long long>(i), c[0], c[1],
      radius->GetTuple1(i));
  }
  return EXIT_SUCCESS;
}

int Islands()
{
  // 0: frame outer, 1: frame hole, 2: island in the hole.
  const std::vector<Loop2> frame = { Rectangle(0, 0, 8, 8), Rectangle(1, 1, 7, 7), Rectangle(3, 3, 5, 5) };
  if (CheckAgainstAlone("island", frame, { { 0, 1 }, { 2 } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // Depth 3: the island has a hole with an island of its own; a separate square beside.
  const std::vector<Loop2> nested = { Rectangle(0, 0, 20, 20), Rectangle(1, 1, 19, 19), Rectangle(3, 3, 17, 17),
    Rectangle(5, 5, 15, 15), Rectangle(8, 8, 12, 12), Rectangle(22, 0, 25, 3) };
  return CheckAgainstAlone("nested islands", nested, { { 0, 1 }, { 2, 3 }, { 4 }, { 5 } });
}

int HorseLegs()
{
  const std::string path = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/horse.ply";
  if (!std::filesystem::exists(path))
  {
    std::printf("skipped: %s is absent\n", path.c_str());
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  double b[6];
  reader->GetOutput()->GetBounds(b);
  // The horse stands along z; a plane at a fifth of its height crosses the four legs.
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, b[4] + 0.2 * (b[5] - b[4]));
  plane->SetNormal(0.0, 0.0, 1.0);
  vtkNew<vtkCutter> cutter;
  cutter->SetInputConnection(reader->GetOutputPort());
  cutter->SetCutFunction(plane);
  cutter->Update();
  const Graph g = Run(cutter->GetOutput());
  std::printf("horse legs: %lld cut segments, %d polygons, %lld arcs\n",
    static_cast<long long>(cutter->GetOutput()->GetNumberOfLines()), g.Polygons,
    static_cast<long long>(g.Output->GetNumberOfLines()));
  MEDIAL_CHECK(g.Ok && g.Polygons == 4, "the slice through the legs gives %d polygons, expected 4", g.Polygons);
  for (int p = 0; p < 4; ++p)
  {
    const Part part = PartOf(g.Output, p);
    std::printf("  leg %d: %d arcs, %d end points, %d junctions\n", p, part.Arcs,
      CountType(part, vtkMedialJunctionFilter::END_POINT), CountType(part, vtkMedialJunctionFilter::JUNCTION_POINT));
    MEDIAL_CHECK(part.Arcs > 0 && CountType(part, vtkMedialJunctionFilter::END_POINT) >= 2, "leg %d has no graph", p);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialJunctionPolygons(int, char*[])
{
  if (FourSquares() != EXIT_SUCCESS || Islands() != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return HorseLegs();
}
