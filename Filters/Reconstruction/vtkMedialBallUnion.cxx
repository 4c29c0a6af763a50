// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallUnion.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialEnvelope.h"
#include "vtkMedialPieces.h"
#include "vtkMedialProgress.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialPlane.h"
#include "vtkMedialThreads.h"
#include "vtkMedialUniformGrid.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFlyingEdges2D.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleStrip.h"
#include "vtkSmartPointer.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialBallUnion);

namespace
{
// Balls in the grid's frame: x, y, z, r. In 2D z is 0 for every centre.
struct Ball
{
  double C[3];
  double R;
};

// A plane fitted to the centres: origin, in-plane axes U, V and normal N.
struct PlaneFrame
{
  double Origin[3] = { 0, 0, 0 };
  double U[3] = { 1, 0, 0 };
  double V[3] = { 0, 1, 0 };
  double N[3] = { 0, 0, 1 };
};

struct Grid
{
  int Dims[3];
  double Origin[3];
  double Spacing[3];
};

// Candidate ball with its bounds over a box of grid points.
struct Candidate
{
  double Lower; // min over the box of |x - c| - r, less a rounding slack
  vtkIdType Ball;
};

constexpr int SuperBlock = 16;
// MEDIAL_MESH: edges and triangles reaching less than this many voxels beyond their
// vertex balls are left out (the surface moves by at most that much).
constexpr double EnvelopeTolerance = 0.1;

// Squared distance bounds from centre c to the axis-aligned box [lo, hi]: nearest and
// farthest.
inline void BoxDistanceBounds2(
  const double lo[3], const double hi[3], const double c[3], double& nearest2, double& farthest2)
{
  double n2 = 0.0, f2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double below = lo[k] - c[k], above = c[k] - hi[k];
    const double d = std::max(0.0, std::max(below, above));
    n2 += d * d;
    const double far = std::max(c[k] - lo[k], hi[k] - c[k]);
    f2 += far * far;
  }
  nearest2 = n2;
  farthest2 = f2;
}

// Distance between two axis-aligned boxes.
inline double BoxBoxDistance(
  const double alo[3], const double ahi[3], const double blo[3], const double bhi[3])
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = std::max(0.0, std::max(alo[k] - bhi[k], blo[k] - ahi[k]));
    d2 += d * d;
  }
  return std::sqrt(d2);
}

// The envelope of a medial mesh (MEDIAL_MESH primitives): isolated balls, edges and
// triangles over the vertex balls. Each primitive lies in its bounding ball (which also
// places it in the superblock bins) and contains its largest vertex ball: over a box,
// these bound its field cheaply, as for balls. Its field is also 1-Lipschitz (a minimum
// of distances minus constants): within its value at the box's centre plus or minus
// the half diagonal.
struct Envelope
{
  std::vector<Ball> Vertices;                        // the vertex balls, in the grid's frame
  std::vector<std::array<vtkIdType, 3>> Primitives; // vertex ids; -1 when unused
  std::vector<Ball> Bounds;
  std::vector<Ball> Inner;

  void Add(const vtkIdType* ids, int n)
  {
    std::array<vtkIdType, 3> p = { -1, -1, -1 };
    const double* centres[3];
    double radii[3];
    vtkIdType inner = ids[0];
    for (int j = 0; j < n; ++j)
    {
      const Ball& v = this->Vertices[ids[j]];
      p[j] = ids[j];
      centres[j] = v.C;
      radii[j] = v.R;
      inner = v.R > this->Vertices[inner].R ? ids[j] : inner;
    }
    Ball bound;
    bound.R = vtkMedialEnvelope::BoundingBall(centres, radii, n, bound.C);
    this->Primitives.push_back(p);
    this->Bounds.push_back(bound);
    this->Inner.push_back(this->Vertices[inner]);
  }

  /// The field of primitive i at x: a ball, a cone or a slab (vtkMedialEnvelope.h).
  /// With `interiorOnly`, a triangle gives its slab only where its minimum is inside it
  /// (+inf elsewhere): enough for a voxel's value, since its sides are primitives or
  /// within the tolerance of their balls.
  double Field(vtkIdType i, const double x[3], bool interiorOnly = false) const
  {
    const auto& p = this->Primitives[i];
    const Ball& a = this->Vertices[p[0]];
    if (p[1] < 0)
    {
      return vtkMedialEnvelope::BallField(x, a.C, a.R);
    }
    const Ball& b = this->Vertices[p[1]];
    if (p[2] < 0)
    {
      return vtkMedialEnvelope::EdgeField(x, a.C, a.R, b.C, b.R);
    }
    // The slab where its minimum is inside, else the nearest side: the whole triangle,
    // a continuous (1-Lipschitz) field.
    const Ball& c = this->Vertices[p[2]];
    const double* centres[3] = { a.C, b.C, c.C };
    const double radii[3] = { a.R, b.R, c.R };
    if (interiorOnly)
    {
      return vtkMedialEnvelope::TriangleField(x, centres, radii);
    }
    return std::min({ vtkMedialEnvelope::TriangleField(x, centres, radii),
      vtkMedialEnvelope::EdgeField(x, a.C, a.R, b.C, b.R), vtkMedialEnvelope::EdgeField(x, b.C, b.R, c.C, c.R),
      vtkMedialEnvelope::EdgeField(x, a.C, a.R, c.C, c.R) });
  }
};

// Keeps the candidates of `from` that can give the clamped field inside box [lo, hi]:
// those with lower bound below the band B and not above U, the smallest upper bound.
// Returns U (+inf when nothing is left).
double PruneCandidates(const std::vector<Ball>& balls, const std::vector<Candidate>& from,
  const double lo[3], const double hi[3], double band, double slack, std::vector<Candidate>& kept)
{
  kept.clear();
  double upper = std::numeric_limits<double>::infinity();
  for (const Candidate& candidate : from)
  {
    const vtkIdType id = candidate.Ball;
    const Ball& b = balls[id];
    double nearest2, farthest2;
    BoxDistanceBounds2(lo, hi, b.C, nearest2, farthest2);
    // Squares first: most balls are rejected without a square root.
    const double farEnough = band + b.R + slack;
    if (nearest2 >= farEnough * farEnough)
    {
      continue; // lower bound >= band
    }
    const double lower = std::sqrt(nearest2) - b.R - slack;
    if (lower >= band)
    {
      continue;
    }
    const double reach = upper + b.R - slack;
    if (!(reach > 0.0) || farthest2 < reach * reach)
    {
      upper = std::min(upper, std::sqrt(farthest2) - b.R + slack);
    }
    kept.push_back({ lower, id });
  }
  kept.erase(std::remove_if(kept.begin(), kept.end(),
               [upper](const Candidate& c) { return c.Lower > upper; }),
    kept.end());
  return upper;
}

// The same for the envelope's primitives: first the cheap bounds of their bounding and
// inner balls (tight for a ball), then, for edges and triangles still in, their value
// at the box's centre plus or minus its half diagonal.
double PruneEnvelope(const Envelope& envelope, const std::vector<Candidate>& from, const double lo[3],
  const double hi[3], double band, double slack, std::vector<Candidate>& kept)
{
  kept.clear();
  double upper = std::numeric_limits<double>::infinity();
  for (const Candidate& candidate : from)
  {
    const Ball& bound = envelope.Bounds[candidate.Ball];
    const Ball& inner = envelope.Inner[candidate.Ball];
    double nearest2, farthest2, unused;
    BoxDistanceBounds2(lo, hi, bound.C, nearest2, unused);
    const double lower = std::sqrt(nearest2) - bound.R - slack;
    if (lower < band)
    {
      BoxDistanceBounds2(lo, hi, inner.C, unused, farthest2);
      upper = std::min(upper, std::sqrt(farthest2) - inner.R + slack);
      kept.push_back({ lower, candidate.Ball });
    }
  }
  double centre[3], half2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    centre[k] = 0.5 * (lo[k] + hi[k]);
    half2 += 0.25 * (hi[k] - lo[k]) * (hi[k] - lo[k]);
  }
  const double half = std::sqrt(half2) + slack;
  size_t count = 0;
  for (const Candidate& candidate : kept)
  {
    if (candidate.Lower >= upper || envelope.Primitives[candidate.Ball][1] < 0)
    {
      // A ball's bounds are already tight; only past the upper bound is it dropped.
      if (candidate.Lower <= upper)
      {
        kept[count++] = candidate;
      }
      continue;
    }
    const double value = envelope.Field(candidate.Ball, centre);
    const double lower = std::max(candidate.Lower, value - half);
    if (lower < band && lower <= upper)
    {
      upper = std::min(upper, value + half);
      kept[count++] = { lower, candidate.Ball };
    }
  }
  kept.resize(count);
  kept.erase(std::remove_if(kept.begin(), kept.end(),
               [upper](const Candidate& c) { return c.Lower > upper; }),
    kept.end());
  return upper;
}

// Fills the clamped field over boxes of grid points, refining each box into halves
// while its candidate list is long: each level tightens the upper bound and so prunes
// the list for the next.
struct FieldFiller
{
  const std::vector<Ball>& Balls; // the balls, or the envelope's bounding balls
  const Grid& G;
  double Band;
  double Slack;
  double* Values;
  vtkIdType SliceSize;
  const Envelope* Env; // null: the union of Balls

  static constexpr int LeafSize = 4;      // voxels per side at which refinement stops
  static constexpr size_t ShortList = 6; // candidates below which refinement stops
  static constexpr size_t MaximumDepth = 8; // halvings from a superblock down to one voxel, and more

  double PointOf(int k, int i) const { return this->G.Origin[k] + i * this->G.Spacing[k]; }

  void Fill(const int first[3], const int last[3], double value) const
  {
    for (int z = first[2]; z <= last[2]; ++z)
    {
      for (int y = first[1]; y <= last[1]; ++y)
      {
        double* row = this->Values + z * this->SliceSize + static_cast<vtkIdType>(y) * this->G.Dims[0];
        std::fill(row + first[0], row + last[0] + 1, value);
      }
    }
  }

  void Refine(const std::vector<Candidate>& parent, const int first[3], const int last[3], size_t depth,
    std::vector<std::vector<Candidate>>& levels) const
  {
    // `levels` is sized up front (MaximumDepth): resizing here would move the parent's list.
    std::vector<Candidate>& kept = levels[depth];
    double lo[3], hi[3];
    int longest = 1;
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = this->PointOf(k, first[k]);
      hi[k] = this->PointOf(k, last[k]);
      longest = std::max(longest, last[k] - first[k] + 1);
    }
    const double upper = this->Env
      ? PruneEnvelope(*this->Env, parent, lo, hi, this->Band, this->Slack, kept)
      : PruneCandidates(this->Balls, parent, lo, hi, this->Band, this->Slack, kept);
    if (kept.empty())
    {
      this->Fill(first, last, this->Band); // f >= B everywhere in the box
      return;
    }
    if (upper <= -this->Band)
    {
      this->Fill(first, last, -this->Band); // f <= -B everywhere in the box
      return;
    }
    if (longest > LeafSize && kept.size() > ShortList)
    {
      int mid[3];
      for (int k = 0; k < 3; ++k)
      {
        mid[k] = first[k] + (last[k] - first[k] + 1) / 2; // first index of the upper half
      }
      int childFirst[3], childLast[3];
      for (int cz = 0; cz < (last[2] > first[2] ? 2 : 1); ++cz)
      {
        childFirst[2] = cz ? mid[2] : first[2];
        childLast[2] = (cz || last[2] == first[2]) ? last[2] : mid[2] - 1;
        for (int cy = 0; cy < (last[1] > first[1] ? 2 : 1); ++cy)
        {
          childFirst[1] = cy ? mid[1] : first[1];
          childLast[1] = (cy || last[1] == first[1]) ? last[1] : mid[1] - 1;
          for (int cx = 0; cx < (last[0] > first[0] ? 2 : 1); ++cx)
          {
            childFirst[0] = cx ? mid[0] : first[0];
            childLast[0] = (cx || last[0] == first[0]) ? last[0] : mid[0] - 1;
            this->Refine(kept, childFirst, childLast, depth + 1, levels);
          }
        }
      }
      return;
    }
    // Leaf: nearest lower bound first lets each voxel stop early; ties by id.
    std::sort(kept.begin(), kept.end(), [](const Candidate& x, const Candidate& y) {
      return x.Lower < y.Lower || (x.Lower == y.Lower && x.Ball < y.Ball);
    });
    if (this->Env)
    {
      this->FillEnvelope(kept, first, last);
      return;
    }
    const double band = this->Band;
    for (int z = first[2]; z <= last[2]; ++z)
    {
      const double pz = this->PointOf(2, z);
      for (int y = first[1]; y <= last[1]; ++y)
      {
        const double py = this->PointOf(1, y);
        double* row = this->Values + z * this->SliceSize + static_cast<vtkIdType>(y) * this->G.Dims[0];
        for (int x = first[0]; x <= last[0]; ++x)
        {
          const double px = this->PointOf(0, x);
          double best = band;
          for (const Candidate& c : kept)
          {
            if (c.Lower >= best || best <= -band)
            {
              break;
            }
            const Ball& ball = this->Balls[c.Ball];
            const double dx = px - ball.C[0], dy = py - ball.C[1], dz = pz - ball.C[2];
            const double d2 = dx * dx + dy * dy + dz * dz;
            // Compare squares first: the square root only for a (near) improvement.
            const double reach = best + ball.R;
            if (reach > 0.0 && d2 <= reach * reach * (1.0 + 1e-12))
            {
              best = std::min(best, std::sqrt(d2) - ball.R);
            }
          }
          row[x] = std::max(-band, best);
        }
      }
    }
  }

  // A leaf of the envelope: the exact minimum over the primitives at each voxel, in
  // increasing lower bound so that it can stop early.
  void FillEnvelope(const std::vector<Candidate>& kept, const int first[3], const int last[3]) const
  {
    const double band = this->Band;
    for (int z = first[2]; z <= last[2]; ++z)
    {
      for (int y = first[1]; y <= last[1]; ++y)
      {
        double* row = this->Values + z * this->SliceSize + static_cast<vtkIdType>(y) * this->G.Dims[0];
        for (int x = first[0]; x <= last[0]; ++x)
        {
          const double p[3] = { this->PointOf(0, x), this->PointOf(1, y), this->PointOf(2, z) };
          double best = band;
          for (const Candidate& c : kept)
          {
            if (c.Lower >= best || best <= -band)
            {
              break;
            }
            best = std::min(best, this->Env->Field(c.Ball, p, true));
          }
          row[x] = std::max(-band, best);
        }
      }
    }
  }
};

// Fits a plane to the centres (vtkMedialPlane::FitPoints). Returns 2 when they span
// exactly one plane, 1 when they are collinear, 0 when they coincide, 3 otherwise;
// `frame` is the best-fit plane, with U the world axis most perpendicular to the
// normal projected into the plane, so that a z = const plane keeps x and y.
int FitPlane(const std::vector<Ball>& balls, double tolerance, PlaneFrame& frame)
{
  const vtkIdType n = static_cast<vtkIdType>(balls.size());
  auto centreOf = [&balls](vtkIdType i, double p[3]) { std::copy(balls[i].C, balls[i].C + 3, p); };
  double centroid[3], values[3], vecs[3][3];
  vtkMedialPlane::FitPoints(n, centreOf, centroid, values, vecs); // eigenvalues decreasing, vectors in columns
  double axis[3], normal[3];
  for (int k = 0; k < 3; ++k)
  {
    axis[k] = vecs[k][0];
    normal[k] = vecs[k][2];
  }
  // Largest distance from the best line and from the best plane.
  const double fromLine = vtkMedialPlane::MaxDistanceFromLine(n, centreOf, centroid, axis);
  const double fromPlane = vtkMedialPlane::MaxDistance(n, centreOf, centroid, normal);
  int rank = 3;
  if (fromPlane <= tolerance)
  {
    rank = fromLine > tolerance ? 2 : (vtkMath::Norm(axis) > 0 && values[0] > 0 ? 1 : 0);
  }
  // Lower ranks: prefer the z = const plane when the centres lie in one.
  if (rank < 2)
  {
    bool sameZ = true;
    for (const Ball& b : balls)
    {
      sameZ = sameZ && std::fabs(b.C[2] - centroid[2]) <= tolerance;
    }
    if (sameZ)
    {
      normal[0] = normal[1] = 0.0;
      normal[2] = 1.0;
    }
  }
  // Snap near-axis normals so that axis-aligned planes give axis-aligned images.
  for (int k = 0; k < 3; ++k)
  {
    if (std::fabs(std::fabs(normal[k]) - 1.0) < 1e-12)
    {
      normal[0] = normal[1] = normal[2] = 0.0;
      normal[k] = 1.0;
    }
  }
  vtkMedialPlane::CanonicalSign(normal); // a reproducible frame
  vtkMath::Normalize(normal);
  double u[3] = { 0, 0, 0 };
  u[vtkMedialPlane::LeastAxis(normal)] = 1.0;
  const double un = vtkMath::Dot(u, normal);
  for (int k = 0; k < 3; ++k)
  {
    u[k] -= un * normal[k];
  }
  vtkMath::Normalize(u);
  double v[3];
  vtkMath::Cross(normal, u, v);
  const double offset = vtkMath::Dot(centroid, normal);
  for (int k = 0; k < 3; ++k)
  {
    frame.Origin[k] = offset * normal[k];
    frame.U[k] = u[k];
    frame.V[k] = v[k];
    frame.N[k] = normal[k];
  }
  return rank;
}

// Joins the two-point segments of a 2D contour into polylines; a closed curve repeats
// its first point id at the end. vtkStripper would cap polylines at 100000 points.
vtkSmartPointer<vtkCellArray> ChainSegments(vtkPolyData* segments)
{
  const vtkIdType np = segments->GetNumberOfPoints();
  vtkCellArray* lines = segments->GetLines();
  const vtkIdType ns = lines->GetNumberOfCells();
  std::vector<std::array<vtkIdType, 2>> ends(static_cast<size_t>(ns));
  std::vector<vtkIdType> incidentStart(np + 1, 0), incident;
  {
    auto it = vtk::TakeSmartPointer(lines->NewIterator());
    vtkIdType k = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++k)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      it->GetCurrentCell(npts, ids);
      ends[k] = { ids[0], ids[npts - 1] };
      ++incidentStart[ends[k][0] + 1];
      ++incidentStart[ends[k][1] + 1];
    }
  }
  std::partial_sum(incidentStart.begin(), incidentStart.end(), incidentStart.begin());
  incident.resize(incidentStart.back());
  {
    std::vector<vtkIdType> fill(incidentStart.begin(), incidentStart.end() - 1);
    for (vtkIdType k = 0; k < ns; ++k)
    {
      incident[fill[ends[k][0]]++] = k;
      incident[fill[ends[k][1]]++] = k;
    }
  }
  std::vector<char> used(static_cast<size_t>(ns), 0);
  auto nextSegment = [&](vtkIdType point) -> vtkIdType {
    for (vtkIdType j = incidentStart[point]; j < incidentStart[point + 1]; ++j)
    {
      if (!used[incident[j]])
      {
        return incident[j];
      }
    }
    return -1;
  };
  auto polylines = vtkSmartPointer<vtkCellArray>::New();
  std::vector<vtkIdType> chain, back;
  for (vtkIdType first = 0; first < ns; ++first)
  {
    if (used[first])
    {
      continue;
    }
    used[first] = 1;
    chain.assign({ ends[first][0], ends[first][1] });
    // Forward from the second end, then backward from the first for open curves.
    for (vtkIdType s = nextSegment(chain.back()); s >= 0 && chain.back() != chain.front();
         s = nextSegment(chain.back()))
    {
      used[s] = 1;
      chain.push_back(ends[s][0] == chain.back() ? ends[s][1] : ends[s][0]);
    }
    if (chain.back() != chain.front())
    {
      back.clear();
      vtkIdType tip = chain.front();
      for (vtkIdType s = nextSegment(tip); s >= 0; s = nextSegment(tip))
      {
        used[s] = 1;
        tip = ends[s][0] == tip ? ends[s][1] : ends[s][0];
        back.push_back(tip);
      }
      chain.insert(chain.begin(), back.rbegin(), back.rend());
    }
    polylines->InsertNextCell(static_cast<vtkIdType>(chain.size()), chain.data());
  }
  return polylines;
}

// The envelope's primitives from the input's cells: a ball per point, a triangle per
// triangle (polygons fanned, strips split), an edge per line segment and triangle side
// (once each). Edges and triangles that reach no further than `tolerance` beyond their
// vertex balls (vtkMedialEnvelope's excess) are left out.
void GatherPrimitives(vtkPolyData* mesh, double tolerance, Envelope& envelope)
{
  const vtkIdType n = static_cast<vtkIdType>(envelope.Vertices.size());
  for (vtkIdType i = 0; i < n; ++i)
  {
    envelope.Add(&i, 1);
  }
  const auto& v = envelope.Vertices;
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  std::vector<std::array<vtkIdType, 2>> segments;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    const vtkIdType ids[3] = { a, b, c };
    const double* centres[3] = { v[a].C, v[b].C, v[c].C };
    const double radii[3] = { v[a].R, v[b].R, v[c].R };
    if (vtkMedialEnvelope::TriangleExcess(centres, radii) > tolerance)
    {
      envelope.Add(ids, 3);
    }
    segments.push_back({ a, b });
    segments.push_back({ b, c });
    segments.push_back({ c, a });
  };
  vtkNew<vtkCellArray> triangles;
  if (mesh)
  {
    for (vtkCellArray* cells : { mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
    {
      auto it = vtk::TakeSmartPointer(cells->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        vtkIdType npts;
        const vtkIdType* ids;
        it->GetCurrentCell(npts, ids);
        if (cells == mesh->GetLines())
        {
          for (vtkIdType k = 0; k + 1 < npts; ++k)
          {
            segments.push_back({ ids[k], ids[k + 1] });
          }
        }
        else if (cells == mesh->GetPolys())
        {
          for (vtkIdType k = 1; k + 1 < npts; ++k)
          {
            addTriangle(ids[0], ids[k], ids[k + 1]);
          }
        }
        else if (npts >= 3)
        {
          vtkTriangleStrip::DecomposeStrip(static_cast<int>(npts), ids, triangles);
        }
      }
    }
    auto it = vtk::TakeSmartPointer(triangles->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* ids;
      it->GetCurrentCell(npts, ids);
      addTriangle(ids[0], ids[1], ids[2]);
    }
  }
  for (const auto& segment : segments)
  {
    const vtkIdType a = segment[0], b = segment[1];
    if (a != b && edges.emplace(std::min(a, b), std::max(a, b)).second &&
      vtkMedialEnvelope::EdgeExcess(v[a].C, v[a].R, v[b].C, v[b].R) > tolerance)
    {
      envelope.Add(segment.data(), 2);
    }
  }
}

// Signed volume of a closed triangle surface (positive when oriented outward).
double SignedVolume(vtkPolyData* surface)
{
  double volume = 0.0;
  vtkPoints* points = surface->GetPoints();
  if (!points)
  {
    return 0.0;
  }
  auto it = vtk::TakeSmartPointer(surface->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* ids;
    it->GetCurrentCell(npts, ids);
    if (npts != 3)
    {
      continue;
    }
    double a[3], b[3], c[3], bc[3];
    points->GetPoint(ids[0], a);
    points->GetPoint(ids[1], b);
    points->GetPoint(ids[2], c);
    vtkMath::Cross(b, c, bc);
    volume += vtkMath::Dot(a, bc) / 6.0;
  }
  return volume;
}

// The centres binned by superblock on a vtkMedialUniformGrid, each bin's balls
// largest radius first, with the bin's largest radius: the candidates of a
// superblock are the balls of the bins that can reach it.
class CentreBins
{
public:
  CentreBins(const std::vector<Ball>& balls, const Grid& grid, double band)
    : Balls(balls)
    , G(grid)
  {
    double origin[3], size[3];
    int dims[3];
    for (int k = 0; k < 3; ++k)
    {
      this->SuperSize[k] = grid.Dims[k] > 1 ? SuperBlock : 1;
      dims[k] = (grid.Dims[k] + this->SuperSize[k] - 1) / this->SuperSize[k];
      origin[k] = grid.Origin[k];
      size[k] = this->SuperSize[k] * grid.Spacing[k];
    }
    this->Bins.Initialize(origin, size, dims);
    this->Bins.Build(static_cast<vtkIdType>(balls.size()),
      [&](vtkIdType i, auto&& add) { add(this->Bins.CellOf(balls[i].C)); });
    // Largest radius first, so that a far bin's scan stops early; ties by id keep the
    // order deterministic.
    this->Bins.SortCells([&balls](vtkIdType a, vtkIdType b) {
      return balls[a].R > balls[b].R || (balls[a].R == balls[b].R && a < b);
    });
    this->MaxRadius.assign(static_cast<size_t>(this->Bins.GetNumberOfCells()), 0.0);
    double maxRadius = 0.0;
    for (vtkIdType bin = 0; bin < this->Bins.GetNumberOfCells(); ++bin)
    {
      for (const vtkIdType* b = this->Bins.CellBegin(bin); b < this->Bins.CellEnd(bin); ++b)
      {
        this->MaxRadius[bin] = std::max(this->MaxRadius[bin], balls[*b].R);
        maxRadius = std::max(maxRadius, balls[*b].R);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Reach[k] = grid.Dims[k] > 1
        ? static_cast<int>(std::ceil((maxRadius + band) / this->Bins.GetCellSize(k))) + 1
        : 0;
    }
  }

  int GetSuperSize(int k) const { return this->SuperSize[k]; }
  int GetSupers(int k) const { return this->Bins.GetDimension(k); }

  /// The balls that can reach the clamped field inside superblock sb, whose grid
  /// points span [slo, shi].
  void Gather(const int sb[3], const double slo[3], const double shi[3], double band, double slack,
    std::vector<Candidate>& gathered) const
  {
    gathered.clear();
    const int lo[3] = { sb[0] - this->Reach[0], sb[1] - this->Reach[1], sb[2] - this->Reach[2] };
    const int hi[3] = { sb[0] + this->Reach[0], sb[1] + this->Reach[1], sb[2] + this->Reach[2] };
    this->Bins.ForEachCellInBox(lo, hi, [&](const int* b, vtkIdType bin) {
      if (this->Bins.IsCellEmpty(bin))
      {
        return;
      }
      // Bins are half-open boxes of superblock size (flat along an axis of one point).
      double blo[3], bhi[3];
      for (int k = 0; k < 3; ++k)
      {
        blo[k] = this->Bins.CellLow(k, b[k]);
        bhi[k] = blo[k] + this->Bins.GetCellSize(k);
        if (this->G.Dims[k] == 1)
        {
          blo[k] = bhi[k] = this->G.Origin[k];
        }
      }
      const double gap = BoxBoxDistance(slo, shi, blo, bhi) - band - slack;
      if (gap - this->MaxRadius[bin] >= 0.0)
      {
        return;
      }
      for (const vtkIdType* id = this->Bins.CellBegin(bin); id < this->Bins.CellEnd(bin); ++id)
      {
        if (gap - this->Balls[*id].R >= 0.0)
        {
          break; // this and every smaller ball stay beyond the band
        }
        gathered.push_back({ 0.0, *id });
      }
    });
  }

private:
  const std::vector<Ball>& Balls;
  const Grid& G;
  int SuperSize[3];
  int Reach[3];
  vtkMedialUniformGrid Bins;
  std::vector<double> MaxRadius;
};

// Pass 1: the balls, validated. Returns an error, or an empty string.
std::string GatherBalls(vtkPointSet* input, vtkDataArray* radii, int association, const char* name,
  std::vector<Ball>& balls)
{
  const std::string quoted = name ? std::string("'") + name + "'" : std::string("the radius array");
  if (!radii)
  {
    return name ? "the input has no point-data array named " + quoted + " (the radius array, see SetInputArrayToProcess)"
                : std::string("the input has no radius array (see SetInputArrayToProcess)");
  }
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    return quoted + " is not point data: the radius array needs one value per ball";
  }
  if (radii->GetNumberOfComponents() != 1)
  {
    return quoted + " has " + std::to_string(radii->GetNumberOfComponents()) + " components, expected 1";
  }
  const vtkIdType count = input->GetNumberOfPoints();
  balls.resize(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    Ball& b = balls[i];
    input->GetPoint(i, b.C);
    b.R = radii->GetTuple1(i);
    if (!std::isfinite(b.R))
    {
      return "point " + std::to_string(i) + " has a NaN or infinite radius";
    }
    if (b.R < 0.0)
    {
      std::ostringstream os;
      os << "point " << i << " has a negative radius (" << b.R << ")";
      return os.str();
    }
    if (!std::isfinite(b.C[0]) || !std::isfinite(b.C[1]) || !std::isfinite(b.C[2]))
    {
      return "point " + std::to_string(i) + " has NaN or infinite coordinates";
    }
  }
  return std::string();
}

// Pass 2: 2D or 3D (see the class comment); in 2D the centres go into the plane's
// frame (z = 0). Returns an error, or an empty string.
std::string ChooseDimension(std::vector<Ball>& balls, int requested, PlaneFrame& frame, int& dimension)
{
  double worldLo[3], worldHi[3];
  for (int k = 0; k < 3; ++k)
  {
    worldLo[k] = HUGE_VAL;
    worldHi[k] = -HUGE_VAL;
  }
  for (const Ball& b : balls)
  {
    for (int k = 0; k < 3; ++k)
    {
      worldLo[k] = std::min(worldLo[k], b.C[k] - b.R);
      worldHi[k] = std::max(worldHi[k], b.C[k] + b.R);
    }
  }
  const double worldDiagonal = std::sqrt(vtkMath::Distance2BetweenPoints(worldLo, worldHi));
  const int rank = FitPlane(balls, 1e-9 * worldDiagonal, frame);
  dimension = requested;
  if (dimension == vtkMedialBallUnion::DIMENSION_AUTOMATIC)
  {
    dimension = rank == 2 ? 2 : 3;
  }
  else if (dimension == vtkMedialBallUnion::DIMENSION_2D && rank == 3)
  {
    return "the centres do not lie in one plane, so there is no 2D union of disks";
  }
  if (dimension == 2)
  {
    for (Ball& b : balls)
    {
      double d[3];
      vtkMath::Subtract(b.C, frame.Origin, d);
      b.C[0] = vtkMath::Dot(d, frame.U);
      b.C[1] = vtkMath::Dot(d, frame.V);
      b.C[2] = 0.0;
    }
  }
  return std::string();
}

// The box of the union (centres +- radii) on the first `axes` axes (0 beyond).
void UnionBox(const std::vector<Ball>& balls, int axes, double lo[3], double hi[3])
{
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = k < axes ? HUGE_VAL : 0.0;
    hi[k] = k < axes ? -HUGE_VAL : 0.0;
  }
  for (const Ball& b : balls)
  {
    for (int k = 0; k < axes; ++k)
    {
      lo[k] = std::min(lo[k], b.C[k] - b.R);
      hi[k] = std::max(hi[k], b.C[k] + b.R);
    }
  }
}

// ModelBounds in the grid's frame: the box itself in 3D, the extent of its
// projection onto the plane's axes U, V in 2D.
void ModelBox(const double bounds[6], int dimension, const PlaneFrame& frame, double lo[3], double hi[3])
{
  if (dimension == 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = bounds[2 * k];
      hi[k] = bounds[2 * k + 1];
    }
    return;
  }
  lo[0] = lo[1] = HUGE_VAL;
  hi[0] = hi[1] = -HUGE_VAL;
  lo[2] = hi[2] = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = bounds[2 * k + ((corner >> k) & 1)] - frame.Origin[k];
    }
    const double uv[2] = { vtkMath::Dot(d, frame.U), vtkMath::Dot(d, frame.V) };
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = std::min(lo[k], uv[k]);
      hi[k] = std::max(hi[k], uv[k]);
    }
  }
}

// Pass 4: the clamped field over the grid, superblock by superblock, in z-slabs
// (parallel within a slab); `balls` are the envelope's bounding balls when there is one.
// False when aborted.
bool FillField(vtkMedialBallUnion* self, const std::vector<Ball>& balls, const Grid& grid, double band,
  double slack, int threads, double* values, const Envelope* envelope)
{
  const CentreBins bins(balls, grid, band);
  const vtkIdType sliceSize = static_cast<vtkIdType>(grid.Dims[0]) * grid.Dims[1];
  const FieldFiller filler{ balls, grid, band, slack, values, sliceSize, envelope };
  const int superPerLayer = bins.GetSupers(0) * bins.GetSupers(1);
  for (int sz = 0; sz < bins.GetSupers(2) && !self->GetAbortExecute(); ++sz)
  {
#pragma omp parallel num_threads(threads)
    {
      std::vector<Candidate> gathered;
      std::vector<std::vector<Candidate>> levels(FieldFiller::MaximumDepth);
#pragma omp for schedule(dynamic, 1)
      for (int s = 0; s < superPerLayer; ++s)
      {
        const int sb[3] = { s % bins.GetSupers(0), s / bins.GetSupers(0), sz };
        int first[3], last[3];
        double slo[3], shi[3];
        for (int k = 0; k < 3; ++k)
        {
          first[k] = sb[k] * bins.GetSuperSize(k);
          last[k] = std::min(grid.Dims[k] - 1, first[k] + bins.GetSuperSize(k) - 1);
          slo[k] = filler.PointOf(k, first[k]);
          shi[k] = filler.PointOf(k, last[k]);
        }
        bins.Gather(sb, slo, shi, band, slack, gathered);
        filler.Refine(gathered, first, last, 0, levels);
      }
    }
    self->UpdateProgress(static_cast<double>(sz + 1) / bins.GetSupers(2));
  }
  return !self->GetAbortExecute();
}

// Output 1: the field image; in 2D its direction matrix holds (u, v, n) and its
// origin is the grid's origin placed in the plane.
void WriteFieldImage(vtkImageData* image, vtkInformation* imageInfo, const Grid& grid, int dimension,
  const PlaneFrame& frame, vtkDoubleArray* field)
{
  image->SetDimensions(grid.Dims);
  image->SetOrigin(grid.Origin);
  image->SetSpacing(grid.Spacing);
  if (dimension == 2)
  {
    const double m[9] = { frame.U[0], frame.V[0], frame.N[0], frame.U[1], frame.V[1], frame.N[1],
      frame.U[2], frame.V[2], frame.N[2] };
    image->SetDirectionMatrix(m);
    double worldOrigin[3];
    for (int k = 0; k < 3; ++k)
    {
      worldOrigin[k] = frame.Origin[k] + grid.Origin[0] * frame.U[k] + grid.Origin[1] * frame.V[k];
    }
    image->SetOrigin(worldOrigin);
  }
  image->GetPointData()->SetScalars(field);
  int wholeExtent[6] = { 0, grid.Dims[0] - 1, 0, grid.Dims[1] - 1, 0, grid.Dims[2] - 1 };
  imageInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
}

// Output 0 in 3D: the zero level by flying edges, triangles facing outward.
void ContourSurface(vtkImageData* local, vtkPolyData* output)
{
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(local);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  output->ShallowCopy(contour->GetOutput());
  output->GetPointData()->Initialize();
  // Flying edges winds triangles by the scalar gradient; make them face outward.
  if (SignedVolume(output) < 0.0)
  {
    vtkNew<vtkCellArray> flipped;
    auto it = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* ids;
      it->GetCurrentCell(npts, ids);
      std::vector<vtkIdType> reversed(ids, ids + npts);
      std::reverse(reversed.begin(), reversed.end());
      flipped->InsertNextCell(npts, reversed.data());
    }
    output->SetPolys(flipped);
  }
}

// Output 0 in 2D: the zero level by flying edges 2D, chained into polylines and
// mapped back into the balls' plane.
void ContourCurves(vtkImageData* local, const PlaneFrame& frame, vtkPolyData* output)
{
  vtkNew<vtkFlyingEdges2D> contour;
  contour->SetInputData(local);
  contour->SetValue(0, 0.0);
  contour->ComputeScalarsOff();
  contour->Update();
  vtkPolyData* curves = contour->GetOutput();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType np = curves->GetNumberOfPoints();
  points->SetNumberOfPoints(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3], w[3];
    curves->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      w[k] = frame.Origin[k] + p[0] * frame.U[k] + p[1] * frame.V[k];
    }
    points->SetPoint(i, w);
  }
  output->SetPoints(points);
  output->SetLines(ChainSegments(curves));
}
}

vtkMedialBallUnion::vtkMedialBallUnion()
{
  this->SetNumberOfOutputPorts(2);
  // The radius: point data named Radius unless chosen otherwise.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
}

void vtkMedialBallUnion::SetSampleDimensions(int i, int j, int k)
{
  const int dims[3] = { std::max(8, i), std::max(8, j), std::max(8, k) };
  if (dims[0] != this->SampleDimensions[0] || dims[1] != this->SampleDimensions[1] ||
    dims[2] != this->SampleDimensions[2])
  {
    std::copy(dims, dims + 3, this->SampleDimensions);
    this->Modified();
  }
}

void vtkMedialBallUnion::SetSampleDimensions(const int dims[3])
{
  this->SetSampleDimensions(dims[0], dims[1], dims[2]);
}

bool vtkMedialBallUnion::HasModelBounds() const
{
  bool extent = false;
  for (int k = 0; k < 3; ++k)
  {
    if (!(this->ModelBounds[2 * k] <= this->ModelBounds[2 * k + 1]))
    {
      return false;
    }
    extent = extent || this->ModelBounds[2 * k] < this->ModelBounds[2 * k + 1];
  }
  return extent;
}

vtkImageData* vtkMedialBallUnion::GetFieldOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkMedialBallUnion::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkMedialBallUnion::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkImageData");
  return 1;
}

std::string vtkMedialBallUnion::PlanGrid(const double lo[3], const double hi[3], int axes, bool exact,
  double gridOrigin[3], double gridSpacing[3], int gridDims[3]) const
{
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  for (int k = 0; k < 3; ++k)
  {
    gridDims[k] = 1;
    gridOrigin[k] = 0.0;
    gridSpacing[k] = 1.0;
  }
  vtkIdType voxels = 1;
  for (int k = 0; k < axes; ++k)
  {
    const double extent = hi[k] - lo[k];
    if (exact && !(extent > 0.0))
    {
      return std::string("ModelBounds has no extent along ") + (axes == 2 ? "uv"[k] : "xyz"[k]) +
        (axes == 2 ? " (the balls' plane)" : "");
    }
    if (this->ResolutionMode == USE_SPACING)
    {
      const double h = this->Spacing * diagonal;
      const double pad = exact ? 0.0 : std::max(this->Padding * diagonal, 2.0 * h);
      const double points = std::ceil((extent + 2.0 * pad) / h) + 1.0;
      if (points > static_cast<double>(this->MaximumNumberOfVoxels) || points > VTK_INT_MAX)
      {
        std::ostringstream os;
        os << "the spacing " << this->Spacing << " needs more than MaximumNumberOfVoxels ("
           << this->MaximumNumberOfVoxels << ") grid points";
        return os.str();
      }
      gridDims[k] = static_cast<int>(points);
      gridSpacing[k] = h;
      // Centre the box in the grid.
      gridOrigin[k] = lo[k] - 0.5 * ((gridDims[k] - 1) * h - extent);
    }
    else
    {
      const int n = std::max(8, this->SampleDimensions[k]);
      gridDims[k] = n;
      if (exact)
      {
        gridSpacing[k] = extent / (n - 1);
        gridOrigin[k] = lo[k];
      }
      else
      {
        // The padding p must be two voxels at least: p >= 2 (extent + 2p) / (n - 1).
        const double pad = std::max(
          { this->Padding * diagonal, 2.0 * extent / (n - 5) * (1.0 + 1e-9), 1e-3 * diagonal });
        gridSpacing[k] = (extent + 2.0 * pad) / (n - 1);
        gridOrigin[k] = lo[k] - pad;
      }
    }
    voxels *= gridDims[k];
    if (voxels > this->MaximumNumberOfVoxels)
    {
      std::ostringstream os;
      os << "the grid would exceed MaximumNumberOfVoxels (" << this->MaximumNumberOfVoxels << ")";
      return os.str();
    }
  }
  return std::string();
}

int vtkMedialBallUnion::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Publish what does not depend on the balls: with ModelBounds in 3D the whole
  // grid, with SampleDimensions and a fixed Dimension its extent. Anything else is
  // set by RequestData; stale keys are dropped so that downstream takes the data's.
  vtkInformation* imageInfo = outputVector->GetInformationObject(1);
  imageInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  imageInfo->Remove(vtkDataObject::ORIGIN());
  imageInfo->Remove(vtkDataObject::SPACING());
  double origin[3], spacing[3];
  int dims[3];
  if (this->Dimension == DIMENSION_3D && this->HasModelBounds())
  {
    const double lo[3] = { this->ModelBounds[0], this->ModelBounds[2], this->ModelBounds[4] };
    const double hi[3] = { this->ModelBounds[1], this->ModelBounds[3], this->ModelBounds[5] };
    if (!this->PlanGrid(lo, hi, 3, true, origin, spacing, dims).empty())
    {
      return 1; // RequestData reports it
    }
    imageInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    imageInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  }
  else if (this->Dimension != DIMENSION_AUTOMATIC && this->ResolutionMode == USE_SAMPLE_DIMENSIONS)
  {
    for (int k = 0; k < 3; ++k)
    {
      dims[k] = k < this->Dimension ? std::max(8, this->SampleDimensions[k]) : 1;
    }
  }
  else
  {
    return 1;
  }
  const int wholeExtent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1 };
  imageInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  return 1;
}

int vtkMedialBallUnion::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Every ball can reach every part of the union: all of them are needed. With one
  // process per piece each keeps its own piece and RequestData gathers them;
  // otherwise every piece asks for all of the input (vtkMedialPieces.h).
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsDistributed())
  {
    vtkMedialRequestWholeInput(inputVector);
  }
  return 1;
}

int vtkMedialBallUnion::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkInformation* imageInfo = outputVector->GetInformationObject(1);
  vtkImageData* image = vtkImageData::GetData(outputVector, 1);
  this->OutputDimension = 0;
  this->VoxelSize = 0.0;
  auto fail = [this](const std::string& why) {
    vtkErrorMacro(<< "Cannot build the union of balls: " << why << ".");
    return 0;
  };

  int association = -1;
  vtkDataArray* radii = input && input->GetNumberOfPoints() > 0
    ? this->GetInputArrayToProcess(0, inputVector, association)
    : nullptr;
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  const char* name = arrayInfo->Has(vtkDataObject::FIELD_NAME()) ? arrayInfo->Get(vtkDataObject::FIELD_NAME()) : nullptr;

  // 0. Pieces: process 0 builds the whole union from every process's balls; the
  // other pieces stay empty.
  const vtkMedialPieces pieces = vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0));
  vtkSmartPointer<vtkPolyData> gathered;
  if (pieces.IsDistributed())
  {
    const std::string arrayName = name ? name : vtkMedialArrayNames::Radius;
    std::string error;
    gathered = pieces.GatherToFirst(input,
      association == vtkDataObject::FIELD_ASSOCIATION_POINTS ? radii : nullptr, arrayName.c_str(), error);
    if (!error.empty())
    {
      return fail(error);
    }
    if (gathered)
    {
      input = gathered;
      radii = gathered->GetPointData()->GetArray(arrayName.c_str());
      association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    }
  }
  if (!pieces.IsFirst())
  {
    return 1;
  }

  // 1. The balls.
  vtkMedialStages stages(this);
  stages.Begin("Gathering the balls", 0.0, 0.02);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return fail("the input has no points");
  }
  std::vector<Ball> balls;
  std::string error = GatherBalls(input, radii, association, name, balls);
  if (!error.empty())
  {
    return fail(error);
  }

  // 2. Dimension.
  PlaneFrame frame;
  int dimension = 3;
  error = ChooseDimension(balls, this->Dimension, frame, dimension);
  if (!error.empty())
  {
    return fail(error);
  }

  // 3. Grid: over the union's box, padded, or over ModelBounds.
  double lo[3], hi[3];
  UnionBox(balls, dimension, lo, hi);
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(lo, hi));
  if (!(diagonal > 0.0))
  {
    return fail("every ball has radius 0 at one point, so the union has no extent");
  }
  Grid grid;
  if (this->HasModelBounds())
  {
    double blo[3], bhi[3];
    ModelBox(this->ModelBounds, dimension, frame, blo, bhi);
    error = this->PlanGrid(blo, bhi, dimension, true, grid.Origin, grid.Spacing, grid.Dims);
    for (int k = 0; k < dimension && error.empty(); ++k)
    {
      if (lo[k] < grid.Origin[k] || hi[k] > grid.Origin[k] + (grid.Dims[k] - 1) * grid.Spacing[k])
      {
        vtkWarningMacro(<< "The union of balls reaches beyond ModelBounds: its surface is cut open there.");
        break;
      }
    }
  }
  else
  {
    error = this->PlanGrid(lo, hi, dimension, false, grid.Origin, grid.Spacing, grid.Dims);
  }
  if (!error.empty())
  {
    return fail(error);
  }
  double voxelSize = 0.0;
  for (int k = 0; k < dimension; ++k)
  {
    voxelSize = std::max(voxelSize, grid.Spacing[k]);
  }
  const double band = this->BandWidth * voxelSize;
  // Rounding margin for the bounds so that pruning never drops the minimising ball.
  const double slack = 1e-12 * (diagonal + std::fabs(lo[0]) + std::fabs(lo[1]) + std::fabs(lo[2]));

  // 4. Field. The envelope's primitives are binned and pruned through their bounding
  // balls.
  std::unique_ptr<Envelope> envelope;
  if (this->Primitives == MEDIAL_MESH)
  {
    envelope.reset(new Envelope);
    envelope->Vertices = balls;
    GatherPrimitives(vtkPolyData::SafeDownCast(input), EnvelopeTolerance * voxelSize, *envelope);
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName(vtkMedialArrayNames::Distance);
  field->SetNumberOfTuples(static_cast<vtkIdType>(grid.Dims[0]) * grid.Dims[1] * grid.Dims[2]);
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  stages.Begin("Filling the distance field", 0.02, 0.9);
  if (!FillField(this, envelope ? envelope->Bounds : balls, grid, band, slack, threads,
        field->GetPointer(0), envelope.get()))
  {
    return 1; // aborted: leave the outputs empty
  }

  // 5. Outputs: the field image, and its zero level contoured on an axis-aligned
  // copy in the grid's frame.
  stages.Begin(dimension == 3 ? "Contouring the surface" : "Contouring the curves", 0.9, 1.0);
  WriteFieldImage(image, imageInfo, grid, dimension, frame, field);
  vtkNew<vtkImageData> local;
  local->SetDimensions(grid.Dims);
  local->SetOrigin(grid.Origin);
  local->SetSpacing(grid.Spacing);
  local->GetPointData()->SetScalars(field);
  if (dimension == 3)
  {
    ContourSurface(local, output);
  }
  else
  {
    ContourCurves(local, frame, output);
  }
  this->OutputDimension = dimension;
  this->VoxelSize = voxelSize;
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialBallUnion::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ResolutionMode: "
     << (this->ResolutionMode == USE_SPACING ? "Spacing" : "SampleDimensions") << "\n";
  os << indent << "SampleDimensions: " << this->SampleDimensions[0] << " "
     << this->SampleDimensions[1] << " " << this->SampleDimensions[2] << "\n";
  os << indent << "Spacing: " << this->Spacing << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "ModelBounds: " << this->ModelBounds[0] << " " << this->ModelBounds[1] << " "
     << this->ModelBounds[2] << " " << this->ModelBounds[3] << " " << this->ModelBounds[4] << " "
     << this->ModelBounds[5] << (this->HasModelBounds() ? "" : " (not set: the union's box)") << "\n";
  os << indent << "BandWidth: " << this->BandWidth << "\n";
  os << indent << "Dimension: " << this->Dimension << "\n";
  os << indent << "Primitives: " << (this->Primitives == MEDIAL_MESH ? "MedialMesh" : "Balls") << "\n";
  os << indent << "MaximumNumberOfVoxels: " << this->MaximumNumberOfVoxels << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputDimension: " << this->OutputDimension << "\n";
  os << indent << "VoxelSize: " << this->VoxelSize << "\n";
}
