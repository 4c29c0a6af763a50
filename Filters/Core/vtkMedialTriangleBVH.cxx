// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialTriangleBVH.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPrefetch.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <omp.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace
{
namespace G = vtkMedialGeometry;
using Node = vtkMedialTriangleBVH::Node;
using WideNode = vtkMedialTriangleBVH::WideNode;

constexpr int LeafSize = 4;

// A triangle whose normal is ill-conditioned (|e1 x e2| tiny against |e1| |e2|): a plane
// computed from it may be off by more than the solid check's tolerance, so the pair
// search keeps any close pair with it (SliverBits).
bool IsSliver(const double* a, const double* b, const double* c)
{
  double e1[3], e2[3], n[3];
  G::Sub(b, a, e1);
  G::Sub(c, a, e2);
  G::Cross(e1, e2, n);
  return !(G::Dot(n, n) >= 1e-14 * G::Dot(e1, e1) * G::Dot(e2, e2));
}

constexpr int Bins = 16;
// Closed-form candidates settle a ball on a face, an edge or a vertex at once;
// a ball still shrinking after this many steps is settling on the cap's cone, and the
// lower end of that triangle's blocked radii is bracketed (LowerEndOfBlocking).
constexpr int StepsBeforeBracketing = 4;
// The tangent search tests inner lanes against their subtrees' inner spheres once it
// has looked at this many triangles. 256 rather than 128: the searches that stop
// between the two mostly cull well without the tests, and pay for them (search
// instructions, 1 thread: -2.1% on the 1.55M horse's balls, -0.8% on horse.ply, while
// a ball inside a finely tessellated sphere, which needs them, costs 3 to 7% more).
constexpr int SpheresAfter = 256;
constexpr std::int32_t SlabMaximumTriangles = 1 << 14;
// Build passes over more triangles than this (the top levels) run on every thread.
constexpr std::int32_t ParallelRange = 1 << 16;
// Partitions of more triangles than this (the first levels) run on every thread. Each
// takes four parallel regions, and on a loaded machine a region's join waits until the
// host runs every thread: below this, a serial partition is cheaper.
constexpr std::int32_t ParallelPartitionRange = 1 << 18;

template <class T>
double BoxDistance2(const T lo[3], const T hi[3], const double x[3])
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max({ static_cast<double>(lo[k]) - x[k], 0.0, x[k] - static_cast<double>(hi[k]) });
    d2 += d * d;
  }
  return d2;
}
double BoxDistance2(const Node& node, const double x[3])
{
  return BoxDistance2(node.Lo, node.Hi, x);
}

// The node cannot reach into the ball (centre, radius), both relative to the
// origin: its box or its slab misses it.
bool MissesBall(const Node& node, const double centre[3], double radius)
{
  if (BoxDistance2(node, centre) >= radius * radius)
  {
    return true;
  }
  if (node.Axis[0] != 0.0f || node.Axis[1] != 0.0f || node.Axis[2] != 0.0f)
  {
    const double m = node.Axis[0] * centre[0] + static_cast<double>(node.Axis[1]) * centre[1] +
      static_cast<double>(node.Axis[2]) * centre[2];
    return m - radius >= node.SlabHi || m + radius <= node.SlabLo;
  }
  return false;
}

/**
 * The tangent search's node tests in single precision, four lanes at once where SSE2
 * is available (x, y, z and an unused lane). Nodes are stored in float relative to
 * the tree's origin, so the rounding of every quantity here is a few float steps of
 * the tree's extent E; each bound is widened by Margin = 1e-5 E, far above that, so
 * a box is dropped only where the same test in exact arithmetic would drop it too.
 * A box kept that exact arithmetic would drop costs time, never correctness: its
 * triangles are tested exactly.
 */
float FloatBelow(float f);

class FloatNodeTests
{
public:
  FloatNodeTests(const Node& root, const double pRel[3], const double n[3], double coneSin)
  {
    float extent = 0.0f;
    for (int k = 0; k < 3; ++k)
    {
      extent = std::max({ extent, std::fabs(root.Lo[k]), std::fabs(root.Hi[k]) });
    }
    this->Margin = 1e-5f * extent;
    for (int k = 0; k < 3; ++k)
    {
      this->P[k] = static_cast<float>(pRel[k]);
      this->N[k] = static_cast<float>(n[k]);
    }
    this->ConeSin2 = static_cast<float>(coneSin * coneSin * (1.0 - 1e-5));
    for (int k = 0; k < 3; ++k)
    {
      this->Far[k] = this->N[k] > 0.0f ? 1 : 0;
    }
#if defined(__SSE2__)
    for (int k = 0; k < 3; ++k)
    {
      this->LaneP[k] = _mm_set1_ps(this->P[k]);
      this->LaneN[k] = _mm_set1_ps(this->N[k]);
    }
    this->LaneMargin = _mm_set1_ps(this->Margin);
    this->FarMask = _mm_castsi128_ps(_mm_set_epi32(0, -this->Far[2], -this->Far[1], -this->Far[0]));
    this->LaneConeSin2 = _mm_set1_ps(this->ConeSin2);
#endif
  }

  /// The ball's centre (relative to the origin) and radius moved.
  void SetBall(const double centreRel[3], double radius)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->C[k] = static_cast<float>(centreRel[k]);
    }
    this->Radius = static_cast<float>(radius) + this->Margin;
    this->Reach2 = this->Radius * this->Radius;
#if defined(__SSE2__)
    for (int k = 0; k < 3; ++k)
    {
      this->LaneC[k] = _mm_set1_ps(this->C[k]);
    }
    this->LaneRadius = _mm_set1_ps(this->Radius);
    this->LaneReach2 = _mm_set1_ps(this->Reach2);
#endif
  }

  /// Squared distance from the ball's centre to the node's box (rounded: for ordering
  /// and for MissesBall).
  float CentreDistance2(const Node& node) const { return Distance2(node.Lo, node.Hi, this->C, 0.0f); }

  /// A triangle's box (lo, hi; four floats readable at each) misses the ball.
  bool BoxMissesBall(const float* lo, const float* hi) const
  {
    return Distance2(lo, hi, this->C, 0.0f) >= this->Reach2;
  }

  /// The node's box (its squared distance `d2` from CentreDistance2) or its slab misses the ball.
  bool MissesBall(const Node& node, float d2) const
  {
    if (d2 >= this->Reach2)
    {
      return true;
    }
    const float m = node.Axis[0] * this->C[0] + node.Axis[1] * this->C[1] + node.Axis[2] * this->C[2];
    return m - this->Radius >= node.SlabHi || m + this->Radius <= node.SlabLo;
  }

  enum Sides
  {
    ABOVE = 0,     // may hold blocking points
    BELOW = 1,     // wholly on or below the tangent plane at p
    OUTSIDE_CONE = 2 // above it, but outside the cone where blockers can lie: the cap's surface
  };
  /// Largest n.(q - p) over the box (lo, hi; four floats readable at each), plus the
  /// margin: an upper bound.
  float Height(const float* lo, const float* hi) const
  {
#if defined(__SSE2__)
    // The far corner's three terms at once, summed in the scalar order below.
    const __m128 far = _mm_or_ps(_mm_and_ps(this->FarMask, _mm_loadu_ps(hi)), _mm_andnot_ps(this->FarMask, _mm_loadu_ps(lo)));
    alignas(16) float terms[4];
    _mm_store_ps(terms, _mm_mul_ps(_mm_load_ps(this->N), _mm_sub_ps(far, _mm_load_ps(this->P))));
    return ((this->Margin + terms[0]) + terms[1]) + terms[2];
#else
    const float* corners[2] = { lo, hi };
    float h = this->Margin;
    for (int k = 0; k < 3; ++k)
    {
      h += this->N[k] * (corners[this->Far[k]][k] - this->P[k]);
    }
    return h;
#endif
  }

  /// Where the box (lo, hi; four floats readable at each) lies.
  Sides Side(const float* lo, const float* hi) const
  {
    const float h = this->Height(lo, hi);
    if (!(h > 0.0f))
    {
      return BELOW;
    }
    // A lower bound of the box's squared distance to p.
    const float d2 = Distance2(lo, hi, this->P, this->Margin) * (1.0f - 1e-5f);
    return h * h < this->ConeSin2 * d2 ? OUTSIDE_CONE : ABOVE;
  }

  /// The tests above on the four lanes of a wide node at once, as bit masks (bit i:
  /// lane i): Miss (MissesBall), and for the others Keep (ABOVE) or Cap (OUTSIDE_CONE);
  /// D2 is each lane's CentreDistance2, for ordering.
  struct Lanes
  {
    int Miss, Keep, Cap;
    int Low; // among Keep: wholly below the cap's plane (SetCapPlane), for now
    alignas(16) float D2[4];
    alignas(16) float H[4]; // an upper bound of n.(q - p) over each lane's box
  };

  /// The height of the cap's plane above p, n.(q - p) = r (1 - cos theta) (a float no
  /// higher than the exact one): a box wholly below it holds nothing admissible yet.
  void SetCapPlane(double height)
  {
    this->CapPlane = FloatBelow(static_cast<float>(height));
#if defined(__SSE2__)
    this->LaneCapPlane = _mm_set1_ps(this->CapPlane);
#endif
  }
  float GetCapPlane() const { return this->CapPlane; }
  void TestLanes(const WideNode& w, Lanes& out) const
  {
#if defined(__SSE2__)
    const __m128 zero = _mm_setzero_ps();
    const __m128 margin = this->LaneMargin;
    __m128 sq[3], sp[3];
    __m128 h = margin, m = zero;
    for (int k = 0; k < 3; ++k)
    {
      const __m128 lo = _mm_load_ps(w.Lo[k]);
      const __m128 hi = _mm_load_ps(w.Hi[k]);
      const __m128 c = this->LaneC[k];
      const __m128 p = this->LaneP[k];
      const __m128 gc = _mm_max_ps(_mm_max_ps(_mm_sub_ps(lo, c), _mm_sub_ps(c, hi)), zero);
      sq[k] = _mm_mul_ps(gc, gc);
      const __m128 gp =
        _mm_max_ps(_mm_sub_ps(_mm_max_ps(_mm_sub_ps(lo, p), _mm_sub_ps(p, hi)), margin), zero);
      sp[k] = _mm_mul_ps(gp, gp);
      const __m128 far = this->Far[k] ? hi : lo;
      h = _mm_add_ps(h, _mm_mul_ps(this->LaneN[k], _mm_sub_ps(far, p)));
      const __m128 mk = _mm_mul_ps(_mm_load_ps(w.Axis[k]), c);
      m = k == 0 ? mk : _mm_add_ps(m, mk);
    }
    // Summed as Distance2 does: (x + z) + y.
    const __m128 d2 = _mm_add_ps(_mm_add_ps(sq[0], sq[2]), sq[1]);
    const __m128 dp2 = _mm_mul_ps(_mm_add_ps(_mm_add_ps(sp[0], sp[2]), sp[1]), _mm_set1_ps(1.0f - 1e-5f));
    _mm_store_ps(out.D2, d2);
    const __m128 radius = this->LaneRadius;
    const __m128 miss = _mm_or_ps(_mm_cmpge_ps(d2, this->LaneReach2),
      _mm_or_ps(_mm_cmpge_ps(_mm_sub_ps(m, radius), _mm_load_ps(w.SlabHi)),
        _mm_cmple_ps(_mm_add_ps(m, radius), _mm_load_ps(w.SlabLo))));
    const int above = _mm_movemask_ps(_mm_cmpgt_ps(h, zero));
    const int outside =
      _mm_movemask_ps(_mm_cmplt_ps(_mm_mul_ps(h, h), _mm_mul_ps(this->LaneConeSin2, dp2)));
    out.Miss = _mm_movemask_ps(miss);
    out.Keep = ~out.Miss & above & ~outside & 0xF;
    out.Cap = ~out.Miss & above & outside & 0xF;
    _mm_store_ps(out.H, h);
    out.Low = out.Keep & _mm_movemask_ps(_mm_cmplt_ps(h, this->LaneCapPlane));
#else
    out.Miss = out.Keep = out.Cap = out.Low = 0;
    for (int i = 0; i < 4; ++i)
    {
      const Node node = LaneNode(w, i);
      out.D2[i] = this->CentreDistance2(node);
      out.H[i] = this->Height(node.Lo, node.Hi);
      if (this->MissesBall(node, out.D2[i]))
      {
        out.Miss |= 1 << i;
        continue;
      }
      const Sides side = this->Side(node.Lo, node.Hi);
      out.Keep |= side == ABOVE ? 1 << i : 0;
      out.Cap |= side == OUTSIDE_CONE ? 1 << i : 0;
      out.Low |= side == ABOVE && out.H[i] < this->CapPlane ? 1 << i : 0;
    }
#endif
  }

  /// MissesBall for lane i of a wide node, read in place (a copy to a Node costs a
  /// stalled reload when the box is then read four floats at a time).
  bool LaneMissesBall(const WideNode& w, int i) const
  {
    float d2[3];
    for (int k = 0; k < 3; ++k)
    {
      const float d = std::max(std::max(w.Lo[k][i] - this->C[k], this->C[k] - w.Hi[k][i]), 0.0f);
      d2[k] = d * d;
    }
    if ((d2[0] + d2[2]) + d2[1] >= this->Reach2) // summed as Distance2 does
    {
      return true;
    }
    const float m = w.Axis[0][i] * this->C[0] + w.Axis[1][i] * this->C[1] + w.Axis[2][i] * this->C[2];
    return m - this->Radius >= w.SlabHi[i] || m + this->Radius <= w.SlabLo[i];
  }

  /// Lane i of a wide node as a binary node (bounds only).
  static Node LaneNode(const WideNode& w, int i)
  {
    Node node{};
    for (int k = 0; k < 3; ++k)
    {
      node.Lo[k] = w.Lo[k][i];
      node.Hi[k] = w.Hi[k][i];
      node.Axis[k] = w.Axis[k][i];
    }
    node.SlabLo = w.SlabLo[i];
    node.SlabHi = w.SlabHi[i];
    return node;
  }

private:
  // Squared distance from x to the box (lo, hi), each axis' gap shrunk by `shrink` (>= 0).
  static float Distance2(const float* lo, const float* hi, const float x[4], float shrink)
  {
#if defined(__SSE2__)
    const __m128 mask = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
    const __m128 px = _mm_loadu_ps(x);
    const __m128 gap = _mm_max_ps(_mm_sub_ps(_mm_loadu_ps(lo), px), _mm_sub_ps(px, _mm_loadu_ps(hi)));
    const __m128 d = _mm_and_ps(_mm_max_ps(_mm_sub_ps(gap, _mm_set1_ps(shrink)), _mm_setzero_ps()), mask);
    const __m128 sq = _mm_mul_ps(d, d);
    const __m128 pair = _mm_add_ps(sq, _mm_movehl_ps(sq, sq)); // x + z, y + 0
    return _mm_cvtss_f32(_mm_add_ss(pair, _mm_shuffle_ps(pair, pair, 1)));
#else
    float d2[3];
    for (int k = 0; k < 3; ++k)
    {
      const float d = std::max(std::max(lo[k] - x[k], x[k] - hi[k]) - shrink, 0.0f);
      d2[k] = d * d;
    }
    return (d2[0] + d2[2]) + d2[1];
#endif
  }

  alignas(16) float P[4] = { 0, 0, 0, 0 }, N[4] = { 0, 0, 0, 0 }, C[4] = { 0, 0, 0, 0 };
  float Margin = 0.0f, ConeSin2 = 0.0f, Radius = 0.0f, Reach2 = 0.0f;
  float CapPlane = -HUGE_VALF; // SetCapPlane: nothing is below it until set
  int Far[3] = { 0, 0, 0 }; // 1 where n points up the axis: the box's far corner takes hi there
#if defined(__SSE2__)
  // The same, broadcast to four lanes once per ball rather than once per node.
  __m128 LaneC[3], LaneP[3], LaneN[3];
  __m128 LaneMargin, LaneConeSin2, LaneRadius, LaneReach2;
  __m128 LaneCapPlane = _mm_set1_ps(-HUGE_VALF);
  __m128 FarMask; // all ones in the components where Far is 1
#endif
};

// std::nextafter(f, -HUGE_VALF) and std::nextafter(f, HUGE_VALF), the same bits, without
// a call into the maths library (six per triangle and eight per node in the build).
float FloatBelow(float f)
{
  if (!(f > -HUGE_VALF)) // -inf or NaN
  {
    return f;
  }
  if (f == 0.0f)
  {
    return -std::numeric_limits<float>::denorm_min();
  }
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof(bits));
  bits = f > 0.0f ? bits - 1 : bits + 1;
  std::memcpy(&f, &bits, sizeof(bits));
  return f;
}
float FloatAbove(float f)
{
  return -FloatBelow(-f);
}
// Single precision bounds that still hold: `pad` (far above the double rounding
// of the subtraction that produced v, far below a float step at the mesh's size)
// and one float step beyond the nearest float.
float Down(double v, double pad)
{
  return FloatBelow(static_cast<float>(v - pad));
}
float Up(double v, double pad)
{
  return FloatAbove(static_cast<float>(v + pad));
}

/**
 * The smallest f(x) = |x - p|^2 / (2 n.(x - p)), the radius of the ball tangent at
 * p through x, over the closed-form critical points of triangle (a, b, c): the
 * point where a ball touches the face's plane, the critical points along each
 * edge, and the vertices. Only points admissible for the current radius (n.(x - p)
 * >= radius * lift) count, so each candidate blocks every radius in (f(x), radius].
 * The slack rule is the closest-point test's. These let a ball that settles on a face or an edge get there in one step
 * instead of converging to it linearly.
 */
void TangentCandidates(const double p[3], const double n[3], const double* a, const double* b,
  const double* c, double lift, double radius, double slack, double& best, double bestPoint[3])
{
  double centre[3];
  G::AddScaled(p, radius, n, centre);
  const double limit = radius - slack;
  auto consider = [&](const double x[3]) {
    double u[3];
    G::Sub(x, p, u);
    const double along = G::Dot(n, u);
    // Blocking by the same rule as the closest-point test: strictly inside by the
    // slack, so rounding on the tangent plane near p never counts.
    if (along > 0.0 && along >= radius * lift && G::Distance2(x, centre) < limit * limit)
    {
      const double f = G::Dot(u, u) / (2.0 * along);
      if (f < best)
      {
        best = f;
        G::Copy(x, bestPoint);
      }
    }
  };
  // Face: the ball tangent to the plane on p's side has r = sigma / (1 - m.n).
  double ab[3], ac[3], m[3];
  G::Sub(b, a, ab);
  G::Sub(c, a, ac);
  G::Cross(ab, ac, m);
  const double m2 = G::Dot(m, m);
  if (m2 > 0.0)
  {
    const double len = std::sqrt(m2);
    for (double& v : m)
    {
      v /= len;
    }
    const double face[3] = { m[0], m[1], m[2] }; // before orienting towards p
    double pa[3];
    G::Sub(p, a, pa);
    double sigma = G::Dot(m, pa);
    if (sigma < 0.0)
    {
      sigma = -sigma;
      for (double& v : m)
      {
        v = -v;
      }
    }
    const double denom = 1.0 - G::Dot(m, n);
    if (sigma > 0.0 && denom > 0.0)
    {
      const double r = sigma / denom;
      double x[3];
      for (int k = 0; k < 3; ++k)
      {
        x[k] = p[k] + r * n[k] - r * m[k];
      }
      // Inside the triangle: barycentric coordinates from the sub-areas.
      double ax[3], t1[3], t2[3];
      G::Sub(x, a, ax);
      G::Cross(ab, ax, t1);
      G::Cross(ax, ac, t2);
      const double w2 = G::Dot(t1, face), w1 = G::Dot(t2, face);
      if (w1 >= 0.0 && w2 >= 0.0 && w1 + w2 <= len)
      {
        consider(x);
      }
    }
  }
  // Edges: d f / d lambda = 0 on x = s + lambda e is a quadratic in lambda.
  const double* v[3] = { a, b, c };
  for (int i = 0; i < 3; ++i)
  {
    const double* s0 = v[i];
    const double* s1 = v[(i + 1) % 3];
    double e[3], w[3];
    G::Sub(s1, s0, e);
    G::Sub(s0, p, w);
    const double A = G::Dot(e, e), B = G::Dot(w, e), C = G::Dot(w, w), D = G::Dot(n, e),
                 E = G::Dot(n, w);
    const double qa = A * D, qb = 2.0 * A * E, qc = 2.0 * B * E - C * D;
    double roots[2];
    int count = 0;
    if (std::fabs(qa) <= 1e-14 * (std::fabs(qb) + std::fabs(qc)))
    {
      if (qb != 0.0)
      {
        roots[count++] = -qc / qb;
      }
    }
    else
    {
      const double disc = qb * qb - 4.0 * qa * qc;
      if (disc >= 0.0)
      {
        const double sq = std::sqrt(disc);
        // Numerically stable pair of roots.
        const double t = -0.5 * (qb + (qb >= 0.0 ? sq : -sq));
        roots[count++] = t / qa;
        if (t != 0.0)
        {
          roots[count++] = qc / t;
        }
      }
    }
    for (int r = 0; r < count; ++r)
    {
      if (roots[r] > 0.0 && roots[r] < 1.0)
      {
        double x[3];
        G::AddScaled(s0, roots[r], e, x);
        consider(x);
      }
    }
    consider(s0);
  }
}

using BuildBounds = vtkMedialTriangleBVH::BuildBounds;

// Bounds of nothing, for min/max folds.
BuildBounds EmptyBounds()
{
  BuildBounds b;
  for (int k = 0; k < 3; ++k)
  {
    b.Lo[k] = b.CLo[k] = HUGE_VAL;
    b.Hi[k] = b.CHi[k] = -HUGE_VAL;
  }
  return b;
}

// Widens `bounds` to hold the box [lo, hi] and the centroids' box [cLo, cHi].
void Widen(BuildBounds& bounds, const double lo[3], const double hi[3], const double cLo[3], const double cHi[3])
{
  for (int k = 0; k < 3; ++k)
  {
    bounds.Lo[k] = std::min(bounds.Lo[k], lo[k]);
    bounds.Hi[k] = std::max(bounds.Hi[k], hi[k]);
    bounds.CLo[k] = std::min(bounds.CLo[k], cLo[k]);
    bounds.CHi[k] = std::max(bounds.CHi[k], cHi[k]);
  }
}

void MergeBounds(BuildBounds& whole, const BuildBounds& part)
{
  Widen(whole, part.Lo, part.Hi, part.CLo, part.CHi);
}

// A bin of the SAH split: the box of its triangles and of their centroids, and their
// number. Min and max do not depend on the order, so a child's bounds are exactly the
// union of its bins': no second pass over its triangles.
struct SahBin
{
  BuildBounds Bounds = EmptyBounds();
  std::int32_t Count = 0;
};

double HalfArea(const double lo[3], const double hi[3])
{
  const double d[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
  return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

// The bin after which splitting costs least (surface area heuristic), -1 when every
// split leaves a side empty. Sweeps from the right, then from the left, to price
// every split plane.
int CheapestSplit(const SahBin bins[Bins], std::int32_t count)
{
  double rightCost[Bins];
  {
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    std::int32_t n = 0;
    for (int b = Bins - 1; b > 0; --b)
    {
      for (int k = 0; k < 3; ++k)
      {
        lo[k] = std::min(lo[k], bins[b].Bounds.Lo[k]);
        hi[k] = std::max(hi[k], bins[b].Bounds.Hi[k]);
      }
      n += bins[b].Count;
      rightCost[b] = n > 0 ? n * HalfArea(lo, hi) : 0.0;
    }
  }
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  std::int32_t n = 0;
  double bestCost = HUGE_VAL;
  int bestSplit = -1;
  for (int b = 0; b + 1 < Bins; ++b)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], bins[b].Bounds.Lo[k]);
      hi[k] = std::max(hi[k], bins[b].Bounds.Hi[k]);
    }
    n += bins[b].Count;
    if (n == 0 || n == count)
    {
      continue;
    }
    const double cost = n * HalfArea(lo, hi) + rightCost[b + 1];
    if (cost < bestCost)
    {
      bestCost = cost;
      bestSplit = b;
    }
  }
  return bestSplit;
}

// Folds the items [begin, end) into `total`: fold(part, i) per item, merge(total,
// part) for each thread's part, which starts as `empty`. Large ranges (the top levels,
// built before the subtrees run in parallel) take every thread; the folds used here
// (counts, min, max) give the same result in any order.
template <class T, class Fold, class Merge>
void FoldRange(std::int32_t begin, std::int32_t end, T& total, Fold fold, Merge merge, const T& empty)
{
  if (end - begin <= ParallelRange)
  {
    for (std::int32_t i = begin; i < end; ++i)
    {
      fold(total, i);
    }
    return;
  }
#pragma omp parallel
  {
    T part = empty;
#pragma omp for schedule(static) nowait
    for (std::int32_t i = begin; i < end; ++i)
    {
      fold(part, i);
    }
#pragma omp critical
    merge(total, part);
  }
}

// A lane reference's wide node and lane. References are never negative, so these
// are shifts, not signed division (which took a fifth of the walk's own instructions).
inline std::int32_t WideOf(std::int32_t ref)
{
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(ref) / 4u);
}
inline int LaneOf(std::int32_t ref)
{
  return static_cast<int>(static_cast<std::uint32_t>(ref) % 4u);
}

// The lanes set in `mask` in order of their keys, the smallest first (ties: the lower
// lane), into order[0 .. count); returns count. A depth-first walk pushes them in
// reverse so that it takes the nearest first. Each kept lane's place is its rank among
// the kept lanes (those with a smaller key, or an equal key and a lower lane, come
// first): the order of a stable sort, found without the data-dependent branches of an
// insertion sort, which mispredict.
inline int NearestFirst(int mask, const float key[4], int order[4])
{
  int count = 0;
  bool ordered = true; // false with a NaN key, which compares false with everything
  for (int i = 0; i < 4; ++i)
  {
    count += (mask >> i) & 1;
    ordered = ordered && !((mask & (1 << i)) && key[i] != key[i]);
  }
  if (!ordered)
  {
    // The insertion sort the ranks stand for, whose order NaN keys leave defined.
    count = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (mask & (1 << i))
      {
        int j = count++;
        for (; j > 0 && key[order[j - 1]] > key[i]; --j)
        {
          order[j] = order[j - 1];
        }
        order[j] = i;
      }
    }
    return count;
  }
  for (int i = 0; i < 4; ++i)
  {
    int rank = 0;
    for (int j = 0; j < 4; ++j)
    {
      const int before = static_cast<int>(key[j] < key[i]) | (static_cast<int>(key[j] == key[i]) & static_cast<int>(j < i));
      rank += (mask >> j) & before;
    }
    if (mask & (1 << i))
    {
      order[rank] = i;
    }
  }
  return count;
}

// A lane waiting in the tangent search, with the number of radius updates when it was pushed.
struct PendingLane
{
  std::int32_t Ref, Steps;
};

// Scratch space reused by every query on a thread: no allocation per sample.
struct Scratch
{
  std::vector<PendingLane> Lanes; // the tangent search's stack (sized, not cleared: its top is local)
  std::vector<std::int32_t> Stack;
  std::vector<std::int32_t> Deferred;
  std::vector<std::int32_t> DeferredSteps; // radius updates when each was last looked at
  std::vector<std::int32_t> CapNodes; // dropped for the cone while reaching into the ball
  std::vector<std::int32_t> CapSlots; // the same, triangles
  std::vector<PendingLane> CapLanes; // InscribeInCap's stack
  std::vector<std::int32_t> LowNodes; // lanes wholly below the cap's plane when met
  std::vector<float> LowHeights;      // the top of each (an upper bound of n.(q - p))
};
Scratch& ThreadScratch()
{
  thread_local Scratch scratch;
  scratch.Stack.clear();
  scratch.Deferred.clear();
  scratch.DeferredSteps.clear();
  scratch.CapNodes.clear();
  scratch.CapSlots.clear();
  scratch.CapLanes.clear();
  scratch.LowNodes.clear();
  scratch.LowHeights.clear();
  return scratch;
}}

namespace
{
// What the splits read of a triangle, stored by its slot in the order being
// partitioned and moved with it: the passes over a node read memory in sequence
// instead of gathering from all over the mesh.
struct BuildItem
{
  double Lo[3], Hi[3]; // the triangle's box
  double Centroid[3];
  std::int32_t Triangle;
};
// A build item in doubles: the items live in the leaf-order vertices' storage (9 doubles a triangle).
constexpr size_t ItemDoubles = (sizeof(BuildItem) + sizeof(double) - 1) / sizeof(double);
static_assert(sizeof(vtkMedialTriangleBVH::LeafTriangle) == 64, "a leaf triangle is one cache line");
static_assert(ItemDoubles * sizeof(double) == sizeof(BuildItem) && alignof(BuildItem) <= alignof(double) &&
    ItemDoubles >= 9,
  "build items must tile the vertices' storage");

// Widen(bounds, item's box, its centroid as a point), written out so that the binning
// loop, the build's hottest, inlines it (a call per item and level before), and two
// coordinates at a time where SSE2 is available: minpd(x, y) is (x < y ? x : y), which
// is std::min(y, x) to the bit (NaN and signed zeros alike), and maxpd likewise.
inline void WidenByItem(BuildBounds& bounds, const BuildItem& item)
{
#if defined(__SSE2__)
  const __m128d lo01 = _mm_loadu_pd(item.Lo), lo2 = _mm_load_sd(item.Lo + 2);
  const __m128d hi01 = _mm_loadu_pd(item.Hi), hi2 = _mm_load_sd(item.Hi + 2);
  const __m128d c01 = _mm_loadu_pd(item.Centroid), c2 = _mm_load_sd(item.Centroid + 2);
  _mm_storeu_pd(bounds.Lo, _mm_min_pd(lo01, _mm_loadu_pd(bounds.Lo)));
  _mm_store_sd(bounds.Lo + 2, _mm_min_sd(lo2, _mm_load_sd(bounds.Lo + 2)));
  _mm_storeu_pd(bounds.Hi, _mm_max_pd(hi01, _mm_loadu_pd(bounds.Hi)));
  _mm_store_sd(bounds.Hi + 2, _mm_max_sd(hi2, _mm_load_sd(bounds.Hi + 2)));
  _mm_storeu_pd(bounds.CLo, _mm_min_pd(c01, _mm_loadu_pd(bounds.CLo)));
  _mm_store_sd(bounds.CLo + 2, _mm_min_sd(c2, _mm_load_sd(bounds.CLo + 2)));
  _mm_storeu_pd(bounds.CHi, _mm_max_pd(c01, _mm_loadu_pd(bounds.CHi)));
  _mm_store_sd(bounds.CHi + 2, _mm_max_sd(c2, _mm_load_sd(bounds.CHi + 2)));
#else
  for (int k = 0; k < 3; ++k)
  {
    bounds.Lo[k] = std::min(bounds.Lo[k], item.Lo[k]);
    bounds.Hi[k] = std::max(bounds.Hi[k], item.Hi[k]);
    bounds.CLo[k] = std::min(bounds.CLo[k], item.Centroid[k]);
    bounds.CHi[k] = std::max(bounds.CHi[k], item.Centroid[k]);
  }
#endif
}

// Partitions [first, last) so that the items satisfying `before` come first, by the
// two-ended exchange (Hoare): scan from the front for an item that must move back and
// from the back for one that must move forward, swap them. Fixed here rather than left
// to std::partition so that the leaf order is the same with every standard library.
template <class Before>
BuildItem* PartitionItems(BuildItem* first, BuildItem* last, Before before)
{
  while (true)
  {
    while (true)
    {
      if (first == last)
      {
        return first;
      }
      if (!before(*first))
      {
        break;
      }
      ++first;
    }
    --last;
    while (true)
    {
      if (first == last)
      {
        return first;
      }
      if (before(*last))
      {
        break;
      }
      --last;
    }
    std::swap(*first, *last);
    ++first;
  }
}

// PartitionItems' result on every thread, for the first levels: the two-ended exchange
// swaps the k-th item of the front part [first, mid) that must move back with the k-th
// item, counted from the end, of the back part [mid, last) that must move forward, mid
// being where the items satisfying `before` end. Chunks count those items, then swap
// them pairwise: the same items in the same slots, whatever the thread count.
template <class Before>
BuildItem* PartitionItemsInParallel(BuildItem* first, BuildItem* last, Before before)
{
  const std::int64_t count = last - first;
  constexpr int Chunks = 64;
  auto chunkBegin = [](std::int64_t from, std::int64_t to, int c) { return from + (to - from) * c / Chunks; };
  std::int64_t staying = 0;
#pragma omp parallel for schedule(static) reduction(+ : staying)
  for (std::int64_t i = 0; i < count; ++i)
  {
    staying += before(first[i]) ? 1 : 0;
  }
  const std::int64_t mid = staying;
  // Per chunk of each part: how many of its items must move (front: !before; back: before).
  std::int64_t moving[2][Chunks + 1] = {};
#pragma omp parallel for schedule(static)
  for (int job = 0; job < 2 * Chunks; ++job)
  {
    const int part = job / Chunks, c = job % Chunks;
    const std::int64_t from = part == 0 ? 0 : mid, to = part == 0 ? mid : count;
    std::int64_t n = 0;
    for (std::int64_t i = chunkBegin(from, to, c); i < chunkBegin(from, to, c + 1); ++i)
    {
      n += before(first[i]) == (part == 1) ? 1 : 0;
    }
    moving[part][c + 1] = n;
  }
  for (int part = 0; part < 2; ++part)
  {
    for (int c = 0; c < Chunks; ++c)
    {
      moving[part][c + 1] += moving[part][c];
    }
  }
  // The back part's moving items, in increasing order; the k-th of the front part's
  // goes where the k-th from the end of these is.
  const std::int64_t swaps = moving[0][Chunks];
  vtkMedialBuffer<std::int64_t> back(static_cast<size_t>(swaps)); // every entry written below
#pragma omp parallel for schedule(static)
  for (int c = 0; c < Chunks; ++c)
  {
    std::int64_t k = moving[1][c];
    for (std::int64_t i = chunkBegin(mid, count, c); i < chunkBegin(mid, count, c + 1); ++i)
    {
      if (before(first[i]))
      {
        back[static_cast<size_t>(k++)] = i;
      }
    }
  }
#pragma omp parallel for schedule(static)
  for (int c = 0; c < Chunks; ++c)
  {
    std::int64_t k = moving[0][c];
    for (std::int64_t i = chunkBegin(0, mid, c); i < chunkBegin(0, mid, c + 1); ++i)
    {
      if (!before(first[i]))
      {
        std::swap(first[i], first[back[static_cast<size_t>(swaps - 1 - k++)]]);
      }
    }
  }
  return first + mid;
}
}

struct vtkMedialTriangleBVH::BuildState
{
  const vtkMedialTriangleMesh& Mesh;
  BuildItem* Items; // by slot; the triangles' order is the leaf order at the end
};

bool vtkMedialTriangleBVH::Build(const vtkMedialTriangleMesh& mesh, const std::function<bool()>& aborted)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  this->Nodes.clear();
  if (nt <= 0 || nt >= std::numeric_limits<std::int32_t>::max() / 2)
  {
    return false;
  }
  double extent = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    this->Origin[k] = 0.5 * (mesh.Bounds[2 * k] + mesh.Bounds[2 * k + 1]);
    extent = std::max({ extent, std::fabs(mesh.Bounds[2 * k]), std::fabs(mesh.Bounds[2 * k + 1]) });
  }
  this->RoundingPad = 1e-14 * extent;
  if (!this->BuildNodes(mesh, aborted))
  {
    this->Nodes.clear();
    vtkMedialBuffer<double>().swap(this->Vertices);
    this->SliverBits.clear();
    return false;
  }
  this->CopyInLeafOrder(mesh);
  if (!this->BuildWideNodes(mesh))
  {
    return false;
  }
  this->MeasureWideSpheres();
  return true;
}

bool vtkMedialTriangleBVH::BuildNodes(const vtkMedialTriangleMesh& mesh, const std::function<bool()>& aborted)
{
  // Per triangle: its box and its centroid, in the storage of the leaf-order vertices,
  // which CopyInLeafOrder writes over them once the order is known: their pages are
  // resident by then (on 1.55M triangles, 112 MB less of first-touch faults and zeroing).
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  this->Vertices.resize(ItemDoubles * static_cast<size_t>(nt));
  BuildState state{ mesh, reinterpret_cast<BuildItem*>(this->Vertices.data()) };
#pragma omp parallel for schedule(static)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    BuildItem& item = state.Items[t];
    for (int k = 0; k < 3; ++k)
    {
      const double a = mesh.GetPoint(v[0])[k], b = mesh.GetPoint(v[1])[k], c = mesh.GetPoint(v[2])[k];
      item.Lo[k] = std::min({ a, b, c });
      item.Hi[k] = std::max({ a, b, c });
      item.Centroid[k] = (a + b + c) / 3.0;
    }
    item.Triangle = static_cast<std::int32_t>(t);
  }
  // Top levels first, then the subtrees below them in parallel, appended in order.
  const std::int32_t grain = std::max<std::int32_t>(4096, static_cast<std::int32_t>(nt / 64));
  std::vector<Subtree> subtrees;
  vtkMedialBuffer<Node> top(1);
  const std::int32_t all = static_cast<std::int32_t>(nt);
  this->BuildNode(state, top, 0, 0, all, MeasureBounds(state, 0, all), &subtrees, grain);
  // Each thread builds a subtree in one scratch buffer that it reuses (a subtree of n
  // triangles has fewer than 2 n nodes), then copies it into the node array after the
  // top levels, packed in the order the subtrees finish; its root goes to the slot its
  // parent reserved. Only where each subtree's nodes are stored depends on the threads:
  // the tree, the leaf order and the 4-wide tree are the same, and no query reads a
  // node's index. Every page is touched once, in huge pages (buffers reserved per
  // subtree at their bound were 4 kB pages, a fault each: a third of the tree's CPU
  // time; a staging buffer copied once more in subtree order was 60 MB more to touch).
  const size_t topNodes = top.size();
  this->Nodes.resize(topNodes + 2 * static_cast<size_t>(nt)); // address space: touched as filled
  std::copy(top.begin(), top.end(), this->Nodes.begin());
  std::atomic<size_t> packed{ topNodes };
  std::atomic<bool> stop{ false };
#pragma omp parallel
  {
    vtkMedialBuffer<Node> scratch;
    scratch.reserve(2 * static_cast<size_t>(grain));
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(subtrees.size()); ++i)
    {
      // Polled on the calling thread only: the callback need not be thread-safe.
      if (stop || (aborted && omp_get_thread_num() == 0 && aborted()))
      {
        stop = true;
        continue;
      }
      scratch.resize(1);
      this->BuildNode(state, scratch, 0, subtrees[i].Begin, subtrees[i].End, subtrees[i].Bounds, nullptr, 0);
      // Local node 0 takes the reserved slot; local node j > 0 goes to at + j - 1.
      const size_t at = packed.fetch_add(scratch.size() - 1);
      auto global = [&](std::int32_t local) {
        return local == 0 ? subtrees[i].Node : static_cast<std::int32_t>(at + local - 1);
      };
      for (size_t j = 0; j < scratch.size(); ++j)
      {
        Node node = scratch[j];
        if (node.Count == 0)
        {
          node.Start = global(node.Start); // children are consecutive locally and globally
        }
        this->Nodes[global(static_cast<std::int32_t>(j))] = node;
      }
    }
  }
  if (stop)
  {
    return false;
  }
  this->Nodes.resize(packed);
  vtkMedialReleaseSpareCapacity(this->Nodes);
  // The leaf order, the ranks and each triangle's float box, from the items (before
  // CopyInLeafOrder writes the vertices over them).
  this->LeafTriangles.resize(nt);
  this->LeafRank.resize(nt);
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < nt; ++i)
  {
    const BuildItem& item = state.Items[i];
    LeafTriangle& leaf = this->LeafTriangles[i];
    leaf.Triangle = item.Triangle;
    this->LeafRank[item.Triangle] = static_cast<std::int32_t>(i);
    for (int k = 0; k < 3; ++k)
    {
      leaf.Lo[k] = Down(item.Lo[k] - this->Origin[k], this->RoundingPad);
      leaf.Hi[k] = Up(item.Hi[k] - this->Origin[k], this->RoundingPad);
    }
  }
  return true;
}

// The triangles' vertices and planes in leaf order, gathered from the mesh; the
// vertices as floats when every coordinate is one.
void vtkMedialTriangleBVH::CopyInLeafOrder(const vtkMedialTriangleMesh& mesh)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  const vtkIdType coordinates = 3 * mesh.GetNumberOfPoints();
  bool floats = true;
#pragma omp parallel for schedule(static) reduction(&& : floats)
  for (vtkIdType i = 0; i < coordinates; ++i)
  {
    floats = floats && static_cast<double>(static_cast<float>(mesh.Points[i])) == mesh.Points[i];
  }
  this->FloatCorners = floats;
  // Over the build items, read by now (9 floats take the first 36 bytes of each item's 80).
  float* floatCorners = reinterpret_cast<float*>(this->Vertices.data());
  if (!floats)
  {
    this->Vertices.resize(9 * static_cast<size_t>(nt));
  }
  this->SliverBits.assign((static_cast<size_t>(nt) + 63) / 64, 0);
  // Gathers from all over the mesh: each slot's triangle is fetched ahead (its corners and
  // normal a little less far ahead, once its vertex ids are in).
  constexpr vtkIdType Ahead = 16;
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < nt; ++i)
  {
    if (i + 2 * Ahead < nt)
    {
      vtkMedialPrefetch(mesh.GetTriangle(this->LeafTriangles[i + 2 * Ahead].Triangle));
    }
    if (i + Ahead < nt)
    {
      const vtkIdType ahead = this->LeafTriangles[i + Ahead].Triangle;
      const vtkIdType* w = mesh.GetTriangle(ahead);
      vtkMedialPrefetch(mesh.GetNormal(ahead));
      vtkMedialPrefetch(mesh.GetPoint(w[0]));
      vtkMedialPrefetch(mesh.GetPoint(w[1]));
      vtkMedialPrefetch(mesh.GetPoint(w[2]));
    }
    LeafTriangle& leaf = this->LeafTriangles[i];
    const vtkIdType* v = mesh.GetTriangle(leaf.Triangle);
    const double* normal = mesh.GetNormal(leaf.Triangle);
    std::copy_n(normal, 3, leaf.Plane);
    leaf.Plane[3] = G::Dot(normal, mesh.GetPoint(v[0]));
    double corners[9];
    for (int j = 0; j < 3; ++j)
    {
      std::copy_n(mesh.GetPoint(v[j]), 3, corners + 3 * j);
    }
    if (floats)
    {
      std::copy_n(corners, 9, floatCorners + 9 * i); // exact: each one is a float
    }
    else
    {
      std::copy_n(corners, 9, &this->Vertices[9 * i]);
    }
    leaf.EdgeThird = FloatAbove(static_cast<float>(G::LongestEdge2(corners, corners + 3, corners + 6) / 3.0));
    if (IsSliver(corners, corners + 3, corners + 6))
    {
      // Two threads' slots may share a word.
#pragma omp atomic
      this->SliverBits[i / 64] |= std::uint64_t(1) << (i % 64);
    }
  }
  if (floats)
  {
    this->Vertices.resize((9 * static_cast<size_t>(nt) + 1) / 2); // 9 floats a triangle
  }
  vtkMedialReleaseSpareCapacity(this->Vertices); // the build items' tail
}

int vtkMedialTriangleBVH::WideLanes(std::int32_t binary, bool root, std::int32_t lanes[4]) const
{
  // The binary root alone for wide node 0, else the node's children with the largest
  // inner one opened until there are four.
  if (root)
  {
    lanes[0] = binary;
    return 1;
  }
  auto halfArea = [&](std::int32_t b) {
    const Node& node = this->Nodes[b];
    const double lo[3] = { node.Lo[0], node.Lo[1], node.Lo[2] };
    const double hi[3] = { node.Hi[0], node.Hi[1], node.Hi[2] };
    return HalfArea(lo, hi);
  };
  const Node& node = this->Nodes[binary];
  lanes[0] = node.Start;
  lanes[1] = node.Start + 1;
  int count = 2;
  while (count < 4)
  {
    int open = -1;
    double largest = -1.0;
    for (int i = 0; i < count; ++i)
    {
      if (this->Nodes[lanes[i]].Count == 0 && halfArea(lanes[i]) > largest)
      {
        largest = halfArea(lanes[i]);
        open = i;
      }
    }
    if (open < 0)
    {
      break;
    }
    const std::int32_t left = this->Nodes[lanes[open]].Start;
    std::copy_backward(lanes + open + 1, lanes + count, lanes + count + 1);
    lanes[open] = left;
    lanes[open + 1] = left + 1;
    ++count;
  }
  return count;
}

void vtkMedialTriangleBVH::WriteWideNode(
  std::int32_t index, const std::int32_t lanes[4], int count, const vtkMedialTriangleMesh& mesh)
{
  WideNode& wide = this->WideNodes[index];
  for (int i = 0; i < 4; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      wide.Lo[k][i] = HUGE_VALF; // empty: an inverted box
      wide.Hi[k][i] = -HUGE_VALF;
      wide.Axis[k][i] = 0.0f;
    }
    wide.SlabLo[i] = wide.SlabHi[i] = 0.0f;
    wide.Child[i] = 0;
  }
  for (int i = 0; i < count; ++i)
  {
    // Each binary node is one wide node's lane at most: no other thread writes it.
    Node& node = this->Nodes[lanes[i]];
    this->MeasureSlab(node, mesh);
    for (int k = 0; k < 3; ++k)
    {
      wide.Lo[k][i] = node.Lo[k];
      wide.Hi[k][i] = node.Hi[k];
      wide.Axis[k][i] = node.Axis[k];
    }
    wide.SlabLo[i] = node.SlabLo;
    wide.SlabHi[i] = node.SlabHi;
    wide.Child[i] = node.Count > 0 ? ~(node.Start * LeafCodeScale + node.Count) : 0;
    if (node.Count > 0)
    {
      std::fill_n(&this->LeafLane[node.Start], node.Count, 4 * index + i);
    }
  }
}

std::int32_t vtkMedialTriangleBVH::WideSubtree(
  std::int32_t binary, std::int32_t first, const vtkMedialTriangleMesh& mesh, bool write)
{
  // Depth first, lane 0's subtree next: a subtree's wide nodes are stored together.
  struct Pending
  {
    std::int32_t Binary, Ref; // an inner binary node, and the lane that will hold its wide node
  };
  std::vector<Pending> stack{ { binary, -1 } };
  std::int32_t next = first;
  while (!stack.empty())
  {
    const Pending pending = stack.back();
    stack.pop_back();
    std::int32_t lanes[4];
    const int count = this->WideLanes(pending.Binary, false, lanes);
    const std::int32_t index = next++;
    if (write)
    {
      if (pending.Ref >= 0)
      {
        this->WideNodes[WideOf(pending.Ref)].Child[LaneOf(pending.Ref)] = index;
      }
      this->WriteWideNode(index, lanes, count, mesh);
    }
    for (int i = count - 1; i >= 0; --i)
    {
      if (this->Nodes[lanes[i]].Count == 0)
      {
        stack.push_back({ lanes[i], 4 * index + i });
      }
    }
  }
  return next - first;
}

bool vtkMedialTriangleBVH::BuildWideNodes(const vtkMedialTriangleMesh& mesh)
{
  this->WideNodes.clear();
  this->LeafLane.resize(this->LeafTriangles.size());
  if (this->Nodes.empty() || this->LeafTriangles.size() >= (size_t(1) << 28))
  {
    return false;
  }
  // The wide nodes are numbered depth first, lane 0's subtree next. The top levels are
  // walked in that order first; the subtrees below them are counted in parallel, which
  // places each one (a subtree's nodes are consecutive), then written in parallel.
  // Counting first also allocates the nodes once (grown by doubling, they would take
  // up to twice the memory).
  constexpr int TopDepth = 5;
  struct TopNode
  {
    std::int32_t Binary, Parent, Lane; // the parent's lane that points at it (Parent -1: none)
    bool Below;                        // the root of a subtree left to the parallel passes
    std::int32_t Index = 0, Size = 1;  // its wide node; its subtree's nodes when Below
  };
  std::vector<TopNode> top; // depth first, lane 0's subtree next
  std::function<void(std::int32_t, std::int32_t, std::int32_t, int)> walk = [&](std::int32_t binary,
                                                                          std::int32_t parent, std::int32_t lane,
                                                                          int depth) {
    const std::int32_t at = static_cast<std::int32_t>(top.size());
    top.push_back({ binary, parent, lane, depth == TopDepth });
    if (depth == TopDepth)
    {
      return;
    }
    std::int32_t lanes[4];
    const int count = this->WideLanes(binary, parent < 0, lanes);
    for (int i = 0; i < count; ++i)
    {
      if (this->Nodes[lanes[i]].Count == 0)
      {
        walk(lanes[i], at, i, depth + 1);
      }
    }
  };
  walk(0, -1, 0, 0);
  const std::int64_t tops = static_cast<std::int64_t>(top.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t t = 0; t < tops; ++t)
  {
    if (top[t].Below)
    {
      top[t].Size = this->WideSubtree(top[t].Binary, 0, mesh, false);
    }
  }
  std::int32_t total = 0;
  for (TopNode& node : top)
  {
    node.Index = total;
    total += node.Size;
  }
  this->WideNodes.resize(static_cast<size_t>(total));
  for (const TopNode& node : top)
  {
    if (!node.Below)
    {
      std::int32_t lanes[4];
      this->WriteWideNode(node.Index, lanes, this->WideLanes(node.Binary, node.Parent < 0, lanes), mesh);
    }
    if (node.Parent >= 0)
    {
      this->WideNodes[top[node.Parent].Index].Child[node.Lane] = node.Index;
    }
  }
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t t = 0; t < tops; ++t)
  {
    if (top[t].Below)
    {
      this->WideSubtree(top[t].Binary, top[t].Index, mesh, true);
    }
  }
  return true;
}

void vtkMedialTriangleBVH::BuildNode(BuildState& state, vtkMedialBuffer<Node>& nodes, std::int32_t nodeIndex,
  std::int32_t begin, std::int32_t end, const BuildBounds& bounds, std::vector<Subtree>* later,
  std::int32_t grain) const
{
  if (later && end - begin <= grain)
  {
    later->push_back({ nodeIndex, begin, end, bounds });
    return;
  }
  Node node = this->BoundNode(begin, end, bounds);
  const std::int32_t count = end - begin;
  node.Start = begin;
  node.Count = count;
  if (count <= LeafSize)
  {
    nodes[nodeIndex] = node;
    return;
  }
  BuildBounds leftBounds, rightBounds;
  const std::int32_t mid = SplitNode(state, begin, end, bounds, leftBounds, rightBounds);
  const std::int32_t left = static_cast<std::int32_t>(nodes.size());
  nodes.emplace_back();
  nodes.emplace_back();
  node.Start = left;
  node.Count = 0;
  nodes[nodeIndex] = node;
  this->BuildNode(state, nodes, left, begin, mid, leftBounds, later, grain);
  this->BuildNode(state, nodes, left + 1, mid, end, rightBounds, later, grain);
}

vtkMedialTriangleBVH::BuildBounds vtkMedialTriangleBVH::MeasureBounds(
  const BuildState& state, std::int32_t begin, std::int32_t end)
{
  BuildBounds bounds = EmptyBounds();
  FoldRange(
    begin, end, bounds,
    [&](BuildBounds& part, std::int32_t i) {
      WidenByItem(part, state.Items[i]);
    },
    MergeBounds, EmptyBounds());
  return bounds;
}

vtkMedialTriangleBVH::Node vtkMedialTriangleBVH::BoundNode(
  std::int32_t begin, std::int32_t end, const BuildBounds& bounds) const
{
  // The box from `bounds`; the slab is measured later, and only for the nodes that a
  // wide node holds (MeasureSlab).
  Node node{};
  for (int k = 0; k < 3; ++k)
  {
    node.Lo[k] = Down(bounds.Lo[k] - this->Origin[k], this->RoundingPad);
    node.Hi[k] = Up(bounds.Hi[k] - this->Origin[k], this->RoundingPad);
  }
  node.Begin = begin;
  node.End = end;
  return node;
}

void vtkMedialTriangleBVH::MeasureSlab(Node& node, const vtkMedialTriangleMesh& mesh) const
{
  // The slab along the area-weighted mean normal, from the leaf-order copies (read in
  // sequence; the normals are the planes' own). Large nodes are never culled by a
  // slab (their boxes decide), so they skip it.
  if (node.End - node.Begin > SlabMaximumTriangles)
  {
    return;
  }
  double area[3] = { 0, 0, 0 }, totalArea = 0.0;
  for (std::int32_t i = node.Begin; i < node.End; ++i)
  {
    const LeafTriangle& leaf = this->LeafTriangles[i];
    const double a = mesh.Areas[leaf.Triangle];
    totalArea += a;
    for (int k = 0; k < 3; ++k)
    {
      area[k] += a * leaf.Plane[k];
    }
  }
  // Skipped when the normals (nearly) cancel out.
  const double areaNorm = std::sqrt(G::Dot(area, area));
  if (!(areaNorm > 0.25 * totalArea && areaNorm > 0.0))
  {
    return;
  }
  // The slab is measured along the axis as stored (float), so it bounds exactly that.
  double axis[3];
  for (int k = 0; k < 3; ++k)
  {
    node.Axis[k] = static_cast<float>(area[k] / areaNorm);
    axis[k] = node.Axis[k];
  }
  double slabLo = HUGE_VAL, slabHi = -HUGE_VAL;
  for (std::int32_t slot = node.Begin; slot < node.End; ++slot)
  {
    double scratch[9];
    const double* corners = this->Corners(slot, scratch);
    for (const double* v = corners; v < corners + 9; v += 3)
    {
      double x[3];
      G::Sub(v, this->Origin, x);
      const double m = G::Dot(axis, x);
      slabLo = std::min(slabLo, m);
      slabHi = std::max(slabHi, m);
    }
  }
  node.SlabLo = Down(slabLo, this->RoundingPad);
  node.SlabHi = Up(slabHi, this->RoundingPad);
}

std::int32_t vtkMedialTriangleBVH::SplitNode(BuildState& state, std::int32_t begin, std::int32_t end,
  const BuildBounds& bounds, BuildBounds& leftBounds, BuildBounds& rightBounds)
{
  // Binned SAH along the widest centroid axis.
  BuildItem* items = state.Items;
  const double* cLo = bounds.CLo;
  const double* cHi = bounds.CHi;
  const std::int32_t count = end - begin;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (cHi[k] - cLo[k] > cHi[axis] - cLo[axis])
    {
      axis = k;
    }
  }
  std::int32_t mid = begin + count / 2;
  bool binnedSplit = false;
  const double extent = cHi[axis] - cLo[axis];
  if (extent > 0.0)
  {
    const double scale = Bins / extent;
    auto binOf = [&](const BuildItem& item) {
      return std::min(Bins - 1, static_cast<int>((item.Centroid[axis] - cLo[axis]) * scale));
    };
    struct Binned
    {
      SahBin Bin[Bins];
    } binned;
    FoldRange(
      begin, end, binned,
      [&](Binned& part, std::int32_t i) {
        SahBin& bin = part.Bin[binOf(items[i])];
        ++bin.Count;
        WidenByItem(bin.Bounds, items[i]);
      },
      [](Binned& whole, const Binned& part) {
        for (int j = 0; j < Bins; ++j)
        {
          whole.Bin[j].Count += part.Bin[j].Count;
          MergeBounds(whole.Bin[j].Bounds, part.Bin[j].Bounds);
        }
      },
      Binned{});
    const SahBin* bins = binned.Bin;
    const int bestSplit = CheapestSplit(bins, count);
    if (bestSplit >= 0)
    {
      auto leftOfSplit = [&](const BuildItem& item) { return binOf(item) <= bestSplit; };
      mid = static_cast<std::int32_t>(
        (count > ParallelPartitionRange ? PartitionItemsInParallel(items + begin, items + end, leftOfSplit)
                               : PartitionItems(items + begin, items + end, leftOfSplit)) -
        items);
      leftBounds = rightBounds = EmptyBounds();
      for (int j = 0; j < Bins; ++j)
      {
        MergeBounds(j <= bestSplit ? leftBounds : rightBounds, bins[j].Bounds);
      }
      binnedSplit = mid > begin && mid < end; // always, as the cheapest split leaves no side empty
    }
  }
  if (binnedSplit)
  {
    return mid;
  }
  if (mid <= begin || mid >= end)
  {
    // All centroids in one bin: split at the median, ties broken by id (deterministic).
    mid = begin + count / 2;
    std::nth_element(items + begin, items + mid, items + end,
      [&](const BuildItem& a, const BuildItem& b) {
        const double ca = a.Centroid[axis], cb = b.Centroid[axis];
        return ca < cb || (ca == cb && a.Triangle < b.Triangle);
      });
  }
  leftBounds = MeasureBounds(state, begin, mid);
  rightBounds = MeasureBounds(state, mid, end);
  return mid;
}

// The one-pass search of MaximalTangentBall: the shrinking ball and its culling
// state, with the passes ShrinkOn (one triangle), Traverse (a subtree), InscribeInCap
// and Run.
class vtkMedialTriangleBVH::TangentSearch
{
public:
  TangentSearch(const vtkMedialTriangleBVH& bvh, const double p[3], const double n[3], vtkIdType ownTriangle,
    double cosMinAngle, double slack, double allowed, TangentBall& result)
    : Tree(bvh)
    , P(p)
    , N(n)
    , OwnTriangle(ownTriangle)
    , CosMinAngle(cosMinAngle)
    , Slack(slack)
    , Capped(cosMinAngle < 1.0)
    , Lift(1.0 - cosMinAngle)                                      // admissible: n.(q - p) >= r * lift
    , ConeSin(cosMinAngle < 1.0 ? std::sqrt(0.5 * (1.0 - cosMinAngle)) : 0.0) // sin(theta / 2)
    , Allowed(allowed)
    , Inscribe(cosMinAngle < 1.0 && allowed < result.Radius)
    , Measure(cosMinAngle < 1.0 && result.MeasureProtrusion)
    , CollectCap(this->Inscribe || (this->Measure && result.LargestProtrusion < result.Radius))
    , Spheres(bvh.UseInnerSpheres && !bvh.WideSpheres.empty())
    , Radius(result.Radius)
    , Result(result)
    , Work(ThreadScratch())
  {
    result.Visited = 0;
    G::AddScaled(p, this->Radius, n, this->Centre);
    // The same two points relative to the origin, for the node bounds.
    G::Sub(p, bvh.Origin, this->PRel);
    G::AddScaled(this->PRel, this->Radius, n, this->CentreRel);
    this->Fast.emplace(bvh.Nodes[0], this->PRel, n, this->ConeSin);
    this->FastFollowsBall();
    this->Clear2 = this->ClearOf(this->Radius - this->Slack);
    this->ClearAll2 = this->ClearOf(this->Radius);
  }

  // First a nearby ball's blockers in the order they shrank it: a neighbour's ball
  // came down from its ray's bound through them, and this one usually can too (the
  // ray's far hit alone rarely blocks: the far wall mostly faces p). Then the leaf of
  // the hinted triangle (a neighbour's contact): on smooth meshes the final contact
  // is often near, and a ball that is small early culls most of the rest of the
  // tree. (Larger seed subtrees, or seeds at the far hit and at p, cost more than
  // they save.) Then the whole tree without that leaf. Then the triangles that only
  // reached into the cap, and the lanes that lay wholly below the cap's plane (which a
  // smaller ball lowers: most never rise above it), until the radius settles. Last,
  // with an allowed protrusion, the cap's surface set aside on the way.
  void Run()
  {
    const BlockerChain replay = this->Result.Blockers;
    this->Result.Blockers.Count = 0;
    for (int i = 0; i < replay.Count; ++i)
    {
      this->Visit(this->Tree.LeafRank[replay.Triangles[i]]);
    }
    std::int32_t seed = -1;
    if (this->Result.HintTriangle >= 0)
    {
      seed = this->Tree.LeafLane[this->Tree.LeafRank[this->Result.HintTriangle]];
      this->Traverse(seed, -1);
    }
    this->Traverse(0, seed);
    // A triangle set aside needs another look only if the ball shrank since its last one;
    // a lane set aside below the cap's plane, once the plane has come down past its top.
    std::vector<std::int32_t>& lookedAt = this->Work.DeferredSteps;
    std::vector<float>& lowTop = this->Work.LowHeights;
    constexpr float Walked = -HUGE_VALF;
    for (bool changed = true; changed;)
    {
      changed = false;
      for (size_t i = 0; i < this->Work.Deferred.size(); ++i)
      {
        if (lookedAt[i] != this->Result.Steps)
        {
          const double before = this->Radius;
          this->ShrinkOn(this->Work.Deferred[i]);
          lookedAt[i] = this->Result.Steps;
          changed = changed || this->Radius < before;
        }
      }
      for (size_t i = 0; i < this->Work.LowNodes.size(); ++i) // grows as lanes are walked
      {
        if (lowTop[i] != Walked && !(lowTop[i] < this->Fast->GetCapPlane()))
        {
          lowTop[i] = Walked;
          const double before = this->Radius;
          this->Traverse(this->Work.LowNodes[i], -1);
          changed = changed || this->Radius < before;
        }
      }
    }
    if (this->CollectCap)
    {
      // Below the final cap's plane: only cap surface there.
      for (size_t i = 0; i < this->Work.LowNodes.size(); ++i)
      {
        if (lowTop[i] != Walked)
        {
          this->Work.CapNodes.push_back(this->Work.LowNodes[i]);
        }
      }
    }
    this->Result.Radius = this->Radius;
    const bool shrink = this->Inscribe && this->Allowed < this->Radius;
    const bool measure = this->Measure && this->Result.LargestProtrusion < this->Radius;
    if (shrink || measure)
    {
      this->InscribeInCap(shrink, measure);
    }
  }

private:
  // Closest admissible point q of triangle (a, b, c) strictly inside the ball of
  // radius r; `touches` tells whether any part of it is inside. With `gap`, also the
  // distance from the centre to the point it decided on minus (r - slack): negative
  // when it blocks, a lower bound of the admissible part's gap otherwise.
  bool Blocks(const double* a, const double* b, const double* c, double r, double q[3], bool& touches,
    double* gap = nullptr) const
  {
    const double limit = r - this->Slack;
    touches = false;
    if (!(limit > 0.0))
    {
      if (gap)
      {
        *gap = HUGE_VAL;
      }
      return false;
    }
    double x[3], u[3];
    G::AddScaled(this->P, r, this->N, x);
    double d2 = G::ClosestPointOnTriangle(x, a, b, c, q);
    touches = d2 < limit * limit;
    G::Sub(q, this->P, u);
    bool blocks = touches;
    if (touches && this->Capped && G::Dot(this->N, u) < r * this->Lift)
    {
      // The closest point is in the cap: the closest admissible point instead, in the
      // half-space (q - x).(p - x) <= r^2 cos(theta), written as w.q <= k.
      const double w[3] = { -r * this->N[0], -r * this->N[1], -r * this->N[2] };
      const double k = G::Dot(w, x) + r * r * this->CosMinAngle;
      d2 = G::ClosestPointOnClippedTriangle(x, a, b, c, w, k, q);
      blocks = d2 < limit * limit;
    }
    if (gap)
    {
      *gap = std::sqrt(d2) - limit;
    }
    return blocks;
  }

  // The triangle reaches into the ball only below the cap's plane. A smaller ball
  // lowers that plane, so it is looked at again at the end (it is inside the cone,
  // or it would not have got this far).
  bool InCap(bool touches) const { return this->Capped && touches; }

  // The float tests follow the current ball and, with theta > 0, its cap's plane.
  void FastFollowsBall()
  {
    this->Fast->SetBall(this->CentreRel, this->Radius);
    if (this->Capped)
    {
      this->Fast->SetCapPlane(this->Radius * this->Lift);
    }
  }

  void Accept(double r, const double q[3], std::int32_t slot)
  {
    this->Radius = r;
    this->Clear2 = this->ClearOf(r - this->Slack);
    this->ClearAll2 = this->ClearOf(r);
    G::AddScaled(this->P, this->Radius, this->N, this->Centre);
    G::AddScaled(this->PRel, this->Radius, this->N, this->CentreRel);
    this->FastFollowsBall();
    G::Copy(q, this->Result.Contact);
    this->Result.ContactTriangle = this->Tree.LeafTriangles[slot].Triangle;
    this->Result.Blockers.Add(this->Result.ContactTriangle);
    ++this->Result.Steps;
  }

  // The triangle at `slot` cannot block this ball or any smaller one: the ball misses
  // its box or its plane, it lies wholly outside the ball by its distance bound `below`
  // (Distance2Below), or it lies outside the cone where blockers can lie. This drops the
  // cap's triangles around p (kept aside for InscribeInCap). The box goes first (in
  // float; on the 1.55 M horse it dropped 4 times what the plane did), the side of the
  // cone last: of the triangles that got that far, 1 in 1000 was not in the cone.
  // A triangle outside the ball is outside every smaller one, the final one included, so
  // InscribeInCap needs only those that reach into it (the same ones, in the same order).
  bool CannotBlock(std::int32_t slot, double& below) const
  {
    const LeafTriangle& leaf = this->Tree.LeafTriangles[slot];
    if (this->Fast->BoxMissesBall(leaf.Lo, leaf.Hi))
    {
      return true;
    }
    if (std::fabs(G::Dot(leaf.Plane, this->Centre) - leaf.Plane[3]) >= this->Radius)
    {
      return true;
    }
    below = this->Distance2Below(slot);
    if (below >= this->ClearAll2)
    {
      return true;
    }
    const FloatNodeTests::Sides side = this->Fast->Side(leaf.Lo, leaf.Hi);
    if (side == FloatNodeTests::OUTSIDE_CONE && this->CollectCap)
    {
      this->Work.CapSlots.push_back(slot); // it may cross the final ball in the cap
    }
    return side != FloatNodeTests::ABOVE;
  }

  // vtkMedialGeometry::TriangleDistance2Below of the triangle at `slot` from the centre,
  // with the edge term stored rounded up: never above it, so a skip it allows is sound.
  double Distance2Below(std::int32_t slot) const
  {
    double scratch[9];
    const double* a = this->Tree.Corners(slot, scratch);
    return G::NearestVertexDistance2(this->Centre, a, a + 3, a + 6) - this->Tree.LeafTriangles[slot].EdgeThird;
  }

  // reach^2 and room for the rounding of an exact squared distance, whose closest
  // point is off by a few ulps of the coordinates (RoundingPad is 1e-14 of them): a
  // triangle whose TriangleDistance2Below reaches this is beyond `reach` for the
  // exact test too, so skipping that test changes no decision.
  double ClearOf(double reach) const
  {
    return reach * reach * (1.0 + 1e-9) + 10.0 * this->Tree.RoundingPad * std::fabs(reach);
  }

  // Shrinks the ball on triangle `slot` until it no longer blocks. Returns true
  // when the triangle still reaches into the ball, but only inside the cap: a
  // smaller ball lowers the cap's plane, so it must be looked at again.
  bool ShrinkOn(std::int32_t slot)
  {
    // The quick tests, then the distance bound against the ball less the slack: most
    // triangles stop before ShrinkWhileBlocked, so this part is inlined into the walk.
    double below;
    return !this->CannotBlock(slot, below) && !(below >= this->Clear2) && this->ShrinkWhileBlocked(slot);
  }

  // All three vertices (so the whole triangle) lie below the plane of the cap at the
  // current radius, n.(q - p) < r (1 - cos theta), where no point is admissible; with
  // room for the rounding of the heights, so that a triangle near the plane is left to
  // Blocks.
  bool BelowCapPlane(const double* a, const double* b, const double* c) const
  {
    const double plane = this->Radius * this->Lift;
    double top = -HUGE_VAL, size = 0.0;
    for (const double* v : { a, b, c })
    {
      double u[3];
      G::Sub(v, this->P, u);
      top = std::max(top, G::Dot(this->N, u));
      size = std::max({ size, std::fabs(u[0]), std::fabs(u[1]), std::fabs(u[2]) });
    }
    return top < plane - 1e-12 * (size + plane) - 4.0 * this->Tree.RoundingPad;
  }

  // ShrinkOn past the quick tests.
  bool ShrinkWhileBlocked(std::int32_t slot)
  {
    double scratch[9];
    const double* a = this->Tree.Corners(slot, scratch);
    const double* b = a + 3;
    const double* c = a + 6;
    if (this->Capped && this->BelowCapPlane(a, b, c))
    {
      return true; // wholly in the cap at this radius: only a smaller ball can see it
    }
    double q[3];
    bool touches;
    for (int step = 0; step < StepsBeforeBracketing; ++step)
    {
      if (!this->Blocks(a, b, c, this->Radius, q, touches))
      {
        return this->InCap(touches);
      }
      double u[3];
      G::Sub(q, this->P, u);
      const double along = G::Dot(this->N, u);
      double next = along > 0.0 ? G::Dot(u, u) / (2.0 * along) : HUGE_VAL;
      TangentCandidates(this->P, this->N, a, b, c, this->Lift, this->Radius, this->Slack, next, q);
      if (!(next < this->Radius))
      {
        return this->InCap(touches); // no progress left at double precision
      }
      this->Accept(next, q, slot);
    }
    double gap;
    if (!this->Blocks(a, b, c, this->Radius, q, touches, &gap))
    {
      return this->InCap(touches);
    }
    // Still blocking: the ball is converging (linearly) onto the point where the
    // triangle crosses the cap's cone. For one triangle the blocked radii form an
    // interval that contains the current radius, so a bracket below it is exact.
    this->Accept(this->LowerEndOfBlocking(a, b, c, gap, q), q, slot);
    this->Blocks(a, b, c, this->Radius, q, touches);
    return this->InCap(touches);
  }

  // The lower end of the radii the triangle blocks below the current (blocked) radius,
  // to 4 ulps: a bracket [lo, hi] with lo free and hi blocked, narrowed by regula falsi
  // on the signed gap of Blocks (Illinois: the end kept twice in a row has its gap
  // halved), with a bisection step whenever an interpolation step did not halve the
  // bracket. The decision at each radius is Blocks' own, so the result is where its
  // answer changes; the gap only chooses where to look. On entry `point` and `gapHi`
  // are Blocks' answer at the current radius; on return `point` is the blocking point
  // at hi.
  double LowerEndOfBlocking(
    const double* a, const double* b, const double* c, double gapHi, double point[3]) const
  {
    double lo = 0.0, hi = this->Radius, gapLo = HUGE_VAL, q[3];
    bool touches;
    int kept = 0; // +1: the last step kept lo, -1: it kept hi
    bool interpolated = false;
    double width = hi - lo;
    for (int i = 0; i < 100 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++i)
    {
      double x = 0.5 * (lo + hi);
      const bool falsi = std::isfinite(gapLo) && gapLo > 0.0 && gapHi < 0.0 &&
        !(interpolated && hi - lo > 0.5 * width);
      if (falsi)
      {
        const double t = lo + (hi - lo) * (gapLo / (gapLo - gapHi));
        x = t > lo && t < hi ? t : x;
      }
      width = hi - lo;
      interpolated = falsi;
      double gap;
      if (this->Blocks(a, b, c, x, q, touches, &gap))
      {
        hi = x;
        gapHi = gap;
        G::Copy(q, point);
        gapLo *= kept == +1 ? 0.5 : 1.0;
        kept = +1;
      }
      else
      {
        lo = x;
        gapLo = gap;
        gapHi *= kept == -1 ? 0.5 : 1.0;
        kept = -1;
      }
    }
    return lo;
  }

  // Shrinks on the triangle at `slot` (not p's own); one that reaches into the ball
  // only in the cap is set aside for another look.
  void Visit(std::int32_t slot)
  {
    ++this->Result.Visited;
    if (this->Tree.LeafTriangles[slot].Triangle != this->OwnTriangle && this->ShrinkOn(slot))
    {
      this->Work.Deferred.push_back(slot);
      this->Work.DeferredSteps.push_back(this->Result.Steps);
    }
  }

  // The lanes among `within` (bit i: lane i) of wide node `index` that may hold
  // blockers of the current ball, their distances in `d2`. Lanes dropped for the cone
  // only are kept aside for InscribeInCap.
  int OpenLanes(std::int32_t index, float d2[4], int within = 0xF) const
  {
    FloatNodeTests::Lanes lanes;
    const WideNode& wide = this->Tree.WideNodes[index];
    this->Fast->TestLanes(wide, lanes);
    if (this->SpheresOn())
    {
      this->DropCleared(wide, within, lanes);
    }
    if ((lanes.Cap & within) && this->CollectCap)
    {
      for (int i = 0; i < 4; ++i)
      {
        if (lanes.Cap & within & (1 << i))
        {
          this->Work.CapNodes.push_back(4 * index + i); // it may cross the final ball in the cap
        }
      }
    }
    // In the cone but wholly below the cap's plane: nothing there blocks this ball. Run
    // walks it once the plane has come down past its top, or hands it to InscribeInCap.
    const int low = lanes.Low & within;
    for (int i = 0; low && i < 4; ++i)
    {
      if (low & (1 << i))
      {
        this->Work.LowNodes.push_back(4 * index + i);
        this->Work.LowHeights.push_back(lanes.H[i]);
      }
    }
    std::copy_n(lanes.D2, 4, d2);
    return lanes.Keep & ~low & within;
  }

  // After a few triangles (a search that culls well never gets there and pays nothing),
  // inner lanes are also tested against their subtree's inner sphere.
  bool SpheresOn() const { return this->Spheres && this->Result.Visited >= SpheresAfter; }

  // Nothing under lane `lane` of `holder` (whose child is wide node `child`) comes
  // within the current radius of the centre, by its inner sphere: none of its triangles
  // could block this ball or a smaller one (each lies inside this one), or lie in the
  // final ball for InscribeInCap, so dropping the lane changes nothing but the cost.
  // (With room for the rounding of an exact distance, as ClearOf.)
  bool SphereClears(const WideNode& holder, int lane, std::int32_t child) const
  {
    return this->Tree.SphereDistance2Below(holder, lane, child, this->CentreRel) >= this->ClearOf(this->Radius);
  }

  // The inner lanes among `within` that OpenLanes would keep or set aside, dropped where
  // their sphere clears the ball. (Out of line: most searches never get here.)
#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  void DropCleared(const WideNode& wide, int within, FloatNodeTests::Lanes& lanes) const
  {
    const int open = (lanes.Keep | lanes.Cap) & within;
    for (int i = 0; i < 4; ++i)
    {
      if ((open & (1 << i)) && wide.Child[i] > 0 && this->SphereClears(wide, i, wide.Child[i]))
      {
        lanes.Keep &= ~(1 << i);
        lanes.Cap &= ~(1 << i);
        lanes.Low &= ~(1 << i);
      }
    }
  }

  // Depth first, nearer lane first, from lane `root` without lane `skip`. A wide
  // node's lanes are tested in full when it is opened and pushed with the number of
  // radius updates so far; when popped after the ball has shrunk, the lane's box and
  // slab are tested again (its side of the cone does not change with the radius).
  void Traverse(std::int32_t root, std::int32_t skip)
  {
    const vtkMedialBuffer<WideNode>& wides = this->Tree.WideNodes;
    std::vector<PendingLane>& stack = this->Work.Lanes;
    float d2[4];
    if (!this->OpenLanes(WideOf(root), d2, 1 << LaneOf(root)))
    {
      return;
    }
    size_t top = 0;
    if (stack.size() < 64)
    {
      stack.resize(64);
    }
    stack[top++] = { root, this->Result.Steps };
    while (top > 0)
    {
      const std::int32_t ref = stack[--top].Ref;
      const bool shrunk = stack[top].Steps != this->Result.Steps;
      if (ref == skip)
      {
        continue;
      }
      const WideNode& holder = wides[WideOf(ref)];
      const int lane = LaneOf(ref);
      // Only this lane's box and slab, as TestLanes' Miss would test them (the same
      // float sums in the same order, so the same decision).
      if (shrunk && this->Fast->LaneMissesBall(holder, lane))
      {
        continue;
      }
      const std::int32_t child = holder.Child[lane];
      if (child < 0)
      {
        const LeafSlots leaf(child);
        for (std::int32_t slot = leaf.Start; slot < leaf.End; ++slot)
        {
          this->Visit(slot);
        }
        continue;
      }
      if (shrunk && this->SpheresOn() && this->SphereClears(holder, lane, child))
      {
        continue;
      }
      const int keep = this->OpenLanes(child, d2);
      // Nearest lane on top: push the others first.
      int order[4];
      const int count = NearestFirst(keep, d2, order);
      if (top + 4 > stack.size())
      {
        stack.resize(2 * stack.size());
      }
      for (int j = count - 1; j >= 0; --j)
      {
        stack[top++] = { 4 * child + order[j], this->Result.Steps };
      }
    }
  }

  // The surface of the cap that the angle rule ignored: only what the traversal dropped
  // for the cone (CapNodes, CapSlots) or set aside as reaching into the ball in the cap
  // only (Deferred) can lie inside the final ball, which is inside every earlier one.
  // With `shrink`, its closest point within Radius - Allowed of the centre, if any, is
  // where the inscribed ball about the same centre touches. With `measure`, the search
  // reaches to Radius - LargestProtrusion, and a closest point found there (and not
  // shrunk to) is this ball's protrusion. The triangles are tried in the same order
  // whatever the reach (a farther reach only culls less), so the first of the closest
  // ones, the point reported, is the same with or without measuring.
  void InscribeInCap(bool shrink, bool measure)
  {
    // The cap: (q - c).(p - c) >= r^2 cos(theta), as w.q <= k for the clipping.
    double w[3];
    G::Sub(this->Centre, this->P, w);
    const double k = G::Dot(w, this->Centre) - this->Radius * this->Radius * this->CosMinAngle;
    const double shrinkReach = shrink ? this->Radius - this->Allowed : 0.0;
    const double reach =
      measure ? std::max(shrinkReach, this->Radius - this->Result.LargestProtrusion) : shrinkReach;
    double best2 = reach * reach, best[3] = { 0, 0, 0 };
    double clear2 = this->ClearOf(reach); // follows best2
    std::int32_t bestSlot = -1;
    auto test = [&](std::int32_t slot) -> bool {
      const LeafTriangle& leaf = this->Tree.LeafTriangles[slot];
      const double off = G::Dot(leaf.Plane, this->Centre) - leaf.Plane[3];
      if (leaf.Triangle == this->OwnTriangle || off * off >= best2)
      {
        return false;
      }
      double scratch[9];
      const double* a = this->Tree.Corners(slot, scratch);
      double q[3];
      if (G::NearestVertexDistance2(this->Centre, a, a + 3, a + 6) - leaf.EdgeThird >= clear2 ||
        G::ClosestPointOnTriangle(this->Centre, a, a + 3, a + 6, q) >= best2)
      {
        return false; // the whole triangle is no closer than its part in the cap
      }
      const double d2 = G::ClosestPointOnClippedTriangle(this->Centre, a, a + 3, a + 6, w, k, q);
      if (d2 < best2)
      {
        best2 = d2;
        clear2 = this->ClearOf(std::sqrt(d2));
        G::Copy(q, best);
        bestSlot = slot;
        return true;
      }
      return false;
    };
    if (this->Result.Blockers.Deepest >= 0)
    {
      test(this->Tree.LeafRank[this->Result.Blockers.Deepest]);
    }
    for (const std::vector<std::int32_t>* slots : { &this->Work.CapSlots, &this->Work.Deferred })
    {
      for (std::int32_t slot : *slots)
      {
        test(slot);
      }
    }
    // Depth first from each lane set aside. A wide node's four lanes are tested at once
    // (in float, conservatively) when it is opened; a lane is tested again in double
    // when popped only if the reach shrank since it was pushed (Steps counts that).
    int shrinks = 0;
    const bool spheres = this->SpheresOn();
    this->Fast->SetBall(this->CentreRel, std::sqrt(best2));
    std::vector<PendingLane>& stack = this->Work.CapLanes;
    // (The root goes in without a trip through the stack, and a lane is read from it
    // field by field: an 8-byte load of two fresh 4-byte stores cannot be forwarded.)
    for (std::int32_t root : this->Work.CapNodes)
    {
      std::int32_t ref = root, steps = -1; // tested against an earlier, larger ball
      for (bool first = true; first || !stack.empty(); first = false)
      {
        if (!first)
        {
          ref = stack.back().Ref;
          steps = stack.back().Steps;
          stack.pop_back();
        }
        const WideNode& holder = this->Tree.WideNodes[WideOf(ref)];
        const int lane = LaneOf(ref);
        if (steps != shrinks)
        {
          // In float, as the children's tests (Fast follows best2): a looser test, never a wrong drop.
          if (this->Fast->LaneMissesBall(holder, lane))
          {
            continue;
          }
        }
        const std::int32_t child = holder.Child[lane];
        // The subtree's inner sphere: in a finely tessellated sphere the cap's facets
        // are all about as far from the centre, and no box keeps them out.
        if (spheres && child > 0 &&
          !(this->Tree.SphereDistance2Below(holder, lane, child, this->CentreRel) < clear2))
        {
          continue;
        }
        if (child < 0)
        {
          const LeafSlots leaf(child);
          for (std::int32_t slot = leaf.Start; slot < leaf.End; ++slot)
          {
            if (test(slot))
            {
              ++shrinks;
              this->Fast->SetBall(this->CentreRel, std::sqrt(best2));
            }
          }
          continue;
        }
        const WideNode& wide = this->Tree.WideNodes[child];
        FloatNodeTests::Lanes lanes;
        this->Fast->TestLanes(wide, lanes);
        for (int i = 3; i >= 0; --i)
        {
          if (!(lanes.Miss & (1 << i)) && wide.Lo[0][i] <= wide.Hi[0][i]) // not empty
          {
            stack.push_back({ 4 * child + i, shrinks });
          }
        }
      }
    }
    if (bestSlot >= 0 && shrink && best2 < shrinkReach * shrinkReach)
    {
      this->Result.Shrunk = true; // and then it only touches: no protrusion
      this->Result.InscribedRadius = std::sqrt(best2);
      std::copy(best, best + 3, this->Result.InscribedContact);
      this->Result.InscribedTriangle = this->Tree.LeafTriangles[bestSlot].Triangle;
      this->Result.Blockers.Deepest = this->Result.InscribedTriangle;
    }
    else if (bestSlot >= 0)
    {
      this->Result.LargestProtrusion = std::max(this->Result.LargestProtrusion, this->Radius - std::sqrt(best2));
    }
  }

  const vtkMedialTriangleBVH& Tree;
  const double* P;
  const double* N;
  const vtkIdType OwnTriangle;
  const double CosMinAngle, Slack;
  const bool Capped;
  const double Lift, ConeSin;
  const double Allowed;
  const bool Inscribe;   // a ball the cap enters deeper than Allowed is shrunk
  const bool Measure;    // the ball's protrusion raises Result.LargestProtrusion
  const bool CollectCap; // the cap's surface is set aside for InscribeInCap
  const bool Spheres;    // the tree's inner spheres may drop lanes
  double Radius;
  double Clear2;    // ClearOf(Radius - Slack)
  double ClearAll2; // ClearOf(Radius): a triangle whose Distance2Below reaches it is outside the ball
  double Centre[3], PRel[3], CentreRel[3];
  TangentBall& Result;
  Scratch& Work;
  std::optional<FloatNodeTests> Fast; // follows Centre and Radius
};

void vtkMedialTriangleBVH::MaximalTangentBall(const double p[3], const double n[3],
  vtkIdType ownTriangle, double cosMinAngle, double slack, double allowed, TangentBall& result) const
{
  TangentSearch(*this, p, n, ownTriangle, cosMinAngle, slack, allowed, result).Run();
}

double vtkMedialTriangleBVH::Extent() const
{
  double extent = 0.0;
  for (int k = 0; k < 3 && !this->Nodes.empty(); ++k)
  {
    extent = std::max({ extent, std::fabs(static_cast<double>(this->Nodes[0].Lo[k])),
      std::fabs(static_cast<double>(this->Nodes[0].Hi[k])) });
  }
  return extent;
}

namespace
{
// A lane waiting in a wide walk: its child code and its key (a ray's entry, a
// ball's squared box distance), for skipping it once the query has narrowed.
struct WaitingLane
{
  std::int32_t Child;
  float Key;
};

// The waiting lanes of one walk: on the stack while they fit (a walk holds at most
// three lanes per level of the wide tree), on the heap beyond. Saves the walk the
// thread-local vector's lookup and its growth checks.
class LaneStack
{
public:
  bool empty() const { return this->Size == 0; }
  const WaitingLane& back() const { return this->Size <= Inline ? this->Near[this->Size - 1] : this->Far.back(); }
  void pop_back()
  {
    if (this->Size-- > Inline)
    {
      this->Far.pop_back();
    }
  }
  void push_back(const WaitingLane& lane)
  {
    if (this->Size < Inline)
    {
      this->Near[this->Size] = lane;
    }
    else
    {
      this->Far.push_back(lane);
    }
    ++this->Size;
  }

private:
  static constexpr size_t Inline = 128;
  WaitingLane Near[Inline];
  size_t Size = 0;
  std::vector<WaitingLane> Far;
};

// Pushes the lanes of `node` set in `mask` with their keys, the smallest key on top
// (ties: the lower lane), so that a depth-first walk takes the nearest first.
template <class Lanes>
void PushNearestOnTop(const vtkMedialTriangleBVH::WideNode& node, int mask, const float key[4], Lanes& lanes)
{
  int order[4];
  for (int j = NearestFirst(mask, key, order) - 1; j >= 0; --j)
  {
    lanes.push_back({ node.Child[order[j]], key[order[j]] });
  }
}

#if defined(__SSE2__)
// A ball (centre relative to the tree's origin) and optionally a half-space w.q <= k
// against the four lanes of a wide node at once, in float. Every bound is widened by
// Pad (1e-5 of the tree's extent), far above the float rounding for a centre within a
// few extents: a lane is dropped only where the double tests of the binary walk would
// drop it too.
class WideBall
{
public:
  WideBall(const double centreRel[3], double extent, const double* w, double kRel)
    : Pad(static_cast<float>(1e-5 * extent))
    , HalfSpace(w != nullptr)
  {
    double w1 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      this->C[k] = _mm_set1_ps(static_cast<float>(centreRel[k]));
      this->W[k] = _mm_set1_ps(w ? static_cast<float>(w[k]) : 0.0f);
      this->Positive[k] = w && w[k] > 0.0;
      w1 += w ? std::fabs(w[k]) : 0.0;
    }
    // A box lies past the plane when w.q - k > 0 at its lowest corner; in float that
    // sum is off by a few float steps of w1 * extent + |k|, so the bound is raised by
    // 1e-6 of that (the boxes' corners are floats: no pad in space is needed).
    this->K = _mm_set1_ps(FloatAbove(static_cast<float>(kRel + 1e-6 * (w1 * extent + std::fabs(kRel)))));
  }

  // Bit i: lane i may hold points within `reach` (already widened by the pad) of the
  // centre on the kept side of the half-space; d2[i] its box's squared distance.
  int Test(const vtkMedialTriangleBVH::WideNode& n, float reach, float d2[4]) const
  {
    const __m128 zero = _mm_setzero_ps();
    __m128 sum = zero, m = zero, lowest = zero;
    for (int k = 0; k < 3; ++k)
    {
      const __m128 lo = _mm_load_ps(n.Lo[k]), hi = _mm_load_ps(n.Hi[k]);
      const __m128 g = _mm_max_ps(_mm_max_ps(_mm_sub_ps(lo, this->C[k]), _mm_sub_ps(this->C[k], hi)), zero);
      sum = _mm_add_ps(sum, _mm_mul_ps(g, g));
      m = _mm_add_ps(m, _mm_mul_ps(_mm_load_ps(n.Axis[k]), this->C[k]));
      lowest = _mm_add_ps(lowest, _mm_mul_ps(this->W[k], this->Positive[k] ? lo : hi));
    }
    _mm_store_ps(d2, sum);
    const __m128 r = _mm_set1_ps(reach);
    __m128 miss = _mm_or_ps(_mm_cmpge_ps(sum, _mm_mul_ps(r, r)),
      _mm_or_ps(_mm_cmpge_ps(_mm_sub_ps(m, r), _mm_load_ps(n.SlabHi)), _mm_cmple_ps(_mm_add_ps(m, r), _mm_load_ps(n.SlabLo))));
    if (this->HalfSpace)
    {
      miss = _mm_or_ps(miss, _mm_cmpgt_ps(lowest, this->K));
    }
    // An empty lane's box is inverted.
    miss = _mm_or_ps(miss, _mm_cmpgt_ps(_mm_load_ps(n.Lo[0]), _mm_load_ps(n.Hi[0])));
    return ~_mm_movemask_ps(miss) & 0xF;
  }

  const float Pad;

private:
  __m128 C[3], W[3], K;
  bool Positive[3];
  const bool HalfSpace;
};
#endif
}

namespace
{
// A leaf triangle that a walk of squared reach reach2 about x skips: its plane misses
// the ball, or its box does (with room for `rounding`), so its closest point would
// come out at reach2 or beyond, which no visit counts. VisitAdmissible and the walks
// read from a Nearby list share it, so that both see the same triangles.
template <class Leaf>
inline bool LeafMisses(const Leaf& leaf, const double x[3], const double xRel[3], double reach2, double rounding)
{
  const double off = G::Dot(leaf.Plane, x) - leaf.Plane[3];
  return off * off >= reach2 || BoxDistance2(leaf.Lo, leaf.Hi, xRel) >= reach2 * (1.0 + 1e-9) + rounding;
}
}

template <class Visit>
void vtkMedialTriangleBVH::VisitListed(const Nearby& nearby, const double x[3], double reach2, Visit visit) const
{
  double xRel[3];
  G::Sub(x, this->Origin, xRel);
  const double rounding = 10.0 * this->RoundingPad * std::sqrt(reach2); // as VisitAdmissible's
  for (const std::int32_t slot : nearby.Slots)
  {
    const LeafTriangle& leaf = this->LeafTriangles[slot];
    if (LeafMisses(leaf, x, xRel, reach2, rounding))
    {
      continue;
    }
    double scratch[9];
    const double* a = this->Corners(slot, scratch);
    double q[3];
    const double d2 = G::ClosestPointOnTriangle(x, a, a + 3, a + 6, q);
    if (!visit(d2, q, leaf.Triangle))
    {
      return;
    }
  }
}

template <class Visit>
void vtkMedialTriangleBVH::VisitAdmissible(const double x[3], vtkIdType ownTriangle,
  const double samplePoint[3], double cosMinAngle, bool capOnly, double& reach2, Visit visit) const
{
  // Admissible part of a triangle: (q - x).(s - x) <= |s - x|^2 cos(theta), as w.q <= k;
  // with capOnly, the other side: the cap, written as (-w).q <= -k.
  const bool capped = cosMinAngle < 1.0 && samplePoint;
  double w[3] = { 0, 0, 0 }, k = 0.0;
  if (capped)
  {
    G::Sub(samplePoint, x, w);
    k = G::Dot(w, x) + G::Dot(w, w) * cosMinAngle;
    if (capOnly)
    {
      for (double& c : w)
      {
        c = -c;
      }
      k = -k;
    }
  }
  double xRel[3]; // x relative to the origin, for the node bounds
  G::Sub(x, this->Origin, xRel);
  // A leaf's triangles, cheapest test first; false when visit asked to stop.
  auto visitLeaf = [&](std::int32_t start, std::int32_t end) {
    // Room for the rounding of an exact squared distance (as in the tangent search's
    // ClearOf), taken at the reach on entry, which only shrinks.
    const double rounding = 10.0 * this->RoundingPad * std::sqrt(reach2);
    for (std::int32_t slot = start; slot < end; ++slot)
    {
      const LeafTriangle& leaf = this->LeafTriangles[slot];
      if (leaf.Triangle == ownTriangle || LeafMisses(leaf, x, xRel, reach2, rounding))
      {
        continue;
      }
      // Then the whole triangle: cheaper, and never farther than its admissible part.
      double scratch[9];
      const double* a = this->Corners(slot, scratch);
      double q[3];
      double d2 = G::ClosestPointOnTriangle(x, a, a + 3, a + 6, q);
      if (capped && d2 < reach2)
      {
        d2 = G::ClosestPointOnClippedTriangle(x, a, a + 3, a + 6, w, k, q);
      }
      if (!visit(d2, q, leaf.Triangle))
      {
        return false;
      }
    }
    return true;
  };
#if defined(__SSE2__)
  const double extent = this->Extent();
  if (extent > 0.0 && std::fabs(xRel[0]) <= 4.0 * extent && std::fabs(xRel[1]) <= 4.0 * extent &&
    std::fabs(xRel[2]) <= 4.0 * extent && !this->WideNodes.empty())
  {
    // Four lanes at once in float, nearest box first.
    const WideBall ball(xRel, extent, capped ? w : nullptr,
      capped ? k - G::Dot(w, this->Origin) : 0.0);
    auto reach = [&]() { return FloatAbove(static_cast<float>(std::sqrt(reach2))) + ball.Pad; };
    LaneStack lanes;
    alignas(16) float d2[4];
    float r = reach();
    if (ball.Test(this->WideNodes[0], r, d2) & 1)
    {
      lanes.push_back({ this->WideNodes[0].Child[0], d2[0] });
    }
    while (!lanes.empty())
    {
      const WaitingLane lane = lanes.back();
      lanes.pop_back();
      r = reach();
      if (lane.Key >= r * r)
      {
        continue; // the reach shrank since the lane was pushed
      }
      if (lane.Child < 0)
      {
        const LeafSlots leaf(lane.Child);
        if (!visitLeaf(leaf.Start, leaf.End))
        {
          return;
        }
        continue;
      }
      const WideNode& node = this->WideNodes[lane.Child];
      const int kept = ball.Test(node, r, d2);
      PushNearestOnTop(node, kept, d2, lanes);
    }
    return;
  }
#endif
  // In double over the binary tree: far points, no SSE2.
  Scratch& scratch = ThreadScratch();
  scratch.Stack.push_back(0);
  while (!scratch.Stack.empty())
  {
    const Node& node = this->Nodes[scratch.Stack.back()];
    scratch.Stack.pop_back();
    if (MissesBall(node, xRel, std::sqrt(reach2)))
    {
      continue;
    }
    if (capped)
    {
      // The whole box on the far side of the plane w.q = k: nothing there counts.
      double lowest = G::Dot(w, this->Origin) - k; // w.q - k at the box's lowest corner
      for (int d = 0; d < 3; ++d)
      {
        lowest += w[d] * (w[d] > 0.0 ? node.Lo[d] : node.Hi[d]);
      }
      if (lowest > 0.0)
      {
        continue;
      }
    }
    if (node.Count > 0)
    {
      if (!visitLeaf(node.Start, node.Start + node.Count))
      {
        scratch.Stack.clear();
        return;
      }
      continue;
    }
    const double dl = BoxDistance2(this->Nodes[node.Start], xRel);
    const double dr = BoxDistance2(this->Nodes[node.Start + 1], xRel);
    scratch.Stack.push_back(dl <= dr ? node.Start + 1 : node.Start);
    scratch.Stack.push_back(dl <= dr ? node.Start : node.Start + 1);
  }
}

bool vtkMedialTriangleBVH::ClosestPoint(const double x[3], double upperBound,
  vtkIdType ownTriangle, const double samplePoint[3], double cosMinAngle, bool capOnly,
  double point[3], double& distance, vtkIdType& triangle) const
{
  double best2 = upperBound * upperBound;
  triangle = -1;
  this->VisitAdmissible(x, ownTriangle, samplePoint, cosMinAngle, capOnly, best2,
    [&](double d2, const double q[3], vtkIdType t) {
      if (d2 < best2)
      {
        best2 = d2; // also shrinks the traversal's reach
        G::Copy(q, point);
        triangle = t;
      }
      return true;
    });
  distance = std::sqrt(best2);
  return triangle >= 0;
}

bool vtkMedialTriangleBVH::ContainsBall(const double x[3], double radius, vtkIdType ownTriangle,
  const double samplePoint[3], double cosMinAngle, bool capOnly) const
{
  double reach2 = radius * radius;
  bool empty = true;
  this->VisitAdmissible(x, ownTriangle, samplePoint, cosMinAngle, capOnly, reach2,
    [&](double d2, const double*, vtkIdType) {
      empty = !(d2 < reach2);
      return empty; // stop at the first point inside
    });
  return empty;
}

namespace
{
// The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013) in double:
// vertices are sheared into a frame where the ray runs along +z, and the signed
// areas U, V, W of the triangle's edges seen from the ray decide. A shared edge gets
// exactly opposite values in its two triangles, so no ray slips between them.
class WatertightRay
{
public:
  WatertightRay(const double origin[3], const double direction[3])
  {
    const double ax = std::fabs(direction[0]), ay = std::fabs(direction[1]), az = std::fabs(direction[2]);
    this->Kz = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    this->Kx = (this->Kz + 1) % 3;
    this->Ky = (this->Kx + 1) % 3;
    if (direction[this->Kz] < 0.0)
    {
      std::swap(this->Kx, this->Ky); // keeps the winding
    }
    this->Sx = direction[this->Kx] / direction[this->Kz];
    this->Sy = direction[this->Ky] / direction[this->Kz];
    this->Sz = 1.0 / direction[this->Kz];
    std::copy_n(origin, 3, this->Origin);
  }

  // The ray's t at triangle (a, b, c), beyond tMin; false when it misses.
  bool Hit(const double* a, const double* b, const double* c, double tMin, double& t) const
  {
    double end;
    bool inPlane;
    if (!this->Meets(a, b, c, t, end, inPlane))
    {
      return false;
    }
    return !inPlane || FirstInSpan(t, end, tMin, t);
  }

  // Hit without its tMin: false when the ray misses; else the triangle is met at t, or,
  // when the ray runs in its plane (inPlane), anywhere in [t, end]: Hit(tMin) is then
  // FirstInSpan(t, end, tMin). For a walk that collects a whole ray's hits at once.
  bool Meets(const double* a, const double* b, const double* c, double& t, double& end, bool& inPlane) const
  {
    double A[3], B[3], C[3];
    this->Shear(a, A);
    this->Shear(b, B);
    this->Shear(c, C);
    const double u = C[0] * B[1] - C[1] * B[0];
    const double v = A[0] * C[1] - A[1] * C[0];
    const double w = B[0] * A[1] - B[1] * A[0];
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0))
    {
      return false;
    }
    const double det = u + v + w;
    inPlane = det == 0.0;
    if (inPlane)
    {
      InPlaneSpan(A, B, C, t, end);
      return end >= t;
    }
    t = (u * A[2] + v * B[2] + w * C[2]) / det;
    end = t;
    return true;
  }

  // The first t beyond tMin of a triangle met by the ray in its plane along [lo, hi].
  static bool FirstInSpan(double lo, double hi, double tMin, double& t)
  {
    if (!(hi > tMin))
    {
      return false;
    }
    t = std::max(lo, std::nextafter(tMin, HUGE_VAL));
    return true;
  }

private:
  // The ray runs in the triangle's plane (a face seen edge-on, e.g. from a box's edge
  // along the next face): it meets the triangle where the sheared triangle, a segment
  // through the axis, crosses the axis, along [lo, hi] (empty, lo > hi, when it does not).
  static void InPlaneSpan(const double A[3], const double B[3], const double C[3], double& lo, double& hi)
  {
    const double* p[3] = { A, B, C };
    int far = 0;
    for (int i = 1; i < 3; ++i)
    {
      if (std::fabs(p[i][0]) + std::fabs(p[i][1]) > std::fabs(p[far][0]) + std::fabs(p[far][1]))
      {
        far = i;
      }
    }
    double s[3]; // positions along the segment's line; the axis is at 0
    for (int i = 0; i < 3; ++i)
    {
      s[i] = p[i][0] * p[far][0] + p[i][1] * p[far][1];
    }
    lo = HUGE_VAL;
    hi = -HUGE_VAL;
    for (int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3;
      if ((s[i] <= 0.0 && s[j] >= 0.0) || (s[i] >= 0.0 && s[j] <= 0.0))
      {
        const double z0 = s[i] == s[j] ? p[i][2] : p[i][2] + (p[j][2] - p[i][2]) * (s[i] / (s[i] - s[j]));
        const double z1 = s[i] == s[j] ? p[j][2] : z0;
        lo = std::min({ lo, z0, z1 });
        hi = std::max({ hi, z0, z1 });
      }
    }
  }

  void Shear(const double* p, double out[3]) const
  {
    const double x = p[this->Kx] - this->Origin[this->Kx];
    const double y = p[this->Ky] - this->Origin[this->Ky];
    const double z = p[this->Kz] - this->Origin[this->Kz];
    out[0] = x - this->Sx * z;
    out[1] = y - this->Sy * z;
    out[2] = this->Sz * z;
  }

  int Kx, Ky, Kz;
  double Sx, Sy, Sz;
  double Origin[3];
};

// Where the ray (origin o relative to the tree's origin, inverse direction inv) enters
// a node's box from tMin on, and where it leaves it: kept with the node on the stack,
// so that a node popped after the hit came nearer needs no second box test.
struct RaySpan
{
  std::int32_t Index; // the node
  double Enter, Exit;
  RaySpan(const vtkMedialBuffer<Node>& nodes, std::int32_t index, const double o[3], const double inv[3],
    double tMin)
    : Index(index)
    , Enter(tMin)
    , Exit(HUGE_VAL)
  {
    // A zero direction component gives NaN at the box's face: comparisons with NaN
    // fail, so the span stays conservative.
    const vtkMedialTriangleBVH::Node& node = nodes[index];
    for (int k = 0; k < 3; ++k)
    {
      double a = (node.Lo[k] - o[k]) * inv[k];
      double b = (node.Hi[k] - o[k]) * inv[k];
      if (a > b)
      {
        std::swap(a, b);
      }
      this->Enter = a > this->Enter ? a : this->Enter;
      this->Exit = b < this->Exit ? b : this->Exit;
    }
  }
  // The ray meets the box before tMax. The box is padded outward; the slack covers the
  // rounding of the products.
  bool Before(double tMax) const
  {
    const double t1 = this->Exit < tMax ? this->Exit : tMax;
    return this->Enter <= t1 + 1e-12 * std::fabs(t1);
  }
};
}

#if defined(__SSE2__)
namespace
{
// The ray against the four lanes of a wide node at once, in float, on the lanes'
// boxes padded by Pad on every side. Pad (1e-5 of the tree's extent) is far above
// the rounding of the float slab products for an origin within a few extents and a
// direction of about unit length, so a lane whose padded span misses [tMin, tMax]
// misses the box in exact arithmetic too: the walk visits every leaf the double walk
// would, and maybe a few more.
class WideRay
{
public:
  WideRay(const double o[3], const double direction[3], float pad)
  {
    for (int k = 0; k < 3; ++k)
    {
      // A zero (or denormal) component: a huge finite inverse instead of inf, so no
      // 0 * inf makes a NaN; exits stay beyond any t the tree can reach.
      const double inv = direction[k] != 0.0 ? 1.0 / direction[k] : HUGE_VAL;
      const float clamped = static_cast<float>(std::max(-1e30, std::min(1e30, inv)));
      this->O[k] = _mm_set1_ps(static_cast<float>(o[k]));
      this->Inv[k] = _mm_set1_ps(clamped);
    }
    this->Pad = _mm_set1_ps(pad);
  }

  // Bit i: lane i's padded box meets the ray within [tMin, tMax]; enter[i] its entry.
  int Test(const vtkMedialTriangleBVH::WideNode& w, float tMin, float tMax, float enter[4]) const
  {
    __m128 t0 = _mm_set1_ps(tMin), t1 = _mm_set1_ps(tMax);
    for (int k = 0; k < 3; ++k)
    {
      const __m128 a = _mm_mul_ps(_mm_sub_ps(_mm_sub_ps(_mm_load_ps(w.Lo[k]), this->Pad), this->O[k]), this->Inv[k]);
      const __m128 b = _mm_mul_ps(_mm_sub_ps(_mm_add_ps(_mm_load_ps(w.Hi[k]), this->Pad), this->O[k]), this->Inv[k]);
      t0 = _mm_max_ps(t0, _mm_min_ps(a, b));
      t1 = _mm_min_ps(t1, _mm_max_ps(a, b));
    }
    _mm_store_ps(enter, t0);
    // An empty lane's box is inverted: the swap above would hide that.
    const __m128 filled = _mm_cmple_ps(_mm_load_ps(w.Lo[0]), _mm_load_ps(w.Hi[0]));
    return _mm_movemask_ps(_mm_and_ps(_mm_cmple_ps(t0, t1), filled));
  }

private:
  __m128 O[3], Inv[3], Pad;
};

}
#endif

bool vtkMedialTriangleBVH::IntersectRay(const double origin[3], const double direction[3], double tMin,
  double tMax, vtkIdType ignoreTriangle, double& t, vtkIdType& triangle) const
{
  if (this->Nodes.empty())
  {
    return false;
  }
  const WatertightRay ray(origin, direction);
  double o[3];
  G::Sub(origin, this->Origin, o);
  double best = tMax;
  triangle = -1;
  // The nearest hit, ties to the lower mesh id: the same answer for any walk order.
  auto hitLeaf = [&](std::int32_t start, std::int32_t end) {
    for (std::int32_t slot = start; slot < end; ++slot)
    {
      double scratch[9];
      const double* v = this->Corners(slot, scratch);
      double hit;
      const std::int32_t id = this->LeafTriangles[slot].Triangle;
      if (id != ignoreTriangle && ray.Hit(v, v + 3, v + 6, tMin, hit) && hit > tMin &&
        (hit < best || (hit == best && triangle >= 0 && id < triangle)))
      {
        best = hit;
        triangle = id;
      }
    }
  };
#if defined(__SSE2__)
  const double extent = this->Extent();
  const double length2 = G::Dot(direction, direction);
  const bool near = std::fabs(o[0]) <= 4.0 * extent && std::fabs(o[1]) <= 4.0 * extent &&
    std::fabs(o[2]) <= 4.0 * extent;
  if (extent > 0.0 && near && length2 >= 0.25 && length2 <= 4.0 && !this->WideNodes.empty())
  {
    // Four lanes at once, nearest entry first.
    const WideRay wide(o, direction, static_cast<float>(1e-5 * extent));
    const float from = FloatBelow(static_cast<float>(tMin));
    float until = FloatAbove(static_cast<float>(best));
    LaneStack lanes;
    alignas(16) float enter[4];
    if (wide.Test(this->WideNodes[0], from, until, enter) & 1)
    {
      lanes.push_back({ this->WideNodes[0].Child[0], enter[0] });
    }
    while (!lanes.empty())
    {
      const WaitingLane lane = lanes.back();
      lanes.pop_back();
      if (lane.Key > until)
      {
        continue; // the hit came nearer since the lane was pushed
      }
      if (lane.Child < 0)
      {
        const LeafSlots leaf(lane.Child);
        hitLeaf(leaf.Start, leaf.End);
        until = FloatAbove(static_cast<float>(best));
        continue;
      }
      const WideNode& node = this->WideNodes[lane.Child];
      const int met = wide.Test(node, from, until, enter);
      PushNearestOnTop(node, met, enter, lanes);
    }
    t = best;
    return triangle >= 0;
  }
#endif
  // In double over the binary tree: far origins, odd directions, no SSE2.
  double inv[3];
  for (int k = 0; k < 3; ++k)
  {
    inv[k] = 1.0 / direction[k];
  }
  thread_local std::vector<RaySpan> stack; // own stack: not the per-sample scratch
  stack.clear();
  const RaySpan root(this->Nodes, 0, o, inv, tMin);
  if (!root.Before(best))
  {
    return false;
  }
  stack.push_back(root);
  while (!stack.empty())
  {
    const RaySpan span = stack.back();
    stack.pop_back();
    if (!span.Before(best))
    {
      continue; // best shrank since the node was pushed
    }
    const Node& node = this->Nodes[span.Index];
    if (node.Count == 0)
    {
      const RaySpan left(this->Nodes, node.Start, o, inv, tMin);
      const RaySpan right(this->Nodes, node.Start + 1, o, inv, tMin);
      const bool inLeft = left.Before(best), inRight = right.Before(best);
      if (inLeft && inRight)
      {
        // Nearer child on top; ties to the left one.
        const bool rightFirst = right.Enter < left.Enter;
        stack.push_back(rightFirst ? left : right);
        stack.push_back(rightFirst ? right : left);
      }
      else if (inLeft || inRight)
      {
        stack.push_back(inLeft ? left : right);
      }
      continue;
    }
    hitLeaf(node.Start, node.Start + node.Count);
  }
  t = best;
  return triangle >= 0;
}

void vtkMedialTriangleBVH::RayCrossings(const double origin[3], const double direction[3], double tMin,
  vtkIdType ignoreTriangle, std::vector<RayCrossing>& crossings) const
{
  crossings.clear();
  if (this->Nodes.empty())
  {
    return;
  }
  const WatertightRay ray(origin, direction);
  double o[3];
  G::Sub(origin, this->Origin, o);
  // Kept when some restart from tMin on may return it: as IntersectRay's test with
  // tMax infinite, only without the hit's own tMin.
  auto hitLeaf = [&](std::int32_t start, std::int32_t end) {
    for (std::int32_t slot = start; slot < end; ++slot)
    {
      double scratch[9];
      const double* v = this->Corners(slot, scratch);
      RayCrossing c;
      c.Triangle = this->LeafTriangles[slot].Triangle;
      if (c.Triangle != ignoreTriangle && ray.Meets(v, v + 3, v + 6, c.T, c.End, c.InPlane) && c.End > tMin)
      {
        crossings.push_back(c);
      }
    }
  };
  // The walks of IntersectRay with the hit never coming nearer: every leaf they may
  // visit for any restart.
#if defined(__SSE2__)
  const double extent = this->Extent();
  const double length2 = G::Dot(direction, direction);
  const bool near = std::fabs(o[0]) <= 4.0 * extent && std::fabs(o[1]) <= 4.0 * extent &&
    std::fabs(o[2]) <= 4.0 * extent;
  if (extent > 0.0 && near && length2 >= 0.25 && length2 <= 4.0 && !this->WideNodes.empty())
  {
    const WideRay wide(o, direction, static_cast<float>(1e-5 * extent));
    const float from = FloatBelow(static_cast<float>(tMin));
    const float until = FloatAbove(static_cast<float>(HUGE_VAL));
    thread_local std::vector<std::int32_t> stack;
    stack.clear();
    alignas(16) float enter[4];
    if (wide.Test(this->WideNodes[0], from, until, enter) & 1)
    {
      stack.push_back(this->WideNodes[0].Child[0]);
    }
    while (!stack.empty())
    {
      const std::int32_t child = stack.back();
      stack.pop_back();
      if (child < 0)
      {
        const LeafSlots leaf(child);
        hitLeaf(leaf.Start, leaf.End);
        continue;
      }
      const WideNode& node = this->WideNodes[child];
      const int met = wide.Test(node, from, until, enter);
      for (int i = 0; i < 4; ++i)
      {
        if (met & (1 << i))
        {
          stack.push_back(node.Child[i]);
        }
      }
    }
    return;
  }
#endif
  double inv[3];
  for (int k = 0; k < 3; ++k)
  {
    inv[k] = 1.0 / direction[k];
  }
  thread_local std::vector<std::int32_t> stack;
  stack.assign(1, 0);
  while (!stack.empty())
  {
    const std::int32_t index = stack.back();
    stack.pop_back();
    if (!RaySpan(this->Nodes, index, o, inv, tMin).Before(HUGE_VAL))
    {
      continue;
    }
    const Node& node = this->Nodes[index];
    if (node.Count == 0)
    {
      stack.push_back(node.Start + 1);
      stack.push_back(node.Start);
      continue;
    }
    hitLeaf(node.Start, node.Start + node.Count);
  }
}

bool vtkMedialTriangleBVH::FirstCrossing(
  const std::vector<RayCrossing>& crossings, double tMin, double tMax, double& t, vtkIdType& triangle)
{
  // IntersectRay's choice over the crossings: the nearest beyond tMin, ties to the lower id.
  double best = tMax;
  triangle = -1;
  for (const RayCrossing& c : crossings)
  {
    double hit = c.T;
    if (c.InPlane ? !WatertightRay::FirstInSpan(c.T, c.End, tMin, hit) : !(hit > tMin))
    {
      continue;
    }
    if (hit < best || (hit == best && triangle >= 0 && c.Triangle < triangle))
    {
      best = hit;
      triangle = c.Triangle;
    }
  }
  t = best;
  return triangle >= 0;
}

void vtkMedialTriangleBVH::VisitBox(
  const double lo[3], const double hi[3], const std::function<bool(vtkIdType)>& visit) const
{
  if (this->Nodes.empty())
  {
    return;
  }
  double l[3], h[3]; // relative to the origin, as the node bounds
  G::Sub(lo, this->Origin, l);
  G::Sub(hi, this->Origin, h);
  std::vector<std::int32_t> stack{ 0 }; // own stack: visit may run other queries
  while (!stack.empty())
  {
    const Node& node = this->Nodes[stack.back()];
    stack.pop_back();
    bool apart = false;
    for (int k = 0; k < 3; ++k)
    {
      apart = apart || node.Lo[k] > h[k] || node.Hi[k] < l[k];
    }
    if (apart)
    {
      continue;
    }
    if (node.Count == 0)
    {
      stack.push_back(node.Start + 1);
      stack.push_back(node.Start);
      continue;
    }
    for (std::int32_t slot = node.Start; slot < node.Start + node.Count; ++slot)
    {
      if (!visit(this->LeafTriangles[slot].Triangle))
      {
        return;
      }
    }
  }
}

void vtkMedialTriangleBVH::VisitWithin(const double x[3], double distance, const double samplePoint[3],
  double cosMinAngle, const std::function<void(double, const double*, vtkIdType)>& visit,
  const Nearby* nearby) const
{
  const double limit2 = distance * distance;
  // The traversal culls nodes at or beyond its reach: reach a little further and
  // decide in double on each triangle.
  double reach2 = limit2 * (1.0 + 1e-12) + 1e-300;
  auto within = [&](double d2, const double q[3], vtkIdType t) {
    if (d2 <= limit2)
    {
      visit(d2, q, t);
    }
    return true;
  };
  if (nearby && !(cosMinAngle < 1.0 && samplePoint) && this->Covers(*nearby, x, distance))
  {
    this->VisitListed(*nearby, x, reach2, within);
    return;
  }
  this->VisitAdmissible(x, -1, samplePoint, cosMinAngle, false, reach2, within);
}

void vtkMedialTriangleBVH::GatherNearby(const double centre[3], double distance, Nearby& out) const
{
  std::copy(centre, centre + 3, out.Centre);
  out.Distance = distance;
  out.Slots.clear();
  this->VisitWithin(centre, distance, nullptr, 1.0,
    [&](double, const double*, vtkIdType t) { out.Slots.push_back(this->LeafRank[t]); });
  std::sort(out.Slots.begin(), out.Slots.end());
}

bool vtkMedialTriangleBVH::Covers(const Nearby& nearby, const double x[3], double distance) const
{
  // A triangle the query can visit or be blocked by has its computed closest point
  // within `distance` of x, so it is within |x - Centre| + distance of Centre, up to
  // the rounding of two closest points (ulps of the extent): the margin is far above.
  const double margin = 1e-9 * nearby.Distance + 1e6 * this->RoundingPad;
  return std::sqrt(G::Distance2(x, nearby.Centre)) + distance + margin <= nearby.Distance;
}

bool vtkMedialTriangleBVH::VisitWithinIfEmpty(const double x[3], double distance, double emptyRadius,
  const std::function<void(double, const double*, vtkIdType)>& visit, double* nearestBound,
  const Nearby* nearby, NearestPoint* nearest) const
{
  if (nearest)
  {
    nearest->Triangle = -1;
  }
  // The blocker's distance (or emptyRadius) is above the closest point's; the pad, far
  // above the rounding of a plane offset or a closest point (ulps of the extent), keeps
  // every triangle at most that far inside the tests of a ClosestPoint walk bounded there.
  const double pad = 100.0 * this->RoundingPad;
  if (nearestBound)
  {
    *nearestBound = emptyRadius + pad;
  }
  double xRel[3];
  G::Sub(x, this->Origin, xRel);
  const double extent = this->Extent();
  bool wide = false;
#if defined(__SSE2__)
  wide = extent > 0.0 && std::fabs(xRel[0]) <= 4.0 * extent && std::fabs(xRel[1]) <= 4.0 * extent &&
    std::fabs(xRel[2]) <= 4.0 * extent && !this->WideNodes.empty();
#endif
  if (!(emptyRadius > 0.0))
  {
    this->VisitWithin(x, distance, nullptr, 1.0, visit, nearby);
    return true; // ContainsBall's reach is empty
  }
  if (!wide || !(emptyRadius <= distance))
  {
    // Not the padded wide walk the argument below needs: the two queries.
    if (!this->ContainsBall(x, emptyRadius, -1, nullptr, 1.0, false))
    {
      return false;
    }
    this->VisitWithin(x, distance, nullptr, 1.0, visit);
    return true;
  }
  // ContainsBall(x, emptyRadius) is false exactly when its walk meets a triangle that
  // passes its leaf tests (plane, box) and lies nearer than emptyRadius. The wide walk
  // drops a lane only when its float box, widened by 1e-5 of the extent, lies beyond
  // the reach, so every triangle nearer than emptyRadius is in a lane that both walks
  // keep (this one's reach is larger); the leaf tests are repeated here at
  // ContainsBall's reach, with its expressions, and the distance is the same number.
  const double empty2 = emptyRadius * emptyRadius; // ContainsBall's reach2
  const double emptyRounding = 10.0 * this->RoundingPad * std::sqrt(empty2);
  const double limit2 = distance * distance;
  double reach2 = limit2 * (1.0 + 1e-12) + 1e-300; // as VisitWithin
  bool blocked = false;
  // With `nearest`, once blocked the walk goes on as ClosestPoint's from the blocker's
  // bound: the wide walk visits the lanes in the order of their keys (ties: the lower
  // lane) whatever its reach, so the leaves both walks visit come in the same order and
  // the first triangle at the least distance, the one ClosestPoint keeps, is the same.
  // The nearest seen before the block counts too (a triangle nearer than emptyRadius
  // that missed the leaf tests at that reach).
  const bool listed = nearby && this->Covers(*nearby, x, distance);
  const bool goOn = nearest && !listed;
  double best2 = HUGE_VAL;
  auto keep = [&](double d2, const double q[3], vtkIdType t) {
    if (d2 < best2)
    {
      best2 = d2;
      G::Copy(q, nearest->Point);
      nearest->Triangle = t;
    }
  };
  auto test = [&](double d2, const double q[3], vtkIdType t) {
    if (blocked)
    {
      keep(d2, q, t);
      reach2 = best2; // ClosestPoint's shrinking reach
      return true;
    }
    if (goOn)
    {
      keep(d2, q, t);
    }
    if (d2 < empty2)
    {
      const LeafTriangle& leaf = this->LeafTriangles[this->LeafRank[t]];
      const double off = G::Dot(leaf.Plane, x) - leaf.Plane[3];
      if (!(off * off >= empty2) && !(BoxDistance2(leaf.Lo, leaf.Hi, xRel) >= empty2 * (1.0 + 1e-9) + emptyRounding))
      {
        if (nearestBound)
        {
          *nearestBound = std::sqrt(d2) + pad;
        }
        blocked = true;
        reach2 = best2;
        return goOn;
      }
    }
    if (d2 <= limit2)
    {
      visit(d2, q, t);
    }
    return true;
  };
  if (listed)
  {
    this->VisitListed(*nearby, x, reach2, test);
  }
  else
  {
    this->VisitAdmissible(x, -1, nullptr, 1.0, false, reach2, test);
  }
  if (goOn)
  {
    if (blocked)
    {
      nearest->Distance = std::sqrt(best2);
    }
    else
    {
      nearest->Triangle = -1;
    }
  }
  return !blocked;
}
