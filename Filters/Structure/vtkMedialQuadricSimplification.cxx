// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialQuadricSimplification.h"

#include "vtkMedialEnvelope.h"
#include "vtkMedialSimplicialComplex.h"
#include "vtkMedialUniformGrid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <queue>

namespace
{
constexpr double Pi = 3.14159265358979323846;
// Index of (i, j), i <= j, in the upper triangle of a symmetric 4 x 4 matrix.
constexpr int Sym[4][4] = { { 0, 1, 2, 3 }, { 1, 4, 5, 6 }, { 2, 5, 7, 8 }, { 3, 6, 8, 9 } };
// Cone tangent planes per edge of no triangle.
constexpr int ConePlanes = 8;

double Distance(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

void Insert(std::vector<vtkIdType>& sorted, vtkIdType x)
{
  auto at = std::lower_bound(sorted.begin(), sorted.end(), x);
  if (at == sorted.end() || *at != x)
  {
    sorted.insert(at, x);
  }
}

void Erase(std::vector<vtkIdType>& sorted, vtkIdType x)
{
  auto at = std::lower_bound(sorted.begin(), sorted.end(), x);
  if (at != sorted.end() && *at == x)
  {
    sorted.erase(at);
  }
}
}

void vtkMedialQuadricSimplification::Quadric::AddPlane(const double n[3], double d, double weight)
{
  const double v[4] = { n[0], n[1], n[2], 1.0 };
  this->AddLinearForm(v, d, weight);
}

void vtkMedialQuadricSimplification::Quadric::AddCentrePlane(const double n[3], double d, double weight)
{
  const double v[4] = { n[0], n[1], n[2], 0.0 };
  this->AddLinearForm(v, d, weight);
}

void vtkMedialQuadricSimplification::Quadric::AddLinearForm(const double v[4], double d, double weight)
{
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i; j < 4; ++j)
    {
      this->A[Sym[i][j]] += weight * v[i] * v[j];
    }
    this->B[i] += weight * d * v[i];
  }
  this->C += weight * d * d;
}

void vtkMedialQuadricSimplification::Quadric::Add(const Quadric& q)
{
  for (int k = 0; k < 10; ++k)
  {
    this->A[k] += q.A[k];
  }
  for (int k = 0; k < 4; ++k)
  {
    this->B[k] += q.B[k];
  }
  this->C += q.C;
}

double vtkMedialQuadricSimplification::Quadric::Evaluate(const double m[4]) const
{
  double e = this->C;
  for (int i = 0; i < 4; ++i)
  {
    double row = 0.0;
    for (int j = 0; j < 4; ++j)
    {
      row += this->A[Sym[i][j]] * m[j];
    }
    e += m[i] * row - 2.0 * this->B[i] * m[i];
  }
  return std::max(0.0, e);
}

bool vtkMedialQuadricSimplification::Quadric::Minimise(double m[4]) const
{
  // Gaussian elimination with partial pivoting on [A | B].
  double a[4][5];
  double largest = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      a[i][j] = this->A[Sym[i][j]];
    }
    a[i][4] = this->B[i];
    largest = std::max(largest, std::abs(a[i][i]));
  }
  for (int col = 0; col < 4; ++col)
  {
    int pivot = col;
    for (int i = col + 1; i < 4; ++i)
    {
      pivot = std::abs(a[i][col]) > std::abs(a[pivot][col]) ? i : pivot;
    }
    if (!(std::abs(a[pivot][col]) > 1e-10 * largest))
    {
      return false;
    }
    std::swap(a[col], a[pivot]);
    for (int i = col + 1; i < 4; ++i)
    {
      const double f = a[i][col] / a[col][col];
      for (int j = col; j < 5; ++j)
      {
        a[i][j] -= f * a[col][j];
      }
    }
  }
  for (int i = 3; i >= 0; --i)
  {
    double s = a[i][4];
    for (int j = i + 1; j < 4; ++j)
    {
      s -= a[i][j] * m[j];
    }
    m[i] = s / a[i][i];
  }
  return std::isfinite(m[0] + m[1] + m[2] + m[3]);
}

void vtkMedialQuadricSimplification::AddConePlanes(
  const vtkMedialSimplicialComplex& complex, vtkIdType a, vtkIdType b, double area, std::vector<double>& weight)
{
  const double length = Distance(complex.Point(a), complex.Point(b));
  const double k = length > 0.0 ? (complex.Radii[b] - complex.Radii[a]) / length : 2.0;
  if (!(std::abs(k) < 1.0) || !(area > 0.0))
  {
    return; // one ball holds the other: no cone
  }
  double u[3], p[3], q[3];
  for (int i = 0; i < 3; ++i)
  {
    u[i] = (complex.Point(b)[i] - complex.Point(a)[i]) / length;
  }
  // p, q: a frame perpendicular to the axis.
  const int axis = std::abs(u[0]) < 0.6 ? 0 : (std::abs(u[1]) < 0.6 ? 1 : 2);
  double helper[3] = { 0.0, 0.0, 0.0 };
  helper[axis] = 1.0;
  p[0] = u[1] * helper[2] - u[2] * helper[1];
  p[1] = u[2] * helper[0] - u[0] * helper[2];
  p[2] = u[0] * helper[1] - u[1] * helper[0];
  const double pn = std::sqrt(vtkMedialEnvelope::Dot3(p, p));
  for (double& x : p)
  {
    x /= pn;
  }
  q[0] = u[1] * p[2] - u[2] * p[1];
  q[1] = u[2] * p[0] - u[0] * p[2];
  q[2] = u[0] * p[1] - u[1] * p[0];
  const double s = std::sqrt(1.0 - k * k);
  for (int j = 0; j < ConePlanes; ++j)
  {
    const double angle = 2.0 * Pi * j / ConePlanes;
    double n[3];
    for (int i = 0; i < 3; ++i)
    {
      n[i] = -k * u[i] + s * (std::cos(angle) * p[i] + std::sin(angle) * q[i]);
    }
    const double d = vtkMedialEnvelope::Dot3(n, complex.Point(a)) + complex.Radii[a];
    for (vtkIdType v : { a, b })
    {
      this->Quadrics[v].AddPlane(n, d, area / ConePlanes);
      weight[v] += area / ConePlanes;
    }
  }
}

void vtkMedialQuadricSimplification::InitialQuadrics(const vtkMedialSimplicialComplex& complex)
{
  const vtkIdType nv = complex.GetNumberOfVertices();
  this->Quadrics.assign(static_cast<size_t>(nv), Quadric());
  std::vector<double> weight(static_cast<size_t>(nv), 0.0);
  // Both tangent planes of every slab.
  for (const auto& t : complex.Triangles)
  {
    const double* c[3] = { complex.Point(t[0]), complex.Point(t[1]), complex.Point(t[2]) };
    const double r[3] = { complex.Radii[t[0]], complex.Radii[t[1]], complex.Radii[t[2]] };
    vtkMedialEnvelope::TangentPlanes planes;
    if (!vtkMedialEnvelope::SlabTangentPlanes(c, r, planes))
    {
      // Degenerate, or the slab is the union of its cones (radii that change faster than
      // the centres, near a sharp edge): its sides' cones carry its area, so that the balls
      // of such triangles are not left with no planes at all. (N, the sides' cross
      // product, is set before SlabTangentPlanes gives up.)
      const double area = 0.5 * std::sqrt(vtkMedialEnvelope::Dot3(planes.N, planes.N));
      for (int k = 0; k < 3; ++k)
      {
        this->AddConePlanes(complex, t[k], t[(k + 1) % 3], area / 3.0, weight);
      }
      continue;
    }
    const double area = 0.5 * std::sqrt(vtkMedialEnvelope::Dot3(planes.N, planes.N));
    for (double side : { 1.0, -1.0 })
    {
      double n[3];
      for (int k = 0; k < 3; ++k)
      {
        n[k] = planes.W[k] + side * planes.Gamma * planes.N[k];
      }
      const double d = vtkMedialEnvelope::Dot3(n, c[0]) + r[0];
      for (vtkIdType v : t)
      {
        this->Quadrics[v].AddPlane(n, d, area);
        weight[v] += area;
      }
    }
  }
  // Planes all around the cone of every edge of no triangle, weighted by its lateral area.
  for (size_t e = 0; e < complex.Edges.size(); ++e)
  {
    if (complex.EdgeTriangles[e].empty())
    {
      const vtkIdType a = complex.Edges[e][0], b = complex.Edges[e][1];
      const double length = Distance(complex.Point(a), complex.Point(b));
      this->AddConePlanes(complex, a, b, Pi * (complex.Radii[a] + complex.Radii[b]) * length, weight);
    }
  }
  this->AddRimPlanes(complex, weight);
  // A weak pull towards each ball's own position (1e-3 of its planes' weight) keeps
  // every solve well posed: a cone or a flat sheet leaves directions free. A ball with
  // no planes (a few on rocker-arm) gets 1e-3 of the mean weight: a pull of the
  // diagonal's square would pin it, as if its error were larger than any other.
  double total = 0.0;
  vtkIdType weighted = 0;
  for (double w : weight)
  {
    total += w;
    weighted += w > 0.0;
  }
  const double fallback = weighted > 0 ? total / weighted : this->Scale * this->Scale;
  for (vtkIdType v = 0; v < nv; ++v)
  {
    const double w = 1e-3 * (weight[v] > 0.0 ? weight[v] : fallback);
    Quadric& q = this->Quadrics[v];
    for (int i = 0; i < 4; ++i)
    {
      q.A[Sym[i][i]] += w;
      q.B[i] += w * this->Balls[v][i];
      q.C += w * this->Balls[v][i] * this->Balls[v][i];
    }
  }
}

void vtkMedialQuadricSimplification::AddRimPlanes(
  const vtkMedialSimplicialComplex& complex, std::vector<double>& weight)
{
  if (!(this->RimWeight > 0.0))
  {
    return;
  }
  for (size_t e = 0; e < complex.Edges.size(); ++e)
  {
    if (complex.EdgeTriangles[e].size() != 1)
    {
      continue;
    }
    const auto& t = complex.Triangles[complex.EdgeTriangles[e][0]];
    const vtkIdType a = complex.Edges[e][0], b = complex.Edges[e][1];
    const vtkIdType third = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
    const double* c[3] = { complex.Point(t[0]), complex.Point(t[1]), complex.Point(t[2]) };
    const double r[3] = { complex.Radii[t[0]], complex.Radii[t[1]], complex.Radii[t[2]] };
    vtkMedialEnvelope::TangentPlanes planes;
    if (!vtkMedialEnvelope::SlabTangentPlanes(c, r, planes))
    {
      continue;
    }
    // The slab's two tangent planes meet at the angle phi, cos(phi / 2) = |W|: a rim
    // pulled in by delta along the sheet moves the envelope by (1 - cos(phi / 2)) delta
    // (nothing on a sheet that ends where its sides meet tangentially, delta on a plate's
    // rounded rim).
    const double f = 1.0 - std::sqrt(vtkMedialEnvelope::Dot3(planes.W, planes.W));
    // The plane through the rim edge, perpendicular to the sheet, facing away from it.
    const double* pa = complex.Point(a);
    const double* pb = complex.Point(b);
    const double* pc = complex.Point(third);
    double u[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = pb[k] - pa[k];
      w[k] = pc[k] - pa[k];
    }
    const double uu = vtkMedialEnvelope::Dot3(u, u);
    const double along = uu > 0.0 ? vtkMedialEnvelope::Dot3(w, u) / uu : 0.0;
    double n[3];
    for (int k = 0; k < 3; ++k)
    {
      n[k] = along * u[k] - w[k];
    }
    const double nn = std::sqrt(vtkMedialEnvelope::Dot3(n, n));
    if (!(f > 0.0) || !(uu > 0.0) || !(nn > 0.0))
    {
      continue;
    }
    for (double& x : n)
    {
      x /= nn;
    }
    // Weighted like a slab triangle of side |ab|, in full where the sheet reaches a crease
    // (radii small against the edge) and fading on rims of large balls, whose envelope
    // the slab planes already hold.
    const double length = std::sqrt(uu);
    const double crease = length / (length + 0.5 * (complex.Radii[a] + complex.Radii[b]));
    const double planeWeight = this->RimWeight * f * f * uu * crease;
    const double d = vtkMedialEnvelope::Dot3(n, pa);
    for (vtkIdType v : { a, b })
    {
      this->Quadrics[v].AddCentrePlane(n, d, planeWeight);
      weight[v] += planeWeight;
    }
  }
}

double vtkMedialQuadricSimplification::CollapseCost(vtkIdType a, vtkIdType b, double m[4]) const
{
  Quadric q = this->Quadrics[a];
  q.Add(this->Quadrics[b]);
  const double* ma = this->Balls[a].data();
  const double* mb = this->Balls[b].data();
  if (!this->Kept.empty())
  {
    std::copy(ma, ma + 4, m); // b goes into a, which stays where it is
    return q.Evaluate(m);
  }
  const double reach = Distance(ma, mb) + std::max(ma[3], mb[3]);
  if (q.Minimise(m) && m[3] >= 0.0)
  {
    double mid[3];
    for (int k = 0; k < 3; ++k)
    {
      mid[k] = 0.5 * (ma[k] + mb[k]);
    }
    if (Distance(m, mid) <= reach)
    {
      return q.Evaluate(m);
    }
  }
  // The best of the two ends and the midpoint.
  double best = HUGE_VAL;
  for (double t : { 0.0, 1.0, 0.5 })
  {
    double x[4];
    for (int k = 0; k < 4; ++k)
    {
      x[k] = (1.0 - t) * ma[k] + t * mb[k];
    }
    const double e = q.Evaluate(x);
    if (e < best)
    {
      best = e;
      std::copy(x, x + 4, m);
    }
  }
  return best;
}

bool vtkMedialQuadricSimplification::Orient(vtkIdType& a, vtkIdType& b) const
{
  if (a > b)
  {
    std::swap(a, b);
  }
  if (this->Kept.empty())
  {
    return true;
  }
  if (this->Kept[a] && this->Kept[b])
  {
    return false;
  }
  // Of two balls that may both go, the one whose removal costs less goes.
  double unused[4];
  if (this->Kept[b] || (!this->Kept[a] && this->CollapseCost(b, a, unused) < this->CollapseCost(a, b, unused)))
  {
    std::swap(a, b);
  }
  return true;
}

int vtkMedialQuadricSimplification::LinkCondition(vtkIdType a, vtkIdType b) const
{
  std::vector<vtkIdType> third;
  std::vector<std::array<vtkIdType, 2>> linkA, linkB;
  auto collect = [&](vtkIdType v, vtkIdType other, std::vector<std::array<vtkIdType, 2>>& link, bool keepThird) {
    for (vtkIdType t : this->VertexTriangles[v])
    {
      if (!this->TriangleAlive[t])
      {
        continue;
      }
      const auto& tri = this->AllTriangles[t];
      const bool hasOther = tri[0] == other || tri[1] == other || tri[2] == other;
      std::array<vtkIdType, 2> rest;
      int k = 0;
      for (vtkIdType x : tri)
      {
        if (x != v)
        {
          rest[k++] = x;
        }
      }
      if (hasOther)
      {
        if (keepThird)
        {
          third.push_back(rest[0] == other ? rest[1] : rest[0]);
        }
      }
      else
      {
        link.push_back({ std::min(rest[0], rest[1]), std::max(rest[0], rest[1]) });
      }
    }
  };
  collect(a, b, linkA, true);
  collect(b, a, linkB, false);
  // The common neighbours must be exactly the third corners of the triangles on ab.
  std::vector<vtkIdType> common;
  std::set_intersection(this->Neighbours[a].begin(), this->Neighbours[a].end(), this->Neighbours[b].begin(),
    this->Neighbours[b].end(), std::back_inserter(common));
  std::sort(third.begin(), third.end());
  // And no edge of both links.
  std::sort(linkA.begin(), linkA.end());
  std::sort(linkB.begin(), linkB.end());
  std::vector<std::array<vtkIdType, 2>> shared;
  std::set_intersection(linkA.begin(), linkA.end(), linkB.begin(), linkB.end(), std::back_inserter(shared));
  if (common == third && shared.empty())
  {
    return LINK_HOLDS;
  }
  // The collapse merges the edges to each common neighbour and the triangles on each
  // shared link edge, and removes the triangles on ab: chi changes by
  // |common| - |third| - |shared|.
  const std::ptrdiff_t change = static_cast<std::ptrdiff_t>(common.size()) -
    static_cast<std::ptrdiff_t>(third.size()) - static_cast<std::ptrdiff_t>(shared.size());
  return change == 0 ? KEEPS_EULER : CHANGES_EULER;
}

void vtkMedialQuadricSimplification::Collapse(vtkIdType a, vtkIdType b, const double m[4])
{
  for (vtkIdType t : this->VertexTriangles[b])
  {
    if (!this->TriangleAlive[t])
    {
      continue;
    }
    auto& tri = this->AllTriangles[t];
    if (tri[0] == a || tri[1] == a || tri[2] == a)
    {
      this->TriangleAlive[t] = 0;
      continue;
    }
    std::replace(tri.begin(), tri.end(), b, a);
    this->VertexTriangles[a].push_back(t);
  }
  // A collapse allowed without the link condition can make two triangles one.
  std::map<std::array<vtkIdType, 3>, vtkIdType> corners;
  for (vtkIdType t : this->VertexTriangles[a])
  {
    if (this->TriangleAlive[t])
    {
      std::array<vtkIdType, 3> key = this->AllTriangles[t];
      std::sort(key.begin(), key.end());
      if (!corners.emplace(key, t).second)
      {
        this->TriangleAlive[t] = 0;
      }
    }
  }
  for (vtkIdType x : this->Neighbours[b])
  {
    if (x != a)
    {
      Erase(this->Neighbours[x], b);
      Insert(this->Neighbours[x], a);
      Insert(this->Neighbours[a], x);
    }
  }
  Erase(this->Neighbours[a], b);
  this->Neighbours[b].clear();
  this->VertexTriangles[b].clear();
  auto& own = this->VertexTriangles[a];
  own.erase(std::remove_if(own.begin(), own.end(), [&](vtkIdType t) { return !this->TriangleAlive[t]; }), own.end());
  this->Alive[b] = 0;
  this->Quadrics[a].Add(this->Quadrics[b]);
  std::copy(m, m + 4, this->Balls[a].begin());
  ++this->Versions[a];
  ++this->Versions[b];
}

void vtkMedialQuadricSimplification::AssignGuardPoints()
{
  this->Owned.clear();
  this->LocalError.clear();
  const vtkIdType np = static_cast<vtkIdType>(this->GuardPoints.size() / 3);
  const vtkIdType nv = static_cast<vtkIdType>(this->Balls.size());
  if (np == 0 || nv == 0 || !this->Kept.empty())
  {
    return;
  }
  // Each point's owner is the ball nearest to it, |p - c| - r least (ties: the lower
  // id). The balls are binned by radius (halving from the largest), each bin on a grid
  // of its centres: a ball within rho of p has its centre within rho + the bin's
  // largest radius, and rho grows until some ball lies within it.
  double largest = 0.0;
  for (const auto& ball : this->Balls)
  {
    largest = std::max(largest, ball[3]);
  }
  constexpr int Bins = 16;
  std::vector<std::vector<vtkIdType>> members(Bins);
  for (vtkIdType v = 0; v < nv; ++v)
  {
    const double r = this->Balls[v][3];
    const int bin = r > 0.0 && largest > 0.0 ? std::min(Bins - 1, static_cast<int>(std::log2(largest / r))) : Bins - 1;
    members[bin].push_back(v);
  }
  struct Bin
  {
    double Largest = 0.0;
    std::vector<vtkIdType> Ids;
    std::vector<double> Centres;
    vtkMedialUniformGrid Grid;
  };
  std::vector<Bin> bins;
  for (auto& ids : members)
  {
    if (ids.empty())
    {
      continue;
    }
    Bin bin;
    double bounds[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
    for (vtkIdType v : ids)
    {
      bin.Largest = std::max(bin.Largest, this->Balls[v][3]);
      for (int k = 0; k < 3; ++k)
      {
        bin.Centres.push_back(this->Balls[v][k]);
        bounds[2 * k] = std::min(bounds[2 * k], this->Balls[v][k]);
        bounds[2 * k + 1] = std::max(bounds[2 * k + 1], this->Balls[v][k]);
      }
    }
    bin.Ids = std::move(ids);
    const double cell = vtkMedialUniformGrid::CubicCellSize(bounds, std::max(bin.Largest, this->Scale / 128.0), 262144.0);
    bin.Grid.InitializeCubic(bounds, cell);
    bin.Grid.BuildPoints(bin.Centres, {});
    bins.push_back(std::move(bin));
  }
  std::vector<vtkIdType> owner(static_cast<size_t>(np));
#pragma omp parallel for schedule(dynamic, 256) num_threads(std::max(1, this->NumberOfThreads))
  for (vtkIdType i = 0; i < np; ++i)
  {
    const double* p = &this->GuardPoints[3 * i];
    double best = HUGE_VAL;
    vtkIdType at = 0;
    for (double rho = this->Scale / 256.0;; rho *= 4.0)
    {
      for (const Bin& bin : bins)
      {
        bin.Grid.ForEachItemNear(p, rho + bin.Largest, [&](vtkIdType item) {
          const vtkIdType v = bin.Ids[item];
          const double g = vtkMedialEnvelope::BallField(p, this->Balls[v].data(), this->Balls[v][3]);
          if (g < best || (g == best && v < at))
          {
            best = g;
            at = v;
          }
        });
      }
      if (best <= rho || rho > 4.0 * this->Scale)
      {
        break;
      }
    }
    owner[i] = at;
  }
  this->Owned.assign(static_cast<size_t>(nv), {});
  for (vtkIdType i = 0; i < np; ++i)
  {
    this->Owned[owner[i]].push_back(i);
  }
  this->LocalError.assign(static_cast<size_t>(nv), 0.0);
#pragma omp parallel for schedule(dynamic, 64) num_threads(std::max(1, this->NumberOfThreads))
  for (vtkIdType v = 0; v < nv; ++v)
  {
    this->LocalError[v] = this->MergedError(v, -1, this->Balls[v].data());
  }
}

double vtkMedialQuadricSimplification::MergedError(vtkIdType a, vtkIdType b, const double m[4]) const
{
  std::vector<vtkIdType> ring;
  for (vtkIdType v : { a, b })
  {
    if (v < 0)
    {
      continue;
    }
    for (vtkIdType x : this->Neighbours[v])
    {
      if (x != a && x != b)
      {
        ring.push_back(x);
      }
    }
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  std::vector<std::array<vtkIdType, 2>> sides;
  for (vtkIdType v : { a, b })
  {
    if (v < 0)
    {
      continue;
    }
    for (vtkIdType t : this->VertexTriangles[v])
    {
      if (!this->TriangleAlive[t])
      {
        continue;
      }
      const auto& tri = this->AllTriangles[t];
      int onAB = 0;
      std::array<vtkIdType, 2> rest{ -1, -1 };
      int k = 0;
      for (vtkIdType x : tri)
      {
        if (x == a || x == b)
        {
          ++onAB;
        }
        else if (k < 2)
        {
          rest[k++] = x;
        }
      }
      if (onAB == 1 && k == 2)
      {
        sides.push_back({ std::min(rest[0], rest[1]), std::max(rest[0], rest[1]) });
      }
    }
  }
  std::sort(sides.begin(), sides.end());
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  // The primitives around m, each with a bounding ball (centre, radius) for pruning:
  // a primitive's field at p is at least |p - centre| - radius.
  struct Primitive
  {
    double Centre[3];
    double Reach;
    const double* C[3];
    double R[3];
    vtkMedialEnvelope::TangentPlanes Planes;
    bool Slab;
  };
  std::vector<Primitive> primitives;
  primitives.reserve(ring.size() + sides.size());
  for (vtkIdType x : ring)
  {
    Primitive q;
    q.C[0] = m;
    q.C[1] = this->Balls[x].data();
    q.R[0] = m[3];
    q.R[1] = this->Balls[x][3];
    q.Slab = false;
    q.Reach = vtkMedialEnvelope::BoundingBall(q.C, q.R, 2, q.Centre);
    primitives.push_back(q);
  }
  for (const auto& side : sides)
  {
    Primitive q;
    q.C[0] = m;
    q.C[1] = this->Balls[side[0]].data();
    q.C[2] = this->Balls[side[1]].data();
    q.R[0] = m[3];
    q.R[1] = this->Balls[side[0]][3];
    q.R[2] = this->Balls[side[1]][3];
    q.Slab = vtkMedialEnvelope::SlabTangentPlanes(q.C, q.R, q.Planes);
    if (q.Slab)
    {
      q.Reach = vtkMedialEnvelope::BoundingBall(q.C, q.R, 3, q.Centre);
      primitives.push_back(q);
    }
  }
  double error = 0.0;
  for (vtkIdType v : { a, b })
  {
    if (v < 0)
    {
      continue;
    }
    for (vtkIdType i : this->Owned[v])
    {
      const double* p = &this->GuardPoints[3 * i];
      double g = vtkMedialEnvelope::BallField(p, m, m[3]);
      for (const Primitive& q : primitives)
      {
        if (Distance(p, q.Centre) - q.Reach >= g)
        {
          continue;
        }
        g = std::min(g,
          q.Slab ? vtkMedialEnvelope::TriangleField(p, q.C, q.R, q.Planes)
                 : vtkMedialEnvelope::EdgeField(p, q.C[0], q.R[0], q.C[1], q.R[1]));
      }
      error = std::max(error, std::fabs(g));
    }
  }
  return error;
}

void vtkMedialQuadricSimplification::Extract()
{
  const vtkIdType nv = static_cast<vtkIdType>(this->Balls.size());
  std::vector<vtkIdType> index(static_cast<size_t>(nv), -1);
  this->Points.clear();
  this->Radii.clear();
  this->Source.clear();
  for (vtkIdType v = 0; v < nv; ++v)
  {
    if (this->Alive[v])
    {
      index[v] = static_cast<vtkIdType>(this->Radii.size());
      this->Points.insert(this->Points.end(), this->Balls[v].begin(), this->Balls[v].begin() + 3);
      this->Radii.push_back(this->Balls[v][3]);
      this->Source.push_back(v);
    }
  }
  std::map<std::array<vtkIdType, 2>, size_t> edgeIds;
  this->Edges.clear();
  for (vtkIdType v = 0; v < nv; ++v)
  {
    for (vtkIdType x : this->Neighbours[v])
    {
      if (this->Alive[v] && v < x)
      {
        edgeIds[{ index[v], index[x] }] = this->Edges.size();
        this->Edges.push_back({ index[v], index[x] });
      }
    }
  }
  this->EdgeTriangles.assign(this->Edges.size(), 0);
  this->Triangles.clear();
  for (size_t t = 0; t < this->AllTriangles.size(); ++t)
  {
    if (!this->TriangleAlive[t])
    {
      continue;
    }
    const auto& tri = this->AllTriangles[t];
    this->Triangles.push_back({ index[tri[0]], index[tri[1]], index[tri[2]] });
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType p = index[tri[k]], q = index[tri[(k + 1) % 3]];
      ++this->EdgeTriangles[edgeIds[{ std::min(p, q), std::max(p, q) }]];
    }
  }
}

bool vtkMedialQuadricSimplification::RunKeeping(const vtkMedialSimplicialComplex& complex,
  const std::vector<char>& kept, bool release, const std::function<bool()>& aborted)
{
  this->Kept = kept;
  this->ReleaseKept = release;
  const vtkIdType target = static_cast<vtkIdType>(std::count(kept.begin(), kept.end(), 1));
  const bool done = this->Run(complex, target, aborted);
  this->Kept.clear();
  return done;
}

bool vtkMedialQuadricSimplification::Run(
  const vtkMedialSimplicialComplex& complex, vtkIdType target, const std::function<bool()>& aborted)
{
  const vtkIdType nv = complex.GetNumberOfVertices();
  this->Balls.resize(static_cast<size_t>(nv));
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (vtkIdType v = 0; v < nv; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Balls[v][k] = complex.Point(v)[k];
      lo[k] = std::min(lo[k], complex.Point(v)[k] - complex.Radii[v]);
      hi[k] = std::max(hi[k], complex.Point(v)[k] + complex.Radii[v]);
    }
    this->Balls[v][3] = complex.Radii[v];
  }
  this->Scale = nv > 0 ? std::max(1e-300, Distance(lo, hi)) : 1.0;
  this->InitialQuadrics(complex);
  this->Versions.assign(static_cast<size_t>(nv), 0);
  this->Alive.assign(static_cast<size_t>(nv), 1);
  this->Neighbours.assign(static_cast<size_t>(nv), {});
  for (const auto& e : complex.Edges)
  {
    Insert(this->Neighbours[e[0]], e[1]);
    Insert(this->Neighbours[e[1]], e[0]);
  }
  this->AllTriangles = complex.Triangles;
  this->TriangleAlive.assign(this->AllTriangles.size(), 1);
  this->VertexTriangles.assign(static_cast<size_t>(nv), {});
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(this->AllTriangles.size()); ++t)
  {
    for (vtkIdType v : this->AllTriangles[t])
    {
      this->VertexTriangles[v].push_back(t);
    }
  }

  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap;
  this->AssignGuardPoints();
  const bool guarded = !this->Owned.empty() && this->Kept.empty();
  auto push = [&](vtkIdType a, vtkIdType b) {
    if (this->Orient(a, b))
    {
      double m[4];
      heap.push({ this->CollapseCost(a, b, m), a, b, this->Versions[a] + this->Versions[b], 0, -1.0 });
    }
  };
  for (const auto& e : complex.Edges)
  {
    push(e[0], e[1]);
  }
  // Collapses that would change the Euler characteristic, by ball: tried again when a
  // neighbour changes.
  std::map<vtkIdType, std::vector<std::array<vtkIdType, 2>>> blocked;
  std::set<std::array<vtkIdType, 2>> waiting; // the pairs in `blocked`, each once
  vtkIdType alive = nv;
  vtkIdType made = 0;
  while (alive > target)
  {
    if (heap.empty())
    {
      // RunKeeping, stuck with balls not kept that cannot go: kept balls may go too.
      if (!this->ReleaseKept || std::find(this->Kept.begin(), this->Kept.end(), 1) == this->Kept.end())
      {
        break;
      }
      std::fill(this->Kept.begin(), this->Kept.end(), 0);
      for (vtkIdType v = 0; v < nv; ++v)
      {
        for (vtkIdType x : this->Neighbours[v])
        {
          if (this->Alive[v] && v < x)
          {
            push(v, x);
          }
        }
      }
      waiting.clear();
      blocked.clear();
      continue;
    }
    const Candidate next = heap.top();
    heap.pop();
    if (!this->Alive[next.A] || !this->Alive[next.B] ||
      this->Versions[next.A] + this->Versions[next.B] != next.Version)
    {
      continue;
    }
    if (this->LinkCondition(next.A, next.B) == CHANGES_EULER)
    {
      // Once per pair: a pair waiting under both balls must not come back twice.
      if (waiting.insert({ next.A, next.B }).second)
      {
        blocked[next.A].push_back({ next.A, next.B });
        blocked[next.B].push_back({ next.A, next.B });
      }
      continue;
    }
    double m[4];
    this->CollapseCost(next.A, next.B, m);
    double error = next.Error;
    if (guarded && next.Tier == 0)
    {
      // Guarded lazily: a collapse that would leave its points farther from the envelope
      // than the tolerance (or than they already are) waits behind every collapse that
      // does not, in the order of that distance.
      error = this->MergedError(next.A, next.B, m);
      if (error > std::max(this->GuardTolerance, std::max(this->LocalError[next.A], this->LocalError[next.B])))
      {
        heap.push({ error, next.A, next.B, next.Version, 1, error });
        continue;
      }
    }
    if ((++made & 1023) == 0 && aborted && aborted())
    {
      return false;
    }
    this->Collapse(next.A, next.B, m);
    if (guarded)
    {
      // The merged ball takes b's points and carries their distance.
      auto& into = this->Owned[next.A];
      auto& from = this->Owned[next.B];
      into.insert(into.end(), from.begin(), from.end());
      std::vector<vtkIdType>().swap(from);
      this->LocalError[next.A] = error;
    }
    --alive;
    std::vector<vtkIdType> ring = this->Neighbours[next.A];
    for (vtkIdType x : ring)
    {
      push(next.A, x);
    }
    ring.push_back(next.A);
    ring.push_back(next.B);
    for (vtkIdType x : ring)
    {
      auto found = blocked.find(x);
      if (found == blocked.end())
      {
        continue;
      }
      const auto pairs = std::move(found->second);
      blocked.erase(found);
      for (const auto& p : pairs)
      {
        if (waiting.erase(p) && this->Alive[p[0]] && this->Alive[p[1]] && std::binary_search(this->Neighbours[p[0]].begin(),
                                                        this->Neighbours[p[0]].end(), p[1]))
        {
          push(p[0], p[1]);
        }
      }
    }
  }
  this->BlockedCollapses = 0;
  if (alive > target)
  {
    this->BlockedCollapses = static_cast<vtkIdType>(waiting.size());
  }
  this->Extract();
  return true;
}
