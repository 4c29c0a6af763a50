// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallSolver.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceNormals.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
namespace G = vtkMedialGeometry;

// With theta > 0 the surface in the cap around p is ignored, so a ball can cross it
// there, where the shape curves faster than the ball. A ball that the cap's surface
// enters deeper than `allowed` is shrunk about its centre to the distance to that
// surface (the rest of the surface is outside it already): it stays centred on the
// smooth axis and becomes inscribed, touching the surface at its new contact. (The
// one-pass traversal does this itself, on the surface it set aside.)
void Inscribe(const vtkMedialSurfaceQuery& query, const vtkMedialSurfaceQuery::ContactFilter& admissible,
  double allowed, vtkMedialSampleRecord& out)
{
  if (!(admissible.CosMinAngle < 1.0) || !(allowed < out.Radius))
  {
    return;
  }
  vtkMedialSurfaceQuery::ContactFilter cap = admissible;
  cap.CapOnly = true;
  vtkMedialSurfaceQuery::ClosestHit closest;
  if (query.ClosestPoint(out.Centre, out.Radius - allowed, closest, &cap))
  {
    out.Radius = closest.Distance;
    std::copy(closest.Point, closest.Point + 3, out.Contact);
    out.Angle = G::AngleDegrees(out.Centre, out.Surface, closest.Point);
    out.Shrunk = true;
  }
}

// Raises `largest` to the ball's protrusion r - d(c) where that is larger: the closest
// point of the whole surface within r - largest of the centre (a shrinking ball capped
// at its iterations need not be empty away from the cap either).
void MeasureProtrusion(const vtkMedialSurfaceQuery& query, const vtkMedialSampleRecord& out, double& largest)
{
  vtkMedialSurfaceQuery::ClosestHit closest;
  if (largest < out.Radius && query.ClosestPoint(out.Centre, out.Radius - largest, closest))
  {
    largest = std::max(largest, out.Radius - closest.Distance);
  }
}
}

vtkMedialBallParameters vtkMedialMakeBallParameters(int method, double tolerance,
  double minimumAngle, double maximumProtrusion, int maximumIterations, double diagonal)
{
  vtkMedialBallParameters param;
  param.Method = method;
  param.Tolerance = tolerance * diagonal;
  param.CosMinAngle = minimumAngle > 0.0 ? std::cos(minimumAngle * 3.14159265358979323846 / 180.0) : 1.0;
  param.MaximumProtrusion = maximumProtrusion >= 1.0 ? HUGE_VAL : maximumProtrusion * diagonal;
  param.MaximumIterations = maximumIterations;
  return param;
}

// Finds the maximal admissible ball tangent at p (on `triangle`) along the inward normal.
void vtkMedialSolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3], vtkMedialSampleRecord& out,
  vtkIdType hintTriangle, vtkMedialTriangleBVH::BlockerChain* blockers, double* largestProtrusion)
{
  const double* outward = query.GetNormal(triangle);
  double n[3] = { -outward[0], -outward[1], -outward[2] };
  vtkIdType own = triangle;
  if (param.Normals && param.CosMinAngle < 1.0)
  {
    double smooth[3], scratch[9];
    if (!param.Normals->At(triangle, query.GetTriangleVertices(triangle, scratch), outward, p, smooth))
    {
      // Not the facet's own normal: the facet is not tangent to the ball, and blocks
      // where it enters it like any other face.
      for (int k = 0; k < 3; ++k)
      {
        n[k] = -smooth[k];
      }
      own = -1;
    }
  }
  vtkMedialSolveBallAlong(query, mesh, param, own, p, n, out, hintTriangle, blockers, largestProtrusion);
  out.SourceCell = mesh.SourceCellIds[triangle];
}

void vtkMedialSolveBallAlong(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3], const double n[3],
  vtkMedialSampleRecord& out, vtkIdType hintTriangle, vtkMedialTriangleBVH::BlockerChain* blockers,
  double* largestProtrusion)
{
  vtkMedialSurfaceQuery::TangentBall ball;
  if (blockers)
  {
    ball.Blockers = *blockers;
    blockers->Count = 0; // until a one-pass search fills it
  }
  out.Valid = false;
  out.ContactTriangle = -1;
  out.Capped = false;
  out.Shrunk = false;
  out.Iterations = 0;
  out.SourceCell = triangle >= 0 ? mesh.SourceCellIds[triangle] : -1;
  std::copy(p, p + 3, out.Surface);

  vtkMedialSurfaceQuery::RayHit hit;
  if (!query.IntersectFromInside(p, n, 1e-9 * mesh.Diagonal, triangle, hit))
  {
    return; // escaped through a hole, or met a face from outside (self-intersection)
  }
  double q[3];
  G::AddScaled(p, hit.Distance, n, q);

  vtkMedialSurfaceQuery::ContactFilter filter;
  filter.OwnTriangle = triangle;
  std::copy(p, p + 3, filter.SamplePoint);
  filter.CosMinAngle = param.CosMinAngle;

  double centre[3];
  double radius = 0.5 * hit.Distance;
  bool haveContact = false;
  vtkMedialSurfaceQuery::ClosestHit closest;

  if (param.Method == vtkMedialBallParameters::ONE_PASS)
  {
    ball.Radius = radius;
    std::copy(q, q + 3, ball.Contact);
    ball.ContactTriangle = hit.Triangle;
    ball.HintTriangle = hintTriangle;
    ball.MeasureProtrusion = largestProtrusion != nullptr;
    ball.LargestProtrusion = largestProtrusion ? *largestProtrusion : 0.0;
    query.MaximalTangentBall(p, n, filter, param.MaximumProtrusion, ball);
    if (largestProtrusion)
    {
      *largestProtrusion = ball.LargestProtrusion; // theta = 0: exact, nothing to add
    }
    if (blockers)
    {
      *blockers = ball.Blockers;
    }
    out.Iterations = 1 + ball.Steps;
    out.Capped = ball.Capped;
    G::AddScaled(p, ball.Radius, n, out.Centre);
    out.Shrunk = ball.Shrunk;
    out.Radius = ball.Shrunk ? ball.InscribedRadius : ball.Radius;
    out.ContactTriangle = ball.ContactTriangle; // the angle rule's: the next sample's hint
    const double* contact = ball.Shrunk ? ball.InscribedContact : ball.Contact;
    std::copy(contact, contact + 3, out.Contact);
    out.Angle = G::AngleDegrees(out.Centre, p, contact);
    out.Valid = true;
    return;
  }
  if (param.Method == vtkMedialBallParameters::SHRINKING_BALL)
  {
    for (;;)
    {
      G::AddScaled(p, radius, n, centre);
      if (out.Iterations >= param.MaximumIterations)
      {
        out.Capped = true;
        break;
      }
      ++out.Iterations;
      if (!query.ClosestPoint(centre, radius - query.GetSlack(), closest, &filter))
      {
        break; // empty: maximal, touching the previous blocker
      }
      double pq[3];
      G::Sub(closest.Point, p, pq);
      const double along = G::Dot(n, pq);
      if (!(along > 0.0))
      {
        break; // flat region: the blocker lies on the tangent plane
      }
      const double next = G::Dot(pq, pq) / (2.0 * along);
      if (!(next < radius))
      {
        break; // no progress left at double precision
      }
      radius = next;
      haveContact = true;
    }
  }
  else
  {
    G::AddScaled(p, radius, n, centre);
    ++out.Iterations;
    if (!query.ContainsBall(centre, radius, &filter))
    {
      radius = G::BisectLargestEmpty(0.0, radius, param.Tolerance,
        [&](double r) {
          G::AddScaled(p, r, n, centre);
          return query.ContainsBall(centre, r, &filter);
        },
        out.Iterations);
      G::AddScaled(p, radius, n, centre);
    }
  }

  // Second touching point: the closest blocking point, just beyond the empty ball.
  const double reach = radius + 2.0 * param.Tolerance + 4.0 * query.GetSlack();
  if (!query.ClosestPoint(centre, reach, closest, &filter) &&
    !(haveContact && query.ClosestPoint(centre, radius * (1.0 + 1e-9) + reach, closest, &filter)))
  {
    std::copy(q, q + 3, closest.Point);
  }
  std::copy(centre, centre + 3, out.Centre);
  out.Radius = radius;
  std::copy(closest.Point, closest.Point + 3, out.Contact);
  out.Angle = G::AngleDegrees(centre, p, closest.Point);
  out.Valid = true;
  Inscribe(query, filter, param.MaximumProtrusion, out);
  if (largestProtrusion)
  {
    MeasureProtrusion(query, out, *largestProtrusion);
  }
}

namespace
{
// Whether triangle t (-1: none) comes within `distance` of x: a contact found through its
// plane only (the plane bound of a curved wall's far triangle) is not one.
bool Touches(const vtkMedialSurfaceQuery& query, vtkIdType t, const double x[3], double distance)
{
  if (t < 0)
  {
    return false;
  }
  double scratch[9], closest[3];
  const double* a = query.GetTriangleVertices(t, scratch);
  return G::ClosestPointOnTriangle(x, a, a + 3, a + 6, closest) <= distance * distance;
}

// Surface points that the ascents found inside a probe's ball (the latest
// MaxSurfacePoints; vtkMedialGrowBall's surfacePoints): a ball that holds one is not
// empty, and the nearest one bounds a closest-point query (which then finds the same
// point, sooner).
using SurfacePoints = std::vector<std::array<double, 3>>;
constexpr size_t MaxSurfacePoints = 64;
void AddSurfacePoint(SurfacePoints& points, const double q[3])
{
  if (points.size() == MaxSurfacePoints)
  {
    points.erase(points.begin(), points.begin() + MaxSurfacePoints / 2);
  }
  points.push_back({ q[0], q[1], q[2] });
}
double NearestSurfacePoint2(const SurfacePoints& points, const double x[3])
{
  double nearest = HUGE_VAL;
  for (const auto& q : points)
  {
    nearest = std::min(nearest, G::Distance2(x, q.data()));
  }
  return nearest;
}

// The rules of one ascent (see vtkMedialGrowBall).
//  - Plain: the ascent as it was before the slide kept its contacts.
//  - Keep: the sliding steps keep their contacts (the ball made exactly tangent, a
//    blocked step ended on the largest empty ball, no stop after a small step that found
//    a contact).
//  - Robust: Keep, and three rules that do not rely on exact coplanarity or tangency.
//    A plane nearly parallel to the step (gamma + n.v below ParallelRate: a contact's
//    plane, or a face coplanar with one to the input's precision, whose approach is
//    decided by rounding) gives the step no bound: a float input turned in space gives a
//    flat wall's faces normals 1e-7 apart, and such a plane's bound, a rounding over a
//    rounding, stopped the slide off a crease at 1e-7 of its length. The start contact
//    is a point where the ball crosses its triangle's plane (it touches the triangle's
//    edge or corner: beside a concave crease), not that plane, which leans off the
//    direction the ball may move. And the sliding steps are counted apart from the
//    ordinary ones, as the limits say: a slide may follow the last ordinary step (a ball
//    shrunk by a faceted wall's tilt, grown by one step onto the wall across the crease,
//    then rounds it).
//  - Thorough: Robust, and four rules for a ball that stops before it can slide. It runs
//    only where another ascent reached one of their branches with a surface point that
//    would join the contacts across a convex crease, less than the slide angle from them
//    (limits.Across, then limits.MaySlide), and the first three apply only there: a
//    step whose probes found only balls out of reach probes once more, at the bound the
//    last one found (a ball shrunk by a facet's tilt that does not reach a flat
//    wall below: the ray runs parallel to that wall, and the bound from its plane is the
//    exact step); a bound that grows the ball by less than the contact tolerance is a
//    contact missed (a ball on a corner's bisector that its solver reports touching one
//    of the corner's walls: the other then bounds every step by 1e-8); a plane's bound
//    is kept as a contact where that plane meets the surface at the ball (a flat wall
//    whose probe found another, distant triangle of it); and a contact counts within
//    ContactTolerance of the radius (a float input's facets lie 1e-6 r off a shrunk ball).
enum class AscentRules
{
  Plain,
  Keep,
  Robust,
  Thorough
};
constexpr double ParallelRate = 1e-6;
constexpr double ContactTolerance = 1e-5; // relative; 1e-7 by the other rules

// Whether the plane of triangle t, which the ball (x, radius) touches, meets the surface
// where it touches the ball (another triangle of a flat wall): then `point` is that place.
bool PlaneMeetsSurface(const vtkMedialSurfaceQuery& query, vtkIdType t, const double x[3], double radius,
  double point[3])
{
  if (t < 0)
  {
    return false;
  }
  const double* outward = query.GetNormal(t);
  double cv[3], scratch[9], foot[3];
  G::Sub(x, query.GetTriangleVertices(t, scratch), cv);
  const double distance = -G::Dot(outward, cv);
  const double near = ContactTolerance * radius + 8.0 * query.GetSlack();
  if (!(std::abs(distance - radius) <= near))
  {
    return false;
  }
  G::AddScaled(x, distance, outward, foot);
  vtkMedialSurfaceQuery::ClosestHit hit;
  if (!query.ClosestPoint(foot, near, hit))
  {
    return false;
  }
  G::Copy(hit.Point, point);
  return true;
}

// What an ascent did: whether it took a sliding step, whether a Robust rule changed
// anything (otherwise it went as the Keep ascent does), and whether it reached a branch
// where a Thorough rule would have changed it.
struct AscentReport
{
  bool Slid = false;
  bool Tolerated = false;
  unsigned Thorough = 0; // the ThoroughRule bits of those branches
};
enum ThoroughRule : unsigned
{
  ProbeAgain = 1,
  CloseBound = 2,
  PlaneContact = 4,
  NearContact = 8
};

// One ascent by `rules`.
AscentReport Ascend(const vtkMedialSurfaceQuery& query, const double p[3], const vtkMedialGrowthLimits& limits,
  const vtkIdType* faces, int faceCount, vtkMedialSampleRecord& out, AscentRules rules, SurfacePoints& inside)
{
  AscentReport report;
  const bool keep = rules != AscentRules::Plain;
  const bool robust = rules == AscentRules::Robust || rules == AscentRules::Thorough;
  const bool thorough = rules == AscentRules::Thorough;
  double c[3];
  G::Copy(out.Centre, c);
  double r = out.Radius;
  if (!(r > 0.0))
  {
    return report;
  }
  const double slack = query.GetSlack();
  auto gapAt = [&](const double x[3], double radius) { return std::sqrt(G::Distance2(x, p)) - radius; };
  double allowed = std::max(limits.Tolerance, gapAt(c, r));
  // The contacts: the planes of the triangles the ball touches (a ball that moves
  // along a face keeps touching its plane; the probes below check the surface itself),
  // or a fixed point (triangle -1: the contact of a ball shrunk to be inscribed).
  struct Touch
  {
    double Point[3];
    vtkIdType Triangle;
  };
  std::vector<Touch> touches;
  for (int i = 0; i < faceCount; ++i)
  {
    touches.push_back({ { p[0], p[1], p[2] }, faces[i] });
  }
  bool pointContact = out.Shrunk || out.ContactTriangle < 0;
  if (!pointContact && robust)
  {
    // Its plane passes nearer the centre than the contact (beyond rounding, which the
    // exact tangency below removes): the ball touches the triangle's edge or corner.
    const double* outward = query.GetNormal(out.ContactTriangle);
    double cv[3], scratch[9];
    G::Sub(c, query.GetTriangleVertices(out.ContactTriangle, scratch), cv);
    pointContact = -G::Dot(outward, cv) < std::sqrt(G::Distance2(c, out.Contact)) * (1.0 - 1e-3);
    report.Tolerated = pointContact;
  }
  touches.push_back({ { out.Contact[0], out.Contact[1], out.Contact[2] }, pointContact ? -1 : out.ContactTriangle });
  std::vector<std::array<double, 3>> directions;
  std::vector<vtkIdType> triangles;
  double contact[3];
  G::Copy(out.Contact, contact);
  bool moved = false;
  int retries = 0; // steps repeated with a contact they found
  // The start ball is tangent to its contacts only to within its solver's precision: it
  // lies along a smooth normal, a fraction of a degree off its faces' normals, so it
  // overlaps some of their planes by about 1e-6 r and stops short of others. Each step
  // makes it tangent to the nearest again (below); the contacts it started with stay
  // contacts while they lie within that first spread, or the next step, having lost
  // one, no longer rounds the crease.
  double spread = 0.0;
  bool first = true;
  // Whether a Thorough rule applies where the surface on triangle t (-1: the sample's
  // faces), seen from the centre along -u, would join the contacts: only where the ball
  // could then slide (the contacts less than the slide angle apart, on walls that may
  // slide). The Thorough ascent follows it; the others report it (once: then the
  // Thorough ascent runs anyway).
  std::vector<vtkIdType> with;
  std::vector<std::array<double, 3>> around;
  double inwardScratch[3];
  auto inward = [&](vtkIdType t) {
    const double* outward = query.GetNormal(t);
    for (int k = 0; k < 3; ++k)
    {
      inwardScratch[k] = -outward[k];
    }
    return inwardScratch;
  };
  auto applies = [&](unsigned rule, vtkIdType t, const double u[3]) {
    if ((!thorough && report.Thorough) || !limits.MaySlide || directions.empty())
    {
      return false;
    }
    if (limits.Across && !limits.Across(triangles.data(), static_cast<int>(triangles.size()), t))
    {
      return false;
    }
    around.assign(directions.begin(), directions.end());
    around.push_back({ u[0], u[1], u[2] });
    double g[3];
    G::NearestHullPoint(around, g);
    if (!(G::Dot(g, g) >= limits.CosHalfSlideAngle * limits.CosHalfSlideAngle))
    {
      return false;
    }
    with.assign(triangles.begin(), triangles.end());
    with.push_back(t);
    if (!limits.MaySlide(with.data(), static_cast<int>(with.size()), c, r))
    {
      return false;
    }
    report.Thorough |= thorough ? 0u : rule;
    return thorough;
  };
  for (int steps = 0, slides = 0; (steps < limits.MaximumSteps || robust) && slides < limits.MaximumSlides;)
  {
    // The directions from the contacts that still touch the ball to its centre.
    const double touching = r * (1.0 + 1e-7) + 8.0 * slack + spread;
    const double nearly = r * (1.0 + ContactTolerance) + 8.0 * slack + spread;
    directions.clear();
    triangles.clear();
    size_t kept = 0;
    vtkIdType near = -2; // (not Thorough) a contact within ContactTolerance only
    double nearU[3] = { 0, 0, 0 };
    for (Touch& t : touches)
    {
      if (t.Triangle >= 0)
      {
        const double* outward = query.GetNormal(t.Triangle);
        double cv[3], scratch[9];
        G::Sub(c, query.GetTriangleVertices(t.Triangle, scratch), cv);
        G::AddScaled(c, -G::Dot(outward, cv), outward, t.Point);
      }
      double u[3];
      G::Sub(c, t.Point, u);
      const double length = std::sqrt(G::Dot(u, u));
      if (!(length > 0.0) || length > (thorough ? nearly : touching))
      {
        if (length > touching && length <= nearly)
        {
          near = t.Triangle;
          for (int k = 0; k < 3; ++k)
          {
            nearU[k] = u[k] / length;
          }
        }
        continue;
      }
      touches[kept++] = t;
      triangles.push_back(t.Triangle);
      for (double& x : u)
      {
        x /= length;
      }
      bool same = false;
      for (const auto& d : directions)
      {
        double e[3];
        G::Sub(d.data(), u, e);
        same = same || G::Dot(e, e) < 1e-16;
      }
      if (!same && directions.size() < 8)
      {
        directions.push_back({ u[0], u[1], u[2] });
      }
    }
    touches.resize(kept);
    if (near > -2)
    {
      applies(NearContact, near, nearU);
    }
    // Tangent to the nearest contact: a ball that overlaps a contact's plane, however
    // little, finds it inside every sliding probe, which then backs off by the square
    // root of the overlap (1% a probe) and ends on the last resort. Only rounding-size
    // overlaps are removed (a contact's plane may also cross the ball beyond its triangle,
    // on a curved wall: that is no overlap to remove).
    double farthest = 0.0;
    const double untouched = r;
    for (size_t i = 0; keep && i < touches.size(); ++i)
    {
      const double length = std::sqrt(G::Distance2(c, touches[i].Point));
      farthest = std::max(farthest, length);
      if (length < r && length > r * (1.0 - 1e-3))
      {
        r = length;
      }
    }
    if (first && keep)
    {
      spread = std::max(0.0, farthest - r);
      first = false;
    }
    double g[3];
    G::NearestHullPoint(directions, g);
    const double speed = std::sqrt(G::Dot(g, g));
    if (!(speed > 1e-6))
    {
      break; // no contact left, or they surround the centre: a local maximum
    }
    // Contacts less than the slide angle apart: the ball rounds a convex feature.
    const bool sliding = speed >= limits.CosHalfSlideAngle && directions.size() >= 2 &&
      (!limits.MaySlide || limits.MaySlide(triangles.data(), static_cast<int>(triangles.size()), c, r));
    if (steps >= limits.MaximumSteps)
    {
      if (!sliding)
      {
        r = untouched; // (Robust) the ordinary steps are spent: the ball as the Keep ascent ends
        break;
      }
      report.Tolerated = true;
    }
    ++(sliding ? slides : steps);
    report.Slid = report.Slid || sliding;
    double v[3];
    double gamma = HUGE_VAL; // how fast the slowest contact recedes
    for (int k = 0; k < 3; ++k)
    {
      v[k] = g[k] / speed;
    }
    for (const auto& d : directions)
    {
      gamma = std::min(gamma, G::Dot(d.data(), v));
    }
    // Centre c + s v, radius rho(s) = r + gamma s: the distance to the plane of the
    // slowest-receding contact. A surface point x is inside that ball from
    // s1 = D / (k + sqrt(k^2 - a D)) on, with D = |c - x|^2 - r^2, k = r gamma + (x - c).v
    // and a = 1 - gamma^2 (until the centre has passed it, which no search reaches).
    auto radiusAt = [&](double s) { return r + gamma * s; };
    auto pointFrom = [&](const double x[3]) {
      double d[3];
      G::Sub(x, c, d);
      const double k = r * gamma + G::Dot(d, v);
      const double D = std::max(0.0, G::Dot(d, d) - r * r);
      const double a = std::max(0.0, 1.0 - gamma * gamma);
      const double disc = k * k - a * D;
      return k > 0.0 && disc >= 0.0 ? D / (k + std::sqrt(disc)) : HUGE_VAL;
    };
    // A triangle's plane, when the ball lies wholly inside it, is entered from
    // (d0 - r) / (gamma + n.v) on (n its outward normal, d0 the centre's distance to
    // it): no later than the triangle, and exactly when the wall is flat. (A curved
    // surface's triangle may lie in a plane that crosses the ball already.)
    auto planeFrom = [&](vtkIdType t) {
      const double* outward = query.GetNormal(t);
      double cv[3], scratch[9];
      G::Sub(c, query.GetTriangleVertices(t, scratch), cv);
      const double d0 = -G::Dot(outward, cv), rate = gamma + G::Dot(outward, v);
      return rate > 0.0 && d0 >= r * (1.0 - 1e-9) ? std::max(0.0, d0 - r) / rate : HUGE_VAL;
    };
    // The step bound from a surface point x on triangle t: the lower of pointFrom(x) and
    // t's plane's, unless (Robust) that plane is nearly parallel to the step.
    auto boundFrom = [&](const double x[3], vtkIdType t) {
      const double point = pointFrom(x), plane = planeFrom(t);
      if (robust && plane < point && gamma + G::Dot(query.GetNormal(t), v) < ParallelRate)
      {
        report.Tolerated = true;
        return point;
      }
      return std::min(point, plane);
    };
    // The first bound: the surface where the ray along v leaves; then the largest step
    // whose ball still comes within `allowed` of p (sliding: within SlideReach times its
    // radius).
    vtkMedialSurfaceQuery::RayHit ray;
    if (!query.Intersect(c, v, 0.0, HUGE_VAL, -1, ray))
    {
      break; // open surface
    }
    double x[3];
    G::AddScaled(c, ray.Distance, v, x);
    double s = boundFrom(x, ray.Triangle);
    auto within = [&](const double centre[3], double radius) {
      return gapAt(centre, radius) <= (sliding ? limits.SlideReach * radius : allowed);
    };
    G::AddScaled(c, s, v, x);
    if (!within(x, radiusAt(s)))
    {
      double lo = 0.0, hi = s;
      for (int i = 0; i < 50; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        G::AddScaled(c, mid, v, x);
        (within(x, radiusAt(mid)) ? lo : hi) = mid;
      }
      s = lo;
    }
    // Probes: the ball at s, empty, or else shrunk about its centre to the closest
    // point found (inscribed either way), whose triangle then sets the next probe's s.
    // A step keeps its largest probe; a sliding one follows the path exactly (a probe
    // counts once nothing is inside it, or as the last resort).
    double best[3], radius = r;
    bool touched = false, missed = false;
    Touch touch{ { 0, 0, 0 }, -1 }, previous{ { 0, 0, 0 }, -1 };
    const int probes = sliding ? limits.SlideProbes : limits.Probes;
    vtkMedialSurfaceQuery::ClosestHit hit;
    double blockedAt = HUGE_VAL; // the smallest step whose ball was found not empty
    int extra = 0; // (Thorough) the probe after those that found only balls out of reach
    for (int i = 0; i < probes + extra && s > 0.0; ++i)
    {
      G::AddScaled(c, s, v, x);
      const double known = std::sqrt(NearestSurfacePoint2(inside, x)) + 4.0 * slack;
      const bool blocked = query.ClosestPoint(x, std::min(radiusAt(s) - slack, known), hit);
      const double inscribed = blocked ? hit.Distance : radiusAt(s);
      if (blocked)
      {
        blockedAt = s;
        AddSurfacePoint(inside, hit.Point);
      }
      if (inscribed > radius && (!sliding || !blocked || i + 1 == probes) && within(x, inscribed))
      {
        radius = inscribed;
        G::Copy(x, best);
        // The point found touches it, or the one that set this probe's step does.
        touched = blocked || (i > 0 && (!keep || Touches(query, previous.Triangle, x, inscribed * (1.0 + 1e-7) + 8.0 * slack)));
        touch = blocked ? Touch{ { hit.Point[0], hit.Point[1], hit.Point[2] }, hit.Triangle } : previous;
        G::Copy(touch.Point, contact);
        if (!touched && i > 0)
        {
          // The ball touches the plane that set this step, not its triangle.
          touched = applies(PlaneContact, previous.Triangle, inward(previous.Triangle)) &&
            PlaneMeetsSurface(query, previous.Triangle, x, inscribed, contact);
        }
      }
      if (!blocked)
      {
        break;
      }
      const double next = boundFrom(hit.Point, hit.Triangle);
      previous = { { hit.Point[0], hit.Point[1], hit.Point[2] }, hit.Triangle };
      if (!(next > 1e-12 * r) ||
        (gamma * next < ContactTolerance * r && applies(CloseBound, hit.Triangle, inward(hit.Triangle))))
      {
        // It touches the ball already (a contact it did not know of, e.g. a third
        // wall at a corner): the direction must account for it.
        missed = true;
        break;
      }
      if (!(next < s))
      {
        break; // no progress at double precision
      }
      s = next;
      if (i + 1 == probes && !sliding && !(radius > r) && applies(ProbeAgain, hit.Triangle, inward(hit.Triangle)))
      {
        extra = 1; // every probe found the surface inside a ball out of reach (or no larger)
      }
    }
    if (keep && sliding && !missed && blockedAt < HUGE_VAL)
    {
      // A blocked sliding step ends on its last probe, or on the last resort, a ball
      // shrunk onto one surface point, which loses the contacts it rounded (the next
      // step then cannot slide); on a curved wall each probe lowers the step only a
      // little, so the probes run out. The largest empty ball on the path below the
      // smallest blocked step, by bisection, is still tangent to every contact and
      // touches what blocks it just beyond. Either may go farther; the larger is kept.
      // A ball that holds a surface point found by this ball's ascents (a probe's or an
      // earlier evaluation's) strictly inside, by more than rounding, is not empty: no
      // query. The contact is the closest point at the last step found not empty, queried
      // at the end when that step was decided so (the same query as without the shortcut).
      vtkMedialSurfaceQuery::ClosestHit beyond;
      bool found = false, known = false; // known: beyond is the last blocked step's
      double lastBlocked = blockedAt;
      int evaluations = 0;
      const double lo = G::BisectLargestEmpty(0.0, blockedAt, 1e-9 * r,
        [&](double step) {
          G::AddScaled(c, step, v, x);
          const double clear = radiusAt(step) - 2.0 * slack;
          const bool blocked = clear > 0.0 && NearestSurfacePoint2(inside, x) < clear * clear;
          const bool queried = !blocked && query.ClosestPoint(x, radiusAt(step) - slack, hit);
          if (queried)
          {
            beyond = hit;
            AddSurfacePoint(inside, hit.Point);
          }
          if (blocked || queried)
          {
            found = true;
            known = queried;
            lastBlocked = step;
            return false;
          }
          return true;
        },
        evaluations);
      if (found && !known)
      {
        G::AddScaled(c, lastBlocked, v, x);
        query.ClosestPoint(x, radiusAt(lastBlocked) - slack, beyond);
      }
      G::AddScaled(c, lo, v, x);
      if (lo > 0.0 && radiusAt(lo) > radius && within(x, radiusAt(lo)))
      {
        radius = radiusAt(lo);
        G::Copy(x, best);
        touched = found;
        if (found)
        {
          touch = Touch{ { beyond.Point[0], beyond.Point[1], beyond.Point[2] }, beyond.Triangle };
          G::Copy(touch.Point, contact);
        }
      }
    }
    if (!(radius > r * (1.0 + 1e-9)))
    {
      if (missed && retries++ < 8)
      {
        touches.push_back(previous);
        --(sliding ? slides : steps);
        continue;
      }
      break;
    }
    const bool small = radius < r * (1.0 + limits.MinimumGain);
    G::Copy(best, c);
    r = radius;
    moved = true;
    if (touched)
    {
      touches.push_back(touch);
    }
    if (sliding)
    {
      allowed = std::max(allowed, gapAt(c, r));
    }
    // A small sliding step that found a new contact is not the last: a curved wall
    // ahead slows the slide, and the new contact turns its direction at the next step
    // (MaximumSlides bounds the cost).
    if (small && !(keep && sliding && touched))
    {
      break;
    }
  }
  if (moved)
  {
    G::Copy(c, out.Centre);
    out.Radius = r;
    G::Copy(contact, out.Contact);
    out.Angle = G::AngleDegrees(c, p, contact);
  }
  return report;
}
}

void vtkMedialGrowBall(const vtkMedialSurfaceQuery& query, const double p[3],
  const vtkMedialGrowthLimits& limits, const vtkIdType* faces, int faceCount, vtkMedialSampleRecord& out,
  vtkMedialSampleRecord* plain, vtkMedialSampleRecord* kept, vtkMedialSampleRecord* prior,
  std::vector<std::array<double, 3>>* surfacePoints)
{
  // The ascent is a local search: where the plain one slides, the one that keeps its
  // contacts goes on where the plain one stops early beside a crease (a curved wall,
  // a start ball not exactly tangent), but it may also reach a smaller local maximum
  // elsewhere. Both balls are inscribed and come within the same reach of p, so the
  // larger is kept: no value falls below the plain ascent's, and a ball that does not
  // slide (most of a smooth surface) costs one ascent, as before.
  // The robust one goes on where rounding (a float input's nearly coplanar faces), a
  // start beside a concave crease or the spent ordinary steps stop the other two; where
  // its rules changed anything, the Keep ascent runs too, so that no value falls below
  // what it gives. The thorough one runs only where one of the others reached a branch
  // that its rules change (a ball that stops before it can slide), and counts where it
  // goes farther.
  const vtkMedialSampleRecord start = out;
  SurfacePoints local;
  SurfacePoints& inside = surfacePoints ? *surfacePoints : local;
  const AscentReport first = Ascend(query, p, limits, faces, faceCount, out, AscentRules::Plain, inside);
  unsigned thorough = first.Thorough;
  if (plain)
  {
    *plain = out;
  }
  if (first.Slid)
  {
    vtkMedialSampleRecord robust = start;
    const AscentReport second = Ascend(query, p, limits, faces, faceCount, robust, AscentRules::Robust, inside);
    thorough |= second.Thorough;
    if (second.Tolerated)
    {
      vtkMedialSampleRecord keep = start;
      thorough |= Ascend(query, p, limits, faces, faceCount, keep, AscentRules::Keep, inside).Thorough;
      if (keep.Radius > out.Radius)
      {
        out = keep;
      }
      if (kept)
      {
        *kept = out;
      }
    }
    else if (kept)
    {
      *kept = robust.Radius > out.Radius ? robust : out; // the Keep ascent's own
    }
    if (robust.Radius > out.Radius)
    {
      out = robust;
    }
  }
  else if (kept)
  {
    *kept = out;
  }
  if (prior)
  {
    *prior = out;
  }
  if (thorough)
  {
    vtkMedialSampleRecord deeper = start;
    Ascend(query, p, limits, faces, faceCount, deeper, AscentRules::Thorough, inside);
    if (deeper.Radius > out.Radius)
    {
      out = deeper;
    }
  }
}
