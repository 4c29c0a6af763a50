// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSolidCheck
 * @brief Internal: whether a prepared surface is a valid solid, from what the mesh's
 * preparation counted and a self-intersection search on the query's tree.
 *
 * A valid solid is closed (no boundary edge), manifold (no edge with more than two
 * triangles), consistently oriented (every shell orientable), has no degenerate or
 * duplicate triangle, no two shells that touch or intersect, no triangle pair that
 * intersects other than where the two share an edge or a corner, and a volume.
 * Nested shells are not a defect: the preparation turns a cavity's shell inward.
 *
 * Run() reads the counts of vtkMedialTriangleMesh::Build and asks the tree for the
 * pairs that may intersect (vtkMedialTriangleBVH::FindIntersectingPairs, in double
 * precision with margins). Those pairs are a superset: touching pairs and pairs too
 * close to tell apart are listed too, and the exact predicates of the repair
 * (vtkMedialRepairFilter, CGAL) decide them. So Run() answers "certainly valid" or
 * "to be repaired or decided exactly", and reuses the tree the queries need anyway:
 * on clean input its cost is the pair search alone, a third to a half of the
 * preparation's CPU time (0.8 s of 1.7 s on the 1.55M-triangle horse; docs/repair.md).
 *
 * Used by vtkMedialSolidPreparation (every filter's RepairMode AUTO) and by
 * vtkMedialRepairFilter's first step.
 */
#ifndef vtkMedialSolidCheck_h
#define vtkMedialSolidCheck_h

#include "vtkType.h"

#include <string>
#include <utility>
#include <vector>

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

class vtkMedialSolidCheck
{
public:
  /// Checks the mesh that `query` was built on, with `threads` for the pair search.
  void Run(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads);

  /// Nothing found: a valid solid.
  bool IsValid() const { return this->CountDefects() == 0 && this->Pairs.empty(); }
  /// Only triangle pairs were found, which the exact predicates may still clear.
  bool OnlyPairs() const { return this->CountDefects() == 0 && !this->Pairs.empty(); }
  /// One line per problem found, e.g. "open: 223 boundary edges".
  std::vector<std::string> Problems() const;

  vtkIdType BoundaryEdges = 0;
  vtkIdType NonManifoldEdges = 0;
  vtkIdType NonOrientableShells = 0;
  vtkIdType DegenerateTriangles = 0;
  vtkIdType DuplicateTriangles = 0;
  vtkIdType ShellContacts = 0; // pairs of shells that touch or intersect
  bool NoVolume = false;       // closed, but the enclosed volume is nil
  /// Triangle pairs (mesh ids, a < b, sorted) that may intersect.
  std::vector<std::pair<vtkIdType, vtkIdType>> Pairs;

private:
  vtkIdType CountDefects() const;
};

#endif
