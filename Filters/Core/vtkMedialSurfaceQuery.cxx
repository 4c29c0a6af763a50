// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSurfaceQuery.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
namespace G = vtkMedialGeometry;
using ClosestHit = vtkMedialSurfaceQuery::ClosestHit;

// The tree's within-distance visits as hits (the walks give squared distances).
struct HitCollector
{
  std::vector<ClosestHit>& Hits;
  void operator()(double d2, const double* q, vtkIdType t) const
  {
    ClosestHit hit;
    std::copy(q, q + 3, hit.Point);
    hit.Distance = std::sqrt(d2);
    hit.Triangle = t;
    this->Hits.push_back(hit);
  }
};

// Hits in triangle order, whatever order the walk visited them in.
void SortByTriangle(std::vector<ClosestHit>& hits)
{
  std::sort(
    hits.begin(), hits.end(), [](const ClosestHit& a, const ClosestHit& b) { return a.Triangle < b.Triangle; });
}
}

bool vtkMedialSurfaceQuery::Build(
  const vtkMedialTriangleMesh* mesh, std::string& error, const std::function<bool()>& aborted)
{
  this->Mesh = mesh;
  const vtkIdType nt = mesh->GetNumberOfTriangles();
  if (nt <= 0 || nt > static_cast<vtkIdType>(std::numeric_limits<unsigned>::max() / 2))
  {
    error = "triangle count is zero or too large for the BVH";
    return false;
  }
  const double* b = mesh->Bounds;
  double extent = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    extent = std::max(extent, 0.5 * (b[2 * i + 1] - b[2 * i]));
  }
  this->RayPad = 1e-6 * extent;
  this->Slack = 1e-12 * mesh->Diagonal;
  if ((aborted && aborted()) || !this->Tree.Build(*mesh, aborted))
  {
    error = aborted && aborted() ? "aborted" : "cannot build the tangent-ball tree";
    return false;
  }
  return true;
}

// The first hit beyond tMin of a ray from `origin`, from first(start, along, triangle),
// the ray's first triangle in (start, tMax); hit distances are redone against the hit
// triangle's plane along the ray from `origin`.
template <class FirstHit>
bool vtkMedialSurfaceQuery::FirstHitFrom(
  const double origin[3], const double direction[3], double tMin, FirstHit first, RayHit& hit) const
{
  double start = tMin;
  // At most a few retries: each one steps past a hit at the origin.
  for (int attempt = 0; attempt < 4; ++attempt)
  {
    double along;
    vtkIdType t;
    if (!first(start, along, t))
    {
      return false;
    }
    const double* n = this->GetNormal(t);
    double scratch[9];
    const double* v0 = this->Tree.GetTriangleVertices(t, scratch);
    double d[3];
    G::Sub(v0, origin, d);
    const double denom = G::Dot(n, direction);
    double distance = along;
    if (std::fabs(denom) > 1e-12)
    {
      const double exact = G::Dot(n, d) / denom;
      if (std::fabs(exact - distance) <= 10.0 * this->RayPad + 1e-6 * distance)
      {
        if (exact <= tMin)
        {
          // A hit at the origin (a face through it, e.g. around a vertex): step past.
          start = std::max(along, start) + this->RayPad;
          continue;
        }
        distance = exact;
      }
    }
    hit.Distance = distance;
    hit.Triangle = t;
    return true;
  }
  return false;
}

// One ray from `rayOrigin` (the origin itself, or nudged off it) through the own tree.
bool vtkMedialSurfaceQuery::IntersectFrom(const double rayOrigin[3], const double origin[3],
  const double direction[3], double tMin, double tMax, vtkIdType ignoreTriangle, RayHit& hit) const
{
  return this->FirstHitFrom(origin, direction, tMin,
    [&](double start, double& along, vtkIdType& t) {
      return this->Tree.IntersectRay(rayOrigin, direction, start, tMax, ignoreTriangle, along, t);
    },
    hit);
}

bool vtkMedialSurfaceQuery::Intersect(const double origin[3], const double direction[3],
  double tMin, double tMax, vtkIdType ignoreTriangle, RayHit& hit) const
{
  return this->IntersectFrom(origin, origin, direction, tMin, tMax, ignoreTriangle, hit);
}

bool vtkMedialSurfaceQuery::IntersectFromInside(
  const double origin[3], const double direction[3], double tMin, vtkIdType ignoreTriangle, RayHit& hit) const
{
  auto fromInside = [&](const double rayOrigin[3]) {
    return this->IntersectFrom(rayOrigin, origin, direction, tMin, HUGE_VAL, ignoreTriangle, hit) &&
      G::Dot(this->GetNormal(hit.Triangle), direction) > 0.0;
  };
  if (fromInside(origin))
  {
    return true;
  }
  // The ray test is watertight, but a ray through a vertex or an edge may still meet
  // a face around it edge-on, or one of a fold, first. Nudge the ray sideways by the
  // padding and try again, on either side.
  double side[3] = { 0, 0, 0 }, unit[3] = { 0, 0, 0 };
  const double ax = std::fabs(direction[0]), ay = std::fabs(direction[1]), az = std::fabs(direction[2]);
  unit[ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  G::Cross(direction, unit, side);
  const double length = std::sqrt(G::Dot(side, side));
  for (double sign : { 1.0, -1.0 })
  {
    double nudged[3];
    G::AddScaled(origin, sign * this->RayPad / length, side, nudged);
    if (length > 0.0 && fromInside(nudged))
    {
      return true;
    }
  }
  return false;
}

bool vtkMedialSurfaceQuery::ClosestPoint(
  const double x[3], double upperBound, ClosestHit& hit, const ContactFilter* filter) const
{
  return this->Tree.ClosestPoint(x, upperBound, filter ? filter->OwnTriangle : -1,
    filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0, filter && filter->CapOnly,
    hit.Point, hit.Distance, hit.Triangle);
}

bool vtkMedialSurfaceQuery::ContainsBall(
  const double centre[3], double radius, const ContactFilter* filter) const
{
  const double limit = radius - this->Slack;
  if (limit <= 0.0)
  {
    return true;
  }
  return this->Tree.ContainsBall(centre, limit, filter ? filter->OwnTriangle : -1,
    filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0, filter && filter->CapOnly);
}

void vtkMedialSurfaceQuery::MaximalTangentBall(const double p[3], const double n[3],
  const ContactFilter& filter, double allowed, TangentBall& ball) const
{
  this->Tree.MaximalTangentBall(p, n, filter.OwnTriangle, filter.CosMinAngle, this->Slack, allowed, ball);
}

int vtkMedialSurfaceQuery::CountCrossings(
  const double origin[3], const double direction[3], double tMax) const
{
  // Every triangle on the ray in one walk; the hits are then read off that list, the
  // same as Intersect() restarted past each one would give (vtkMedialTriangleBVH::
  // FirstCrossing), at a fraction of the cost (a walk per hit, and a last one that
  // meets nothing).
  thread_local std::vector<vtkMedialTriangleBVH::RayCrossing> crossings;
  this->Tree.RayCrossings(origin, direction, 0.0, -1, crossings);
  auto first = [&](double start, double& along, vtkIdType& t) {
    return vtkMedialTriangleBVH::FirstCrossing(crossings, start, tMax, along, t);
  };
  int count = 0;
  double start = 0.0;
  RayHit hit;
  // Each hit restarts the ray just past it (a hit on an edge shared by two triangles
  // counts once); the cap only guards against a stall.
  while (count < 100000 && this->FirstHitFrom(origin, direction, start, first, hit))
  {
    ++count;
    start = std::max(hit.Distance, start) + this->CrossingStep();
  }
  return count;
}

bool vtkMedialSurfaceQuery::IsInside(const double x[3]) const
{
  // Three unit directions far from the axes and from each other.
  static const double directions[3][3] = { { 0.5773502691896258, 0.6172133998483676,
                                             0.5345224838248488 },
    { -0.7071067811865476, 0.2672612419124244, 0.6546536707079771 },
    { 0.2182178902359924, -0.8728715609439696, 0.4364357804719848 } };
  const double* b = this->Mesh->Bounds;
  if (x[0] < b[0] || x[0] > b[1] || x[1] < b[2] || x[1] > b[3] || x[2] < b[4] || x[2] > b[5])
  {
    return false;
  }
  // The third ray only breaks a tie.
  const int first = this->CountCrossings(x, directions[0], HUGE_VAL) % 2;
  const int second = this->CountCrossings(x, directions[1], HUGE_VAL) % 2;
  if (first == second)
  {
    return first == 1;
  }
  return this->CountCrossings(x, directions[2], HUGE_VAL) % 2 == 1;
}

void vtkMedialSurfaceQuery::FindIntersectingPairs(int threads, std::vector<std::pair<vtkIdType, vtkIdType>>& pairs,
  vtkMedialTriangleBVH::PairSearchStatistics* statistics) const
{
  const double* b = this->Mesh->Bounds;
  double extent = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    extent = std::max(extent, std::fabs(b[k]));
  }
  // Plane distances are computed on absolute coordinates: their rounding grows with
  // the coordinates' size, not only with the mesh's.
  this->Tree.FindIntersectingPairs(*this->Mesh, 1e-9 * this->Mesh->Diagonal + 1e-13 * extent, threads, pairs, statistics);
}

bool vtkMedialSurfaceQuery::SegmentCrossesSurface(const double p[3], const double q[3]) const
{
  const double* ends[2] = { p, q };
  return this->CrossesSurface(ends, 2, nullptr);
}

bool vtkMedialSurfaceQuery::TriangleCrossesSurface(
  const double a[3], const double b[3], const double c[3]) const
{
  const double* corners[3] = { a, b, c };
  return this->CrossesSurface(corners, 3, nullptr);
}

bool vtkMedialSurfaceQuery::CrossesSurface(const double* const points[], int n, CrossingTest test) const
{
  bool crosses = false;
  if (test)
  {
    // An exact test says yes only for a triangle that meets the points' simplex, hence
    // its box: only the triangles whose own box meets the simplex's (padded by the
    // slack) are tested, through the tree's box walk. The answer is that of every
    // triangle near the points (VisitNear, as the double-precision tests below are):
    // the same triangles can cross, at a fraction of the candidates (long medial edges
    // and wide triangles have a large ball about them and a thin box) and without a
    // closest point per candidate.
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = hi[k] = points[0][k];
      for (int j = 1; j < n; ++j)
      {
        lo[k] = std::min(lo[k], points[j][k]);
        hi[k] = std::max(hi[k], points[j][k]);
      }
      lo[k] -= this->Slack;
      hi[k] += this->Slack;
    }
    this->Tree.VisitBox(lo, hi, [&](vtkIdType t) {
      double scratch[9];
      const double* v = this->Tree.GetTriangleVertices(t, scratch);
      for (int k = 0; k < 3; ++k)
      {
        if (std::min(v[k], std::min(v[3 + k], v[6 + k])) > hi[k] || std::max(v[k], std::max(v[3 + k], v[6 + k])) < lo[k])
        {
          return true; // apart: cannot cross
        }
      }
      const double* u[3] = { v, v + 3, v + 6 };
      crosses = test(points, n, u);
      return !crosses;
    });
    return crosses;
  }
  this->VisitNear(points, n, [&](const double* const u[3]) {
    crosses = test ? test(points, n, u)
                   : n == 2 ? G::SegmentCrossesTriangle(points[0], points[1], u[0], u[1], u[2])
                            : G::TrianglesCross(points, u);
    return crosses;
  });
  return crosses;
}

void vtkMedialSurfaceQuery::VisitNear(
  const double* const points[], int n, const std::function<bool(const double* const corners[3])>& visit) const
{
  // A point where they meet lies in the smallest ball about the centroid that holds the points.
  double centre[3] = { 0, 0, 0 }, reach2 = 0.0;
  for (int j = 0; j < n; ++j)
  {
    G::AddScaled(centre, 1.0 / n, points[j], centre);
  }
  for (int j = 0; j < n; ++j)
  {
    reach2 = std::max(reach2, G::Distance2(centre, points[j]));
  }
  const double reach = std::sqrt(reach2) * (1.0 + 1e-9) + this->Slack;
  bool stop = false;
  this->Tree.VisitWithin(centre, reach, nullptr, 1.0, [&](double, const double*, vtkIdType t) {
    if (!stop)
    {
      double scratch[9];
      const double* v = this->Tree.GetTriangleVertices(t, scratch);
      const double* u[3] = { v, v + 3, v + 6 };
      stop = visit(u);
    }
  });
}

bool vtkMedialSurfaceQuery::TrianglesWithinIfEmpty(const double x[3], double distance, double emptyRadius,
  std::vector<ClosestHit>& hits, double* nearestBound, const Nearby* nearby, ClosestHit* nearest) const
{
  hits.clear();
  // ContainsBall's limit: at or below zero the ball is empty.
  const double limit = emptyRadius - this->Slack;
  vtkMedialTriangleBVH::NearestPoint closest;
  const bool empty = this->Tree.VisitWithinIfEmpty(x, distance, limit > 0.0 ? limit : 0.0,
    HitCollector{ hits }, nearestBound, nearby, nearest ? &closest : nullptr);
  SortByTriangle(hits);
  if (nearest)
  {
    nearest->Triangle = empty ? -1 : closest.Triangle;
    if (nearest->Triangle >= 0)
    {
      std::copy(closest.Point, closest.Point + 3, nearest->Point);
      nearest->Distance = closest.Distance;
    }
  }
  return empty;
}

void vtkMedialSurfaceQuery::TrianglesWithin(
  const double x[3], double distance, std::vector<ClosestHit>& hits, const ContactFilter* filter,
  const Nearby* nearby) const
{
  hits.clear();
  this->Tree.VisitWithin(x, distance, filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0,
    HitCollector{ hits }, nearby);
  SortByTriangle(hits);
}
