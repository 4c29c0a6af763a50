// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialGovernors.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialSort.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace
{
namespace G = vtkMedialGeometry;

// Unit normals closer than this (|n1 x n2|) are one plane; unit directions, one line.
constexpr double CoplanarSine = 1e-9;
// c - q along the inward normal within this (1 - cos): the contact is the face's plane.
constexpr double AlongNormal = 1e-12;
// c - q perpendicular to a line within this (cosine): the contact is on the line.
constexpr double AcrossLine = 1e-10;

struct UnionFind
{
  std::vector<int> Parent;
  void Reset(int n)
  {
    this->Parent.resize(static_cast<size_t>(n));
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int i)
  {
    while (this->Parent[i] != i)
    {
      this->Parent[i] = this->Parent[this->Parent[i]];
      i = this->Parent[i];
    }
    return i;
  }
  // The smaller root wins, so the result does not depend on the order of unions.
  void Union(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a != b)
    {
      this->Parent[std::max(a, b)] = std::min(a, b);
    }
  }
};

// Dense ids 0, 1, ... for the roots, in the order of their first member.
int DenseRoots(UnionFind& sets, int n, std::vector<int>& id)
{
  id.assign(static_cast<size_t>(n), -1);
  std::vector<int> rootId(static_cast<size_t>(n), -1);
  int count = 0;
  for (int i = 0; i < n; ++i)
  {
    const int r = sets.Find(i);
    if (rootId[r] < 0)
    {
      rootId[r] = count++;
    }
    id[i] = rootId[r];
  }
  return count;
}

bool Parallel(const double a[3], const double b[3])
{
  double x[3];
  G::Cross(a, b, x);
  return G::Dot(x, x) <= CoplanarSine * CoplanarSine;
}

}

// Per-thread scratch space of Classify.
struct vtkMedialGovernors::ClassifyScratch
{
  std::vector<vtkMedialSurfaceQuery::ClosestHit> Hits;
  std::vector<std::tuple<vtkIdType, vtkIdType, int>> Keys; // (a, b, hit): a vertex (b = -1) or an edge
  std::vector<int> Feature;        // per hit
  std::vector<unsigned char> Cap;  // per hit: in the cap around the sample point
  std::vector<int> Best;           // per region or governor root: its best contact
  std::vector<int> Used;
  std::vector<std::array<double, 3>> Direction;
  std::vector<std::pair<std::array<long long, 3>, int>> Cells;
  UnionFind Sets;
  double CapAxis[3] = { 0, 0, 0 }; // unit direction from the centre to the cap's anchor
  double CapLimit = 0.0;           // outside the cap where (q - c).CapAxis <= CapLimit
  double Nearest = 0.0;            // distance of the nearest surface point
};

namespace
{
using ClassifyScratch = vtkMedialGovernors::ClassifyScratch;

// With theta > 0: joins the contacts outside the cap whose directions from c are
// less than theta apart. Single linkage; a grid on the unit directions with cells
// one chord wide keeps it linear in the number of contacts.
void MergeCloserThan(const double c[3], double thetaDegrees,
  const std::vector<vtkMedialSurfaceQuery::ClosestHit>& hits, ClassifyScratch& s)
{
  const double theta = thetaDegrees * (3.14159265358979323846 / 180.0);
  const double cosTheta = std::cos(theta);
  const int k = static_cast<int>(hits.size());
  s.Direction.resize(static_cast<size_t>(k));
  std::vector<int>& used = s.Used;
  used.clear();
  for (int i = 0; i < k; ++i)
  {
    double d[3];
    G::Sub(hits[i].Point, c, d);
    const double len = std::sqrt(G::Dot(d, d));
    if (len > 0.0 && !s.Cap[i])
    {
      for (int j = 0; j < 3; ++j)
      {
        s.Direction[i][j] = d[j] / len;
      }
      used.push_back(i);
    }
  }
  auto join = [&](int i, int j) {
    if (G::Dot(s.Direction[i].data(), s.Direction[j].data()) > cosTheta)
    {
      s.Sets.Union(i, j);
    }
  };
  const size_t n = used.size();
  const double chord = 2.0 * std::sin(0.5 * theta);
  if (n <= 48 || chord > 0.5)
  {
    for (size_t a = 0; a < n; ++a)
    {
      for (size_t b = a + 1; b < n; ++b)
      {
        join(used[a], used[b]);
      }
    }
    return;
  }
  s.Cells.clear();
  auto cellOf = [&](int i) {
    std::array<long long, 3> key;
    for (int j = 0; j < 3; ++j)
    {
      key[j] = static_cast<long long>(std::floor(s.Direction[i][j] / chord));
    }
    return key;
  };
  for (int i : used)
  {
    s.Cells.emplace_back(cellOf(i), i);
  }
  std::sort(s.Cells.begin(), s.Cells.end());
  for (int i : used)
  {
    const auto key = cellOf(i);
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        for (long long dz = -1; dz <= 1; ++dz)
        {
          const std::pair<std::array<long long, 3>, int> lo({ key[0] + dx, key[1] + dy, key[2] + dz }, -1);
          for (auto it = std::upper_bound(s.Cells.begin(), s.Cells.end(), lo);
               it != s.Cells.end() && it->first == lo.first; ++it)
          {
            if (it->second > i)
            {
              join(i, it->second);
            }
          }
        }
      }
    }
  }
}

// The cap (theta > 0): contacts less than theta from the anchor, seen from c, and
// contacts inside the ball. The anchor is the sample point P, or without it the
// deepest contact when the ball overlaps the surface. False when there is none.
bool MarkCap(const double c[3], double radius, const double* surfacePoint, double thetaDegrees,
  double tolerance, const std::vector<vtkMedialSurfaceQuery::ClosestHit>& hits, ClassifyScratch& s)
{
  const int k = static_cast<int>(hits.size());
  s.Cap.assign(static_cast<size_t>(k), 0);
  const double* anchor = surfacePoint;
  if (!anchor && k == 0)
  {
    return false; // an untouched ball without its sample point: no cap
  }
  if (!anchor)
  {
    int deepest = 0;
    for (int i = 1; i < k; ++i)
    {
      deepest = hits[i].Distance < hits[deepest].Distance ? i : deepest;
    }
    anchor = hits[deepest].Distance < radius - tolerance ? hits[deepest].Point : nullptr;
  }
  double* u = s.CapAxis;
  if (!(thetaDegrees > 0.0) || !anchor)
  {
    return false;
  }
  G::Sub(anchor, c, u);
  const double ul = std::sqrt(G::Dot(u, u));
  if (!(ul > 0.0))
  {
    return false;
  }
  // The sampler's rule (vtkMedialSurfaceQuery::ContactFilter), a plane cut:
  // q is outside the cap where (q - c).u <= r cos(theta), u the unit direction to
  // the anchor; the contact that stopped the ball is there, on the cone's rim, so
  // the test leans that way by the tolerance.
  const double cosTheta = std::cos(thetaDegrees * (3.14159265358979323846 / 180.0));
  for (int j = 0; j < 3; ++j)
  {
    u[j] /= ul;
  }
  s.CapLimit = radius * cosTheta + tolerance;
  for (int i = 0; i < k; ++i)
  {
    double d[3];
    G::Sub(hits[i].Point, c, d);
    s.Cap[i] = hits[i].Distance < radius - tolerance || G::Dot(u, d) > s.CapLimit;
  }
  return true;
}
}

bool vtkMedialGovernors::BallGovernors::AllSimple() const
{
  return std::find(this->Compound.begin(), this->Compound.end(), 1) == this->Compound.end();
}

bool vtkMedialGovernors::Build(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
  const Settings& settings, std::string& error)
{
  this->Mesh = &mesh;
  this->Query = &query;
  this->Diagonal = mesh.Diagonal;
  this->ContactTolerance = settings.Tolerance * mesh.Diagonal;
  this->Theta = settings.MinimumSeparationAngle;
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Points.size() / 3);
  if (nt <= 0 || !(mesh.Diagonal > 0.0) || nt >= (1LL << 30) || nv >= (1LL << 30))
  {
    error = "the surface is empty, flat or too large";
    return false;
  }
  // Edges: (min vertex, max vertex, triangle), sorted so each edge's triangles are adjacent.
  EdgeList edges;
  edges.reserve(static_cast<size_t>(3 * nt));
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      const vtkIdType a = v[j], b = v[(j + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b), t);
    }
  }
  vtkMedialSort(edges.begin(), edges.end(), settings.Threads); // equivalent entries are equal
  this->BuildPlanes(edges);
  std::vector<std::pair<vtkIdType, int>> atVertex; // (vertex, sharp edge)
  this->BuildLines(edges, atVertex);
  this->BuildPoints(atVertex, settings.Threads);
  return true;
}

void vtkMedialGovernors::BuildPlanes(const EdgeList& edges)
{
  // Coplanar triangles joined across manifold edges; each group's plane is its
  // largest triangle's.
  const vtkMedialTriangleMesh& mesh = *this->Mesh;
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  UnionFind sets;
  sets.Reset(static_cast<int>(nt));
  auto sameEdge = [&](size_t i, size_t j) {
    return std::get<0>(edges[i]) == std::get<0>(edges[j]) && std::get<1>(edges[i]) == std::get<1>(edges[j]);
  };
  auto coplanar = [&](vtkIdType s, vtkIdType t) {
    return G::Dot(mesh.GetNormal(s), mesh.GetNormal(t)) > 0.0 && Parallel(mesh.GetNormal(s), mesh.GetNormal(t));
  };
  for (size_t i = 0; i + 1 < edges.size(); ++i)
  {
    const bool manifold = sameEdge(i, i + 1) && (i == 0 || !sameEdge(i - 1, i)) &&
      (i + 2 >= edges.size() || !sameEdge(i + 1, i + 2));
    if (manifold && coplanar(std::get<2>(edges[i]), std::get<2>(edges[i + 1])))
    {
      sets.Union(static_cast<int>(std::get<2>(edges[i])), static_cast<int>(std::get<2>(edges[i + 1])));
    }
  }
  this->NumberOfPlanes = DenseRoots(sets, static_cast<int>(nt), this->TrianglePlane);
  this->Features.assign(static_cast<size_t>(this->NumberOfPlanes), Feature());
  std::vector<double> largest(static_cast<size_t>(this->NumberOfPlanes), -1.0);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const int p = this->TrianglePlane[t];
    if (mesh.Areas[t] > largest[p])
    {
      largest[p] = mesh.Areas[t];
      Feature& f = this->Features[p];
      f.Kind = PLANE;
      std::copy(mesh.GetPoint(mesh.GetTriangle(t)[0]), mesh.GetPoint(mesh.GetTriangle(t)[0]) + 3, f.Point);
      for (int k = 0; k < 3; ++k)
      {
        f.Direction[k] = -mesh.GetNormal(t)[k];
      }
    }
  }
  // Sharp edges: between two plane groups (or on a boundary).
  this->SharpEdges.clear();
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    bool sharp = false;
    while (j < edges.size() && sameEdge(i, j))
    {
      sharp = sharp || this->TrianglePlane[std::get<2>(edges[j])] != this->TrianglePlane[std::get<2>(edges[i])];
      ++j;
    }
    if (sharp || j == i + 1)
    {
      this->SharpEdges.emplace_back(std::get<0>(edges[i]), std::get<1>(edges[i]));
    }
    i = j;
  }
}

void vtkMedialGovernors::BuildLines(const EdgeList& edges, std::vector<std::pair<vtkIdType, int>>& atVertex)
{
  // Collinear sharp edges joined at shared vertices; each line's direction is its
  // longest edge's.
  const vtkMedialTriangleMesh& mesh = *this->Mesh;
  const int ns = static_cast<int>(this->SharpEdges.size());
  std::vector<std::array<double, 3>> direction(static_cast<size_t>(ns));
  atVertex.clear();
  for (int e = 0; e < ns; ++e)
  {
    const double* a = mesh.GetPoint(this->SharpEdges[e].first);
    const double* b = mesh.GetPoint(this->SharpEdges[e].second);
    G::Sub(b, a, direction[e].data());
    const double len = std::sqrt(G::Dot(direction[e].data(), direction[e].data()));
    for (double& x : direction[e])
    {
      x = len > 0.0 ? x / len : 0.0;
    }
    atVertex.emplace_back(this->SharpEdges[e].first, e);
    atVertex.emplace_back(this->SharpEdges[e].second, e);
  }
  std::sort(atVertex.begin(), atVertex.end());
  UnionFind sets;
  sets.Reset(ns);
  for (size_t i = 0; i < atVertex.size(); ++i)
  {
    for (size_t j = i + 1; j < atVertex.size() && atVertex[j].first == atVertex[i].first; ++j)
    {
      if (Parallel(direction[atVertex[i].second].data(), direction[atVertex[j].second].data()))
      {
        sets.Union(atVertex[i].second, atVertex[j].second);
      }
    }
  }
  this->NumberOfLines = DenseRoots(sets, ns, this->SharpEdgeLine);
  this->Features.resize(static_cast<size_t>(this->NumberOfPlanes + this->NumberOfLines));
  this->LinePlanes.assign(static_cast<size_t>(this->NumberOfLines), {});
  std::vector<double> longest(static_cast<size_t>(this->NumberOfLines), -1.0);
  for (int e = 0; e < ns; ++e)
  {
    const int l = this->SharpEdgeLine[e];
    const double* a = mesh.GetPoint(this->SharpEdges[e].first);
    const double len2 = G::Distance2(a, mesh.GetPoint(this->SharpEdges[e].second));
    if (len2 > longest[l])
    {
      longest[l] = len2;
      Feature& f = this->Features[this->NumberOfPlanes + l];
      f.Kind = LINE;
      std::copy(a, a + 3, f.Point);
      std::copy(direction[e].begin(), direction[e].end(), f.Direction);
    }
  }
  // Each edge's line (LineOf): `edges` and SharpEdges are sorted alike, so one merge walk.
  size_t s = 0;
  for (const auto& edge : edges)
  {
    const std::pair<vtkIdType, vtkIdType> key(std::get<0>(edge), std::get<1>(edge));
    while (s < this->SharpEdges.size() && this->SharpEdges[s] < key)
    {
      ++s;
    }
    if (s < this->SharpEdges.size() && this->SharpEdges[s] == key)
    {
      this->LinePlanes[this->SharpEdgeLine[s]].push_back(this->TrianglePlane[std::get<2>(edge)]);
    }
  }
  for (auto& planes : this->LinePlanes)
  {
    std::sort(planes.begin(), planes.end());
    planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
  }
}

void vtkMedialGovernors::BuildPoints(const std::vector<std::pair<vtkIdType, int>>& atVertex, int threads)
{
  // Every vertex, with the planes and lines incident to it (CSR).
  const vtkMedialTriangleMesh& mesh = *this->Mesh;
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Points.size() / 3);
  const int first = this->NumberOfPlanes + this->NumberOfLines;
  this->Features.resize(static_cast<size_t>(first + nv));
  std::vector<std::pair<vtkIdType, int>> incident;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      incident.emplace_back(mesh.GetTriangle(t)[j], this->TrianglePlane[t]);
    }
  }
  for (const auto& ve : atVertex)
  {
    incident.emplace_back(ve.first, this->NumberOfPlanes + this->SharpEdgeLine[ve.second]);
  }
  vtkMedialSort(incident.begin(), incident.end(), threads); // equivalent entries are equal
  incident.erase(std::unique(incident.begin(), incident.end()), incident.end());
  this->VertexOffsets.assign(static_cast<size_t>(nv + 1), 0);
  this->VertexIncident.clear();
  for (const auto& vi : incident)
  {
    ++this->VertexOffsets[vi.first + 1];
    this->VertexIncident.push_back(vi.second);
  }
  std::partial_sum(this->VertexOffsets.begin(), this->VertexOffsets.end(), this->VertexOffsets.begin());
  for (vtkIdType v = 0; v < nv; ++v)
  {
    Feature& f = this->Features[first + v];
    f.Kind = POINT;
    std::copy(mesh.GetPoint(v), mesh.GetPoint(v) + 3, f.Point);
  }
}

int vtkMedialGovernors::LineOf(vtkIdType a, vtkIdType b) const
{
  const std::pair<vtkIdType, vtkIdType> key(std::min(a, b), std::max(a, b));
  const auto it = std::lower_bound(this->SharpEdges.begin(), this->SharpEdges.end(), key);
  if (it == this->SharpEdges.end() || *it != key)
  {
    return -1;
  }
  return this->NumberOfPlanes + this->SharpEdgeLine[it - this->SharpEdges.begin()];
}

bool vtkMedialGovernors::IsCorner(vtkIdType v) const
{
  int lines = 0;
  for (vtkIdType i = this->VertexOffsets[v]; i < this->VertexOffsets[v + 1]; ++i)
  {
    lines += this->Features[this->VertexIncident[i]].Kind == LINE ? 1 : 0;
  }
  return lines >= 2;
}

bool vtkMedialGovernors::AreIncident(int a, int b) const
{
  if (this->Features[a].Kind > this->Features[b].Kind)
  {
    std::swap(a, b);
  }
  const int ka = this->Features[a].Kind, kb = this->Features[b].Kind;
  if (ka == kb)
  {
    return false;
  }
  if (kb == LINE)
  {
    const auto& planes = this->LinePlanes[b - this->NumberOfPlanes];
    return std::binary_search(planes.begin(), planes.end(), a);
  }
  const vtkIdType v = b - this->NumberOfPlanes - this->NumberOfLines;
  return std::binary_search(this->VertexIncident.begin() + this->VertexOffsets[v],
    this->VertexIncident.begin() + this->VertexOffsets[v + 1], a);
}

double vtkMedialGovernors::DistanceToFeature(int id, const double x[3]) const
{
  const Feature& f = this->Features[id];
  double d[3];
  G::Sub(x, f.Point, d);
  if (f.Kind == PLANE)
  {
    return std::fabs(G::Dot(d, f.Direction));
  }
  if (f.Kind == LINE)
  {
    const double along = G::Dot(d, f.Direction);
    return std::sqrt(std::max(0.0, G::Dot(d, d) - along * along));
  }
  return std::sqrt(G::Dot(d, d));
}

int vtkMedialGovernors::FeatureOfContact(
  const double c[3], const double q[3], double distance, vtkIdType t) const
{
  const int plane = this->PlaneOf(t);
  if (!(distance > 0.0))
  {
    return plane;
  }
  double w[3];
  G::Sub(c, q, w);
  for (double& x : w)
  {
    x /= distance;
  }
  if (-G::Dot(w, this->Mesh->GetNormal(t)) >= 1.0 - AlongNormal)
  {
    return plane;
  }
  const vtkIdType* v = this->Mesh->GetTriangle(t);
  const double eps2 = 1e-24 * this->Diagonal * this->Diagonal;
  for (int j = 0; j < 3; ++j)
  {
    if (G::Distance2(q, this->Mesh->GetPoint(v[j])) <= eps2)
    {
      // At a vertex: on a line through it when c - q is across that line.
      for (vtkIdType i = this->VertexOffsets[v[j]]; i < this->VertexOffsets[v[j] + 1]; ++i)
      {
        const int f = this->VertexIncident[i];
        if (this->Features[f].Kind == LINE && std::fabs(G::Dot(w, this->Features[f].Direction)) <= AcrossLine)
        {
          return f;
        }
      }
      return this->NumberOfPlanes + this->NumberOfLines + static_cast<int>(v[j]);
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    const double* a = this->Mesh->GetPoint(v[j]);
    const double* b = this->Mesh->GetPoint(v[(j + 1) % 3]);
    if (G::SegmentDistance2(q, a, b) <= eps2)
    {
      const int line = this->LineOf(v[j], v[(j + 1) % 3]);
      return line >= 0 ? line : plane;
    }
  }
  return plane;
}

void vtkMedialGovernors::Classify(
  const double centre[3], double radius, const double* surfacePoint, BallGovernors& out) const
{
  this->Classify(centre, radius, surfacePoint, this->ContactTolerance, this->Theta, out);
}

void vtkMedialGovernors::Classify(const double c[3], double radius, const double* surfacePoint,
  double tolerance, double thetaDegrees, BallGovernors& out) const
{
  this->Classify(c, radius, surfacePoint, tolerance, thetaDegrees, false, out);
}

bool vtkMedialGovernors::ClassifyIfEmpty(
  const double c[3], double radius, double tolerance, double thetaDegrees, BallGovernors& out) const
{
  return this->Classify(c, radius, nullptr, tolerance, thetaDegrees, true, out);
}

bool vtkMedialGovernors::Classify(const double c[3], double radius, const double* surfacePoint,
  double tolerance, double thetaDegrees, bool requireEmpty, BallGovernors& out) const
{
  out.Features.clear();
  out.Compound.clear();
  out.ContactFeatures.clear();
  out.NearestDistance = HUGE_VAL;
  thread_local vtkMedialGovernors::ClassifyScratch s;
  bool blocked = false;
  const int capFeature = this->GatherContacts(c, radius, surfacePoint, tolerance, thetaDegrees, requireEmpty, blocked, s);
  if (blocked)
  {
    return false;
  }
  if (s.Hits.empty() && capFeature < 0)
  {
    return true;
  }
  out.NearestDistance = s.Nearest;
  const double reach = std::max(0.0, radius) + tolerance;
  const auto& hits = s.Hits;
  const int k = static_cast<int>(hits.size());

  // 1. Connected regions: triangles sharing a vertex or an edge inside the band,
  //    on the same side of the cap's border.
  s.Sets.Reset(k);
  s.Keys.clear();
  const double reach2 = reach * reach;
  for (int i = 0; i < k; ++i)
  {
    const vtkIdType* v = this->Mesh->GetTriangle(hits[i].Triangle);
    for (int j = 0; j < 3; ++j)
    {
      const vtkIdType a = v[j], b = v[(j + 1) % 3];
      if (G::Distance2(c, this->Mesh->GetPoint(a)) <= reach2)
      {
        s.Keys.emplace_back(a, -1, i);
      }
      if (G::SegmentDistance2(c, this->Mesh->GetPoint(a), this->Mesh->GetPoint(b)) <= reach2)
      {
        s.Keys.emplace_back(std::min(a, b), std::max(a, b), i);
      }
    }
  }
  std::sort(s.Keys.begin(), s.Keys.end());
  for (size_t i = 1; i < s.Keys.size(); ++i)
  {
    const int x = std::get<2>(s.Keys[i]), y = std::get<2>(s.Keys[i - 1]);
    if (std::get<0>(s.Keys[i]) == std::get<0>(s.Keys[i - 1]) &&
      std::get<1>(s.Keys[i]) == std::get<1>(s.Keys[i - 1]) && s.Cap[x] == s.Cap[y])
    {
      s.Sets.Union(x, y);
    }
  }

  // 2. The feature of each region: that of its best contact.
  s.Feature.resize(static_cast<size_t>(k));
  for (int i = 0; i < k; ++i)
  {
    s.Feature[i] = this->FeatureOfContact(c, hits[i].Point, hits[i].Distance, hits[i].Triangle);
  }
  this->BestContacts(s);
  std::vector<std::pair<int, int>> regionFeature; // (feature, root) of the regions outside the cap
  for (int i = 0; i < k; ++i)
  {
    if (s.Best[i] >= 0)
    {
      out.ContactFeatures.push_back(s.Feature[s.Best[i]]);
      if (!s.Cap[i])
      {
        regionFeature.emplace_back(s.Feature[s.Best[i]], i);
      }
    }
  }
  std::sort(out.ContactFeatures.begin(), out.ContactFeatures.end());
  out.ContactFeatures.erase(std::unique(out.ContactFeatures.begin(), out.ContactFeatures.end()), out.ContactFeatures.end());

  // 3. Governors: the cap is one; outside it, regions with the same feature and
  //    contacts less than theta apart.
  std::sort(regionFeature.begin(), regionFeature.end());
  for (size_t i = 1; i < regionFeature.size(); ++i)
  {
    if (regionFeature[i].first == regionFeature[i - 1].first)
    {
      s.Sets.Union(regionFeature[i].second, regionFeature[i - 1].second);
    }
  }
  {
    int first = -1;
    for (int i = 0; i < k; ++i)
    {
      if (s.Cap[i])
      {
        first < 0 ? (void)(first = i) : s.Sets.Union(first, i);
      }
    }
  }
  if (thetaDegrees > 0.0)
  {
    MergeCloserThan(c, thetaDegrees, hits, s);
  }

  // 4. Each governor's feature (its best contact's) and whether every contact lies on it.
  this->BestContacts(s);
  std::vector<std::pair<int, unsigned char>> governors;
  for (int root = 0; root < k; ++root)
  {
    if (s.Best[root] < 0)
    {
      continue;
    }
    const int f = s.Feature[s.Best[root]];
    bool simple = true;
    for (int i = 0; i < k && simple; ++i)
    {
      simple = s.Sets.Find(i) != root || this->Explains(f, hits[i].Point, hits[i].Triangle, tolerance);
    }
    governors.emplace_back(f, simple ? 0 : 1);
  }
  if (capFeature >= 0)
  {
    governors.emplace_back(capFeature, 1); // the cap of a ball that overlaps the surface
    out.ContactFeatures.push_back(capFeature);
    std::sort(out.ContactFeatures.begin(), out.ContactFeatures.end());
    out.ContactFeatures.erase(std::unique(out.ContactFeatures.begin(), out.ContactFeatures.end()), out.ContactFeatures.end());
  }
  std::sort(governors.begin(), governors.end());
  for (const auto& g : governors)
  {
    out.Features.push_back(g.first);
    out.Compound.push_back(g.second);
  }
  return true;
}

int vtkMedialGovernors::GatherContacts(const double c[3], double radius, const double* surfacePoint,
  double tolerance, double thetaDegrees, bool requireEmpty, bool& blocked, ClassifyScratch& s) const
{
  const double reach = std::max(0.0, radius) + tolerance;
  vtkMedialSurfaceQuery::ClosestHit deepest;
  // Whether the ball is empty (at radius - tolerance) and its contacts, in one walk:
  // the contacts are read again only for a ball that is not.
  bool read = false;
  blocked = false;
  if ((thetaDegrees > 0.0 || requireEmpty) && radius > tolerance)
  {
    // Where the walk stopped bounds the nearest point: the closest-point walk starts there.
    // With theta > 0 a ball that is not empty needs its nearest point: the walk goes on for it.
    double nearestBound = radius;
    const bool wantNearest = thetaDegrees > 0.0 && !requireEmpty;
    read = this->Query->TrianglesWithinIfEmpty(
      c, reach, radius - tolerance, s.Hits, &nearestBound, nullptr, wantNearest ? &deepest : nullptr);
    if (!read && requireEmpty)
    {
      blocked = true;
      return -1;
    }
    if (!read && thetaDegrees > 0.0 &&
      (deepest.Triangle >= 0 || this->Query->ClosestPoint(c, std::min(radius, nearestBound), deepest)))
    {
      // The ball overlaps the surface inside its cap (the sampler ignores contacts
      // there): the cap is one compound governor, and only the contacts beyond it,
      // on the far side of the sampler's plane cut, are read.
      const double* anchor = surfacePoint ? surfacePoint : deepest.Point;
      double u[3];
      G::Sub(anchor, c, u);
      const double ul = std::sqrt(G::Dot(u, u));
      if (ul > 0.0)
      {
        vtkMedialSurfaceQuery::ContactFilter filter;
        G::AddScaled(c, radius / ul, u, filter.SamplePoint);
        // The stopping contact lies on the cone's rim: lean towards keeping it.
        filter.CosMinAngle = std::min(1.0, std::cos(thetaDegrees * (3.14159265358979323846 / 180.0)) + tolerance / radius);
        this->Query->TrianglesWithin(c, reach, s.Hits, &filter);
        s.Cap.assign(s.Hits.size(), 0);
        s.Nearest = deepest.Distance;
        return this->FeatureOfContact(c, deepest.Point, deepest.Distance, deepest.Triangle);
      }
    }
  }
  if (!read)
  {
    this->Query->TrianglesWithin(c, reach, s.Hits);
  }
  s.Nearest = HUGE_VAL;
  for (const auto& hit : s.Hits)
  {
    s.Nearest = std::min(s.Nearest, hit.Distance);
  }
  if (MarkCap(c, radius, surfacePoint, thetaDegrees, tolerance, s.Hits, s))
  {
    this->AddContactsBeyondCap(c, radius, tolerance, s);
  }
  return -1;
}

void vtkMedialGovernors::AddContactsBeyondCap(const double c[3], double radius, double tolerance,
  ClassifyScratch& s) const
{
  // A triangle whose closest point is in the cap may still touch the sphere beyond
  // it: a ball stopped on the cone's rim touches there (the sampler's blocker).
  const double reach = radius + tolerance;
  const size_t k = s.Hits.size();
  const double limit = G::Dot(s.CapAxis, c) + s.CapLimit; // outside: CapAxis.q <= limit
  for (size_t i = 0; i < k; ++i)
  {
    if (!s.Cap[i])
    {
      continue;
    }
    const vtkIdType* v = this->Mesh->GetTriangle(s.Hits[i].Triangle);
    vtkMedialSurfaceQuery::ClosestHit beyond;
    const double d2 = G::ClosestPointOnClippedTriangle(c, this->Mesh->GetPoint(v[0]), this->Mesh->GetPoint(v[1]),
      this->Mesh->GetPoint(v[2]), s.CapAxis, limit, beyond.Point);
    if (d2 <= reach * reach)
    {
      beyond.Distance = std::sqrt(d2);
      beyond.Triangle = s.Hits[i].Triangle;
      s.Hits.push_back(beyond);
      s.Cap.push_back(beyond.Distance < radius - tolerance ? 1 : 0);
    }
  }
}

void vtkMedialGovernors::BestContacts(ClassifyScratch& s) const
{
  // A nearer contact describes its set better; among contacts at the same distance
  // a plane before a line before a point, then the smaller feature id.
  const double tie = 1e-12 * this->Diagonal;
  const auto& hits = s.Hits;
  auto better = [&](int i, int j) {
    const double di = hits[i].Distance, dj = hits[j].Distance;
    if (std::fabs(di - dj) > tie + 1e-12 * std::min(di, dj))
    {
      return di < dj;
    }
    const int ki = this->Features[s.Feature[i]].Kind, kj = this->Features[s.Feature[j]].Kind;
    return ki != kj ? ki < kj : s.Feature[i] < s.Feature[j];
  };
  const int k = static_cast<int>(hits.size());
  s.Best.assign(static_cast<size_t>(k), -1);
  for (int i = 0; i < k; ++i)
  {
    int& b = s.Best[s.Sets.Find(i)];
    b = b < 0 || better(i, b) ? i : b;
  }
}

bool vtkMedialGovernors::Explains(int f, const double q[3], vtkIdType t, double tolerance) const
{
  const Feature& feature = this->Features[f];
  if (feature.Kind == PLANE && this->PlaneOf(t) == f)
  {
    return true;
  }
  if (feature.Kind == LINE)
  {
    const auto& planes = this->LinePlanes[f - this->NumberOfPlanes];
    if (std::binary_search(planes.begin(), planes.end(), this->PlaneOf(t)))
    {
      return true;
    }
  }
  if (feature.Kind == POINT)
  {
    const vtkIdType v = f - this->NumberOfPlanes - this->NumberOfLines;
    const vtkIdType* tv = this->Mesh->GetTriangle(t);
    if (tv[0] == v || tv[1] == v || tv[2] == v)
    {
      return true;
    }
  }
  return this->DistanceToFeature(f, q) <= tolerance;
}

bool vtkMedialGovernors::TouchedFeatures(const double c[3], double radius, double tolerance, std::vector<int>& out,
  bool checkEmpty, const vtkMedialTriangleBVH::Nearby* nearby) const
{
  out.clear();
  thread_local std::vector<vtkMedialSurfaceQuery::ClosestHit> hits;
  if (checkEmpty)
  {
    if (!this->Query->TrianglesWithinIfEmpty(c, radius + tolerance, radius - tolerance, hits, nullptr, nearby))
    {
      out.clear();
      return false;
    }
  }
  else
  {
    this->Query->TrianglesWithin(c, radius + tolerance, hits, nullptr, nearby);
  }
  const double eps2 = 1e-24 * this->Diagonal * this->Diagonal;
  auto consider = [&](int f) {
    if (std::fabs(this->DistanceToFeature(f, c) - radius) <= tolerance)
    {
      out.push_back(f);
    }
  };
  for (const auto& hit : hits)
  {
    if (hit.Distance < radius - tolerance)
    {
      out.clear();
      return false;
    }
    consider(this->PlaneOf(hit.Triangle));
    const vtkIdType* v = this->Mesh->GetTriangle(hit.Triangle);
    for (int j = 0; j < 3; ++j)
    {
      if (G::SegmentDistance2(hit.Point, this->Mesh->GetPoint(v[j]), this->Mesh->GetPoint(v[(j + 1) % 3])) <= eps2)
      {
        const int line = this->LineOf(v[j], v[(j + 1) % 3]);
        if (line >= 0)
        {
          consider(line);
        }
      }
      if (G::Distance2(hit.Point, this->Mesh->GetPoint(v[j])) <= eps2 && this->IsCorner(v[j]))
      {
        consider(this->NumberOfPlanes + this->NumberOfLines + static_cast<int>(v[j]));
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return true;
}

int vtkMedialGovernors::PointType(int governorCount, double radius) const
{
  if (governorCount <= 1 || radius <= this->ContactTolerance)
  {
    return RIM;
  }
  return governorCount == 2 ? SHEET : (governorCount == 3 ? SEAM : JUNCTION);
}
