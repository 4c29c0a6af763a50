// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialEnvelope.h
 * @brief Internal: the balls interpolated along a medial mesh's edges and triangles
 * (the primitives of sphere-meshes: cones and slabs), and their distance-like function.
 * Used by vtkMedialBallUnion (the envelope) and by the structure filters (the slabs'
 * tangent planes and the slope of the radius).
 *
 * A primitive with vertex balls (c_j, r_j) is the union of the balls
 * B(c(l), r(l)) whose centre and radius are interpolated with barycentric weights l
 * (an edge: a cone between two spheres; a triangle: a slab between three). Its field
 *     g(x) = min over l of (|x - c(l)| - r(l))
 * is negative inside, zero on the envelope and, outside, the Euclidean distance to it
 * (each ball lies in the union, and at the minimiser x is at distance g from its
 * ball along the normal of the envelope). g is convex in l, so
 *  - an edge's minimum is at the stationary point of the axis, t = (a + k h / s) / L
 *    with a the axial and h the radial coordinate of x, k = (r1 - r0) / L and
 *    s = sqrt(1 - k^2), where g = h s - k a - r0; or at an end (a sphere); when
 *    |k| >= 1 one ball contains the other and only the ends count;
 *  - a triangle's minimum inside is on the tangent plane u.y = u.c_j + r_j common to
 *    the three spheres (u unit, u.(c_j - c_0) = -(r_j - r_0)), on x's side, where
 *    g = u.(x - c_0) - r_0, provided x's foot on that plane is the tangent point of a
 *    ball inside the triangle; otherwise the minimum is on an edge, which its own
 *    primitive gives (TriangleField then returns +inf).
 * Pruning bounds: a primitive lies in the ball (C, R) with C the mean of its centres
 * and R = max_j (|C - c_j| + r_j), so g(x) >= |x - C| - R; and g(x) <= |x - c_j| - r_j
 * for each vertex ball. See vtkMedialBallUnion's MEDIAL_MESH primitives.
 *
 * Excess (EdgeExcess, TriangleExcess): how far a primitive reaches beyond the union of
 * its vertex balls (the one-sided Hausdorff distance). In a dense medial mesh, where
 * neighbouring balls overlap deeply, it is a tiny fraction of a voxel, and the
 * primitive can be left out with the shape moving by at most that much.
 *  - Edge: the cone leaves the two spheres only in the sliver between its generator
 *    and the circle where the spheres meet; the sliver is thickest there, so the excess
 *    is the distance from that circle to the generator. 0 when one ball contains the
 *    other, +inf when they are disjoint.
 *  - Triangle: beyond its three cones, the slab only fills the slivers under each
 *    tangent plane, over the triangle T of the tangent points; a point of T at
 *    distance d from a side lies at most r - sqrt(r^2 - d^2) above the sphere touching
 *    the plane at the foot on that side (r >= the smallest vertex radius), and d is at
 *    most T's inradius. Its excess is at most that plus its sides' largest.
 */
#ifndef vtkMedialEnvelope_h
#define vtkMedialEnvelope_h

#include <algorithm>
#include <cmath>

namespace vtkMedialEnvelope
{
inline double Dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// An upper bound of how far the ball (c, r), interpolated from n vertex balls
/// (centres[j], radii[j]) each at most as large as its centre's distance to the surface
/// (inscribed), reaches through the surface: that distance is 1-Lipschitz, so at c it is
/// at least radii[j] - |c - centres[j]| for every j. A probe whose bound is within a
/// tolerance needs no surface query (on dense meshes, most of them).
inline double ProtrusionBound(const double c[3], double r, const double* const centres[], const double radii[], int n)
{
  double reach = -HUGE_VAL;
  for (int j = 0; j < n; ++j)
  {
    const double d[3] = { c[0] - centres[j][0], c[1] - centres[j][1], c[2] - centres[j][2] };
    reach = std::max(reach, radii[j] - std::sqrt(Dot3(d, d)));
  }
  return r - reach;
}

/// How far the ball (c, r) reaches through the surface, r minus c's distance to it, when
/// that exceeds `tolerance` (> 0 or not is all a caller decides on); otherwise the
/// tolerance stands for it (an upper bound; 0 for r <= 0). Read from `query` (a
/// vtkMedialSurfaceQuery) as the triangles nearer than r - tolerance, padded for the
/// rounding of that test: one walk that never shrinks, cheaper than a nearest-point walk
/// to r, which must find the nearest even when the ball protrudes by less (most probes
/// that need a query). Beyond the tolerance, the largest protrusion read is the nearest
/// triangle's, the same number as the nearest-point walk gives. `hits` is scratch.
template <class Query, class Hits>
double ProtrusionBeyond(const Query& query, const double c[3], double r, double tolerance, Hits& hits)
{
  const double reach = (r - tolerance) * (1.0 + 1e-9) + 1e-12 * query.GetMesh()->Diagonal;
  double worst = -HUGE_VAL;
  if (reach > 0.0)
  {
    query.TrianglesWithin(c, reach, hits);
    for (const auto& hit : hits)
    {
      worst = std::max(worst, r - hit.Distance);
    }
  }
  return worst > tolerance ? worst : std::max(0.0, std::min(r, tolerance));
}

/// The protrusion of the ball interpolated at barycentric `weights` over n inscribed
/// vertex balls (centres[j], radii[j]), for deciding whether it exceeds `tolerance`:
/// where the vertex balls bound it within the tolerance (ProtrusionBound), that bound
/// (at least 0), without a query; otherwise ProtrusionBeyond's value. The one probe of
/// the envelope refinement and of the complex's protrusion pruning.
template <class Query, class Hits>
double InterpolatedProtrusion(const Query& query, const double* const centres[], const double radii[],
  const double weights[], int n, double tolerance, Hits& hits)
{
  double c[3] = { 0, 0, 0 }, r = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += weights[j] * centres[j][k];
    }
    r += weights[j] * radii[j];
  }
  const double bound = ProtrusionBound(c, r, centres, radii, n);
  if (bound <= tolerance)
  {
    return std::max(0.0, bound);
  }
  return ProtrusionBeyond(query, c, r, tolerance, hits);
}

/// |x - c| - r: a sphere.
inline double BallField(const double x[3], const double c[3], double r)
{
  const double d[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
  return std::sqrt(Dot3(d, d)) - r;
}

/// The cone between balls (c0, r0) and (c1, r1), ends included.
inline double EdgeField(const double x[3], const double c0[3], double r0, const double c1[3], double r1)
{
  const double e[3] = { c1[0] - c0[0], c1[1] - c0[1], c1[2] - c0[2] };
  const double w[3] = { x[0] - c0[0], x[1] - c0[1], x[2] - c0[2] };
  const double length2 = Dot3(e, e);
  const double ends = std::min(std::sqrt(Dot3(w, w)) - r0, BallField(x, c1, r1));
  if (!(length2 > 0.0))
  {
    return ends;
  }
  const double length = std::sqrt(length2);
  const double k = (r1 - r0) / length;
  if (!(std::fabs(k) < 1.0))
  {
    return ends; // one ball contains the other
  }
  const double a = Dot3(w, e) / length;
  const double h = std::sqrt(std::max(0.0, Dot3(w, w) - a * a));
  const double s = std::sqrt(1.0 - k * k);
  const double t = (a + k * h / s) / length;
  if (t <= 0.0 || t >= 1.0)
  {
    return ends; // convex in t: the nearer end
  }
  return std::min(ends, h * s - k * a - r0);
}

/// The common tangent planes of three balls: their unit normals are W + s Gamma N
/// (s = +1 or -1), W in the plane of the centres with W.(c_j - c_0) = -(r_j - r_0), N
/// the plane's normal (c_1 - c_0) x (c_2 - c_0), not unit. False for collinear centres
/// or when no such plane exists (|W| >= 1: the slab is the union of its cones).
struct TangentPlanes
{
  double E1[3], E2[3], N[3], W[3], Gamma;
};
inline bool SlabTangentPlanes(const double* const c[3], const double r[3], TangentPlanes& t)
{
  for (int k = 0; k < 3; ++k)
  {
    t.E1[k] = c[1][k] - c[0][k];
    t.E2[k] = c[2][k] - c[0][k];
  }
  t.N[0] = t.E1[1] * t.E2[2] - t.E1[2] * t.E2[1];
  t.N[1] = t.E1[2] * t.E2[0] - t.E1[0] * t.E2[2];
  t.N[2] = t.E1[0] * t.E2[1] - t.E1[1] * t.E2[0];
  const double g11 = Dot3(t.E1, t.E1), g12 = Dot3(t.E1, t.E2), g22 = Dot3(t.E2, t.E2);
  const double det = g11 * g22 - g12 * g12, n2 = Dot3(t.N, t.N);
  if (!(det > 1e-24 * g11 * g22) || !(n2 > 0.0))
  {
    return false;
  }
  const double d1 = -(r[1] - r[0]), d2 = -(r[2] - r[0]);
  const double alpha = (d1 * g22 - d2 * g12) / det, beta = (d2 * g11 - d1 * g12) / det;
  for (int k = 0; k < 3; ++k)
  {
    t.W[k] = alpha * t.E1[k] + beta * t.E2[k];
  }
  const double inPlane2 = Dot3(t.W, t.W);
  if (!(inPlane2 < 1.0))
  {
    return false;
  }
  t.Gamma = std::sqrt((1.0 - inPlane2) / n2);
  return true;
}

/// The slab of the triangle of balls (c_j, r_j) where its minimum is inside the
/// triangle; +inf where it is on an edge (or for a degenerate triangle).
/// The same with the slab's tangent planes computed already (SlabTangentPlanes true).
inline double TriangleField(const double x[3], const double* const c[3], const double r[3], const TangentPlanes& t)
{
  const double* e1 = t.E1;
  const double* e2 = t.E2;
  const double w[3] = { x[0] - c[0][0], x[1] - c[0][1], x[2] - c[0][2] };
  // The tangent plane on x's side.
  const double gamma = Dot3(w, t.N) >= 0.0 ? t.Gamma : -t.Gamma;
  double u[3];
  for (int k = 0; k < 3; ++k)
  {
    u[k] = t.W[k] + gamma * t.N[k];
  }
  const double g = Dot3(u, w) - r[0];
  // The foot x - g u is the tangent point c(l) + r(l) u: solve for l in the frame
  // f_j = e_j + (r_j - r_0) u (least squares; the foot lies in their span).
  double f1[3], f2[3], q[3];
  for (int k = 0; k < 3; ++k)
  {
    f1[k] = e1[k] + (r[1] - r[0]) * u[k];
    f2[k] = e2[k] + (r[2] - r[0]) * u[k];
    q[k] = w[k] - (g + r[0]) * u[k];
  }
  const double h11 = Dot3(f1, f1), h12 = Dot3(f1, f2), h22 = Dot3(f2, f2);
  const double hdet = h11 * h22 - h12 * h12;
  if (!(hdet > 0.0))
  {
    return HUGE_VAL;
  }
  const double q1 = Dot3(f1, q), q2 = Dot3(f2, q);
  const double l1 = (q1 * h22 - q2 * h12) / hdet, l2 = (q2 * h11 - q1 * h12) / hdet;
  if (l1 < 0.0 || l2 < 0.0 || l1 + l2 > 1.0)
  {
    return HUGE_VAL;
  }
  return g;
}

inline double TriangleField(const double x[3], const double* const c[3], const double r[3])
{
  TangentPlanes t;
  return SlabTangentPlanes(c, r, t) ? TriangleField(x, c, r, t) : HUGE_VAL;
}

/// The pruning bound of a primitive with n (1 to 3) vertex balls: the ball centred at the
/// mean of their centres, of radius max_j (|centre - c_j| + r_j), which the primitive lies in.
inline double BoundingBall(const double* const c[], const double r[], int n, double centre[3])
{
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.0;
    for (int j = 0; j < n; ++j)
    {
      centre[k] += c[j][k] / n;
    }
  }
  double radius = 0.0;
  for (int j = 0; j < n; ++j)
  {
    const double d[3] = { centre[0] - c[j][0], centre[1] - c[j][1], centre[2] - c[j][2] };
    radius = std::max(radius, std::sqrt(Dot3(d, d)) + r[j]);
  }
  return radius;
}

/// Upper bound of how far the cone of an edge reaches beyond its two balls.
inline double EdgeExcess(const double c0[3], double r0, const double c1[3], double r1)
{
  const double e[3] = { c1[0] - c0[0], c1[1] - c0[1], c1[2] - c0[2] };
  const double length = std::sqrt(Dot3(e, e));
  if (length <= std::fabs(r1 - r0))
  {
    return 0.0; // one ball contains the other: the cone is the larger one
  }
  if (length >= r0 + r1)
  {
    return HUGE_VAL; // disjoint balls
  }
  const double k = (r1 - r0) / length, s = std::sqrt(1.0 - k * k);
  // Where the spheres meet, in (axial, radial) coordinates from c0; the generator is the
  // line at distance r0 from c0 along the normal (-k, s).
  const double a = (length * length + r0 * r0 - r1 * r1) / (2.0 * length);
  const double h = std::sqrt(std::max(0.0, r0 * r0 - a * a));
  return std::max(0.0, r0 + k * a - s * h);
}

/// Upper bound of how far the slab of a triangle reaches beyond its three balls.
inline double TriangleExcess(const double* const c[3], const double r[3])
{
  double sides = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    sides = std::max(sides, EdgeExcess(c[j], r[j], c[(j + 1) % 3], r[(j + 1) % 3]));
  }
  TangentPlanes planes;
  if (!SlabTangentPlanes(c, r, planes))
  {
    return sides; // degenerate, or no common tangent plane: the union of its sides
  }
  const double rMin = std::min({ r[0], r[1], r[2] });
  double sliver = 0.0;
  for (double side : { 1.0, -1.0 })
  {
    double t[3][3]; // the tangent points
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        t[j][k] = c[j][k] + r[j] * (planes.W[k] + side * planes.Gamma * planes.N[k]);
      }
    }
    double ab[3], ac[3], cross[3], perimeter = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      ab[k] = t[1][k] - t[0][k];
      ac[k] = t[2][k] - t[0][k];
    }
    cross[0] = ab[1] * ac[2] - ab[2] * ac[1];
    cross[1] = ab[2] * ac[0] - ab[0] * ac[2];
    cross[2] = ab[0] * ac[1] - ab[1] * ac[0];
    for (int j = 0; j < 3; ++j)
    {
      double d[3];
      for (int k = 0; k < 3; ++k)
      {
        d[k] = t[(j + 1) % 3][k] - t[j][k];
      }
      perimeter += std::sqrt(Dot3(d, d));
    }
    const double inradius = perimeter > 0.0 ? std::sqrt(Dot3(cross, cross)) / perimeter : 0.0;
    if (!(inradius < rMin))
    {
      return HUGE_VAL;
    }
    sliver = std::max(sliver, rMin - std::sqrt(rMin * rMin - inradius * inradius));
  }
  return sliver + sides;
}
}

#endif
