// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSurfaceNormals
 * @brief Internal: the normals of the smooth surface that a triangle mesh
 * approximates, at any point of a triangle: per-corner normals interpolated linearly.
 *
 * A facet's own normal is tilted against the surface it approximates by up to half
 * the angle between neighbouring facets; a ball tangent to the facet at a point away
 * from where the facet touches the surface is then pushed off the medial axis (on a
 * 5120-triangle sphere, sideways by about 2.6 times the point's distance from the
 * facet's circumcentre at the default angle, so the ball shrunk to be inscribed lost
 * 5% of its radius on median). The normal of the surface is better estimated from
 * the vertices, where a tessellation of a smooth surface is exact:
 *  - each corner (a vertex of a triangle) gets the mean of the outward normals of the
 *    triangles around its vertex that are within the crease angle of the corner's own
 *    triangle, with Max's weights (area vector over the product of the two edge lengths
 *    squared: exact for vertices on a sphere; N. Max, "Weights for computing vertex
 *    normals from facet normals", 1999), so that a sharp edge keeps each side's
 *    normal and a flat face keeps its own;
 *  - the normal at a point p of a triangle is its three corner normals weighted by
 *    p's barycentric coordinates, normalised; within 1e-6 radians of the facet's
 *    normal (a flat region, where the float storage is the only difference) it is the
 *    facet's normal, bit for bit.
 * Corner normals are stored in single precision (36 bytes a triangle). Build needs the
 * mesh's points, triangles and normals; At reads only this object and the three
 * vertices passed in (the query's copies), so the mesh may release its geometry after
 * Build. Thread-safe after Build.
 */
#ifndef vtkMedialSurfaceNormals_h
#define vtkMedialSurfaceNormals_h

#include "vtkMedialBuffer.h"
#include "vtkType.h"

class vtkMedialTriangleMesh;

class vtkMedialSurfaceNormals
{
public:
  /// Corner normals of every triangle of `mesh`; triangles around a vertex whose
  /// normals differ by more than `creaseDegrees` from a corner's triangle do not count
  /// for that corner.
  void Build(const vtkMedialTriangleMesh& mesh, double creaseDegrees);

  /// The unit outward normal at p on triangle t, whose vertices (9 coordinates, in the
  /// mesh's order) are `vertices` and whose facet normal is `facetNormal`. True when it
  /// is the facet's normal (flat region, degenerate triangle, or nothing built).
  bool At(vtkIdType t, const double vertices[9], const double facetNormal[3], const double p[3],
    double n[3]) const;

  bool IsEmpty() const { return this->Corners.empty(); }

private:
  vtkMedialBuffer<float> Corners; // 9 per triangle: the corners' unit normals, in the mesh's order
};

#endif
