// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialBallSolver.h
 * @brief Internal: one medial ball of a triangle mesh, shared by every sampling
 * strategy of vtkMedialAxisSampler and by vtkMedialThickness.
 *
 * vtkMedialSolveBall finds the maximal admissible ball tangent at a given surface
 * point p on a given triangle, along the inward normal, by bisection or the
 * shrinking ball or the one-pass traversal (see vtkMedialAxisSampler), then, when the
 * surface in the cap around p (which the separation angle ignores) enters the ball
 * deeper than MaximumProtrusion, shrinks it about its centre to the distance to that
 * surface, so that it is inscribed (out.Shrunk); any strategy that chooses its own
 * surface points calls it (the Random strategy draws them with
 * vtkMedialDrawSurfacePoint, vtkMedialRandom.h). vtkMedialSolveBallAlong does the same
 * along any inward direction (a vertex normal). All are thread-safe after the mesh
 * and the query are built. Internal header; not installed.
 */
#ifndef vtkMedialBallSolver_h
#define vtkMedialBallSolver_h

#include "vtkMedialTriangleBVH.h" // for BlockerChain
#include "vtkType.h"

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;
struct vtkMedialSampleRecord;

struct vtkMedialBallParameters
{
  // The same values as vtkMedialAxisSampler::Methods.
  enum Methods
  {
    BISECTION = 0,
    SHRINKING_BALL = 1,
    ONE_PASS = 2
  };
  int Method;             // one of Methods
  double Tolerance;       // absolute bisection tolerance
  double CosMinAngle;     // cos(theta); 1 for theta = 0
  double MaximumProtrusion; // absolute: a ball the cap's surface enters deeper is shrunk (HUGE_VAL: never)
  int MaximumIterations;  // shrinking-ball cap
};

/// Parameters in absolute units from the filters' settings: tolerance and protrusion
/// relative to the diagonal, angle in degrees. A protrusion of 1 or more: never shrink
/// (the angle rule alone).
vtkMedialBallParameters vtkMedialMakeBallParameters(int method, double tolerance,
  double minimumAngle, double maximumProtrusion, int maximumIterations, double diagonal);

/// Maximal admissible ball tangent at p (lying on `triangle`). out.Valid is false when
/// the inward ray escapes through a hole.
/// `hintTriangle`: a triangle where the contact is likely (e.g. a neighbouring
/// sample's contact); it changes how fast ONE_PASS finds the ball, and the ball only
/// within the query's 1e-12 slack. `blockers`, the same kind of hint: in, a nearby
/// ball's blockers (the previous sample's); out, this ball's (ONE_PASS; else empty).
/// `largestProtrusion`, when given: a running maximum of the balls' protrusions r - d(c)
/// (absolute; start it at 0), raised to this ball's where that is larger. ONE_PASS
/// measures it in its own cap search (exact up to the query's slack: away from the cap
/// the ball is empty by construction), the other methods by a closest-point query
/// within r - *largestProtrusion of the centre; balls that protrude no more than the
/// running maximum are not measured further, so it ends exact whatever the order. The
/// ball is the same with or without it.
void vtkMedialSolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3],
  vtkMedialSampleRecord& out, vtkIdType hintTriangle = -1,
  vtkMedialTriangleBVH::BlockerChain* blockers = nullptr, double* largestProtrusion = nullptr);

/// The same along a given unit inward direction n, e.g. a vertex normal.
/// `ownTriangle` (never blocking, its input cell is out.SourceCell) may be -1: then
/// the faces through p block only where they enter the ball, and ray hits at p are skipped.
void vtkMedialSolveBallAlong(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType ownTriangle, const double p[3], const double n[3],
  vtkMedialSampleRecord& out, vtkIdType hintTriangle = -1,
  vtkMedialTriangleBVH::BlockerChain* blockers = nullptr, double* largestProtrusion = nullptr);

#endif
