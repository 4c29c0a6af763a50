// SPDX-License-Identifier: BSD-3-Clause
// The repair's CGAL steps with exact constructions (Epeck): the union of two closed
// shells by corefinement and the autorefinement of a shell that crosses itself. This is
// the heaviest file to compile (about 90 CPU seconds and 2.7 GB with GCC 12): it holds
// nothing else. The results are rounded to doubles; vtkMedialRepairFilter tidies them.
#include "vtkMedialSurfaceRepair.h"

// First of the CGAL headers: the order of CGAL's box intersection (see there).
#include "vtkMedialCGALBoxOrder.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <exception>

namespace
{
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
using Soup = vtkMedialSurfaceRepair::Soup;

bool ToMesh(const Soup& soup, Mesh& mesh, std::string& error)
{
  std::vector<Point> points;
  points.reserve(soup.Points.size());
  for (const auto& x : soup.Points)
  {
    points.emplace_back(x[0], x[1], x[2]);
  }
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(soup.Triangles.size());
  for (const auto& t : soup.Triangles)
  {
    polygons.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]) });
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    // A pinch (two fans of triangles at a point) is split, as in
    // vtkMedialSurfaceRepair.cxx.
    PMP::orient_polygon_soup(points, polygons);
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    {
      error = "a shell is not an oriented manifold";
      return false;
    }
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return true;
}

// The exact points rounded to the nearest doubles.
void FromMesh(const Mesh& mesh, Soup& soup)
{
  soup = Soup();
  std::vector<vtkIdType> id(mesh.num_vertices(), -1);
  for (Mesh::Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    id[v] = static_cast<vtkIdType>(soup.Points.size());
    soup.Points.push_back({ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) });
  }
  for (Mesh::Face_index f : mesh.faces())
  {
    std::array<vtkIdType, 3> t;
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      if (k < 3)
      {
        t[k] = id[v];
      }
      ++k;
    }
    if (k == 3)
    {
      soup.Triangles.push_back(t);
    }
  }
}
}

namespace vtkMedialSurfaceRepair
{
bool Union(const Soup& a, const Soup& b, Soup& joined, std::string& error)
{
  try
  {
    Mesh ma, mb, out;
    if (!ToMesh(a, ma, error) || !ToMesh(b, mb, error))
    {
      return false;
    }
    if (!PMP::corefine_and_compute_union(ma, mb, out))
    {
      error = "CGAL's corefinement cannot make the union (it would not be manifold)";
      return false;
    }
    FromMesh(out, joined);
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
  return true;
}

bool Autorefine(Soup& soup, std::string& error)
{
  try
  {
    Mesh mesh;
    if (!ToMesh(soup, mesh, error))
    {
      return false;
    }
    const bool solved = PMP::experimental::autorefine_and_remove_self_intersections(mesh);
    FromMesh(mesh, soup);
    if (!solved)
    {
      error = "CGAL's autorefinement left some self-intersections";
    }
    return solved;
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
}
}
