// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPolygon
 * @brief Internal: planar polygon preparation and exact 2D queries, shared by
 * vtkMedialJunctionFilter and the 2D mode of vtkMedialAxisSampler.
 *
 * Build() accepts vtkPolyData whose loops are polygon cells or closed polylines
 * (a polyline whose last point equals its first, or open polylines that chain
 * end to end into closed loops, e.g. vtkCutter output), lying in any plane.
 * Polygons that share edges (a triangulated planar region) stand for the region
 * bounded by their edges used once.
 * Build() runs these passes, each stopping at the first problem with its reason:
 *  1. MergePoints: coincident points are merged;
 *  2. ReadLoops, ChainOpenPolylines: the loops are gathered (shared polygon edges
 *     replaced by the region's boundary, open polylines chained);
 *  3. FitFrame, ProjectLoops: the plane is fitted (Newell normal of the largest
 *     loop, sign made canonical so that reversed loops give the same frame; see
 *     vtkMedialPlane.h), points are expressed in an orthonormal frame (U, V) of it,
 *     centred on the bounding box, and every point must lie within 1e-6 * diagonal
 *     of it;
 *  4. CleanLoops: repeated points and straight (180 degree) vertices are dropped;
 *     a loop needs 3 distinct vertices;
 *  5. OrientLoops, NestLoops: a loop inside an even number of loops is an outer
 *     boundary, made counter-clockwise; inside an odd number, a hole of the
 *     smallest loop around it, made clockwise; so the interior is always on the
 *     left of an edge whatever the input point order. Each outer boundary with the
 *     holes directly inside it is one polygon (islands inside holes are polygons
 *     again); polygons are numbered by decreasing area, and their loops follow
 *     one another (outer first, then its holes in input order). Then the edges,
 *     the vertex kinds and the grid, and loops must not cross or touch themselves
 *     or each other (CheckTouchingEdges: the grid, double-precision orientation
 *     tests);
 *  6. MeasurePolygons: the diagonal of each polygon's box.
 *
 * Several polygons need no special care in the queries: a disk centred inside one
 * polygon and empty of its boundary lies inside it, so the polygons' medial axes
 * never meet.
 *
 * Queries (const, thread-safe after Build) run on a uniform grid over the edges
 * and decide in double precision: ray cast, bounded closest point, contains-ball,
 * with an optional contact filter that mirrors vtkMedialSurfaceQuery's (ignored
 * edges, and the cap of angle theta around the sample point).
 *
 * Governors of the 2D medial axis are edges (ids 0..E-1) and reflex vertices
 * (id E + vertex index).
 */
#ifndef vtkMedialPolygon_h
#define vtkMedialPolygon_h

#include "vtkMedialUniformGrid.h"
#include "vtkType.h"

#include <algorithm>
#include <string>
#include <vector>

class vtkPolyData;

class vtkMedialPolygon
{
public:
  struct Edge
  {
    int A, B;             // vertex indices, interior on the left of A -> B
    int Loop;
    vtkIdType SourceCell; // input cell the edge came from
    double Normal[2];     // unit inward (left) normal
    double Offset;        // Normal . x + Offset = signed distance to the edge's line
    double Length;
  };
  enum VertexKind
  {
    CONVEX = 0,
    REFLEX = 1
  };
  struct ContactFilter
  {
    int IgnoreEdge[2] = { -1, -1 };
    bool UseCap = false; // a point q blocks only where Cap . q <= CapLimit
    double Cap[2] = { 0, 0 };
    double CapLimit = 0.0;
  };

  /// Prepares the polygon. Returns false with a reason when the input is not valid planar loops.
  bool Build(vtkPolyData* input, std::string& error);

  int GetNumberOfEdges() const { return static_cast<int>(this->Edges.size()); }
  int GetNumberOfVertices() const { return static_cast<int>(this->Points.size()) / 2; }
  const Edge& GetEdge(int e) const { return this->Edges[e]; }
  const double* GetPoint(int v) const { return &this->Points[2 * v]; }
  int GetVertexKind(int v) const { return this->Kinds[v]; }
  int GetIncomingEdge(int v) const { return this->Incoming[v]; }
  int GetOutgoingEdge(int v) const { return this->Outgoing[v]; }
  int GetNumberOfLoops() const { return this->NumberOfLoops; }
  /// Polygons: outer loops with their holes, numbered by decreasing area.
  int GetNumberOfPolygons() const { return this->NumberOfPolygons; }
  /// The polygon a loop bounds (its own as an outer loop, its outer loop's as a hole).
  int GetLoopPolygon(int loop) const { return this->LoopPolygons[loop]; }
  /// The diagonal of the bounding box of a polygon (in the plane).
  double GetPolygonDiagonal(int polygon) const { return this->PolygonDiagonals[polygon]; }
  /// Edges of a loop in boundary order (interior on the left).
  const std::vector<int>& GetLoopEdges(int loop) const { return this->LoopEdges[loop]; }
  double GetDiagonal() const { return this->Diagonal; }

  /// Plane frame: x3 = Origin + x * U + y * V.
  void To3D(const double p[2], double x[3]) const;
  const double* GetNormal3D() const { return this->Frame[3]; }

  /// First hit of origin + t * direction (unit), t in (tMin, tMax), skipping filter's ignored edges.
  bool Intersect(const double origin[2], const double direction[2], double tMin, double tMax,
    const ContactFilter* filter, double& t, int& edge) const;
  /// Closest boundary point to x closer than upperBound. False when none.
  bool ClosestPoint(const double x[2], double upperBound, const ContactFilter* filter, double point[2],
    double& distance, int& edge) const;
  /// True when no boundary point lies strictly inside the disk (centre, radius).
  bool ContainsBall(const double centre[2], double radius, const ContactFilter* filter) const;
  /// Calls visit(edge) for every edge that may lie within `reach` of x (a superset).
  template <typename F>
  void VisitEdgesNear(const double x[2], double reach, F&& visit) const;
  /// The same, skipping cells entirely closer than `inner` to x (for an empty disk's rim).
  template <typename F>
  void VisitEdgesInRing(const double x[2], double inner, double reach, F&& visit) const;

  /// Closest point to x on edge e (restricted by the filter's cap); squared distance or HUGE_VAL.
  double ClosestPointOnEdge(int e, const double x[2], const ContactFilter* filter, double out[2]) const;

private:
  // The passes of Build (see the class comment), on the loops being prepared.
  struct LoopSet;
  bool MergePoints(vtkPolyData* input, LoopSet& set, std::string& error) const;
  bool ReadLoops(vtkPolyData* input, LoopSet& set, std::string& error) const;
  static void SharedEdgesToPolylines(LoopSet& set, size_t firstPolygon);
  bool ChainOpenPolylines(LoopSet& set, std::string& error) const;
  bool FitFrame(LoopSet& set, std::string& error);
  static double WidestTriangleNormal(const LoopSet& set, double normal[3]);
  bool ProjectLoops(LoopSet& set, std::string& error) const;
  static bool CleanLoops(LoopSet& set, std::string& error);
  bool OrientLoops(LoopSet& set, std::string& error);
  static void NestLoops(
    const LoopSet& set, const std::vector<double>& areas, std::vector<int>& parent, std::vector<int>& depth);
  bool MeasurePolygons();
  void AddLoop(const std::vector<double>& pts2, const std::vector<int>& loop, int index, vtkIdType cell);
  void ClassifyVertices();
  bool CheckTouchingEdges(std::string& error) const;

  void BuildGrid();
  bool EdgesTouch(int e, int f) const;
  // The grid cells covering [x - reach, x + reach].
  void CellBox(const double x[2], double reach, int lo[3], int hi[3]) const;

  std::vector<double> Points; // 2D, interleaved
  std::vector<Edge> Edges;
  std::vector<int> Kinds, Incoming, Outgoing;
  std::vector<std::vector<int>> LoopEdges;
  int NumberOfLoops = 0;
  int NumberOfPolygons = 0;
  std::vector<int> LoopPolygons;
  std::vector<double> PolygonDiagonals;
  double Diagonal = 0.0;
  double Frame[4][3] = {}; // origin, U, V, normal

  // Uniform grid over the edges (one layer); an edge lies in every cell it comes near.
  vtkMedialUniformGrid Grid;
  std::vector<int> EmptyRings; // per cell, rings of empty cells around it

};

template <typename F>
void vtkMedialPolygon::VisitEdgesNear(const double x[2], double reach, F&& visit) const
{
  int lo[3], hi[3];
  this->CellBox(x, reach, lo, hi);
  this->Grid.ForEachItemInBox(lo, hi, [&](vtkIdType e) { visit(static_cast<int>(e)); });
}

template <typename F>
void vtkMedialPolygon::VisitEdgesInRing(const double x[2], double inner, double reach, F&& visit) const
{
  int lo[3], hi[3];
  this->CellBox(x, reach, lo, hi);
  const double inner2 = inner > 0.0 ? inner * inner : -1.0;
  this->Grid.ForEachCellInBox(lo, hi, [&](const int* ijk, vtkIdType cell) {
    const double y0 = this->Grid.CellLow(1, ijk[1]) - x[1];
    const double y1 = y0 + this->Grid.GetCellSize(1);
    const double x0 = this->Grid.CellLow(0, ijk[0]) - x[0];
    const double x1 = x0 + this->Grid.GetCellSize(0);
    if (std::max(x0 * x0, x1 * x1) + std::max(y0 * y0, y1 * y1) < inner2)
    {
      return; // the whole cell lies inside the inner disk
    }
    this->Grid.ForEachItemInCell(cell, [&](vtkIdType e) { visit(static_cast<int>(e)); });
  });
}

#endif
