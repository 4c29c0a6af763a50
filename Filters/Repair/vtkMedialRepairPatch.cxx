// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialRepairPatch.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vtkMedialSurfaceRepair
{
vtkSmartPointer<vtkPolyData> ToPolyData(const Soup& soup)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(soup.Points.size()));
  for (size_t i = 0; i < soup.Points.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), soup.Points[i].data());
  }
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(soup.Triangles.size()), 3 * static_cast<vtkIdType>(soup.Triangles.size()));
  for (const auto& t : soup.Triangles)
  {
    cells->InsertNextCell(3, t.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}
}

namespace
{
using Soup = vtkMedialSurfaceRepair::Soup;

// Every point of `p` has one closed fan of triangles around it in `soup`, each edge at it
// used once in each direction: the triangles (v, a, b) around v, read as a -> b, are one
// cycle through distinct a's.
bool Umbrellas(const Soup& soup, const std::vector<char>& check)
{
  std::vector<std::vector<std::pair<vtkIdType, vtkIdType>>> around(soup.Points.size());
  for (const auto& t : soup.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (check[t[k]])
      {
        around[t[k]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
      }
    }
  }
  for (size_t v = 0; v < around.size(); ++v)
  {
    auto& fan = around[v];
    if (!check[v])
    {
      continue;
    }
    if (fan.size() < 3)
    {
      return false;
    }
    std::sort(fan.begin(), fan.end());
    for (size_t i = 1; i < fan.size(); ++i)
    {
      if (fan[i].first == fan[i - 1].first)
      {
        return false; // an edge used twice in one direction
      }
    }
    // Walk a -> b from the first: one cycle through every triangle.
    vtkIdType at = fan[0].first;
    for (size_t step = 0; step < fan.size(); ++step)
    {
      const auto it = std::lower_bound(fan.begin(), fan.end(), std::make_pair(at, vtkIdType(-1)));
      if (it == fan.end() || it->first != at)
      {
        return false; // an edge used once: a border
      }
      at = it->second;
      if (at == fan[0].first && step + 1 != fan.size())
      {
        return false; // more than one fan
      }
    }
    if (at != fan[0].first)
    {
      return false;
    }
  }
  return true;
}

// Whether the triangles are edge-connected.
bool Connected(const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  std::vector<size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](size_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  std::vector<std::array<vtkIdType, 3>> edges; // lower, higher, triangle
  for (size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), static_cast<vtkIdType>(t) });
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 1; i < edges.size(); ++i)
  {
    if (edges[i][0] == edges[i - 1][0] && edges[i][1] == edges[i - 1][1])
    {
      parent[find(static_cast<size_t>(edges[i][2]))] = find(static_cast<size_t>(edges[i - 1][2]));
    }
  }
  size_t roots = 0;
  for (size_t t = 0; t < triangles.size(); ++t)
  {
    roots += find(t) == t ? 1 : 0;
  }
  return roots == 1;
}

double SignedVolume(const Soup& soup)
{
  double volume = 0.0;
  for (const auto& t : soup.Triangles)
  {
    const auto& a = soup.Points[t[0]];
    const auto& b = soup.Points[t[1]];
    const auto& c = soup.Points[t[2]];
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6.0;
}

bool BuildTree(const Soup& soup, vtkMedialTriangleMesh& mesh, vtkMedialSurfaceQuery& query)
{
  std::string error;
  return mesh.Build(vtkMedialSurfaceRepair::ToPolyData(soup), error) && query.Build(&mesh, error);
}
}

vtkMedialRepairPatch::Soup vtkMedialRepairPatch::Extract(
  const Soup& soup, const std::vector<char>& in, std::vector<vtkIdType>& soupPoint)
{
  Soup patch;
  soupPoint.clear();
  std::vector<vtkIdType> id(soup.Points.size(), -1);
  for (size_t t = 0; t < soup.Triangles.size(); ++t)
  {
    if (!in[t])
    {
      continue;
    }
    std::array<vtkIdType, 3> tri;
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType v = soup.Triangles[t][k];
      if (id[v] < 0)
      {
        id[v] = static_cast<vtkIdType>(patch.Points.size());
        patch.Points.push_back(soup.Points[v]);
        soupPoint.push_back(v);
      }
      tri[k] = id[v];
    }
    patch.Triangles.push_back(tri);
  }
  return patch;
}

bool vtkMedialRepairPatch::Certify(const Soup& shell, const vtkMedialSurfaceQuery& query,
  const std::vector<char>& in, const Soup& before, const Soup& stitched, std::string& why)
{
  this->ShellQuery = &query;
  this->In = in;
  this->Before = before;
  const vtkMedialTriangleMesh& shellMesh = *query.GetMesh();
  const size_t rest = static_cast<size_t>(std::count(in.begin(), in.end(), 0));
  if (shellMesh.GetNumberOfTriangles() != static_cast<vtkIdType>(shell.Triangles.size()) ||
    in.size() != shell.Triangles.size() || stitched.Triangles.size() <= rest)
  {
    why = "the patch does not match its shell";
    return false;
  }
  // P' over its own points: the stitched triangles after S - P.
  std::vector<char> inAfter(stitched.Triangles.size(), 0);
  std::fill(inAfter.begin() + static_cast<std::ptrdiff_t>(rest), inAfter.end(), 1);
  std::vector<vtkIdType> stitchedId;
  const Soup after = Extract(stitched, inAfter, stitchedId);
  std::vector<char> onPatch(stitched.Points.size(), 0);
  for (const vtkIdType v : stitchedId)
  {
    onPatch[v] = 1;
  }
  // Topology: one closed, oriented fan around every point of P', and P' in one piece.
  if (!Umbrellas(stitched, onPatch))
  {
    why = "the stitched shell is not a closed, oriented manifold at the patch";
    return false;
  }
  if (!Connected(after.Triangles))
  {
    why = "the patch came back in pieces";
    return false;
  }
  // Bounds within S's, no degenerate triangle.
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] = HUGE_VAL;
    this->Bounds[2 * k + 1] = -HUGE_VAL;
  }
  for (const auto& x : stitched.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Bounds[2 * k] = std::min(this->Bounds[2 * k], x[k]);
      this->Bounds[2 * k + 1] = std::max(this->Bounds[2 * k + 1], x[k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    if (this->Bounds[2 * k] < shellMesh.Bounds[2 * k] || this->Bounds[2 * k + 1] > shellMesh.Bounds[2 * k + 1])
    {
      why = "the patch reaches out of the shell's bounds";
      return false;
    }
  }
  const double diagonal = shellMesh.Diagonal;
  for (const auto& t : after.Triangles)
  {
    const auto &a = after.Points[t[0]], &b = after.Points[t[1]], &c = after.Points[t[2]];
    const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0] };
    if (0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) <= 2e-14 * diagonal * diagonal)
    {
      why = "the patch has a degenerate triangle";
      return false;
    }
  }
  // Trees of P' and P (P for the crossings only). P' keeps every triangle and point.
  if (!BuildTree(after, this->AfterMesh, this->AfterQuery) || !BuildTree(before, this->BeforeMesh, this->BeforeQuery) ||
    this->AfterMesh.GetNumberOfTriangles() != static_cast<vtkIdType>(after.Triangles.size()) ||
    this->AfterMesh.UsedPoints != static_cast<vtkIdType>(after.Points.size()))
  {
    why = "the patch has coincident points or triangles";
    return false;
  }
  // Every pair with a triangle of P': all triangles within each one's bounding ball.
  std::vector<vtkIdType> restId(in.size(), -1); // S's triangle -> S''s, outside P
  {
    vtkIdType next = 0;
    for (size_t t = 0; t < in.size(); ++t)
    {
      restId[t] = in[t] ? -1 : next++;
    }
  }
  const double margin = 1e-9 * diagonal;
  std::vector<std::array<double, 18>> corners;
  std::vector<std::array<vtkIdType, 6>> ids;
  std::vector<vtkMedialSurfaceQuery::ClosestHit> hits;
  auto addPair = [&](vtkIdType a, vtkIdType b) {
    std::array<double, 18> x;
    std::array<vtkIdType, 6> id;
    for (int k = 0; k < 3; ++k)
    {
      id[k] = stitched.Triangles[a][k];
      id[3 + k] = stitched.Triangles[b][k];
      std::copy_n(stitched.Points[id[k]].data(), 3, &x[3 * k]);
      std::copy_n(stitched.Points[id[3 + k]].data(), 3, &x[9 + 3 * k]);
    }
    corners.push_back(x);
    ids.push_back(id);
  };
  for (size_t i = 0; i < after.Triangles.size(); ++i)
  {
    const vtkIdType a = static_cast<vtkIdType>(rest + i);
    double centre[3] = { 0, 0, 0 }, radius2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        centre[j] += after.Points[after.Triangles[i][k]][j] / 3.0;
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      const auto& p = after.Points[after.Triangles[i][k]];
      radius2 = std::max(radius2,
        (p[0] - centre[0]) * (p[0] - centre[0]) + (p[1] - centre[1]) * (p[1] - centre[1]) + (p[2] - centre[2]) * (p[2] - centre[2]));
    }
    const double radius = std::sqrt(radius2) * (1.0 + 1e-9) + margin;
    this->AfterQuery.TrianglesWithin(centre, radius, hits);
    for (const auto& hit : hits)
    {
      const vtkIdType b = static_cast<vtkIdType>(rest) + this->AfterMesh.SourceCellIds[hit.Triangle];
      if (b > a)
      {
        addPair(a, b);
      }
    }
    query.TrianglesWithin(centre, radius, hits);
    for (const auto& hit : hits)
    {
      if (!in[hit.Triangle])
      {
        addPair(a, restId[hit.Triangle]);
      }
    }
  }
  const std::vector<char> intersecting = vtkMedialSurfaceRepair::IntersectingPairs(corners, ids);
  if (std::find(intersecting.begin(), intersecting.end(), 1) != intersecting.end())
  {
    why = "the patch intersects the shell";
    return false;
  }
  // Facing out: the preparation then keeps every winding.
  if (!(SignedVolume(stitched) > 1e-6 * std::fabs(SignedVolume(shell))))
  {
    why = "the stitched shell faces inward";
    return false;
  }
  for (size_t i = 0; i < after.Points.size(); ++i)
  {
    this->AfterPoints.emplace(after.Points[i], static_cast<vtkIdType>(i));
  }
  for (const auto& t : after.Triangles)
  {
    std::array<vtkIdType, 3> s = t;
    std::sort(s.begin(), s.end());
    this->AfterTriangles.push_back(s);
  }
  std::sort(this->AfterTriangles.begin(), this->AfterTriangles.end());
  return true;
}

double vtkMedialRepairPatch::Distance(const double x[3], double bound) const
{
  vtkMedialSurfaceQuery::ClosestHit hit;
  double d = this->AfterQuery.ClosestPoint(x, bound, hit) ? hit.Distance : bound;
  thread_local std::vector<vtkMedialSurfaceQuery::ClosestHit> hits;
  this->ShellQuery->TrianglesWithin(x, d, hits);
  for (const auto& h : hits)
  {
    if (!this->In[h.Triangle])
    {
      d = std::min(d, h.Distance);
    }
  }
  return d;
}

bool vtkMedialRepairPatch::IsInside(const double x[3]) const
{
  // vtkMedialSurfaceQuery::IsInside's rays and vote, on S - P + P'.
  static const double directions[3][3] = { { 0.5773502691896258, 0.6172133998483676, 0.5345224838248488 },
    { -0.7071067811865476, 0.2672612419124244, 0.6546536707079771 },
    { 0.2182178902359924, -0.8728715609439696, 0.4364357804719848 } };
  const double* b = this->Bounds;
  if (x[0] < b[0] || x[0] > b[1] || x[1] < b[2] || x[1] > b[3] || x[2] < b[4] || x[2] > b[5])
  {
    return false;
  }
  auto parity = [&](int i) {
    return (this->ShellQuery->CountCrossings(x, directions[i], HUGE_VAL) +
             this->BeforeQuery.CountCrossings(x, directions[i], HUGE_VAL) +
             this->AfterQuery.CountCrossings(x, directions[i], HUGE_VAL)) %
      2;
  };
  const int first = parity(0), second = parity(1);
  return first == second ? first == 1 : parity(2) == 1;
}

bool vtkMedialRepairPatch::KeptPoint(const double x[3]) const
{
  return this->AfterPoints.count({ x[0], x[1], x[2] }) > 0;
}

bool vtkMedialRepairPatch::KeptTriangle(const double a[3], const double b[3], const double c[3]) const
{
  const auto ia = this->AfterPoints.find({ a[0], a[1], a[2] });
  const auto ib = this->AfterPoints.find({ b[0], b[1], b[2] });
  const auto ic = this->AfterPoints.find({ c[0], c[1], c[2] });
  if (ia == this->AfterPoints.end() || ib == this->AfterPoints.end() || ic == this->AfterPoints.end())
  {
    return false;
  }
  std::array<vtkIdType, 3> s{ ia->second, ib->second, ic->second };
  std::sort(s.begin(), s.end());
  return std::binary_search(this->AfterTriangles.begin(), this->AfterTriangles.end(), s);
}
