// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialEnvelopeRefinement.h"

#include "vtkMedialEnvelope.h"
#include "vtkMedialSort.h"
#include "vtkMedialSpatialOrder.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace
{
using Edge = std::array<vtkIdType, 2>;

Edge Sorted(vtkIdType a, vtkIdType b)
{
  return { std::min(a, b), std::max(a, b) };
}

struct EdgeHash
{
  size_t operator()(const Edge& e) const { return std::hash<vtkIdType>()(e[0]) * 1000003u ^ std::hash<vtkIdType>()(e[1]); }
};

// Probe weights: the barycentric points of step 1/4 of a triangle, corners excepted.
constexpr int Steps = 4;
}

double vtkMedialEnvelopeRefinement::Probe(
  const Mesh& mesh, const vtkMedialSurfaceQuery& query, const vtkIdType* ids, int n) const
{
  // `ids` holds n balls, followed by n weights (in Steps) packed as ids[n + j].
  const double* centres[3];
  double radii[3], weights[3];
  for (int j = 0; j < n; ++j)
  {
    centres[j] = &(*mesh.Centres)[3 * ids[j]];
    radii[j] = (*mesh.Radii)[ids[j]];
    weights[j] = static_cast<double>(ids[n + j]) / Steps;
  }
  thread_local std::vector<vtkMedialSurfaceQuery::ClosestHit> hits;
  return vtkMedialEnvelope::InterpolatedProtrusion(query, centres, radii, weights, n, this->Tolerance, hits);
}

double vtkMedialEnvelopeRefinement::ProbeEdge(
  const Mesh& mesh, const vtkMedialSurfaceQuery& query, vtkIdType a, vtkIdType b) const
{
  // Only whether an edge protrudes beyond the tolerance decides: stop at the first
  // probe that does (its value stands for the edge's; the rest need no query).
  double worst = 0.0;
  for (vtkIdType i = 1; i < Steps && worst <= this->Tolerance; ++i)
  {
    const vtkIdType probe[4] = { a, b, Steps - i, i };
    worst = std::max(worst, this->Probe(mesh, query, probe, 2));
  }
  return worst;
}

double vtkMedialEnvelopeRefinement::ProbeInterior(
  const Mesh& mesh, const vtkMedialSurfaceQuery& query, const std::array<vtkIdType, 3>& t) const
{
  double worst = 0.0; // stops past the tolerance, as ProbeEdge does
  for (vtkIdType i = 1; i < Steps; ++i)
  {
    for (vtkIdType j = 1; i + j < Steps && worst <= this->Tolerance; ++j)
    {
      const vtkIdType probe[6] = { t[0], t[1], t[2], i, j, Steps - i - j };
      worst = std::max(worst, this->Probe(mesh, query, probe, 3));
    }
  }
  return worst;
}

namespace
{
// Probes in a spatially coherent order (vtkMedialSpatialOrder.h): the n items by the
// centre of one of their balls, ballOf(i).
template <class BallOf>
std::vector<vtkIdType> SpatialOrder(const vtkMedialEnvelopeRefinement::Mesh& mesh,
  const vtkMedialSurfaceQuery& query, vtkIdType n, BallOf ballOf, int threads)
{
  const double* bounds = query.GetMesh()->Bounds;
  return vtkMedialSpatialOrder::Order(
    n, [&](vtkIdType i) { return vtkMedialSpatialOrder::Key(&(*mesh.Centres)[3 * ballOf(i)], bounds); }, threads);
}
}

// The worst protrusion at each edge's probes (1/4, 1/2, 3/4), probed once per edge:
// it depends on the edge's two balls only, which never move. A triangle's probes on
// its sides are the same points, computed alike (a two-term weighted sum is the same
// in either order, and the third ball's zero weight adds nothing), so a triangle's
// worst protrusion is its interior probes' and its sides'.
class vtkMedialEnvelopeRefinement::EdgeProbes
{
public:
  // Probes the edges of `edges` (sorted pairs, any order, repeats allowed) not known yet.
  void Probe(const vtkMedialEnvelopeRefinement& self, const Mesh& mesh, const vtkMedialSurfaceQuery& query,
    std::vector<Edge>& edges, int threads)
  {
    // The new edges, each once, in the order first met (the order only decides which
    // thread probes which edge): an open-addressing table whose slots for them hold
    // Unknown until the parallel loop has probed them. It grows as new edges come, not
    // by the input's count: most input edges repeat (each is on two triangles), and
    // room for all of them doubled the table, the refinement's peak memory.
    size_t kept = 0;
    for (const Edge& e : edges)
    {
      if (2 * (this->Size + 1) > this->Keys.size())
      {
        this->Reserve(this->Size + 1);
      }
      const size_t slot = this->Slot(e);
      if (this->Keys[slot][0] < 0)
      {
        this->Keys[slot] = e;
        this->Values[slot] = Unknown;
        ++this->Size;
        edges[kept++] = e;
      }
    }
    edges.resize(kept);
    const vtkIdType n = static_cast<vtkIdType>(edges.size());
    const std::vector<vtkIdType> order = SpatialOrder(mesh, query, n, [&](vtkIdType i) { return edges[i][0]; }, threads);
    // The keys do not change in this loop, so each thread finds its edge's slot alone.
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType i = order[k];
      this->Values[this->Slot(edges[i])] = self.ProbeEdge(mesh, query, edges[i][0], edges[i][1]);
    }
  }
  // The value of an edge probed before (read-only: safe from parallel loops).
  double Get(const Edge& e) const { return this->Values[this->Slot(e)]; }

private:
  static constexpr double Unknown = -1.0;
  // The slot of e, or the empty slot where it would go (linear probing).
  size_t Slot(const Edge& e) const
  {
    const std::uint64_t h =
      (static_cast<std::uint64_t>(e[0]) * 0x9E3779B97F4A7C15ull) ^ (static_cast<std::uint64_t>(e[1]) * 0xC2B2AE3D27D4EB4Full);
    size_t slot = static_cast<size_t>(h >> 20) & (this->Keys.size() - 1);
    while (this->Keys[slot][0] >= 0 && this->Keys[slot] != e)
    {
      slot = (slot + 1) & (this->Keys.size() - 1);
    }
    return slot;
  }
  // Room for n entries at a load of at most one half.
  void Reserve(size_t n)
  {
    size_t capacity = std::max<size_t>(this->Keys.size(), 1024);
    while (capacity < 2 * n)
    {
      capacity *= 2;
    }
    if (capacity == this->Keys.size())
    {
      return;
    }
    std::vector<Edge> keys(capacity, Edge{ -1, -1 });
    std::vector<double> values(capacity, Unknown);
    keys.swap(this->Keys);
    values.swap(this->Values);
    for (size_t k = 0; k < keys.size(); ++k)
    {
      if (keys[k][0] >= 0)
      {
        const size_t slot = this->Slot(keys[k]);
        this->Keys[slot] = keys[k];
        this->Values[slot] = values[k];
      }
    }
  }

  std::vector<Edge> Keys; // {-1, -1}: empty
  std::vector<double> Values;
  size_t Size = 0;
};

// The triangles on each edge, kept through the splits without re-sorting every side each
// round: the sides as they were at the start (sorted once; an entry counts while its
// triangle still has both ends) and the sides that splits made since.
class vtkMedialEnvelopeRefinement::SideIndex
{
public:
  SideIndex(const std::vector<std::array<vtkIdType, 3>>& triangles, int threads)
  {
    this->Base.reserve(3 * triangles.size());
    for (vtkIdType t = 0; t < static_cast<vtkIdType>(triangles.size()); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Base.push_back({ Sorted(triangles[t][k], triangles[t][(k + 1) % 3]), t });
      }
    }
    vtkMedialSort(this->Base.begin(), this->Base.end(), threads); // (side, triangle): distinct
  }
  // The triangles that have e as a side now, in increasing order.
  void Find(const Edge& e, const std::vector<std::array<vtkIdType, 3>>& triangles, std::vector<vtkIdType>& out) const
  {
    out.clear();
    auto has = [&](vtkIdType t) {
      const auto& v = triangles[t];
      return std::find(v.begin(), v.end(), e[0]) != v.end() && std::find(v.begin(), v.end(), e[1]) != v.end();
    };
    for (auto s = std::lower_bound(this->Base.begin(), this->Base.end(), std::make_pair(e, vtkIdType(-1)));
         s != this->Base.end() && s->first == e; ++s)
    {
      if (has(s->second))
      {
        out.push_back(s->second);
      }
    }
    const auto added = this->Added.find(e);
    if (added != this->Added.end())
    {
      for (vtkIdType t : added->second)
      {
        if (has(t))
        {
          out.push_back(t);
        }
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  void Add(vtkIdType a, vtkIdType b, vtkIdType t) { this->Added[Sorted(a, b)].push_back(t); }

private:
  std::vector<std::pair<Edge, vtkIdType>> Base;
  std::unordered_map<Edge, std::vector<vtkIdType>, EdgeHash> Added;
};

vtkIdType vtkMedialEnvelopeRefinement::SplitEdges(const Mesh& mesh, const vtkMedialSurfaceQuery& query,
  SideIndex& index, std::vector<Edge>& marked, std::vector<Edge>& free, std::vector<vtkIdType>& touched, int threads)
{
  std::vector<std::array<vtkIdType, 3>>& triangles = *mesh.Triangles;
  touched.clear();
  const size_t freeCount = free.size(); // sorted up to here; split halves are appended
  std::sort(marked.begin(), marked.end());
  marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
  const double far = 2.0 * query.GetMesh()->Diagonal;
  // The triangles on each marked edge as the round starts (a triangle split through
  // another edge first may no longer have it, but must still hold it back).
  std::vector<std::vector<vtkIdType>> onEdge(marked.size());
  for (size_t k = 0; k < marked.size(); ++k)
  {
    index.Find(marked[k], triangles, onEdge[k]);
  }
  // The edges split, in order: an edge is held back when a triangle on it was split
  // in this round (only the triangles there at the start matter: a split's new
  // triangle is on no marked edge's list).
  std::vector<size_t> chosen;
  {
    std::vector<char> split(triangles.size(), 0);
    for (size_t k = 0; k < marked.size(); ++k)
    {
      const std::vector<vtkIdType>& on = onEdge[k];
      if (std::any_of(on.begin(), on.end(), [&split](vtkIdType t) { return split[t] != 0; }))
      {
        continue;
      }
      chosen.push_back(k);
      for (vtkIdType s : on)
      {
        split[s] = 1;
      }
    }
  }
  // The new balls: each chosen edge's midpoint, with the largest inscribed radius
  // there (independent queries, in parallel).
  const vtkIdType nc = static_cast<vtkIdType>(chosen.size());
  std::vector<double> centres(3 * chosen.size()), radii(chosen.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
  for (vtkIdType i = 0; i < nc; ++i)
  {
    const Edge& e = marked[chosen[i]];
    double* c = &centres[3 * i];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = 0.5 * ((*mesh.Centres)[3 * e[0] + k] + (*mesh.Centres)[3 * e[1] + k]);
    }
    vtkMedialSurfaceQuery::ClosestHit hit;
    radii[i] = query.ClosestPoint(c, far, hit) ? hit.Distance : 0.5 * ((*mesh.Radii)[e[0]] + (*mesh.Radii)[e[1]]);
  }
  std::vector<std::pair<size_t, Edge>> halves; // free edges split: replaced after the round
  for (vtkIdType i = 0; i < nc; ++i)
  {
    const Edge& e = marked[chosen[i]];
    const std::vector<vtkIdType>& on = onEdge[chosen[i]];
    const vtkIdType m = static_cast<vtkIdType>(mesh.Radii->size());
    mesh.Centres->insert(mesh.Centres->end(), &centres[3 * i], &centres[3 * i] + 3);
    mesh.Radii->push_back(radii[i]);
    mesh.Vertices->push_back(m);
    if (on.empty())
    {
      // An edge of no triangle: (a, b) becomes (a, m) and (m, b); the sorted part of
      // `free` stays as it is until the round's searches are done.
      auto at = std::lower_bound(free.begin(), free.begin() + freeCount, e);
      if (at != free.begin() + freeCount && *at == e)
      {
        halves.push_back({ static_cast<size_t>(at - free.begin()), Edge{ e[0], m } });
        free.push_back({ e[1], m });
      }
      continue;
    }
    for (vtkIdType s : on)
    {
      // (a, b, c) becomes (a, m, c) and (m, b, c), in the same orientation.
      std::array<vtkIdType, 3> t = triangles[s];
      std::array<vtkIdType, 3> other = t;
      std::replace(t.begin(), t.end(), e[1], m);
      std::replace(other.begin(), other.end(), e[0], m);
      const vtkIdType u = static_cast<vtkIdType>(triangles.size());
      const vtkIdType apex = t[0] + t[1] + t[2] - e[0] - m;
      triangles[s] = t;
      triangles.push_back(other);
      touched.push_back(s);
      touched.push_back(u);
      index.Add(e[0], m, s);
      index.Add(m, apex, s);
      index.Add(m, apex, u);
      index.Add(m, e[1], u);
      index.Add(e[1], apex, u);
    }
  }
  for (const auto& half : halves)
  {
    free[half.first] = half.second;
  }
  return nc;
}

vtkIdType vtkMedialEnvelopeRefinement::Refine(const Mesh& mesh, const vtkMedialSurfaceQuery& query,
  double tolerance, int threads, const std::function<bool()>& aborted)
{
  this->WorstProtrusion = 0.0;
  this->Rounds = 0;
  this->Tolerance = tolerance;
  std::vector<std::array<vtkIdType, 3>>& triangles = *mesh.Triangles;
  std::vector<Edge>& edges = *mesh.Edges;
  const vtkIdType limit = static_cast<vtkIdType>(mesh.Vertices->size());
  vtkIdType added = 0;
  // Edges of no triangle (sorted), and which primitives may have changed.
  std::vector<Edge> free;
  for (size_t e = 0; e < edges.size(); ++e)
  {
    if ((*mesh.EdgeTriangles)[e] == 0)
    {
      free.push_back(Sorted(edges[e][0], edges[e][1]));
    }
  }
  std::sort(free.begin(), free.end());
  // Each triangle's protrusion, kept between rounds: only the triangles a split made or
  // changed are probed again (the balls of the others did not move). A triangle's
  // probes on its sides are its edges' probes (see EdgeProbes), kept per edge.
  std::vector<vtkIdType> dirty(triangles.size());
  std::iota(dirty.begin(), dirty.end(), vtkIdType(0));
  std::vector<double> triangleProtrusion(triangles.size(), 0.0);
  EdgeProbes sides;
  SideIndex index(triangles, threads);
  for (; this->Rounds < MaximumRounds && added < limit; ++this->Rounds)
  {
    if (aborted && aborted())
    {
      break;
    }
    const vtkIdType nt = static_cast<vtkIdType>(triangles.size());
    const vtkIdType nf = static_cast<vtkIdType>(free.size());
    const vtkIdType nd = static_cast<vtkIdType>(dirty.size());
    std::vector<Edge> probed(free.begin(), free.end());
    for (vtkIdType t : dirty)
    {
      for (int k = 0; k < 3; ++k)
      {
        probed.push_back(Sorted(triangles[t][k], triangles[t][(k + 1) % 3]));
      }
    }
    sides.Probe(*this, mesh, query, probed, threads);
    triangleProtrusion.resize(nt, 0.0);
    const std::vector<vtkIdType> order = SpatialOrder(mesh, query, nd, [&](vtkIdType i) { return triangles[dirty[i]][0]; }, threads);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
    for (vtkIdType k = 0; k < nd; ++k)
    {
      const vtkIdType t = dirty[order[k]];
      // The sides first (probed already): a triangle a side marks needs no interior probe.
      double worst = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        worst = std::max(worst, sides.Get(Sorted(triangles[t][j], triangles[t][(j + 1) % 3])));
      }
      if (worst <= tolerance)
      {
        worst = std::max(worst, this->ProbeInterior(mesh, query, triangles[t]));
      }
      triangleProtrusion[t] = worst;
    }
    std::vector<Edge> marked;
    double worst = 0.0;
    for (vtkIdType t = 0; t < nt; ++t)
    {
      worst = std::max(worst, triangleProtrusion[t]);
      if (triangleProtrusion[t] > tolerance)
      {
        // The longest side.
        const auto& tri = triangles[t];
        Edge best = Sorted(tri[0], tri[1]);
        double longest = -1.0;
        for (int k = 0; k < 3; ++k)
        {
          const double* p = &(*mesh.Centres)[3 * tri[k]];
          const double* q = &(*mesh.Centres)[3 * tri[(k + 1) % 3]];
          const double d2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
          if (d2 > longest)
          {
            longest = d2;
            best = Sorted(tri[k], tri[(k + 1) % 3]);
          }
        }
        marked.push_back(best);
      }
    }
    for (vtkIdType e = 0; e < nf; ++e)
    {
      const double protrusion = sides.Get(free[e]);
      worst = std::max(worst, protrusion);
      if (protrusion > tolerance)
      {
        marked.push_back(free[e]);
      }
    }
    this->WorstProtrusion = worst;
    if (marked.empty())
    {
      break;
    }
    added += this->SplitEdges(mesh, query, index, marked, free, dirty, threads);
    std::sort(free.begin(), free.end());
  }
  // Every edge again: the sides of the triangles and the edges of no triangle.
  std::vector<std::pair<Edge, int>> counted;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      counted.push_back({ Sorted(t[k], t[(k + 1) % 3]), 1 });
    }
  }
  for (const Edge& e : free)
  {
    counted.push_back({ e, 0 });
  }
  vtkMedialSort(counted.begin(), counted.end(), threads); // equivalent entries are equal
  edges.clear();
  mesh.EdgeTriangles->clear();
  for (const auto& c : counted)
  {
    if (!edges.empty() && edges.back() == c.first)
    {
      mesh.EdgeTriangles->back() += c.second;
    }
    else
    {
      edges.push_back(c.first);
      mesh.EdgeTriangles->push_back(c.second);
    }
  }
  return added;
}
