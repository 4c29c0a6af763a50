// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSurfaceQuery.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialTriangleMesh.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
namespace G = vtkMedialGeometry;

struct QueryState
{
  const vtkMedialSurfaceQuery* Self;
  const vtkMedialTriangleMesh* Mesh;
  double Centre[3];
  const vtkMedialSurfaceQuery::ContactFilter* Filter;
  // ContainsBall: block when squared distance < Limit2. ClosestPoint: best so far.
  double Limit2;
  double Pad; // float padding added to Embree's radius
  bool Blocked = false;
  vtkIdType BestTriangle = -1;
  double BestPoint[3] = { 0, 0, 0 };
};

// Squared distance from the state's centre to the admissible part of triangle t.
double AdmissibleDistance2(const QueryState& s, vtkIdType t, double out[3])
{
  const vtkIdType* v = s.Mesh->GetTriangle(t);
  const double* a = s.Mesh->GetPoint(v[0]);
  const double* b = s.Mesh->GetPoint(v[1]);
  const double* c = s.Mesh->GetPoint(v[2]);
  const auto* f = s.Filter;
  if (!f || f->CosMinAngle >= 1.0)
  {
    return G::ClosestPointOnTriangle(s.Centre, a, b, c, out);
  }
  // Half-space (q - c).(P - c) <= |P - c|^2 cos(theta), written as w.q <= k; the
  // other side (the cap) with CapOnly.
  double w[3];
  G::Sub(f->SamplePoint, s.Centre, w);
  double k = G::Dot(w, s.Centre) + G::Dot(w, w) * f->CosMinAngle;
  if (f->CapOnly)
  {
    for (double& c : w)
    {
      c = -c;
    }
    k = -k;
  }
  return G::ClosestPointOnClippedTriangle(s.Centre, a, b, c, w, k, out);
}

bool ContainsBallCallback(RTCPointQueryFunctionArguments* args)
{
  auto* s = static_cast<QueryState*>(args->userPtr);
  if (s->Blocked)
  {
    return false; // Embree still visits nodes containing the centre; stay cheap.
  }
  const vtkIdType t = static_cast<vtkIdType>(args->primID);
  if (s->Filter && t == s->Filter->OwnTriangle)
  {
    return false;
  }
  double q[3];
  if (AdmissibleDistance2(*s, t, q) < s->Limit2)
  {
    s->Blocked = true;
    args->query->radius = 0.0f;
    return true;
  }
  return false;
}

bool ClosestPointCallback(RTCPointQueryFunctionArguments* args)
{
  auto* s = static_cast<QueryState*>(args->userPtr);
  const vtkIdType t = static_cast<vtkIdType>(args->primID);
  if (s->Filter && t == s->Filter->OwnTriangle)
  {
    return false;
  }
  double q[3];
  const double d2 = AdmissibleDistance2(*s, t, q);
  if (d2 < s->Limit2)
  {
    s->Limit2 = d2;
    s->BestTriangle = t;
    s->BestPoint[0] = q[0];
    s->BestPoint[1] = q[1];
    s->BestPoint[2] = q[2];
    args->query->radius = static_cast<float>(std::sqrt(d2) + s->Pad);
    return true;
  }
  return false;
}
}

struct vtkMedialSurfaceQuery::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  double Origin[3] = { 0, 0, 0 }; // Embree coordinates are relative to this
  double FloatPad = 0.0;          // covers float rounding of vertices and query centres

  void Release()
  {
    if (this->Scene)
    {
      rtcReleaseScene(this->Scene);
    }
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
    this->Scene = nullptr;
    this->Device = nullptr;
  }

  RTCPointQuery MakePointQuery(const double x[3], double radius) const
  {
    RTCPointQuery q;
    q.x = static_cast<float>(x[0] - this->Origin[0]);
    q.y = static_cast<float>(x[1] - this->Origin[1]);
    q.z = static_cast<float>(x[2] - this->Origin[2]);
    q.time = 0.0f;
    q.radius = static_cast<float>(radius + this->FloatPad);
    return q;
  }
};

vtkMedialSurfaceQuery::vtkMedialSurfaceQuery()
  : Impl(new Internals)
{
}

vtkMedialSurfaceQuery::~vtkMedialSurfaceQuery()
{
  this->Impl->Release();
  delete this->Impl;
}

bool vtkMedialSurfaceQuery::Build(
  const vtkMedialTriangleMesh* mesh, std::string& error, const std::function<bool()>& aborted)
{
  this->Impl->Release();
  this->Mesh = mesh;
  const vtkIdType nt = mesh->GetNumberOfTriangles();
  const vtkIdType np = static_cast<vtkIdType>(mesh->Points.size() / 3);
  if (nt <= 0 || nt > static_cast<vtkIdType>(std::numeric_limits<unsigned>::max() / 2))
  {
    error = "triangle count is zero or too large for the BVH";
    return false;
  }
  const double* b = mesh->Bounds;
  double extent = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    this->Impl->Origin[i] = 0.5 * (b[2 * i] + b[2 * i + 1]);
    extent = std::max(extent, 0.5 * (b[2 * i + 1] - b[2 * i]));
  }
  // Float rounding of coordinates relative to the origin is below 6e-8 * extent;
  // pad generously, it only costs a few extra candidates.
  this->Impl->FloatPad = 1e-6 * extent;
  this->Slack = 1e-12 * mesh->Diagonal;

  this->Impl->Device = rtcNewDevice(nullptr);
  if (!this->Impl->Device)
  {
    error = "cannot create the Embree device";
    return false;
  }
  this->Impl->Scene = rtcNewScene(this->Impl->Device);
  rtcSetSceneFlags(this->Impl->Scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(this->Impl->Scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtcNewGeometry(this->Impl->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), np));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
  if (!vertices || !indices)
  {
    rtcReleaseGeometry(geometry);
    this->Impl->Release();
    error = "cannot allocate the Embree buffers (out of memory?)";
    return false;
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      vertices[3 * i + k] = static_cast<float>(mesh->Points[3 * i + k] - this->Impl->Origin[k]);
    }
  }
  for (vtkIdType i = 0; i < 3 * nt; ++i)
  {
    indices[i] = static_cast<unsigned>(mesh->Triangles[i]);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(this->Impl->Scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(this->Impl->Scene);
  if (rtcGetDeviceError(this->Impl->Device) != RTC_ERROR_NONE)
  {
    this->Impl->Release();
    error = "Embree failed to build the BVH";
    return false;
  }
  if ((aborted && aborted()) || !this->Tree.Build(*mesh, aborted))
  {
    this->Impl->Release();
    error = aborted && aborted() ? "aborted" : "cannot build the tangent-ball tree";
    return false;
  }
  return true;
}

// One Embree ray from `rayOrigin` (the origin itself, or nudged off it); hit distances
// are redone in double along the ray from `origin`.
bool vtkMedialSurfaceQuery::IntersectFrom(const double rayOrigin[3], const double origin[3],
  const double direction[3], double tMin, double tMax, vtkIdType ignoreTriangle, RayHit& hit) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  double start = tMin;
  // At most a few retries: each one steps past a hit on the ignored triangle.
  for (int attempt = 0; attempt < 4; ++attempt)
  {
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(rayOrigin[0] - this->Impl->Origin[0]);
    rh.ray.org_y = static_cast<float>(rayOrigin[1] - this->Impl->Origin[1]);
    rh.ray.org_z = static_cast<float>(rayOrigin[2] - this->Impl->Origin[2]);
    rh.ray.dir_x = static_cast<float>(direction[0]);
    rh.ray.dir_y = static_cast<float>(direction[1]);
    rh.ray.dir_z = static_cast<float>(direction[2]);
    rh.ray.tnear = static_cast<float>(start);
    rh.ray.tfar = static_cast<float>(std::min(tMax, 3.4e38));
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(this->Impl->Scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    {
      return false;
    }
    const vtkIdType t = static_cast<vtkIdType>(rh.hit.primID);
    if (t == ignoreTriangle)
    {
      start = std::max(static_cast<double>(rh.ray.tfar), start) + this->Impl->FloatPad;
      continue;
    }
    // Redo the hit distance in double against the triangle's plane.
    const double* n = this->Mesh->GetNormal(t);
    const double* v0 = this->Mesh->GetPoint(this->Mesh->GetTriangle(t)[0]);
    double d[3];
    G::Sub(v0, origin, d);
    const double denom = G::Dot(n, direction);
    double distance = rh.ray.tfar;
    if (std::fabs(denom) > 1e-12)
    {
      const double exact = G::Dot(n, d) / denom;
      if (std::fabs(exact - distance) <= 10.0 * this->Impl->FloatPad + 1e-6 * distance)
      {
        if (exact <= tMin)
        {
          // A float hit at the origin (a face through it, e.g. around a vertex): step past.
          start = std::max(static_cast<double>(rh.ray.tfar), start) + this->Impl->FloatPad;
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
      G::Dot(this->Mesh->GetNormal(hit.Triangle), direction) > 0.0;
  };
  if (fromInside(origin))
  {
    return true;
  }
  // Embree's float test is not watertight: a ray aimed exactly at a vertex (e.g. from
  // a vertex of a symmetric mesh to its antipode) can slip between the triangles around
  // it and escape, or go on to meet a face from outside. Nudge the ray sideways by the
  // float padding and try again, on either side.
  double side[3] = { 0, 0, 0 }, unit[3] = { 0, 0, 0 };
  const double ax = std::fabs(direction[0]), ay = std::fabs(direction[1]), az = std::fabs(direction[2]);
  unit[ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2)] = 1.0;
  G::Cross(direction, unit, side);
  const double length = std::sqrt(G::Dot(side, side));
  for (double sign : { 1.0, -1.0 })
  {
    double nudged[3];
    G::AddScaled(origin, sign * this->Impl->FloatPad / length, side, nudged);
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
  if (this->PointQueryEngine == OWN_TREE)
  {
    return this->Tree.ClosestPoint(x, upperBound, filter ? filter->OwnTriangle : -1,
      filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0,
      filter && filter->CapOnly, hit.Point, hit.Distance, hit.Triangle);
  }
  QueryState s;
  s.Self = this;
  s.Mesh = this->Mesh;
  s.Centre[0] = x[0];
  s.Centre[1] = x[1];
  s.Centre[2] = x[2];
  s.Filter = filter;
  s.Limit2 = upperBound * upperBound;
  s.Pad = this->Impl->FloatPad;
  RTCPointQuery q = this->Impl->MakePointQuery(x, upperBound);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(this->Impl->Scene, &q, &context, ClosestPointCallback, &s);
  if (s.BestTriangle < 0)
  {
    return false;
  }
  hit.Triangle = s.BestTriangle;
  hit.Distance = std::sqrt(s.Limit2);
  hit.Point[0] = s.BestPoint[0];
  hit.Point[1] = s.BestPoint[1];
  hit.Point[2] = s.BestPoint[2];
  return true;
}

bool vtkMedialSurfaceQuery::ContainsBall(
  const double centre[3], double radius, const ContactFilter* filter) const
{
  const double limit = radius - this->Slack;
  if (limit <= 0.0)
  {
    return true;
  }
  if (this->PointQueryEngine == OWN_TREE)
  {
    return this->Tree.ContainsBall(centre, limit, filter ? filter->OwnTriangle : -1,
      filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0,
      filter && filter->CapOnly);
  }
  QueryState s;
  s.Self = this;
  s.Mesh = this->Mesh;
  s.Centre[0] = centre[0];
  s.Centre[1] = centre[1];
  s.Centre[2] = centre[2];
  s.Filter = filter;
  s.Limit2 = limit * limit;
  s.Pad = this->Impl->FloatPad;
  RTCPointQuery q = this->Impl->MakePointQuery(centre, radius);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(this->Impl->Scene, &q, &context, ContainsBallCallback, &s);
  return !s.Blocked;
}

void vtkMedialSurfaceQuery::MaximalTangentBall(const double p[3], const double n[3],
  const ContactFilter& filter, double allowed, TangentBall& ball) const
{
  this->Tree.MaximalTangentBall(p, n, filter.OwnTriangle, filter.CosMinAngle, this->Slack, allowed, ball);
}

int vtkMedialSurfaceQuery::CountCrossings(
  const double origin[3], const double direction[3], double tMax) const
{
  int crossings = 0;
  double start = 0.0;
  RayHit hit;
  // Each hit restarts the ray just past it; the cap only guards against a stall.
  while (crossings < 100000 && this->Intersect(origin, direction, start, tMax, -1, hit))
  {
    ++crossings;
    start = std::max(hit.Distance, start) + 4.0 * this->Impl->FloatPad;
  }
  return crossings;
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

bool vtkMedialSurfaceQuery::SegmentCrossesSurface(const double p[3], const double q[3]) const
{
  const double* ends[2] = { p, q };
  return this->CrossesSurface(ends, 2);
}

bool vtkMedialSurfaceQuery::TriangleCrossesSurface(
  const double a[3], const double b[3], const double c[3]) const
{
  const double* corners[3] = { a, b, c };
  return this->CrossesSurface(corners, 3);
}

bool vtkMedialSurfaceQuery::CrossesSurface(const double* const points[], int n) const
{
  // Candidates: the triangles within the smallest ball about the centroid that holds
  // the points (a crossing point lies in it).
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
  bool crosses = false;
  this->Tree.VisitWithin(centre, reach, nullptr, 1.0, [&](double, const double*, vtkIdType t) {
    if (crosses)
    {
      return;
    }
    const vtkIdType* v = this->Mesh->GetTriangle(t);
    const double* u[3] = { this->Mesh->GetPoint(v[0]), this->Mesh->GetPoint(v[1]), this->Mesh->GetPoint(v[2]) };
    crosses = n == 2 ? G::SegmentCrossesTriangle(points[0], points[1], u[0], u[1], u[2])
                     : G::TrianglesCross(points, u);
  });
  return crosses;
}

void vtkMedialSurfaceQuery::TrianglesWithin(
  const double x[3], double distance, std::vector<ClosestHit>& hits, const ContactFilter* filter) const
{
  hits.clear();
  this->Tree.VisitWithin(x, distance, filter ? filter->SamplePoint : nullptr, filter ? filter->CosMinAngle : 1.0,
    [&](double d2, const double* q, vtkIdType t) {
    ClosestHit hit;
    std::copy(q, q + 3, hit.Point);
    hit.Distance = std::sqrt(d2);
    hit.Triangle = t;
    hits.push_back(hit);
  });
  std::sort(hits.begin(), hits.end(),
    [](const ClosestHit& a, const ClosestHit& b) { return a.Triangle < b.Triangle; });
}
