// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialGovernors
 * @brief Internal: the governors of 3D medial balls (the surface regions a ball
 * touches), and the surface features they are made of.
 *
 * Features. Build() splits a closed vtkMedialTriangleMesh into the primitives a
 * medial ball can be tangent to (the report's 3D governors on a polyhedron):
 *  - PLANE: a maximal edge-connected group of coplanar triangles (adjacent
 *    triangles whose unit normals differ by at most 1e-9);
 *  - LINE: a maximal chain of collinear sharp edges (edges between two plane
 *    groups); a ball inside the solid can only touch a reflex one;
 *  - POINT: a mesh vertex; a ball can only touch a non-convex one.
 * Feature ids are dense: planes [0, P), lines [P, P + L), points [P + L, P + L + V)
 * with point id = P + L + vertex id. They depend only on the mesh (deterministic).
 *
 * Governors of a ball (Classify). The contacts are every triangle whose closest
 * point to the centre c is within radius + tolerance (vtkMedialSurfaceQuery::
 * TrianglesWithin). With theta > 0 (MinimumSeparationAngle) the sampler's rule
 * (vtkMedialSurfaceQuery::ContactFilter) splits them: the cap is the contacts on
 * the near side of the plane cut (q - c).u > r cos(theta), u the unit direction
 * to the sample point P (without P: to the deepest contact, when the ball overlaps
 * the surface), and the contacts inside the ball; the cap is one governor, P's. A
 * triangle crossing the cut also gives its closest point beyond it (a ball stopped
 * on the cone's rim touches there). A ball that overlaps the surface reads only
 * the contacts beyond the cap (TrianglesWithin with the filter), so a tessellated
 * cap costs nothing. Outside the cap, two contacts belong to one governor when
 *  - they are connected on the surface inside the band: the triangles share a
 *    vertex or an edge that is itself within radius + tolerance of c; or
 *  - their connected regions have the same feature; or
 *  - theta > 0 and the angle between them, seen from c, is below theta (single
 *    linkage: contacts closer than theta count as one).
 * The feature of a connected region is the feature of its nearest contact q on
 * triangle t: PLANE (t's group) when c - q is along t's inward normal, else LINE
 * when q is on a sharp edge and c - q is perpendicular to it, else POINT (q is a
 * vertex). Among contacts at the same distance a plane wins over a line, a line
 * over a point. A governor is simple when every contact point lies on its
 * feature within the tolerance (a face, a reflex edge, a reflex vertex), and
 * compound otherwise (a cap that overlaps the surface, theta-merged regions of
 * several features). Only simple governors have an exact equation
 * (vtkMedialSeamSolver). At theta = 0 there is no cap.
 *
 * MedialPointType (3D codes, vtkMedialArrayNames.h): 0 rim (at most one governor,
 * or radius within the tolerance: the sheet's free boundary, where the radius goes
 * to zero, or where contacts on both sides of a convex edge or ridge merge), 1 sheet
 * (2 governors), 2 seam (3), 3 junction (4 or more).
 *
 * API for the structure filters (thread-safe after Build, no allocation per call
 * beyond the output's vectors):
 * @code
 *   vtkMedialTriangleMesh mesh;  mesh.Build(surface, error);
 *   vtkMedialSurfaceQuery query; query.Build(&mesh, error);
 *   vtkMedialGovernors governors;
 *   governors.Build(mesh, query, { tolerance, theta }, error);
 *   vtkMedialGovernors::BallGovernors g;
 *   governors.Classify(centre, radius, surfacePointOrNull, g);
 *   int count = g.Count(), type = governors.PointType(g.Count(), radius);
 * @endcode
 */
#ifndef vtkMedialGovernors_h
#define vtkMedialGovernors_h

#include "vtkMedialTriangleBVH.h"
#include "vtkType.h"

#include <string>
#include <tuple>
#include <utility>
#include <vector>

class vtkMedialTriangleMesh;
class vtkMedialSurfaceQuery;

class vtkMedialGovernors
{
public:
  enum FeatureKinds
  {
    PLANE = 0,
    LINE = 1,
    POINT = 2
  };
  /// MedialPointType's 3D codes.
  enum PointTypes
  {
    RIM = 0,
    SHEET = 1,
    SEAM = 2,
    JUNCTION = 3
  };

  struct Feature
  {
    int Kind = PLANE;
    double Point[3] = { 0, 0, 0 };     // a point on the feature
    double Direction[3] = { 0, 0, 0 }; // PLANE: unit inward normal; LINE: unit direction
  };

  struct Settings
  {
    double Tolerance = 1e-6;             // contact band, relative to the diagonal
    double MinimumSeparationAngle = 0.0; // theta, degrees
    int Threads = 1;                     // for the preparation's sorts (same result for any)
  };

  /// The governors of one ball, sorted by feature id.
  struct BallGovernors
  {
    std::vector<int> Features;          // one feature per governor
    std::vector<unsigned char> Compound; // per governor: 1 when not a single feature
    std::vector<int> ContactFeatures;   // features of every connected contact region (sorted, unique)
    double NearestDistance = 0.0;       // closest surface point's distance (< radius: the ball overlaps the surface)
    int Count() const { return static_cast<int>(this->Features.size()); }
    bool AllSimple() const;
  };

  /// Splits the mesh into features. `query` must be built on `mesh`; both must outlive this object.
  bool Build(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const Settings& settings, std::string& error);

  /// Governors of the ball (centre, radius) with the Settings' tolerance and theta.
  /// surfacePoint (may be null) is the sample P the ball is tangent at.
  void Classify(const double centre[3], double radius, const double* surfacePoint, BallGovernors& out) const;
  /// The same with an absolute contact tolerance and theta in degrees.
  void Classify(const double centre[3], double radius, const double* surfacePoint,
    double absoluteTolerance, double thetaDegrees, BallGovernors& out) const;
  /// The same without a surface point, when the query's ContainsBall(centre, radius -
  /// absoluteTolerance) holds; false (and `out` unspecified) when it does not, found
  /// in the walk that reads the contacts.
  bool ClassifyIfEmpty(const double centre[3], double radius, double absoluteTolerance, double thetaDegrees,
    BallGovernors& out) const;

  /**
   * Every feature whose primitive is tangent to the sphere (centre, radius) within
   * `tolerance` where the ball touches it: a face's plane when the contact is on the
   * face, an edge's line and a vertex where the contact is on them (so a contact on
   * a reflex edge gives the edge and no face). Sorted ids. Returns false when some
   * surface point is closer than radius - tolerance (the ball is not empty). With
   * checkEmpty, also false when the query's ContainsBall(centre, radius - tolerance)
   * is, found in the same walk as the contacts. `nearby` (may be null): the query's
   * list of the triangles near the ball (vtkMedialSurfaceQuery::GatherNearby), read
   * instead of the tree when it covers the ball; the same answer.
   */
  bool TouchedFeatures(const double centre[3], double radius, double tolerance, std::vector<int>& out,
    bool checkEmpty = false, const vtkMedialTriangleBVH::Nearby* nearby = nullptr) const;

  /// MedialPointType of a ball with that many governors (see the class comment).
  int PointType(int governorCount, double radius) const;

  int GetNumberOfFeatures() const { return static_cast<int>(this->Features.size()); }
  int GetNumberOfPlanes() const { return this->NumberOfPlanes; }
  int GetNumberOfLines() const { return this->NumberOfLines; }
  const Feature& GetFeature(int id) const { return this->Features[id]; }
  /// True when one feature lies on the other's boundary (a face and one of its edges or
  /// vertices, a line and one of its vertices): a ball touching both touches them at one point.
  bool AreIncident(int a, int b) const;
  /// Distance from x to the feature's primitive (infinite plane or line, or the point).
  double DistanceToFeature(int id, const double x[3]) const;

  const vtkMedialTriangleMesh& GetMesh() const { return *this->Mesh; }
  const vtkMedialSurfaceQuery& GetQuery() const { return *this->Query; }
  /// Absolute contact tolerance (Settings.Tolerance times the diagonal).
  double GetContactTolerance() const { return this->ContactTolerance; }
  double GetMinimumSeparationAngle() const { return this->Theta; }
  double GetDiagonal() const { return this->Diagonal; }

  struct ClassifyScratch; // per-thread scratch space of Classify (defined in the .cxx)

private:
  using EdgeList = std::vector<std::tuple<vtkIdType, vtkIdType, vtkIdType>>; // (min, max vertex, triangle)
  // Build's passes: plane groups and sharp edges; lines of collinear sharp edges
  // (atVertex: each sharp edge at each of its vertices); vertices and their incidences.
  void BuildPlanes(const EdgeList& edges);
  void BuildLines(const EdgeList& edges, std::vector<std::pair<vtkIdType, int>>& atVertex);
  void BuildPoints(const std::vector<std::pair<vtkIdType, int>>& atVertex, int threads);
  // The contacts of a ball in s.Hits (s.Cap marks those in the cap around the
  // sample point). When the ball overlaps the surface (theta > 0) only the
  // contacts beyond the cap are read, and the cap's feature is returned (else -1).
  bool Classify(const double centre[3], double radius, const double* surfacePoint, double absoluteTolerance,
    double thetaDegrees, bool requireEmpty, BallGovernors& out) const;
  int GatherContacts(const double c[3], double radius, const double* surfacePoint, double tolerance,
    double thetaDegrees, bool requireEmpty, bool& blocked, ClassifyScratch& s) const;
  // With theta > 0: contacts on the triangles of the cap that lie beyond it.
  void AddContactsBeyondCap(const double c[3], double radius, double tolerance, ClassifyScratch& s) const;
  // The best contact of each set of s.Sets (s.Best, indexed by root).
  void BestContacts(ClassifyScratch& s) const;
  // Feature of the contact q (at `distance` from c) on `triangle`.
  int FeatureOfContact(const double c[3], const double q[3], double distance, vtkIdType triangle) const;
  // True when the contact q on `triangle` is part of feature f: on one of its
  // triangles (for a line, an adjacent face; for a point, an incident triangle),
  // or within `tolerance` of its primitive.
  bool Explains(int f, const double q[3], vtkIdType triangle, double tolerance) const;
  int PlaneOf(vtkIdType triangle) const { return this->TrianglePlane[triangle]; }
  // A vertex where two or more lines meet (a ball can touch it as a point).
  bool IsCorner(vtkIdType vertex) const;
  int LineOf(vtkIdType a, vtkIdType b) const;

  const vtkMedialTriangleMesh* Mesh = nullptr;
  const vtkMedialSurfaceQuery* Query = nullptr;
  std::vector<Feature> Features;
  int NumberOfPlanes = 0;
  int NumberOfLines = 0;
  std::vector<int> TrianglePlane;                 // plane feature of each triangle
  std::vector<std::pair<vtkIdType, vtkIdType>> SharpEdges; // (min, max) vertex ids, sorted
  std::vector<int> SharpEdgeLine;                 // line feature of each sharp edge
  std::vector<std::vector<int>> LinePlanes;       // planes along each line (sorted)
  std::vector<vtkIdType> VertexOffsets;           // CSR: incident features of each vertex
  std::vector<int> VertexIncident;                // planes and lines at each vertex (sorted)
  double ContactTolerance = 0.0;
  double Theta = 0.0;
  double Diagonal = 0.0;
};

#endif
