// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialGeometry.h
 * @brief Small double-precision geometric kernels shared by the medial filters.
 *
 * Closest point on a triangle (Ericson, "Real-Time Collision Detection" 5.1.5),
 * the same on a triangle clipped by a half-space (used to ignore contacts in
 * the cap around a sample point), and vector helpers. Internal header; not
 * installed. Every decisive inside/outside comparison goes through here, in
 * double precision. Also the bisection shared by the 2D and 3D samplers, and the
 * orientation, segment-triangle and triangle-triangle crossing tests used to keep
 * the medial mesh inside the shape, and the nearest point of a small convex hull to
 * the origin (the direction in which a ball grows away from its contacts).
 */
#ifndef vtkMedialGeometry_h
#define vtkMedialGeometry_h

// The exact tests need IEEE arithmetic: -ffinite-math-only deletes the NaN checks that
// refuse bad input, and -ffast-math reorders the roundings the bounds rely on (built
// with it, several tests ran for minutes instead of seconds). Fusing a * b + c is
// turned off by the build instead (cmake/medialaxisCompileSettings.cmake).
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) || defined(_M_FP_FAST)
#error "medialaxis needs IEEE floating point: build it without -ffast-math, -ffinite-math-only or /fp:fast"
#endif

#include <algorithm>
#include <cmath>

namespace vtkMedialGeometry
{
inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline void Sub(const double a[3], const double b[3], double r[3])
{
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline void Cross(const double a[3], const double b[3], double r[3])
{
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
/// r = a, three coordinates (inlined where std::copy becomes a memmove call).
inline void Copy(const double a[3], double r[3])
{
  r[0] = a[0];
  r[1] = a[1];
  r[2] = a[2];
}
inline double Distance2(const double a[3], const double b[3])
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return Dot(d, d);
}
/// r = a + s * d
inline void AddScaled(const double a[3], double s, const double d[3], double r[3])
{
  r[0] = a[0] + s * d[0];
  r[1] = a[1] + s * d[1];
  r[2] = a[2] + s * d[2];
}
/// Angle between (a - apex) and (b - apex), in degrees; 0 when degenerate.
inline double AngleDegrees(const double apex[3], const double a[3], const double b[3])
{
  double u[3], v[3], w[3];
  Sub(a, apex, u);
  Sub(b, apex, v);
  Cross(u, v, w);
  // atan2 of |u x v| and u.v is accurate at every angle, unlike acos.
  return std::atan2(std::sqrt(Dot(w, w)), Dot(u, v)) * (180.0 / 3.14159265358979323846);
}

/// Squared distance from p to the segment [a, b] (to a when a == b).
inline double SegmentDistance2(const double p[3], const double a[3], const double b[3])
{
  double ab[3], ap[3];
  Sub(b, a, ab);
  Sub(p, a, ap);
  const double len2 = Dot(ab, ab);
  const double t = len2 > 0.0 ? std::min(1.0, std::max(0.0, Dot(ap, ab) / len2)) : 0.0;
  double q[3];
  AddScaled(a, t, ab, q);
  return Distance2(p, q);
}

/// TriangleDistance2Below's first term: the squared distance from p to the nearest of a, b, c.
inline double NearestVertexDistance2(const double p[3], const double a[3], const double b[3], const double c[3])
{
  return std::min({ Distance2(p, a), Distance2(p, b), Distance2(p, c) });
}

/// TriangleDistance2Below's second term before the division by 3: the longest edge's square.
inline double LongestEdge2(const double a[3], const double b[3], const double c[3])
{
  return std::max({ Distance2(a, b), Distance2(b, c), Distance2(c, a) });
}

/**
 * A lower bound of the squared distance from p to triangle (a, b, c): the nearest
 * vertex's squared distance less a third of the longest edge's square. For a point
 * x = l_a a + l_b b + l_c c of the triangle, |x - p|^2 is the weighted sum of the
 * vertices' squared distances less sum l_i l_j |v_i - v_j|^2 (i < j), and
 * sum l_i l_j <= 1/3. Close to the distance for triangles small against it, without
 * branches, so a search can skip most exact tests of triangles that only come near.
 */
inline double TriangleDistance2Below(const double p[3], const double a[3], const double b[3], const double c[3])
{
  return NearestVertexDistance2(p, a, b, c) - LongestEdge2(a, b, c) / 3.0;
}

/// Closest point to p on triangle (a, b, c); returns the squared distance.
inline double ClosestPointOnTriangle(
  const double p[3], const double a[3], const double b[3], const double c[3], double out[3])
{
  double ab[3], ac[3], ap[3];
  Sub(b, a, ab);
  Sub(c, a, ac);
  Sub(p, a, ap);
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    Copy(a, out);
    return Distance2(p, out);
  }
  double bp[3];
  Sub(p, b, bp);
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    Copy(b, out);
    return Distance2(p, out);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    AddScaled(a, d1 / (d1 - d3), ab, out);
    return Distance2(p, out);
  }
  double cp[3];
  Sub(p, c, cp);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    Copy(c, out);
    return Distance2(p, out);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    AddScaled(a, d2 / (d2 - d6), ac, out);
    return Distance2(p, out);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    double bc[3];
    Sub(c, b, bc);
    AddScaled(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), bc, out);
    return Distance2(p, out);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) // degenerate triangle: fall back to its edges
  {
    double best = Distance2(p, a), q[3];
    Copy(a, out);
    const double* v[3] = { a, b, c };
    for (int e = 0; e < 3; ++e)
    {
      const double* s = v[e];
      const double* t = v[(e + 1) % 3];
      double st[3], sp[3];
      Sub(t, s, st);
      Sub(p, s, sp);
      const double len2 = Dot(st, st);
      const double u = len2 > 0.0 ? std::min(1.0, std::max(0.0, Dot(sp, st) / len2)) : 0.0;
      AddScaled(s, u, st, q);
      const double d = Distance2(p, q);
      if (d < best)
      {
        best = d;
        Copy(q, out);
      }
    }
    return best;
  }
  const double v = vb / sum, w = vc / sum;
  for (int i = 0; i < 3; ++i)
  {
    out[i] = a[i] + ab[i] * v + ac[i] * w;
  }
  return Distance2(p, out);
}

/**
 * Closest point to p on the part of triangle (a, b, c) where dot(w, x) <= k.
 * Returns the squared distance, or +inf when that part is empty.
 */
inline double ClosestPointOnClippedTriangle(const double p[3], const double a[3], const double b[3],
  const double c[3], const double w[3], double k, double out[3])
{
  const double* v[3] = { a, b, c };
  const double s[3] = { Dot(w, a) - k, Dot(w, b) - k, Dot(w, c) - k };
  if (s[0] <= 0.0 && s[1] <= 0.0 && s[2] <= 0.0)
  {
    return ClosestPointOnTriangle(p, a, b, c, out);
  }
  if (s[0] > 0.0 && s[1] > 0.0 && s[2] > 0.0)
  {
    return HUGE_VAL;
  }
  // Sutherland-Hodgman against one plane: at most 4 vertices survive.
  double poly[4][3];
  int n = 0;
  for (int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    if (s[i] <= 0.0)
    {
      Copy(v[i], poly[n++]);
    }
    if ((s[i] <= 0.0) != (s[j] <= 0.0))
    {
      const double t = s[i] / (s[i] - s[j]);
      for (int d = 0; d < 3; ++d)
      {
        poly[n][d] = v[i][d] + t * (v[j][d] - v[i][d]);
      }
      ++n;
    }
  }
  // The clipped polygon is convex: fan it into triangles.
  double best = HUGE_VAL, q[3];
  for (int i = 1; i + 1 < n; ++i)
  {
    const double d = ClosestPointOnTriangle(p, poly[0], poly[i], poly[i + 1], q);
    if (d < best)
    {
      best = d;
      Copy(q, out);
    }
  }
  return best;
}
/**
 * Clips the ray origin + t d, t in [t0, t1], to the axis-aligned box [lo, hi] in the
 * first `dimensions` coordinates (slab test): narrows [t0, t1] and returns false when
 * the ray misses the box.
 */
inline bool ClipRayToBox(const double lo[], const double hi[], const double origin[],
  const double d[], int dimensions, double& t0, double& t1)
{
  for (int k = 0; k < dimensions; ++k)
  {
    if (d[k] == 0.0)
    {
      if (origin[k] < lo[k] || origin[k] > hi[k])
      {
        return false;
      }
      continue;
    }
    double a = (lo[k] - origin[k]) / d[k], b = (hi[k] - origin[k]) / d[k];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

/// Six times the signed volume of (a, b, c, d): positive when d lies on the side of
/// the plane (a, b, c) that its normal (b - a) x (c - a) points to.
inline double Orient3D(const double a[3], const double b[3], const double c[3], const double d[3])
{
  double ab[3], ac[3], ad[3], n[3];
  Sub(b, a, ab);
  Sub(c, a, ac);
  Sub(d, a, ad);
  Cross(ab, ac, n);
  return Dot(n, ad);
}

/**
 * True when the segment [p, q] passes through the interior of triangle (a, b, c):
 * p and q strictly on opposite sides of its plane and the segment's line strictly
 * inside its three edges. Touching (through an edge or a vertex, or an end point
 * on the plane) and coplanar segments do not count.
 */
inline bool SegmentCrossesTriangle(
  const double p[3], const double q[3], const double a[3], const double b[3], const double c[3])
{
  const double sp = Orient3D(a, b, c, p), sq = Orient3D(a, b, c, q);
  if (!((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0)))
  {
    return false;
  }
  // The line pq meets the triangle inside when it turns the same way around each edge.
  const double e0 = Orient3D(p, q, a, b), e1 = Orient3D(p, q, b, c), e2 = Orient3D(p, q, c, a);
  return (e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0);
}

/**
 * True when two triangles cross: an edge of one passes through the interior of the
 * other (the intersection of two non-coplanar triangles is a segment whose ends lie
 * on their edges). Touching and coplanar contact do not count.
 */
inline bool TrianglesCross(const double* const t[3], const double* const u[3])
{
  for (int i = 0; i < 3; ++i)
  {
    if (SegmentCrossesTriangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2]) ||
      SegmentCrossesTriangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2]))
    {
      return true;
    }
  }
  return false;
}

/**
 * The point of the convex hull of the unit vectors u nearest to the origin (zero when
 * the hull holds it): for the unit vectors from a ball's contacts to its centre, the
 * direction along which the centre moves away from all of them fastest (the
 * generalised gradient of the distance to the surface), and its speed. Up to 8 vectors
 * (a ball's contacts), exactly, by enumeration of the vertices, edges and triangles
 * whose projection of the origin lies inside them, and of the tetrahedra that hold the
 * origin; more, by Gilbert's iteration (to about 1e-12).
 */
template <class Vectors>
void NearestHullPoint(const Vectors& u, double g[3])
{
  const int n = static_cast<int>(u.size());
  double best = HUGE_VAL;
  g[0] = g[1] = g[2] = 0.0;
  if (n > 8)
  {
    // Many vectors (a vertex where many faces meet): Gilbert's iteration instead, each
    // step to the nearest point of the segment towards the farthest-back vector.
    Copy(u[0].data(), g);
    for (int step = 0; step < 200; ++step)
    {
      int back = 0;
      for (int i = 1; i < n; ++i)
      {
        back = Dot(u[i].data(), g) < Dot(u[back].data(), g) ? i : back;
      }
      double e[3];
      Sub(u[back].data(), g, e);
      const double ee = Dot(e, e);
      const double t = ee > 0.0 ? std::min(1.0, std::max(0.0, -Dot(g, e) / ee)) : 0.0;
      if (!(t > 1e-12))
      {
        break;
      }
      AddScaled(g, t, e, g);
    }
    return;
  }
  auto consider = [&](const double x[3]) {
    const double d = Dot(x, x);
    if (d < best)
    {
      best = d;
      Copy(x, g);
    }
  };
  const double origin[3] = { 0, 0, 0 };
  for (int i = 0; i < n; ++i)
  {
    const double* a = u[i].data();
    consider(a);
    for (int j = i + 1; j < n; ++j)
    {
      const double* b = u[j].data();
      double e[3];
      Sub(b, a, e);
      const double ee = Dot(e, e);
      const double t = ee > 0.0 ? -Dot(a, e) / ee : -1.0;
      if (t > 0.0 && t < 1.0)
      {
        double x[3];
        AddScaled(a, t, e, x);
        consider(x);
      }
      for (int k = j + 1; k < n; ++k)
      {
        // The origin's projection on the plane of (a, b, c), if inside the triangle.
        const double* c = u[k].data();
        double f[3], m[3];
        Sub(c, a, f);
        Cross(e, f, m);
        const double mm = Dot(m, m);
        if (!(mm > 1e-18))
        {
          continue; // a degenerate triangle: its edges and corners count
        }
        double x[3];
        const double h = Dot(a, m) / mm;
        for (int q = 0; q < 3; ++q)
        {
          x[q] = h * m[q];
        }
        const double* corner[3] = { a, b, c };
        bool inside = true;
        for (int q = 0; q < 3 && inside; ++q)
        {
          double edge[3], to[3], side[3];
          Sub(corner[(q + 1) % 3], corner[q], edge);
          Sub(x, corner[q], to);
          Cross(edge, to, side);
          inside = Dot(side, m) > 0.0;
        }
        if (inside)
        {
          consider(x);
        }
        for (int l = k + 1; l < n && best > 0.0; ++l)
        {
          // The origin strictly inside the tetrahedron: on the same side of every face
          // as the opposite corner.
          const double* t4[4] = { a, b, c, u[l].data() };
          bool holds = true;
          for (int face = 0; face < 4 && holds; ++face)
          {
            const double s1 = Orient3D(t4[(face + 1) % 4], t4[(face + 2) % 4], t4[(face + 3) % 4], t4[face]);
            const double s0 = Orient3D(t4[(face + 1) % 4], t4[(face + 2) % 4], t4[(face + 3) % 4], origin);
            // A flat tetrahedron (nearly equal or coplanar vectors) holds nothing.
            holds = std::fabs(s1) > 1e-9 && s0 != 0.0 && (s0 > 0.0) == (s1 > 0.0);
          }
          if (holds)
          {
            best = 0.0;
            g[0] = g[1] = g[2] = 0.0;
          }
        }
      }
    }
  }
}

/**
 * The report's bisection: given empty(lo) and not empty(hi), halves [lo, hi] until
 * it is at most `tolerance` wide and returns the lower end, an empty radius.
 * `evaluations` is increased by the number of calls to empty(r).
 */
template <class Empty>
double BisectLargestEmpty(double lo, double hi, double tolerance, Empty empty, int& evaluations)
{
  while (hi - lo > tolerance)
  {
    const double mid = 0.5 * (lo + hi);
    ++evaluations;
    if (empty(mid))
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}
} // namespace vtkMedialGeometry

#endif
