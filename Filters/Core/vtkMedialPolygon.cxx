// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPolygon.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPlane.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace
{
double Cross2(const double a[2], const double b[2], const double c[2])
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Closed segments [a,b] and [c,d] share a point.
bool SegmentsTouch(const double a[2], const double b[2], const double c[2], const double d[2])
{
  const double d1 = Cross2(c, d, a), d2 = Cross2(c, d, b);
  const double d3 = Cross2(a, b, c), d4 = Cross2(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
  {
    return true;
  }
  auto onSegment = [](const double p[2], const double q[2], const double r[2]) {
    return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
      std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) ||
    (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
}

double SignedArea(const std::vector<double>& pts, const std::vector<int>& loop)
{
  double a = 0.0;
  for (size_t i = 0; i < loop.size(); ++i)
  {
    const double* p = &pts[2 * loop[i]];
    const double* q = &pts[2 * loop[(i + 1) % loop.size()]];
    a += p[0] * q[1] - p[1] * q[0];
  }
  return 0.5 * a;
}

bool InsideLoop(const std::vector<double>& pts, const std::vector<int>& loop, const double x[2])
{
  bool inside = false;
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
  {
    const double* p = &pts[2 * loop[i]];
    const double* q = &pts[2 * loop[j]];
    if ((p[1] > x[1]) != (q[1] > x[1]) &&
      x[0] < (q[0] - p[0]) * (x[1] - p[1]) / (q[1] - p[1]) + p[0])
    {
      inside = !inside;
    }
  }
  return inside;
}
}

// Loops as the passes of Build see them: merged 3D points, then vertex indices per
// loop with the input cell each came from.
struct vtkMedialPolygon::LoopSet
{
  std::vector<std::array<double, 3>> XYZ; // merged points
  std::vector<int> Canonical;             // input point -> merged point
  std::vector<std::vector<int>> Loops;
  std::vector<vtkIdType> LoopCells;
  std::vector<std::vector<int>> Open; // open polylines, chained into loops
  std::vector<vtkIdType> OpenCells;
  double Diagonal3D = 0.0;      // of the loops' bounding box
  std::vector<double> Points2D; // merged points in the plane's frame
};

bool vtkMedialPolygon::Build(vtkPolyData* input, std::string& error)
{
  this->Points.clear();
  this->Edges.clear();
  this->LoopEdges.clear();
  this->LoopPolygons.clear();
  this->PolygonDiagonals.clear();
  this->NumberOfPolygons = 0;
  LoopSet set;
  // The passes of the class comment, in order; each one stops at the first problem.
  return this->MergePoints(input, set, error) && this->ReadLoops(input, set, error) &&
    this->ChainOpenPolylines(set, error) && this->FitFrame(set, error) && this->ProjectLoops(set, error) &&
    this->CleanLoops(set, error) && this->OrientLoops(set, error) && this->MeasurePolygons();
}

// 1. Merges coincident points; keeps the 3D coordinates of the canonical points.
bool vtkMedialPolygon::MergePoints(vtkPolyData* input, LoopSet& set, std::string& error) const
{
  const vtkIdType np = input ? input->GetNumberOfPoints() : 0;
  if (np == 0)
  {
    error = "input has no points";
    return false;
  }
  set.Canonical.resize(static_cast<size_t>(np));
  std::map<std::array<double, 3>, int> seen;
  for (vtkIdType i = 0; i < np; ++i)
  {
    std::array<double, 3> p;
    input->GetPoint(i, p.data());
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "input has NaN or infinite coordinates";
      return false;
    }
    auto it = seen.emplace(p, static_cast<int>(set.XYZ.size())).first;
    if (it->second == static_cast<int>(set.XYZ.size()))
    {
      set.XYZ.push_back(p);
    }
    set.Canonical[i] = it->second;
  }
  return true;
}

// 2. Loops: polygon cells and closed polylines; open polylines are kept for chaining.
// Polygons that share edges are a planar mesh (e.g. a triangulated polygon): its
// region is bounded by the edges used once, which join the open polylines.
bool vtkMedialPolygon::ReadLoops(vtkPolyData* input, LoopSet& set, std::string& error) const
{
  vtkIdType cellId = 0;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* verts = input->GetVerts();
  cellId += verts ? verts->GetNumberOfCells() : 0;
  auto cellLoop = [&]() {
    std::vector<int> l;
    for (vtkIdType i = 0; i < npts; ++i)
    {
      l.push_back(set.Canonical[ids[i]]);
    }
    return l;
  };
  if (vtkCellArray* lines = input->GetLines())
  {
    for (lines->InitTraversal(); lines->GetNextCell(npts, ids); ++cellId)
    {
      std::vector<int> l = cellLoop();
      if (l.size() >= 2 && l.front() == l.back())
      {
        l.pop_back();
        set.Loops.push_back(l);
        set.LoopCells.push_back(cellId);
      }
      else if (l.size() >= 2)
      {
        set.Open.push_back(l);
        set.OpenCells.push_back(cellId);
      }
    }
  }
  const size_t firstPolygon = set.Loops.size();
  if (vtkCellArray* polys = input->GetPolys())
  {
    for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++cellId)
    {
      set.Loops.push_back(cellLoop());
      set.LoopCells.push_back(cellId);
    }
  }
  if (input->GetNumberOfStrips() > 0)
  {
    error = "input has triangle strips, not planar loops";
    return false;
  }
  SharedEdgesToPolylines(set, firstPolygon);
  return true;
}

// Polygons from `firstPolygon` on that share an edge become their boundary: the
// edges used once, as two-point open polylines.
void vtkMedialPolygon::SharedEdgesToPolylines(LoopSet& set, size_t firstPolygon)
{
  std::map<std::pair<int, int>, int> uses;
  bool shared = false;
  for (size_t i = firstPolygon; i < set.Loops.size(); ++i)
  {
    // An edge counts once per polygon (a 2-point polygon runs it both ways).
    std::set<std::pair<int, int>> own;
    const auto& l = set.Loops[i];
    for (size_t k = 0; k < l.size(); ++k)
    {
      const int a = l[k], b = l[(k + 1) % l.size()];
      if (a != b)
      {
        own.insert({ std::min(a, b), std::max(a, b) });
      }
    }
    for (const auto& e : own)
    {
      shared = ++uses[e] > 1 || shared;
    }
  }
  if (!shared)
  {
    return;
  }
  for (size_t i = firstPolygon; i < set.Loops.size(); ++i)
  {
    const auto& l = set.Loops[i];
    for (size_t k = 0; k < l.size(); ++k)
    {
      const int a = l[k], b = l[(k + 1) % l.size()];
      if (a != b && uses[{ std::min(a, b), std::max(a, b) }] == 1)
      {
        set.Open.push_back({ a, b });
        set.OpenCells.push_back(set.LoopCells[i]);
      }
    }
  }
  set.Loops.resize(firstPolygon);
  set.LoopCells.resize(firstPolygon);
}

// 2. Chains open polylines sharing end points into loops; every end must meet exactly
// one other end.
bool vtkMedialPolygon::ChainOpenPolylines(LoopSet& set, std::string& error) const
{
  const auto& open = set.Open;
  std::map<int, std::vector<int>> ends;
  for (size_t i = 0; i < open.size(); ++i)
  {
    ends[open[i].front()].push_back(static_cast<int>(i));
    ends[open[i].back()].push_back(static_cast<int>(i));
  }
  for (const auto& kv : ends)
  {
    if (kv.second.size() != 2)
    {
      std::ostringstream os;
      os << (kv.second.size() < 2 ? "open polyline: an end point meets no other polyline"
                                  : "polylines branch at a point")
         << " (point " << kv.first << ")";
      error = os.str();
      return false;
    }
  }
  std::vector<bool> used(open.size(), false);
  for (size_t s = 0; s < open.size(); ++s)
  {
    if (used[s])
    {
      continue;
    }
    used[s] = true;
    std::vector<int> chain = open[s];
    while (chain.back() != chain.front())
    {
      int next = -1;
      for (int c : ends[chain.back()])
      {
        if (!used[c])
        {
          next = c;
        }
      }
      if (next < 0)
      {
        error = "open polyline: chained polylines do not close";
        return false;
      }
      used[next] = true;
      std::vector<int> piece = open[next];
      if (piece.front() != chain.back())
      {
        std::reverse(piece.begin(), piece.end());
      }
      chain.insert(chain.end(), piece.begin() + 1, piece.end());
    }
    chain.pop_back();
    set.Loops.push_back(chain);
    set.LoopCells.push_back(set.OpenCells[s]);
  }
  if (set.Loops.empty())
  {
    error = "input has no polygons or closed polylines";
    return false;
  }
  return true;
}

// 3. The plane: Newell normal of the loop with the largest one (or, with no net area,
// the plane of the widest vertex triangle), sign made canonical; the frame's origin
// is the loops' bounding-box centre moved onto the plane, U = axis x N, V = N x U
// with `axis` the world axis most perpendicular to N.
bool vtkMedialPolygon::FitFrame(LoopSet& set, std::string& error)
{
  const auto& xyz = set.XYZ;
  double best = -1.0, normal[3] = { 0, 0, 1 };
  for (const auto& l : set.Loops)
  {
    double n[3];
    vtkMedialPlane::NewellNormal(static_cast<vtkIdType>(l.size()),
      [&](vtkIdType i, double p[3]) { std::copy(xyz[l[i]].begin(), xyz[l[i]].end(), p); }, n);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > best)
    {
      best = len;
      for (int k = 0; k < 3; ++k)
      {
        normal[k] = len > 0 ? n[k] / len : 0.0;
      }
    }
  }
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const auto& l : set.Loops)
  {
    for (int v : l)
    {
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], xyz[v][k]);
        hi[k] = std::max(hi[k], xyz[v][k]);
      }
    }
  }
  const double diag3 = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if (!(diag3 > 0.0))
  {
    error = "a loop has fewer than 3 distinct vertices";
    return false;
  }
  if (!(best > 1e-12 * diag3 * diag3) && !(WidestTriangleNormal(set, normal) > 1e-12 * diag3 * diag3))
  {
    error = "a loop has fewer than 3 distinct vertices (all points collinear)";
    return false;
  }
  vtkMedialPlane::CanonicalSign(normal);
  double* origin = this->Frame[0];
  double* u = this->Frame[1];
  double* v = this->Frame[2];
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = 0.5 * (lo[k] + hi[k]);
    this->Frame[3][k] = normal[k];
  }
  // Put the origin on the plane (through the mean of the vertices).
  double mean[3] = { 0, 0, 0 };
  size_t count = 0;
  for (const auto& l : set.Loops)
  {
    for (int p : l)
    {
      for (int k = 0; k < 3; ++k)
      {
        mean[k] += xyz[p][k];
      }
      ++count;
    }
  }
  double off = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    off += (mean[k] / count - origin[k]) * normal[k];
  }
  for (int k = 0; k < 3; ++k)
  {
    origin[k] += off * normal[k];
  }
  double axis[3] = { 0, 0, 0 };
  axis[vtkMedialPlane::LeastAxis(normal)] = 1.0;
  // u = axis x n, v = n x u: (u, v, n) is right-handed.
  u[0] = axis[1] * normal[2] - axis[2] * normal[1];
  u[1] = axis[2] * normal[0] - axis[0] * normal[2];
  u[2] = axis[0] * normal[1] - axis[1] * normal[0];
  const double ul = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (int k = 0; k < 3; ++k)
  {
    u[k] /= ul;
  }
  v[0] = normal[1] * u[2] - normal[2] * u[1];
  v[1] = normal[2] * u[0] - normal[0] * u[2];
  v[2] = normal[0] * u[1] - normal[1] * u[0];
  set.Diagonal3D = diag3;
  return true;
}

// Loops with no net area (e.g. a bow tie): the unit normal of the widest triangle of
// the first vertex, the farthest vertex from it and any other vertex, so that the
// validation names the real problem. Returns that triangle's doubled area.
double vtkMedialPolygon::WidestTriangleNormal(const LoopSet& set, double normal[3])
{
  const auto& xyz = set.XYZ;
  const auto& p0 = xyz[set.Loops[0][0]];
  std::array<double, 3> far = p0;
  double farthest = 0.0;
  for (const auto& l : set.Loops)
  {
    for (int v : l)
    {
      const double d = std::hypot(std::hypot(xyz[v][0] - p0[0], xyz[v][1] - p0[1]), xyz[v][2] - p0[2]);
      if (d > farthest)
      {
        farthest = d;
        far = xyz[v];
      }
    }
  }
  double best = 0.0;
  for (const auto& l : set.Loops)
  {
    for (int v : l)
    {
      const double a[3] = { far[0] - p0[0], far[1] - p0[1], far[2] - p0[2] };
      const double b[3] = { xyz[v][0] - p0[0], xyz[v][1] - p0[1], xyz[v][2] - p0[2] };
      const double n[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (len > best)
      {
        best = len;
        for (int k = 0; k < 3; ++k)
        {
          normal[k] = n[k] / len;
        }
      }
    }
  }
  return best;
}

// 3. The points in the plane's frame; every point of a loop must lie within 1e-6 of the
// diagonal from the plane.
bool vtkMedialPolygon::ProjectLoops(LoopSet& set, std::string& error) const
{
  const auto& xyz = set.XYZ;
  const double* origin = this->Frame[0];
  const double* u = this->Frame[1];
  const double* v = this->Frame[2];
  const double* normal = this->Frame[3];
  std::vector<bool> inLoop(xyz.size(), false);
  for (const auto& l : set.Loops)
  {
    for (int p : l)
    {
      inLoop[p] = true;
    }
  }
  auto& pts2 = set.Points2D;
  pts2.resize(2 * xyz.size());
  for (size_t i = 0; i < xyz.size(); ++i)
  {
    double d[3], h = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d[k] = xyz[i][k] - origin[k];
      h += d[k] * normal[k];
    }
    pts2[2 * i] = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    pts2[2 * i + 1] = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    if (std::abs(h) > 1e-6 * set.Diagonal3D && inLoop[i]) // only points used by a loop matter
    {
      std::ostringstream os;
      os << "loops are not coplanar (a point lies " << std::abs(h) / set.Diagonal3D
         << " diagonals off their plane)";
      error = os.str();
      return false;
    }
  }
  return true;
}

// 4. Drops repeated points and straight (180 degree) vertices; a loop needs 3
// distinct vertices.
bool vtkMedialPolygon::CleanLoops(LoopSet& set, std::string& error)
{
  const auto& pts2 = set.Points2D;
  for (auto& l : set.Loops)
  {
    bool changed = true;
    while (changed && l.size() >= 3)
    {
      changed = false;
      for (size_t i = 0; i < l.size() && l.size() >= 3; ++i)
      {
        const size_t n = l.size();
        const double* a = &pts2[2 * l[(i + n - 1) % n]];
        const double* b = &pts2[2 * l[i]];
        const double* c = &pts2[2 * l[(i + 1) % n]];
        const bool repeated = (a[0] == b[0] && a[1] == b[1]);
        const bool straight = Cross2(a, b, c) == 0.0 &&
          ((c[0] - b[0]) * (b[0] - a[0]) + (c[1] - b[1]) * (b[1] - a[1])) > 0.0;
        if (repeated || straight)
        {
          l.erase(l.begin() + static_cast<long>(i));
          changed = true;
          --i;
        }
      }
    }
    if (l.size() < 3)
    {
      error = "a loop has fewer than 3 distinct vertices";
      return false;
    }
  }
  return true;
}

// 5. Nesting and orientation: a loop inside an even number of others is an outer
// boundary, made counter-clockwise; inside an odd number, a hole of the smallest loop
// around it, made clockwise. Each outer boundary with its holes is one polygon. Then
// the edges, vertex kinds and the grid, and the check that no two edges touch.
bool vtkMedialPolygon::OrientLoops(LoopSet& set, std::string& error)
{
  const auto& loops = set.Loops;
  const auto& pts2 = set.Points2D;
  std::vector<double> areas;
  for (const auto& l : loops)
  {
    areas.push_back(SignedArea(pts2, l));
  }
  std::vector<int> parent, depth;
  NestLoops(set, areas, parent, depth);
  // Polygons by decreasing outer area (input order on ties); in each, the outer loop
  // first, then its holes in input order: deterministic ids.
  std::vector<int> outers;
  for (size_t i = 0; i < loops.size(); ++i)
  {
    if (depth[i] % 2 == 0)
    {
      outers.push_back(static_cast<int>(i));
    }
  }
  std::stable_sort(outers.begin(), outers.end(),
    [&](int a, int b) { return std::abs(areas[a]) > std::abs(areas[b]); });
  std::vector<int> order;
  this->LoopPolygons.clear();
  for (size_t p = 0; p < outers.size(); ++p)
  {
    order.push_back(outers[p]);
    for (size_t i = 0; i < loops.size(); ++i)
    {
      if (parent[i] == outers[p] && depth[i] % 2 == 1)
      {
        order.push_back(static_cast<int>(i));
      }
    }
    this->LoopPolygons.resize(order.size(), static_cast<int>(p));
  }
  this->NumberOfPolygons = static_cast<int>(outers.size());
  this->NumberOfLoops = static_cast<int>(loops.size());
  this->LoopEdges.assign(loops.size(), {});
  for (int li = 0; li < this->NumberOfLoops; ++li)
  {
    const int i = order[li];
    std::vector<int> ordered = loops[i];
    if ((depth[i] % 2 == 0) != (areas[i] > 0.0))
    {
      std::reverse(ordered.begin(), ordered.end());
    }
    this->AddLoop(pts2, ordered, li, set.LoopCells[i]);
  }
  this->ClassifyVertices();
  this->BuildGrid();
  if (!this->CheckTouchingEdges(error))
  {
    return false;
  }
  if (!(std::abs(areas[outers.front()]) > 0.0))
  {
    error = "loops enclose no area";
    return false;
  }
  return true;
}

// The loop directly around each loop (-1 for none) and how many loops surround it.
// Loops do not cross (CheckTouchingEdges rejects them otherwise), so a loop is inside
// another when one of its vertices is; only larger loops whose box holds it are tried.
void vtkMedialPolygon::NestLoops(
  const LoopSet& set, const std::vector<double>& areas, std::vector<int>& parent, std::vector<int>& depth)
{
  const auto& loops = set.Loops;
  const auto& pts2 = set.Points2D;
  const size_t n = loops.size();
  std::vector<std::array<double, 4>> boxes(n, { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL });
  for (size_t i = 0; i < n; ++i)
  {
    for (int v : loops[i])
    {
      boxes[i][0] = std::min(boxes[i][0], pts2[2 * v]);
      boxes[i][1] = std::max(boxes[i][1], pts2[2 * v]);
      boxes[i][2] = std::min(boxes[i][2], pts2[2 * v + 1]);
      boxes[i][3] = std::max(boxes[i][3], pts2[2 * v + 1]);
    }
  }
  parent.assign(n, -1);
  depth.assign(n, 0);
  for (size_t i = 0; i < n; ++i)
  {
    const double* p = &pts2[2 * loops[i][0]];
    for (size_t j = 0; j < n; ++j)
    {
      const auto& b = boxes[j];
      if (j == i || std::abs(areas[j]) <= std::abs(areas[i]) || p[0] < b[0] || p[0] > b[1] || p[1] < b[2] ||
        p[1] > b[3] || !InsideLoop(pts2, loops[j], p))
      {
        continue;
      }
      ++depth[i];
      if (parent[i] < 0 || std::abs(areas[j]) < std::abs(areas[parent[i]]))
      {
        parent[i] = static_cast<int>(j);
      }
    }
  }
}

// Appends loop `li` (vertices in boundary order, interior on the left) and its edges.
void vtkMedialPolygon::AddLoop(const std::vector<double>& pts2, const std::vector<int>& l, int li, vtkIdType cell)
{
  const int first = static_cast<int>(this->Points.size() / 2);
  for (int p : l)
  {
    this->Points.push_back(pts2[2 * p]);
    this->Points.push_back(pts2[2 * p + 1]);
  }
  const int n = static_cast<int>(l.size());
  for (int i = 0; i < n; ++i)
  {
    Edge e;
    e.A = first + i;
    e.B = first + (i + 1) % n;
    e.Loop = li;
    e.SourceCell = cell;
    const double* a = this->GetPoint(e.A);
    const double* b = this->GetPoint(e.B);
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    e.Length = std::sqrt(dx * dx + dy * dy);
    e.Normal[0] = -dy / e.Length;
    e.Normal[1] = dx / e.Length;
    e.Offset = -(e.Normal[0] * a[0] + e.Normal[1] * a[1]);
    this->LoopEdges[li].push_back(static_cast<int>(this->Edges.size()));
    this->Edges.push_back(e);
  }
}

// Incoming and outgoing edges, convex or reflex, and the diagonal of the 2D points.
void vtkMedialPolygon::ClassifyVertices()
{
  const int nv = this->GetNumberOfVertices();
  this->Kinds.assign(nv, CONVEX);
  this->Incoming.assign(nv, -1);
  this->Outgoing.assign(nv, -1);
  for (int e = 0; e < this->GetNumberOfEdges(); ++e)
  {
    this->Outgoing[this->Edges[e].A] = e;
    this->Incoming[this->Edges[e].B] = e;
  }
  for (int vtx = 0; vtx < nv; ++vtx)
  {
    const Edge& in = this->Edges[this->Incoming[vtx]];
    const Edge& out = this->Edges[this->Outgoing[vtx]];
    this->Kinds[vtx] =
      Cross2(this->GetPoint(in.A), this->GetPoint(vtx), this->GetPoint(out.B)) < 0.0 ? REFLEX : CONVEX;
  }
  double lo2[2] = { HUGE_VAL, HUGE_VAL }, hi2[2] = { -HUGE_VAL, -HUGE_VAL };
  for (int i = 0; i < nv; ++i)
  {
    for (int k = 0; k < 2; ++k)
    {
      lo2[k] = std::min(lo2[k], this->Points[2 * i + k]);
      hi2[k] = std::max(hi2[k], this->Points[2 * i + k]);
    }
  }
  this->Diagonal = std::sqrt((hi2[0] - lo2[0]) * (hi2[0] - lo2[0]) + (hi2[1] - lo2[1]) * (hi2[1] - lo2[1]));
}

// No edge may touch another, except neighbours at their shared vertex. Two touching
// edges share the grid cell of the touching point.
bool vtkMedialPolygon::CheckTouchingEdges(std::string& error) const
{
  for (vtkIdType cell = 0; cell < this->Grid.GetNumberOfCells(); ++cell)
  {
    const vtkIdType* first = this->Grid.CellBegin(cell);
    const vtkIdType* last = this->Grid.CellEnd(cell);
    for (const vtkIdType* i = first; i < last; ++i)
    {
      for (const vtkIdType* j = i + 1; j < last; ++j)
      {
        const int e = static_cast<int>(std::min(*i, *j));
        const int f = static_cast<int>(std::max(*i, *j));
        if (e == f || !this->EdgesTouch(e, f))
        {
          continue;
        }
        double x[3], y[3];
        this->To3D(this->GetPoint(this->Edges[e].A), x);
        this->To3D(this->GetPoint(this->Edges[f].A), y);
        std::ostringstream os;
        os << "loops intersect themselves or each other (self-intersecting polygon): the edge from ("
           << x[0] << ", " << x[1] << ", " << x[2] << ") meets the edge from (" << y[0] << ", " << y[1]
           << ", " << y[2] << ")";
        error = os.str();
        return false;
      }
    }
  }
  return true;
}

// 6. The diagonal of each polygon's box (its outer loop's), for per-polygon densities.
bool vtkMedialPolygon::MeasurePolygons()
{
  this->PolygonDiagonals.assign(static_cast<size_t>(this->NumberOfPolygons), 0.0);
  for (int li = 0; li < this->NumberOfLoops; ++li)
  {
    double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
    for (int e : this->LoopEdges[li])
    {
      const double* p = this->GetPoint(this->Edges[e].A);
      for (int k = 0; k < 2; ++k)
      {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
    double& diagonal = this->PolygonDiagonals[this->LoopPolygons[li]];
    diagonal = std::max(diagonal, std::hypot(hi[0] - lo[0], hi[1] - lo[1]));
  }
  return true;
}

bool vtkMedialPolygon::EdgesTouch(int e, int f) const
{
  const Edge& E = this->Edges[e];
  const Edge& F = this->Edges[f];
  const double* a = this->GetPoint(E.A);
  const double* b = this->GetPoint(E.B);
  const double* c = this->GetPoint(F.A);
  const double* d = this->GetPoint(F.B);
  if (F.A == E.B && F.B == E.A)
  {
    return true; // a two-edge loop
  }
  if (F.A == E.B || F.B == E.A)
  {
    // Neighbours share a vertex; they must not fold back onto each other.
    const double* shared = F.A == E.B ? b : a;
    const double* p = F.A == E.B ? a : b;
    const double* q = F.A == E.B ? d : c;
    return Cross2(p, shared, q) == 0.0 &&
      (q[0] - shared[0]) * (p[0] - shared[0]) + (q[1] - shared[1]) * (p[1] - shared[1]) > 0.0;
  }
  return SegmentsTouch(a, b, c, d);
}

void vtkMedialPolygon::BuildGrid()
{
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
  const int nv = this->GetNumberOfVertices();
  for (int i = 0; i < nv; ++i)
  {
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = std::min(lo[k], this->Points[2 * i + k]);
      hi[k] = std::max(hi[k], this->Points[2 * i + k]);
    }
  }
  const double w = std::max(hi[0] - lo[0], 1e-300), h = std::max(hi[1] - lo[1], 1e-300);
  const double ne = std::max<double>(1, this->Edges.size());
  // About two cells per edge.
  const double size = std::max(std::sqrt(w * h / (2.0 * ne)), 1e-3 * std::max(w, h));
  double origin[3] = { 0, 0, 0 };
  const double cellSize[3] = { size, size, size };
  int dims[3] = { 1, 1, 1 };
  for (int k = 0; k < 2; ++k)
  {
    const double ext = (k == 0 ? w : h);
    dims[k] = std::max(1, std::min(4096, static_cast<int>(std::ceil(ext / size)) + 1));
    origin[k] = lo[k] - 0.5 * (dims[k] * size - ext);
  }
  this->Grid.Initialize(origin, cellSize, dims);
  // An edge goes into every cell whose centre lies within half a cell diagonal of it.
  const double halfDiag = size * 0.7072;
  this->Grid.Build(this->GetNumberOfEdges(), [&](vtkIdType item, auto&& add) {
    const int e = static_cast<int>(item);
    const double* a = this->GetPoint(this->Edges[e].A);
    const double* b = this->GetPoint(this->Edges[e].B);
    const int i0 = this->Grid.Coordinate(std::min(a[0], b[0]), 0);
    const int i1 = this->Grid.Coordinate(std::max(a[0], b[0]), 0);
    const int j0 = this->Grid.Coordinate(std::min(a[1], b[1]), 1);
    const int j1 = this->Grid.Coordinate(std::max(a[1], b[1]), 1);
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double c[2] = { this->Grid.GetOrigin(0) + (i + 0.5) * size, this->Grid.GetOrigin(1) + (j + 0.5) * size };
        double q[2];
        if (this->ClosestPointOnEdge(e, c, nullptr, q) <= halfDiag * halfDiag)
        {
          add(this->Grid.CellId(i, j, 0));
        }
      }
    }
  });
  // Closest-point searches skip the rings of empty cells around x (empty disks are
  // large and empty).
  this->EmptyRings = this->Grid.DistanceToItems();
}

void vtkMedialPolygon::CellBox(const double x[2], double reach, int lo[3], int hi[3]) const
{
  for (int k = 0; k < 2; ++k)
  {
    lo[k] = this->Grid.Coordinate(x[k] - reach, k);
    hi[k] = this->Grid.Coordinate(x[k] + reach, k);
  }
  lo[2] = hi[2] = 0;
}

void vtkMedialPolygon::To3D(const double p[2], double x[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    x[k] = this->Frame[0][k] + p[0] * this->Frame[1][k] + p[1] * this->Frame[2][k];
  }
}

double vtkMedialPolygon::ClosestPointOnEdge(
  int e, const double x[2], const ContactFilter* filter, double out[2]) const
{
  const double* a = this->GetPoint(this->Edges[e].A);
  const double* b = this->GetPoint(this->Edges[e].B);
  double t0 = 0.0, t1 = 1.0;
  const double d[2] = { b[0] - a[0], b[1] - a[1] };
  if (filter && filter->UseCap)
  {
    // Keep the part where Cap . (a + t d) <= CapLimit.
    const double s0 = filter->Cap[0] * a[0] + filter->Cap[1] * a[1] - filter->CapLimit;
    const double sd = filter->Cap[0] * d[0] + filter->Cap[1] * d[1];
    if (sd == 0.0)
    {
      if (s0 > 0.0)
      {
        return HUGE_VAL;
      }
    }
    else
    {
      const double tc = -s0 / sd;
      if (sd > 0.0)
      {
        t1 = std::min(t1, tc);
      }
      else
      {
        t0 = std::max(t0, tc);
      }
      if (t0 > t1)
      {
        return HUGE_VAL;
      }
    }
  }
  const double len2 = d[0] * d[0] + d[1] * d[1];
  double t = ((x[0] - a[0]) * d[0] + (x[1] - a[1]) * d[1]) / len2;
  t = std::min(t1, std::max(t0, t));
  if (t == 0.0)
  {
    out[0] = a[0];
    out[1] = a[1];
  }
  else if (t == 1.0)
  {
    out[0] = b[0];
    out[1] = b[1];
  }
  else
  {
    out[0] = a[0] + t * d[0];
    out[1] = a[1] + t * d[1];
  }
  const double dx = out[0] - x[0], dy = out[1] - x[1];
  return dx * dx + dy * dy;
}

bool vtkMedialPolygon::ClosestPoint(const double x[2], double upperBound, const ContactFilter* filter,
  double point[2], double& distance, int& edge) const
{
  if (!(upperBound > 0.0))
  {
    return false;
  }
  double best2 = upperBound * upperBound;
  bool found = false;
  const vtkMedialUniformGrid& grid = this->Grid;
  const double size = grid.GetCellSize(0);
  const int centre[3] = { grid.Coordinate(x[0], 0), grid.Coordinate(x[1], 1), 0 };
  // Distance from x to the grid box; rings closer than that are empty.
  const double gx =
    std::max({ 0.0, grid.GetOrigin(0) - x[0], x[0] - grid.CellLow(0, grid.GetDimension(0)) });
  const double gy =
    std::max({ 0.0, grid.GetOrigin(1) - x[1], x[1] - grid.CellLow(1, grid.GetDimension(1)) });
  const double outside = std::sqrt(gx * gx + gy * gy);
  const int maxRing = std::max(grid.GetDimension(0), grid.GetDimension(1));
  // Long edges sit in many cells: test each once per query.
  thread_local std::vector<unsigned> stamps;
  thread_local unsigned stamp = 0;
  if (stamps.size() != this->Edges.size() || ++stamp == 0)
  {
    stamps.assign(this->Edges.size(), 0);
    stamp = 1;
  }
  auto visitCell = [&](const int* ijk, vtkIdType cell) {
    // Skip cells that lie entirely beyond the best distance so far.
    const double x0 = grid.CellLow(0, ijk[0]) - x[0];
    const double y0 = grid.CellLow(1, ijk[1]) - x[1];
    const double dx = std::max({ 0.0, x0, -(x0 + size) });
    const double dy = std::max({ 0.0, y0, -(y0 + size) });
    if (dx * dx + dy * dy >= best2)
    {
      return;
    }
    grid.ForEachItemInCell(cell, [&](vtkIdType item) {
      const int e = static_cast<int>(item);
      if (stamps[e] == stamp || (filter && (e == filter->IgnoreEdge[0] || e == filter->IgnoreEdge[1])))
      {
        return;
      }
      stamps[e] = stamp;
      double q[2];
      const double d2 = this->ClosestPointOnEdge(e, x, filter, q);
      if (d2 < best2)
      {
        best2 = d2;
        point[0] = q[0];
        point[1] = q[1];
        edge = e;
        found = true;
      }
    });
  };
  for (int ring = std::max(0, this->EmptyRings[grid.CellId(centre[0], centre[1], 0)]); ring <= maxRing; ++ring)
  {
    // Cells of ring k are at least (k - 1) * CellSize away from x (or the grid's distance).
    const double reach = std::max(outside, (ring - 1) * size);
    if (reach * reach >= best2)
    {
      break;
    }
    grid.ForEachCellInShell(centre, ring, visitCell);
  }
  if (found)
  {
    distance = std::sqrt(best2);
  }
  return found;
}

bool vtkMedialPolygon::ContainsBall(const double centre[2], double radius, const ContactFilter* filter) const
{
  if (!(radius > 0.0))
  {
    return true;
  }
  bool blocked = false;
  const double r2 = radius * radius;
  this->VisitEdgesNear(centre, radius, [&](int e) {
    if (blocked || (filter && (e == filter->IgnoreEdge[0] || e == filter->IgnoreEdge[1])))
    {
      return;
    }
    double q[2];
    blocked = this->ClosestPointOnEdge(e, centre, filter, q) < r2;
  });
  return !blocked;
}

bool vtkMedialPolygon::Intersect(const double origin[2], const double direction[2], double tMin,
  double tMax, const ContactFilter* filter, double& tHit, int& edgeHit) const
{
  // Amanatides-Woo walk through the grid; a cell's edges are tested in full, so a
  // hit is final once it lies before the next cell boundary.
  double best = tMax;
  bool found = false;
  double tEnter = 0.0;
  double p[2] = { origin[0], origin[1] };
  // Clip the ray start to the grid box.
  {
    double t0 = 0.0, t1 = HUGE_VAL;
    const double lo[2] = { this->Grid.GetOrigin(0), this->Grid.GetOrigin(1) };
    const double hi[2] = { this->Grid.CellLow(0, this->Grid.GetDimension(0)),
      this->Grid.CellLow(1, this->Grid.GetDimension(1)) };
    if (!vtkMedialGeometry::ClipRayToBox(lo, hi, origin, direction, 2, t0, t1))
    {
      return false;
    }
    tEnter = t0;
    p[0] = origin[0] + t0 * direction[0];
    p[1] = origin[1] + t0 * direction[1];
  }
  int cell[2], step[2];
  double tNext[2], tDelta[2];
  for (int k = 0; k < 2; ++k)
  {
    cell[k] = this->Grid.Coordinate(p[k], k);
    step[k] = direction[k] > 0 ? 1 : -1;
    if (direction[k] == 0.0)
    {
      tNext[k] = HUGE_VAL;
      tDelta[k] = HUGE_VAL;
    }
    else
    {
      const double boundary = this->Grid.CellLow(k, cell[k] + (direction[k] > 0 ? 1 : 0));
      tNext[k] = (boundary - origin[k]) / direction[k];
      tDelta[k] = this->Grid.GetCellSize(k) / std::abs(direction[k]);
    }
  }
  (void)tEnter;
  for (;;)
  {
    this->Grid.ForEachItemInCell(this->Grid.CellId(cell[0], cell[1], 0), [&](vtkIdType item) {
      const int e = static_cast<int>(item);
      if (filter && (e == filter->IgnoreEdge[0] || e == filter->IgnoreEdge[1]))
      {
        return;
      }
      const double* a = this->GetPoint(this->Edges[e].A);
      const double* b = this->GetPoint(this->Edges[e].B);
      const double s[2] = { b[0] - a[0], b[1] - a[1] };
      const double denom = direction[0] * s[1] - direction[1] * s[0];
      if (denom == 0.0)
      {
        return;
      }
      const double w[2] = { a[0] - origin[0], a[1] - origin[1] };
      const double t = (w[0] * s[1] - w[1] * s[0]) / denom;
      const double u = (w[0] * direction[1] - w[1] * direction[0]) / denom;
      // A ray through a vertex may miss both of its edges by a rounding error.
      if (u >= -1e-12 && u <= 1.0 + 1e-12 && t > tMin && t < best)
      {
        best = t;
        edgeHit = e;
        found = true;
      }
    });
    const int axis = tNext[0] < tNext[1] ? 0 : 1;
    if (found && best <= tNext[axis])
    {
      break;
    }
    if (tNext[axis] > tMax)
    {
      break;
    }
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= this->Grid.GetDimension(axis))
    {
      break;
    }
    tNext[axis] += tDelta[axis];
  }
  if (found)
  {
    tHit = best;
  }
  return found;
}
