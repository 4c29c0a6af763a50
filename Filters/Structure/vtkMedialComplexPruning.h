// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialComplexPruning
 * @brief Internal: significance-ordered collapses of a 3D medial mesh (triangles, edges,
 * balls). Used by vtkMedialPruneFilter.
 *
 * Only elementary collapses are made: a triangle with a free edge (an edge of no other
 * triangle) goes with that edge, an edge of no triangle with a free end (a ball on no
 * other edge) goes with that ball. Collapses keep the homotopy type, so components and
 * the Euler characteristic never change.
 *
 * Passes:
 *  1. Burn (Yan et al. 2016's extended grassfire, on the simplices): the free faces
 *     start burning at their balls' radii; fire crosses a triangle from its free edge to
 *     the opposite ball (min over the edge's ends of B + distance, and never before the
 *     edge burnt) and an edge from its free end; collapses happen in order of time, so
 *     a seam burns once all but one of its sheets have. Each ball gets its burn time B
 *     (balls never reached: infinite, the core).
 *  2. Measures: per ball the erosion thickness B - R, the tubularity (B - R) / B and
 *     the scale axis cover 1 - 1/s (s: the smallest factor at which a neighbour's scaled
 *     ball covers it); per triangle and curve edge the separation angle theta from the
 *     slope of the radius (|grad R| = cos(theta / 2)) and lambda = R sin(theta / 2). A
 *     collapse is worth the largest value over the simplex's balls (or its own angle).
 *  3. Pruning: collapses again, least significant first, to the end; each removed
 *     simplex gets the running maximum (its level), so pruning at t keeps the simplices
 *     whose level is at least t, and that set is what the collapses left at that point.
 */
#ifndef vtkMedialComplexPruning_h
#define vtkMedialComplexPruning_h

#include "vtkType.h"

#include <functional>
#include <vector>

class vtkMedialSimplicialComplex;

class vtkMedialComplexPruning
{
public:
  /// Runs the passes with a vtkMedialPruneFilter measure; `diagonal` scales the absolute
  /// measures. Returns false when `aborted` returns true.
  bool Run(const vtkMedialSimplicialComplex& complex, int measure, double diagonal,
    const std::function<bool()>& aborted = {});

  /// Per ball: the burn time (pass 1) and its measure.
  std::vector<double> Burn;
  std::vector<double> VertexSignificance;
  /// Per simplex: the threshold from which pruning removes it.
  std::vector<double> VertexLevels, EdgeLevels, TriangleLevels;
  /// Levels of the collapses, in order (non-decreasing).
  std::vector<double> RemovalLevels;

  /// Collapses made by pruning at `threshold`.
  vtkIdType CountRemovedBelow(double threshold) const;
  /// Connected pieces removed at `threshold` (simplices joined through removed balls).
  vtkIdType CountRemovedPieces(double threshold) const;

private:
  enum Kind
  {
    TRIANGLE = 0, // a triangle with its free edge
    EDGE = 1      // an edge with its free end
  };
  struct Collapse
  {
    double Key;
    int Kind;
    vtkIdType Simplex;
    vtkIdType Face;
    bool operator>(const Collapse& o) const
    {
      return Key != o.Key ? Key > o.Key : (Kind != o.Kind ? Kind > o.Kind : Simplex > o.Simplex);
    }
  };
  using KeyFunction = std::function<double(int kind, vtkIdType simplex, vtkIdType face)>;
  using CollapseFunction = std::function<void(const Collapse&)>;

  // Every collapse until none is left, in order of `key` (evaluated again when popped).
  bool CollapseAll(const KeyFunction& key, const CollapseFunction& done, const std::function<bool()>& aborted);
  void ComputeBurn(const std::function<bool()>& aborted);
  void ComputeMeasures(int measure, double diagonal);
  vtkIdType OtherEnd(vtkIdType edge, vtkIdType v) const;
  vtkIdType Opposite(vtkIdType triangle, vtkIdType edge) const;

  const vtkMedialSimplicialComplex* Complex = nullptr;
  std::vector<double> TriangleAngle, EdgeAngle; // separation angle from the slope, degrees
  int Measure = 0;
  double Diagonal = 1.0;
};

#endif
