// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialBallSolver.h
 * @brief Internal: one medial sample of a triangle mesh, shared by every sampling
 * strategy of vtkMedialAxisSampler.
 *
 * vtkMedialDrawSurfacePoint draws the area-weighted random surface point of sample
 * `index` from the stream (seed, index) (the Random strategy's samples).
 * vtkMedialSolveBall finds the maximal admissible ball tangent at a given surface
 * point p on a given triangle, along the inward normal, by bisection or the
 * shrinking ball or the one-pass traversal (see vtkMedialAxisSampler); any strategy that
 * chooses its own surface points calls it. Both are thread-safe after the mesh and
 * the query are built. Internal header; not installed.
 */
#ifndef vtkMedialBallSolver_h
#define vtkMedialBallSolver_h

#include "vtkType.h"

class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;
struct vtkMedialSampleRecord;

struct vtkMedialBallParameters
{
  int Method;             // vtkMedialAxisSampler::BISECTION, SHRINKING_BALL or ONE_PASS
  double Tolerance;       // absolute bisection tolerance
  double CosMinAngle;     // cos(theta); 1 for theta = 0
  int MaximumIterations;  // shrinking-ball cap
};

/// Triangle of sample `index` (the one vtkMedialDrawSurfacePoint picks), without the point.
vtkIdType vtkMedialPickSampleTriangle(const vtkMedialTriangleMesh& mesh, vtkTypeUInt64 seed, vtkIdType index);

/// Surface point of sample `index`: a triangle picked by area, a uniform point on it.
void vtkMedialDrawSurfacePoint(const vtkMedialTriangleMesh& mesh, vtkTypeUInt64 seed,
  vtkIdType index, vtkIdType& triangle, double p[3]);

/// Maximal admissible ball tangent at p (lying on `triangle`). out.Valid is false when
/// the inward ray escapes through a hole.
/// `hintTriangle`: a triangle where the contact is likely (e.g. a neighbouring
/// sample's contact); it changes how fast ONE_PASS finds the ball, and the ball only
/// within the query's 1e-12 slack.
void vtkMedialSolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3],
  vtkMedialSampleRecord& out, vtkIdType hintTriangle = -1);

#endif
