// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSolidDiagnosis
 * @brief Internal: whether a prepared surface bounds a valid solid and, if not, why
 *        (CGAL's predicates).
 *
 * A surface bounds a valid solid when its triangles form a closed, manifold, oriented
 * mesh (CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh, CGAL::is_closed,
 * is_outward_oriented) whose triangles do not intersect each other except along their
 * shared edges and vertices (self_intersections, exact predicates). Only then has the
 * solid a topology (its Euler characteristic is half its surface's) that the medial
 * mesh can have. Collapsed (collinear) triangles count as intersecting themselves.
 *
 * Check() runs on the vtkMedialTriangleMesh every filter prepares (exactly coincident
 * points merged, duplicate triangles dropped, shells oriented; see that class), so it
 * judges the surface the filters see. Its cost is CGAL's box intersection over the
 * triangles (about 0.3 s for 100k triangles): vtkMedialMeshFilter runs it only when the
 * medial mesh's topology differs from the solid's, to name the cause.
 *
 * One function on purpose: a single place to replace by a public valid-solid check. It
 * diagnoses (names the defect and where) rather than screens: a fast tree-based
 * pre-check that only says yes or no belongs elsewhere.
 * This class includes CGAL in its .cxx only.
 */
#ifndef vtkMedialSolidDiagnosis_h
#define vtkMedialSolidDiagnosis_h

#include "vtkType.h"

class vtkMedialTriangleMesh;

class vtkMedialSolidDiagnosis
{
public:
  struct Result
  {
    bool PolygonMesh = false;     // manifold and consistently oriented (a halfedge mesh can hold it)
    bool Closed = false;          // no border edge (checked on a polygon mesh only)
    bool OutwardOriented = false; // every shell's normals point out (closed polygon mesh only)
    vtkIdType CollapsedTriangles = 0; // collinear corners
    vtkIdType IntersectingPairs = 0;  // pairs of distinct triangles that cross or touch wrongly
    double IntersectionPoint[3] = { 0, 0, 0 }; // a point of the first such pair (a centroid)
    bool IsValidSolid() const
    {
      return this->PolygonMesh && this->Closed && this->OutwardOriented && this->CollapsedTriangles == 0 &&
        this->IntersectingPairs == 0;
    }
  };

  /// Checks the prepared mesh (its points and triangles must not have been released).
  static Result Check(const vtkMedialTriangleMesh& mesh);
};

#endif
