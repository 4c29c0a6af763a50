// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialTriangleBVH::FindIntersectingPairs: the self-intersection search of the
// solid check (vtkMedialSolidCheck), the tree walked against itself.
#include "vtkMedialTriangleBVH.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPrefetch.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace
{
namespace G = vtkMedialGeometry;

// A triangle as the tests read it: its corners, its plane (unit normal n, n.x = d) and
// whether that plane can be trusted.
struct Triangle
{
  const double* X[3];
  const double* Plane;
  bool Sliver;
  double Corners[9]; // where X points when the tree keeps its corners as floats
};

double Side(const double* plane, const double* x)
{
  return plane[0] * x[0] + plane[1] * x[1] + plane[2] * x[2] - plane[3];
}

// Every value beyond eps on the same side.
bool OneSide(const double d[], int n, double eps)
{
  bool above = true, below = true;
  for (int i = 0; i < n; ++i)
  {
    above = above && d[i] > eps;
    below = below && d[i] < -eps;
  }
  return above || below;
}

// Two coplanar triangles (within the tolerance): true unless an edge of one separates
// them in their plane by more than eps.
bool CoplanarMayOverlap(const Triangle& a, const Triangle& b, double eps)
{
  // The plane's two coordinates that the normal leans on least.
  const double* n = a.Plane;
  const int drop = std::fabs(n[0]) > std::fabs(n[1]) ? (std::fabs(n[0]) > std::fabs(n[2]) ? 0 : 2)
                                                      : (std::fabs(n[1]) > std::fabs(n[2]) ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  auto separates = [&](const Triangle& s, const Triangle& t) {
    for (int i = 0; i < 3; ++i)
    {
      const double* p = s.X[i];
      const double* q = s.X[(i + 1) % 3];
      const double* r = s.X[(i + 2) % 3];
      const double m[2] = { -(q[v] - p[v]), q[u] - p[u] };
      const double length = std::sqrt(m[0] * m[0] + m[1] * m[1]);
      const double inner = m[0] * (r[u] - p[u]) + m[1] * (r[v] - p[v]);
      const double sign = inner < 0.0 ? 1.0 : -1.0; // towards the outside of s
      bool apart = length > 0.0;
      for (int k = 0; k < 3 && apart; ++k)
      {
        apart = sign * (m[0] * (t.X[k][u] - p[u]) + m[1] * (t.X[k][v] - p[v])) > eps * length;
      }
      if (apart)
      {
        return true;
      }
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

// The interval of triangle t (signed distances d to the other plane) on the line along u
// where the planes meet; corners within eps of the plane count as on it.
void LineInterval(const Triangle& t, const double d[3], const double u[3], double eps, double& lo, double& hi)
{
  lo = HUGE_VAL;
  hi = -HUGE_VAL;
  auto add = [&](const double x[3]) {
    const double s = G::Dot(u, x);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  };
  for (int i = 0; i < 3; ++i)
  {
    if (std::fabs(d[i]) <= eps)
    {
      add(t.X[i]);
    }
    const int j = (i + 1) % 3;
    if ((d[i] > eps && d[j] < -eps) || (d[i] < -eps && d[j] > eps))
    {
      const double s = d[i] / (d[i] - d[j]);
      double x[3];
      for (int k = 0; k < 3; ++k)
      {
        x[k] = t.X[i][k] + s * (t.X[j][k] - t.X[i][k]);
      }
      add(x);
    }
  }
}

// Triangles that share no corner: true unless they are certainly apart by more than the
// rounding of the test (Moller's interval test with margins; coplanar ones in 2D).
bool MayTouch(const Triangle& a, const Triangle& b, double eps)
{
  double db[3], da[3];
  for (int i = 0; i < 3; ++i)
  {
    db[i] = Side(a.Plane, b.X[i]);
  }
  if (OneSide(db, 3, eps) && !a.Sliver)
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    da[i] = Side(b.Plane, a.X[i]);
  }
  if (OneSide(da, 3, eps) && !b.Sliver)
  {
    return false;
  }
  if (a.Sliver || b.Sliver)
  {
    return true;
  }
  double u[3];
  G::Cross(a.Plane, b.Plane, u);
  const double length = std::sqrt(G::Dot(u, u));
  if (length < 1e-6)
  {
    return CoplanarMayOverlap(a, b, eps);
  }
  for (double& c : u)
  {
    c /= length;
  }
  double alo, ahi, blo, bhi;
  LineInterval(a, da, u, eps, alo, ahi);
  LineInterval(b, db, u, eps, blo, bhi);
  // The intervals' ends carry the plane distances' error over the planes' angle.
  const double margin = 4.0 * eps / length;
  return alo <= bhi + margin && blo <= ahi + margin;
}

// Triangles a = (v, a1, a2) and b = (v, b1, b2) that share the corner v only: true
// unless they certainly meet at v alone.
bool MayTouchBeyondVertex(const Triangle& a, int va, const Triangle& b, int vb, double eps)
{
  const double* v = a.X[va];
  const double* a1 = a.X[(va + 1) % 3];
  const double* a2 = a.X[(va + 2) % 3];
  const double* b1 = b.X[(vb + 1) % 3];
  const double* b2 = b.X[(vb + 2) % 3];
  if (a.Sliver || b.Sliver)
  {
    return true;
  }
  // One triangle on one side of the other's plane: they meet at v only.
  const double db[2] = { Side(a.Plane, b1), Side(a.Plane, b2) };
  if (OneSide(db, 2, eps))
  {
    return false;
  }
  const double da[2] = { Side(b.Plane, a1), Side(b.Plane, a2) };
  if (OneSide(da, 2, eps))
  {
    return false;
  }
  double u[3];
  G::Cross(a.Plane, b.Plane, u);
  const double length = std::sqrt(G::Dot(u, u));
  if (length < 1e-6)
  {
    // Coplanar: two convex corner sectors at v (each under 180 degrees) overlap only if
    // an edge of one from v lies in the other, so they are apart when each edge from v
    // is strictly outside the other triangle's sector.
    auto outside = [&](const double* q1, const double* q2, const double* r) {
      double e1[3], e2[3], w[3], c1[3], c2[3], c12[3];
      G::Sub(q1, v, e1);
      G::Sub(q2, v, e2);
      G::Sub(r, v, w);
      G::Cross(e1, w, c1);
      G::Cross(w, e2, c2);
      G::Cross(e1, e2, c12);
      const double s1 = G::Dot(c1, a.Plane), s2 = G::Dot(c2, a.Plane), s = G::Dot(c12, a.Plane);
      const double ww = G::Dot(w, w);
      const double m = 1e-9 * (std::sqrt(G::Dot(e1, e1) * ww) + std::sqrt(G::Dot(e2, e2) * ww));
      return (s > 0.0 && (s1 < -m || s2 < -m)) || (s < 0.0 && (s1 > m || s2 > m));
    };
    return !(outside(a1, a2, b1) && outside(a1, a2, b2) && outside(b1, b2, a1) && outside(b1, b2, a2));
  }
  // The planes meet along the line through v with direction u. Each triangle meets it
  // in a segment from v, to where its opposite edge crosses the other plane; they meet
  // beyond v when the two segments leave v the same way.
  auto direction = [&](const double* p1, const double* p2, const double d[2]) {
    const double s = d[0] / (d[0] - d[1]);
    double x[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = p1[k] + s * (p2[k] - p1[k]);
    }
    G::Sub(x, v, w);
    const double t = G::Dot(u, w);
    const double size = length * std::sqrt(G::Dot(w, w));
    return t > 1e-9 * size ? 1 : (t < -1e-9 * size ? -1 : 0);
  };
  const int sa = direction(a1, a2, da), sb = direction(b1, b2, db);
  return sa == 0 || sb == 0 || sa == sb;
}

// Triangles sharing the edge (v, w), with opposite corners a and b: true when they may
// fold onto each other (coplanar, a and b on the same side of the edge).
bool MayFold(const Triangle& ta, const double* v, const double* w, const double* a, const Triangle& tb,
  const double* b, double eps)
{
  if (!ta.Sliver && !tb.Sliver && std::fabs(Side(ta.Plane, b)) > eps)
  {
    return false;
  }
  double e[3], pa[3], pb[3], ca[3], cb[3];
  G::Sub(w, v, e);
  G::Sub(a, v, pa);
  G::Sub(b, v, pb);
  G::Cross(e, pa, ca);
  G::Cross(e, pb, cb);
  return G::Dot(ca, cb) >= -1e-9 * std::sqrt(G::Dot(ca, ca) * G::Dot(cb, cb));
}
}

// Normal-cone culling (Volino and Thalmann 1994), kept exact. A node's triangles form
// a patch S of the closed, manifold, consistently oriented mesh. Project S along a
// direction v such that every triangle's normal n has n.v > 0: every projected
// triangle is then positively oriented, so the number of triangles of S over a point of
// the plane is the winding number of S's projected boundary around it (the degree of
// the projection). If that boundary is one simple loop (winding 0 or 1 everywhere), no
// two triangles of S overlap in projection, so none intersect or touch in space other
// than along the edge or at the corner they share (a touching pair overlaps in
// projection with itself or a neighbour, or makes the boundary touch itself). The
// boundary is checked to be one loop (each corner starts one boundary edge, and they
// chain through all of them), whose edges that follow each other do not fold back and
// whose other edges are apart by more than the search's tolerance (far above the
// projection's rounding).
// The patch's self-tests are then skipped; pairs between patches are still searched.
// Only on meshes whose triangles' edge neighbours the mesh kept (closed, manifold) and
// that are oriented, without degenerate triangles or slivers in the patch.
class vtkMedialTriangleBVH::PatchCulling
{
public:
  // A boundary edge from corner From to corner To (mesh point ids), projected: X[0..1]
  // then X[2..3].
  struct Edge
  {
    double X[4];
    vtkIdType From, To;
    bool Pinched = false; // From is a corner where the boundary is pinched
  };
  struct Scratch
  {
    std::vector<Edge> Edges; // the boundary, projected
    std::vector<std::int32_t> Order;
    // Pinched boundaries only: the edges into pinched corners, each edge's successor
    // with the patch kept on the left and on the right of the walk, and marks.
    std::vector<std::pair<vtkIdType, std::int32_t>> Into;
    std::vector<std::int32_t> Left, Right;
    std::vector<char> Seen;
    struct Ray
    {
      double Angle, X, Y;
      std::int32_t Edge;
      bool Out;
    };
    std::vector<Ray> Rays;
    PairSearchStatistics Statistics;
  };

  PatchCulling(const vtkMedialTriangleBVH& tree, const vtkMedialTriangleMesh& mesh, double tolerance)
    : Tree(tree)
    , Mesh(mesh)
    , Tolerance(tolerance)
  {
    const size_t triangles = static_cast<size_t>(mesh.GetNumberOfTriangles());
    this->Enabled = mesh.EdgeNeighbours.size() == 3 * triangles && tree.LeafTriangles.size() == triangles &&
      mesh.BoundaryEdges == 0 && mesh.NonManifoldEdges == 0 && mesh.NonOrientableComponents == 0 &&
      mesh.DegenerateTriangles == 0;
  }

  // True when the patch of inner node `node` certainly has no intersecting pair.
  bool CannotSelfIntersect(std::int32_t node, Scratch& scratch) const
  {
    const Node& n = this->Tree.Nodes[node];
    const std::int32_t begin = n.Begin, end = n.End;
    if (!this->Enabled || n.Count > 0 || end - begin > MaxPatch)
    {
      return false;
    }
    ++scratch.Statistics.CullingTests;
    const LeafTriangle* leaves = this->Tree.LeafTriangles.data();
    // The direction: the mean normal of up to 64 of its triangles (any direction is
    // sound; every triangle is tested against the one taken).
    double v[3] = { 0, 0, 0 };
    const std::int32_t step = std::max<std::int32_t>(1, (end - begin) / 64);
    for (std::int32_t s = begin; s < end; s += step)
    {
      for (int k = 0; k < 3; ++k)
      {
        v[k] += leaves[s].Plane[k];
      }
    }
    const double norm = std::sqrt(G::Dot(v, v));
    if (!(norm > 0.0))
    {
      return false;
    }
    for (double& c : v)
    {
      c /= norm;
    }
    for (std::int32_t s = begin; s < end; ++s)
    {
      if (G::Dot(leaves[s].Plane, v) < MinCosine || this->Tree.IsSliverSlot(s))
      {
        return false;
      }
    }
    // The plane's axes (u, w) with u x w = v, and a reference point: the box's centre.
    double u[3], w[3];
    const int least = std::fabs(v[0]) < std::fabs(v[1]) ? (std::fabs(v[0]) < std::fabs(v[2]) ? 0 : 2)
                                                        : (std::fabs(v[1]) < std::fabs(v[2]) ? 1 : 2);
    double unit[3] = { 0, 0, 0 };
    unit[least] = 1.0;
    G::Cross(v, unit, u);
    const double ul = std::sqrt(G::Dot(u, u));
    for (double& c : u)
    {
      c /= ul;
    }
    G::Cross(v, u, w);
    double centre[3];
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = this->Tree.Origin[k] + 0.5 * (static_cast<double>(n.Lo[k]) + static_cast<double>(n.Hi[k]));
    }
    // The boundary: edges whose neighbour across lies outside the patch.
    std::vector<Edge>& edges = scratch.Edges;
    edges.clear();
    const std::int32_t* across = this->Mesh.EdgeNeighbours.data();
    const std::int32_t* rank = this->Tree.LeafRank.data();
    // The neighbours' ids and ranks are read from all over the mesh: fetched ahead (the
    // ids further, then the ranks once the ids are in). On the 1.55M horse about half of
    // this rule's time was spent waiting for them.
    constexpr std::int32_t Ahead = 16;
    for (std::int32_t s = begin; s < end; ++s)
    {
      if (s + 2 * Ahead < end)
      {
        vtkMedialPrefetch(across + 3 * static_cast<size_t>(leaves[s + 2 * Ahead].Triangle));
      }
      if (s + Ahead < end)
      {
        const std::int32_t* ahead = across + 3 * static_cast<size_t>(leaves[s + Ahead].Triangle);
        vtkMedialPrefetch(rank + ahead[0]);
        vtkMedialPrefetch(rank + ahead[1]);
        vtkMedialPrefetch(rank + ahead[2]);
      }
      const vtkIdType t = leaves[s].Triangle;
      for (int j = 0; j < 3; ++j)
      {
        const std::int32_t other = across[3 * t + j];
        const std::int32_t r = rank[other];
        if (r >= begin && r < end)
        {
          continue;
        }
        // The edge shared with `other`: the one opposite t's corner that `other` lacks.
        const vtkIdType* vt = this->Mesh.GetTriangle(t);
        const vtkIdType* vo = this->Mesh.GetTriangle(other);
        int m = 0;
        while (m < 3 && (vt[m] == vo[0] || vt[m] == vo[1] || vt[m] == vo[2]))
        {
          ++m;
        }
        if (m == 3)
        {
          return false; // a duplicate (the mesh drops them)
        }
        double corners[9];
        const double* x = this->Tree.Corners(s, corners);
        Edge edge;
        edge.From = vt[(m + 1) % 3];
        edge.To = vt[(m + 2) % 3];
        for (int end = 0; end < 2; ++end)
        {
          const int c = (m + 1 + end) % 3;
          const double d[3] = { x[3 * c] - centre[0], x[3 * c + 1] - centre[1], x[3 * c + 2] - centre[2] };
          edge.X[2 * end] = G::Dot(u, d);
          edge.X[2 * end + 1] = G::Dot(w, d);
        }
        edges.push_back(edge);
      }
    }
    const size_t count = edges.size();
    if (count < 3)
    {
      return false;
    }
    // The boundary's walks. Sorted by their start, edges that start at the same corner
    // are a run: the boundary is pinched there (it passes the corner more than once).
    std::vector<std::int32_t>& order = scratch.Order;
    order.resize(count);
    for (size_t i = 0; i < count; ++i)
    {
      order[i] = static_cast<std::int32_t>(i);
    }
    std::vector<Edge>& e = edges;
    std::sort(order.begin(), order.end(), [&](std::int32_t i, std::int32_t j) { return e[i].From < e[j].From; });
    bool pinched = false;
    for (size_t i = 1; i < count; ++i)
    {
      if (e[order[i]].From == e[order[i - 1]].From)
      {
        pinched = true;
        e[order[i]].Pinched = e[order[i - 1]].Pinched = true;
      }
    }
    // The first edge (in `order`) that starts where `edge` ends, or -1.
    auto firstNext = [&](const Edge& edge) -> std::int32_t {
      const auto it = std::lower_bound(order.begin(), order.end(), edge.To,
        [&](std::int32_t i, vtkIdType from) { return e[i].From < from; });
      return it != order.end() && e[*it].From == edge.To ? static_cast<std::int32_t>(it - order.begin()) : -1;
    };
    if (!pinched)
    {
      // One loop: following the edges from the first comes back after all of them.
      size_t length = 0;
      std::int32_t at = 0;
      do
      {
        const std::int32_t k = firstNext(e[at]);
        at = k < 0 ? -1 : order[k];
        ++length;
      } while (at > 0 && length <= count);
      if (at != 0 || length != count)
      {
        return false;
      }
    }
    else if (!this->OneWalk(e, order, firstNext, scratch))
    {
      return false;
    }
    // Simple: edges that follow each other do not fold back onto each other, and every
    // other two are apart by more than the tolerance (one on one side of the other's
    // line). A sweep along x over the edges sorted by their lowest x.
    std::sort(order.begin(), order.end(), [&](std::int32_t i, std::int32_t j) {
      return std::min(e[i].X[0], e[i].X[2]) < std::min(e[j].X[0], e[j].X[2]);
    });
    const double tol = this->Tolerance;
    // Both ends of g beyond tol on one side of f's line.
    auto beside = [tol](const Edge& f, const Edge& g) {
      const double dx = f.X[2] - f.X[0], dy = f.X[3] - f.X[1];
      const double margin = tol * std::sqrt(dx * dx + dy * dy);
      const double s0 = dx * (g.X[1] - f.X[1]) - dy * (g.X[0] - f.X[0]);
      const double s1 = dx * (g.X[3] - f.X[1]) - dy * (g.X[2] - f.X[0]);
      return (s0 > margin && s1 > margin) || (s0 < -margin && s1 < -margin);
    };
    // f ends where g starts: they overlap when g turns back along f.
    auto foldsBack = [tol](const Edge& f, const Edge& g) {
      const double ux = f.X[0] - f.X[2], uy = f.X[1] - f.X[3]; // from the shared corner back along f
      const double wx = g.X[2] - g.X[0], wy = g.X[3] - g.X[1]; // and along g
      const double cross = ux * wy - uy * wx;
      const double size = std::sqrt(ux * ux + uy * uy) + std::sqrt(wx * wx + wy * wy);
      return std::fabs(cross) <= tol * size && ux * wx + uy * wy > 0.0;
    };
    for (size_t i = 0; i < count; ++i)
    {
      const Edge& f = e[order[i]];
      const double hi = std::max(f.X[0], f.X[2]) + tol;
      for (size_t j = i + 1; j < count; ++j)
      {
        const Edge& g = e[order[j]];
        if (std::min(g.X[0], g.X[2]) > hi)
        {
          break;
        }
        if (pinched && SharePinchedCorner(f, g))
        {
          continue; // their directions from it were found apart by OneWalk
        }
        if (f.To == g.From || g.To == f.From)
        {
          if (f.To == g.From ? foldsBack(f, g) : foldsBack(g, f))
          {
            return false;
          }
        }
        else if (!beside(f, g) && !beside(g, f))
        {
          return false;
        }
      }
    }
    ++scratch.Statistics.Culled;
    scratch.Statistics.PinchedCulled += pinched ? 1 : 0;
    return true;
  }

private:
  // Two boundary edges that share a corner where the boundary is pinched (called once
  // OneWalk has found every corner with as many edges in as out).
  static bool SharePinchedCorner(const Edge& f, const Edge& g)
  {
    return ((f.From == g.From || f.From == g.To) && f.Pinched) || f.To == g.To || (f.To == g.From && g.Pinched);
  }

  // A boundary pinched at some corners (where it passes more than once). At each, the
  // directions (projected) of the edges out of it and back along the edges into it
  // must be apart and alternate around it, out, in, out, in: the patch's sectors there
  // lie apart, each between an edge out and the next edge in counter-clockwise (the
  // patch is on the left of its boundary). With the edges apart elsewhere (the sweep
  // below), the boundary is then a plane graph, and the number of triangles over a
  // point is constant on each of its faces, one more on the left of an edge than on
  // its right, never negative. Walk the boundary keeping the patch on the left: at a
  // pinched corner leave by the edge out just clockwise of the edge in (the patch's
  // fan order), and each walk goes round one face on the left of its edges. One walk:
  // one such face, so every face on the right has one count less than it, and the
  // outer face (count 0) is one of them: the count is 0 or 1 everywhere. Else walk
  // keeping the patch on the right (leave by the edge out just counter-clockwise):
  // one walk is then one face on the right, the outer one, so every face on the left
  // counts 1. A patch pinched into a ring (one boundary face on the left, with a
  // hole) passes the first; two lobes that touch at a corner, the second; one lobe
  // over another, neither (nor the alternation).
  template <class FirstNext>
  bool OneWalk(const std::vector<Edge>& e, const std::vector<std::int32_t>& order, FirstNext firstNext,
    Scratch& scratch) const
  {
    const std::int32_t count = static_cast<std::int32_t>(e.size());
    auto& into = scratch.Into;
    auto& left = scratch.Left;
    auto& right = scratch.Right;
    into.clear();
    left.assign(count, -1);
    right.assign(count, -1);
    for (std::int32_t i = 0; i < count; ++i)
    {
      const std::int32_t k = firstNext(e[i]);
      if (k < 0)
      {
        return false;
      }
      if (e[order[k]].Pinched)
      {
        into.emplace_back(e[i].To, i);
      }
      else
      {
        left[i] = right[i] = order[k];
      }
    }
    std::sort(into.begin(), into.end());
    const double tol = this->Tolerance;
    auto& rays = scratch.Rays;
    for (size_t i = 0; i < into.size();)
    {
      const vtkIdType corner = into[i].first;
      size_t j = i;
      while (j < into.size() && into[j].first == corner)
      {
        ++j;
      }
      const std::int32_t k0 = firstNext(e[into[i].second]);
      std::int32_t k1 = k0;
      while (k1 < count && e[order[k1]].From == corner)
      {
        ++k1;
      }
      if (static_cast<size_t>(k1 - k0) != j - i)
      {
        return false;
      }
      rays.clear();
      for (std::int32_t k = k0; k < k1; ++k)
      {
        const Edge& b = e[order[k]];
        rays.push_back({ 0.0, b.X[2] - b.X[0], b.X[3] - b.X[1], order[k], true });
      }
      for (size_t k = i; k < j; ++k)
      {
        const Edge& a = e[into[k].second];
        rays.push_back({ 0.0, a.X[0] - a.X[2], a.X[1] - a.X[3], into[k].second, false });
      }
      // Apart: no two within the tolerance of leaving the corner the same way.
      for (size_t p = 0; p < rays.size(); ++p)
      {
        for (size_t q = p + 1; q < rays.size(); ++q)
        {
          const double cross = rays[p].X * rays[q].Y - rays[p].Y * rays[q].X;
          const double dot = rays[p].X * rays[q].X + rays[p].Y * rays[q].Y;
          const double size = std::hypot(rays[p].X, rays[p].Y) + std::hypot(rays[q].X, rays[q].Y);
          if (std::fabs(cross) <= tol * size && dot >= 0.0)
          {
            return false;
          }
        }
      }
      for (auto& ray : rays)
      {
        ray.Angle = std::atan2(ray.Y, ray.X);
      }
      std::sort(rays.begin(), rays.end(), [](const Scratch::Ray& a, const Scratch::Ray& b) { return a.Angle < b.Angle; });
      const size_t n = rays.size();
      for (size_t r = 0; r < n; ++r)
      {
        if (rays[r].Out == rays[(r + 1) % n].Out)
        {
          return false;
        }
        if (!rays[r].Out)
        {
          left[rays[r].Edge] = rays[(r + n - 1) % n].Edge;
          right[rays[r].Edge] = rays[(r + 1) % n].Edge;
        }
      }
      i = j;
    }
    // The walks of a successor map; 0 when it is not one-to-one.
    auto& seen = scratch.Seen;
    auto walks = [&](const std::vector<std::int32_t>& next) {
      seen.assign(count, 0);
      int found = 0;
      for (std::int32_t s = 0; s < count; ++s)
      {
        if (seen[s])
        {
          continue;
        }
        ++found;
        std::int32_t at = s;
        do
        {
          if (seen[at])
          {
            return 0;
          }
          seen[at] = 1;
          at = next[at];
        } while (at != s);
      }
      return found;
    };
    return walks(left) == 1 || walks(right) == 1;
  }

  // Patches larger than this are left to their children (a wide normal cone is likely,
  // and a failed test costs a pass over the patch).
  static constexpr std::int32_t MaxPatch = 1 << 15;
  // n.v below this (about 89.4 degrees) does not count as positive: far above the
  // normals' rounding, which slivers (not culled) would exceed.
  static constexpr double MinCosine = 0.01;
  const vtkMedialTriangleBVH& Tree;
  const vtkMedialTriangleMesh& Mesh;
  const double Tolerance;
  bool Enabled = false;
};

void vtkMedialTriangleBVH::FindIntersectingPairs(const vtkMedialTriangleMesh& mesh, double tolerance, int threads,
  std::vector<std::pair<vtkIdType, vtkIdType>>& pairs, PairSearchStatistics* statistics) const
{
  if (statistics)
  {
    *statistics = PairSearchStatistics();
  }
  pairs.clear();
  const std::int64_t slots = static_cast<std::int64_t>(this->LeafTriangles.size());
  if (this->Nodes.empty() || slots == 0)
  {
    return;
  }
  threads = std::max(1, threads);
  // Boxes (floats relative to Origin, rounded outward) are compared padded by the
  // tolerance, so that pairs closer than it are tested too.
  const float pad = static_cast<float>(tolerance) * (1.0f + 1e-6f);
  auto overlap = [pad](const float* alo, const float* ahi, const float* blo, const float* bhi) {
    return alo[0] <= bhi[0] + pad && blo[0] <= ahi[0] + pad && alo[1] <= bhi[1] + pad && blo[1] <= ahi[1] + pad &&
      alo[2] <= bhi[2] + pad && blo[2] <= ahi[2] + pad;
  };
  // The corners from the tree's leaf-order copy (the mesh's points, the same bits, as
  // doubles or as floats when every coordinate is one), which nearby slots share in
  // cache where the mesh's arrays would be read at random.
  auto triangle = [&](std::int32_t slot, Triangle& t) {
    const double* x = this->Corners(slot, t.Corners);
    t.X[0] = x;
    t.X[1] = x + 3;
    t.X[2] = x + 6;
    t.Plane = this->LeafTriangles[slot].Plane;
    t.Sliver = this->IsSliverSlot(slot);
  };
  using Pairs = std::vector<std::pair<vtkIdType, vtkIdType>>;
  const PatchCulling culling(*this, mesh, tolerance);
  // One pair of slots whose boxes overlap: the test by the corners they share. Shared
  // corners are found by their coordinates, without a per-slot copy of the point ids
  // (12 bytes a triangle at the check's memory peak): the mesh merged every two points
  // with equal coordinates into one, so equal corners are the same point, and the
  // tree's corners are the mesh's values (as floats only when they are floats).
  auto test = [&](std::int32_t i, std::int32_t j, Pairs& out) {
    Triangle a, b;
    triangle(i, a);
    triangle(j, b);
    int sharedI[3], sharedJ[3], shared = 0;
    for (int p = 0; p < 3; ++p)
    {
      for (int q = 0; q < 3; ++q)
      {
        if (a.X[p][0] == b.X[q][0] && a.X[p][1] == b.X[q][1] && a.X[p][2] == b.X[q][2])
        {
          sharedI[shared] = p;
          sharedJ[shared] = q;
          ++shared;
        }
      }
    }
    bool may = true; // three shared corners: a duplicate (the mesh drops them)
    if (shared == 0)
    {
      may = MayTouch(a, b, tolerance);
    }
    else if (shared == 1)
    {
      may = MayTouchBeyondVertex(a, sharedI[0], b, sharedJ[0], tolerance);
    }
    else if (shared == 2)
    {
      const int oa = 3 - sharedI[0] - sharedI[1], ob = 3 - sharedJ[0] - sharedJ[1];
      may = MayFold(a, a.X[sharedI[0]], a.X[sharedI[1]], a.X[oa], b, b.X[ob], tolerance);
    }
    if (may)
    {
      const vtkIdType ta = this->LeafTriangles[i].Triangle, tb = this->LeafTriangles[j].Triangle;
      out.emplace_back(std::min(ta, tb), std::max(ta, tb));
    }
  };
  // Work items: a node against itself (B < 0), or two nodes whose boxes overlap.
  struct Item
  {
    std::int32_t A, B;
  };
  auto expand = [&](const Item& item, std::vector<Item>& stack, Pairs& out, PatchCulling::Scratch& patch) {
    const Node& a = this->Nodes[item.A];
    if (item.B < 0)
    {
      if (culling.CannotSelfIntersect(item.A, patch))
      {
        return;
      }
      if (a.Count > 0)
      {
        for (std::int32_t i = a.Start; i < a.Start + a.Count; ++i)
        {
          for (std::int32_t j = i + 1; j < a.Start + a.Count; ++j)
          {
            if (overlap(this->LeafTriangles[i].Lo, this->LeafTriangles[i].Hi, this->LeafTriangles[j].Lo,
                  this->LeafTriangles[j].Hi))
            {
              test(i, j, out);
            }
          }
        }
        return;
      }
      stack.push_back({ a.Start, -1 });
      stack.push_back({ a.Start + 1, -1 });
      const Node& l = this->Nodes[a.Start];
      const Node& r = this->Nodes[a.Start + 1];
      if (overlap(l.Lo, l.Hi, r.Lo, r.Hi))
      {
        stack.push_back({ a.Start, a.Start + 1 });
      }
      return;
    }
    const Node& b = this->Nodes[item.B];
    if (a.Count > 0 && b.Count > 0)
    {
      for (std::int32_t i = a.Start; i < a.Start + a.Count; ++i)
      {
        const LeafTriangle& ti = this->LeafTriangles[i];
        if (!overlap(ti.Lo, ti.Hi, b.Lo, b.Hi))
        {
          continue;
        }
        for (std::int32_t j = b.Start; j < b.Start + b.Count; ++j)
        {
          if (overlap(ti.Lo, ti.Hi, this->LeafTriangles[j].Lo, this->LeafTriangles[j].Hi))
          {
            test(i, j, out);
          }
        }
      }
      return;
    }
    // Open the node with more triangles (never a leaf); keep the children that overlap.
    const bool openA = b.Count > 0 || (a.Count == 0 && a.End - a.Begin >= b.End - b.Begin);
    const std::int32_t open = openA ? item.A : item.B, other = openA ? item.B : item.A;
    const Node& o = this->Nodes[other];
    for (std::int32_t child = this->Nodes[open].Start; child <= this->Nodes[open].Start + 1; ++child)
    {
      const Node& c = this->Nodes[child];
      if (overlap(c.Lo, c.Hi, o.Lo, o.Hi))
      {
        stack.push_back({ child, other });
      }
    }
  };
  // The top items, expanded breadth first until there are enough to share out.
  std::vector<Item> top{ { 0, -1 } };
  Pairs found;
  PatchCulling::Scratch topPatch;
  const size_t wanted = 64 * static_cast<size_t>(threads);
  while (!top.empty() && top.size() < wanted)
  {
    std::vector<Item> next;
    for (const Item& item : top)
    {
      expand(item, next, found, topPatch);
    }
    top.swap(next);
  }
  std::vector<Pairs> perThread(threads);
  std::vector<PairSearchStatistics> perThreadStatistics(threads);
#pragma omp parallel num_threads(threads)
  {
    Pairs& out = perThread[omp_get_thread_num()];
    PatchCulling::Scratch patch;
    std::vector<Item> stack;
    stack.reserve(256);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(top.size()); ++i)
    {
      stack.assign(1, top[i]);
      while (!stack.empty())
      {
        const Item item = stack.back();
        stack.pop_back();
        expand(item, stack, out, patch);
      }
    }
    perThreadStatistics[omp_get_thread_num()] = patch.Statistics;
  }
  for (const Pairs& p : perThread)
  {
    found.insert(found.end(), p.begin(), p.end());
  }
  if (statistics)
  {
    *statistics = topPatch.Statistics;
    for (const PairSearchStatistics& s : perThreadStatistics)
    {
      statistics->CullingTests += s.CullingTests;
      statistics->Culled += s.Culled;
      statistics->PinchedCulled += s.PinchedCulled;
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  pairs.swap(found);
}
