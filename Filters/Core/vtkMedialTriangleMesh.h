// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialTriangleMesh
 * @brief Internal: a validated, consistently oriented triangle mesh in double precision.
 *
 * Build() takes any vtkPolyData surface and:
 *  1. rejects empty input and NaN/Inf coordinates;
 *  2. triangulates polygons and strips (vtkTriangleFilter), remembering the input cell id;
 *  3. merges exactly coincident points (vtkStaticCleanPolyData, tolerance 0), so
 *     that soups from STL/OBJ become connected;
 *  4. orients each edge-connected component consistently by a breadth-first walk
 *     over manifold edges, then flips every component whose signed volume is
 *     negative, so normals point outward whatever the file's winding;
 *  5. computes unit outward normals, areas and the area CDF used for sampling.
 *
 * It counts boundary edges (open mesh), non-manifold edges, components that could
 * not be oriented, and degenerate (zero-area) triangles, so callers can warn.
 * Limitation: a component nested inside another (a cavity) is oriented by its own
 * volume sign, i.e. as a separate solid.
 */
#ifndef vtkMedialTriangleMesh_h
#define vtkMedialTriangleMesh_h

#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

class vtkMedialTriangleMesh
{
public:
  /// Returns false and fills `error` with a one-line reason on unusable input.
  /// `aborted`, when given, is polled between stages; true stops the build
  /// (false, error "aborted") so that a caller's abort is honoured promptly.
  bool Build(vtkPolyData* input, std::string& error, const std::function<bool()>& aborted = {});

  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->Areas.size()); }
  const double* GetPoint(vtkIdType i) const { return &this->Points[3 * i]; }
  const vtkIdType* GetTriangle(vtkIdType t) const { return &this->Triangles[3 * t]; }
  const double* GetNormal(vtkIdType t) const { return &this->Normals[3 * t]; }

  /// V - E + F of the triangulated surface (2 - 2 genus for a closed, connected one).
  vtkIdType GetEulerCharacteristic() const
  {
    return this->UsedPoints - this->Edges + this->GetNumberOfTriangles();
  }

  /// Index of the triangle whose cumulative area bracket holds u in [0, 1).
  vtkIdType PickTriangleByArea(double u) const;

  std::vector<double> Points;          // 3 per point
  std::vector<vtkIdType> Triangles;    // 3 per triangle, counter-clockwise seen from outside
  std::vector<vtkIdType> SourceCellIds; // input cell id of each triangle
  std::vector<double> Normals;         // unit outward normal, 3 per triangle
  std::vector<double> Areas;
  std::vector<double> AreaCdf; // normalised cumulative area, last entry 1

  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  double Diagonal = 0.0;
  double TotalArea = 0.0;
  double Volume = 0.0; // enclosed volume after orientation (meaningful when closed)
  vtkIdType BoundaryEdges = 0;
  vtkIdType Edges = 0;      // distinct edges of the kept triangles
  vtkIdType UsedPoints = 0; // points referenced by the kept triangles
  vtkIdType NonManifoldEdges = 0;
  vtkIdType NonOrientableComponents = 0;
  vtkIdType DegenerateTriangles = 0;
  vtkIdType DuplicateTriangles = 0; // same three vertices as an earlier triangle: dropped
  vtkIdType Components = 0;
  vtkIdType FlippedComponents = 0;

private:
  void DropDuplicateTriangles();
};

#endif
