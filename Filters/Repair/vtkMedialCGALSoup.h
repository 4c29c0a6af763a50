// SPDX-License-Identifier: BSD-3-Clause
// The repair's soup (vtkMedialSurfaceRepair::Soup) to and from CGAL's Surface_mesh, for
// both kernels: Epick in vtkMedialSurfaceRepair.cxx, Epeck in
// vtkMedialSurfaceRepairExact.cxx. It includes CGAL headers: only those two files, which
// link CGAL privately, may include it.
#ifndef vtkMedialCGALSoup_h
#define vtkMedialCGALSoup_h

#include "vtkMedialSurfaceRepair.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <vector>

namespace vtkMedialCGALSoup
{
using Polygons = std::vector<std::vector<std::size_t>>;

// The soup's points in the kernel's type and its triangles as CGAL's polygons.
template <class Point>
void ToPolygons(const vtkMedialSurfaceRepair::Soup& soup, std::vector<Point>& points, Polygons& polygons)
{
  points.clear();
  polygons.clear();
  points.reserve(soup.Points.size());
  for (const auto& x : soup.Points)
  {
    points.emplace_back(x[0], x[1], x[2]);
  }
  polygons.reserve(soup.Triangles.size());
  for (const auto& t : soup.Triangles)
  {
    polygons.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]) });
  }
}

// The mesh of a soup that is oriented and manifold; false when it is not. A point where
// two fans of triangles meet (a pinch, which the preparation does not count as a
// defect) is first split as orient_polygon_soup splits it: the copies keep their
// coordinates, and the preparation merges them again.
template <class Point>
bool ToMesh(const vtkMedialSurfaceRepair::Soup& soup, CGAL::Surface_mesh<Point>& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point> points;
  Polygons polygons;
  ToPolygons(soup, points, polygons);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    PMP::orient_polygon_soup(points, polygons);
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    {
      return false;
    }
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return true;
}

// The mesh's triangles (faces with more corners are fanned), its points rounded to
// doubles and numbered in vertex order.
template <class Point>
void FromMesh(const CGAL::Surface_mesh<Point>& mesh, vtkMedialSurfaceRepair::Soup& soup)
{
  using Mesh = CGAL::Surface_mesh<Point>;
  soup = vtkMedialSurfaceRepair::Soup();
  std::vector<vtkIdType> id(mesh.num_vertices(), -1);
  for (typename Mesh::Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    id[v] = static_cast<vtkIdType>(soup.Points.size());
    soup.Points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
  }
  std::vector<vtkIdType> corners;
  for (typename Mesh::Face_index f : mesh.faces())
  {
    corners.clear();
    for (typename Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      corners.push_back(id[v]);
    }
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    {
      soup.Triangles.push_back({ corners[0], corners[i], corners[i + 1] });
    }
  }
}
}

#endif
