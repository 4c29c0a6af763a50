// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSimplicialComplex
 * @brief Internal: a medial mesh as a simplicial complex of balls, edges and triangles,
 * read from vtkPolyData and written back in the layout of vtkMedialMeshFilter. Used by
 * the medial mesh, pruning and simplification filters.
 *
 * Read: vertex cells, the segments of lines, and triangles (polygons are fanned);
 * repeated edges and triangles count once, a triangle with a repeated corner is an
 * edge. Every triangle side is an edge.
 *
 * WriteCells: given the edges (with the number of triangles on each) and the triangles
 * on points 0..n-1, writes vertex cells for the points on no edge, lines for the edges
 * of no triangle (curves) and of three or more (seams), the triangles, the cell data
 * MedialCellType (0 isolated ball, 1 curve edge, 2 seam edge, 3 sheet triangle), and
 * gives the point types read from the mesh (0 rim, 1 sheet, 2 seam, 3 junction).
 */
#ifndef vtkMedialSimplicialComplex_h
#define vtkMedialSimplicialComplex_h

#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPolyData;

class vtkMedialSimplicialComplex
{
public:
  std::vector<double> Points; // 3 coordinates per vertex
  std::vector<double> Radii;
  std::vector<std::array<vtkIdType, 2>> Edges;         // smaller id first
  std::vector<std::array<vtkIdType, 3>> Triangles;     // as read
  std::vector<std::array<vtkIdType, 3>> TriangleEdges; // sides v0v1, v1v2, v2v0
  std::vector<std::vector<vtkIdType>> EdgeTriangles;
  std::vector<std::vector<vtkIdType>> VertexEdges;

  /// Reads the complex; false with a reason on triangle strips or a bad radius array.
  bool Read(vtkPolyData* mesh, vtkDataArray* radius, std::string& error);

  /// Builds edges and incidences from segments and triangles on `vertices` points.
  void Assemble(vtkIdType vertices, const std::vector<std::array<vtkIdType, 2>>& segments,
    const std::vector<std::array<vtkIdType, 3>>& triangles);

  vtkIdType GetNumberOfVertices() const { return static_cast<vtkIdType>(this->Radii.size()); }
  const double* Point(vtkIdType v) const { return &this->Points[3 * v]; }

  /// V - E + F and the connected components of the simplices kept (every flag vector
  /// empty: all kept).
  static vtkIdType EulerCharacteristic(const std::vector<char>& vertices, const std::vector<char>& edges,
    const std::vector<char>& triangles);
  vtkIdType CountComponents(const std::vector<char>& vertices, const std::vector<char>& edges) const;

  /// What WriteCells made: for each line, its edge; the point types from the mesh.
  struct Cells
  {
    std::vector<vtkIdType> LineEdges;
    std::vector<int> PointTypes;
  };

  /// Cells of a medial mesh on points 0..vertices-1 (see the class comment).
  static Cells WriteCells(vtkIdType vertices, const std::vector<std::array<vtkIdType, 2>>& edges,
    const std::vector<int>& edgeTriangles, const std::vector<std::array<vtkIdType, 3>>& triangles,
    vtkPolyData* output);
};

#endif
