// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialQuadricSimplification
 * @brief Internal: Q-MAT's simplification of a medial mesh (Li et al. 2015) to a given
 * number of balls, by edge collapses under the spherical quadric error. Used by
 * vtkMedialSimplifyFilter.
 *
 * A ball m = (c, r) is a point of R^4. A plane n.x = d (n unit, pointing out of the
 * shape) that the ball should touch from inside gives the error (n.c + r - d)^2, a
 * quadric in m. Each ball starts with the tangent planes of its primitives: both
 * tangent planes of every triangle's slab (vtkMedialEnvelope::SlabTangentPlanes),
 * weighted by the triangle's area, and, for edges of no triangle, planes tangent to
 * the cone all around its axis, weighted by its lateral area.
 *
 * Collapses: an edge (a, b) becomes one ball at the minimiser of the summed quadric
 * (a 4 x 4 solve; when it is singular, or the minimiser leaves the segment's
 * neighbourhood or has a negative radius, the best of a, b and their midpoint), and
 * costs the quadric's value there. The cheapest collapse goes first; a collapse that
 * would change the topology (the link condition: the common neighbours of a and b
 * are exactly the third corners of the triangles on ab, and no edge xy has triangles
 * on both a and b; Dey et al. 1999) is skipped until its neighbourhood changes.
 * Collapses keep the homotopy type: components and Euler characteristic stay.
 *
 * When no collapse is left under the link condition before the target, the refused
 * collapses that keep the Euler characteristic are allowed (the medial mesh of a
 * sampled surface has small cycles bounding small cavities: such a collapse removes one
 * of each), still cheapest first; the components and the Euler characteristic never
 * change.
 *
 * Stops at the target number of balls, or earlier when no collapse is allowed.
 */
#ifndef vtkMedialQuadricSimplification_h
#define vtkMedialQuadricSimplification_h

#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

class vtkMedialSimplicialComplex;

class vtkMedialQuadricSimplification
{
public:
  /// Collapses edges until `target` balls are left (or none can go). Returns false
  /// when `aborted` returns true.
  bool Run(const vtkMedialSimplicialComplex& complex, vtkIdType target, const std::function<bool()>& aborted = {});

  /// The result: balls (centres and radii), edges with their triangle counts, triangles.
  std::vector<double> Points;
  std::vector<double> Radii;
  std::vector<std::array<vtkIdType, 2>> Edges;
  std::vector<int> EdgeTriangles;
  std::vector<std::array<vtkIdType, 3>> Triangles;
  /// Per result ball, the input ball it was last merged into (its id in the input).
  std::vector<vtkIdType> Source;
  /// Collapses refused by the link condition at the end (0 when the target was reached).
  vtkIdType BlockedCollapses = 0;

private:
  struct Quadric
  {
    double A[10] = { 0 }; // symmetric 4 x 4, upper triangle by rows
    double B[4] = { 0 };
    double C = 0.0;
    void AddPlane(const double n[3], double d, double weight);
    void Add(const Quadric& q);
    double Evaluate(const double m[4]) const;
    bool Minimise(double m[4]) const;
  };
  struct Candidate
  {
    double Cost;
    vtkIdType A, B;
    unsigned Version; // sum of the two balls' versions when it was queued
    bool operator>(const Candidate& o) const
    {
      return Cost != o.Cost ? Cost > o.Cost : (A != o.A ? A > o.A : B > o.B);
    }
  };

  void InitialQuadrics(const vtkMedialSimplicialComplex& complex);
  double CollapseCost(vtkIdType a, vtkIdType b, double m[4]) const;
  enum LinkVerdict
  {
    LINK_HOLDS = 0,   // the collapse keeps the homotopy type
    KEEPS_EULER = 1,  // it does not, but keeps the Euler characteristic
    CHANGES_EULER = 2 // refused
  };
  int LinkCondition(vtkIdType a, vtkIdType b) const;
  void Collapse(vtkIdType a, vtkIdType b, const double m[4]);
  void Extract();

  std::vector<std::array<double, 4>> Balls;
  std::vector<Quadric> Quadrics;
  std::vector<unsigned> Versions;
  std::vector<char> Alive;
  std::vector<std::vector<vtkIdType>> Neighbours;        // sorted
  std::vector<std::vector<vtkIdType>> VertexTriangles;   // may hold dead triangles
  std::vector<std::array<vtkIdType, 3>> AllTriangles;
  std::vector<char> TriangleAlive;
  double Scale = 1.0; // the balls' extent, for the regularisation
};

#endif
