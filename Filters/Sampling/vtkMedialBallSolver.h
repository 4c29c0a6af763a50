// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialBallSolver.h
 * @brief Internal: one medial sample of a triangle mesh, shared by every sampling
 * strategy of vtkMedialAxisSampler.
 *
 * vtkMedialSolveBall finds the maximal admissible ball tangent at a given surface
 * point p on a given triangle, along the inward normal, by bisection or the
 * shrinking ball or the one-pass traversal (see vtkMedialAxisSampler); any strategy that
 * chooses its own surface points calls it (the Random strategy draws them with
 * vtkMedialDrawSurfacePoint, vtkMedialRandom.h). It is thread-safe after the mesh and
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

/// Maximal admissible ball tangent at p (lying on `triangle`). out.Valid is false when
/// the inward ray escapes through a hole.
/// `hintTriangle`: a triangle where the contact is likely (e.g. a neighbouring
/// sample's contact); it changes how fast ONE_PASS finds the ball, and the ball only
/// within the query's 1e-12 slack.
void vtkMedialSolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialBallParameters& param, vtkIdType triangle, const double p[3],
  vtkMedialSampleRecord& out, vtkIdType hintTriangle = -1);

#endif
