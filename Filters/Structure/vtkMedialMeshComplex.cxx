// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshComplex.h"

#include "vtkMedialDisjointSets.h"
#include "vtkMedialEnvelope.h"
#include "vtkMedialExactPredicates.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialPowerComplex.h"
#include "vtkMedialSpatialOrder.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace
{
namespace G = vtkMedialGeometry;

enum ContainmentState : char
{
  UNKNOWN = 0,
  INSIDE = 1,
  CROSSES = 2
};

// The n simplices in the spatial order of one of their balls, ballOf(i), given each
// ball's rank in that order (vtkMedialSpatialOrder.h): the loops of surface queries run
// in this order. A stable counting sort on the rank; only the order in which independent
// queries run depends on it, never a result.
template <class BallOf>
std::vector<vtkIdType> OrderByBall(const std::vector<vtkIdType>& ballRanks, vtkIdType n, BallOf ballOf)
{
  std::vector<vtkIdType> start(ballRanks.size() + 1, 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ++start[ballRanks[ballOf(i)] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<vtkIdType> order(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    order[start[ballRanks[ballOf(i)]]++] = i;
  }
  return order;
}
}

bool vtkMedialMeshComplex::Build(const vtkMedialPowerComplex& power, const vtkMedialSurfaceQuery& query,
  const Balls& balls, double protrusionTolerance, int threads, const std::function<bool()>& aborted)
{
  this->Power = &power;
  this->Query = &query;
  this->BallData = balls;
  this->Threads = std::max(1, threads);
  this->Stats = Statistics();
  this->EdgeState.assign(power.GetNumberOfEdges(), UNKNOWN);
  const vtkIdType nb = static_cast<vtkIdType>(balls.Radii->size());
  const std::vector<vtkIdType> ballOrder = vtkMedialSpatialOrder::Order(
    nb, [&](vtkIdType b) { return vtkMedialSpatialOrder::Key(this->Centre(b), query.GetMesh()->Bounds); },
    this->Threads);
  this->BallRanks.resize(nb);
  for (vtkIdType k = 0; k < nb; ++k)
  {
    this->BallRanks[ballOrder[k]] = k;
  }
  this->TriangleState.assign(power.GetNumberOfTriangles(), UNKNOWN);
  auto stop = [&aborted]() { return aborted && aborted(); };

  this->SelectCandidates();
  if (stop())
  {
    return false;
  }
  this->KeepContained();
  this->Stats.FilledTetrahedra += this->FillVoids();
  this->ConnectComponents();
  if (stop())
  {
    return false;
  }
  this->FillEmptyTriangles();
  if (stop())
  {
    return false;
  }
  this->DropDetachedComponents(*balls.SolidComponents);
  this->FillLoops();
  this->Collapse();
  this->TrimAdded();
  if (protrusionTolerance >= 0.0)
  {
    this->PruneProtrusions(protrusionTolerance);
  }
  this->Extract();
  return true;
}

bool vtkMedialMeshComplex::EdgeInside(vtkIdType e)
{
  if (this->EdgeState[e] == UNKNOWN)
  {
    const auto& v = this->Power->EdgeVertices[e];
    // Balls of two solid components: the edge leaves the solid even where it only
    // touches the surface (bodies that touch along an edge or at a point).
    const std::vector<vtkIdType>* solid = this->BallData.SolidComponents;
    const bool apart = solid && (*solid)[v[0]] >= 0 && (*solid)[v[1]] >= 0 && (*solid)[v[0]] != (*solid)[v[1]];
    const double* ends[2] = { this->Centre(v[0]), this->Centre(v[1]) };
    this->EdgeState[e] =
      apart || this->Query->CrossesSurface(ends, 2, vtkMedialExactPredicates::Crosses) ? CROSSES : INSIDE;
  }
  return this->EdgeState[e] == INSIDE;
}

bool vtkMedialMeshComplex::TriangleInside(vtkIdType t)
{
  if (this->TriangleState[t] == UNKNOWN)
  {
    const auto& edges = this->Power->TriangleEdges[t];
    const auto& v = this->Power->TriangleVertices[t];
    const double* corners[3] = { this->Centre(v[0]), this->Centre(v[1]), this->Centre(v[2]) };
    // Its sides cross nothing when they are inside: only the surface's edges through it are left.
    const bool inside = this->EdgeInside(edges[0]) && this->EdgeInside(edges[1]) && this->EdgeInside(edges[2]) &&
      !this->Query->CrossesSurface(corners, 3, vtkMedialExactPredicates::EdgesCrossTriangle);
    this->TriangleState[t] = inside ? INSIDE : CROSSES;
  }
  return this->TriangleState[t] == INSIDE;
}

void vtkMedialMeshComplex::SelectCandidates()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nt = p.GetNumberOfTetrahedra(), nf = p.GetNumberOfTriangles();
  this->TetCandidate.assign(nt, 0);
  this->TriangleCandidate.assign(nf, 0);
  const vtkMedialTriangleMesh& mesh = *this->Query->GetMesh();
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = mesh.Bounds[2 * k] - 1e-3 * mesh.Diagonal;
    hi[k] = mesh.Bounds[2 * k + 1] + 1e-3 * mesh.Diagonal;
  }
  const std::vector<vtkIdType> tetOrder = OrderByBall(this->BallRanks, nt, [&](vtkIdType t) { return p.TetVertices[t][0]; });
#pragma omp parallel for schedule(dynamic, 256) num_threads(this->Threads)
  for (vtkIdType k = 0; k < nt; ++k)
  {
    const vtkIdType t = tetOrder[k];
    this->TetCandidate[t] = p.TetInUnion[t] || this->Query->IsInside(&p.PowerCentres[3 * t]);
  }
  // A triangle's dual: the segment between its tetrahedra's power centres, or on the
  // convex hull the ray from the inner one away from its apex; taken along the line
  // through the triangle's own power centre (GetTriangleDual), which keeps its digits
  // near the shape when those power centres are far off.
  const std::vector<vtkIdType> triangleOrder =
    OrderByBall(this->BallRanks, nf, [&](vtkIdType f) { return p.TriangleVertices[f][0]; });
#pragma omp parallel for schedule(dynamic, 256) num_threads(this->Threads)
  for (vtkIdType k = 0; k < nf; ++k)
  {
    const vtkIdType f = triangleOrder[k];
    const auto& tets = p.TriangleTets[f];
    if (p.TriangleInUnion[f] || this->TetCandidate[tets[0]] || (tets[1] >= 0 && this->TetCandidate[tets[1]]))
    {
      this->TriangleCandidate[f] = 1;
      continue;
    }
    double origin[3], direction[3], t0 = 0.0, t1 = 0.0;
    p.GetTriangleDual(f, origin, direction, t0, t1);
    // Only near the shape (its box): its power centres are outside the solid.
    if (!(t0 < t1) || !G::ClipRayToBox(lo, hi, origin, direction, 3, t0, t1))
    {
      continue;
    }
    double start[3];
    G::AddScaled(origin, t0, direction, start);
    vtkMedialSurfaceQuery::RayHit hit;
    this->TriangleCandidate[f] = this->Query->Intersect(start, direction, 0.0, t1 - t0, -1, hit);
  }
}

void vtkMedialMeshComplex::KeepContained()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nt = p.GetNumberOfTetrahedra(), nf = p.GetNumberOfTriangles(), ne = p.GetNumberOfEdges();
  // An edge is a candidate in the union or on a candidate triangle.
  std::vector<char> edgeCandidate(ne);
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads)
  for (vtkIdType e = 0; e < ne; ++e)
  {
    bool candidate = p.EdgeInUnion[e] != 0;
    for (vtkIdType k = p.EdgeTriangleStart[e]; k < p.EdgeTriangleStart[e + 1] && !candidate; ++k)
    {
      candidate = this->TriangleCandidate[p.EdgeTriangleList[k]] != 0;
    }
    edgeCandidate[e] = candidate;
  }
  // Edges, then triangles (which read their edges' states): each state is written by
  // one thread only.
  const std::vector<vtkIdType> edgeOrder = OrderByBall(this->BallRanks, ne, [&](vtkIdType e) { return p.EdgeVertices[e][0]; });
#pragma omp parallel for schedule(dynamic, 256) num_threads(this->Threads)
  for (vtkIdType k = 0; k < ne; ++k)
  {
    const vtkIdType e = edgeOrder[k];
    if (edgeCandidate[e] && !p.EdgeInUnion[e])
    {
      this->EdgeInside(e);
    }
  }
  const std::vector<vtkIdType> triangleOrder =
    OrderByBall(this->BallRanks, nf, [&](vtkIdType f) { return p.TriangleVertices[f][0]; });
#pragma omp parallel for schedule(dynamic, 64) num_threads(this->Threads)
  for (vtkIdType k = 0; k < nf; ++k)
  {
    const vtkIdType f = triangleOrder[k];
    if (this->TriangleCandidate[f] && !p.TriangleInUnion[f])
    {
      this->TriangleInside(f);
    }
  }
  this->EdgeIn.assign(ne, 0);
  this->TriangleIn.assign(nf, 0);
  this->TetIn.assign(nt, 0);
  vtkIdType rejected = 0;
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads) reduction(+ : rejected)
  for (vtkIdType e = 0; e < ne; ++e)
  {
    this->EdgeIn[e] = edgeCandidate[e] && (p.EdgeInUnion[e] || this->EdgeState[e] == INSIDE);
    rejected += edgeCandidate[e] && !this->EdgeIn[e];
  }
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads) reduction(+ : rejected)
  for (vtkIdType f = 0; f < nf; ++f)
  {
    this->TriangleIn[f] = this->TriangleCandidate[f] && (p.TriangleInUnion[f] || this->TriangleState[f] == INSIDE);
    rejected += this->TriangleCandidate[f] && !this->TriangleIn[f];
  }
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads) reduction(+ : rejected)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    bool in = this->TetCandidate[t];
    for (int j = 0; j < 4 && in && !p.TetInUnion[t]; ++j)
    {
      in = this->TriangleIn[p.TetTriangles[t][j]];
    }
    this->TetIn[t] = in;
    rejected += this->TetCandidate[t] && !in;
  }
  this->Stats.RejectedSimplices = rejected;
  this->VertexIn.assign(p.VertexInUnion.begin(), p.VertexInUnion.end());
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e])
    {
      this->VertexIn[p.EdgeVertices[e][0]] = this->VertexIn[p.EdgeVertices[e][1]] = 1;
    }
  }
}

vtkIdType vtkMedialMeshComplex::FillVoids()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nt = p.GetNumberOfTetrahedra(), nf = p.GetNumberOfTriangles();
  // Flood the complement from the infinite side through triangles not in K.
  std::vector<char> reached(nt, 0);
  std::vector<vtkIdType> queue;
  auto flood = [&](size_t head) {
    for (; head < queue.size(); ++head)
    {
      const vtkIdType t = queue[head];
      for (int j = 0; j < 4; ++j)
      {
        const vtkIdType n = p.TetNeighbours[t][j];
        if (n >= 0 && !this->TriangleIn[p.TetTriangles[t][j]] && !this->TetIn[n] && !reached[n])
        {
          reached[n] = 1;
          queue.push_back(n);
        }
      }
    }
  };
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const vtkIdType t = p.TriangleTets[f][0];
    if (p.TriangleTets[f][1] < 0 && !this->TriangleIn[f] && !this->TetIn[t] && !reached[t])
    {
      reached[t] = 1;
      queue.push_back(t);
    }
  }
  flood(0);
  // Each void left is filled unless one of its simplices crosses the surface (a cavity).
  vtkIdType filled = 0;
  for (vtkIdType seed = 0; seed < nt; ++seed)
  {
    if (reached[seed] || this->TetIn[seed])
    {
      continue;
    }
    const size_t first = queue.size();
    reached[seed] = 1;
    queue.push_back(seed);
    flood(first);
    bool inside = true;
    for (size_t k = first; k < queue.size() && inside; ++k)
    {
      for (int j = 0; j < 4 && inside; ++j)
      {
        const vtkIdType f = p.TetTriangles[queue[k]][j];
        inside = this->TriangleIn[f] || this->TriangleInside(f);
      }
    }
    for (size_t k = first; k < queue.size() && inside; ++k)
    {
      const vtkIdType t = queue[k];
      this->TetIn[t] = 1;
      for (int j = 0; j < 4; ++j)
      {
        const vtkIdType f = p.TetTriangles[t][j];
        this->TriangleIn[f] = 1;
        for (vtkIdType e : p.TriangleEdges[f])
        {
          this->EdgeIn[e] = 1;
        }
      }
      for (vtkIdType b : p.TetVertices[t])
      {
        this->VertexIn[b] = 1;
      }
      ++filled;
    }
  }
  return filled;
}

void vtkMedialMeshComplex::ConnectComponents()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size()), ne = p.GetNumberOfEdges();
  const std::vector<char>& present = this->VertexIn;
  vtkMedialDisjointSets sets(nb);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e])
    {
      sets.Join(p.EdgeVertices[e][0], p.EdgeVertices[e][1]);
    }
  }
  vtkIdType components = 0;
  for (vtkIdType b = 0; b < nb; ++b)
  {
    components += present[b] && sets.Find(b) == b;
  }
  if (components <= 1)
  {
    return;
  }
  // Kruskal: the shortest edges that join two components and stay inside.
  std::vector<std::pair<double, vtkIdType>> order;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const auto& v = p.EdgeVertices[e];
    if (!this->EdgeIn[e] && present[v[0]] && present[v[1]] && sets.Find(v[0]) != sets.Find(v[1]))
    {
      order.emplace_back(G::Distance2(this->Centre(v[0]), this->Centre(v[1])), e);
    }
  }
  std::sort(order.begin(), order.end());
  for (const auto& candidate : order)
  {
    const auto& v = p.EdgeVertices[candidate.second];
    if (sets.Find(v[0]) != sets.Find(v[1]) && this->EdgeInside(candidate.second))
    {
      sets.Join(v[0], v[1]);
      this->EdgeIn[candidate.second] = 1;
      ++this->Stats.ConnectingEdges;
    }
  }
}

void vtkMedialMeshComplex::FillEmptyTriangles()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nf = p.GetNumberOfTriangles();
  for (int round = 0; round < 8; ++round)
  {
    std::vector<vtkIdType> empty;
    for (vtkIdType f = 0; f < nf; ++f)
    {
      const auto& e = p.TriangleEdges[f];
      if (!this->TriangleIn[f] && this->EdgeIn[e[0]] && this->EdgeIn[e[1]] && this->EdgeIn[e[2]])
      {
        empty.push_back(f);
      }
    }
    const vtkIdType n = static_cast<vtkIdType>(empty.size());
#pragma omp parallel for schedule(dynamic, 16) num_threads(this->Threads)
    for (vtkIdType k = 0; k < n; ++k)
    {
      this->TriangleInside(empty[k]); // edges are in K: their states are known
    }
    vtkIdType added = 0;
    for (vtkIdType f : empty)
    {
      if (this->TriangleState[f] == INSIDE)
      {
        this->TriangleIn[f] = 1;
        ++added;
      }
    }
    this->Stats.EmptyTriangles += added;
    const vtkIdType filled = this->FillVoids();
    this->Stats.FilledTetrahedra += filled;
    if (added == 0 && filled == 0)
    {
      break;
    }
  }
}

void vtkMedialMeshComplex::DropDetachedComponents(const std::vector<vtkIdType>& solidComponents)
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size()), ne = p.GetNumberOfEdges();
  vtkMedialDisjointSets sets(nb);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e])
    {
      sets.Join(p.EdgeVertices[e][0], p.EdgeVertices[e][1]);
    }
  }
  // Balls per component of K; the largest per solid component wins (ties: smaller root).
  std::vector<vtkIdType> size(nb, 0);
  for (vtkIdType b = 0; b < nb; ++b)
  {
    size[sets.Find(b)] += this->VertexIn[b];
  }
  std::vector<std::pair<vtkIdType, vtkIdType>> best; // per solid component: (size, root)
  for (vtkIdType b = 0; b < nb; ++b)
  {
    if (!this->VertexIn[b] || sets.Find(b) != b || solidComponents[b] < 0)
    {
      continue;
    }
    const size_t label = static_cast<size_t>(solidComponents[b]);
    if (best.size() <= label)
    {
      best.resize(label + 1, { 0, -1 });
    }
    if (size[b] > best[label].first)
    {
      best[label] = { size[b], b };
    }
  }
  std::vector<char> keep(nb, 0);
  for (const auto& winner : best)
  {
    if (winner.second >= 0)
    {
      keep[winner.second] = 1;
    }
  }
  for (vtkIdType b = 0; b < nb; ++b)
  {
    if (this->VertexIn[b] && !keep[sets.Find(b)])
    {
      this->VertexIn[b] = 0;
      ++this->Stats.DetachedBalls;
    }
  }
  if (this->Stats.DetachedBalls == 0)
  {
    return;
  }
  // Simplices of the dropped balls go with them (a component keeps its simplices whole).
  for (vtkIdType e = 0; e < ne; ++e)
  {
    this->EdgeIn[e] = this->EdgeIn[e] && this->VertexIn[p.EdgeVertices[e][0]];
  }
  for (vtkIdType f = 0; f < p.GetNumberOfTriangles(); ++f)
  {
    this->TriangleIn[f] = this->TriangleIn[f] && this->VertexIn[p.TriangleVertices[f][0]];
  }
  for (vtkIdType t = 0; t < p.GetNumberOfTetrahedra(); ++t)
  {
    this->TetIn[t] = this->TetIn[t] && this->VertexIn[p.TetVertices[t][0]];
  }
}

void vtkMedialMeshComplex::Collapse()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nf = p.GetNumberOfTriangles();
  std::vector<int> cofaces = this->TetsOnTriangles(this->TetIn);
  std::vector<vtkIdType> queue;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (this->TriangleIn[f] && cofaces[f] == 1)
    {
      queue.push_back(f);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType f = queue[head];
    if (!this->TriangleIn[f] || cofaces[f] != 1)
    {
      continue;
    }
    const auto& tets = p.TriangleTets[f];
    const vtkIdType t = this->TetIn[tets[0]] ? tets[0] : tets[1];
    this->TetIn[t] = 0;
    this->TriangleIn[f] = 0;
    for (vtkIdType g : p.TetTriangles[t])
    {
      if (g != f && --cofaces[g] == 1)
      {
        queue.push_back(g);
      }
    }
  }
  this->Stats.RemainingTetrahedra = std::count(this->TetIn.begin(), this->TetIn.end(), 1);
}

double vtkMedialMeshComplex::Protrusion(const vtkIdType* ids, const double* weights, int n, double tolerance) const
{
  const double* centres[3];
  double radii[3];
  for (int j = 0; j < n; ++j)
  {
    centres[j] = this->Centre(ids[j]);
    radii[j] = (*this->BallData.Radii)[ids[j]];
  }
  thread_local std::vector<vtkMedialSurfaceQuery::ClosestHit> hits;
  return vtkMedialEnvelope::InterpolatedProtrusion(*this->Query, centres, radii, weights, n, tolerance, hits);
}

// Protrusions of the collapses' candidates, probed once each and only when asked
// for: a triangle protrudes when its centroid or a side's midpoint does (its sides
// first), an edge when its midpoint does (shared by its triangles). Values are functions of the balls
// only, so when they are probed does not change them.
class vtkMedialMeshComplex::ProtrusionMemo
{
public:
  ProtrusionMemo(const vtkMedialMeshComplex& complex, double tolerance)
    : Complex(complex)
    , Tolerance(tolerance)
    , Edge(complex.Power->GetNumberOfEdges(), Unknown)
    , Triangle(complex.Power->GetNumberOfTriangles(), Unknown)
  {
  }
  // Probes the given triangles and edges (repeats allowed) in parallel.
  void ProbeAll(const std::vector<vtkIdType>& triangles, std::vector<vtkIdType>& edges)
  {
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    const vtkIdType ne = static_cast<vtkIdType>(edges.size()), nt = static_cast<vtkIdType>(triangles.size());
    const vtkMedialPowerComplex& p = *this->Complex.Power;
    const std::vector<vtkIdType> edgeOrder =
      OrderByBall(this->Complex.BallRanks, ne, [&](vtkIdType k) { return p.EdgeVertices[edges[k]][0]; });
#pragma omp parallel for schedule(dynamic, 256) num_threads(this->Complex.Threads)
    for (vtkIdType k = 0; k < ne; ++k)
    {
      const vtkIdType e = edges[edgeOrder[k]];
      this->Edge[e] = this->ProbeEdge(e);
    }
    const std::vector<vtkIdType> triangleOrder =
      OrderByBall(this->Complex.BallRanks, nt, [&](vtkIdType k) { return p.TriangleVertices[triangles[k]][0]; });
#pragma omp parallel for schedule(dynamic, 64) num_threads(this->Complex.Threads)
    for (vtkIdType k = 0; k < nt; ++k)
    {
      const vtkIdType f = triangles[triangleOrder[k]];
      this->Triangle[f] = this->ProbeTriangle(f); // its sides are known
    }
  }
  bool EdgeProtrudes(vtkIdType e) { return this->EdgeValue(e) > this->Tolerance; }
  bool TriangleProtrudes(vtkIdType f)
  {
    if (this->Triangle[f] == Unknown)
    {
      this->Triangle[f] = this->ProbeTriangle(f);
    }
    return this->Triangle[f] > this->Tolerance;
  }

private:
  static constexpr double Unknown = -1.0; // protrusions are >= 0
  double ProbeEdge(vtkIdType e) const
  {
    const double half[2] = { 0.5, 0.5 };
    return this->Complex.Protrusion(this->Complex.Power->EdgeVertices[e].data(), half, 2, this->Tolerance);
  }
  double ProbeTriangle(vtkIdType f)
  {
    // The sides first: one beyond the tolerance decides, and the centroid needs no probe.
    double worst = 0.0;
    for (vtkIdType e : this->Complex.Power->TriangleEdges[f])
    {
      worst = std::max(worst, this->EdgeValue(e));
    }
    if (worst > this->Tolerance)
    {
      return worst;
    }
    const double third[3] = { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };
    return std::max(worst, this->Complex.Protrusion(this->Complex.Power->TriangleVertices[f].data(), third, 3, this->Tolerance));
  }
  double EdgeValue(vtkIdType e)
  {
    if (this->Edge[e] == Unknown)
    {
      this->Edge[e] = this->ProbeEdge(e);
    }
    return this->Edge[e];
  }

  const vtkMedialMeshComplex& Complex;
  double Tolerance;
  std::vector<double> Edge, Triangle;
};

void vtkMedialMeshComplex::PruneProtrusions(double tolerance)
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nf = p.GetNumberOfTriangles(), ne = p.GetNumberOfEdges();
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size());
  // Triangles on each edge (CSR over the triangles left) and edges on each ball.
  std::vector<vtkIdType> triangles;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (this->TriangleIn[f])
    {
      triangles.push_back(f);
    }
  }
  std::vector<vtkIdType> edgeStart(ne + 1, 0), edgeTriangles, alive(ne, 0), degree(nb, 0);
  for (vtkIdType f : triangles)
  {
    for (vtkIdType e : p.TriangleEdges[f])
    {
      ++edgeStart[e + 1];
      ++alive[e];
    }
  }
  std::partial_sum(edgeStart.begin(), edgeStart.end(), edgeStart.begin());
  edgeTriangles.resize(edgeStart.back());
  {
    std::vector<vtkIdType> fill(edgeStart.begin(), edgeStart.end() - 1);
    for (vtkIdType f : triangles)
    {
      for (vtkIdType e : p.TriangleEdges[f])
      {
        edgeTriangles[fill[e]++] = f;
      }
    }
  }
  // The edges of K on each ball (CSR, in increasing order).
  std::vector<vtkIdType> ballEdgeStart(nb + 1, 0), ballEdges;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e])
    {
      for (vtkIdType b : p.EdgeVertices[e])
      {
        ++degree[b];
        ++ballEdgeStart[b + 1];
      }
    }
  }
  std::partial_sum(ballEdgeStart.begin(), ballEdgeStart.end(), ballEdgeStart.begin());
  ballEdges.resize(ballEdgeStart.back());
  {
    std::vector<vtkIdType> fill(ballEdgeStart.begin(), ballEdgeStart.end() - 1);
    for (vtkIdType e = 0; e < ne; ++e)
    {
      if (this->EdgeIn[e])
      {
        ballEdges[fill[p.EdgeVertices[e][0]]++] = e;
        ballEdges[fill[p.EdgeVertices[e][1]]++] = e;
      }
    }
  }
  // Collapses, in a fixed order: a triangle through a free side, an edge through a free end.
  auto freeSide = [&](vtkIdType f) {
    for (vtkIdType e : p.TriangleEdges[f])
    {
      if (alive[e] == 1)
      {
        return e;
      }
    }
    return vtkIdType(-1);
  };
  auto freeEnd = [&](vtkIdType e) {
    return this->EdgeIn[e] && alive[e] == 0 && (degree[p.EdgeVertices[e][0]] == 1 || degree[p.EdgeVertices[e][1]] == 1);
  };
  // Protrusions are probed only where a collapse asks for them: in parallel for the
  // triangles with a free side and the edges with a free end now, one by one for those
  // the collapses free later. Each is a function of its balls only (the same value
  // whenever it is probed), and an edge's midpoint is probed once for all its triangles.
  ProtrusionMemo memo(*this, tolerance);
  {
    std::vector<vtkIdType> freeTriangles, edges;
    for (vtkIdType f : triangles)
    {
      if (freeSide(f) >= 0)
      {
        freeTriangles.push_back(f);
        edges.insert(edges.end(), p.TriangleEdges[f].begin(), p.TriangleEdges[f].end());
      }
    }
    for (vtkIdType e = 0; e < ne; ++e)
    {
      if (freeEnd(e))
      {
        edges.push_back(e);
      }
    }
    memo.ProbeAll(freeTriangles, edges);
  }
  std::vector<vtkIdType> queue(triangles.begin(), triangles.end());
  auto removeEdge = [&](vtkIdType e) {
    this->EdgeIn[e] = 0;
    for (vtkIdType b : p.EdgeVertices[e])
    {
      if (--degree[b] == 0)
      {
        this->VertexIn[b] = 0;
      }
    }
  };
  std::vector<vtkIdType> bareEdges;
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e] && alive[e] == 0)
    {
      bareEdges.push_back(e);
    }
  }
  for (size_t head = 0, bare = 0; head < queue.size() || bare < bareEdges.size();)
  {
    if (head < queue.size())
    {
      const vtkIdType f = queue[head++];
      const vtkIdType side = this->TriangleIn[f] ? freeSide(f) : -1;
      if (side < 0 || !memo.TriangleProtrudes(f))
      {
        continue;
      }
      this->TriangleIn[f] = 0;
      removeEdge(side);
      ++this->Stats.PrunedTriangles;
      for (vtkIdType e : p.TriangleEdges[f])
      {
        if (--alive[e] == 1)
        {
          for (vtkIdType g = edgeStart[e]; g < edgeStart[e + 1]; ++g)
          {
            queue.push_back(edgeTriangles[g]); // its other triangle may now have a free side
          }
        }
        else if (alive[e] == 0 && e != side)
        {
          bareEdges.push_back(e); // may have a free end now
        }
      }
      continue;
    }
    const vtkIdType e = bareEdges[bare++];
    const auto& v = p.EdgeVertices[e];
    if (!freeEnd(e) || !memo.EdgeProtrudes(e))
    {
      continue;
    }
    const vtkIdType inner = degree[v[0]] == 1 ? v[1] : v[0];
    removeEdge(e);
    ++this->Stats.PrunedEdges;
    for (vtkIdType k = ballEdgeStart[inner]; k < ballEdgeStart[inner + 1]; ++k)
    {
      const vtkIdType next = ballEdges[k];
      if (this->EdgeIn[next] && alive[next] == 0)
      {
        bareEdges.push_back(next); // may now have a free end
      }
    }
  }
}

void vtkMedialMeshComplex::Extract()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size());
  const vtkIdType ne = p.GetNumberOfEdges(), nf = p.GetNumberOfTriangles();
  std::vector<int> edgeTriangles(ne, 0);
  this->Triangles.clear();
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (this->TriangleIn[f])
    {
      this->Triangles.push_back(p.TriangleVertices[f]);
      for (vtkIdType e : p.TriangleEdges[f])
      {
        ++edgeTriangles[e];
      }
    }
  }
  const std::vector<char>& present = this->VertexIn;
  vtkMedialDisjointSets sets(nb);
  this->Edges.clear();
  this->EdgeTriangles.clear();
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (this->EdgeIn[e])
    {
      const auto& v = p.EdgeVertices[e];
      this->Edges.push_back(v);
      this->EdgeTriangles.push_back(edgeTriangles[e]);
      sets.Join(v[0], v[1]);
    }
  }
  this->Vertices.clear();
  this->Components = 0;
  for (vtkIdType b = 0; b < nb; ++b)
  {
    if (present[b])
    {
      this->Vertices.push_back(b);
      this->Components += sets.Find(b) == b;
    }
  }
}

std::vector<vtkIdType> vtkMedialMeshComplex::LoopBalls() const
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size());
  const vtkIdType ne = p.GetNumberOfEdges(), nf = p.GetNumberOfTriangles();
  std::vector<char> tetIn = this->TetIn, triangleIn = this->TriangleIn, edgeIn = this->EdgeIn;
  // Tetrahedra through free triangles.
  std::vector<int> triangleTets = this->TetsOnTriangles(tetIn);
  std::vector<vtkIdType> queue;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (triangleIn[f] && triangleTets[f] == 1)
    {
      queue.push_back(f);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType f = queue[head];
    if (!triangleIn[f] || triangleTets[f] != 1)
    {
      continue;
    }
    const auto& tets = p.TriangleTets[f];
    const vtkIdType t = tetIn[tets[0]] ? tets[0] : tets[1];
    tetIn[t] = 0;
    triangleIn[f] = 0;
    for (vtkIdType g : p.TetTriangles[t])
    {
      if (--triangleTets[g] == 1 && triangleIn[g])
      {
        queue.push_back(g);
      }
    }
  }
  // Triangles (with no tetrahedron left) through free edges.
  std::vector<int> edgeTriangles = this->TrianglesOnEdges(triangleIn);
  auto freeEdge = [&](vtkIdType f) {
    for (vtkIdType e : p.TriangleEdges[f])
    {
      if (edgeTriangles[e] == 1 && edgeIn[e])
      {
        return e;
      }
    }
    return vtkIdType(-1);
  };
  queue.clear();
  for (vtkIdType f = 0; f < nf; ++f)
  {
    if (triangleIn[f] && triangleTets[f] == 0)
    {
      queue.push_back(f);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType f = queue[head];
    const vtkIdType e = triangleIn[f] && triangleTets[f] == 0 ? freeEdge(f) : -1;
    if (e < 0)
    {
      continue;
    }
    triangleIn[f] = 0;
    edgeIn[e] = 0;
    for (vtkIdType g : p.TriangleEdges[f])
    {
      if (--edgeTriangles[g] == 1)
      {
        for (vtkIdType k = p.EdgeTriangleStart[g]; k < p.EdgeTriangleStart[g + 1]; ++k)
        {
          queue.push_back(p.EdgeTriangleList[k]);
        }
      }
    }
  }
  // Edges (with no triangle left) through free ends. Taking one away only lowers
  // degrees, so an edge that may go stays so until it goes: the edges left do not
  // depend on the order, and a queue (the bare edges at each ball whose degree falls
  // to 1) finds them in one pass instead of sweeping every edge until nothing changes.
  std::vector<int> degree(nb, 0);
  std::vector<vtkIdType> bare; // in K and on no triangle
  for (vtkIdType e = 0; e < ne; ++e)
  {
    if (edgeIn[e])
    {
      ++degree[p.EdgeVertices[e][0]];
      ++degree[p.EdgeVertices[e][1]];
      if (edgeTriangles[e] == 0)
      {
        bare.push_back(e);
      }
    }
  }
  std::vector<vtkIdType> bareStart(nb + 1, 0), bareAt(2 * bare.size());
  for (vtkIdType e : bare)
  {
    ++bareStart[p.EdgeVertices[e][0] + 1];
    ++bareStart[p.EdgeVertices[e][1] + 1];
  }
  std::partial_sum(bareStart.begin(), bareStart.end(), bareStart.begin());
  {
    std::vector<vtkIdType> fill(bareStart.begin(), bareStart.end() - 1);
    for (vtkIdType e : bare)
    {
      bareAt[fill[p.EdgeVertices[e][0]]++] = e;
      bareAt[fill[p.EdgeVertices[e][1]]++] = e;
    }
  }
  queue.clear();
  for (vtkIdType e : bare)
  {
    if (degree[p.EdgeVertices[e][0]] == 1 || degree[p.EdgeVertices[e][1]] == 1)
    {
      queue.push_back(e);
    }
  }
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType e = queue[head];
    if (!edgeIn[e])
    {
      continue;
    }
    edgeIn[e] = 0;
    for (vtkIdType b : p.EdgeVertices[e])
    {
      if (--degree[b] == 1)
      {
        for (vtkIdType k = bareStart[b]; k < bareStart[b + 1]; ++k)
        {
          if (edgeIn[bareAt[k]])
          {
            queue.push_back(bareAt[k]);
          }
        }
      }
    }
  }
  // The loops: what is left of the edges of no triangle (closed surfaces left are
  // voids, FillVoids' concern).
  std::vector<char> core(nb, 0);
  for (vtkIdType e : bare)
  {
    if (edgeIn[e])
    {
      core[p.EdgeVertices[e][0]] = core[p.EdgeVertices[e][1]] = 1;
    }
  }
  std::vector<vtkIdType> balls;
  for (vtkIdType b = 0; b < nb; ++b)
  {
    if (core[b])
    {
      balls.push_back(b);
    }
  }
  return balls;
}

void vtkMedialMeshComplex::FillLoops()
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nb = static_cast<vtkIdType>(p.BallIsVertex.size());
  const vtkIdType ne = p.GetNumberOfEdges(), nf = p.GetNumberOfTriangles(), nt = p.GetNumberOfTetrahedra();
  const std::vector<vtkIdType> core = this->LoopBalls();
  if (core.empty())
  {
    return;
  }
  // Tetrahedra on each ball.
  std::vector<vtkIdType> ballTetStart(nb + 1, 0), ballTets;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (vtkIdType b : p.TetVertices[t])
    {
      ++ballTetStart[b + 1];
    }
  }
  std::partial_sum(ballTetStart.begin(), ballTetStart.end(), ballTetStart.begin());
  ballTets.resize(ballTetStart.back());
  {
    std::vector<vtkIdType> fill(ballTetStart.begin(), ballTetStart.end() - 1);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      for (vtkIdType b : p.TetVertices[t])
      {
        ballTets[fill[b]++] = t;
      }
    }
  }
  // The region: the tetrahedra on the loops' balls and on their neighbours.
  std::vector<char> inRegion(nb, 0);
  for (vtkIdType b : core)
  {
    for (vtkIdType k = ballTetStart[b]; k < ballTetStart[b + 1]; ++k)
    {
      for (vtkIdType c : p.TetVertices[ballTets[k]])
      {
        inRegion[c] = 1;
      }
    }
  }
  std::vector<vtkIdType> tets, triangles, edges;
  {
    std::vector<char> tetSeen(nt, 0), triangleSeen(nf, 0), edgeSeen(ne, 0);
    for (vtkIdType b = 0; b < nb; ++b)
    {
      for (vtkIdType k = ballTetStart[b]; inRegion[b] && k < ballTetStart[b + 1]; ++k)
      {
        const vtkIdType t = ballTets[k];
        if (tetSeen[t])
        {
          continue;
        }
        tetSeen[t] = 1;
        tets.push_back(t);
        for (vtkIdType f : p.TetTriangles[t])
        {
          if (!triangleSeen[f])
          {
            triangleSeen[f] = 1;
            triangles.push_back(f);
            for (vtkIdType e : p.TriangleEdges[f])
            {
              if (!edgeSeen[e])
              {
                edgeSeen[e] = 1;
                edges.push_back(e);
              }
            }
          }
        }
      }
    }
    std::sort(tets.begin(), tets.end());
    std::sort(triangles.begin(), triangles.end());
    std::sort(edges.begin(), edges.end());
  }
  // Containment of the region's simplices (edges first: triangles read them).
  const vtkIdType nre = static_cast<vtkIdType>(edges.size()), nrf = static_cast<vtkIdType>(triangles.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(this->Threads)
  for (vtkIdType k = 0; k < nre; ++k)
  {
    this->EdgeInside(edges[k]);
  }
#pragma omp parallel for schedule(dynamic, 64) num_threads(this->Threads)
  for (vtkIdType k = 0; k < nrf; ++k)
  {
    this->TriangleInside(triangles[k]);
  }
  // Closure under the operations that keep or lower the homology: a triangle inside the
  // solid whose sides are in K (it fills a loop or closes a void), or whose two sides are
  // and the third is added with it (an expansion); a tetrahedron inside whose faces are in
  // K (it fills a void), or whose three faces are and the fourth is added with it.
  vtkIdType added = 0;
  for (bool changed = true; changed;)
  {
    changed = false;
    for (vtkIdType f : triangles)
    {
      if (this->TriangleIn[f] || this->TriangleState[f] != INSIDE)
      {
        continue;
      }
      int missing = 0;
      vtkIdType gap = -1;
      for (vtkIdType e : p.TriangleEdges[f])
      {
        if (!this->EdgeIn[e])
        {
          ++missing;
          gap = e;
        }
      }
      const auto& v = p.TriangleVertices[f];
      if (missing > 1 || !this->VertexIn[v[0]] || !this->VertexIn[v[1]] || !this->VertexIn[v[2]])
      {
        continue;
      }
      if (gap >= 0)
      {
        this->EdgeIn[gap] = 1;
      }
      this->TriangleIn[f] = 1;
      this->TriangleAdded.push_back(f);
      ++added;
      changed = true;
    }
    for (vtkIdType t : tets)
    {
      if (this->TetIn[t])
      {
        continue;
      }
      int missing = 0, inside = 0;
      vtkIdType gap = -1;
      for (vtkIdType f : p.TetTriangles[t])
      {
        inside += this->TriangleState[f] == INSIDE || this->TriangleIn[f];
        if (!this->TriangleIn[f])
        {
          ++missing;
          gap = f;
        }
      }
      if (inside < 4 || missing > 1)
      {
        continue;
      }
      if (gap >= 0)
      {
        bool sides = true;
        for (vtkIdType e : p.TriangleEdges[gap])
        {
          sides = sides && this->EdgeIn[e];
        }
        if (!sides)
        {
          continue;
        }
        this->TriangleIn[gap] = 1;
        this->TriangleAdded.push_back(gap);
      }
      this->TetIn[t] = 1;
      ++added;
      changed = true;
    }
  }
  this->Stats.EmptyTriangles += added;
  this->Stats.FilledTetrahedra += this->FillVoids();
}

void vtkMedialMeshComplex::TrimAdded()
{
  const vtkMedialPowerComplex& p = *this->Power;
  if (this->TriangleAdded.empty())
  {
    return;
  }
  std::vector<int> edgeTriangles = this->TrianglesOnEdges(this->TriangleIn);
  std::vector<char> added(p.GetNumberOfTriangles(), 0);
  for (vtkIdType f : this->TriangleAdded)
  {
    added[f] = 1;
  }
  const std::vector<int> cofaces = this->TetsOnTriangles(this->TetIn); // tetrahedra left (not collapsible)
  std::vector<vtkIdType> queue(this->TriangleAdded);
  std::sort(queue.begin(), queue.end());
  queue.erase(std::unique(queue.begin(), queue.end()), queue.end());
  for (size_t head = 0; head < queue.size(); ++head)
  {
    const vtkIdType f = queue[head];
    if (!this->TriangleIn[f] || cofaces[f] > 0)
    {
      continue;
    }
    vtkIdType side = -1;
    for (vtkIdType e : p.TriangleEdges[f])
    {
      side = side < 0 && edgeTriangles[e] == 1 && this->EdgeIn[e] ? e : side;
    }
    if (side < 0)
    {
      continue;
    }
    this->TriangleIn[f] = 0;
    this->EdgeIn[side] = 0;
    for (vtkIdType e : p.TriangleEdges[f])
    {
      if (--edgeTriangles[e] == 1)
      {
        for (vtkIdType k = p.EdgeTriangleStart[e]; k < p.EdgeTriangleStart[e + 1]; ++k)
        {
          const vtkIdType g = p.EdgeTriangleList[k];
          if (added[g] && this->TriangleIn[g])
          {
            queue.push_back(g);
          }
        }
      }
    }
  }
  this->TriangleAdded.clear();
}


std::vector<int> vtkMedialMeshComplex::TetsOnTriangles(const std::vector<char>& tetIn) const
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType nf = p.GetNumberOfTriangles();
  std::vector<int> count(nf);
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads)
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const auto& tets = p.TriangleTets[f];
    count[f] = (tetIn[tets[0]] != 0) + (tets[1] >= 0 && tetIn[tets[1]] != 0);
  }
  return count;
}

std::vector<int> vtkMedialMeshComplex::TrianglesOnEdges(const std::vector<char>& triangleIn) const
{
  const vtkMedialPowerComplex& p = *this->Power;
  const vtkIdType ne = p.GetNumberOfEdges();
  std::vector<int> count(ne);
#pragma omp parallel for schedule(static, 4096) num_threads(this->Threads)
  for (vtkIdType e = 0; e < ne; ++e)
  {
    int n = 0;
    for (vtkIdType k = p.EdgeTriangleStart[e]; k < p.EdgeTriangleStart[e + 1]; ++k)
    {
      n += triangleIn[p.EdgeTriangleList[k]] != 0;
    }
    count[e] = n;
  }
  return count;
}

void vtkMedialMeshComplex::CountComponents()
{
  vtkIdType nb = 0;
  for (vtkIdType b : this->Vertices)
  {
    nb = std::max(nb, b + 1);
  }
  vtkMedialDisjointSets sets(nb);
  for (const auto& e : this->Edges)
  {
    sets.Join(e[0], e[1]);
  }
  this->Components = 0;
  for (vtkIdType b : this->Vertices)
  {
    this->Components += sets.Find(b) == b;
  }
}
