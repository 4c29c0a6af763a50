// SPDX-License-Identifier: BSD-3-Clause
// Junctions of random polygons (star-shaped, integer coordinates, some with one or two holes)
// against an independent exact reference: Boost.Polygon's segment Voronoi diagram.
// A reference junction is a Voronoi vertex inside the polygon, off the boundary,
// whose incident sites are 3 or more distinct governors (a segment and its own end
// point meeting there is a transition, not a junction). Every reference junction
// must be found within 1e-6 of the diagonal, and no junction may be extra. The
// graph must also be connected with one independent cycle per hole.
#include "MedialPolygonTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkMedialJunctionFilter.h"

#include <boost/polygon/polygon.hpp>
#include <boost/polygon/voronoi.hpp>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <set>

using namespace medialtest;

namespace
{
using IPoint = boost::polygon::point_data<int>;
using ISegment = boost::polygon::segment_data<int>;

struct Reference
{
  std::vector<std::array<double, 3>> Junctions;
};

Reference VoronoiJunctions(const std::vector<std::vector<std::array<long long, 2>>>& loops, vtkPolyData* poly)
{
  std::vector<ISegment> segments;
  for (const auto& l : loops)
  {
    for (size_t i = 0; i < l.size(); ++i)
    {
      const auto& a = l[i];
      const auto& b = l[(i + 1) % l.size()];
      segments.emplace_back(IPoint(static_cast<int>(a[0]), static_cast<int>(a[1])), IPoint(static_cast<int>(b[0]), static_cast<int>(b[1])));
    }
  }
  boost::polygon::voronoi_diagram<double> vd;
  boost::polygon::construct_voronoi(segments.begin(), segments.end(), &vd);

  // Distance to the boundary, and inside test (even-odd over all loops).
  auto boundaryDistance = [&](double x, double y) {
    double best = HUGE_VAL;
    for (const auto& s : segments)
    {
      const double ax = s.low().x(), ay = s.low().y(), bx = s.high().x(), by = s.high().y();
      const double dx = bx - ax, dy = by - ay;
      double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
      t = std::max(0.0, std::min(1.0, t));
      best = std::min(best, std::hypot(ax + t * dx - x, ay + t * dy - y));
    }
    return best;
  };
  auto inside = [&](double x, double y) {
    bool in = false;
    for (const auto& s : segments)
    {
      const double ax = s.low().x(), ay = s.low().y(), bx = s.high().x(), by = s.high().y();
      if ((ay > y) != (by > y) && x < (bx - ax) * (y - ay) / (by - ay) + ax)
      {
        in = !in;
      }
    }
    return in;
  };
  const double diag = Diagonal(poly);
  Reference ref;
  for (const auto& v : vd.vertices())
  {
    // Sites around the vertex: (segment index, which end: 0 low, 1 high, -1 the segment itself).
    std::set<std::pair<size_t, int>> sites;
    const auto* edge = v.incident_edge();
    do
    {
      const auto* cell = edge->cell();
      const size_t s = cell->source_index();
      int which = -1;
      if (cell->contains_point())
      {
        which = cell->source_category() == boost::polygon::SOURCE_CATEGORY_SEGMENT_START_POINT ? 0 : 1;
      }
      sites.insert({ s, which });
      edge = edge->rot_next();
    } while (edge != v.incident_edge());
    // Points: identify by coordinates (each polygon vertex is the end of two segments).
    std::set<std::pair<long long, long long>> points;
    std::set<size_t> segs;
    for (const auto& s : sites)
    {
      if (s.second < 0)
      {
        segs.insert(s.first);
      }
      else
      {
        const auto& p = s.second == 0 ? segments[s.first].low() : segments[s.first].high();
        points.insert({ p.x(), p.y() });
      }
    }
    // A segment touched at one of its own end points counts as that point.
    int governors = static_cast<int>(points.size());
    for (size_t s : segs)
    {
      const auto& a = segments[s].low();
      const auto& b = segments[s].high();
      if (!points.count({ a.x(), a.y() }) && !points.count({ b.x(), b.y() }))
      {
        ++governors;
      }
    }
    if (governors < 3 || !inside(v.x(), v.y()) || boundaryDistance(v.x(), v.y()) < 1e-9 * diag)
    {
      continue;
    }
    // Voronoi vertices of several sites at one point come as close copies: keep one.
    bool duplicate = false;
    for (const auto& j : ref.Junctions)
    {
      duplicate = duplicate || std::hypot(j[0] - v.x(), j[1] - v.y()) < 1e-8 * diag;
    }
    if (!duplicate)
    {
      ref.Junctions.push_back({ v.x(), v.y(), 0.0 });
    }
  }
  return ref;
}

std::vector<std::array<long long, 2>> RandomStar(std::mt19937_64& rng, int n, double rMin, double rMax)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i)
  {
    angles.push_back(2.0 * 3.14159265358979323846 * unit(rng));
  }
  std::sort(angles.begin(), angles.end());
  std::vector<std::array<long long, 2>> loop;
  for (double a : angles)
  {
    const double r = rMin + (rMax - rMin) * unit(rng);
    const std::array<long long, 2> p = { std::llround(r * std::cos(a)), std::llround(r * std::sin(a)) };
    if (loop.empty() || p != loop.back())
    {
      loop.push_back(p); // Boost's diagram needs non-degenerate segments
    }
  }
  if (loop.size() > 1 && loop.front() == loop.back())
  {
    loop.pop_back();
  }
  return loop;
}
}

int TestMedialJunctionOracle(int, char*[])
{
  std::mt19937_64 rng(20261124);
  double worst = 0.0;
  int total = 0, tested = 0;
  // MEDIAL_ORACLE_TRIALS raises the count for a longer soak outside ctest.
  const int trials = getenv("MEDIAL_ORACLE_TRIALS") ? std::atoi(getenv("MEDIAL_ORACLE_TRIALS")) : 40;
  for (int trial = 0; trial < trials; ++trial)
  {
    const int n = 6 + static_cast<int>(rng() % (trial < 40 ? 40 : 400));
    // MEDIAL_ORACLE_SCALE < 1 shrinks the grid: rounding then makes many exact
    // degeneracies (parallel and collinear edges, co-circular vertices).
    const double scale = getenv("MEDIAL_ORACLE_SCALE") ? std::atof(getenv("MEDIAL_ORACLE_SCALE")) : 1.0;
    std::vector<std::vector<std::array<long long, 2>>> loops = { RandomStar(rng, n, 300 * scale, 1000 * scale) };
    if (trial % 4 == 1)
    {
      // A small hole inside the star's kernel: a random triangle or quadrilateral.
      loops.push_back(RandomStar(rng, 3 + static_cast<int>(rng() % 2), 60 * scale, 200 * scale));
    }
    else if (trial % 4 == 3)
    {
      // Two holes side by side (a trial whose loops cross is skipped below).
      for (long long shift : { -140, 140 })
      {
        auto hole = RandomStar(rng, 3 + static_cast<int>(rng() % 3), 30 * scale, 100 * scale);
        for (auto& p : hole)
        {
          p[0] += std::llround(shift * scale);
        }
        loops.push_back(hole);
      }
    }
    std::vector<Loop2> dloops;
    for (const auto& l : loops)
    {
      Loop2 d;
      for (const auto& p : l)
      {
        d.push_back({ static_cast<double>(p[0]), static_cast<double>(p[1]) });
      }
      dloops.push_back(d);
    }
    auto poly = MakePolygon(dloops);
    EventLog log;
    vtkNew<vtkMedialJunctionFilter> filter;
    log.Watch(filter);
    filter->SetInputData(poly);
    filter->Update();
    if (log.Errors > 0 || filter->GetNumberOfPolygons() != 1)
    {
      // Rounding to integers made the loop self-intersecting or degenerate, or a hole
      // fell outside the star (then it is a second polygon): skip it.
      continue;
    }
    ++tested;
    if (getenv("MEDIAL_ORACLE_DEBUG") && log.Warnings > 0)
    {
      for (const auto& l : loops)
      {
        for (const auto& p : l)
        {
          std::printf("(%lld,%lld) ", p[0], p[1]);
        }
        std::printf("\n");
      }
    }
    MEDIAL_CHECK(log.Warnings == 0, "trial %d: %s", trial, log.Text.c_str());
    // The medial graph of a region with h holes is connected with h independent cycles.
    {
      vtkPolyData* graph = filter->GetOutput();
      std::vector<vtkIdType> parent(static_cast<size_t>(graph->GetNumberOfPoints()));
      for (size_t i = 0; i < parent.size(); ++i)
      {
        parent[i] = static_cast<vtkIdType>(i);
      }
      std::function<vtkIdType(vtkIdType)> root = [&](vtkIdType x) {
        return parent[x] == x ? x : parent[x] = root(parent[x]);
      };
      std::set<vtkIdType> nodes;
      vtkIdType npts;
      const vtkIdType* ids;
      for (graph->GetLines()->InitTraversal(); graph->GetLines()->GetNextCell(npts, ids);)
      {
        nodes.insert(ids[0]);
        nodes.insert(ids[npts - 1]);
        parent[root(ids[0])] = root(ids[npts - 1]);
      }
      std::set<vtkIdType> components;
      for (vtkIdType n : nodes)
      {
        components.insert(root(n));
      }
      const long long cycles = graph->GetNumberOfLines() - static_cast<long long>(nodes.size()) + 1;
      if (getenv("MEDIAL_ORACLE_DEBUG") && (components.size() != 1 || cycles != static_cast<long long>(loops.size()) - 1))
      {
        for (const auto& l : loops)
        {
          for (const auto& p : l)
          {
            std::printf("(%lld,%lld) ", p[0], p[1]);
          }
          std::printf("\n");
        }
      }
      MEDIAL_CHECK(components.size() == 1 && cycles == static_cast<long long>(loops.size()) - 1,
        "trial %d: graph has %zu components and %lld cycles for %zu holes", trial, components.size(), cycles,
        loops.size() - 1);
    }
    const Reference ref = VoronoiJunctions(loops, poly);
    const auto found = NodesOfType(filter->GetOutput(), vtkMedialJunctionFilter::JUNCTION_POINT);
    const double diag = Diagonal(poly);
    const double missing = MatchError(found, ref.Junctions) / diag;
    std::vector<MedialNode> refNodes;
    for (const auto& j : ref.Junctions)
    {
      refNodes.push_back({ { j[0], j[1], j[2] }, 0.0, 3 });
    }
    std::vector<std::array<double, 3>> foundPoints;
    for (const auto& f : found)
    {
      foundPoints.push_back({ f.X[0], f.X[1], f.X[2] });
    }
    const double extra = MatchError(refNodes, foundPoints) / diag;
    worst = std::max({ worst, missing, extra });
    total += static_cast<int>(ref.Junctions.size());
    if (found.size() != ref.Junctions.size() || missing > 1e-6 || extra > 1e-6)
    {
      std::printf("trial %d (%d vertices, %zu loops): %zu junctions, reference %zu, missing error %.3g, "
                  "extra error %.3g\n",
        trial, n, loops.size(), found.size(), ref.Junctions.size(), missing, extra);
    }
    if (getenv("MEDIAL_ORACLE_DEBUG") && found.size() != ref.Junctions.size())
    {
      for (const auto& l : loops) { for (const auto& p : l) std::printf("(%lld,%lld) ", p[0], p[1]); std::printf("\n"); }
      for (const auto& f : found)
      {
        double best = HUGE_VAL;
        for (const auto& j : ref.Junctions) best = std::min(best, std::hypot(j[0] - f.X[0], j[1] - f.X[1]));
        std::printf("found %.6f %.6f r %.6f gov %d  nearest ref %.3g\n", f.X[0], f.X[1], f.Radius, f.Governors, best);
      }
    }
    MEDIAL_CHECK(found.size() == ref.Junctions.size(), "trial %d: junction count", trial);
    MEDIAL_CHECK(missing <= 1e-6 && extra <= 1e-6, "trial %d: junction position", trial);
  }
  std::printf("%d random polygons, %d reference junctions, max junction error %.3g diagonal\n", tested, total, worst);
  MEDIAL_CHECK(tested >= trials / 2 || getenv("MEDIAL_ORACLE_SCALE"), "too few valid random polygons (%d)", tested);
  return EXIT_SUCCESS;
}
