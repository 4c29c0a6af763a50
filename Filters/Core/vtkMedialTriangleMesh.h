// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialTriangleMesh
 * @brief Internal: a validated triangle mesh in double precision, oriented as a solid.
 *
 * Build() takes any vtkPolyData surface and runs these passes:
 *  1. ValidateInput: rejects empty input, NaN/Inf coordinates, input without surface cells;
 *  2. ImportTriangles: reads the triangles (polygons and strips go through
 *     vtkTriangleFilter), remembering the input cell id, and merges exactly coincident
 *     points (as vtkStaticCleanPolyData with tolerance 0, in linear time), so that soups
 *     from STL/OBJ become connected; drops collapsed and duplicate triangles;
 *  3. BuildAdjacency: the triangles sharing each edge; counts boundary and non-manifold edges;
 *  4. OrientShells, MarkClosedShells, OrientByVolume: each shell (edge-connected
 *     component) is wound consistently by a breadth-first walk over manifold edges,
 *     marked closed when each of its edges is used an even number of times by it, and
 *     turned so that its own signed volume is positive;
 *  5. ComputeNormalsAndAreas: unit normals and areas;
 *  6. FindShellContacts (two shells or more): pairs of shells whose triangles touch or
 *     intersect, through a vtkMedialTriangleBVH box query and exact triangle tests;
 *  7. OrientByNesting (two closed shells or more): a ray from a point of each closed
 *     shell counts how many other closed shells enclose it (parity of the crossings).
 *     A shell inside an odd number of others bounds a cavity: it is turned so that its
 *     normals point into the cavity (out of the solid), as the 2D code does for holes.
 *     Disjoint shells at even depth are separate solid bodies. Shells that touch or
 *     intersect each other do not count for each other's depth;
 *  8. the area CDF used for sampling.
 * After Build, every normal points out of the solid, whatever the file's winding.
 *
 * It counts boundary edges (open mesh), non-manifold edges, shells that could not be
 * oriented, degenerate (zero-area) and duplicate triangles, cavities and touching
 * shells; Warnings() turns them into the messages every filter prints.
 */
#ifndef vtkMedialTriangleMesh_h
#define vtkMedialTriangleMesh_h

#include "vtkMedialBuffer.h"
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkPolyData;
class vtkMedialTriangleBVH;

class vtkMedialTriangleMesh
{
public:
  /// Returns false and fills `error` with a one-line reason on unusable input.
  /// `aborted`, when given, is polled between passes; true stops the build
  /// (false, error "aborted") so that a caller's abort is honoured promptly.
  bool Build(vtkPolyData* input, std::string& error, const std::function<bool()>& aborted = {});

  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->SourceCellIds.size()); }
  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size() / 3); }
  const double* GetPoint(vtkIdType i) const { return &this->Points[3 * i]; }
  const vtkIdType* GetTriangle(vtkIdType t) const { return &this->Triangles[3 * t]; }
  const double* GetNormal(vtkIdType t) const { return &this->Normals[3 * t]; }
  /// Frees EdgeNeighbours and PointTriangle (12 and 2 bytes a triangle) once the solid
  /// check has run.
  void FreeEdgeNeighbours()
  {
    this->EdgeNeighbours = vtkMedialBuffer<std::int32_t>();
    this->PointTriangle = vtkMedialBuffer<std::int32_t>();
  }

  /// On a closed, edge-manifold, oriented mesh (else 0): the vertices whose triangles
  /// form two or more fans that share only the vertex (pinched, non-manifold vertices:
  /// the surface touches itself there, as two shells touching at a point do), and in
  /// `example` (when given) the lowest such vertex, or -1. Free when the Euler
  /// characteristic rules them out (PinchedVertexBound() == 0, e.g. on any mesh whose
  /// shells are all of genus 0); else, with EdgeNeighbours, a walk of one fan per
  /// vertex, a step a corner (without them, the corners grouped by vertex).
  vtkIdType CountPinchedVertices(vtkIdType* example = nullptr) const;
  /// On a closed, edge-manifold, oriented mesh (else 0): 2 Shells - (V - E + F), which
  /// is the number of extra fans at pinched vertices plus twice the shells' total genus
  /// (splitting every pinched vertex into its fans gives closed orientable surfaces,
  /// one per shell, each of Euler characteristic 2 - 2 genus). So 0 means no pinched
  /// vertex, and an odd value at least one.
  vtkIdType PinchedVertexBound() const;
  /// Frees the normals (24 bytes a triangle) for a caller that reads them from a built
  /// vtkMedialSurfaceQuery instead (its tree keeps the same values); GetNormal and the
  /// Normals array must not be used afterwards.
  void ReleaseNormals() { vtkMedialBuffer<double>().swap(this->Normals); }
  /// Frees the points, triangles, normals, areas and area CDF (about 90 bytes a
  /// triangle) for a caller that has drawn its samples and from then on only queries a
  /// built vtkMedialSurfaceQuery (which reads the tree's copies). Afterwards only
  /// GetNumberOfTriangles, the scalar fields, Shells, Contacts, ShellOfTriangle and
  /// SourceCellIds remain; GetPoint, GetTriangle, GetNormal and PickTriangleByArea must
  /// not be used.
  void ReleaseGeometry();

  /// V - E + F of the triangulated surface (2 - 2 genus for a closed, connected one).
  vtkIdType GetEulerCharacteristic() const
  {
    return this->UsedPoints - this->Edges + this->GetNumberOfTriangles();
  }

  /// The triangles around each point, as offsets `start` (one per point, plus the end)
  /// into `around`; a point no triangle uses has none.
  void TrianglesAroundPoints(std::vector<vtkIdType>& start, std::vector<vtkIdType>& around) const;
  /// The same with 32-bit triangle ids (half the memory: 12 bytes a triangle), in
  /// buffers that give their memory back when freed.
  void TrianglesAroundPoints(vtkMedialBuffer<vtkIdType>& start, vtkMedialBuffer<std::int32_t>& around) const;

  /// Index of the triangle whose cumulative area bracket holds u in [0, 1).
  vtkIdType PickTriangleByArea(double u) const;

  /// One line per problem or notable fact of the input (duplicate triangles,
  /// non-manifold edges, non-orientable shells, cavities that were wound as solids, touching
  /// or intersecting shells), for the filters to print as warnings. Open surfaces
  /// and discarded samples are reported by the sampler, which knows the counts.
  std::vector<std::string> Warnings() const;

  /// Name of a shell in messages: "shell K (input cell C)".
  std::string ShellName(int shell) const;

  struct Shell
  {
    vtkIdType FirstTriangle = -1; // its lowest triangle id
    vtkIdType Triangles = 0;
    vtkIdType Rewound = 0;   // its triangles whose input winding was turned over
    bool Closed = false;     // every edge is used an even number of times within the shell
    bool Orientable = true;  // the breadth-first walk found no contradiction
    int Depth = 0;           // closed shells enclosing it (parity of the crossings)
    int Parent = -1;         // the innermost closed shell enclosing it
    double Volume = 0.0;     // signed, after orientation: > 0 a solid, < 0 a cavity
    double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  };
  /// Two shells whose triangles touch or intersect (within 1e-6 of the diagonal).
  struct ShellContact
  {
    int A = -1, B = -1;           // shell indices, A < B
    double Point[3] = { 0, 0, 0 }; // where: the centroid of one of the touching triangles
  };

  vtkMedialBuffer<double> Points;          // 3 per point
  vtkMedialBuffer<vtkIdType> Triangles;    // 3 per triangle, counter-clockwise seen from outside
  vtkMedialBuffer<vtkIdType> SourceCellIds; // input cell id of each triangle
  vtkMedialBuffer<double> Normals;         // unit normal out of the solid, 3 per triangle
  vtkMedialBuffer<double> Areas;
  vtkMedialBuffer<double> AreaCdf; // normalised cumulative area, last entry 1
  // AreaGuide[j]: the first entry of AreaCdf above j / (AreaGuide.size() - 1), so that a
  // pick searches only the few entries between two guides (one cache miss or two
  // instead of one per level of a binary search over millions).
  vtkMedialBuffer<std::uint32_t> AreaGuide;
  vtkMedialBuffer<int> ShellOfTriangle;
  // On a closed mesh without non-manifold edges (else empty): the three triangles that
  // share an edge with each triangle, 3 per triangle in the order of their edges'
  // (lower, higher) vertex ids: a triangle whose vertices are a < b < c has its
  // neighbours across ab, ac, bc. The solid check's normal-cone culling reads a patch's
  // boundary from them, and CountPinchedVertices its fans.
  vtkMedialBuffer<std::int32_t> EdgeNeighbours;
  // With EdgeNeighbours (else empty): a triangle of each point, -1 for a point that no
  // triangle uses; where CountPinchedVertices starts the walk of the point's fan.
  vtkMedialBuffer<std::int32_t> PointTriangle;
  std::vector<Shell> Shells; // in the order of their first triangle
  std::vector<ShellContact> Contacts;

  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  double Diagonal = 0.0;
  double TotalArea = 0.0;
  double Volume = 0.0; // enclosed volume: solids minus cavities (meaningful when closed)
  vtkIdType BoundaryEdges = 0;
  vtkIdType Edges = 0;      // distinct edges of the kept triangles
  vtkIdType UsedPoints = 0; // points referenced by the kept triangles
  vtkIdType NonManifoldEdges = 0;
  vtkIdType NonOrientableComponents = 0;
  vtkIdType DegenerateTriangles = 0;
  vtkIdType DuplicateTriangles = 0; // same three vertices as an earlier triangle: dropped
  vtkIdType Components = 0;         // shells
  vtkIdType FlippedComponents = 0;  // shells turned over (volume sign or nesting)
  vtkIdType Cavities = 0;           // closed shells at odd depth
  vtkIdType Bodies = 0;             // closed shells at even depth, and open shells

private:
  // Manifold neighbours of each triangle and the sorted edge uses (see BuildAdjacency).
  struct Adjacency;

  bool ValidateInput(vtkPolyData* input, std::string& error); // and reads the points
  void ImportTriangles(vtkPolyData* input);
  bool DropDuplicateTriangles(const Adjacency& adjacency); // true when some were dropped
  bool BuildAdjacency(Adjacency& adjacency, const std::function<bool()>& aborted);
  void OrientShells(const Adjacency& adjacency);
  void MarkClosedShells(const Adjacency& adjacency);
  void OrientByVolume();
  void ComputeNormalsAndAreas();
  bool FindShellContacts(const vtkMedialTriangleBVH& tree, const std::function<bool()>& aborted);
  void OrientByNesting(const vtkMedialTriangleBVH& tree);
  void FlipShell(int shell);
  bool BuildAreaCdf(std::string& error);
};

#endif
