// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialRepairFilter
 * @brief Any polygonal surface in, a valid solid out: closed, consistently oriented,
 * manifold and free of self-intersections, bounding the solid the input means; with
 * a report of what was done.
 *
 * Algorithm (each step only when it is needed, in this order; see docs/repair.md):
 *  0. Check: the input is prepared as every filter prepares it (vtkMedialTriangleMesh:
 *     exact duplicates merged, shells oriented, nesting found) and checked as a solid
 *     (vtkMedialSolidCheck); the triangle pairs the double-precision search cannot
 *     clear are decided with CGAL's exact predicates, as
 *     CGAL::Polygon_mesh_processing::self_intersections decides them. A valid solid
 *     whose triangles already face out of it is passed through untouched (the output
 *     shares the input's arrays). Nested shells are not a defect: a cavity stays a
 *     cavity.
 *  1. Weld: when the surface is open, points at most WeldTolerance apart (relative to
 *     the diagonal) are merged, transitively (every chain of such pairs becomes one
 *     point: union-find over the pairs a vtkStaticPointLocator finds, so the result
 *     depends on the coordinates only, not on threads or order; vtkMedialRepairWeld),
 *     and the triangles that collapse are dropped.
 *  2. Clean: invalid, degenerate and duplicate triangles are dropped
 *     (repair_polygon_soup, remove_degenerate_faces), the soup is oriented (points on
 *     non-manifold edges and corners are split, orient_polygon_soup) and its borders
 *     stitched (stitch_borders). Every shell is then turned to bound a volume at the end
 *     (orient_to_bound_a_volume: cavities face into their cavity).
 *  3. Holes: a border cycle no larger than MaximumHoleSize (the diagonal of its box,
 *     relative to the surface's) that bounds less than half of its piece's area is
 *     filled (triangulate_refine_and_fair_hole); larger ones are left to step 7, and a
 *     piece whose border spans more than half of it is a sheet, not a holed shell.
 *     When no piece is closed and holes were too large (an open car body), the wrap
 *     would make a thin solid around the sheet: the larger holes are then filled too,
 *     and kept when that closes every piece.
 *  4. Union: closed shells whose solids overlap are joined exactly
 *     (corefine_and_compute_union), so two overlapping spheres become one solid.
 *     Shells that only touch (along an edge or at points, without a volume in common)
 *     are kept as separate bodies.
 *  5. Self-crossing shells: a closed shell that intersects itself is autorefined
 *     exactly (experimental::autorefine_and_remove_self_intersections: the patches
 *     inside are removed, so the shell bounds the solid it means, with that solid's
 *     topology); failing that, CGAL's local removal (experimental::
 *     remove_self_intersections, on a patch around the crossing pairs cut out of the
 *     shell and stitched back along its unchanged border; first when the pairs are few;
 *     the result of one shell is then checked and measured on the patch alone,
 *     vtkMedialRepairPatch); failing that, step 7. A point where two fans of triangles
 *     meet (a pinch) is split for CGAL's halfedge mesh. Corefinement needs shells
 *     that do not cross themselves, so a shell resolved here is joined to the shells
 *     it overlaps in the next round of steps 4 and 5.
 *  6. Stray sheets: open pieces that lie inside the closed shells' solid are removed.
 *  7. Wrap, the last resort for whatever is still not a valid solid (holes larger than
 *     MaximumHoleSize, open pieces outside the solid, failed steps): CGAL's 3D alpha
 *     wrapping of the surface with WrapAlpha and WrapOffset (relative to the diagonal):
 *     closed and manifold by construction, but offset outwards by WrapOffset and
 *     blind to features narrower than WrapAlpha. Mode WRAP goes there at once.
 *  8. Pinches: a point where the solid touches itself (its triangles form two or more
 *     fans that share only it: a horn torus's centre, two shells sharing a corner)
 *     gets a copy per extra fan, at the same place (as orient_polygon_soup duplicates
 *     it), so that the output is manifold at its vertices too. The check counts them
 *     (a valid solid with a pinch is not passed through); the other filters'
 *     preparations keep them (they merge equal points again; the balls are the same)
 *     and say where they are.
 * Progress is reported between the steps, and an abort (SetAbortExecute) is honoured
 * there and while the input's mesh is built: the output is then empty.
 * Input with no volume (no polygons, a single flat or open sheet with nothing closed)
 * is an error that says why, unless Mode is WRAP: then the wrap makes a thin solid
 * around it, with a warning.
 *
 * Report: the counts below, one line per step that ran (GetReportLine; also emitted
 * as warnings when ReportSteps is on), and the largest distance from the input surface
 * (its points and triangle centroids) to the output, relative to the diagonal, over the
 * input that is not buried inside the repaired solid (unless wrapped); the share of
 * the input's area that is buried (overlaps joined, sheets removed). As field data on
 * the output (vtkMedialArrayNames: RepairReport and the Repair* counts).
 *
 * Input: vtkPolyData (polygons and triangle strips; lines and vertices are only wrapped).
 * Output: vtkPolyData of triangles in double precision, or the input itself when it is
 * a valid solid; field data: the report.
 * Pieces: the whole input, in piece 0 (vtkMedialPieces: first piece).
 * @sa vtkMedialAxisSampler vtkMedialMeshFilter vtkMedialThickness (their RepairMode)
 */
#ifndef vtkMedialRepairFilter_h
#define vtkMedialRepairFilter_h

#include "vtkMedialAxisRepairModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <array>   // for the exact pair test
#include <string>  // for the report
#include <utility> // for the stage times
#include <vector> // for the report

class vtkMedialSolidCheck;
class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

class VTKMEDIALAXISREPAIR_EXPORT vtkMedialRepairFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings and the report of the last update).
  static vtkMedialRepairFilter* New();
  vtkTypeMacro(vtkMedialRepairFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The modes of this filter and of every filter's RepairMode.
  enum Modes
  {
    AUTO = 0, ///< repair what the check finds; a valid solid passes untouched
    NONE = 1, ///< check and report only (the output is the input)
    WRAP = 2  ///< the alpha wrap at once
  };

  ///@{
  /// What to do (default AUTO).
  vtkSetClampMacro(Mode, int, AUTO, WRAP);
  vtkGetMacro(Mode, int);
  void SetModeToAuto() { this->SetMode(AUTO); }
  void SetModeToNone() { this->SetMode(NONE); }
  void SetModeToWrap() { this->SetMode(WRAP); }
  ///@}

  /// "auto", "none", "wrap"; "unknown" otherwise.
  static const char* GetModeName(int mode);
  /// The mode named `name`, or -1.
  static int GetModeFromName(const char* name);

  ///@{
  /// Points at most this far apart, relative to the diagonal, are welded when the
  /// surface is open (default 1e-6, at most 1e-3: on stanford-bunny 2e-3 collapses 125
  /// triangles, 5e-3 nine tenths of them), transitively: keep it well below the shortest
  /// edge. The report warns when the weld collapses more than 1% of the triangles.
  vtkSetClampMacro(WeldTolerance, double, 0.0, 0.001);
  vtkGetMacro(WeldTolerance, double);
  ///@}

  ///@{
  /// Holes whose box diagonal is at most this, relative to the surface's, are filled
  /// (default 0.25: the Stanford bunny's largest hole, 0.18, is filled; the cut of a
  /// sphere whose cap is cut away, 0.36, is not); larger ones go to the wrap.
  vtkSetClampMacro(MaximumHoleSize, double, 0.0, 2.0);
  vtkGetMacro(MaximumHoleSize, double);
  ///@}

  ///@{
  /// The alpha wrap's alpha (the size of the ball that carves the wrap: no feature
  /// narrower than it is followed) and offset (the wrap's distance from the input),
  /// relative to the diagonal (defaults 0.02 and 0.001).
  vtkSetClampMacro(WrapAlpha, double, 1e-4, 1.0);
  vtkGetMacro(WrapAlpha, double);
  vtkSetClampMacro(WrapOffset, double, 1e-6, 0.1);
  vtkGetMacro(WrapOffset, double);
  ///@}

  ///@{
  /// Each step that ran is also emitted as a warning (default on). The filters that
  /// repair their input turn it off and print the lines themselves.
  vtkSetMacro(ReportSteps, bool);
  vtkGetMacro(ReportSteps, bool);
  vtkBooleanMacro(ReportSteps, bool);
  ///@}

  ///@{
  /// OpenMP threads for the check and the distances; 0 means all cores (default 0).
  /// The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// The report of the last update.
  vtkGetMacro(InputWasValid, bool);       ///< a valid solid: passed through untouched
  vtkGetMacro(Changed, bool);             ///< the output is not the input
  vtkGetMacro(IntersectingPairs, vtkIdType); ///< triangle pairs of the input that intersect (exact)
  vtkGetMacro(WeldedPoints, vtkIdType);     ///< merged into another point: points - clusters, never negative
  vtkGetMacro(DroppedTriangles, vtkIdType); ///< invalid, degenerate and duplicate
  vtkGetMacro(SplitPoints, vtkIdType);     ///< split off non-manifold edges and corners
  vtkGetMacro(StitchedEdges, vtkIdType);
  vtkGetMacro(RewoundTriangles, vtkIdType); ///< input triangles wound against the rest of their shell
  vtkGetMacro(TurnedShells, vtkIdType);     ///< input shells wound inward as a whole, turned over
  vtkGetMacro(FilledHoles, vtkIdType);
  vtkGetMacro(UnfilledHoles, vtkIdType);    ///< larger than MaximumHoleSize
  vtkGetMacro(ResolvedShells, vtkIdType);   ///< self-crossing shells made to bound their solid
  vtkGetMacro(JoinedShells, vtkIdType);     ///< unions made (one shell fewer each)
  vtkGetMacro(TouchingShells, vtkIdType);   ///< pairs of shells that only touch: kept
  vtkGetMacro(RemovedSheets, vtkIdType);    ///< open pieces removed from inside the solid
  vtkGetMacro(Wrapped, bool);
  vtkGetMacro(MaximumDistance, double);     ///< from the input to the output, relative to the diagonal
  vtkGetMacro(BuriedArea, double);          ///< share of the input's area inside the solid now
  vtkGetMacro(Seconds, double);             ///< wall time of the last update
  int GetNumberOfReportLines() { return static_cast<int>(this->Report.size()); }
  const char* GetReportLine(int i);
  /// Wall time of each stage that ran (check, weld, clean, holes, shells, sheets,
  /// orient, wrap, measure), in order: for benchmarks.
  int GetNumberOfTimedStages() { return static_cast<int>(this->StageTimes.size()); }
  const char* GetTimedStageName(int i);
  double GetTimedStageSeconds(int i);
  /// CPU time of the process (every thread) during each stage: on a loaded machine a
  /// fairer measure of the work than the wall time.
  double GetTimedStageCpuSeconds(int i);
  ///@}

#ifndef __VTK_WRAP__
  /**
   * Internal, for a filter's preparation (vtkMedialRepairCallback.h): the next update's
   * input has been prepared as `mesh` and `query` and checked (`check`), so the repair
   * starts from them instead of building them again. The pointers must stay valid
   * through that update; ClearCheckedInput() forgets them. The output is then the
   * input, with Changed false, when the repair would only change what the preparation
   * does anyway (winding, a pinch's split, touching shells kept apart).
   */
  void SetCheckedInput(
    const vtkMedialTriangleMesh* mesh, const vtkMedialSurfaceQuery* query, const vtkMedialSolidCheck* check)
  {
    this->CheckedMesh = mesh;
    this->CheckedQuery = query;
    this->CheckedResult = check;
  }
  /// Forgets what SetCheckedInput gave: the next update prepares its input itself.
  void ClearCheckedInput() { this->SetCheckedInput(nullptr, nullptr, nullptr); }

  /// Internal: CGAL's exact test of triangle pairs (as PMP::self_intersections decides
  /// them), for vtkMedialSolidCheck::Decide in the modules without CGAL.
  static std::vector<char> ExactPairTest(
    const std::vector<std::array<double, 18>>& corners, const std::vector<std::array<vtkIdType, 6>>& ids);
#endif

protected:
  vtkMedialRepairFilter();
  ~vtkMedialRepairFilter() override = default;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = AUTO;
  double WeldTolerance = 1e-6;
  double MaximumHoleSize = 0.25;
  double WrapAlpha = 0.02;
  double WrapOffset = 0.001;
  bool ReportSteps = true;
  int NumberOfThreads = 0;

  bool InputWasValid = false;
  bool Changed = false;
  vtkIdType IntersectingPairs = 0;
  vtkIdType WeldedPoints = 0;
  vtkIdType DroppedTriangles = 0;
  vtkIdType SplitPoints = 0;
  vtkIdType StitchedEdges = 0;
  vtkIdType RewoundTriangles = 0;
  vtkIdType TurnedShells = 0;
  vtkIdType FilledHoles = 0;
  vtkIdType UnfilledHoles = 0;
  vtkIdType ResolvedShells = 0;
  vtkIdType JoinedShells = 0;
  vtkIdType TouchingShells = 0;
  vtkIdType RemovedSheets = 0;
  bool Wrapped = false;
  double MaximumDistance = 0.0;
  double BuriedArea = 0.0;
  double Seconds = 0.0;
  std::vector<std::string> Report;
  std::vector<std::pair<std::string, double>> StageTimes;
  std::vector<double> StageCpuTimes;
  const vtkMedialTriangleMesh* CheckedMesh = nullptr;
  const vtkMedialSurfaceQuery* CheckedQuery = nullptr;
  const vtkMedialSolidCheck* CheckedResult = nullptr;

private:
  vtkMedialRepairFilter(const vtkMedialRepairFilter&) = delete;
  void operator=(const vtkMedialRepairFilter&) = delete;

  class vtkInternals; // the steps (vtkMedialRepairFilter.cxx)
  friend class vtkInternals;
};

#endif
