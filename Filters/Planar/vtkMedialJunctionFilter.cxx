// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialArrayNames.h"

#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialPolygon.h"
#include "vtkMedialProgress.h"
#include "vtkMedialThreads.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkMedialJunctionFilter);

namespace
{
using Governors = std::vector<int>; // sorted: edges e, reflex vertices E + v

// A place on the boundary: an edge at parameter t in [0, 1], or a reflex vertex's
// cone of inward directions at parameter in [0, 1].
struct Station
{
  int Feature = -1;
  double Param = 0.0;
};

struct Sample
{
  Station Before, After; // differ only at a convex vertex (end point)
  double Centre[2] = { 0, 0 };
  double Radius = 0.0;
  Governors Gov;
  bool End = false;
  int Vertex = -1;
  bool Valid = false;
};

struct Event
{
  double Centre[2];
  double Radius;
  int Count;     // distinct governors touched
  bool IsEnd;
  int Vertex;    // for ends
};

// One walk item: a sample (carrying its governor set) or an event (a graph node).
struct Item
{
  bool IsEvent;
  Governors Gov; // samples; for ends the pair of edges
  Event Ev;
};

struct Disk
{
  double C[2];
  double R;
};

class Solver
{
public:
  Solver(const vtkMedialPolygon& p, double tol)
    : Poly(p)
    , E(p.GetNumberOfEdges())
    , Tol(tol * p.GetDiagonal())
  {
  }

  const vtkMedialPolygon& Poly;
  const int E;
  const double Tol;

  bool IsVertex(int f) const { return f >= this->E; }
  int VertexOf(int f) const { return f - this->E; }

  // Cone of reflex vertex v: directions turning clockwise from the incoming edge's
  // normal to the outgoing edge's.
  double ConeAngle(int v) const
  {
    const double* a = this->Poly.GetEdge(this->Poly.GetIncomingEdge(v)).Normal;
    const double* b = this->Poly.GetEdge(this->Poly.GetOutgoingEdge(v)).Normal;
    return std::atan2(-(a[0] * b[1] - a[1] * b[0]), a[0] * b[0] + a[1] * b[1]);
  }
  void ConeDirection(int v, double param, double d[2]) const
  {
    const double* a = this->Poly.GetEdge(this->Poly.GetIncomingEdge(v)).Normal;
    const double angle = param * this->ConeAngle(v);
    const double c = std::cos(angle), s = std::sin(angle);
    d[0] = a[0] * c + a[1] * s;
    d[1] = -a[0] * s + a[1] * c;
  }

  // Where a disk touches feature f, as that feature's station parameter.
  double ContactParam(int f, const double c[2], double r) const
  {
    if (this->IsVertex(f))
    {
      const int v = this->VertexOf(f);
      const double* p = this->Poly.GetPoint(v);
      const double* a = this->Poly.GetEdge(this->Poly.GetIncomingEdge(v)).Normal;
      const double d[2] = { c[0] - p[0], c[1] - p[1] };
      const double angle = std::atan2(-(a[0] * d[1] - a[1] * d[0]), a[0] * d[0] + a[1] * d[1]);
      return angle / this->ConeAngle(v);
    }
    const auto& e = this->Poly.GetEdge(f);
    const double* a = this->Poly.GetPoint(e.A);
    const double* b = this->Poly.GetPoint(e.B);
    const double q[2] = { c[0] - r * e.Normal[0] - a[0], c[1] - r * e.Normal[1] - a[1] };
    return (q[0] * (b[0] - a[0]) + q[1] * (b[1] - a[1])) / (e.Length * e.Length);
  }

  // Radius at which the disk tangent at p along n first touches point q.
  static double RadiusThrough(const double p[2], const double n[2], const double q[2])
  {
    const double w[2] = { q[0] - p[0], q[1] - p[1] };
    const double along = n[0] * w[0] + n[1] * w[1];
    return along > 0.0 ? (w[0] * w[0] + w[1] * w[1]) / (2.0 * along) : HUGE_VAL;
  }

  // Radius at which the disk tangent at p along n first touches edge g from inside.
  double RadiusTouchingEdge(const double p[2], const double n[2], int g) const
  {
    const auto& e = this->Poly.GetEdge(g);
    double best = std::min(RadiusThrough(p, n, this->Poly.GetPoint(e.A)),
      RadiusThrough(p, n, this->Poly.GetPoint(e.B)));
    const double denom = 1.0 - (e.Normal[0] * n[0] + e.Normal[1] * n[1]);
    if (denom > 1e-15)
    {
      const double r = (e.Normal[0] * p[0] + e.Normal[1] * p[1] + e.Offset) / denom;
      if (r > 0.0 && r < best)
      {
        const double c[2] = { p[0] + r * n[0], p[1] + r * n[1] };
        const double t = this->ContactParam(g, c, r);
        if (t >= 0.0 && t <= 1.0)
        {
          best = r;
        }
      }
    }
    return best;
  }

  // Largest empty disk tangent at p with inward direction n. Exact up to rounding.
  bool MaximalDisk(const double p[2], const double n[2], const vtkMedialPolygon::ContactFilter& filter,
    Disk& out) const
  {
    double t;
    int hitEdge;
    if (!this->Poly.Intersect(p, n, 1e-12 * this->Poly.GetDiagonal(), HUGE_VAL, &filter, t, hitEdge))
    {
      return false;
    }
    double r = 0.5 * t;
    for (int iteration = 0; iteration < 200; ++iteration)
    {
      const double c[2] = { p[0] + r * n[0], p[1] + r * n[1] };
      double q[2], d;
      int g;
      if (!this->Poly.ClosestPoint(c, r * (1.0 - 1e-13), &filter, q, d, g))
      {
        break;
      }
      const double next = std::min(this->RadiusTouchingEdge(p, n, g), RadiusThrough(p, n, q));
      if (!(next < r))
      {
        break;
      }
      r = next;
    }
    out.C[0] = p[0] + r * n[0];
    out.C[1] = p[1] + r * n[1];
    out.R = r;
    return true;
  }

  // Governors a disk touches within Tol. An edge whose closest point is inside it is
  // touched as the edge; one whose closest point is a reflex end is touched as that
  // vertex, unless the vertex's other edge is touched inside: a disk tangent to a
  // line meets it once, so the vertex is then only near, and the set changes exactly
  // where a contact passes the vertex (the transition the solver computes).
  Governors Touching(const double c[2], double r, double tol) const
  {
    Governors edges, vertices;
    this->Poly.VisitEdgesInRing(c, r - tol, r + tol, [&](int e) {
      double q[2];
      const double d = std::sqrt(this->Poly.ClosestPointOnEdge(e, c, nullptr, q));
      if (d > r + tol)
      {
        return;
      }
      const auto& edge = this->Poly.GetEdge(e);
      const double* a = this->Poly.GetPoint(edge.A);
      const double* b = this->Poly.GetPoint(edge.B);
      const double t = ((c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1]) * (b[1] - a[1])) / (edge.Length * edge.Length);
      const int end = t <= 0.0 ? edge.A : (t >= 1.0 ? edge.B : -1);
      if (end >= 0 && this->Poly.GetVertexKind(end) == vtkMedialPolygon::REFLEX)
      {
        vertices.push_back(end);
      }
      else
      {
        edges.push_back(e);
      }
    });
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    Governors g = edges;
    for (int v : vertices)
    {
      if (!std::binary_search(edges.begin(), edges.end(), this->Poly.GetIncomingEdge(v)) &&
        !std::binary_search(edges.begin(), edges.end(), this->Poly.GetOutgoingEdge(v)))
      {
        g.push_back(this->E + v);
      }
    }
    std::sort(g.begin(), g.end());
    g.erase(std::unique(g.begin(), g.end()), g.end());
    return g;
  }

  Sample SampleAt(const Station& s) const
  {
    Sample out;
    out.Before = out.After = s;
    vtkMedialPolygon::ContactFilter filter;
    double p[2], n[2];
    if (this->IsVertex(s.Feature))
    {
      const int v = this->VertexOf(s.Feature);
      p[0] = this->Poly.GetPoint(v)[0];
      p[1] = this->Poly.GetPoint(v)[1];
      this->ConeDirection(v, s.Param, n);
      filter.IgnoreEdge[0] = this->Poly.GetIncomingEdge(v);
      filter.IgnoreEdge[1] = this->Poly.GetOutgoingEdge(v);
    }
    else
    {
      const auto& e = this->Poly.GetEdge(s.Feature);
      const double* a = this->Poly.GetPoint(e.A);
      const double* b = this->Poly.GetPoint(e.B);
      p[0] = a[0] + s.Param * (b[0] - a[0]);
      p[1] = a[1] + s.Param * (b[1] - a[1]);
      n[0] = e.Normal[0];
      n[1] = e.Normal[1];
      filter.IgnoreEdge[0] = s.Feature;
    }
    Disk d;
    if (!this->MaximalDisk(p, n, filter, d))
    {
      return out;
    }
    out.Centre[0] = d.C[0];
    out.Centre[1] = d.C[1];
    out.Radius = d.R;
    out.Gov = this->Touching(d.C, d.R, this->Tol);
    // The own feature always governs (its contact may be within Tol of a reflex end).
    const int own = s.Feature;
    if (!std::binary_search(out.Gov.begin(), out.Gov.end(), own) && this->IsVertex(own))
    {
      out.Gov.insert(std::lower_bound(out.Gov.begin(), out.Gov.end(), own), own);
    }
    out.Valid = true;
    return out;
  }

  Sample EndAt(int v) const
  {
    Sample out;
    const int in = this->Poly.GetIncomingEdge(v), outEdge = this->Poly.GetOutgoingEdge(v);
    out.Before = { in, 1.0 };
    out.After = { outEdge, 0.0 };
    out.Centre[0] = this->Poly.GetPoint(v)[0];
    out.Centre[1] = this->Poly.GetPoint(v)[1];
    out.Radius = 0.0;
    out.Gov = { std::min(in, outEdge), std::max(in, outEdge) };
    out.End = true;
    out.Vertex = v;
    out.Valid = true;
    return out;
  }

  // Disks tangent to three governors (at most 2 solutions): the special cases first,
  // then the general system.
  int SolveTriple(const int f[3], Disk out[2]) const
  {
    int count = 0;
    if (this->SolveTangentAtOwnVertex(f, out, count) || this->SolveFlatCorner(f, out, count))
    {
      return count;
    }
    return this->SolveGeneral(f, out);
  }

  // An edge and its own end vertex: the disk is tangent to the edge at that vertex.
  // False when no such pair is among f.
  bool SolveTangentAtOwnVertex(const int f[3], Disk out[2], int& count) const
  {
    count = 0;
    for (int i = 0; i < 3; ++i)
    {
      if (this->IsVertex(f[i]))
      {
        continue;
      }
      const auto& e = this->Poly.GetEdge(f[i]);
      for (int j = 0; j < 3; ++j)
      {
        if (!this->IsVertex(f[j]) || (this->VertexOf(f[j]) != e.A && this->VertexOf(f[j]) != e.B))
        {
          continue;
        }
        const int h = f[3 - i - j];
        const double* v = this->Poly.GetPoint(this->VertexOf(f[j]));
        double r;
        if (this->IsVertex(h))
        {
          r = RadiusThrough(v, e.Normal, this->Poly.GetPoint(this->VertexOf(h)));
        }
        else
        {
          const auto& g = this->Poly.GetEdge(h);
          if (g.A == this->VertexOf(f[j]) || g.B == this->VertexOf(f[j]))
          {
            return true; // the vertex and both of its edges: no disk
          }
          const double denom = 1.0 - (g.Normal[0] * e.Normal[0] + g.Normal[1] * e.Normal[1]);
          r = denom > 1e-15 ? (g.Normal[0] * v[0] + g.Normal[1] * v[1] + g.Offset) / denom : HUGE_VAL;
        }
        if (!(r > 0.0 && r < HUGE_VAL))
        {
          return true;
        }
        out[0].C[0] = v[0] + r * e.Normal[0];
        out[0].C[1] = v[1] + r * e.Normal[1];
        out[0].R = r;
        count = 1;
        return true;
      }
    }
    return false;
  }

  // Two edges meeting at a nearly straight convex vertex V: the disk's centre is on
  // their bisector, c = V + s b with r = s (n1 . b). Solving along it stays exact
  // however flat the corner, where the general system loses all precision (its
  // condition grows as 1 / turn angle). Sharp corners keep the general system.
  // False when f has no such corner.
  bool SolveFlatCorner(const int f[3], Disk out[2], int& count) const
  {
    count = 0;
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        if (i == j || this->IsVertex(f[i]) || this->IsVertex(f[j]))
        {
          continue;
        }
        const auto& e1 = this->Poly.GetEdge(f[i]);
        const auto& e2 = this->Poly.GetEdge(f[j]);
        const double half = 0.5 * std::hypot(e1.Normal[0] - e2.Normal[0], e1.Normal[1] - e2.Normal[1]);
        if (e1.B != e2.A || this->Poly.GetVertexKind(e1.B) != vtkMedialPolygon::CONVEX || half > 1e-3)
        {
          continue;
        }
        const double* V = this->Poly.GetPoint(e1.B);
        double b[2] = { e1.Normal[0] + e2.Normal[0], e1.Normal[1] + e2.Normal[1] };
        const double bl = std::hypot(b[0], b[1]);
        b[0] /= bl;
        b[1] /= bl;
        const double rate = e1.Normal[0] * b[0] + e1.Normal[1] * b[1]; // r per unit of s
        double roots[2];
        const int nr = this->BisectorRoots(V, b, rate, half, f[3 - i - j], roots);
        for (int k = 0; k < nr; ++k)
        {
          const double r = rate * roots[k];
          if (r > 0.0 && std::isfinite(r))
          {
            out[count].C[0] = V[0] + roots[k] * b[0];
            out[count].C[1] = V[1] + roots[k] * b[1];
            out[count].R = r;
            ++count;
          }
        }
        return true;
      }
    }
    return false;
  }

  // Where along the bisector V + s b (radius rate * s) the disk touches governor h.
  int BisectorRoots(const double V[2], const double b[2], double rate, double half, int h, double roots[2]) const
  {
    int nr = 0;
    if (!this->IsVertex(h))
    {
      const auto& g = this->Poly.GetEdge(h);
      const double denom = rate - (g.Normal[0] * b[0] + g.Normal[1] * b[1]);
      if (std::abs(denom) > 1e-15)
      {
        roots[nr++] = (g.Normal[0] * V[0] + g.Normal[1] * V[1] + g.Offset) / denom;
      }
      return nr;
    }
    // |V + s b - q|^2 = (rate s)^2: (1 - rate^2) s^2 + 2 s b.(V - q) + |V - q|^2 = 0.
    const double* q = this->Poly.GetPoint(this->VertexOf(h));
    const double w[2] = { V[0] - q[0], V[1] - q[1] };
    const double qa = half * half; // 1 - rate^2, without cancellation
    const double qb = 2.0 * (b[0] * w[0] + b[1] * w[1]);
    const double qc = w[0] * w[0] + w[1] * w[1];
    if (qa < 1e-30 * (qb * qb + qc))
    {
      if (qb != 0.0)
      {
        roots[nr++] = -qc / qb;
      }
      return nr;
    }
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0)
    {
      const double t = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (t != 0.0)
      {
        roots[nr++] = t / qa;
        roots[nr++] = qc / t;
      }
    }
    return nr;
  }

  // The general system. Unknowns X = (cx, cy, r). Edges give n.c - r = -k; vertex
  // pairs give 2 (vi - v0).c = |vi|^2 - |v0|^2; the first vertex gives |c - v0|^2 = r^2.
  int SolveGeneral(const int f[3], Disk out[2]) const
  {
    double rows[3][4];
    int m = 0;
    const double* v0 = nullptr;
    for (int i = 0; i < 3; ++i)
    {
      if (!this->IsVertex(f[i]))
      {
        const auto& e = this->Poly.GetEdge(f[i]);
        rows[m][0] = e.Normal[0];
        rows[m][1] = e.Normal[1];
        rows[m][2] = -1.0;
        rows[m][3] = -e.Offset;
        ++m;
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      if (this->IsVertex(f[i]))
      {
        const double* v = this->Poly.GetPoint(this->VertexOf(f[i]));
        if (!v0)
        {
          v0 = v;
          continue;
        }
        rows[m][0] = 2.0 * (v[0] - v0[0]);
        rows[m][1] = 2.0 * (v[1] - v0[1]);
        rows[m][2] = 0.0;
        rows[m][3] = (v[0] * v[0] + v[1] * v[1]) - (v0[0] * v0[0] + v0[1] * v0[1]);
        ++m;
      }
    }
    return m == 3 ? SolveLinear(rows, out) : SolveLineAndCircle(rows, v0, out);
  }

  // Three linear rows (three edges): Cramer's rule.
  static int SolveLinear(const double rows[3][4], Disk out[2])
  {
    auto det3 = [](const double a[3], const double b[3], const double c[3]) {
      return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
        a[2] * (b[0] * c[1] - b[1] * c[0]);
    };
    const double a[3] = { rows[0][0], rows[1][0], rows[2][0] };
    const double b[3] = { rows[0][1], rows[1][1], rows[2][1] };
    const double c[3] = { rows[0][2], rows[1][2], rows[2][2] };
    const double rhs[3] = { rows[0][3], rows[1][3], rows[2][3] };
    const double det = det3(a, b, c);
    if (std::abs(det) < 1e-14)
    {
      return 0;
    }
    out[0].C[0] = det3(rhs, b, c) / det;
    out[0].C[1] = det3(a, rhs, c) / det;
    out[0].R = det3(a, b, rhs) / det;
    return out[0].R > 0.0 ? 1 : 0;
  }

  // Two linear rows: a line X0 + s D, then the quadratic of vertex v0.
  static int SolveLineAndCircle(const double rows[3][4], const double* v0, Disk out[2])
  {
    const double* r0 = rows[0];
    const double* r1 = rows[1];
    const double D[3] = { r0[1] * r1[2] - r0[2] * r1[1], r0[2] * r1[0] - r0[0] * r1[2],
      r0[0] * r1[1] - r0[1] * r1[0] };
    int k = 0;
    for (int i = 1; i < 3; ++i)
    {
      if (std::abs(D[i]) > std::abs(D[k]))
      {
        k = i;
      }
    }
    const double scale = std::max({ std::abs(r0[0]), std::abs(r0[1]), std::abs(r0[2]) }) *
      std::max({ std::abs(r1[0]), std::abs(r1[1]), std::abs(r1[2]) });
    if (!(std::abs(D[k]) > 1e-14 * scale))
    {
      return 0;
    }
    // X_k = 0; solve the 2x2 in the other two unknowns.
    const int i0 = (k + 1) % 3, i1 = (k + 2) % 3;
    const double det = r0[i0] * r1[i1] - r0[i1] * r1[i0];
    double X0[3] = { 0, 0, 0 };
    X0[i0] = (r0[3] * r1[i1] - r0[i1] * r1[3]) / det;
    X0[i1] = (r0[i0] * r1[3] - r0[3] * r1[i0]) / det;
    const double px = X0[0] - v0[0], py = X0[1] - v0[1];
    const double qa = D[0] * D[0] + D[1] * D[1] - D[2] * D[2];
    const double qb = 2.0 * (px * D[0] + py * D[1] - X0[2] * D[2]);
    const double qc = px * px + py * py - X0[2] * X0[2];
    double roots[2];
    const int nr = StableQuadraticRoots(qa, qb, qc, D, roots);
    int count = 0;
    for (int i = 0; i < nr; ++i)
    {
      const double x[3] = { X0[0] + roots[i] * D[0], X0[1] + roots[i] * D[1], X0[2] + roots[i] * D[2] };
      const double r = rows[0][2] == 0.0 && rows[1][2] == 0.0
        ? std::hypot(x[0] - v0[0], x[1] - v0[1]) // three vertices: r only through the quadratic
        : x[2];
      if (r > 0.0)
      {
        out[count].C[0] = x[0];
        out[count].C[1] = x[1];
        out[count].R = r;
        ++count;
      }
    }
    return count;
  }

  // Roots of qa s^2 + qb s + qc (linear when qa is negligible against |D|^2).
  static int StableQuadraticRoots(double qa, double qb, double qc, const double D[3], double roots[2])
  {
    int nr = 0;
    if (std::abs(qa) < 1e-14 * (D[0] * D[0] + D[1] * D[1] + D[2] * D[2]))
    {
      if (qb != 0.0)
      {
        roots[nr++] = -qc / qb;
      }
      return nr;
    }
    double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0 && disc > -1e-12 * qb * qb)
    {
      disc = 0.0;
    }
    if (disc >= 0.0)
    {
      // Stable form: no cancellation between -b and sqrt(disc).
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      if (q != 0.0)
      {
        roots[nr++] = q / qa;
        roots[nr++] = qc / q;
      }
      else
      {
        roots[nr++] = 0.0;
      }
    }
    return nr;
  }

  // The disk touches each of f validly, lies between stations a and b, and is empty.
  bool Accept(const Disk& d, const int f[3], const Station& a, const Station& b) const
  {
    // Governor sets change where a contact comes within Tol, not exactly at the
    // event; at a transition (tangential contact) that shifts the change along the
    // boundary by up to sqrt(2 r Tol). Stations are compared with that slack.
    // The contacts themselves must lie on their edges (or in their vertex's cone) to
    // rounding: a line's tangency just beyond the segment's end is a different disk.
    const double slack = 2.0 * std::sqrt(2.0 * d.R * this->Tol) + 2.0 * this->Tol;
    for (int i = 0; i < 3; ++i)
    {
      const double t = this->ContactParam(f[i], d.C, d.R);
      const bool vertex = this->IsVertex(f[i]);
      // Up to Tol of overshoot: near-collinear edges put an exact contact at a shared
      // vertex only to within rounding amplified by their conditioning.
      const double inside = vertex
        ? std::max(1e-9, this->Tol / std::max(d.R, this->Tol)) / this->ConeAngle(this->VertexOf(f[i]))
        : std::max(1e-9, this->Tol / this->Poly.GetEdge(f[i]).Length);
      if (!(t >= -inside && t <= 1.0 + inside))
      {
        return false;
      }
      if (vertex &&
        std::abs(std::hypot(d.C[0] - this->Poly.GetPoint(this->VertexOf(f[i]))[0],
                   d.C[1] - this->Poly.GetPoint(this->VertexOf(f[i]))[1]) -
          d.R) > 1e-3 * this->Tol)
      {
        return false;
      }
      const double eps = vertex
        ? slack / (std::max(d.R, this->Tol) * this->ConeAngle(this->VertexOf(f[i])))
        : slack / this->Poly.GetEdge(f[i]).Length;
      if (f[i] == a.Feature && t < a.Param - eps)
      {
        return false;
      }
      if (f[i] == b.Feature && t > b.Param + eps)
      {
        return false;
      }
    }
    double q[2], dist;
    int g;
    return !this->Poly.ClosestPoint(d.C, d.R - this->Tol, nullptr, q, dist, g);
  }

  // Station halfway between a and b along the walk; false when they meet.
  static bool Midway(const Station& a, const Station& b, Station& m)
  {
    if (a.Feature == b.Feature)
    {
      m = { a.Feature, 0.5 * (a.Param + b.Param) };
      return b.Param - a.Param > 1e-13;
    }
    if (a.Param < 1.0 - 1e-13)
    {
      m = { a.Feature, 0.5 * (a.Param + 1.0) };
      return true;
    }
    if (b.Param > 1e-13)
    {
      m = { b.Feature, 0.5 * b.Param };
      return true;
    }
    return false;
  }

  static bool Includes(const Governors& big, const Governors& small)
  {
    return std::includes(big.begin(), big.end(), small.begin(), small.end());
  }

  Event MakeEvent(const Disk& d) const
  {
    Event ev;
    ev.Centre[0] = d.C[0];
    ev.Centre[1] = d.C[1];
    ev.Radius = d.R;
    // Solved disks are exact to rounding: count their governors tightly, so that a
    // transition next to a grazing third governor is not taken for a junction.
    ev.Count = static_cast<int>(this->Touching(d.C, d.R, 1e-3 * this->Tol).size());
    ev.IsEnd = false;
    ev.Vertex = -1;
    return ev;
  }

  Item SampleItem(const Sample& s) const
  {
    Item it;
    it.IsEvent = s.End || s.Gov.size() >= 3;
    it.Gov = s.Gov;
    it.Ev.Centre[0] = s.Centre[0];
    it.Ev.Centre[1] = s.Centre[1];
    it.Ev.Radius = s.Radius;
    it.Ev.Count = s.End ? 2 : static_cast<int>(s.Gov.size());
    it.Ev.IsEnd = s.End;
    it.Ev.Vertex = s.Vertex;
    if (it.IsEvent && !s.End)
    {
      // A sample touching 3+ governors within Tol lies near an event, or on a branch
      // grazing a third governor. Take the exact, valid, empty solution of three of
      // its governors nearest to it; without one the sample is a regular point.
      const size_t n = s.Gov.size();
      double best = 1e-3 * this->Poly.GetDiagonal();
      bool found = false;
      // Large sets (a regular n-gon's centre) only need triples with the own feature.
      const size_t own = static_cast<size_t>(
        std::lower_bound(s.Gov.begin(), s.Gov.end(), s.After.Feature) - s.Gov.begin());
      for (size_t i = 0; i < n; ++i)
      {
        if (n > 12 && i != own)
        {
          continue;
        }
        // Any three governors of an exact event give it: a few pairs are enough.
        const size_t last = n > 12 ? std::min<size_t>(n, 7) : n;
        for (size_t j = n > 12 ? 0 : i + 1; j < last; ++j)
        {
          for (size_t k = j + 1; k < last; ++k)
          {
            if (j == i || k == i)
            {
              continue;
            }
            const int f[3] = { s.Gov[i], s.Gov[j], s.Gov[k] };
            Disk d[2];
            const int m = this->SolveTriple(f, d);
            for (int q = 0; q < m; ++q)
            {
              const double dist = std::hypot(d[q].C[0] - s.Centre[0], d[q].C[1] - s.Centre[1]);
              if (dist < best && this->Accept(d[q], f, Station(), Station()))
              {
                best = dist;
                it.Ev = this->MakeEvent(d[q]);
                found = true;
              }
            }
          }
        }
      }
      it.IsEvent = found;
    }
    return it;
  }

  // Appends the first disk tangent to governors f that Accept takes between stations
  // a and b, as an event; false when there is none.
  bool AddEventOf(const int f[3], const Station& a, const Station& b, std::vector<Item>& items) const
  {
    Disk d[2];
    const int n = this->SolveTriple(f, d);
    for (int i = 0; i < n; ++i)
    {
      if (this->Accept(d[i], f, a, b))
      {
        Item it;
        it.IsEvent = true;
        it.Ev = this->MakeEvent(d[i]);
        items.push_back(it);
        return true;
      }
    }
    return false;
  }

  // Appends the items strictly between samples a and b, in walk order.
  void FindEvents(const Sample& a, const Sample& b, int depth, std::vector<Item>& items, int& unresolved) const
  {
    if (!a.Valid || !b.Valid || Includes(a.Gov, b.Gov) || Includes(b.Gov, a.Gov))
    {
      return;
    }
    Governors u;
    std::set_union(a.Gov.begin(), a.Gov.end(), b.Gov.begin(), b.Gov.end(), std::back_inserter(u));
    if (u.size() == 3)
    {
      const int f[3] = { u[0], u[1], u[2] };
      if (this->AddEventOf(f, a.After, b.Before, items))
      {
        return;
      }
    }
    Station mid;
    if (depth >= 60 || !Midway(a.After, b.Before, mid))
    {
      // Several changes at one point (e.g. two transitions facing each other across
      // a strip): any valid triple of the union describes it.
      for (size_t i = 0; i < u.size() && u.size() <= 12; ++i)
      {
        for (size_t j = i + 1; j < u.size(); ++j)
        {
          for (size_t k = j + 1; k < u.size(); ++k)
          {
            const int f[3] = { u[i], u[j], u[k] };
            if (this->AddEventOf(f, a.After, b.Before, items))
            {
              return;
            }
          }
        }
      }
      ++unresolved;
      return;
    }
    const Sample m = this->SampleAt(mid);
    this->FindEvents(a, m, depth + 1, items, unresolved);
    if (m.Valid)
    {
      items.push_back(SampleItem(m));
    }
    this->FindEvents(m, b, depth + 1, items, unresolved);
  }
};

struct Node
{
  double Centre[2];
  double Radius;
  int Type;
  int Count;
  int Polygon;
};

// Merges nodes of one polygon closer than a tolerance (a junction is found from
// every side).
class NodeSet
{
public:
  explicit NodeSet(double tol)
    : Tol(tol)
  {
  }
  int Add(const Event& ev, int polygon)
  {
    const long long ix = static_cast<long long>(std::floor(ev.Centre[0] / this->Tol));
    const long long iy = static_cast<long long>(std::floor(ev.Centre[1] / this->Tol));
    const int type = ev.IsEnd ? vtkMedialJunctionFilter::END_POINT
                              : (ev.Count >= 3 ? vtkMedialJunctionFilter::JUNCTION_POINT
                                               : vtkMedialJunctionFilter::REGULAR_POINT);
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        auto it = this->Cells.find(Key(ix + dx, iy + dy));
        if (it == this->Cells.end())
        {
          continue;
        }
        for (int id : it->second)
        {
          Node& n = this->Nodes[id];
          if (n.Polygon == polygon && std::hypot(n.Centre[0] - ev.Centre[0], n.Centre[1] - ev.Centre[1]) <= this->Tol)
          {
            n.Count = std::max(n.Count, ev.Count);
            n.Type = n.Type == vtkMedialJunctionFilter::END_POINT ? n.Type : std::max(n.Type, type);
            return id;
          }
        }
      }
    }
    const int id = static_cast<int>(this->Nodes.size());
    this->Nodes.push_back({ { ev.Centre[0], ev.Centre[1] }, ev.Radius, type, ev.IsEnd ? 2 : ev.Count, polygon });
    this->Cells[Key(ix, iy)].push_back(id);
    return id;
  }
  std::vector<Node> Nodes;

private:
  static long long Key(long long x, long long y) { return x * 1000003LL + y; }
  double Tol;
  std::unordered_map<long long, std::vector<int>> Cells;
};

// An arc of the graph between nodes A and B of one polygon, with the governor pair
// that traces it.
struct Arc
{
  int A, B;
  Governors Pair;
  int Polygon;
};

// The passes of vtkMedialJunctionFilter::RequestData on one prepared polygon, in the
// order of the class comment: Walk, SolveSamples, FindAllEvents, Connect. Each
// parallel pass works in blocks, reporting progress and honouring an abort between them.
class JunctionPasses
{
public:
  JunctionPasses(vtkMedialJunctionFilter* self, const vtkMedialPolygon& poly, const Solver& solver, int threads)
    : Self(self)
    , Poly(poly)
    , S(solver)
    , Threads(threads)
  {
  }

  // 1. The walk: stations in boundary order, loop by loop. Returns the samples to solve.
  vtkIdType Walk(double samplesPerUnitLength, int minimumSamplesPerEdge)
  {
    const vtkMedialPolygon& poly = this->Poly;
    this->Walks.assign(static_cast<size_t>(poly.GetNumberOfLoops()), {});
    for (int loop = 0; loop < poly.GetNumberOfLoops(); ++loop)
    {
      // Each polygon is sampled as if it were alone: by its own diagonal.
      const double diagonal = poly.GetPolygonDiagonal(poly.GetLoopPolygon(loop));
      auto& walk = this->Walks[loop];
      for (int e : poly.GetLoopEdges(loop))
      {
        const auto& edge = poly.GetEdge(e);
        if (poly.GetVertexKind(edge.A) == vtkMedialPolygon::CONVEX)
        {
          walk.push_back(this->S.EndAt(edge.A));
        }
        const int n = std::max(minimumSamplesPerEdge,
          static_cast<int>(std::ceil(samplesPerUnitLength * edge.Length / diagonal)));
        for (int k = 0; k < n; ++k)
        {
          this->AddStation(loop, { e, (k + 0.5) / n });
        }
        if (poly.GetVertexKind(edge.B) == vtkMedialPolygon::REFLEX)
        {
          const int v = edge.B;
          const int m =
            std::max(1, static_cast<int>(std::ceil(this->S.ConeAngle(v) / (3.14159265358979323846 / 2))));
          for (int k = 0; k <= m; ++k)
          {
            this->AddStation(loop, { poly.GetNumberOfEdges() + v, static_cast<double>(k) / m });
          }
        }
      }
    }
    return static_cast<vtkIdType>(this->ToSolve.size());
  }

  // 2. The maximal disks of the samples. False when aborted.
  bool SolveSamples()
  {
    const vtkIdType count = static_cast<vtkIdType>(this->ToSolve.size());
    return this->InBlocks(count, [this](vtkIdType i) {
      Sample& s = this->Walks[this->ToSolve[i].first][this->ToSolve[i].second];
      s = this->S.SampleAt(s.Before);
    });
  }

  // 3. The events between neighbouring samples, interval by interval. False when
  // aborted; `unresolved` counts the intervals without an answer.
  bool FindAllEvents(vtkIdType& unresolved)
  {
    std::vector<std::pair<int, size_t>> intervals;
    for (int loop = 0; loop < this->Poly.GetNumberOfLoops(); ++loop)
    {
      for (size_t i = 0; i < this->Walks[loop].size(); ++i)
      {
        intervals.emplace_back(loop, i);
      }
    }
    this->Found.assign(intervals.size(), {});
    std::vector<int> failed(intervals.size(), 0);
    const bool done =
      this->InBlocks(static_cast<vtkIdType>(intervals.size()), [&](vtkIdType i) {
        const auto& walk = this->Walks[intervals[i].first];
        const size_t k = intervals[i].second;
        this->S.FindEvents(walk[k], walk[(k + 1) % walk.size()], 0, this->Found[i], failed[i]);
      });
    if (!done)
    {
      return false;
    }
    unresolved = 0;
    for (int u : failed)
    {
      unresolved += u;
    }
    // A sample without a disk (its ray found no far side) hides its two intervals.
    for (const auto& walk : this->Walks)
    {
      for (const Sample& s : walk)
      {
        unresolved += s.Valid ? 0 : 2;
      }
    }
    return true;
  }

  // 4. Nodes and arcs, in walk order: consecutive events of a loop's walk are joined
  // by one arc, found once from each side and kept once.
  void Connect(NodeSet& nodes, std::vector<Arc>& arcs) const
  {
    std::map<std::tuple<int, int, Governors>, bool> seen;
    size_t next = 0;
    for (int loop = 0; loop < this->Poly.GetNumberOfLoops(); ++loop)
    {
      // Flatten the loop's walk: samples and events in order.
      std::vector<Item> items;
      for (size_t i = 0; i < this->Walks[loop].size(); ++i, ++next)
      {
        if (this->Walks[loop][i].Valid)
        {
          items.push_back(this->S.SampleItem(this->Walks[loop][i]));
        }
        items.insert(items.end(), this->Found[next].begin(), this->Found[next].end());
      }
      std::vector<size_t> eventAt;
      std::vector<int> nodeOf;
      for (size_t i = 0; i < items.size(); ++i)
      {
        if (items[i].IsEvent)
        {
          eventAt.push_back(i);
          nodeOf.push_back(nodes.Add(items[i].Ev, this->Poly.GetLoopPolygon(loop)));
        }
      }
      for (size_t j = 0; j < eventAt.size(); ++j)
      {
        const int a = nodeOf[j], b = nodeOf[(j + 1) % eventAt.size()];
        if (a == b)
        {
          continue;
        }
        const Governors pair = ArcPair(items, eventAt[j], eventAt[(j + 1) % eventAt.size()]);
        auto key = std::make_tuple(std::min(a, b), std::max(a, b), pair);
        if (seen.emplace(key, true).second)
        {
          arcs.push_back({ a, b, pair, this->Poly.GetLoopPolygon(loop) });
        }
      }
    }
  }

private:
  void AddStation(int loop, const Station& station)
  {
    Sample s;
    s.Before = s.After = station;
    this->ToSolve.emplace_back(loop, this->Walks[loop].size());
    this->Walks[loop].push_back(s);
  }

  // Runs work(i) for i in [0, count) in parallel blocks, reporting the fraction done
  // (the stage's progress). False when aborted.
  template <class Work>
  bool InBlocks(vtkIdType count, Work&& work) const
  {
    const vtkIdType block = 16384;
    for (vtkIdType begin = 0; begin < count && !this->Self->GetAbortExecute(); begin += block)
    {
      const vtkIdType end = std::min(count, begin + block);
#pragma omp parallel for num_threads(this->Threads) schedule(dynamic, 64)
      for (vtkIdType i = begin; i < end; ++i)
      {
        work(i);
      }
      this->Self->UpdateProgress(static_cast<double>(end) / static_cast<double>(count));
    }
    return !this->Self->GetAbortExecute();
  }

  // The governor pair of the arc between the events at `from` and `to`: an end's
  // edges, or the first two-governor sample between them.
  static Governors ArcPair(const std::vector<Item>& items, size_t from, size_t to)
  {
    if (items[from].Ev.IsEnd)
    {
      return items[from].Gov;
    }
    if (items[to].Ev.IsEnd)
    {
      return items[to].Gov;
    }
    for (size_t i = (from + 1) % items.size(); i != to; i = (i + 1) % items.size())
    {
      if (!items[i].IsEvent && items[i].Gov.size() == 2)
      {
        return items[i].Gov;
      }
    }
    return Governors();
  }

  vtkMedialJunctionFilter* Self;
  const vtkMedialPolygon& Poly;
  const Solver& S;
  const int Threads;
  std::vector<std::vector<Sample>> Walks;
  std::vector<std::pair<int, size_t>> ToSolve; // (loop, index)
  std::vector<std::vector<Item>> Found;         // per interval
};

// 5. The output in the input's plane: nodes (a regular node where 3 or more arcs meet
// becomes a junction), then one line per arc, parabolic arcs sampled at `resolution`
// inner points. Returns the number of junctions and end points.
void WriteGraph(const vtkMedialPolygon& poly, NodeSet& nodes, const std::vector<Arc>& arcs, int resolution,
  vtkPolyData* output, vtkIdType& junctions, vtkIdType& ends)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  vtkNew<vtkIntArray> type;
  type->SetName(vtkMedialArrayNames::MedialPointType);
  vtkNew<vtkIntArray> governors;
  governors->SetName(vtkMedialArrayNames::GovernorCount);
  auto addPoint = [&](const double c[2], double r, int t, int g) {
    double x[3];
    poly.To3D(c, x);
    radius->InsertNextValue(r);
    type->InsertNextValue(t);
    governors->InsertNextValue(g);
    return points->InsertNextPoint(x);
  };
  // Where 3 or more arcs meet is a junction even if its disk, solved in an
  // ill-conditioned corner (nearly straight vertices of a sampled curve), touched
  // its third governor just outside the tight event tolerance.
  std::vector<int> degree(nodes.Nodes.size(), 0);
  for (const Arc& arc : arcs)
  {
    ++degree[arc.A];
    ++degree[arc.B];
  }
  junctions = ends = 0;
  for (size_t i = 0; i < nodes.Nodes.size(); ++i)
  {
    Node& n = nodes.Nodes[i];
    if (n.Type == vtkMedialJunctionFilter::REGULAR_POINT && degree[i] >= 3)
    {
      n.Type = vtkMedialJunctionFilter::JUNCTION_POINT;
      n.Count = std::max(n.Count, degree[i]);
    }
  }
  for (const Node& n : nodes.Nodes)
  {
    addPoint(n.Centre, n.Radius, n.Type, n.Count);
    junctions += n.Type == vtkMedialJunctionFilter::JUNCTION_POINT ? 1 : 0;
    ends += n.Type == vtkMedialJunctionFilter::END_POINT ? 1 : 0;
  }
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> arcType;
  arcType->SetName(vtkMedialArrayNames::ArcType);
  vtkNew<vtkIntArray> polygonId;
  polygonId->SetName(vtkMedialArrayNames::PolygonId);
  const int E = poly.GetNumberOfEdges();
  for (const Arc& arc : arcs)
  {
    const bool parabolic = arc.Pair.size() == 2 && ((arc.Pair[0] < E) != (arc.Pair[1] < E));
    std::vector<vtkIdType> ids = { arc.A };
    if (parabolic)
    {
      // Centre over the foot point s on the edge: r = |v - F|^2 / (2 n.(v - F)).
      const auto& e = poly.GetEdge(arc.Pair[0]);
      const double* v = poly.GetPoint(arc.Pair[1] - E);
      const double* o = poly.GetPoint(e.A);
      const double dir[2] = { -e.Normal[1], e.Normal[0] }; // along the edge (interior on the left)
      auto along = [&](const Node& n) {
        const double q[2] = { n.Centre[0] - o[0], n.Centre[1] - o[1] };
        return q[0] * dir[0] + q[1] * dir[1];
      };
      const double s0 = along(nodes.Nodes[arc.A]), s1 = along(nodes.Nodes[arc.B]);
      for (int k = 1; k <= resolution; ++k)
      {
        const double s = s0 + (s1 - s0) * k / (resolution + 1.0);
        const double F[2] = { o[0] + s * dir[0], o[1] + s * dir[1] };
        const double r = Solver::RadiusThrough(F, e.Normal, v);
        if (!(r < HUGE_VAL))
        {
          continue;
        }
        const double c[2] = { F[0] + r * e.Normal[0], F[1] + r * e.Normal[1] };
        ids.push_back(addPoint(c, r, vtkMedialJunctionFilter::REGULAR_POINT, 2));
      }
    }
    ids.push_back(arc.B);
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    arcType->InsertNextValue(parabolic ? vtkMedialJunctionFilter::PARABOLIC_ARC : vtkMedialJunctionFilter::LINEAR_ARC);
    polygonId->InsertNextValue(arc.Polygon);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetActiveScalars(vtkMedialArrayNames::Radius);
  output->GetPointData()->AddArray(type);
  output->GetPointData()->AddArray(governors);
  output->GetCellData()->AddArray(arcType);
  output->GetCellData()->AddArray(polygonId);
}
}

vtkMedialJunctionFilter::vtkMedialJunctionFilter() = default;

int vtkMedialJunctionFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialJunctionFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The graph needs every loop of the polygon, whatever piece is requested.
  vtkMedialRequestWholeInput(inputVector);
  return 1;
}

int vtkMedialJunctionFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfJunctions = 0;
  this->NumberOfEndPoints = 0;
  this->NumberOfBoundarySamples = 0;
  this->UnresolvedIntervals = 0;
  this->NumberOfPolygons = 0;
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 holds the whole graph
  }

  vtkMedialStages stages(this);
  stages.Begin("Preparing the polygon", 0.0, 0.02);
  vtkMedialPolygon poly;
  std::string error;
  if (!poly.Build(input, error))
  {
    vtkErrorMacro(<< "Cannot compute the medial graph: " << error << ".");
    return 0;
  }
  this->NumberOfPolygons = poly.GetNumberOfPolygons();
  const Solver solver(poly, this->Tolerance);
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  JunctionPasses passes(this, poly, solver, threads);
  this->NumberOfBoundarySamples = passes.Walk(this->SamplesPerUnitLength, this->MinimumSamplesPerEdge);
  stages.Begin("Solving the boundary disks", 0.02, 0.5);
  if (!passes.SolveSamples())
  {
    return 1; // aborted: leave the output empty
  }
  stages.Begin("Finding the junctions", 0.5, 0.9);
  if (!passes.FindAllEvents(this->UnresolvedIntervals))
  {
    return 1;
  }
  stages.Begin("Connecting the graph", 0.9, 1.0);
  NodeSet nodes(1e-8 * poly.GetDiagonal());
  std::vector<Arc> arcs;
  passes.Connect(nodes, arcs);
  WriteGraph(poly, nodes, arcs, this->ArcResolution, output, this->NumberOfJunctions, this->NumberOfEndPoints);

  if (this->UnresolvedIntervals > 0)
  {
    vtkWarningMacro(<< this->UnresolvedIntervals
                    << " sample interval(s) could not be resolved; the graph may miss junctions there.");
  }
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialJunctionFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerUnitLength: " << this->SamplesPerUnitLength << "\n";
  os << indent << "MinimumSamplesPerEdge: " << this->MinimumSamplesPerEdge << "\n";
  os << indent << "ArcResolution: " << this->ArcResolution << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfJunctions: " << this->NumberOfJunctions << "\n";
  os << indent << "NumberOfEndPoints: " << this->NumberOfEndPoints << "\n";
  os << indent << "NumberOfBoundarySamples: " << this->NumberOfBoundarySamples << "\n";
  os << indent << "UnresolvedIntervals: " << this->UnresolvedIntervals << "\n";
  os << indent << "NumberOfPolygons: " << this->NumberOfPolygons << "\n";
}
