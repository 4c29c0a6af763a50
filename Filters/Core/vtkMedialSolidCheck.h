// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSolidCheck
 * @brief Internal: the one answer to "is this prepared surface a valid solid", and if
 * not, why and where.
 *
 * A valid solid is closed (no boundary edge), manifold (no edge with more than two
 * triangles), consistently oriented (every shell orientable), has no degenerate or
 * duplicate triangle, no two shells that touch or intersect, no triangle pair that
 * intersects other than where the two share an edge or a corner, and a volume.
 * Nested shells are not a defect: the preparation turns a cavity's shell inward.
 *
 * Two passes:
 *  - Run(), the screen: reads the counts of vtkMedialTriangleMesh::Build and asks the
 *    tree for the pairs that may intersect (vtkMedialTriangleBVH::FindIntersectingPairs,
 *    in double precision with margins; skipped when another defect already decides,
 *    unless `allPairs`). Those pairs are a superset: touching pairs and pairs too close
 *    to tell apart are listed too. So Run() answers "certainly valid" (IsValid) or
 *    "to be repaired or decided exactly", and reuses the tree the queries need anyway.
 *  - Decide(), the exact answer: the candidate pairs tested with exact predicates
 *    (CGAL's, as PMP::self_intersections decides them; the test is handed in, since
 *    this module has no CGAL: vtkMedialRepairFilter::ExactPairTest). Then
 *    IsValidSolid() and Cause() are exact, and IntersectionPoint says where.
 *
 * Used by vtkMedialSolidPreparation (every filter's RepairMode AUTO), by
 * vtkMedialRepairFilter's first step, and by vtkMedialMeshFilter to name the cause
 * when the medial mesh's topology is not the solid's.
 */
#ifndef vtkMedialSolidCheck_h
#define vtkMedialSolidCheck_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

class vtkMedialSolidCheck
{
public:
  using PairList = std::vector<std::pair<vtkIdType, vtkIdType>>;
  /// Per pair of triangles (6 corners, a's then b's, and their point ids): whether
  /// the two intersect other than along a shared edge or at a shared corner.
  using ExactTest = std::function<std::vector<char>(
    const std::vector<std::array<double, 18>>& corners, const std::vector<std::array<vtkIdType, 6>>& ids)>;

  /// The screen, on the mesh that `query` was built on, with `threads` for the pair
  /// search (run only when no other defect was counted, or always with `allPairs`).
  void Run(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads,
    bool allPairs = false);

  /// PinchedVertices and PinchedVertex from `mesh` alone (Run calls it with its pair
  /// search; the medial mesh's warning calls it on its own).
  void CountPinches(const vtkMedialTriangleMesh& mesh);

  /// Nothing found: a valid solid.
  bool IsValid() const { return this->CountDefects() == 0 && this->Pairs.empty(); }
  /// Only triangle pairs were found, which the exact predicates may still clear.
  bool OnlyPairs() const { return this->CountDefects() == 0 && !this->Pairs.empty(); }
  /// One line per problem the screen found, e.g. "223 boundary edges (the surface is open)".
  std::vector<std::string> Problems() const;
  /// The pinched vertices as one clause ("2 pinched vertices (...), e.g. at (x, y, z)"),
  /// or empty when there are none.
  std::string PinchedClause() const;

  /// The exact pass: Pairs decided by `exact`, into Intersecting and IntersectionPoint.
  void Decide(const vtkMedialTriangleMesh& mesh, const ExactTest& exact);
  /// After Decide: exactly a valid solid.
  bool IsValidSolid() const { return this->Decided && this->CountDefects() == 0 && this->Intersecting.empty(); }
  /// After Decide, for a surface that is not a valid solid: why, as one clause (the
  /// first of: not manifold or not orientable, intersecting pairs and where, open,
  /// degenerate or duplicate triangles, shells in contact, no volume).
  std::string Cause() const;

  vtkIdType BoundaryEdges = 0;
  vtkIdType NonManifoldEdges = 0;
  vtkIdType NonOrientableShells = 0;
  vtkIdType DegenerateTriangles = 0;
  vtkIdType DuplicateTriangles = 0;
  vtkIdType ShellContacts = 0; // pairs of shells that touch or intersect
  bool NoVolume = false;       // closed, but the enclosed volume is nil
  /// Pinched (non-manifold) vertices, where the surface touches itself at a point
  /// (vtkMedialTriangleMesh::CountPinchedVertices), counted whenever the pair search
  /// runs: free on a mesh whose Euler characteristic rules them out (every shell of
  /// genus 0, as the 1.55 M horse), two passes over the corners otherwise. Not a defect
  /// for IsValid(): the solid is what it is there, the preparation's geometry and every
  /// ball are the same whether the point is split or not (and the preparation merges
  /// equal points again); vtkMedialRepairFilter splits them in its output, which is
  /// then vertex-manifold too. PinchedVertex is where the lowest one lies.
  vtkIdType PinchedVertices = 0;
  double PinchedVertex[3] = { 0, 0, 0 };
  bool PairsSearched = false;  // the pair search ran (Pairs is complete)
  /// Triangle pairs (mesh ids, a < b, sorted) that may intersect.
  PairList Pairs;
  /// The pair search's normal-cone culling: patches of the tree tested, those whose
  /// self-tests it skipped, and of those the ones whose boundary is pinched at a corner.
  long long PatchesTested = 0;
  long long PatchesCulled = 0;
  long long PinchedPatchesCulled = 0;
  bool Decided = false;
  /// After Decide: the pairs that intersect, by the exact test.
  PairList Intersecting;
  /// After Decide: a point of the first intersecting pair (its first triangle's centroid).
  double IntersectionPoint[3] = { 0, 0, 0 };

private:
  vtkIdType CountDefects() const;
};

#endif
