// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBoundaryDistance
 * @brief Internal (MedialAxis::Reconstruction): distances from points to a shape's
 * boundary, and points spread uniformly over it; the engine of
 * vtkMedialReconstructionError and vtkMedialBallProtrusion.
 *
 * The boundary is either
 *  - a surface (3D): the input's polygons and strips as a vtkMedialTriangleMesh; or
 *  - curves (2D, planar loops): the edges of polygon cells and the segments of
 *    polylines.
 * Distances come from one of two engines:
 *  - OWN_BVH (surfaces): vtkMedialSurfaceQuery::ClosestPoint, the project's own BVH,
 *    exact in double precision;
 *  - CELL_LOCATOR: a vtkStaticCellLocator over the segments (curves; always) or over
 *    the input's cells as they are (surfaces).
 * Measured on horse.ply (97k triangles) the own BVH answers a closest-point query
 * from a reconstruction's vertex about 8 times faster and costs more to build
 * (medial-reconstruct-bench --compare-locator).
 *
 * Distances() runs in parallel (OpenMP) and returns the distances in point order,
 * so sums over them do not depend on the thread count. SamplePoints() draws point i
 * from the random stream (seed, i): the same points for any thread count.
 */
#ifndef vtkMedialBoundaryDistance_h
#define vtkMedialBoundaryDistance_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <memory>
#include <string>
#include <vector>

class vtkPoints;
class vtkPolyData;

class vtkMedialBoundaryDistance
{
public:
  vtkMedialBoundaryDistance();
  ~vtkMedialBoundaryDistance();
  vtkMedialBoundaryDistance(const vtkMedialBoundaryDistance&) = delete;
  vtkMedialBoundaryDistance& operator=(const vtkMedialBoundaryDistance&) = delete;

  enum Engines
  {
    OWN_BVH = 0,
    CELL_LOCATOR = 1
  };

  /// Prepares the boundary of `shape`: its triangulated polygons, or with `curves` the
  /// edges of its polygons and lines; `engine` answers the distances (curves always use
  /// the locator). False with a one-line reason when there is no boundary.
  bool Build(vtkPolyData* shape, bool curves, int engine, std::string& error);

  /// Distance from every point of `points` to the boundary, in point order. With
  /// `near` (one value per point; own BVH only), each query first looks no farther
  /// than a little beyond near[i], where the answer is likely (a ball's radius: a
  /// medial ball touches the surface), and only when nothing is that close from
  /// the whole shape's bound: the same exact distances, much faster from points close
  /// to the surface, since the tree's search is bounded from the start.
  std::vector<double> Distances(vtkPoints* points, int threads, const double* near = nullptr) const;

  /// The largest of radius[i] - d(points[i]) over the points, d the distance to the
  /// boundary (own BVH only), and 0 when none is positive: the exact figure, at a
  /// fraction of the cost of every distance, since a running maximum M bounds each
  /// query to radius[i] - M (a point whose excess cannot raise it is not measured).
  double LargestExcess(vtkPoints* points, const double* radius, int threads) const;

  /// `count` points uniform over the boundary (by area, or by length for curves);
  /// point i comes from the random stream (seed, i).
  vtkSmartPointer<vtkPoints> SamplePoints(vtkIdType count, vtkTypeUInt64 seed, int threads) const;

  /// True when `shape` is planar loops (the sampler's 2D mode): measure it by its curves.
  static bool IsPlanar(vtkPolyData* shape);

private:
  struct Surface;
  struct Curves;
  struct Locator;
  std::unique_ptr<Surface> SurfaceEngine; // triangles: area sampling, and the own BVH
  std::unique_ptr<Curves> CurveEngine;    // segments: length sampling
  std::unique_ptr<Locator> LocatorEngine; // distances through vtkStaticCellLocator
};

#endif
