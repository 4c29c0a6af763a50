// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSolidPreparation
 * @brief Internal: the mesh preparation of every 3D filter with its RepairMode: the
 * surface checked as a solid and, when it is not one, repaired before it is prepared.
 *
 * Prepare() builds the vtkMedialTriangleMesh and the vtkMedialSurfaceQuery of the
 * input, then by mode:
 *  - NONE: nothing more (the behaviour before the repair existed, with the mesh's
 *    warnings);
 *  - AUTO: vtkMedialSolidCheck on the mesh and its tree. A valid solid goes on as it
 *    is (the same mesh, the same bits downstream). Otherwise the repair is asked; when
 *    it decides the input is a valid solid to the filters after all (the exact test
 *    clears the pairs, or all it would change is winding, a pinch or shells that only
 *    touch) the prepared mesh is kept, else mesh and query are built again on the
 *    repaired surface;
 *  - WRAP: the repair is asked to wrap the input first.
 *
 * The repair is a callback, so that this engine (Core, the lowest module) does not
 * depend on the module that implements it: the filters pass one that runs their
 * vtkMedialRepairFilter (MedialAxis::Repair, CGAL). Messages() are the warnings the
 * filter prints: the mesh's (valid or unrepaired input), or the repair's, one line
 * per step that ran.
 */
#ifndef vtkMedialSolidPreparation_h
#define vtkMedialSolidPreparation_h

#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkFieldData;
class vtkMedialSolidCheck;
class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;
class vtkPolyData;

class vtkMedialSolidPreparation
{
public:
  /// The values of vtkMedialRepairFilter's modes and of every filter's RepairMode.
  enum Modes
  {
    AUTO = 0,
    NONE = 1,
    WRAP = 2
  };

  /// What a repair returns.
  struct Repair
  {
    vtkSmartPointer<vtkPolyData> Surface;  // the repaired surface (the input when unchanged)
    bool Changed = false;                  // false: the input was a valid solid after all
    std::vector<std::string> Messages;     // one line per step that ran
    vtkSmartPointer<vtkFieldData> Report;  // the report's field data, for the filter's output
  };
  /// What Prepare() found of the input before asking for its repair, for the repair to
  /// start from (its mesh, tree and check are not built twice); null members when wrapping.
  struct Checked
  {
    const vtkMedialTriangleMesh* Mesh = nullptr;
    const vtkMedialSurfaceQuery* Query = nullptr;
    const vtkMedialSolidCheck* Check = nullptr;
  };
  /// Repairs `input` (wrap: the alpha wrap at once); false with `error` when it cannot.
  using Repairer =
    std::function<bool(vtkPolyData* input, bool wrap, const Checked& checked, Repair& result, std::string& error)>;

  /// The stages Prepare() goes through, for the caller's progress: the mesh, the
  /// queries (with the check in AUTO mode), the repair (then the mesh and the queries
  /// again, on the repaired surface).
  enum Stages
  {
    MESH = 0,
    QUERIES = 1,
    REPAIR = 2
  };

  /**
   * Builds `mesh` and `query` on `input` (repaired as `mode` says). False with a
   * one-line `error`, or "aborted" when `aborted` returns true between the stages.
   * `stage`, when given, is called as each stage begins.
   */
  bool Prepare(vtkPolyData* input, int mode, const Repairer& repair, int threads, vtkMedialTriangleMesh& mesh,
    vtkMedialSurfaceQuery& query, std::string& error, const std::function<bool()>& aborted = {},
    const std::function<void(int)>& stage = {});

  /// The surface the mesh was built on: the input, or the repaired surface.
  vtkPolyData* GetSurface() const { return this->Surface; }
  /// True when the mesh was built on a repaired surface.
  bool GetRepaired() const { return this->Repaired; }
  /// The warnings for the filter to print (see the class comment).
  const std::vector<std::string>& GetMessages() const { return this->Messages; }
  /// The repair's report (field data) when the surface was repaired, else null.
  vtkFieldData* GetReport() const { return this->Report; }

private:
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkFieldData> Report;
  std::vector<std::string> Messages;
  bool Repaired = false;
};

#endif
