// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPowerComplex
 * @brief Internal: the regular (weighted Delaunay) triangulation of a set of balls,
 * indexed, with the alpha complex at alpha = 0 marked on it.
 *
 * Build() triangulates the centres with weights r^2 (CGAL's Regular_triangulation_3,
 * exact predicates) and classifies every simplex with CGAL's Fixed_alpha_shape_3 at
 * alpha = 0: a simplex is "in the union" when its dual power face meets the union of
 * the balls, i.e. it belongs to the dual complex of the union (Edelsbrunner 1995),
 * which is homotopy equivalent to the union. The convex hull of such a simplex lies
 * in the union of its own balls (they share a point of equal power <= 0, and the
 * power function averaged over the simplex's barycentric weights is below the one
 * at that point).
 *
 * Everything is then copied into plain arrays in a canonical order (simplices sorted
 * by their sorted ball ids), so that the result does not depend on CGAL's internal
 * order. Balls hidden by the others (an empty power cell) are not vertices; their
 * ball is covered by the union of the others.
 *
 * This is the only class that includes CGAL (a private, header-only dependency of
 * MedialAxis::Structure); this header does not.
 */
#ifndef vtkMedialPowerComplex_h
#define vtkMedialPowerComplex_h

#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkMedialPowerComplex
{
public:
  /// Triangulates the balls (3 coordinates per centre, one radius each). Returns false
  /// with a reason when there are fewer than four balls or the centres are coplanar.
  bool Build(const std::vector<double>& centres, const std::vector<double>& radii, std::string& error);

  vtkIdType GetNumberOfTetrahedra() const { return static_cast<vtkIdType>(this->TetVertices.size()); }
  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->TriangleVertices.size()); }
  vtkIdType GetNumberOfEdges() const { return static_cast<vtkIdType>(this->EdgeVertices.size()); }

  // Finite tetrahedra: ball ids (sorted); the tetrahedron across the face opposite
  // vertex j (-1: the infinite side, outside the convex hull) and that face's
  // triangle; the power centre (the point of equal power to its four balls) and
  // whether it lies in the union (power <= 0).
  std::vector<std::array<vtkIdType, 4>> TetVertices;
  std::vector<std::array<vtkIdType, 4>> TetNeighbours;
  std::vector<std::array<vtkIdType, 4>> TetTriangles;
  std::vector<double> PowerCentres;
  std::vector<char> TetInUnion;

  // Finite triangles: ball ids (sorted), the two tetrahedra on either side (-1 for
  // the infinite side; at most one), the edges (v0 v1, v0 v2, v1 v2), in the union.
  std::vector<std::array<vtkIdType, 3>> TriangleVertices;
  std::vector<std::array<vtkIdType, 2>> TriangleTets;
  std::vector<std::array<vtkIdType, 3>> TriangleEdges;
  std::vector<char> TriangleInUnion;

  // Finite edges: ball ids (sorted), in the union.
  std::vector<std::array<vtkIdType, 2>> EdgeVertices;
  std::vector<char> EdgeInUnion;

  // Per ball: a vertex of the triangulation (not hidden), in the union.
  std::vector<char> BallIsVertex;
  std::vector<char> VertexInUnion;
};

#endif
