// SPDX-License-Identifier: BSD-3-Clause
// The repair's CGAL steps with exact constructions (Epeck): the union of two closed
// shells by corefinement and the autorefinement of a shell that crosses itself. This is
// the heaviest file to compile (about 90 CPU seconds and 2.7 GB with GCC 12): it holds
// nothing else. The results are rounded to doubles; vtkMedialRepairFilter tidies them.
#include "vtkMedialSurfaceRepair.h"

// First of the CGAL headers: the order of CGAL's box intersection (see there).
#include "vtkMedialCGALBoxOrder.h"

#include "vtkMedialCGALSoup.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
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
  if (!vtkMedialCGALSoup::ToMesh(soup, mesh))
  {
    error = "a shell is not an oriented manifold";
    return false;
  }
  return true;
}
using vtkMedialCGALSoup::FromMesh;
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
    // Shells that touch at points only come out as the same two shells (CGAL keeps a
    // point shared by two fans): nothing was joined, and a next round would "join"
    // them again.
    auto piece = out.add_property_map<Mesh::Face_index, std::size_t>("f:piece", 0).first;
    if (PMP::connected_components(out, piece) > 1)
    {
      error = "the shells only touch";
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
