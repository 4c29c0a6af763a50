// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSolidDiagnosis.h"

#include "vtkMedialTriangleMesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <iterator>
#include <utility>
#include <vector>

vtkMedialSolidDiagnosis::Result vtkMedialSolidDiagnosis::Check(const vtkMedialTriangleMesh& mesh)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Face = SurfaceMesh::Face_index;
  namespace PMP = CGAL::Polygon_mesh_processing;

  Result result;
  std::vector<Kernel::Point_3> points;
  points.reserve(mesh.GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh.GetNumberOfPoints(); ++i)
  {
    const double* p = mesh.GetPoint(i);
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::array<std::size_t, 3>> triangles(mesh.GetNumberOfTriangles());
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    triangles[t] = { static_cast<std::size_t>(v[0]), static_cast<std::size_t>(v[1]),
      static_cast<std::size_t>(v[2]) };
  }
  result.PolygonMesh = PMP::is_polygon_soup_a_polygon_mesh(triangles);
  if (!result.PolygonMesh)
  {
    return result; // non-manifold or not orientable: no halfedge mesh to test further
  }
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface);
  result.Closed = CGAL::is_closed(surface);
  std::vector<std::pair<Face, Face>> pairs;
  PMP::self_intersections(surface, std::back_inserter(pairs));
  for (const auto& pair : pairs)
  {
    if (pair.first == pair.second)
    {
      ++result.CollapsedTriangles;
      continue;
    }
    if (result.IntersectingPairs++ == 0)
    {
      // Faces keep the soup's order: the triangle's centroid, where it happens.
      const vtkIdType* v = mesh.GetTriangle(static_cast<vtkIdType>(pair.first.idx()));
      for (int k = 0; k < 3; ++k)
      {
        result.IntersectionPoint[k] =
          (mesh.GetPoint(v[0])[k] + mesh.GetPoint(v[1])[k] + mesh.GetPoint(v[2])[k]) / 3.0;
      }
    }
  }
  // Orientation with nesting (cavities inward) is defined for a closed surface without
  // self-intersections only.
  result.OutwardOriented = result.Closed && pairs.empty() && PMP::does_bound_a_volume(surface);
  return result;
}
