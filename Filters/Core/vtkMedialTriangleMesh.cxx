// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialTriangleMesh.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialGroupByKey.h"
#include "vtkMedialTriangleBVH.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkLine.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangle.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <sstream>
#include <type_traits>

#include <omp.h>


namespace
{
namespace G = vtkMedialGeometry;
constexpr const char* SourceIdsName = "vtkMedialSourceCellId";
// Shells closer than this (relative to the diagonal) touch.
constexpr double ContactTolerance = 1e-6;
// Points of a shell tried as ray origins for its nesting depth.
constexpr int NestingTrials = 8;
// Messages list at most this many shells or pairs.
constexpr size_t ListedInMessages = 3;

bool BoxesOverlap(const double a[6], const double b[6], double pad)
{
  for (int k = 0; k < 3; ++k)
  {
    if (a[2 * k] > b[2 * k + 1] + pad || b[2 * k] > a[2 * k + 1] + pad)
    {
      return false;
    }
  }
  return true;
}

std::string FormatPoint(const double x[3])
{
  std::ostringstream os;
  os.precision(6);
  os << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  return os.str();
}

// The points as doubles, 3 per point, without a virtual call per point for the usual
// float and double arrays.
void ReadPoints(vtkPoints* points, vtkMedialBuffer<double>& out)
{
  const vtkIdType n = points->GetNumberOfPoints();
  out.resize(3 * static_cast<size_t>(n));
  vtkDataArray* data = points->GetData();
  auto* floats = vtkFloatArray::FastDownCast(data);
  auto* doubles = vtkDoubleArray::FastDownCast(data);
  if (floats || doubles)
  {
    const float* f = floats ? floats->GetPointer(0) : nullptr;
    const double* d = doubles ? doubles->GetPointer(0) : nullptr;
#pragma omp parallel for schedule(static)
    for (vtkIdType i = 0; i < 3 * n; ++i)
    {
      out[i] = f ? static_cast<double>(f[i]) : d[i];
    }
    return;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, &out[3 * i]);
  }
}

// Every cell of `cells` as a triangle, 3 ids each; false (nothing read) when a cell
// has another size.
template <class Ids>
bool ReadTriangleCells(const Ids* offsets, const Ids* connectivity, vtkIdType cells, vtkMedialBuffer<vtkIdType>& out)
{
  bool triangles = true;
#pragma omp parallel for schedule(static) reduction(&& : triangles)
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    triangles = triangles && offsets[c] == 3 * c;
  }
  if (!triangles)
  {
    return false;
  }
  out.resize(3 * static_cast<size_t>(cells));
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < 3 * cells; ++i)
  {
    out[i] = connectivity[i];
  }
  return true;
}
bool ReadTriangleCells(vtkCellArray* cells, vtkMedialBuffer<vtkIdType>& out)
{
  const vtkIdType n = cells->GetNumberOfCells();
  if (cells->GetNumberOfConnectivityIds() != 3 * n)
  {
    return false;
  }
  if (cells->IsStorage64Bit())
  {
    return ReadTriangleCells(cells->GetOffsetsArray64()->GetPointer(0),
      cells->GetConnectivityArray64()->GetPointer(0), n, out);
  }
  return ReadTriangleCells(cells->GetOffsetsArray32()->GetPointer(0),
    cells->GetConnectivityArray32()->GetPointer(0), n, out);
}

// Merges exactly coincident points (equal doubles; -0 equals 0) into the lowest id
// among them, as vtkStaticCleanPolyData does with tolerance 0: the kept points keep
// their order (unused ones too) and the triangles are renumbered. Linear: points
// are grouped by a hash of their coordinates, then compared within each group.
void MergeCoincidentPoints(vtkMedialBuffer<double>& points, vtkMedialBuffer<vtkIdType>& triangles)
{
  const vtkIdType np = static_cast<vtkIdType>(points.size() / 3);
  vtkIdType buckets = 1;
  while (buckets < np)
  {
    buckets <<= 1;
  }
  vtkMedialBuffer<vtkIdType> hash(np);
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < np; ++i)
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (int k = 0; k < 3; ++k)
    {
      const double x = points[3 * i + k] + 0.0; // -0 becomes +0
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof(bits));
      h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
      h ^= h >> 33;
    }
    hash[i] = static_cast<vtkIdType>(h & static_cast<std::uint64_t>(buckets - 1));
  }
  vtkMedialBuffer<vtkIdType> byHash(np);
  const vtkMedialBuffer<vtkIdType> offsets = vtkMedialGroupByKey(
    np, buckets, [&](vtkIdType i) { return hash[i]; }, [&](vtkIdType i, vtkIdType at) { byHash[at] = i; });
  vtkMedialBuffer<vtkIdType>& merged = hash; // reused: the point each one merges into
  vtkIdType mergedCount = 0;
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : mergedCount)
  for (vtkIdType b = 0; b < buckets; ++b)
  {
    for (vtkIdType i = offsets[b]; i < offsets[b + 1]; ++i)
    {
      const vtkIdType p = byHash[i];
      merged[p] = p;
      for (vtkIdType j = offsets[b]; j < i; ++j)
      {
        const vtkIdType q = byHash[j];
        if (merged[q] == q && points[3 * p] == points[3 * q] && points[3 * p + 1] == points[3 * q + 1] &&
          points[3 * p + 2] == points[3 * q + 2])
        {
          merged[p] = q;
          ++mergedCount;
          break;
        }
      }
    }
  }
  if (mergedCount == 0)
  {
    return;
  }
  vtkMedialBuffer<vtkIdType>& newId = byHash; // reused
  vtkIdType kept = 0;
  for (vtkIdType p = 0; p < np; ++p)
  {
    if (merged[p] == p)
    {
      std::copy_n(&points[3 * p], 3, &points[3 * kept]);
      newId[p] = kept++;
    }
  }
  points.resize(3 * kept);
#pragma omp parallel for schedule(static)
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(triangles.size()); ++i)
  {
    triangles[i] = newId[merged[triangles[i]]];
  }
}
}

struct vtkMedialTriangleMesh::Adjacency
{
  // The uses of edges (Lo, Hi), Lo < Hi, grouped by Lo: Uses[First[Lo], First[Lo + 1]),
  // sorted by Hi, then by triangle. The uses of one edge are adjacent.
  // 32-bit fields (Build rejects larger meshes): half the memory to fill and sort.
  struct EdgeUse
  {
    std::int32_t Hi;
    std::int32_t TriangleAndDirection; // 2 * triangle, + 1 when the triangle walks Lo -> Hi
    bool operator<(const EdgeUse& o) const
    {
      return Hi != o.Hi ? Hi < o.Hi : TriangleAndDirection < o.TriangleAndDirection;
    }
    vtkIdType Triangle() const { return TriangleAndDirection >> 1; }
    bool Forward() const { return (TriangleAndDirection & 1) != 0; }
  };
  vtkMedialBuffer<vtkIdType> First;
  vtkMedialBuffer<EdgeUse> Uses;
  // Entries k < Degree of each triangle are set, the others never read.
  vtkMedialBuffer<std::int32_t> Neighbour; // 3 per triangle, across manifold edges
  vtkMedialBuffer<char> SameDirection;  // 3 per triangle: the neighbour walks the edge the same way
  vtkMedialBuffer<unsigned char> Degree; // neighbours of each triangle
  vtkMedialBuffer<std::int32_t> PointTriangle; // a triangle of each point (its last), or -1

  // Calls visit(begin, end) for the uses [begin, end) of each edge, in (Lo, Hi) order;
  // only for the edges whose lower vertex is in [loBegin, loEnd) when given.
  template <class Visit>
  void ForEachEdge(Visit visit, vtkIdType loBegin = 0, vtkIdType loEnd = -1) const
  {
    const vtkIdType points = static_cast<vtkIdType>(this->First.size()) - 1;
    for (vtkIdType lo = loBegin; lo < (loEnd < 0 ? points : loEnd); ++lo)
    {
      const size_t last = static_cast<size_t>(this->First[lo + 1]);
      for (size_t i = static_cast<size_t>(this->First[lo]); i < last;)
      {
        size_t j = i + 1;
        while (j < last && this->Uses[j].Hi == this->Uses[i].Hi)
        {
          ++j;
        }
        visit(i, j);
        i = j;
      }
    }
  }
};

bool vtkMedialTriangleMesh::Build(
  vtkPolyData* input, std::string& error, const std::function<bool()>& aborted)
{
  auto stop = [&]() {
    if (aborted && aborted())
    {
      error = "aborted";
      return true;
    }
    return false;
  };
  *this = vtkMedialTriangleMesh();
  if (!this->ValidateInput(input, error))
  {
    return false;
  }
  this->ImportTriangles(input);
  if (stop())
  {
    return false;
  }
  if (this->SourceCellIds.empty())
  {
    error = "input has no non-degenerate triangles";
    return false;
  }
  // The adjacency and the tree number triangles and points in 32 bits.
  if (this->GetNumberOfPoints() >= (vtkIdType(1) << 31) ||
    static_cast<vtkIdType>(this->SourceCellIds.size()) >= (vtkIdType(1) << 30))
  {
    error = "input has too many triangles (at most 2^30) or points (2^31)";
    return false;
  }
  {
    Adjacency adjacency;
    if (stop() || !this->BuildAdjacency(adjacency, aborted) || stop())
    {
      error = "aborted";
      return false;
    }
    // Duplicates share their edges with the first copy: found there, and in the rare
    // input that has them, dropped before the adjacency is built again without them.
    if (this->DropDuplicateTriangles(adjacency))
    {
      adjacency = Adjacency();
      this->UsedPoints = 0;
      if (stop() || !this->BuildAdjacency(adjacency, aborted) || stop())
      {
        error = "aborted";
        return false;
      }
    }
    this->OrientShells(adjacency);
    if (stop())
    {
      return false;
    }
    this->MarkClosedShells(adjacency);
    if (this->BoundaryEdges == 0 && this->NonManifoldEdges == 0)
    {
      this->EdgeNeighbours = std::move(adjacency.Neighbour); // every triangle has three
      this->PointTriangle = std::move(adjacency.PointTriangle);
    }
  }
  if (stop())
  {
    return false;
  }
  this->OrientByVolume();
  if (stop())
  {
    return false;
  }
  this->ComputeNormalsAndAreas();
  if (stop())
  {
    return false;
  }
  if (this->Shells.size() > 1)
  {
    // A tree over every shell: which triangles may touch, which ones a ray crosses.
    vtkMedialTriangleBVH tree;
    if (!tree.Build(*this, aborted) || !this->FindShellContacts(tree, aborted))
    {
      error = stop() ? "aborted" : "cannot build the shell-nesting tree";
      return false;
    }
    this->OrientByNesting(tree);
  }
  for (const Shell& shell : this->Shells)
  {
    const bool cavity = shell.Closed && shell.Depth % 2 == 1;
    this->Cavities += cavity ? 1 : 0;
    this->Bodies += cavity ? 0 : 1;
    this->Volume += shell.Volume;
  }
  return this->BuildAreaCdf(error);
}

bool vtkMedialTriangleMesh::ValidateInput(vtkPolyData* input, std::string& error)
{
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    error = "input has no points or no cells";
    return false;
  }
  ReadPoints(input->GetPoints(), this->Points);
  const vtkIdType np = this->GetNumberOfPoints();
  for (vtkIdType i = 0; i < np; ++i)
  {
    const double* x = this->GetPoint(i);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      std::ostringstream os;
      os << "input point " << i << " has a NaN or infinite coordinate";
      error = os.str();
      return false;
    }
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    error = "input has no polygons or triangle strips (a surface is required)";
    return false;
  }
  return true;
}

// Triangulates, merges coincident points, and keeps the non-collapsed triangles
// with their input cell ids. A surface made of triangles only (the usual case) is
// read straight from its cell array; others go through vtkTriangleFilter.
void vtkMedialTriangleMesh::ImportTriangles(vtkPolyData* input)
{
  vtkMedialBuffer<vtkIdType> triangles, sourceIds;
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const bool direct = input->GetNumberOfStrips() == 0 && ReadTriangleCells(input->GetPolys(), triangles);
  if (!direct)
  {
    // Shallow copy: the pipeline's input must not be modified.
    vtkNew<vtkPolyData> shallow;
    shallow->CopyStructure(input);
    vtkNew<vtkIdFilter> ids;
    ids->SetInputData(shallow);
    ids->PointIdsOff();
    ids->CellIdsOn();
    ids->FieldDataOff();
    ids->SetCellIdsArrayName(SourceIdsName);
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputConnection(ids->GetOutputPort());
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    vtkPolyData* tri = triangulate->GetOutput();
    ReadTriangleCells(tri->GetPolys(), triangles);
    auto* cellIds = vtkIdTypeArray::SafeDownCast(tri->GetCellData()->GetArray(SourceIdsName));
    sourceIds.assign(cellIds->GetPointer(0), cellIds->GetPointer(0) + triangles.size() / 3);
  }
  MergeCoincidentPoints(this->Points, triangles);
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] = HUGE_VAL;
    this->Bounds[2 * k + 1] = -HUGE_VAL;
  }
  for (vtkIdType i = 0; i < this->GetNumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Bounds[2 * k] = std::min(this->Bounds[2 * k], this->Points[3 * i + k]);
      this->Bounds[2 * k + 1] = std::max(this->Bounds[2 * k + 1], this->Points[3 * i + k]);
    }
  }
  this->Diagonal = std::sqrt((this->Bounds[1] - this->Bounds[0]) * (this->Bounds[1] - this->Bounds[0]) +
    (this->Bounds[3] - this->Bounds[2]) * (this->Bounds[3] - this->Bounds[2]) +
    (this->Bounds[5] - this->Bounds[4]) * (this->Bounds[5] - this->Bounds[4]));

  // Drop the triangles collapsed by the merge, in place; usually there are none, and
  // the ids are written on every thread.
  const vtkIdType cells = static_cast<vtkIdType>(triangles.size() / 3);
  this->SourceCellIds.resize(cells);
  vtkIdType collapsed = 0;
#pragma omp parallel for schedule(static) reduction(+ : collapsed)
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const vtkIdType* pts = &triangles[3 * c];
    collapsed += (pts[0] == pts[1] || pts[1] == pts[2] || pts[0] == pts[2]) ? 1 : 0;
    this->SourceCellIds[c] = direct ? firstPoly + c : sourceIds[c];
  }
  if (collapsed == 0)
  {
    this->Triangles = std::move(triangles);
    return;
  }
  vtkIdType kept = 0;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const vtkIdType* pts = &triangles[3 * c];
    if (pts[0] == pts[1] || pts[1] == pts[2] || pts[0] == pts[2])
    {
      ++this->DegenerateTriangles;
      continue;
    }
    std::copy_n(pts, 3, &triangles[3 * kept]);
    this->SourceCellIds[kept++] = direct ? firstPoly + c : sourceIds[c];
  }
  triangles.resize(3 * kept);
  this->SourceCellIds.resize(kept);
  this->Triangles = std::move(triangles);
}

// A triangle with the same three vertices as an earlier one (either orientation) would
// make each of its edges non-manifold and block every ray leaving it: keep the first.
// Such triangles share every edge: each triangle looks among the other uses of the
// edge between its two lowest vertices for an earlier one with the same third vertex.
bool vtkMedialTriangleMesh::DropDuplicateTriangles(const Adjacency& adjacency)
{
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  vtkMedialBuffer<char> duplicate(nt);
  vtkIdType duplicates = 0;
#pragma omp parallel for schedule(static) reduction(+ : duplicates)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    std::array<vtkIdType, 3> v = { this->Triangles[3 * t], this->Triangles[3 * t + 1], this->Triangles[3 * t + 2] };
    std::sort(v.begin(), v.end());
    const auto last = adjacency.Uses.begin() + adjacency.First[v[0] + 1];
    auto use = std::lower_bound(adjacency.Uses.begin() + adjacency.First[v[0]], last,
      Adjacency::EdgeUse{ static_cast<std::int32_t>(v[1]), 0 });
    bool earlier = false;
    for (; use != last && use->Hi == v[1] && use->Triangle() < t && !earlier; ++use)
    {
      const vtkIdType* w = &this->Triangles[3 * use->Triangle()];
      earlier = (w[0] == v[2] || w[1] == v[2] || w[2] == v[2]);
    }
    duplicate[t] = earlier;
    duplicates += earlier ? 1 : 0;
  }
  this->DuplicateTriangles = duplicates;
  if (this->DuplicateTriangles == 0)
  {
    return false;
  }
  size_t kept = 0;
  for (size_t t = 0; t < static_cast<size_t>(nt); ++t)
  {
    if (!duplicate[t])
    {
      std::copy_n(&this->Triangles[3 * t], 3, &this->Triangles[3 * kept]);
      this->SourceCellIds[kept++] = this->SourceCellIds[t];
    }
  }
  this->Triangles.resize(3 * kept);
  this->SourceCellIds.resize(kept);
  return true;
}

// Edge uses sorted so that the uses of one edge are adjacent; manifold edges (two
// uses) link their triangles, with a flag telling whether both walk it the same way.
bool vtkMedialTriangleMesh::BuildAdjacency(Adjacency& adjacency, const std::function<bool()>& aborted)
{
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  // The points in use, and a triangle of each (for CountPinchedVertices' fan walks).
  adjacency.PointTriangle.assign(this->Points.size() / 3, -1);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      std::int32_t& of = adjacency.PointTriangle[this->Triangles[3 * t + k]];
      this->UsedPoints += of < 0 ? 1 : 0;
      of = static_cast<std::int32_t>(t);
    }
  }
  // Each triangle's three edge uses, grouped by their lower vertex in linear time,
  // then each group sorted by (Hi, triangle): the order of a full sort by (Lo, Hi, triangle).
  auto& uses = adjacency.Uses;
  uses.resize(3 * nt);
  auto ends = [this](vtkIdType use, vtkIdType& a, vtkIdType& b) {
    const vtkIdType* v = &this->Triangles[3 * (use / 3)];
    a = v[use % 3];
    b = v[(use + 1) % 3];
  };
  adjacency.First = vtkMedialGroupByKey(
    3 * nt, this->GetNumberOfPoints(),
    [&](vtkIdType use) {
      vtkIdType a, b;
      ends(use, a, b);
      return std::min(a, b);
    },
    [&](vtkIdType use, vtkIdType at) {
      vtkIdType a, b;
      ends(use, a, b);
      uses[at] = { static_cast<std::int32_t>(std::max(a, b)),
        static_cast<std::int32_t>(2 * (use / 3) + (a < b ? 1 : 0)) };
    });
  if (aborted && aborted())
  {
    return false;
  }
  const vtkIdType np = this->GetNumberOfPoints();
#pragma omp parallel for schedule(dynamic, 4096)
  for (vtkIdType lo = 0; lo < np; ++lo)
  {
    std::sort(uses.begin() + adjacency.First[lo], uses.begin() + adjacency.First[lo + 1]);
  }
  if (aborted && aborted())
  {
    return false;
  }
  adjacency.Neighbour.resize(3 * nt);
  adjacency.SameDirection.resize(3 * nt);
  adjacency.Degree.resize(nt);
  // Edge counts, over ranges of lower vertices on every thread.
  vtkIdType edges = 0, boundary = 0, nonManifold = 0;
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : edges, boundary, nonManifold)
  for (vtkIdType lo = 0; lo < np; ++lo)
  {
    adjacency.ForEachEdge(
      [&](size_t i, size_t j) {
        ++edges;
        boundary += j - i == 1 ? 1 : 0;
        nonManifold += j - i > 2 ? 1 : 0;
      },
      lo, lo + 1);
  }
  this->Edges = edges;
  this->BoundaryEdges = boundary;
  this->NonManifoldEdges = nonManifold;
  // Each triangle's neighbours across its manifold edges (two uses), in the (Lo, Hi)
  // order of those edges, found by a search in each edge's group of uses.
#pragma omp parallel for schedule(static)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    struct Link
    {
      std::int64_t Edge; // Lo * points + Hi: the edges' order
      std::int32_t Neighbour;
      bool Same;
    };
    Link links[3];
    int count = 0;
    const vtkIdType* v = &this->Triangles[3 * t];
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType lo = std::min(v[k], v[(k + 1) % 3]), hi = std::max(v[k], v[(k + 1) % 3]);
      const Adjacency::EdgeUse key{ static_cast<std::int32_t>(hi), 0 };
      const auto first = uses.begin() + adjacency.First[lo];
      const auto last = uses.begin() + adjacency.First[lo + 1];
      const auto begin = std::lower_bound(first, last, key,
        [](const Adjacency::EdgeUse& a, const Adjacency::EdgeUse& b) { return a.Hi < b.Hi; });
      if (last - begin < 2 || begin[1].Hi != hi || (last - begin > 2 && begin[2].Hi == hi))
      {
        continue; // a boundary or non-manifold edge
      }
      const bool mine = begin[0].Triangle() == t;
      links[count++] = { static_cast<std::int64_t>(lo) * np + hi,
        static_cast<std::int32_t>(begin[mine ? 1 : 0].Triangle()), begin[0].Forward() == begin[1].Forward() };
    }
    std::sort(links, links + count, [](const Link& a, const Link& b) { return a.Edge < b.Edge; });
    for (int k = 0; k < count; ++k)
    {
      adjacency.Neighbour[3 * t + k] = links[k].Neighbour;
      adjacency.SameDirection[3 * t + k] = links[k].Same;
    }
    adjacency.Degree[t] = static_cast<unsigned char>(count);
  }
  return true;
}

vtkIdType vtkMedialTriangleMesh::PinchedVertexBound() const
{
  if (this->BoundaryEdges > 0 || this->NonManifoldEdges > 0 || this->NonOrientableComponents > 0)
  {
    return 0;
  }
  return std::max<vtkIdType>(0, 2 * this->Components - this->GetEulerCharacteristic());
}

// On a closed, edge-manifold mesh each edge at a vertex v joins two of v's triangles, so
// v's triangles form cycles, its fans, each followed by leaving every triangle through
// its other edge at v; v is pinched when it has two fans or more. With the edge
// neighbours (the solid check's case), one fan is followed from a triangle of each
// vertex (PointTriangle, noted for free by BuildAdjacency's pass that counts the points
// in use): a step a triangle of the fan, 17 instructions and no search. When the fans
// followed hold every corner, no vertex is pinched (the usual answer, one step a
// corner); else a vertex is pinched when its fan holds fewer of its corners than it
// has, the fans followed again and the corners counted. Without them (freed after the
// check), the corners are grouped by vertex, and the triangles (v, a, b) of each vertex
// give its link's edges a -> b (each a starts one on an oriented mesh): its link is
// followed from its first edge within its group.
vtkIdType vtkMedialTriangleMesh::CountPinchedVertices(vtkIdType* example) const
{
  if (example)
  {
    *example = -1;
  }
  if (this->PinchedVertexBound() == 0)
  {
    return 0;
  }
  const vtkIdType np = this->GetNumberOfPoints();
  const vtkIdType nt = this->GetNumberOfTriangles();
  const vtkIdType corners = 3 * nt;
  const vtkIdType* tris = this->Triangles.data();
  vtkIdType pinched = 0, lowest = np;
  if (this->EdgeNeighbours.size() == static_cast<size_t>(corners) &&
    this->PointTriangle.size() == static_cast<size_t>(np))
  {
    // The triangles of the fan of v through its triangle PointTriangle[v] (0 for a
    // point in no triangle). In at the edge (v, in), out at (v, out). A triangle's
    // neighbours are in the order of their edges' (lower, higher) ids: a triangle
    // a < b < c has them across ab, ac, bc, so the one across (v, out), opposite `in`,
    // is at 2 minus the rank of `in` among the three (ids as unsigned: two
    // compare-and-borrows).
    using Id = std::make_unsigned<vtkIdType>::type;
    const Id* ids = reinterpret_cast<const Id*>(tris);
    const std::int32_t* lastOf = this->EdgeNeighbours.data() + 2; // neighbour across bc
    const std::int32_t* firstOf = this->PointTriangle.data();
    auto fan = [ids, lastOf, firstOf](vtkIdType v) {
      const std::int32_t first = firstOf[v];
      vtkIdType steps = 0;
      if (first >= 0)
      {
        const Id at = static_cast<Id>(v);
        const Id* f = ids + 3 * static_cast<Id>(first);
        Id in = f[0] != at ? f[0] : f[1];
        std::int32_t t = first;
        do
        {
          f = ids + 3 * static_cast<Id>(t);
          const Id out = f[0] + f[1] + f[2] - (at + in);
          Id slot = 3 * static_cast<Id>(t);
          slot -= at < in ? 1 : 0;
          slot -= out < in ? 1 : 0;
          t = lastOf[slot];
          in = out;
          ++steps;
        } while (t != first);
      }
      return steps;
    };
    vtkIdType followed = 0;
#pragma omp parallel for schedule(static) reduction(+ : followed)
    for (vtkIdType v = 0; v < np; ++v)
    {
      followed += fan(v);
    }
    if (followed < corners)
    {
      vtkMedialBuffer<vtkIdType> around(static_cast<size_t>(np), 0); // every corner of each vertex
      for (vtkIdType c = 0; c < corners; ++c)
      {
        ++around[tris[c]];
      }
#pragma omp parallel for schedule(static) reduction(+ : pinched) reduction(min : lowest)
      for (vtkIdType v = 0; v < np; ++v)
      {
        if (fan(v) < around[v])
        {
          ++pinched;
          lowest = std::min(lowest, v);
        }
      }
    }
  }
  else
  {
    struct LinkEdge
    {
      std::int32_t From, To;
    };
    vtkMedialBuffer<LinkEdge> links(static_cast<size_t>(corners));
    const vtkMedialBuffer<vtkIdType> group = vtkMedialGroupByKey(
      corners, np, [tris](vtkIdType c) { return tris[c]; },
      [&](vtkIdType c, vtkIdType at) {
        const vtkIdType* v = tris + 3 * (c / 3);
        const int k = static_cast<int>(c % 3);
        links[at] = { static_cast<std::int32_t>(v[(k + 1) % 3]), static_cast<std::int32_t>(v[(k + 2) % 3]) };
      });
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : pinched) reduction(min : lowest)
    for (vtkIdType v = 0; v < np; ++v)
    {
      const vtkIdType begin = group[v], end = group[v + 1];
      if (end - begin < 2)
      {
        continue;
      }
      vtkIdType steps = 1;
      std::int32_t at = links[begin].To;
      while (at != links[begin].From && steps < end - begin)
      {
        vtkIdType i = begin;
        while (i < end && links[i].From != at)
        {
          ++i;
        }
        if (i == end)
        {
          break;
        }
        at = links[i].To;
        ++steps;
      }
      if (steps < end - begin)
      {
        ++pinched;
        lowest = std::min(lowest, v);
      }
    }
  }
  if (example)
  {
    *example = pinched > 0 ? lowest : -1;
  }
  return pinched;
}

// Breadth-first consistent winding per shell (edge-connected component).
void vtkMedialTriangleMesh::OrientShells(const Adjacency& adjacency)
{
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  this->ShellOfTriangle.assign(nt, -1);
  vtkMedialBuffer<char> flip(nt, 0);
  vtkMedialBuffer<vtkIdType> queue;
  queue.reserve(nt);
  for (vtkIdType seed = 0; seed < nt; ++seed)
  {
    if (this->ShellOfTriangle[seed] >= 0)
    {
      continue;
    }
    const int c = static_cast<int>(this->Shells.size());
    this->Shells.emplace_back();
    Shell& shell = this->Shells.back();
    shell.FirstTriangle = seed;
    this->ShellOfTriangle[seed] = c;
    queue.clear();
    queue.push_back(seed);
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const vtkIdType t = queue[q];
      for (int k = 0; k < adjacency.Degree[t]; ++k)
      {
        const vtkIdType u = adjacency.Neighbour[3 * t + k];
        const char want = flip[t] ^ adjacency.SameDirection[3 * t + k];
        if (this->ShellOfTriangle[u] < 0)
        {
          this->ShellOfTriangle[u] = c;
          flip[u] = want;
          queue.push_back(u);
        }
        else if (flip[u] != want)
        {
          shell.Orientable = false;
        }
      }
    }
    shell.Triangles = static_cast<vtkIdType>(queue.size());
  }
  this->Components = static_cast<vtkIdType>(this->Shells.size());
  for (const Shell& shell : this->Shells)
  {
    this->NonOrientableComponents += shell.Orientable ? 0 : 1;
  }
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (flip[t])
    {
      std::swap(this->Triangles[3 * t], this->Triangles[3 * t + 2]);
      ++this->Shells[this->ShellOfTriangle[t]].Rewound;
    }
  }
}

// Closed: each edge of the shell is used an even number of times by the shell (an
// edge shared with another shell, e.g. two boxes on one edge, is non-manifold but
// closes both).
void vtkMedialTriangleMesh::MarkClosedShells(const Adjacency& adjacency)
{
  // Shells with an edge used an odd number of times by them, found over ranges of
  // lower vertices on every thread (the result does not depend on the order).
  const size_t ns = this->Shells.size();
  std::vector<char> open(ns, 0);
  const vtkIdType np = this->GetNumberOfPoints();
#pragma omp parallel
  {
    std::vector<char> openHere(ns, 0);
    std::vector<int> shellsOnEdge;
#pragma omp for schedule(static) nowait
    for (vtkIdType chunk = 0; chunk < (np + 4095) / 4096; ++chunk)
    {
      adjacency.ForEachEdge(
        [&](size_t i, size_t j) {
          if (j - i == 2 &&
            this->ShellOfTriangle[adjacency.Uses[i].Triangle()] ==
              this->ShellOfTriangle[adjacency.Uses[i + 1].Triangle()])
          {
            return; // the usual edge: used twice by one shell
          }
          shellsOnEdge.clear();
          for (; i < j; ++i)
          {
            shellsOnEdge.push_back(this->ShellOfTriangle[adjacency.Uses[i].Triangle()]);
          }
          std::sort(shellsOnEdge.begin(), shellsOnEdge.end());
          for (size_t a = 0; a < shellsOnEdge.size();)
          {
            size_t b = a;
            while (b < shellsOnEdge.size() && shellsOnEdge[b] == shellsOnEdge[a])
            {
              ++b;
            }
            if ((b - a) % 2 == 1)
            {
              openHere[shellsOnEdge[a]] = 1;
            }
            a = b;
          }
        },
        chunk * 4096, std::min(np, (chunk + 1) * 4096));
    }
#pragma omp critical
    for (size_t s = 0; s < ns; ++s)
    {
      open[s] |= openHere[s];
    }
  }
  for (size_t s = 0; s < ns; ++s)
  {
    this->Shells[s].Closed = !open[s];
  }
}

// Signed volume and bounds per shell (the volume about the box centre, for accuracy);
// each shell is turned so that its own volume is positive.
void vtkMedialTriangleMesh::OrientByVolume()
{
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  const double centre[3] = { 0.5 * (this->Bounds[0] + this->Bounds[1]),
    0.5 * (this->Bounds[2] + this->Bounds[3]), 0.5 * (this->Bounds[4] + this->Bounds[5]) };
  for (Shell& shell : this->Shells)
  {
    for (int k = 0; k < 3; ++k)
    {
      shell.Bounds[2 * k] = HUGE_VAL;
      shell.Bounds[2 * k + 1] = -HUGE_VAL;
    }
  }
  for (vtkIdType t = 0; t < nt; ++t)
  {
    Shell& shell = this->Shells[this->ShellOfTriangle[t]];
    double a[3], b[3], c[3], bc[3];
    const vtkIdType* v = &this->Triangles[3 * t];
    G::Sub(this->GetPoint(v[0]), centre, a);
    G::Sub(this->GetPoint(v[1]), centre, b);
    G::Sub(this->GetPoint(v[2]), centre, c);
    G::Cross(b, c, bc);
    shell.Volume += G::Dot(a, bc) / 6.0;
    for (int j = 0; j < 3; ++j)
    {
      const double* x = this->GetPoint(v[j]);
      for (int k = 0; k < 3; ++k)
      {
        shell.Bounds[2 * k] = std::min(shell.Bounds[2 * k], x[k]);
        shell.Bounds[2 * k + 1] = std::max(shell.Bounds[2 * k + 1], x[k]);
      }
    }
  }
  std::vector<char> negative(this->Shells.size(), 0);
  for (size_t s = 0; s < this->Shells.size(); ++s)
  {
    negative[s] = this->Shells[s].Volume < 0.0;
    if (negative[s])
    {
      this->Shells[s].Volume = -this->Shells[s].Volume;
      this->Shells[s].Rewound = this->Shells[s].Triangles - this->Shells[s].Rewound;
      ++this->FlippedComponents;
    }
  }
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (negative[this->ShellOfTriangle[t]])
    {
      std::swap(this->Triangles[3 * t], this->Triangles[3 * t + 2]);
    }
  }
}

// Normals and areas. Zero-area triangles get zero weight and are never sampled.
void vtkMedialTriangleMesh::ComputeNormalsAndAreas()
{
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  this->Normals.resize(3 * nt);
  this->Areas.resize(nt);
  const double tinyArea = 1e-14 * this->Diagonal * this->Diagonal;
  vtkIdType degenerate = 0;
#pragma omp parallel for schedule(static) reduction(+ : degenerate)
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType* v = &this->Triangles[3 * t];
    double ab[3], ac[3], n[3];
    G::Sub(this->GetPoint(v[1]), this->GetPoint(v[0]), ab);
    G::Sub(this->GetPoint(v[2]), this->GetPoint(v[0]), ac);
    G::Cross(ab, ac, n);
    const double len = std::sqrt(G::Dot(n, n));
    double area = 0.5 * len;
    if (area <= tinyArea)
    {
      ++degenerate;
      area = 0.0;
    }
    for (int i = 0; i < 3; ++i)
    {
      this->Normals[3 * t + i] = len > 0.0 ? n[i] / len : 0.0;
    }
    this->Areas[t] = area;
  }
  this->DegenerateTriangles += degenerate;
}

namespace
{
// Triangles (a0, a1, a2) and (b0, b1, b2) intersect or come within `tolerance`.
bool TrianglesTouch(const double* a[3], const double* b[3], double tolerance)
{
  if (vtkTriangle::TrianglesIntersect(a[0], a[1], a[2], b[0], b[1], b[2]))
  {
    return true;
  }
  // Apart: the closest pair is a vertex and a face, or two edges.
  const double tolerance2 = tolerance * tolerance;
  double q[3];
  for (int i = 0; i < 3; ++i)
  {
    if (G::ClosestPointOnTriangle(a[i], b[0], b[1], b[2], q) <= tolerance2 ||
      G::ClosestPointOnTriangle(b[i], a[0], a[1], a[2], q) <= tolerance2)
    {
      return true;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double p0[3], p1[3], r0[3], r1[3], c0[3], c1[3], s, t;
      std::copy_n(a[i], 3, p0);
      std::copy_n(a[(i + 1) % 3], 3, p1);
      std::copy_n(b[j], 3, r0);
      std::copy_n(b[(j + 1) % 3], 3, r1);
      if (vtkLine::DistanceBetweenLineSegments(p0, p1, r0, r1, c0, c1, s, t) <= tolerance2)
      {
        return true;
      }
    }
  }
  return false;
}
}

// Pairs of closed shells with triangles that touch or intersect. Every triangle of a
// shell whose box meets a later shell's box asks the tree for the triangles around it.
// (Open shells are left out: a soup of unconnected triangles would touch everywhere.)
bool vtkMedialTriangleMesh::FindShellContacts(
  const vtkMedialTriangleBVH& tree, const std::function<bool()>& aborted)
{
  const int ns = static_cast<int>(this->Shells.size());
  const double tolerance = ContactTolerance * this->Diagonal;
  // Sweep the closed shells' boxes along x: mark the lower shell of each overlapping pair.
  std::vector<int> byLeft;
  for (int s = 0; s < ns; ++s)
  {
    if (this->Shells[s].Closed)
    {
      byLeft.push_back(s);
    }
  }
  std::sort(byLeft.begin(), byLeft.end(),
    [this](int a, int b) { return this->Shells[a].Bounds[0] < this->Shells[b].Bounds[0]; });
  std::vector<char> mayTouchLater(ns, 0);
  for (size_t i = 0; i < byLeft.size(); ++i)
  {
    const Shell& a = this->Shells[byLeft[i]];
    for (size_t j = i + 1; j < byLeft.size() && this->Shells[byLeft[j]].Bounds[0] <= a.Bounds[1] + tolerance; ++j)
    {
      if (BoxesOverlap(a.Bounds, this->Shells[byLeft[j]].Bounds, tolerance))
      {
        mayTouchLater[std::min(byLeft[i], byLeft[j])] = 1;
      }
    }
  }
  std::vector<vtkIdType> asking;
  for (vtkIdType t = 0; t < this->GetNumberOfTriangles(); ++t)
  {
    if (mayTouchLater[this->ShellOfTriangle[t]] && this->Areas[t] > 0.0)
    {
      asking.push_back(t);
    }
  }
  // (shell a, shell b, triangle of a) for every touching pair of triangles.
  std::vector<std::array<vtkIdType, 3>> found;
  constexpr vtkIdType Block = 1 << 16;
  for (vtkIdType begin = 0; begin < static_cast<vtkIdType>(asking.size()); begin += Block)
  {
    if (aborted && aborted())
    {
      return false;
    }
    const vtkIdType end = std::min<vtkIdType>(begin + Block, asking.size());
#pragma omp parallel
    {
      std::vector<std::array<vtkIdType, 3>> local;
#pragma omp for schedule(dynamic, 256) nowait
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType t = asking[i];
        const int shell = this->ShellOfTriangle[t];
        const double* a[3] = { this->GetPoint(this->GetTriangle(t)[0]),
          this->GetPoint(this->GetTriangle(t)[1]), this->GetPoint(this->GetTriangle(t)[2]) };
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min({ a[0][k], a[1][k], a[2][k] }) - tolerance;
          hi[k] = std::max({ a[0][k], a[1][k], a[2][k] }) + tolerance;
        }
        int lastShell = -1; // one hit per neighbouring shell is enough
        tree.VisitBox(lo, hi, [&](vtkIdType u) {
          const int other = this->ShellOfTriangle[u];
          if (other <= shell || other == lastShell || this->Areas[u] == 0.0 ||
            !this->Shells[other].Closed)
          {
            return true;
          }
          const double* b[3] = { this->GetPoint(this->GetTriangle(u)[0]),
            this->GetPoint(this->GetTriangle(u)[1]), this->GetPoint(this->GetTriangle(u)[2]) };
          if (TrianglesTouch(a, b, tolerance))
          {
            local.push_back({ shell, other, t });
            lastShell = other;
          }
          return true;
        });
      }
#pragma omp critical
      found.insert(found.end(), local.begin(), local.end());
    }
  }
  // One contact per pair, at its lowest triangle: the same whatever the thread count.
  std::sort(found.begin(), found.end());
  for (size_t i = 0; i < found.size(); ++i)
  {
    if (i > 0 && found[i][0] == found[i - 1][0] && found[i][1] == found[i - 1][1])
    {
      continue;
    }
    ShellContact contact;
    contact.A = static_cast<int>(found[i][0]);
    contact.B = static_cast<int>(found[i][1]);
    const vtkIdType* v = this->GetTriangle(found[i][2]);
    for (int k = 0; k < 3; ++k)
    {
      contact.Point[k] =
        (this->GetPoint(v[0])[k] + this->GetPoint(v[1])[k] + this->GetPoint(v[2])[k]) / 3.0;
    }
    this->Contacts.push_back(contact);
  }
  return true;
}

namespace
{
// Crossing of the ray x + t (1, 0, 0), t > 0, with triangle (a, b, c): 1 when it
// crosses inside, 0 when it misses, -1 when it passes too close to an edge or starts
// on the triangle to tell (the caller tries another origin).
int RayCrossing(const double x[3], const double* a, const double* b, const double* c, double tolerance)
{
  const double* v[3] = { a, b, c };
  double s[3];
  for (int i = 0; i < 3; ++i)
  {
    const double* p = v[i];
    const double* q = v[(i + 1) % 3];
    const double ey = q[1] - p[1], ez = q[2] - p[2];
    // Twice the signed area of (p, q, x) projected on the yz plane.
    s[i] = ey * (x[2] - p[2]) - ez * (x[1] - p[1]);
    if (std::fabs(s[i]) <= tolerance * std::sqrt(ey * ey + ez * ez))
    {
      // Close to this edge's line: undecidable only where the triangle is.
      const double lo1 = std::min({ a[1], b[1], c[1] }), hi1 = std::max({ a[1], b[1], c[1] });
      const double lo2 = std::min({ a[2], b[2], c[2] }), hi2 = std::max({ a[2], b[2], c[2] });
      if (x[1] >= lo1 - tolerance && x[1] <= hi1 + tolerance && x[2] >= lo2 - tolerance &&
        x[2] <= hi2 + tolerance)
      {
        return -1;
      }
      return 0;
    }
  }
  if (!((s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0)))
  {
    return 0;
  }
  // Where the ray meets the triangle: barycentric weights from the sub-areas.
  const double sum = s[0] + s[1] + s[2];
  const double hitX = (s[1] * a[0] + s[2] * b[0] + s[0] * c[0]) / sum;
  if (std::fabs(hitX - x[0]) <= tolerance)
  {
    return -1;
  }
  return hitX > x[0] ? 1 : 0;
}
}

// Nesting depth of every closed shell (how many other closed shells enclose it, by
// the parity of a ray's crossings), then shells at odd depth become cavities.
void vtkMedialTriangleMesh::OrientByNesting(const vtkMedialTriangleBVH& tree)
{
  const int ns = static_cast<int>(this->Shells.size());
  auto counts = [this](int s) { return this->Shells[s].Closed && this->Shells[s].Orientable; };
  int closed = 0;
  for (int s = 0; s < ns; ++s)
  {
    closed += counts(s) ? 1 : 0;
  }
  if (closed < 2)
  {
    return;
  }
  // Ray origins: the centroids of a few of each shell's first non-degenerate triangles.
  std::vector<std::vector<vtkIdType>> origins(ns);
  for (vtkIdType t = 0; t < this->GetNumberOfTriangles(); ++t)
  {
    auto& o = origins[this->ShellOfTriangle[t]];
    if (this->Areas[t] > 0.0 && o.size() < static_cast<size_t>(NestingTrials))
    {
      o.push_back(t);
    }
  }
  // Contacts are sorted by (A, B), A < B.
  auto touching = [this](int a, int b) {
    ShellContact key;
    key.A = std::min(a, b);
    key.B = std::max(a, b);
    return std::binary_search(this->Contacts.begin(), this->Contacts.end(), key,
      [](const ShellContact& x, const ShellContact& y) { return x.A < y.A || (x.A == y.A && x.B < y.B); });
  };
  const double tolerance = 1e-9 * this->Diagonal;
  std::vector<std::vector<int>> enclosing(ns);
  std::vector<int> crossings(ns, 0);
  for (int s = 0; s < ns; ++s)
  {
    if (!counts(s))
    {
      continue;
    }
    for (vtkIdType t : origins[s])
    {
      const vtkIdType* v = this->GetTriangle(t);
      double x[3];
      for (int k = 0; k < 3; ++k)
      {
        x[k] = (this->GetPoint(v[0])[k] + this->GetPoint(v[1])[k] + this->GetPoint(v[2])[k]) / 3.0;
      }
      const double lo[3] = { x[0], x[1], x[2] };
      const double hi[3] = { this->Bounds[1] + this->Diagonal, x[1], x[2] };
      std::fill(crossings.begin(), crossings.end(), 0);
      bool undecided = false;
      tree.VisitBox(lo, hi, [&](vtkIdType u) {
        const int other = this->ShellOfTriangle[u];
        if (other == s || !counts(other) || touching(s, other))
        {
          return true;
        }
        const vtkIdType* w = this->GetTriangle(u);
        const int crossing = RayCrossing(
          x, this->GetPoint(w[0]), this->GetPoint(w[1]), this->GetPoint(w[2]), tolerance);
        undecided = crossing < 0;
        crossings[other] += crossing > 0 ? 1 : 0;
        return !undecided;
      });
      if (!undecided)
      {
        for (int other = 0; other < ns; ++other)
        {
          if (crossings[other] % 2 == 1)
          {
            enclosing[s].push_back(other);
          }
        }
        break;
      }
    }
    this->Shells[s].Depth = static_cast<int>(enclosing[s].size());
  }
  for (int s = 0; s < ns; ++s)
  {
    for (int other : enclosing[s])
    {
      const int parent = this->Shells[s].Parent;
      if (parent < 0 || this->Shells[other].Depth > this->Shells[parent].Depth)
      {
        this->Shells[s].Parent = other;
      }
    }
    if (this->Shells[s].Depth % 2 == 1)
    {
      this->FlipShell(s);
    }
  }
}

void vtkMedialTriangleMesh::FlipShell(int shell)
{
  for (vtkIdType t = 0; t < this->GetNumberOfTriangles(); ++t)
  {
    if (this->ShellOfTriangle[t] == shell)
    {
      std::swap(this->Triangles[3 * t], this->Triangles[3 * t + 2]);
      for (int k = 0; k < 3; ++k)
      {
        this->Normals[3 * t + k] = -this->Normals[3 * t + k];
      }
    }
  }
  this->Shells[shell].Volume = -this->Shells[shell].Volume;
  this->Shells[shell].Rewound = this->Shells[shell].Triangles - this->Shells[shell].Rewound;
  ++this->FlippedComponents;
}

bool vtkMedialTriangleMesh::BuildAreaCdf(std::string& error)
{
  this->AreaCdf.resize(this->Areas.size());
  double sum = 0.0;
  for (size_t t = 0; t < this->Areas.size(); ++t)
  {
    sum += this->Areas[t];
    this->AreaCdf[t] = sum;
  }
  this->TotalArea = sum;
  if (!(sum > 0.0) || !(this->Diagonal > 0.0))
  {
    error = "input surface has no area";
    return false;
  }
  for (double& c : this->AreaCdf)
  {
    c /= sum;
  }
  this->AreaCdf.back() = 1.0;
  // About one entry per guide (a power of two, so that u * guides is exact).
  const size_t n = this->AreaCdf.size();
  if (n >= (size_t(1) << 32))
  {
    this->AreaGuide.clear(); // indices beyond 32 bits: the plain binary search
    return true;
  }
  size_t guides = 1;
  while (2 * guides <= n && guides < (size_t(1) << 30))
  {
    guides *= 2;
  }
  this->AreaGuide.resize(guides + 1);
  size_t at = 0;
  for (size_t j = 0; j <= guides; ++j)
  {
    const double step = static_cast<double>(j) / static_cast<double>(guides);
    while (at < n && this->AreaCdf[at] <= step)
    {
      ++at;
    }
    this->AreaGuide[j] = static_cast<std::uint32_t>(at);
  }
  return true;
}

namespace
{
// TrianglesAroundPoints with `around` of either width.
template <class Start, class Around>
void FillTrianglesAround(const vtkMedialTriangleMesh& mesh, Start& start, Around& around)
{
  const vtkIdType np = mesh.GetNumberOfPoints();
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  start.assign(np + 1, 0);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      ++start[mesh.GetTriangle(t)[j] + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  around.resize(start.back());
  Start next(start.begin(), start.end() - 1);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      around[next[mesh.GetTriangle(t)[j]]++] = static_cast<typename Around::value_type>(t);
    }
  }
}
}

void vtkMedialTriangleMesh::TrianglesAroundPoints(
  std::vector<vtkIdType>& start, std::vector<vtkIdType>& around) const
{
  FillTrianglesAround(*this, start, around);
}

void vtkMedialTriangleMesh::TrianglesAroundPoints(
  vtkMedialBuffer<vtkIdType>& start, vtkMedialBuffer<std::int32_t>& around) const
{
  FillTrianglesAround(*this, start, around);
}

void vtkMedialTriangleMesh::ReleaseGeometry()
{
  vtkMedialBuffer<double>().swap(this->Points);
  vtkMedialBuffer<vtkIdType>().swap(this->Triangles);
  vtkMedialBuffer<double>().swap(this->Normals);
  vtkMedialBuffer<double>().swap(this->Areas);
  vtkMedialBuffer<double>().swap(this->AreaCdf);
  vtkMedialBuffer<std::uint32_t>().swap(this->AreaGuide);
}

std::string vtkMedialTriangleMesh::ShellName(int shell) const
{
  std::ostringstream os;
  os << "shell " << shell << " (input cell " << this->SourceCellIds[this->Shells[shell].FirstTriangle]
     << ")";
  return os.str();
}

std::vector<std::string> vtkMedialTriangleMesh::Warnings() const
{
  std::vector<std::string> warnings;
  if (this->DuplicateTriangles > 0)
  {
    std::ostringstream os;
    os << "Input has " << this->DuplicateTriangles << " duplicate triangles; they were ignored.";
    warnings.push_back(os.str());
  }
  if (this->NonManifoldEdges > 0)
  {
    std::ostringstream os;
    os << "Input has " << this->NonManifoldEdges
       << " non-manifold edges; inside and outside may be ambiguous there.";
    warnings.push_back(os.str());
  }
  if (this->NonOrientableComponents > 0)
  {
    std::ostringstream os;
    os << this->NonOrientableComponents
       << " component(s) cannot be oriented consistently (non-orientable surface).";
    warnings.push_back(os.str());
  }

  // A cavity is no defect: only cavities whose input winding was that of a solid (most
  // of their triangles turned to face into the cavity) are worth a word.
  auto woundAsSolid = [](const Shell& shell) {
    return shell.Closed && shell.Depth % 2 == 1 && 2 * shell.Rewound > shell.Triangles;
  };
  const vtkIdType turnedCavities = static_cast<vtkIdType>(
    std::count_if(this->Shells.begin(), this->Shells.end(), woundAsSolid));
  if (turnedCavities > 0)
  {
    std::ostringstream os;
    os << "Nested shells handled: " << this->Shells.size() << " shells make " << this->Bodies
       << (this->Bodies == 1 ? " solid body" : " solid bodies") << " and " << this->Cavities
       << (this->Cavities == 1 ? " cavity" : " cavities")
       << ". A shell inside an odd number of others bounds a cavity; "
       << (turnedCavities == 1 ? "one was wound as a solid and now faces" : "these were wound as solids and now face")
       << " into its cavity: ";
    size_t listed = 0;
    for (size_t s = 0; s < this->Shells.size() && listed < ListedInMessages; ++s)
    {
      const Shell& shell = this->Shells[s];
      if (woundAsSolid(shell))
      {
        os << (listed++ ? ", " : "") << this->ShellName(static_cast<int>(s)) << " inside "
           << this->ShellName(shell.Parent);
      }
    }
    os << (static_cast<vtkIdType>(listed) < turnedCavities ? ", ..." : "") << ".";
    warnings.push_back(os.str());
  }
  if (!this->Contacts.empty())
  {
    std::ostringstream os;
    const size_t n = this->Contacts.size();
    os << (n == 1 ? "Two shells touch or intersect: " : std::to_string(n) + " pairs of shells touch or intersect: ");
    for (size_t i = 0; i < n && i < ListedInMessages; ++i)
    {
      const ShellContact& c = this->Contacts[i];
      os << (i ? "; " : "") << this->ShellName(c.A) << " and " << this->ShellName(c.B) << " near "
         << FormatPoint(c.Point);
    }
    os << (n > ListedInMessages ? "; ..." : "")
       << ". They are neither one solid nor separate ones, so balls and thickness near the contact "
          "are unreliable; join the bodies (boolean union) or move them apart.";
    warnings.push_back(os.str());
  }
  return warnings;
}

vtkIdType vtkMedialTriangleMesh::PickTriangleByArea(double u) const
{
  // First entry strictly greater than u: zero-area triangles repeat the previous
  // CDF value and so are never picked. For u in [j, j + 1) / guides it lies between
  // guides j and j + 1 (the same search for the two ends), so only that run is
  // searched; when no entry of the run is above u, guide j + 1 is the answer, which
  // is where the search then stops.
  auto first = this->AreaCdf.begin(), last = this->AreaCdf.end();
  if (u >= 0.0 && u < 1.0 && this->AreaGuide.size() > 1)
  {
    const size_t guides = this->AreaGuide.size() - 1;
    const size_t j = static_cast<size_t>(u * static_cast<double>(guides));
    first = this->AreaCdf.begin() + this->AreaGuide[j];
    last = this->AreaCdf.begin() + this->AreaGuide[j + 1];
  }
  auto it = std::upper_bound(first, last, u);
  if (it == this->AreaCdf.end())
  {
    --it;
  }
  return static_cast<vtkIdType>(it - this->AreaCdf.begin());
}
