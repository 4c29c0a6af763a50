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
 * Corner normals are stored in single precision, once per distinct normal at a vertex:
 * where every triangle around a vertex is within the crease angle of every other (a
 * smooth vertex), all its corners have the same normal (the same sum in the same
 * order) and share one; at a crease vertex each distinct corner normal is stored once.
 * Each corner holds the index of its normal: about 18 bytes a triangle on a smooth
 * mesh (36 when every corner had its own copy: 56 MB on 1.55 M triangles). Build needs
 * the mesh's points, triangles and areas, and the facets' normals from the mesh or
 * from a built query (its tree keeps the same values, so the mesh's copy may already
 * be released); At reads only this object and the three vertices passed in (the
 * query's copies), so the mesh may release its geometry after Build. Thread-safe
 * after Build.
 */
#ifndef vtkMedialSurfaceNormals_h
#define vtkMedialSurfaceNormals_h

#include "vtkMedialBuffer.h"
#include "vtkType.h"

#include <cstdint>

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

class vtkMedialSurfaceNormals
{
public:
  /// Corner normals of every triangle of `mesh`; triangles around a vertex whose
  /// normals differ by more than `creaseDegrees` from a corner's triangle do not count
  /// for that corner. The facets' normals come from `query` when given (the mesh's
  /// Normals may then be released), else from the mesh.
  void Build(const vtkMedialTriangleMesh& mesh, double creaseDegrees, const vtkMedialSurfaceQuery* query = nullptr);

  /// The unit outward normal at p on triangle t, whose vertices (9 coordinates, in the
  /// mesh's order) are `vertices` and whose facet normal is `facetNormal`. True when it
  /// is the facet's normal (flat region, degenerate triangle, or nothing built).
  bool At(vtkIdType t, const double vertices[9], const double facetNormal[3], const double p[3],
    double n[3]) const;

  bool IsEmpty() const { return this->CornerNormals.empty(); }

  /// Number of normals stored: one per point (smooth or not), plus one per further
  /// distinct normal at a crease point.
  vtkIdType GetNumberOfNormals() const { return static_cast<vtkIdType>(this->Normals.size() / 3); }

private:
  // The distinct unit normals at `point`, 3 floats each, into `normals`, and for the
  // i-th triangle around it (`around`, `count` of them, with their facet normals and
  // whether they have an area) the index of its corner's normal among them into
  // `slot`; returns how many.
  int NormalsAtPoint(const vtkMedialTriangleMesh& mesh, vtkIdType point, const std::int32_t* around, int count,
    const double* const* facetNormals, const char* usable, double cosCrease, float* normals, int* slot) const;

  vtkMedialBuffer<std::int32_t> CornerNormals; // 3 per triangle, the mesh's order: index into Normals
  // 3 floats per normal: each point's first at the point's index, then the others of
  // the points at creases, point by point.
  vtkMedialBuffer<float> Normals;
};

#endif
