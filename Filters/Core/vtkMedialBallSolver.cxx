// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallSolver.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>

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
  const double n[3] = { -outward[0], -outward[1], -outward[2] };
  vtkMedialSolveBallAlong(query, mesh, param, triangle, p, n, out, hintTriangle, blockers, largestProtrusion);
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
