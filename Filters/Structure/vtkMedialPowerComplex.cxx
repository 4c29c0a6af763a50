// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPowerComplex.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<vtkIdType, Kernel,
  CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
// Hidden balls are not kept in the cells (nothing asks for them: BallIsVertex is read
// from the vertices).
using CellBase = CGAL::Triangulation_cell_base_with_info_3<vtkIdType, Kernel,
  CGAL::Regular_triangulation_cell_base_3<Kernel, CGAL::Triangulation_cell_base_3<Kernel>, CGAL::Discard_hidden_points>>;
using WeightedPoint = Kernel::Weighted_point_3;
using Triangulation = CGAL::Regular_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<VertexBase, CellBase>>;

// The finite cells of the triangulation in its own order: their balls (in vertex order)
// and their neighbours' positions in that order (-1: infinite), read in parallel once
// the cells are numbered; and which balls are vertices.
void ReadCells(Triangulation& triangulation, std::vector<std::array<vtkIdType, 4>>& vertices,
  std::vector<std::array<vtkIdType, 4>>& neighbours, std::vector<char>& ballIsVertex, int threads)
{
  using Cell = Triangulation::Cell_handle;
  for (auto v = triangulation.finite_vertices_begin(); v != triangulation.finite_vertices_end(); ++v)
  {
    ballIsVertex[v->info()] = 1;
  }
  std::vector<Cell> cells;
  cells.reserve(triangulation.tds().number_of_cells());
  for (auto c = triangulation.all_cells_begin(); c != triangulation.all_cells_end(); ++c)
  {
    if (triangulation.is_infinite(c))
    {
      c->info() = -1;
    }
    else
    {
      c->info() = static_cast<vtkIdType>(cells.size());
      cells.push_back(c);
    }
  }
  const vtkIdType n = static_cast<vtkIdType>(cells.size());
  vertices.resize(n);
  neighbours.resize(n);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      vertices[i][j] = cells[i]->vertex(j)->info();
      neighbours[i][j] = cells[i]->neighbor(j)->info();
    }
  }
}

// The permutation that sorts `keys` (distinct sorted ball ids, each below `balls`):
// order[k] is the index of the k-th smallest. A counting sort on the first ball, then a
// sort of each (short) group in place: a few passes over contiguous memory instead of
// a comparison sort that reads the keys at random. The groups are filled in any order
// (atomic counters): each is then sorted on (key, index), which are distinct.
template <size_t N>
std::vector<vtkIdType> SortedOrder(const std::vector<std::array<vtkIdType, N>>& keys, vtkIdType balls, int threads)
{
  const vtkIdType n = static_cast<vtkIdType>(keys.size());
  std::vector<vtkIdType> start(balls + 1, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType i = 0; i < n; ++i)
  {
#pragma omp atomic
    ++start[keys[i][0] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<std::array<vtkIdType, N>, vtkIdType>> grouped(n);
  {
    std::vector<vtkIdType> fill(start.begin(), start.end() - 1);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
    for (vtkIdType i = 0; i < n; ++i)
    {
      vtkIdType at;
#pragma omp atomic capture
      at = fill[keys[i][0]]++;
      grouped[at] = { keys[i], i };
    }
  }
  std::vector<vtkIdType> order(n);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (vtkIdType b = 0; b < balls; ++b)
  {
    std::sort(grouped.begin() + start[b], grouped.begin() + start[b + 1]);
    for (vtkIdType k = start[b]; k < start[b + 1]; ++k)
    {
      order[k] = grouped[k].second;
    }
  }
  return order;
}

std::vector<vtkIdType> Inverse(const std::vector<vtkIdType>& order)
{
  std::vector<vtkIdType> inverse(order.size());
  for (size_t k = 0; k < order.size(); ++k)
  {
    inverse[order[k]] = static_cast<vtkIdType>(k);
  }
  return inverse;
}

// Power centres that keep their digits on near-flat simplices. The double formulas
// divide by a determinant (a tetrahedron's volume, a triangle's squared area) that
// cancels when the simplex is nearly flat, as thousands are where balls sample a flat
// medial sheet densely: the centre then lands far off, even on the wrong side of the
// simplex, and every test made with it is wrong. Below a relative size of 1e-6 of that
// determinant (relative error above about 1e-9) the same formula is evaluated in exact
// rational arithmetic on the input doubles and rounded once.
constexpr double FlatSimplex = 1e-6;

template <class T>
void CrossT(const T a[3], const T b[3], T out[3])
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

template <class T>
T DotT(const T a[3], const T b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The point of equal power to the 4 weighted points (x[k], w[k]) (their orthogonal
// sphere's centre): x0 + (A b x c + B c x a + C a x b) / (2 a . (b x c)), with a, b, c the
// edges from x0 and A = |a|^2 - w1 + w0, etc.
template <class T>
void PowerCentre4T(const double* const x[4], const double w[4], double out[3])
{
  T e[3][3], lifted[3];
  for (int k = 0; k < 3; ++k)
  {
    for (int d = 0; d < 3; ++d)
    {
      e[k][d] = T(x[k + 1][d]) - T(x[0][d]);
    }
    lifted[k] = DotT(e[k], e[k]) - T(w[k + 1]) + T(w[0]);
  }
  T bc[3], ca[3], ab[3];
  CrossT(e[1], e[2], bc);
  CrossT(e[2], e[0], ca);
  CrossT(e[0], e[1], ab);
  const T den = T(2) * DotT(e[0], bc);
  for (int d = 0; d < 3; ++d)
  {
    out[d] = CGAL::to_double(T(x[0][d]) + (lifted[0] * bc[d] + lifted[1] * ca[d] + lifted[2] * ab[d]) / den);
  }
}

void PowerCentre4(const double* const x[4], const double w[4], double out[3])
{
  double e[3][3];
  for (int k = 0; k < 3; ++k)
  {
    for (int d = 0; d < 3; ++d)
    {
      e[k][d] = x[k + 1][d] - x[0][d];
    }
  }
  double bc[3];
  CrossT(e[1], e[2], bc);
  const double scale = std::sqrt(DotT(e[0], e[0]) * DotT(e[1], e[1]) * DotT(e[2], e[2]));
  if (std::fabs(DotT(e[0], bc)) > FlatSimplex * scale)
  {
    PowerCentre4T<double>(x, w, out);
  }
  else
  {
    PowerCentre4T<CGAL::Exact_rational>(x, w, out);
  }
}

// The point of the plane of 3 weighted points with equal power to them, and the plane's
// normal a x b (not unit): x0 + (A b x n + B n x a) / (2 |n|^2), n = a x b.
template <class T>
void PowerCentre3T(const double* const x[3], const double w[3], double out[3], double normal[3])
{
  T e[2][3], lifted[2];
  for (int k = 0; k < 2; ++k)
  {
    for (int d = 0; d < 3; ++d)
    {
      e[k][d] = T(x[k + 1][d]) - T(x[0][d]);
    }
    lifted[k] = DotT(e[k], e[k]) - T(w[k + 1]) + T(w[0]);
  }
  T n[3], bn[3], na[3];
  CrossT(e[0], e[1], n);
  CrossT(e[1], n, bn);
  CrossT(n, e[0], na);
  const T den = T(2) * DotT(n, n);
  for (int d = 0; d < 3; ++d)
  {
    out[d] = CGAL::to_double(T(x[0][d]) + (lifted[0] * bn[d] + lifted[1] * na[d]) / den);
    normal[d] = CGAL::to_double(n[d]);
  }
}

void PowerCentre3(const double* const x[3], const double w[3], double out[3], double normal[3])
{
  double a[3], b[3], n[3];
  for (int d = 0; d < 3; ++d)
  {
    a[d] = x[1][d] - x[0][d];
    b[d] = x[2][d] - x[0][d];
  }
  CrossT(a, b, n);
  if (DotT(n, n) > FlatSimplex * FlatSimplex * DotT(a, a) * DotT(b, b))
  {
    PowerCentre3T<double>(x, w, out, normal);
  }
  else
  {
    PowerCentre3T<CGAL::Exact_rational>(x, w, out, normal);
  }
}

// Power of x with respect to ball b (|x - c|^2 - r^2).
inline double PowerOf(const double x[3], const double* c, double r)
{
  const double d[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
  return DotT(d, d) - r * r;
}
}

bool vtkMedialPowerComplex::Build(
  const std::vector<double>& centres, const std::vector<double>& radii, int threads, std::string& error)
{
  const vtkIdType nb = static_cast<vtkIdType>(radii.size());
  this->Centres = &centres;
  this->Radii = &radii;
  if (nb < 4)
  {
    error = "fewer than four balls";
    return false;
  }
  std::vector<std::pair<WeightedPoint, vtkIdType>> points;
  points.reserve(nb);
  for (vtkIdType i = 0; i < nb; ++i)
  {
    const double* c = &centres[3 * i];
    points.emplace_back(WeightedPoint(Kernel::Point_3(c[0], c[1], c[2]), radii[i] * radii[i]), i);
  }
  // The tetrahedra in CGAL's order: their balls and their neighbours' positions (the
  // triangulation is freed before the indexing allocates).
  std::vector<std::array<vtkIdType, 4>> cellVertices, cellNeighbours;
  this->BallIsVertex.assign(nb, 0);
  int dimension = 0;
  {
    Triangulation triangulation(points.begin(), points.end());
    points = {};
    dimension = triangulation.dimension();
    if (dimension == 3)
    {
      ReadCells(triangulation, cellVertices, cellNeighbours, this->BallIsVertex, threads);
    }
  }
  if (dimension < 3)
  {
    error = "the ball centres are coplanar";
    return false;
  }
  // Every simplex from here on is in a canonical order (sorted by its sorted ball ids),
  // so that nothing depends on CGAL's internal order.
  this->IndexTetrahedra(cellVertices, cellNeighbours, threads);
  this->IndexTriangles(threads);
  this->IndexEdges(threads);
  this->ClassifyUnion(threads);
  return true;
}

void vtkMedialPowerComplex::IndexTetrahedra(const std::vector<std::array<vtkIdType, 4>>& cellVertices,
  const std::vector<std::array<vtkIdType, 4>>& cellNeighbours, int threads)
{
  const vtkIdType raw = static_cast<vtkIdType>(cellVertices.size());
  std::vector<std::array<vtkIdType, 4>> keys(cellVertices);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType i = 0; i < raw; ++i)
  {
    std::sort(keys[i].begin(), keys[i].end());
  }
  const vtkIdType nb = static_cast<vtkIdType>(this->BallIsVertex.size());
  const std::vector<vtkIdType> order = SortedOrder(keys, nb, threads);
  const std::vector<vtkIdType> rank = Inverse(order);
  this->TetVertices.resize(raw);
  this->TetNeighbours.resize(raw);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType k = 0; k < raw; ++k)
  {
    const std::array<vtkIdType, 4>& key = keys[order[k]];
    this->TetVertices[k] = key;
    for (int j = 0; j < 4; ++j)
    {
      const vtkIdType slot = std::find(key.begin(), key.end(), cellVertices[order[k]][j]) - key.begin();
      const vtkIdType n = cellNeighbours[order[k]][j];
      this->TetNeighbours[k][slot] = n < 0 ? -1 : rank[n];
    }
  }
}

void vtkMedialPowerComplex::IndexTriangles(int threads)
{
  // Each triangle once, from the tetrahedron with the smaller index (or the finite one):
  // the number each tetrahedron owns, then each writes its own at its offset.
  const vtkIdType nt = this->GetNumberOfTetrahedra();
  auto owns = [this](vtkIdType t, int s) {
    const vtkIdType n = this->TetNeighbours[t][s];
    return n < 0 || n > t;
  };
  std::vector<vtkIdType> first(nt + 1, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    first[t + 1] = owns(t, 0) + owns(t, 1) + owns(t, 2) + owns(t, 3);
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  const vtkIdType nf = first[nt];
  std::vector<std::array<vtkIdType, 3>> keys(nf);
  std::vector<std::array<vtkIdType, 2>> sides(nf); // (tetrahedron, slot of the opposite vertex)
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const auto& v = this->TetVertices[t];
    vtkIdType at = first[t];
    for (int s = 0; s < 4; ++s)
    {
      if (!owns(t, s))
      {
        continue;
      }
      std::array<vtkIdType, 3>& key = keys[at];
      for (int m = 0, k = 0; m < 4; ++m)
      {
        if (m != s)
        {
          key[k++] = v[m]; // sorted, as v is
        }
      }
      sides[at++] = { t, s };
    }
  }
  const std::vector<vtkIdType> order =
    SortedOrder(keys, static_cast<vtkIdType>(this->BallIsVertex.size()), threads);
  this->TriangleVertices.resize(nf);
  this->TriangleTets.resize(nf);
  this->TetTriangles.resize(nt);
  // Every (tetrahedron, slot) is one triangle's: the writes below never meet.
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const auto& side = sides[order[f]];
    const vtkIdType t = side[0], n = this->TetNeighbours[t][side[1]];
    this->TriangleVertices[f] = keys[order[f]];
    this->TriangleTets[f] = { t, n };
    this->TetTriangles[t][side[1]] = f;
    if (n >= 0)
    {
      const auto& nv = this->TetVertices[n];
      // The slot of n's vertex opposite the shared face: the one not in the triangle.
      const vtkIdType apex = nv[0] + nv[1] + nv[2] + nv[3] - keys[order[f]][0] - keys[order[f]][1] -
        keys[order[f]][2];
      this->TetTriangles[n][std::find(nv.begin(), nv.end(), apex) - nv.begin()] = f;
    }
  }
}

void vtkMedialPowerComplex::IndexEdges(int threads)
{
  // The sides of the triangles, grouped by their first ball (a counting sort), then
  // sorted by the second within each group: the edges in canonical order, and for
  // each the triangles on it. Groups are filled in any order (atomic counters) and
  // then sorted on (second ball, triangle), distinct within a group.
  const vtkIdType nf = this->GetNumberOfTriangles();
  const vtkIdType nb = static_cast<vtkIdType>(this->BallIsVertex.size());
  std::vector<vtkIdType> start(nb + 1, 0);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const auto& v = this->TriangleVertices[f];
#pragma omp atomic
    start[v[0] + 1] += 2;
#pragma omp atomic
    start[v[1] + 1] += 1;
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  struct Use
  {
    vtkIdType Second, Triangle;
    int Side; // 0: v0 v1, 1: v0 v2, 2: v1 v2
    bool operator<(const Use& o) const
    {
      return this->Second < o.Second || (this->Second == o.Second && this->Triangle < o.Triangle);
    }
  };
  std::vector<Use> uses(3 * nf);
  {
    std::vector<vtkIdType> fill(start.begin(), start.end() - 1);
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
    for (vtkIdType f = 0; f < nf; ++f)
    {
      const auto& v = this->TriangleVertices[f];
      vtkIdType at0, at1;
#pragma omp atomic capture
      { at0 = fill[v[0]]; fill[v[0]] += 2; }
#pragma omp atomic capture
      at1 = fill[v[1]]++;
      uses[at0] = { v[1], f, 0 };
      uses[at0 + 1] = { v[2], f, 1 };
      uses[at1] = { v[2], f, 2 };
    }
  }
  // Each group sorted, and its edges (distinct second balls) counted.
  std::vector<vtkIdType> firstEdge(nb + 1, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (vtkIdType a = 0; a < nb; ++a)
  {
    std::sort(uses.begin() + start[a], uses.begin() + start[a + 1]);
    vtkIdType edges = 0;
    for (vtkIdType k = start[a]; k < start[a + 1]; ++k)
    {
      edges += k == start[a] || uses[k].Second != uses[k - 1].Second;
    }
    firstEdge[a + 1] = edges;
  }
  std::partial_sum(firstEdge.begin(), firstEdge.end(), firstEdge.begin());
  const vtkIdType ne = firstEdge[nb];
  this->TriangleEdges.resize(nf);
  this->EdgeVertices.resize(ne);
  this->EdgeTriangleStart.resize(ne + 1);
  this->EdgeTriangleList.resize(3 * nf);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (vtkIdType a = 0; a < nb; ++a)
  {
    vtkIdType edge = firstEdge[a] - 1;
    for (vtkIdType k = start[a]; k < start[a + 1]; ++k)
    {
      const Use& u = uses[k];
      if (k == start[a] || u.Second != uses[k - 1].Second)
      {
        ++edge;
        this->EdgeVertices[edge] = { a, u.Second };
        this->EdgeTriangleStart[edge] = k;
      }
      this->TriangleEdges[u.Triangle][u.Side] = edge;
      this->EdgeTriangleList[k] = u.Triangle;
    }
  }
  this->EdgeTriangleStart[ne] = 3 * nf;
}

void vtkMedialPowerComplex::ClassifyUnion(int threads)
{
  const std::vector<double>& centres = *this->Centres;
  const std::vector<double>& radii = *this->Radii;
  const vtkIdType nt = this->GetNumberOfTetrahedra(), nf = this->GetNumberOfTriangles();
  const vtkIdType ne = this->GetNumberOfEdges();
  // Tetrahedra: the power centre, in the union when its power is at most 0.
  this->PowerCentres.resize(3 * nt);
  this->TetInUnion.resize(nt);
#pragma omp parallel for schedule(static, 1024) num_threads(threads)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const auto& v = this->TetVertices[t];
    const double* x[4];
    double w[4];
    for (int j = 0; j < 4; ++j)
    {
      x[j] = &centres[3 * v[j]];
      w[j] = radii[v[j]] * radii[v[j]];
    }
    double* p = &this->PowerCentres[3 * t];
    PowerCentre4(x, w, p);
    this->TetInUnion[t] = PowerOf(p, x[0], radii[v[0]]) <= 0.0;
  }
  // Triangles: the dual segment meets the union where its point of least power (its
  // own power centre, t = 0, or the nearer end) has power at most 0.
  this->TriangleInUnion.resize(nf);
#pragma omp parallel for schedule(static, 1024) num_threads(threads)
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const auto& tets = this->TriangleTets[f];
    if (this->TetInUnion[tets[0]] || (tets[1] >= 0 && this->TetInUnion[tets[1]]))
    {
      this->TriangleInUnion[f] = 1;
      continue;
    }
    double origin[3], normal[3], tLow, tHigh;
    this->GetTriangleDual(f, origin, normal, tLow, tHigh);
    const vtkIdType b = this->TriangleVertices[f][0];
    this->TriangleInUnion[f] = tLow <= 0.0 && 0.0 <= tHigh && PowerOf(origin, &centres[3 * b], radii[b]) <= 0.0;
  }
  // Edges: likewise over the dual polygon, in the radical plane: its point of least
  // power is the edge's own power centre m when the polygon holds it (no ball of the
  // link has less power there), otherwise a point of its boundary, the dual of a
  // triangle on the edge.
  this->EdgeInUnion.resize(ne);
#pragma omp parallel for schedule(static, 1024) num_threads(threads)
  for (vtkIdType e = 0; e < ne; ++e)
  {
    bool in = false;
    for (vtkIdType k = this->EdgeTriangleStart[e]; k < this->EdgeTriangleStart[e + 1] && !in; ++k)
    {
      in = this->TriangleInUnion[this->EdgeTriangleList[k]];
    }
    if (!in)
    {
      const auto& v = this->EdgeVertices[e];
      const double *a = &centres[3 * v[0]], *b = &centres[3 * v[1]];
      const double ra = radii[v[0]], rb = radii[v[1]];
      const double d[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double d2 = DotT(d, d);
      const double s = (d2 + ra * ra - rb * rb) / (2.0 * d2);
      const double m[3] = { a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2] };
      const double power = PowerOf(m, a, ra);
      in = power <= 0.0;
      for (vtkIdType k = this->EdgeTriangleStart[e]; k < this->EdgeTriangleStart[e + 1] && in; ++k)
      {
        const auto& tv = this->TriangleVertices[this->EdgeTriangleList[k]];
        const vtkIdType c = tv[0] + tv[1] + tv[2] - v[0] - v[1];
        in = PowerOf(m, &centres[3 * c], radii[c]) >= power;
      }
    }
    this->EdgeInUnion[e] = in;
  }
  this->VertexInUnion = this->BallIsVertex;
}

void vtkMedialPowerComplex::GetTriangleDual(
  vtkIdType f, double origin[3], double normal[3], double& tLow, double& tHigh) const
{
  const std::array<vtkIdType, 3>& v = this->TriangleVertices[f];
  const std::array<vtkIdType, 2>& tets = this->TriangleTets[f];
  const std::array<vtkIdType, 4>& tv = this->TetVertices[tets[0]];
  const vtkIdType apex = tv[0] + tv[1] + tv[2] + tv[3] - v[0] - v[1] - v[2];
  const double* x[3];
  double weights[3];
  for (int k = 0; k < 3; ++k)
  {
    x[k] = &(*this->Centres)[3 * v[k]];
    weights[k] = (*this->Radii)[v[k]] * (*this->Radii)[v[k]];
  }
  PowerCentre3(x, weights, origin, normal);
  // Towards the apex: the exact orientation of the (positively oriented) tetrahedron.
  const double* a = &(*this->Centres)[3 * apex];
  const CGAL::Orientation side = CGAL::orientation(Kernel::Point_3(x[0][0], x[0][1], x[0][2]),
    Kernel::Point_3(x[1][0], x[1][1], x[1][2]), Kernel::Point_3(x[2][0], x[2][1], x[2][2]),
    Kernel::Point_3(a[0], a[1], a[2]));
  const double norm = std::sqrt(DotT(normal, normal));
  for (int d = 0; d < 3; ++d)
  {
    normal[d] *= (side == CGAL::NEGATIVE ? -1.0 : 1.0) / norm;
  }
  auto along = [&](vtkIdType tet) {
    const double* w = &this->PowerCentres[3 * tet];
    const double d[3] = { w[0] - origin[0], w[1] - origin[1], w[2] - origin[2] };
    return DotT(d, normal);
  };
  tHigh = along(tets[0]);
  tLow = tets[1] >= 0 ? along(tets[1]) : -HUGE_VAL;
}

