// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialJunctionFilter
 * @brief Medial graph of planar polygons (with holes, several outer boundaries,
 * islands in holes): junctions, end points and the linear and parabolic arcs
 * between them, one graph per polygon.
 *
 * Algorithm:
 *  1. The input loops are prepared by vtkMedialPolygon (plane frame, validation,
 *     nesting, interior on the left of every edge): each outer loop with the holes
 *     directly inside it is one polygon, and an island inside a hole is a polygon
 *     again. Governors are the edges and the reflex vertices.
 *  2. The boundary is walked in order. Every edge gets
 *     max(MinimumSamplesPerEdge, SamplesPerUnitLength * length / diagonal)
 *     samples, the diagonal being its polygon's (so each polygon's graph is the
 *     one it would have alone); every reflex vertex gets samples over its cone of inward directions;
 *     every convex vertex is an end point (radius 0). For each sample the maximal
 *     inscribed disk tangent there is computed exactly (ray for an upper bound,
 *     then closest blockers until none is left) and its governor set recorded:
 *     the governors it touches within Tolerance * diagonal, a contact at a reflex
 *     end of an edge counting as that vertex.
 *  3. Between neighbouring samples whose governor sets differ, the three governors
 *     involved are solved exactly for the disk tangent to all three (edge-edge-edge
 *     linear; with vertices a quadratic; an edge and its own end vertex mean the
 *     disk is tangent to the edge at that vertex), and the solution is accepted when
 *     it lies between the two samples and is empty. When the interval hides more
 *     than one change it is bisected. A solution touching 3 or more distinct
 *     governors is a junction; one touching 2 is a transition (a regular point
 *     where a line turns into a parabola). Junctions found from several sides or
 *     from 4+ governors are merged within 1e-8 * diagonal.
 *  4. The medial graph follows from the boundary order: consecutive events
 *     (ends, junctions, transitions) are joined by one arc, found once from each
 *     side and emitted once.
 *
 * Input: vtkPolyData with polygon cells or closed polylines in any plane: any
 * number of outer boundaries, holes and islands, none touching another (see
 * vtkMedialPolygon for what is rejected).
 *
 * Output (in the input's plane): points = junctions, end points, transitions and
 * the inner points of parabolic arcs; lines = one cell per arc between events
 * (2 points when linear, ArcResolution + 2 when parabolic). Point data Radius
 * (double), MedialPointType (int: 0 end, 1 regular/arc sample, 2 junction; the 3D
 * codes of vtkMedialBallClassifier are 0 rim, 1 sheet, 2 seam, 3 junction),
 * GovernorCount (int); cell data ArcType (int: 0 linear, 1 parabolic) and
 * PolygonId (int: the polygon the arc lies in, 0 for the largest; the arcs of one
 * polygon follow one another). Bisectors of two reflex vertices are straight and
 * reported as linear.
 *
 * Output is identical for any thread count.
 *
 * Pieces (see vtkMedialPieces.h): the graph needs the whole polygon, and it is cheap:
 * the filter requests the whole input and computes the graph in piece 0; the other
 * pieces are empty.
 *
 * @sa vtkMedialAxisSampler
 */
#ifndef vtkMedialJunctionFilter_h
#define vtkMedialJunctionFilter_h

#include "vtkMedialAxisPlanarModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISPLANAR_EXPORT vtkMedialJunctionFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialJunctionFilter* New();
  vtkTypeMacro(vtkMedialJunctionFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The 2D codes of the point-data array MedialPointType.
  enum PointTypes
  {
    END_POINT = 0,     ///< the free end of a branch (one arc)
    REGULAR_POINT = 1, ///< a point inside an arc, or joining two arcs
    JUNCTION_POINT = 2 ///< where three or more arcs meet (three or more governors)
  };
  /// The codes of the cell-data array ArcType.
  enum ArcTypes
  {
    LINEAR_ARC = 0,   ///< a straight arc, between two edges
    PARABOLIC_ARC = 1 ///< a parabolic arc, between an edge and a reflex vertex
  };

  ///@{
  /// Boundary samples per diagonal of boundary length (default 100): an edge of length
  /// L gets max(MinimumSamplesPerEdge, ceil(SamplesPerUnitLength * L / D)) samples,
  /// D being the diagonal of the polygon's bounding box in its plane.
  vtkSetClampMacro(SamplesPerUnitLength, double, 0.0, 1e9);
  vtkGetMacro(SamplesPerUnitLength, double);
  ///@}

  ///@{
  /// Samples on every edge however short (default 2).
  vtkSetClampMacro(MinimumSamplesPerEdge, int, 1, 1000000);
  vtkGetMacro(MinimumSamplesPerEdge, int);
  ///@}

  ///@{
  /// Inner points of each parabolic arc (default 16).
  vtkSetClampMacro(ArcResolution, int, 1, 100000);
  vtkGetMacro(ArcResolution, int);
  ///@}

  ///@{
  /// Contact tolerance relative to the bounding-box diagonal (default 1e-9).
  vtkSetClampMacro(Tolerance, double, 1e-15, 1e-3);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// OpenMP threads; 0 means all cores (default 0). The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Figures from the last execution. UnresolvedIntervals counts sample intervals
  /// whose governor change could not be solved (0 on valid input).
  vtkGetMacro(NumberOfJunctions, vtkIdType);
  vtkGetMacro(NumberOfEndPoints, vtkIdType);
  /// Boundary samples whose maximal disk was solved (edge and reflex-vertex stations;
  /// not the sampler's NumberOfSamples, which is an input).
  vtkGetMacro(NumberOfBoundarySamples, vtkIdType);
  vtkGetMacro(UnresolvedIntervals, vtkIdType);
  /// Polygons (outer boundaries with their holes) of the input.
  vtkGetMacro(NumberOfPolygons, int);
  ///@}

protected:
  vtkMedialJunctionFilter();
  ~vtkMedialJunctionFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double SamplesPerUnitLength = 100.0;
  int MinimumSamplesPerEdge = 2;
  int ArcResolution = 16;
  double Tolerance = 1e-9;
  int NumberOfThreads = 0;

  vtkIdType NumberOfJunctions = 0;
  vtkIdType NumberOfEndPoints = 0;
  vtkIdType NumberOfBoundarySamples = 0;
  vtkIdType UnresolvedIntervals = 0;
  int NumberOfPolygons = 0;

private:
  vtkMedialJunctionFilter(const vtkMedialJunctionFilter&) = delete;
  void operator=(const vtkMedialJunctionFilter&) = delete;
};

#endif
