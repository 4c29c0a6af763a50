// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSurfaceRepair
 * @brief Internal (MedialAxis::Repair): the CGAL steps of vtkMedialRepairFilter, on
 * plain triangle soups, so that CGAL stays in two translation units:
 *  - vtkMedialSurfaceRepair.cxx (exact predicates, inexact constructions: Epick):
 *    soup cleaning, orientation and stitching, hole filling, removal of degenerate
 *    faces, the exact test of triangle pairs, CGAL's local self-intersection removal,
 *    the orientation to bound a volume and the alpha wrap;
 *  - vtkMedialSurfaceRepairExact.cxx (exact constructions: Epeck): the union of two
 *    closed shells by corefinement and the autorefinement of a shell that crosses
 *    itself. The exact results are rounded to doubles, then tidied (Clean) because the
 *    rounding can merge points.
 * Each function is one CGAL call or a short sequence of them; the decisions (which
 * step runs, on what) are vtkMedialRepairFilter's. None of them throws: CGAL's
 * exceptions become a false return.
 */
#ifndef vtkMedialSurfaceRepair_h
#define vtkMedialSurfaceRepair_h

#include "vtkType.h"

#include <array>
#include <string>
#include <vector>

namespace vtkMedialSurfaceRepair
{
/// Triangles over points, in double precision.
struct Soup
{
  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<vtkIdType, 3>> Triangles;
};

/// What Clean changed.
struct CleanCounts
{
  vtkIdType MergedPoints = 0;      // equal points merged (repair_polygon_soup)
  vtkIdType DroppedTriangles = 0;  // invalid and duplicate polygons (repair_polygon_soup)
  vtkIdType SplitPoints = 0;       // points duplicated to make the soup manifold (orient_polygon_soup)
  vtkIdType StitchedEdges = 0;     // pairs of border edges stitched (stitch_borders)
  vtkIdType DegenerateFaces = 0;   // degenerate and almost degenerate faces removed
  vtkIdType BorderEdges = 0;       // left afterwards
};
/// repair_polygon_soup, orient_polygon_soup, polygon_soup_to_polygon_mesh,
/// stitch_borders, remove_degenerate_faces, and experimental::
/// remove_almost_degenerate_faces on the faces whose area is at most `tinyArea` (the
/// slivers that exact constructions leave along intersection curves once rounded: the
/// preparation counts them as degenerate; edges up to 10 sqrt(tinyArea) long may be
/// collapsed); the soup is replaced by the mesh's faces.
bool Clean(Soup& soup, CleanCounts& counts, std::string& error, double tinyArea = 0.0);

/// One border cycle of a mesh and what FillHoles did with it.
struct Hole
{
  vtkIdType Edges = 0;
  double Size = 0.0;       // its diameter: the largest distance between two of its points
  double Area = 0.0;       // of the patch spanned by it (its vector area)
  double PieceArea = 0.0;  // of the connected piece it bounds
  bool Filled = false;
  bool Faired = false;     // the fairing succeeded (else the patch is refined only)
};
/**
 * Fills each border cycle no larger than `maximumSize` whose vector area is below half
 * of its piece's area (a smaller patch than the piece: a hole, not the rim of a
 * sheet), with triangulate_refine_and_fair_hole. Every cycle is listed in `holes`.
 */
bool FillHoles(Soup& soup, double maximumSize, std::vector<Hole>& holes, std::string& error);

/**
 * Pairs of triangles, each given by its 6 corners (a's three, then b's) and their
 * point ids (shared corners have the same id). Returns, per pair, whether the two
 * intersect other than along a shared edge or at a shared corner, decided with
 * CGAL's exact predicates exactly as PMP::self_intersections decides it.
 */
std::vector<char> IntersectingPairs(const std::vector<std::array<double, 18>>& corners,
  const std::vector<std::array<vtkIdType, 6>>& ids);

/// PMP::experimental::remove_self_intersections (local smoothing and hole filling) on
/// the triangles `near` (and their neighbours `rings` rings out; all of them when
/// empty); true when none is left there.
bool RemoveSelfIntersections(Soup& soup, const std::vector<vtkIdType>& near, int rings, std::string& error);

/// A closed, edge-manifold, oriented soup made vertex-manifold: every point whose
/// triangles form two or more fans (a pinch) gets one copy per fan after the first, at
/// the same place (as PMP::orient_polygon_soup duplicates them; the soup's winding is
/// kept, as it is already consistent). Returns the copies added.
vtkIdType SplitPinchedPoints(Soup& soup);

/// PMP::orient_to_bound_a_volume on a closed soup; `turned` counts the connected
/// components it turned over.
bool OrientToBoundVolume(Soup& soup, vtkIdType& turned, std::string& error);

/// CGAL::alpha_wrap_3 of the triangles (or, with none, of the points) with absolute
/// alpha and offset: a closed, 2-manifold, intersection-free surface around them.
bool Wrap(const Soup& soup, double alpha, double offset, Soup& wrapped, std::string& error);

/// PMP::corefine_and_compute_union of two closed shells, exactly; false when CGAL
/// cannot (e.g. the union would not be manifold: shells touching along an edge) and
/// when the union is still two pieces (shells touching at points only).
bool Union(const Soup& a, const Soup& b, Soup& joined, std::string& error);

/// PMP::experimental::autorefine_and_remove_self_intersections of a closed shell,
/// exactly; false when some self-intersection is left.
bool Autorefine(Soup& soup, std::string& error);
}

#endif
