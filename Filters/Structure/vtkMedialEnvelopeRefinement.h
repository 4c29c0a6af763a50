// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialEnvelopeRefinement
 * @brief Internal: splits the edges of a medial mesh whose envelope crosses the surface,
 * until no interpolated ball protrudes by more than a tolerance. Used by
 * vtkMedialMeshFilter after the complex is built.
 *
 * Why: the complex joins inscribed balls, but the balls interpolated along its long
 * edges and wide triangles (cones and slabs, vtkMedialEnvelope.h) may cross the surface
 * where the medial sheet curves or the radius varies non-linearly between the vertex
 * balls: on fandisk by up to 2% of the diagonal, on horse.ply 1.1%, which was the
 * envelope's whole error (the vertex balls alone stay within 0.7%). A point of the
 * original inside such a protrusion is as far from the envelope's boundary as the
 * protrusion is deep, so the error shows in both directions.
 *
 * Algorithm, in rounds: every triangle is probed at the barycentric points of step 1/4
 * (its corners excepted), every edge of no triangle at 1/4, 1/2 and 3/4; the protrusion of
 * the interpolated ball (c, r) is r minus the distance from c to the surface (through
 * vtkMedialSurfaceQuery, in parallel), unless the vertex balls bound it within the
 * tolerance (vtkMedialEnvelope::ProtrusionBound: nearly 9 probes in 10 on horse.ply at
 * 100,000 samples), which decides alike without a query. Only whether a triangle or
 * edge protrudes by more than the tolerance decides, so a probe reads only the
 * triangles nearer than r - tolerance (an emptiness walk, not a nearest-point one: on
 * horse.ply at 100,000 samples 99.7% of the probes that need a query protrude by less),
 * and probing stops at the first probe past the tolerance (a triangle probes its sides
 * first). Each triangle or edge protruding by
 * more than the tolerance marks its longest edge (its own, for an edge); marked edges are split at
 * their midpoint m, in increasing order of their vertex ids, skipping an edge one of whose
 * triangles was already split in the round. The new ball is centred at m with the
 * largest inscribed radius there (its distance to the surface), so it is inscribed like
 * the others, and the triangles on the edge become two each. An edge split is a
 * subdivision: the components, the Euler characteristic and the homotopy type do not
 * change, and nothing new crosses the surface (the pieces lie in the old simplices).
 * Rounds end when nothing protrudes, after MaximumRounds, or when the number of balls
 * has doubled. Sequential splits over parallel probes: the result does not depend on
 * the thread count.
 */
#ifndef vtkMedialEnvelopeRefinement_h
#define vtkMedialEnvelopeRefinement_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

class vtkMedialSurfaceQuery;

class vtkMedialEnvelopeRefinement
{
public:
  /// The mesh, refined in place: ball centres (3 per ball) and radii, the vertices
  /// (ball ids), every edge (triangle sides included) with its triangle count, and the
  /// triangles. New balls are appended to the centres and radii and to the vertices.
  struct Mesh
  {
    std::vector<double>* Centres = nullptr;
    std::vector<double>* Radii = nullptr;
    std::vector<vtkIdType>* Vertices = nullptr;
    std::vector<std::array<vtkIdType, 2>>* Edges = nullptr;
    std::vector<int>* EdgeTriangles = nullptr;
    std::vector<std::array<vtkIdType, 3>>* Triangles = nullptr;
  };

  static constexpr int MaximumRounds = 12;

  /// Refines until no interpolated ball protrudes by more than `tolerance` (absolute).
  /// Returns the number of balls added; false in `completed` when aborted.
  vtkIdType Refine(const Mesh& mesh, const vtkMedialSurfaceQuery& query, double tolerance, int threads,
    const std::function<bool()>& aborted = {});

  /// The largest protrusion probed in the last round (absolute), and the rounds run.
  /// When the rounds ended with nothing beyond the tolerance, an upper bound at most the
  /// tolerance (a probe within it counts as its vertex balls' bound, or as the tolerance
  /// where a query decided it); when they ran out first, at least the largest protrusion
  /// beyond the tolerance that was met (probing stops at the first probe past it).
  double WorstProtrusion = 0.0;
  int Rounds = 0;

private:
  double Tolerance = 0.0;
  double Probe(const Mesh& mesh, const vtkMedialSurfaceQuery& query, const vtkIdType* ids, int n) const;
  double ProbeEdge(const Mesh& mesh, const vtkMedialSurfaceQuery& query, vtkIdType a, vtkIdType b) const;
  // The probes strictly inside a triangle (its side probes are its edges').
  double ProbeInterior(const Mesh& mesh, const vtkMedialSurfaceQuery& query, const std::array<vtkIdType, 3>& t) const;
  class EdgeProbes;
  class SideIndex;
  // Splits the marked edges (see the class comment); `free` holds the edges of no
  // triangle, `touched` gets the triangles rewritten or made.
  vtkIdType SplitEdges(const Mesh& mesh, const vtkMedialSurfaceQuery& query, SideIndex& index,
    std::vector<std::array<vtkIdType, 2>>& marked, std::vector<std::array<vtkIdType, 2>>& free,
    std::vector<vtkIdType>& touched, int threads);
};

#endif
