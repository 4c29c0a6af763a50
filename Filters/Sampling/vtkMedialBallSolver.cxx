// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallSolver.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>

namespace
{
namespace G = vtkMedialGeometry;
}

// Finds the maximal admissible ball tangent at p (on `triangle`) along the inward normal.
void vtkMedialSolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3], vtkMedialSampleRecord& out,
  vtkIdType hintTriangle)
{
  out.Valid = false;
  out.ContactTriangle = -1;
  out.Capped = false;
  out.Iterations = 0;
  out.SourceCell = mesh.SourceCellIds[triangle];
  std::copy(p, p + 3, out.Surface);
  const double* outward = mesh.GetNormal(triangle);
  const double n[3] = { -outward[0], -outward[1], -outward[2] };

  vtkMedialSurfaceQuery::RayHit hit;
  if (!query.Intersect(p, n, 1e-9 * mesh.Diagonal, HUGE_VAL, triangle, hit))
  {
    return; // escaped through a hole
  }
  if (G::Dot(mesh.GetNormal(hit.Triangle), n) <= 0.0)
  {
    return; // hit a face from outside: the ray left through a hole
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

  if (param.Method == vtkMedialAxisSampler::ONE_PASS)
  {
    vtkMedialSurfaceQuery::TangentBall ball;
    ball.Radius = radius;
    std::copy(q, q + 3, ball.Contact);
    ball.ContactTriangle = hit.Triangle;
    ball.HintTriangle = hintTriangle;
    query.MaximalTangentBall(p, n, filter, ball);
    out.Iterations = 1 + ball.Steps;
    out.Capped = ball.Capped;
    out.ContactTriangle = ball.ContactTriangle;
    G::AddScaled(p, ball.Radius, n, out.Centre);
    out.Radius = ball.Radius;
    std::copy(ball.Contact, ball.Contact + 3, out.Contact);
    out.Angle = G::AngleDegrees(out.Centre, p, ball.Contact);
    out.Valid = true;
    return;
  }
  if (param.Method == vtkMedialAxisSampler::SHRINKING_BALL)
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
}
