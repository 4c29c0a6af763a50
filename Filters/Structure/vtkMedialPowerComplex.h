// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPowerComplex
 * @brief Internal: the regular (weighted Delaunay) triangulation of a set of balls,
 * indexed, with the dual complex of their union marked on it.
 *
 * Build() triangulates the centres with weights r^2 (CGAL's Regular_triangulation_3,
 * exact predicates; hidden balls are not kept) and copies every simplex into plain
 * arrays in a canonical order (simplices sorted by their sorted ball ids, a counting sort
 * on the first), so that nothing depends on CGAL's internal order or on the thread
 * count; the edges come with the triangles on each. Balls hidden by the
 * others (an empty power cell) are not vertices; their ball is covered by the union of
 * the others.
 *
 * Each simplex is then marked "in the union" when its dual power face meets the union
 * of the balls: the dual complex of the union (the alpha complex at alpha = 0,
 * Edelsbrunner 1995), homotopy equivalent to the union. The power function of the
 * simplex's balls, restricted to its dual face, is least at the simplex's own power
 * centre when the face holds it and otherwise on the face's boundary (the dual of a
 * coface), so: a tetrahedron is in when its power centre has power <= 0; a triangle
 * when a tetrahedron on it is, or its own power centre (in its plane) lies on its dual
 * segment with power <= 0; an edge when a triangle on it is, or its power centre on
 * the segment has power <= 0 and no ball of its link has less power there. The convex
 * hull of such a simplex lies in the union of its own balls (they share a point of
 * equal power <= 0, and the power function averaged over the simplex's barycentric
 * weights is below the one at that point).
 *
 * Power centres are exact up to one rounding, also on near-flat simplices, where the
 * double formula loses every digit (see PowerCentre4 in the .cxx); dual segments are
 * taken from the triangle's own power centre (GetTriangleDual), which stays accurate
 * when its tetrahedra's are far off.
 *
 * This class and vtkMedialExactPredicates are the only ones that include CGAL (a private,
 * header-only dependency of MedialAxis::Structure); this header does not.
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
  /// Triangulates the balls (3 coordinates per centre, one radius each; both must
  /// outlive this object), with `threads` OpenMP threads for the indexing and the
  /// classification (the result does not depend on it). Returns false with a reason when there are fewer
  /// than four balls or the centres are coplanar.
  bool Build(const std::vector<double>& centres, const std::vector<double>& radii, int threads, std::string& error);

  /// The line dual to triangle f (its points of equal power to the triangle's three
  /// balls) as origin + t normal: origin is the triangle's own power centre, in its
  /// plane; normal is unit, towards the apex of TriangleTets[f][0]; the dual segment
  /// (or ray, on the convex hull: tLow = -inf) is t in [tLow, tHigh]. Unlike the segment
  /// between its tetrahedra's power centres, it stays accurate near the shape when those
  /// are far off (near-flat tetrahedra).
  void GetTriangleDual(vtkIdType f, double origin[3], double normal[3], double& tLow, double& tHigh) const;

  vtkIdType GetNumberOfTetrahedra() const { return static_cast<vtkIdType>(this->TetVertices.size()); }
  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->TriangleVertices.size()); }
  vtkIdType GetNumberOfEdges() const { return static_cast<vtkIdType>(this->EdgeVertices.size()); }

  // Finite tetrahedra: ball ids (sorted); the tetrahedron across the face opposite
  // vertex j (-1: the infinite side, outside the convex hull) and that face's
  // triangle; the power centre (the point of equal power to its four balls; exact up
  // to one rounding on near-flat tetrahedra) and whether it lies in the union (power <= 0).
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

  // Finite edges: ball ids (sorted), in the union; the triangles on edge e are
  // EdgeTriangleList[EdgeTriangleStart[e] .. EdgeTriangleStart[e + 1]).
  std::vector<std::array<vtkIdType, 2>> EdgeVertices;
  std::vector<char> EdgeInUnion;
  std::vector<vtkIdType> EdgeTriangleStart, EdgeTriangleList;

  // Per ball: a vertex of the triangulation (not hidden), in the union.
  std::vector<char> BallIsVertex;
  std::vector<char> VertexInUnion;

private:
  // The tetrahedra in canonical order, from CGAL's cells (their balls in CGAL's vertex
  // order, and their neighbours' positions in CGAL's order; -1: infinite).
  void IndexTetrahedra(const std::vector<std::array<vtkIdType, 4>>& cellVertices,
    const std::vector<std::array<vtkIdType, 4>>& cellNeighbours, int threads);
  void IndexTriangles(int threads);
  void IndexEdges(int threads);
  void ClassifyUnion(int threads);

  const std::vector<double>* Centres = nullptr;
  const std::vector<double>* Radii = nullptr;
};

#endif
