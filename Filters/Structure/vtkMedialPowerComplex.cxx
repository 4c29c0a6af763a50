// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPowerComplex.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fixed_alpha_shape_3.h>
#include <CGAL/Fixed_alpha_shape_cell_base_3.h>
#include <CGAL/Fixed_alpha_shape_vertex_base_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Fixed_alpha_shape_vertex_base_3<Kernel,
  CGAL::Triangulation_vertex_base_with_info_3<vtkIdType, Kernel,
    CGAL::Regular_triangulation_vertex_base_3<Kernel>>>;
using CellBase = CGAL::Fixed_alpha_shape_cell_base_3<Kernel,
  CGAL::Triangulation_cell_base_with_info_3<vtkIdType, Kernel,
    CGAL::Regular_triangulation_cell_base_3<Kernel>>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Triangulation = CGAL::Regular_triangulation_3<Kernel, Tds>;
using AlphaShape = CGAL::Fixed_alpha_shape_3<Triangulation>;
using WeightedPoint = Kernel::Weighted_point_3;

// Sorts `keys` and returns the permutation: order[k] is the raw index of the k-th smallest.
template <class Key>
std::vector<vtkIdType> CanonicalOrder(const std::vector<Key>& keys)
{
  std::vector<vtkIdType> order(keys.size());
  std::iota(order.begin(), order.end(), vtkIdType(0));
  std::sort(order.begin(), order.end(), [&keys](vtkIdType a, vtkIdType b) { return keys[a] < keys[b]; });
  return order;
}

template <class T>
std::vector<T> Permute(const std::vector<T>& raw, const std::vector<vtkIdType>& order)
{
  std::vector<T> out(raw.size());
  for (size_t k = 0; k < order.size(); ++k)
  {
    out[k] = raw[order[k]];
  }
  return out;
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

using Cell = Triangulation::Cell_handle;

// The finite tetrahedra: raw index (CGAL's order, stored in each cell's info, -1 for
// infinite cells), sorted vertices, and the canonical order of those keys.
struct TetIndex
{
  std::vector<std::array<vtkIdType, 4>> Keys; // by raw index
  std::vector<Cell> Cells;                    // by raw index
  std::vector<vtkIdType> Order;               // canonical -> raw
  std::vector<vtkIdType> Rank;                // raw -> canonical

  vtkIdType size() const { return static_cast<vtkIdType>(this->Cells.size()); }
  vtkIdType CanonicalOf(Cell c) const { return c->info() < 0 ? -1 : this->Rank[c->info()]; }
};

TetIndex IndexTetrahedra(AlphaShape& shape)
{
  vtkIdType rawTets = 0;
  for (auto c = shape.all_cells_begin(); c != shape.all_cells_end(); ++c)
  {
    c->info() = shape.is_infinite(c) ? -1 : rawTets++;
  }
  TetIndex tets;
  tets.Keys.resize(rawTets);
  tets.Cells.resize(rawTets);
  for (auto c = shape.finite_cells_begin(); c != shape.finite_cells_end(); ++c)
  {
    auto& key = tets.Keys[c->info()];
    for (int j = 0; j < 4; ++j)
    {
      key[j] = c->vertex(j)->info();
    }
    std::sort(key.begin(), key.end());
    tets.Cells[c->info()] = c;
  }
  tets.Order = CanonicalOrder(tets.Keys);
  tets.Rank = Inverse(tets.Order);
  return tets;
}

// The triangles in raw order (found from the finite side with the smaller raw index).
struct RawTriangles
{
  std::vector<std::array<vtkIdType, 3>> Keys;
  std::vector<std::array<vtkIdType, 2>> Tets; // canonical tetrahedra on either side
  std::vector<char> InUnion;
  std::vector<vtkIdType> FacetTriangle; // raw triangle of (raw cell, CGAL index)
};

RawTriangles IndexTriangles(const AlphaShape& shape, const TetIndex& tets)
{
  RawTriangles tris;
  tris.FacetTriangle.assign(4 * tets.size(), -1);
  for (vtkIdType raw = 0; raw < tets.size(); ++raw)
  {
    const Cell c = tets.Cells[raw];
    for (int j = 0; j < 4; ++j)
    {
      const Cell n = c->neighbor(j);
      if (n->info() >= 0 && n->info() < raw)
      {
        continue; // done from n
      }
      const vtkIdType t = static_cast<vtkIdType>(tris.Keys.size());
      std::array<vtkIdType, 3> key;
      for (int m = 0, k = 0; m < 4; ++m)
      {
        if (m != j)
        {
          key[k++] = c->vertex(m)->info();
        }
      }
      std::sort(key.begin(), key.end());
      tris.Keys.push_back(key);
      tris.Tets.push_back({ tets.CanonicalOf(c), tets.CanonicalOf(n) });
      tris.InUnion.push_back(shape.classify(AlphaShape::Facet(c, j)) != AlphaShape::EXTERIOR);
      tris.FacetTriangle[4 * raw + j] = t;
      if (n->info() >= 0)
      {
        tris.FacetTriangle[4 * n->info() + n->index(c)] = t;
      }
    }
  }
  return tris;
}

// Tetrahedra in canonical order; neighbours and faces follow the sorted vertices.
void CopyTetrahedra(const AlphaShape& shape, const TetIndex& tets, const RawTriangles& tris,
  const std::vector<vtkIdType>& triRank, vtkMedialPowerComplex& complex)
{
  const vtkIdType rawTets = tets.size();
  complex.TetVertices.resize(rawTets);
  complex.TetNeighbours.resize(rawTets);
  complex.TetTriangles.resize(rawTets);
  complex.PowerCentres.resize(3 * rawTets);
  complex.TetInUnion.resize(rawTets);
  for (vtkIdType k = 0; k < rawTets; ++k)
  {
    const vtkIdType raw = tets.Order[k];
    const Cell c = tets.Cells[raw];
    const std::array<vtkIdType, 4>& key = tets.Keys[raw];
    complex.TetVertices[k] = key;
    for (int j = 0; j < 4; ++j)
    {
      const vtkIdType slot = std::find(key.begin(), key.end(), c->vertex(j)->info()) - key.begin();
      complex.TetNeighbours[k][slot] = tets.CanonicalOf(c->neighbor(j));
      complex.TetTriangles[k][slot] = triRank[tris.FacetTriangle[4 * raw + j]];
    }
    const Kernel::Point_3 w = shape.dual(c);
    complex.PowerCentres[3 * k] = w.x();
    complex.PowerCentres[3 * k + 1] = w.y();
    complex.PowerCentres[3 * k + 2] = w.z();
    complex.TetInUnion[k] = shape.classify(c) == AlphaShape::INTERIOR;
  }
}

// Edges: the sides of the (canonical) triangles (every finite edge is one), sorted and
// made unique; each is classified through a cell of the first triangle that has it.
void IndexEdges(const AlphaShape& shape, const TetIndex& tets, const RawTriangles& tris,
  const std::vector<vtkIdType>& triOrder, vtkMedialPowerComplex& complex)
{
  struct EdgeUse
  {
    std::array<vtkIdType, 2> Key;
    vtkIdType Triangle; // canonical triangle index
    int Side;           // 0: v0 v1, 1: v0 v2, 2: v1 v2
    bool operator<(const EdgeUse& other) const
    {
      return this->Key < other.Key || (this->Key == other.Key && this->Triangle < other.Triangle);
    }
  };
  const vtkIdType nf = static_cast<vtkIdType>(complex.TriangleVertices.size());
  std::vector<EdgeUse> uses(3 * nf);
  for (vtkIdType t = 0; t < nf; ++t)
  {
    const auto& v = complex.TriangleVertices[t];
    uses[3 * t] = { { v[0], v[1] }, t, 0 };
    uses[3 * t + 1] = { { v[0], v[2] }, t, 1 };
    uses[3 * t + 2] = { { v[1], v[2] }, t, 2 };
  }
  std::sort(uses.begin(), uses.end());
  complex.TriangleEdges.resize(nf);
  complex.EdgeVertices.clear();
  complex.EdgeInUnion.clear();
  for (size_t k = 0; k < uses.size(); ++k)
  {
    if (k == 0 || uses[k].Key != uses[k - 1].Key)
    {
      const vtkIdType rawTriangle = triOrder[uses[k].Triangle];
      const std::array<vtkIdType, 2>& triTets = tris.Tets[rawTriangle];
      const Cell c = tets.Cells[tets.Order[triTets[0]]];
      int i = -1, j = -1;
      for (int m = 0; m < 4; ++m)
      {
        i = c->vertex(m)->info() == uses[k].Key[0] ? m : i;
        j = c->vertex(m)->info() == uses[k].Key[1] ? m : j;
      }
      complex.EdgeVertices.push_back(uses[k].Key);
      complex.EdgeInUnion.push_back(shape.classify(AlphaShape::Edge(c, i, j)) != AlphaShape::EXTERIOR);
    }
    complex.TriangleEdges[uses[k].Triangle][uses[k].Side] = static_cast<vtkIdType>(complex.EdgeVertices.size() - 1);
  }
}
}

bool vtkMedialPowerComplex::Build(
  const std::vector<double>& centres, const std::vector<double>& radii, std::string& error)
{
  const vtkIdType nb = static_cast<vtkIdType>(radii.size());
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
  Triangulation triangulation(points.begin(), points.end());
  if (triangulation.dimension() < 3)
  {
    error = "the ball centres are coplanar";
    return false;
  }
  AlphaShape shape(triangulation, 0.0); // takes over the triangulation

  this->BallIsVertex.assign(nb, 0);
  this->VertexInUnion.assign(nb, 0);
  for (auto v = shape.finite_vertices_begin(); v != shape.finite_vertices_end(); ++v)
  {
    this->BallIsVertex[v->info()] = 1;
    this->VertexInUnion[v->info()] = shape.classify(v) != AlphaShape::EXTERIOR;
  }

  const TetIndex tets = IndexTetrahedra(shape);
  const RawTriangles tris = IndexTriangles(shape, tets);
  const std::vector<vtkIdType> triOrder = CanonicalOrder(tris.Keys);
  const std::vector<vtkIdType> triRank = Inverse(triOrder);
  this->TriangleVertices = Permute(tris.Keys, triOrder);
  this->TriangleTets = Permute(tris.Tets, triOrder);
  this->TriangleInUnion = Permute(tris.InUnion, triOrder);
  CopyTetrahedra(shape, tets, tris, triRank, *this);
  IndexEdges(shape, tets, tris, triOrder, *this);
  return true;
}
