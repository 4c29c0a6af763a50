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
 *  1. coincident points are merged; the plane is fitted (Newell normal of the
 *     largest loop, sign made canonical so that reversed loops give the same
 *     frame) and every point must lie within 1e-6 * diagonal of it;
 *  2. points are expressed in an orthonormal frame (U, V) of that plane,
 *     centred on the bounding box;
 *  3. repeated points and straight (180 degree) vertices are dropped; a loop needs
 *     3 distinct vertices;
 *  4. loops must not cross or touch themselves or each other (uniform grid over
 *     the edges, double-precision orientation tests);
 *  5. the loop of largest area is the outer boundary, every other loop must lie
 *     inside it and not inside another hole; the outer loop is made counter-
 *     clockwise and the holes clockwise, so the interior is always on the left of
 *     an edge whatever the input point order.
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

  /// True when the data looks like planar loops (the 2D mode of vtkMedialAxisSampler):
  /// polygons all in one plane, or polylines of which one is closed or which come in
  /// 3 or more pieces. Build() then validates them.
  static bool LooksPlanarLoops(vtkPolyData* input);

  int GetNumberOfEdges() const { return static_cast<int>(this->Edges.size()); }
  int GetNumberOfVertices() const { return static_cast<int>(this->Points.size()) / 2; }
  const Edge& GetEdge(int e) const { return this->Edges[e]; }
  const double* GetPoint(int v) const { return &this->Points[2 * v]; }
  int GetVertexKind(int v) const { return this->Kinds[v]; }
  int GetIncomingEdge(int v) const { return this->Incoming[v]; }
  int GetOutgoingEdge(int v) const { return this->Outgoing[v]; }
  int GetNumberOfLoops() const { return this->NumberOfLoops; }
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
  void BuildGrid();
  bool EdgesTouch(int e, int f) const;
  void CellRange(double lo, double hi, int axis, int& first, int& last) const;

  std::vector<double> Points; // 2D, interleaved
  std::vector<Edge> Edges;
  std::vector<int> Kinds, Incoming, Outgoing;
  std::vector<std::vector<int>> LoopEdges;
  int NumberOfLoops = 0;
  double Diagonal = 0.0;
  double Frame[4][3] = {}; // origin, U, V, normal

  // Uniform grid over the edges, compressed rows.
  double GridOrigin[2] = { 0, 0 };
  double CellSize = 1.0;
  int Dims[2] = { 1, 1 };
  std::vector<int> CellStart, CellEdges;
  std::vector<int> EmptyRings;
};

template <typename F>
void vtkMedialPolygon::VisitEdgesNear(const double x[2], double reach, F&& visit) const
{
  int i0, i1, j0, j1;
  this->CellRange(x[0] - reach, x[0] + reach, 0, i0, i1);
  this->CellRange(x[1] - reach, x[1] + reach, 1, j0, j1);
  for (int j = j0; j <= j1; ++j)
  {
    for (int i = i0; i <= i1; ++i)
    {
      const int c = j * this->Dims[0] + i;
      for (int k = this->CellStart[c]; k < this->CellStart[c + 1]; ++k)
      {
        visit(this->CellEdges[k]);
      }
    }
  }
}

template <typename F>
void vtkMedialPolygon::VisitEdgesInRing(const double x[2], double inner, double reach, F&& visit) const
{
  int i0, i1, j0, j1;
  this->CellRange(x[0] - reach, x[0] + reach, 0, i0, i1);
  this->CellRange(x[1] - reach, x[1] + reach, 1, j0, j1);
  const double inner2 = inner > 0.0 ? inner * inner : -1.0;
  for (int j = j0; j <= j1; ++j)
  {
    const double y0 = this->GridOrigin[1] + j * this->CellSize - x[1];
    const double y1 = y0 + this->CellSize;
    const double fy = std::max(y0 * y0, y1 * y1);
    for (int i = i0; i <= i1; ++i)
    {
      const double x0 = this->GridOrigin[0] + i * this->CellSize - x[0];
      const double x1 = x0 + this->CellSize;
      if (std::max(x0 * x0, x1 * x1) + fy < inner2)
      {
        continue; // the whole cell lies inside the inner disk
      }
      const int c = j * this->Dims[0] + i;
      for (int k = this->CellStart[c]; k < this->CellStart[c + 1]; ++k)
      {
        visit(this->CellEdges[k]);
      }
    }
  }
}

#endif
