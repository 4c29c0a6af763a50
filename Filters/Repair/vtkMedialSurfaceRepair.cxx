// SPDX-License-Identifier: BSD-3-Clause
// The repair's CGAL steps with exact predicates and inexact constructions (Epick). The
// exact-construction steps are in vtkMedialSurfaceRepairExact.cxx. Each CGAL header
// here costs compile time and memory: keep this file to the calls it makes.
#include "vtkMedialSurfaceRepair.h"

// First of the CGAL headers: the order of CGAL's box intersection (see there).
#include "vtkMedialCGALBoxOrder.h"

#include "vtkMedialCGALSoup.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>

namespace
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygons = vtkMedialCGALSoup::Polygons;
using vtkMedialCGALSoup::FromMesh;
using vtkMedialCGALSoup::ToPolygons;
namespace PMP = CGAL::Polygon_mesh_processing;
using Soup = vtkMedialSurfaceRepair::Soup;

// The soup's faces added one by one: false when one cannot be (a non-manifold edge or
// corner, an orientation that disagrees) or when a vertex ends with more than one fan
// of faces. Cheaper than is_polygon_soup_a_polygon_mesh, which sorts every edge first.
bool AddFaces(const Soup& soup, Mesh& mesh)
{
  mesh.reserve(static_cast<Mesh::size_type>(soup.Points.size()), static_cast<Mesh::size_type>(3 * soup.Triangles.size() / 2),
    static_cast<Mesh::size_type>(soup.Triangles.size()));
  for (const auto& x : soup.Points)
  {
    mesh.add_vertex(Point(x[0], x[1], x[2]));
  }
  for (const auto& t : soup.Triangles)
  {
    const Mesh::Vertex_index a(static_cast<Mesh::size_type>(t[0])), b(static_cast<Mesh::size_type>(t[1])),
      c(static_cast<Mesh::size_type>(t[2]));
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || mesh.add_face(a, b, c) == Mesh::null_face())
    {
      return false;
    }
  }
  // One fan per vertex: the halfedges around it are all that point to it.
  std::vector<Mesh::size_type> incoming(mesh.num_vertices(), 0);
  for (Mesh::Halfedge_index h : mesh.halfedges())
  {
    ++incoming[mesh.target(h)];
  }
  for (Mesh::Vertex_index v : mesh.vertices())
  {
    Mesh::size_type around = 0;
    if (mesh.halfedge(v) != Mesh::null_halfedge())
    {
      for (Mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
      {
        (void)h;
        ++around;
      }
    }
    if (around != incoming[v])
    {
      return false;
    }
  }
  return true;
}

// A mesh of a soup that is already a polygon mesh (oriented, manifold).
bool ToMesh(const Soup& soup, Mesh& mesh, std::string& error)
{
  if (AddFaces(soup, mesh))
  {
    for (Mesh::Vertex_index v : mesh.vertices())
    {
      if (mesh.is_isolated(v))
      {
        mesh.remove_vertex(v); // a point no triangle uses, as the soup's conversion drops it
      }
    }
    mesh.collect_garbage();
    return true;
  }
  mesh.clear();
  if (!vtkMedialCGALSoup::ToMesh(soup, mesh))
  {
    error = "the surface is not an oriented manifold";
    return false;
  }
  return true;
}

struct CountDuplicates : PMP::Default_orientation_visitor
{
  vtkIdType* Duplicated;
  void duplicated_vertex(std::size_t, std::size_t) { ++*this->Duplicated; }
};

vtkIdType BorderEdges(const Mesh& mesh)
{
  vtkIdType count = 0;
  for (Mesh::Halfedge_index h : mesh.halfedges())
  {
    count += mesh.is_border(h) ? 1 : 0;
  }
  return count;
}
}

namespace vtkMedialSurfaceRepair
{
bool Clean(Soup& soup, CleanCounts& counts, std::string& error, double tinyArea)
{
  counts = CleanCounts();
  try
  {
    std::vector<Point> points;
    Polygons polygons;
    ToPolygons(soup, points, polygons);
    std::vector<char> used(points.size(), 0);
    for (const auto& p : polygons)
    {
      for (std::size_t v : p)
      {
        used[v] = 1;
      }
    }
    const vtkIdType usedBefore = static_cast<vtkIdType>(std::count(used.begin(), used.end(), 1));
    const vtkIdType trianglesBefore = static_cast<vtkIdType>(polygons.size());
    PMP::repair_polygon_soup(points, polygons);
    counts.MergedPoints = usedBefore - static_cast<vtkIdType>(points.size());
    counts.DroppedTriangles = trianglesBefore - static_cast<vtkIdType>(polygons.size());
    CountDuplicates visitor;
    visitor.Duplicated = &counts.SplitPoints;
    PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(visitor));
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    counts.StitchedEdges = static_cast<vtkIdType>(PMP::stitch_borders(mesh));
    const vtkIdType faces = static_cast<vtkIdType>(mesh.number_of_faces());
    PMP::remove_degenerate_faces(mesh);
    mesh.collect_garbage();
    if (tinyArea > 0.0)
    {
      // Slivers, among the tiny faces only: needles (an edge 4 times shorter than the
      // longest, collapsed when under 10 times the square root of the area bound) and
      // caps (an angle above 170 degrees, flipped), a few rounds since each change can
      // leave another.
      for (int round = 0; round < 8; ++round)
      {
        std::vector<Mesh::Face_index> tiny;
        for (Mesh::Face_index f : mesh.faces())
        {
          if (PMP::face_area(f, mesh) <= tinyArea)
          {
            tiny.push_back(f);
          }
        }
        if (tiny.empty())
        {
          break;
        }
        PMP::experimental::remove_almost_degenerate_faces(
          tiny, mesh, std::cos(170.0 * CGAL_PI / 180.0), 4.0, 10.0 * std::sqrt(tinyArea));
        mesh.collect_garbage();
      }
    }
    counts.DegenerateFaces = faces - static_cast<vtkIdType>(mesh.number_of_faces());
    counts.BorderEdges = BorderEdges(mesh);
    FromMesh(mesh, soup);
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
  return true;
}

vtkIdType SplitPinchedPoints(Soup& soup)
{
  std::vector<Point> points;
  Polygons polygons;
  ToPolygons(soup, points, polygons);
  if (PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    return 0;
  }
  vtkIdType split = 0;
  CountDuplicates visitor;
  visitor.Duplicated = &split;
  PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(visitor));
  if (split == 0)
  {
    return 0;
  }
  // The copies are appended after the points; the triangles as they are now (the
  // copies' ids in them), their winding unchanged.
  for (std::size_t i = soup.Points.size(); i < points.size(); ++i)
  {
    soup.Points.push_back({ CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
      CGAL::to_double(points[i].z()) });
  }
  for (std::size_t t = 0; t < polygons.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      soup.Triangles[t][k] = static_cast<vtkIdType>(polygons[t][k]);
    }
  }
  return split;
}

bool FillHoles(Soup& soup, double maximumSize, std::vector<Hole>& holes, std::string& error)
{
  holes.clear();
  try
  {
    Mesh mesh;
    if (!ToMesh(soup, mesh, error))
    {
      return false;
    }
    // The area of each connected piece, for the sheet test.
    auto piece = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:piece", 0).first;
    const std::size_t pieces = PMP::connected_components(mesh, piece);
    std::vector<double> pieceArea(pieces, 0.0);
    for (Mesh::Face_index f : mesh.faces())
    {
      pieceArea[piece[f]] += PMP::face_area(f, mesh);
    }
    std::vector<Mesh::Halfedge_index> cycles;
    PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
    for (Mesh::Halfedge_index start : cycles)
    {
      Hole hole;
      double vector[3] = { 0, 0, 0 };
      std::vector<Point> loop;
      for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(start, mesh))
      {
        const Point& p = mesh.point(mesh.source(h));
        const Point& q = mesh.point(mesh.target(h));
        const double a[3] = { p.x(), p.y(), p.z() }, b[3] = { q.x(), q.y(), q.z() };
        vector[0] += 0.5 * (a[1] * b[2] - a[2] * b[1]);
        vector[1] += 0.5 * (a[2] * b[0] - a[0] * b[2]);
        vector[2] += 0.5 * (a[0] * b[1] - a[1] * b[0]);
        loop.push_back(p);
        ++hole.Edges;
      }
      // The diameter: every pair for a small cycle, else every fourth point against all
      // (within a few percent on a smooth cycle; the filling decision only needs that).
      const size_t step = loop.size() <= 2000 ? 1 : 4;
      double diameter2 = 0.0;
      for (size_t i = 0; i < loop.size(); i += step)
      {
        for (size_t j = 0; j < loop.size(); ++j)
        {
          diameter2 = std::max(diameter2, CGAL::to_double(CGAL::squared_distance(loop[i], loop[j])));
        }
      }
      hole.Size = std::sqrt(diameter2);
      hole.Area = std::sqrt(vector[0] * vector[0] + vector[1] * vector[1] + vector[2] * vector[2]);
      hole.PieceArea = pieceArea[piece[mesh.face(mesh.opposite(start))]];
      if (hole.Size <= maximumSize && hole.Area < 0.5 * hole.PieceArea)
      {
        std::vector<Mesh::Face_index> newFaces;
        std::vector<Mesh::Vertex_index> newVertices;
        hole.Faired = std::get<0>(PMP::triangulate_refine_and_fair_hole(
          mesh, start, std::back_inserter(newFaces), std::back_inserter(newVertices)));
        hole.Filled = !newFaces.empty();
      }
      holes.push_back(hole);
    }
    mesh.remove_property_map(piece);
    FromMesh(mesh, soup);
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
  return true;
}

std::vector<char> IntersectingPairs(
  const std::vector<std::array<double, 18>>& corners, const std::vector<std::array<vtkIdType, 6>>& ids)
{
  std::vector<char> result(corners.size(), 1);
  for (size_t i = 0; i < corners.size(); ++i)
  {
    const auto& x = corners[i];
    Point p[6];
    for (int k = 0; k < 6; ++k)
    {
      p[k] = Point(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
    }
    const K::Triangle_3 a(p[0], p[1], p[2]), b(p[3], p[4], p[5]);
    if (a.is_degenerate() || b.is_degenerate())
    {
      continue; // a defect in itself: counted as intersecting
    }
    int sharedA[3], sharedB[3], shared = 0;
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (ids[i][j] == ids[i][3 + k])
        {
          sharedA[shared] = j;
          sharedB[shared] = k;
          ++shared;
        }
      }
    }
    bool meet = true;
    if (shared == 0)
    {
      meet = CGAL::do_intersect(a, b);
    }
    else if (shared == 1)
    {
      // As PMP::self_intersections: the edge opposite the shared corner of each against
      // the other triangle.
      const int ja = sharedA[0], jb = sharedB[0];
      const K::Segment_3 oppositeA(p[(ja + 1) % 3], p[(ja + 2) % 3]);
      const K::Segment_3 oppositeB(p[3 + (jb + 1) % 3], p[3 + (jb + 2) % 3]);
      meet = CGAL::do_intersect(a, oppositeB) || CGAL::do_intersect(b, oppositeA);
    }
    else if (shared == 2)
    {
      // A shared edge: they overlap only when coplanar and on the same side of it.
      const Point& e0 = p[sharedA[0]];
      const Point& e1 = p[sharedA[1]];
      const Point& r = p[3 - sharedA[0] - sharedA[1]];
      const Point& s = p[3 + 3 - sharedB[0] - sharedB[1]];
      meet = CGAL::coplanar(e0, e1, r, s) && CGAL::coplanar_orientation(e0, e1, r, s) == CGAL::POSITIVE;
    }
    result[i] = meet ? 1 : 0;
  }
  return result;
}

bool RemoveSelfIntersections(Soup& soup, const std::vector<vtkIdType>& near, int rings, std::string& error)
{
  try
  {
    Mesh mesh;
    if (!ToMesh(soup, mesh, error))
    {
      return false;
    }
    // The working faces: `near` grown by `rings` rings (the mesh's faces are the soup's
    // triangles in order), so that CGAL searches and smooths there only.
    std::vector<Mesh::Face_index> range;
    if (near.empty())
    {
      range.assign(mesh.faces().begin(), mesh.faces().end());
    }
    else
    {
      std::vector<char> in(mesh.num_faces(), 0);
      for (vtkIdType f : near)
      {
        if (f >= 0 && static_cast<std::size_t>(f) < in.size() && !in[f])
        {
          in[f] = 1;
          range.push_back(Mesh::Face_index(static_cast<Mesh::size_type>(f)));
        }
      }
      for (int ring = 0; ring < rings; ++ring)
      {
        const std::size_t end = range.size();
        for (std::size_t i = 0; i < end; ++i)
        {
          for (Mesh::Face_index g : CGAL::faces_around_face(mesh.halfedge(range[i]), mesh))
          {
            if (g != Mesh::null_face() && !in[g])
            {
              in[g] = 1;
              range.push_back(g);
            }
          }
        }
      }
    }
    const bool solved = PMP::experimental::remove_self_intersections(range, mesh);
    mesh.collect_garbage();
    FromMesh(mesh, soup);
    if (!solved)
    {
      error = "CGAL's local self-intersection removal left some";
    }
    return solved;
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
}

bool OrientToBoundVolume(Soup& soup, vtkIdType& turned, std::string& error)
{
  turned = 0;
  try
  {
    Mesh mesh;
    if (!ToMesh(soup, mesh, error))
    {
      return false;
    }
    if (!CGAL::is_closed(mesh))
    {
      error = "the surface is not closed";
      return false;
    }
    // A face's first corner before and after: a turned component's faces reverse.
    std::vector<std::array<Mesh::Vertex_index, 2>> before;
    for (Mesh::Face_index f : mesh.faces())
    {
      const Mesh::Halfedge_index h = mesh.halfedge(f);
      before.push_back({ mesh.source(h), mesh.target(h) });
    }
    auto piece = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:piece", 0).first;
    const std::size_t pieces = PMP::connected_components(mesh, piece);
    PMP::orient_to_bound_a_volume(mesh);
    std::vector<char> flipped(pieces, 0);
    size_t i = 0;
    for (Mesh::Face_index f : mesh.faces())
    {
      bool same = false;
      for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      {
        same = same || (mesh.source(h) == before[i][0] && mesh.target(h) == before[i][1]);
      }
      flipped[piece[f]] = same ? 0 : 1;
      ++i;
    }
    turned = static_cast<vtkIdType>(std::count(flipped.begin(), flipped.end(), 1));
    mesh.remove_property_map(piece);
    FromMesh(mesh, soup);
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
  return true;
}

bool Wrap(const Soup& soup, double alpha, double offset, Soup& wrapped, std::string& error)
{
  try
  {
    std::vector<Point> points;
    points.reserve(soup.Points.size());
    for (const auto& x : soup.Points)
    {
      points.emplace_back(x[0], x[1], x[2]);
    }
    Mesh mesh;
    if (soup.Triangles.empty())
    {
      CGAL::alpha_wrap_3(points, alpha, offset, mesh);
    }
    else
    {
      std::vector<std::array<std::size_t, 3>> faces;
      faces.reserve(soup.Triangles.size());
      for (const auto& t : soup.Triangles)
      {
        faces.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]) });
      }
      CGAL::alpha_wrap_3(points, faces, alpha, offset, mesh);
    }
    FromMesh(mesh, wrapped);
  }
  catch (const std::exception& e)
  {
    error = std::string("CGAL: ") + e.what();
    return false;
  }
  if (wrapped.Triangles.empty())
  {
    error = "the alpha wrap is empty";
    return false;
  }
  return true;
}
}
