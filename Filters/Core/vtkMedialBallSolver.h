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
 * vtkMedialDrawSurfacePoint, vtkMedialRandom.h). With the smooth surface's normals
 * (vtkMedialBallParameters::Normals, theta > 0), vtkMedialSolveBall follows the normal
 * interpolated from the corners at p instead of the facet's, which a tessellation
 * tilts: the ball is then centred on the smooth surface's medial axis. vtkMedialSolveBallAlong
 * does the same along any inward direction (a vertex normal). All are thread-safe after the mesh
 * and the query are built. Internal header; not installed.
 */
#ifndef vtkMedialBallSolver_h
#define vtkMedialBallSolver_h

#include "vtkMedialTriangleBVH.h" // for BlockerChain
#include "vtkType.h"

#include <array>
#include <functional>
#include <vector>

class vtkMedialSurfaceNormals;
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
  // With theta > 0: the smooth surface's normals (vtkMedialSurfaceNormals); a sample's
  // ball then follows the smooth normal at its point instead of its facet's. Null: facets'.
  const vtkMedialSurfaceNormals* Normals = nullptr;
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

/// How far vtkMedialGrowBall may move a ball.
struct vtkMedialGrowthLimits
{
  // The grown ball comes within this distance of its sample p (|centre - p| - radius
  // at most this), or no farther from it than the ball it started from.
  double Tolerance = 0.0;
  // A ball whose contacts are all less than the slide angle apart (seen from its
  // centre) rounds a convex feature instead of spanning a wall: it may slide away from
  // them while it stays within SlideReach times its radius of p. The cosine of half the
  // angle; above 1: never.
  double CosHalfSlideAngle = 2.0;
  double SlideReach = 1.0;
  // Optional: whether a ball (centre, radius) whose contacts lie on these triangles
  // (-1: the sample's own faces) may slide (vtkMedialThickness: only where they lie on
  // walls that meet along convex edges near it). Unset: wherever the angle allows.
  std::function<bool(const vtkIdType* triangles, int count, const double* centre, double radius)> MaySlide;
  // Optional, with MaySlide: whether a surface point on triangle t, joining contacts on
  // these triangles, lies across a convex crease from them (the cheap test asked before
  // MaySlide where the thorough ascent's rules may apply; vtkMedialThickness: on another
  // wall that meets one of theirs along a convex crease). Unset: MaySlide alone.
  std::function<bool(const vtkIdType* triangles, int count, vtkIdType t)> Across;
  // Steps (each one ray and up to Probes closest-point queries), and sliding steps
  // (up to SlideProbes each), counted apart.
  int MaximumSteps = 1;
  int Probes = 1;
  int MaximumSlides = 16;
  int SlideProbes = 8;
  // A step that grows the radius by less than this fraction is the last.
  double MinimumGain = 1e-3;
};

/**
 * Grows an inscribed ball (out.Centre, out.Radius) whose sample is p: the centre moves
 * away from every surface point the ball touches, along the direction in which its
 * distance to all of them grows fastest (the nearest point to the origin of the convex
 * hull of the unit vectors from the contacts to the centre: the generalised gradient of
 * the distance to the surface), by the step after which the ball through the
 * slowest-receding contact's plane meets the surface (a ray gives the first bound;
 * each closest-point probe that finds the surface inside lowers it), within the
 * limits; then again from the new contacts. A probe that finds the surface inside
 * counts as the ball about its centre that touches it, so the ball stays inscribed.
 * Stops when the contacts surround the centre (no direction increases the distance),
 * when a step no longer grows it, or after the limits' steps.
 * Where that ascent slides, a second one that keeps the sliding ball's contacts runs too
 * (the start made exactly tangent to its contacts, a blocked sliding step ended on the
 * largest empty ball on its path, no stop after a small sliding step that found a new
 * contact, a contact found through a triangle's plane only not kept), and that does not
 * rely on exact coplanarity (a plane nearly parallel to the step, such as a face coplanar
 * with a contact to the input's precision, does not bound it; a start contact on its
 * triangle's edge or corner is a point, not the plane); where those last rules changed
 * anything, the ascent without them runs as well. Where one of these ascents stops
 * before it can slide (it reaches a branch after which the surface found would join its
 * contacts on walls that may slide, limits.MaySlide), a thorough one runs too: it probes
 * once more after probes that found only balls out of reach, takes a bound that grows
 * the ball by less than 1e-5 of its radius as a contact missed, keeps a plane's bound as
 * a contact where that plane meets the surface at the ball, and counts contacts within
 * 1e-5 of the radius (1e-7 otherwise). The largest ball is the result.
 * The contacts at the start: the planes of `faces` (the triangles around p, when the
 * ball touches p) and out.Contact (on out.ContactTriangle's plane, or a point when
 * out.Shrunk). out.Contact becomes its last contact.
 */
/// `plain`, when given: the plain ascent's ball; `kept`: the larger of the plain ascent's
/// and the one that keeps its contacts without the rules that do not rely on exact
/// coplanarity (a caller that compares balls at other points may still want those where
/// the largest lies too far from them); `prior`: the largest ball without the thorough
/// ascent. `surfacePoints`, when given: points of this query's surface found by earlier
/// calls (a caller that grows nearby balls in turn keeps it between them; it gets this
/// call's too); they only spare closest-point queries (a ball that holds one is not
/// empty, the nearest bounds a search), the balls are the same without them.
void vtkMedialGrowBall(const vtkMedialSurfaceQuery& query, const double p[3],
  const vtkMedialGrowthLimits& limits, const vtkIdType* faces, int faceCount, vtkMedialSampleRecord& out,
  vtkMedialSampleRecord* plain = nullptr, vtkMedialSampleRecord* kept = nullptr,
  vtkMedialSampleRecord* prior = nullptr, std::vector<std::array<double, 3>>* surfacePoints = nullptr);

#endif
