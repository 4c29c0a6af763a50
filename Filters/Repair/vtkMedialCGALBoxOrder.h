// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialCGALBoxOrder.h
 * @brief Internal (MedialAxis::Repair): makes the order in which CGAL 5.5 meets the
 * boxes of mesh edges and faces independent of where the allocator put them. Every
 * translation unit of the project that includes CGAL's polygon mesh processing must
 * include this first (vtkMedialSurfaceRepair.cxx, vtkMedialSurfaceRepairExact.cxx):
 * one definition of the box class for the whole program.
 *
 * Why: CGAL's corefinement (the union, the autorefinement) and the local
 * self-intersection removal look for the pairs of boxes that overlap with
 * box_intersection_d over `Box_with_info_d<double, 3, halfedge, ID_FROM_BOX_ADDRESS>`:
 * a box's id, which breaks the ties between boxes with equal coordinates, is its
 * address. The face boxes and the edge boxes are in two vectors, so whether a face box
 * comes before an edge box with the same coordinate is decided by which vector the
 * allocator placed lower, which changes from one call to the next in one process (the
 * first union of a process differed from the later ones: glibc serves its first large
 * blocks with mmap, later ones from the heap). The pairs' order decides the order of the
 * intersection points, and with it the triangulation of the cut faces where points are
 * cocircular (two spheres with the same facets meet in such points): the union of the
 * same two spheres gave different surfaces in one process.
 *
 * Here the box with a Surface_mesh halfedge takes CGAL's explicit ids (ID_EXPLICIT: a
 * counter, copied with the box) instead: boxes are numbered in the order they are made,
 * face boxes before edge boxes, each in mesh order, whatever their addresses. Within
 * one vector that is the order the addresses gave, so only the ties between the two
 * vectors change, and they now go the same way every time.
 */
#ifndef vtkMedialCGALBoxOrder_h
#define vtkMedialCGALBoxOrder_h

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL
{
namespace Box_intersection_d
{
template <>
class Box_with_info_d<double, 3, SM_Halfedge_index, ID_FROM_BOX_ADDRESS>
  : public Box_with_info_d<double, 3, SM_Halfedge_index, ID_EXPLICIT>
{
public:
  using Base = Box_with_info_d<double, 3, SM_Halfedge_index, ID_EXPLICIT>;
  using Base::Base;
  Box_with_info_d() = default;
};
}
}

#endif
