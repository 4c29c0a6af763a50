// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialThickness.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialBallSolver.h"
#include "vtkMedialDisjointSets.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialProgress.h"
#include "vtkMedialRepairCallback.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidPreparation.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceNormals.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>

vtkStandardNewMacro(vtkMedialThickness);

namespace
{
namespace G = vtkMedialGeometry;
constexpr double Pi = 3.14159265358979323846;
// A ball whose contacts are all less than this far apart (seen from its centre), on
// walls that meet along convex creases, rounds their edge instead of spanning a wall:
// it slides off it (see the class comment). A wedge sharper than 180 - WallAngle
// degrees stays thin.
constexpr double WallAngle = 120.0;
// Consecutive items (in the tree's leaf order) solved on one thread, each hinted with
// the previous one's contact; groups start at multiples of Chain whatever the thread
// count, so the output does not depend on it (as in the sampler).
constexpr vtkIdType Chain = 8;
// Items per block between progress reports and abort checks.
constexpr vtkIdType Block = 8192;

const double NaN = std::nan("");

// Max's weight of a triangle (at, b, c) for the normal at vertex `at`: its area vector
// divided by |b - at|^2 |c - at|^2 (N. Max, "Weights for computing vertex normals from
// facet normals", 1999). The sum is exact when the neighbours lie on a sphere.
void AddMaxWeighted(const double* at, const double* b, const double* c, double n[3])
{
  double u[3], v[3], w[3];
  G::Sub(b, at, u);
  G::Sub(c, at, v);
  G::Cross(u, v, w);
  const double weight = G::Dot(u, u) * G::Dot(v, v);
  if (weight > 0.0)
  {
    G::AddScaled(n, -1.0 / weight, w, n); // inward
  }
}

// The limits of the balls' growth at a point whose local facet size is `size`.
vtkMedialGrowthLimits GrowthLimits(double tolerance, double size)
{
  vtkMedialGrowthLimits limits;
  limits.Tolerance = tolerance * size;
  limits.CosHalfSlideAngle = std::cos(0.5 * WallAngle * Pi / 180.0);
  return limits;
}

// At a sharp vertex p (faces `fan`, local facet size `size`), a small inscribed ball
// just inside the wedge of its faces, along the direction that makes equal angles with
// their nearest inward normals (the nearest point of the normals' hull); invalid where
// no such direction enters the solid (a fold). `withinStep`: whether its contact lies
// less than the step from its centre (as a wedge ball had to before concave creases got
// one).
vtkMedialSampleRecord WedgeBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const double p[3], const std::vector<vtkIdType>& fan, double size, bool& withinStep)
{
  withinStep = false;
  vtkMedialSampleRecord ball;
  ball.Valid = false;
  std::vector<std::array<double, 3>> inward;
  for (vtkIdType t : fan)
  {
    if (mesh.Areas[t] > 0.0)
    {
      const double* o = mesh.GetNormal(t);
      inward.push_back({ -o[0], -o[1], -o[2] });
    }
  }
  double d[3];
  G::NearestHullPoint(inward, d);
  const double length = std::sqrt(G::Dot(d, d));
  if (!(length > 1e-3))
  {
    return ball;
  }
  for (double& x : d)
  {
    x /= length;
  }
  const double step = 1e-3 * size;
  G::AddScaled(p, step, d, ball.Centre);
  vtkMedialSurfaceQuery::RayHit ray;
  vtkMedialSurfaceQuery::ClosestHit hit;
  // The closest point within 2 steps: beside a convex edge a face's plane is nearer than
  // p, but in a concave one p itself is the closest, exactly a step away, and a search
  // within the step found it or not as rounding went.
  if (!query.IntersectFromInside(ball.Centre, d, 0.0, -1, ray) || !(ray.Distance > 2.0 * step) ||
    !query.ClosestPoint(ball.Centre, 2.0 * step, hit))
  {
    return ball;
  }
  ball.Valid = true;
  ball.Shrunk = false;
  ball.Radius = hit.Distance;
  vtkMedialSurfaceQuery::ClosestHit near;
  withinStep = hit.Distance < step * (1.0 - 1e-9) || query.ClosestPoint(ball.Centre, step, near);
  std::copy(hit.Point, hit.Point + 3, ball.Contact);
  ball.ContactTriangle = hit.Triangle;
  std::copy(p, p + 3, ball.Surface);
  return ball;
}

// Runs solve(item, hint) for every (item, triangle) pair, in the tree's leaf order of
// the triangles (neighbours touch the same nodes), in fixed groups of Chain in parallel;
// solve returns the contact triangle to hint the next item with. Reports the stage's
// progress (0 to 1) between blocks; false when aborted.
template <class Solve>
bool SolveInLeafOrder(vtkAlgorithm* self, const vtkMedialSurfaceQuery& query,
  std::vector<std::pair<vtkIdType, vtkIdType>> items, int threads, Solve solve)
{
  const auto& rank = query.GetLeafRanks();
  std::stable_sort(items.begin(), items.end(),
    [&](const auto& a, const auto& b) { return rank[a.second] < rank[b.second]; });
  const vtkIdType n = static_cast<vtkIdType>(items.size());
  for (vtkIdType begin = 0; begin < n; begin += Block)
  {
    const vtkIdType end = std::min(n, begin + Block);
    const vtkIdType groups = (end - begin + Chain - 1) / Chain;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (vtkIdType g = 0; g < groups; ++g)
    {
      vtkIdType hint = -1;
      for (vtkIdType k = begin + g * Chain; k < std::min(end, begin + (g + 1) * Chain); ++k)
      {
        hint = solve(items[k].first, hint);
      }
    }
    self->UpdateProgress(static_cast<double>(end) / static_cast<double>(n));
    if (self->GetAbortExecute())
    {
      return false;
    }
  }
  return true;
}

// The surface points that the ascents of this thread's chain found so far
// (vtkMedialGrowBall's surfacePoints): neighbours' balls meet the same surface. Every
// item asks for them first, and a chain starts with no hint (SolveInLeafOrder), so they
// never outlive it, nor reach a run on another surface; they only spare queries, and
// the balls are the same without them.
std::vector<std::array<double, 3>>& ChainPoints(vtkIdType hint)
{
  thread_local std::vector<std::array<double, 3>> points;
  if (hint < 0)
  {
    points.clear();
  }
  return points;
}

// The ball of a valid record as a radius and a centre; its contact triangle hints the
// next item.
vtkIdType Keep(const vtkMedialSampleRecord& ball, vtkIdType hint, double& radius, double centre[3])
{
  if (!ball.Valid)
  {
    return hint;
  }
  radius = ball.Radius;
  std::copy(ball.Centre, ball.Centre + 3, centre);
  return ball.ContactTriangle;
}

// Distance along the inward direction n from p to the surface beyond, or NaN when the
// ray escapes or meets a face from outside.
double RayLength(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const double p[3], const double n[3], vtkIdType ownTriangle)
{
  vtkMedialSurfaceQuery::RayHit hit;
  return query.IntersectFromInside(p, n, 1e-9 * mesh.Diagonal, ownTriangle, hit) ? hit.Distance : NaN;
}

// Coordinates as a sort key; + 0.0 turns -0 into +0, which the point merge treats alike.
std::array<double, 3> Key(const double x[3])
{
  return { x[0] + 0.0, x[1] + 0.0, x[2] + 0.0 };
}
}

// The walls of the surface: its triangles split along its creases (adjacent faces'
// normals more than CreaseAngle apart), and which walls meet along a convex crease (where
// the solid's two faces meet at less than 180 degrees). Only a ball that touches walls
// meeting so rounds an edge and may slide off it: on one smooth wall, a ball whose
// contacts are close together is a rim's, and its size is the wall's.
// A crease may fade out (a rounded wall that meets a flat one along a crease that ends
// where their facets turn less than the crease angle apart): the two sides are then one
// wall, joined around the crease's end, though the crease runs between them. So for two
// triangles of a wall with a convex crease inside it the question is asked near the
// ball instead: the triangles joined to each across smooth edges within reach of the
// ball (LocalReach times its radius from its centre) are its local wall, and two local
// walls meet along a convex crease there if one of its edges joins them.
// Asked so, the local walls would be floods of (r / h)^2 triangles (r the radius, h the
// facet size) at every sliding step, and a scanned surface's noise creases make most
// walls creased: so the question is answered by searches that stop early. Two contacts
// share a local wall if a search from one, nearest to the other first, reaches it; only
// when it does not (it ran out of triangles: it visited the whole local wall) are the
// convex crease edges out of that local wall followed. A search that visits more than
// LocalBudget triangles gives up, and the whole wall's answer (one wall: they do not
// meet) stands.
struct vtkMedialThickness::Walls
{
  enum EdgeKind : unsigned char
  {
    Smooth,
    ConvexCrease,
    ConcaveCrease,
    Other // a boundary or non-manifold edge, or a degenerate face
  };
  // How far from a ball's centre (times its radius) its local walls reach: a convex
  // crease between contacts less than WallAngle apart lies within 1 / sin(30 degrees)
  // = 2 radii of the centre.
  static constexpr double LocalReach = 2.5;
  // Triangles one local search may visit before it gives up.
  static constexpr int LocalBudget = 8192;

  std::vector<vtkIdType> OfTriangle;
  std::vector<std::pair<vtkIdType, vtkIdType>> Convex; // (a < b), sorted, unique
  // Walls (by their OfTriangle) with a convex crease edge between two of their triangles.
  std::vector<char> InnerConvex;
  // Each triangle's neighbour across its edge j (vertices j, j + 1) and that edge's kind.
  std::vector<vtkIdType> Neighbour;
  std::vector<EdgeKind> Kind;
  // Each triangle's bounding box (low x, y, z, high x, y, z) and centroid, for the
  // local searches.
  std::vector<std::array<double, 6>> Box;
  std::vector<std::array<double, 3>> Middle;
  // The local facet size at each point: the longest edge that ends there (the
  // tolerance's unit; a cell's is the largest of its corners').
  std::vector<double> Size;

  // `start` and `around`: the triangles around each point, by increasing id
  // (vtkMedialTriangleMesh::TrianglesAroundPoints).
  void Build(const vtkMedialTriangleMesh& mesh, double creaseDegrees, const std::vector<vtkIdType>& start,
    const std::vector<vtkIdType>& around)
  {
    const double cosCrease = std::cos(creaseDegrees * Pi / 180.0);
    const vtkIdType nt = mesh.GetNumberOfTriangles();
    this->Box.resize(nt);
    this->Middle.resize(nt);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      const vtkIdType* v = mesh.GetTriangle(t);
      const double *a = mesh.GetPoint(v[0]), *b = mesh.GetPoint(v[1]), *c = mesh.GetPoint(v[2]);
      for (int k = 0; k < 3; ++k)
      {
        this->Box[t][k] = std::min({ a[k], b[k], c[k] });
        this->Box[t][k + 3] = std::max({ a[k], b[k], c[k] });
        this->Middle[t][k] = (a[k] + b[k] + c[k]) / 3.0;
      }
    }
    this->Size.assign(mesh.GetNumberOfPoints(), 0.0);
    this->Neighbour.assign(3 * static_cast<size_t>(nt), -1);
    this->Kind.assign(3 * static_cast<size_t>(nt), Other);
    vtkMedialDisjointSets sets(nt);
    std::vector<std::pair<vtkIdType, vtkIdType>> convex;
    // The edges in (lower point, higher point, triangle, edge index) order, an edge of
    // exactly two triangles joining them unless it is a crease: the order of the joins
    // fixes the walls' ids. A point's edges to higher points are gathered from the
    // triangles around it and sorted there (a few), not all edges sorted at once.
    std::vector<std::array<vtkIdType, 3>> edges; // (higher point, triangle, edge index)
    const vtkIdType np = mesh.GetNumberOfPoints();
    for (vtkIdType p = 0; p < np; ++p)
    {
      edges.clear();
      for (vtkIdType k = start[p]; k < start[p + 1]; ++k)
      {
        const vtkIdType t = around[k];
        const vtkIdType* v = mesh.GetTriangle(t);
        for (int j = 0; j < 3; ++j)
        {
          const vtkIdType u = v[j], w = v[(j + 1) % 3];
          if (std::min(u, w) == p)
          {
            edges.push_back({ std::max(u, w), t, j });
          }
        }
      }
      std::sort(edges.begin(), edges.end());
      for (const auto& e : edges)
      {
        const double length = std::sqrt(G::Distance2(mesh.GetPoint(p), mesh.GetPoint(e[0])));
        this->Size[p] = std::max(this->Size[p], length);
        this->Size[e[0]] = std::max(this->Size[e[0]], length);
      }
      for (size_t i = 0; i < edges.size();)
      {
        size_t j = i + 1;
        while (j < edges.size() && edges[j][0] == edges[i][0])
        {
          ++j;
        }
        const vtkIdType a = edges[i][1], b = edges[j - 1][1];
        if (j == i + 2 && mesh.Areas[a] > 0.0 && mesh.Areas[b] > 0.0)
        {
          EdgeKind kind = Smooth;
          if (G::Dot(mesh.GetNormal(a), mesh.GetNormal(b)) >= cosCrease)
          {
            sets.Join(a, b);
          }
          else
          {
            // Convex: b's third point lies below a's plane.
            const vtkIdType* tb = mesh.GetTriangle(b);
            int k = 0;
            while (k < 2 && (tb[k] == p || tb[k] == edges[i][0]))
            {
              ++k;
            }
            double d[3];
            G::Sub(mesh.GetPoint(tb[k]), mesh.GetPoint(p), d);
            kind = G::Dot(mesh.GetNormal(a), d) < 0.0 ? ConvexCrease : ConcaveCrease;
            if (kind == ConvexCrease)
            {
              convex.emplace_back(a, b);
            }
          }
          this->Neighbour[3 * a + edges[i][2]] = b;
          this->Neighbour[3 * b + edges[i + 1][2]] = a;
          this->Kind[3 * a + edges[i][2]] = kind;
          this->Kind[3 * b + edges[i + 1][2]] = kind;
        }
        i = j;
      }
    }
    this->OfTriangle.resize(nt);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      this->OfTriangle[t] = sets.Find(t);
    }
    this->Convex.clear();
    this->InnerConvex.assign(nt, 0);
    for (const auto& c : convex)
    {
      const vtkIdType a = this->OfTriangle[c.first], b = this->OfTriangle[c.second];
      if (a != b)
      {
        this->Convex.emplace_back(std::min(a, b), std::max(a, b));
      }
      else
      {
        this->InnerConvex[a] = 1;
      }
    }
    std::sort(this->Convex.begin(), this->Convex.end());
    this->Convex.erase(std::unique(this->Convex.begin(), this->Convex.end()), this->Convex.end());
  }

  // Per-thread scratch of the local searches: a stamp per triangle marks what one
  // search reached without clearing (Reached lists it).
  struct Scratch
  {
    std::vector<unsigned> Mark;
    unsigned Stamp = 0;
    std::vector<std::pair<double, vtkIdType>> Heap;
    std::vector<vtkIdType> Reached;
  };
  static Scratch& LocalScratch()
  {
    thread_local Scratch scratch;
    return scratch;
  }

  // How a local search ended: it reached its target, it ran out of triangles (all
  // those of the source's local wall carry the search's stamp), or it gave up.
  enum class Search
  {
    Joined,
    Apart,
    GaveUp
  };
  // Whether triangles a and b lie on one local wall: a search from a across smooth
  // edges through the triangles within reach of the ball, nearest to b first.
  Search Join(vtkIdType a, vtkIdType b, const double centre[3], double reach2, Scratch& scratch) const
  {
    const size_t nt = this->OfTriangle.size();
    if (scratch.Mark.size() < nt)
    {
      scratch.Mark.assign(nt, 0);
      scratch.Stamp = 0;
    }
    if (++scratch.Stamp == 0) // wrapped: clear the old marks
    {
      std::fill(scratch.Mark.begin(), scratch.Mark.end(), 0u);
      scratch.Stamp = 1;
    }
    scratch.Mark[a] = scratch.Stamp;
    scratch.Reached.assign(1, a);
    if (a == b)
    {
      return Search::Joined;
    }
    const double* target = this->Middle[b].data();
    auto later = [](const std::pair<double, vtkIdType>& x, const std::pair<double, vtkIdType>& y) {
      return x.first > y.first || (x.first == y.first && x.second > y.second);
    };
    std::vector<std::pair<double, vtkIdType>>& heap = scratch.Heap;
    heap.clear();
    heap.emplace_back(0.0, a);
    for (int visited = 0; !heap.empty(); ++visited)
    {
      if (visited == LocalBudget)
      {
        return Search::GaveUp;
      }
      std::pop_heap(heap.begin(), heap.end(), later);
      const vtkIdType u = heap.back().second;
      heap.pop_back();
      for (int j = 0; j < 3; ++j)
      {
        const vtkIdType n = this->Neighbour[3 * u + j];
        if (n < 0 || this->Kind[3 * u + j] != Smooth || scratch.Mark[n] == scratch.Stamp)
        {
          continue;
        }
        if (n == b)
        {
          return Search::Joined;
        }
        if (this->BoxDistance2(n, centre) > reach2)
        {
          continue;
        }
        scratch.Mark[n] = scratch.Stamp;
        scratch.Reached.push_back(n);
        heap.emplace_back(G::Distance2(this->Middle[n].data(), target), n);
        std::push_heap(heap.begin(), heap.end(), later);
      }
    }
    return Search::Apart;
  }

  // After a search from a that ran out of triangles (a's local wall carries the
  // scratch's stamp and is listed in Reached): whether a convex crease edge out of it
  // joins it to b's local wall, near the ball.
  bool JoinedAcross(vtkIdType b, const double centre[3], double reach2, Scratch& scratch) const
  {
    const unsigned ofA = scratch.Stamp;
    const vtkIdType w = this->OfTriangle[b];
    std::vector<vtkIdType> across;
    for (vtkIdType u : scratch.Reached)
    {
      for (int j = 0; j < 3; ++j)
      {
        const vtkIdType n = this->Neighbour[3 * u + j];
        if (this->Kind[3 * u + j] == ConvexCrease && scratch.Mark[n] != ofA && this->OfTriangle[n] == w &&
          (n == b || this->BoxDistance2(n, centre) <= reach2))
        {
          across.push_back(n);
        }
      }
    }
    for (vtkIdType t : across)
    {
      if (this->Join(t, b, centre, reach2, scratch) == Search::Joined)
      {
        return true;
      }
    }
    return false;
  }

  // Whether triangles a and b of one wall lie on two local walls that meet along a
  // convex crease near the ball.
  bool MeetLocally(vtkIdType a, vtkIdType b, const double centre[3], double reach2, Scratch& scratch) const
  {
    return this->InnerConvex[this->OfTriangle[a]] && this->Join(a, b, centre, reach2, scratch) == Search::Apart &&
      this->JoinedAcross(b, centre, reach2, scratch);
  }

  // The squared distance from x to triangle t's bounding box.
  double BoxDistance2(vtkIdType t, const double x[3]) const
  {
    const std::array<double, 6>& box = this->Box[t];
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double d = x[k] < box[k] ? box[k] - x[k] : x[k] > box[k + 3] ? x[k] - box[k + 3] : 0.0;
      d2 += d * d;
    }
    return d2;
  }

  // Whether a tangent ball at a point of `faces` may grow: the surface near its point
  // shrank it (a facet's tilt or a ripple), or what stopped it lies less than the wall
  // angle away on a wall that meets the point's along a convex crease (an edge), near
  // the ball where one wall holds both.
  bool MayGrow(const std::vector<vtkIdType>& faces, const vtkMedialSampleRecord& ball) const
  {
    if (!ball.Valid || !(ball.Radius > 0.0))
    {
      return false;
    }
    if (ball.Shrunk)
    {
      return true;
    }
    if (!(ball.Angle < WallAngle) || ball.ContactTriangle < 0)
    {
      return false;
    }
    const vtkIdType w = this->OfTriangle[ball.ContactTriangle];
    bool local = false;
    for (vtkIdType f : faces)
    {
      if (this->MeetConvex(w, this->OfTriangle[f]))
      {
        return true;
      }
      local = local || w == this->OfTriangle[f];
    }
    if (!local || !this->InnerConvex[w])
    {
      return false;
    }
    // The faces on the contact's wall, each unless a search from it reaches the
    // contact's local wall (or a face already known on it, for the fan's faces meet).
    const double reach2 = LocalReach * LocalReach * ball.Radius * ball.Radius;
    Scratch& scratch = LocalScratch();
    vtkIdType onContactWall = -1;
    for (vtkIdType f : faces)
    {
      if (this->OfTriangle[f] != w ||
        (onContactWall >= 0 && this->Join(f, onContactWall, ball.Centre, reach2, scratch) == Search::Joined))
      {
        continue;
      }
      switch (this->Join(f, ball.ContactTriangle, ball.Centre, reach2, scratch))
      {
        case Search::Joined:
          onContactWall = f;
          break;
        case Search::Apart:
          if (this->JoinedAcross(ball.ContactTriangle, ball.Centre, reach2, scratch))
          {
            return true;
          }
          break;
        case Search::GaveUp:
          break;
      }
    }
    return false;
  }

  bool MeetConvex(vtkIdType a, vtkIdType b) const
  {
    return a != b &&
      std::binary_search(this->Convex.begin(), this->Convex.end(), std::make_pair(std::min(a, b), std::max(a, b)));
  }

  // The triangle that stands for a contact on triangle t on its wall: t itself, or for a
  // point contact (-1) the sample's first face (-1 when it has none).
  static vtkIdType WallOf(const std::vector<vtkIdType>& faces, vtkIdType t)
  {
    return t >= 0 ? t : (faces.empty() ? -1 : faces.front());
  }

  // True when triangle t lies on none of the walls of the contacts on `triangles` (-1:
  // one of `faces`) and its wall meets one of theirs along a convex crease (whole walls:
  // the cheap part of MaySlide, asked first where a new contact may join).
  bool Across(const std::vector<vtkIdType>& faces, const vtkIdType* triangles, int count, vtkIdType t) const
  {
    if (t < 0)
    {
      return false;
    }
    const vtkIdType w = this->OfTriangle[t];
    bool meets = false;
    for (int i = 0; i < count; ++i)
    {
      const vtkIdType c = WallOf(faces, triangles[i]);
      if (c >= 0)
      {
        const vtkIdType wc = this->OfTriangle[c];
        if (wc == w)
        {
          return false;
        }
        meets = meets || this->MeetConvex(w, wc);
      }
    }
    return meets;
  }

  // True when the contacts on `triangles` (-1: one of `faces`) of a ball (centre,
  // radius) lie on at least two walls, each of which meets another one of them along a
  // convex crease (local walls, near the ball, where a wall has a convex crease inside it).
  bool MaySlide(const std::vector<vtkIdType>& faces, const vtkIdType* triangles, int count,
    const double centre[3], double radius) const
  {
    // Each contact's wall, and one contact per local wall (a wall without a convex
    // crease near the ball is one).
    struct Local
    {
      vtkIdType Wall;
      vtkIdType Triangle;
    };
    std::vector<Local> walls;
    const double reach2 = LocalReach * LocalReach * radius * radius;
    Scratch& scratch = LocalScratch();
    for (int i = 0; i < count; ++i)
    {
      const vtkIdType t = WallOf(faces, triangles[i]);
      if (t < 0)
      {
        continue;
      }
      // A new local wall unless a contact already listed lies on t's wall, and it is
      // whole or a search from t reaches that contact (a search that gives up counts as
      // reaching it: the whole wall's answer).
      const vtkIdType w = this->OfTriangle[t];
      bool joined = false;
      for (const Local& l : walls)
      {
        joined = joined ||
          (l.Wall == w &&
            (!this->InnerConvex[w] || this->Join(t, l.Triangle, centre, reach2, scratch) != Search::Apart));
      }
      if (!joined)
      {
        walls.push_back({ w, t });
      }
    }
    if (walls.size() < 2)
    {
      return false;
    }
    for (const Local& a : walls)
    {
      bool meets = false;
      for (const Local& b : walls)
      {
        meets = meets ||
          (&a != &b &&
            (a.Wall != b.Wall ? this->MeetConvex(a.Wall, b.Wall)
                              : this->MeetLocally(a.Triangle, b.Triangle, centre, reach2, scratch)));
      }
      if (!meets)
      {
        return false;
      }
    }
    return true;
  }
};

vtkMedialThickness::vtkMedialThickness()
{
  this->Repair = vtkMedialRepairFilter::New();
}

vtkMedialThickness::~vtkMedialThickness()
{
  this->SetRepair(nullptr);
}

vtkCxxSetObjectMacro(vtkMedialThickness, Repair, vtkMedialRepairFilter);

vtkMTimeType vtkMedialThickness::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->Repair ? std::max(time, this->Repair->GetMTime()) : time;
}

int vtkMedialThickness::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialThickness::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Rays need the whole surface whatever piece is requested downstream.
  vtkMedialRequestWholeInput(inputVector);
  return 1;
}

void vtkMedialThickness::VertexNormals(const vtkMedialTriangleMesh& mesh,
  const std::vector<vtkIdType>& start, const std::vector<vtkIdType>& around,
  std::vector<double>& normals, std::vector<char>& sharp)
{
  const vtkIdType np = mesh.GetNumberOfPoints();
  normals.assign(3 * np, 0.0);
  sharp.assign(np, 0);
  const double cosSpread = std::cos(this->MinimumSeparationAngle * Pi / 180.0);
  for (vtkIdType v = 0; v < np; ++v)
  {
    double* n = &normals[3 * v];
    double lowestCos = 1.0;
    for (vtkIdType i = start[v]; i < start[v + 1]; ++i)
    {
      const vtkIdType t = around[i];
      const vtkIdType* tri = mesh.GetTriangle(t);
      const int j = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
      AddMaxWeighted(mesh.GetPoint(v), mesh.GetPoint(tri[(j + 1) % 3]), mesh.GetPoint(tri[(j + 2) % 3]), n);
      for (vtkIdType k = start[v]; k < i; ++k)
      {
        if (mesh.Areas[t] > 0.0 && mesh.Areas[around[k]] > 0.0)
        {
          lowestCos = std::min(lowestCos, G::Dot(mesh.GetNormal(t), mesh.GetNormal(around[k])));
        }
      }
    }
    const double length = std::sqrt(G::Dot(n, n));
    for (int k = 0; k < 3; ++k)
    {
      n[k] = length > 0.0 ? n[k] / length : 0.0;
    }
    sharp[v] = !(length > 0.0) || lowestCos < cosSpread;
    this->SharpVertices += sharp[v];
  }
}

bool vtkMedialThickness::VertexBalls(const vtkMedialTriangleMesh& mesh,
  const vtkMedialSurfaceQuery& query, const vtkMedialBallParameters& param, const Walls& walls,
  const std::vector<vtkIdType>& start, const std::vector<vtkIdType>& around,
  const std::vector<double>& normals, const std::vector<char>& sharp, std::vector<Measure>& measures)
{
  const vtkIdType np = mesh.GetNumberOfPoints();
  measures.assign(np, Measure{});
  std::vector<std::pair<vtkIdType, vtkIdType>> items; // (vertex, one of its triangles)
  for (vtkIdType v = 0; v < np; ++v)
  {
    if (start[v + 1] > start[v])
    {
      items.emplace_back(v, around[start[v]]);
    }
  }
  auto solve = [&](vtkIdType v, vtkIdType hint) {
    std::vector<std::array<double, 3>>& points = ChainPoints(hint);
    const double* p = mesh.GetPoint(v);
    const double* n = &normals[3 * v];
    const std::vector<vtkIdType> fan(around.begin() + start[v], around.begin() + start[v + 1]);
    // The tangent ball (TangentThickness): along the mean normal, or at a sharp vertex
    // the smallest over the adjacent faces' normals.
    vtkMedialSampleRecord along, tangent;
    along.Valid = false;
    if (!sharp[v])
    {
      vtkMedialSolveBallAlong(query, mesh, param, -1, p, n, along, hint);
    }
    tangent = along;
    if (!tangent.Valid) // sharp, or the mean normal leaves the solid at once (a fold)
    {
      for (vtkIdType t : fan)
      {
        vtkMedialSampleRecord face;
        face.Valid = false; // degenerate faces are skipped
        if (mesh.Areas[t] > 0.0)
        {
          vtkMedialSolveBall(query, mesh, param, t, p, face, hint);
        }
        if (face.Valid && (!tangent.Valid || face.Radius < tangent.Radius))
        {
          tangent = face;
        }
      }
    }
    if (!tangent.Valid && mesh.BoundaryEdges == 0)
    {
      // Closed, yet every direction leaves the solid at once: a fold (adjacent faces
      // nearly opposite) where no ball fits.
      tangent.Valid = true;
      tangent.Radius = 0.0;
      tangent.ContactTriangle = -1; // no ball, so no hint for the next vertex
      std::copy(p, p + 3, tangent.Centre);
    }
    Measure& m = measures[v];
    m.Ray = RayLength(query, mesh, p, n, -1);
    if (std::isnan(m.Ray) && tangent.Valid)
    {
      // The mean normal leaves the solid: the ray along the chosen ball's direction.
      double d[3];
      G::Sub(tangent.Centre, p, d);
      const double length = std::sqrt(G::Dot(d, d));
      for (double& x : d)
      {
        x = length > 0.0 ? x / length : 0.0;
      }
      m.Ray = length > 0.0 ? RayLength(query, mesh, p, d, -1) : 0.0;
    }
    m.TangentRadius = tangent.Valid ? tangent.Radius : NaN;
    const vtkIdType next = Keep(tangent, hint, m.Radius, m.Centre);

    // The grown ball (Thickness): from the ball along the mean normal, or at a sharp
    // vertex from a small ball in its wedge.
    const double size = walls.Size[v];
    vtkMedialGrowthLimits limits = GrowthLimits(this->SurfaceTolerance, size);
    limits.MaySlide = [&](const vtkIdType* t, int count, const double* centre, double radius) {
      return walls.MaySlide(fan, t, count, centre, radius);
    };
    limits.Across = [&](const vtkIdType* t, int count, vtkIdType other) { return walls.Across(fan, t, count, other); };
    vtkMedialSampleRecord grown = along;
    bool wedgeWithinStep = true;
    // The vertex's own faces stopped the ball along the mean normal within the tolerance:
    // a face more than theta / 2 from the normal rises into every ball tangent at p along
    // it, however small (a saddle or a concave crease, or a fan whose Max weights put the
    // normal near one side of the faces' normals). Such a ball reads about 0 (1e-11); it
    // is grown from the wedge ball instead, as at a sharp vertex.
    const bool stoppedByOwnFaces = along.Valid && along.Radius < limits.Tolerance &&
      std::find(fan.begin(), fan.end(), along.ContactTriangle) != fan.end();
    if (!along.Valid || stoppedByOwnFaces)
    {
      grown = WedgeBall(query, mesh, p, fan, size, wedgeWithinStep);
      limits.MaximumSteps = 2; // it touches one face first: a second probe finds the other
      limits.Probes = 4;
    }
    else if (!walls.MayGrow(fan, along))
    {
      return next;
    }
    if (grown.Valid)
    {
      vtkMedialSampleRecord plain, kept, prior;
      vtkMedialGrowBall(
        query, p, limits, fan.data(), static_cast<int>(fan.size()), grown, &plain, &kept, &prior, &points);
      for (const auto& [ball, radius, centre] : { std::make_tuple(&plain, &m.PlainRadius, m.PlainCentre),
             std::make_tuple(&kept, &m.KeptRadius, m.KeptCentre),
             std::make_tuple(&prior, &m.PriorRadius, m.PriorCentre) })
      {
        // (Kept: the tangent ball where the wedge ball is a concave crease's.)
        const bool tangentLarger =
          tangent.Valid && (tangent.Radius > ball->Radius || (ball == &kept && !wedgeWithinStep));
        *radius = tangentLarger ? m.Radius : ball->Radius;
        std::copy(tangentLarger ? m.Centre : ball->Centre, (tangentLarger ? m.Centre : ball->Centre) + 3, centre);
      }
      if (!(tangent.Valid && tangent.Radius > grown.Radius))
      {
        m.Radius = grown.Radius;
        std::copy(grown.Centre, grown.Centre + 3, m.Centre);
      }
    }
    return next;
  };
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  return SolveInLeafOrder(this, query, items, threads, solve);
}

bool vtkMedialThickness::CellBalls(const vtkMedialTriangleMesh& mesh,
  const vtkMedialSurfaceQuery& query, const vtkMedialBallParameters& param, const Walls& walls, vtkIdType cells,
  const std::vector<Measure>& corners, std::vector<Measure>& measures)
{
  // The smooth surface's normals, creased where the walls are.
  vtkMedialSurfaceNormals normals;
  vtkMedialBallParameters smoothParameters = param;
  const vtkMedialBallParameters* smooth = nullptr;
  if (param.CosMinAngle < 1.0)
  {
    normals.Build(mesh, this->CreaseAngle);
    smoothParameters.Normals = &normals;
    smooth = &smoothParameters;
  }
  measures.assign(cells, Measure{});
  // Each cell is represented by its largest triangle (the first among equals).
  std::vector<vtkIdType> largest(cells, -1);
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    vtkIdType& l = largest[mesh.SourceCellIds[t]];
    if (mesh.Areas[t] > 0.0 && (l < 0 || mesh.Areas[t] > mesh.Areas[l]))
    {
      l = t;
    }
  }
  std::vector<std::pair<vtkIdType, vtkIdType>> items; // (cell, its largest triangle)
  for (vtkIdType c = 0; c < cells; ++c)
  {
    if (largest[c] >= 0)
    {
      items.emplace_back(c, largest[c]);
    }
  }
  auto solve = [&](vtkIdType c, vtkIdType hint) {
    std::vector<std::array<double, 3>>& points = ChainPoints(hint);
    const vtkIdType t = largest[c];
    const vtkIdType* v = mesh.GetTriangle(t);
    double p[3], n[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (mesh.GetPoint(v[0])[k] + mesh.GetPoint(v[1])[k] + mesh.GetPoint(v[2])[k]) / 3.0;
      n[k] = -mesh.GetNormal(t)[k];
    }
    vtkMedialSampleRecord ball;
    vtkMedialSolveBall(query, mesh, param, t, p, ball, hint);
    Measure& m = measures[c];
    m.Ray = RayLength(query, mesh, p, n, t);
    const vtkIdType next = Keep(ball, hint, m.Radius, m.Centre);
    m.TangentRadius = m.Radius;
    // The grown ball starts along the smooth surface's normal at the centroid: a
    // facet's own normal may be tilted by far more than a vertex's (a contour's sliver),
    // and its ball then stops early on the same wall, or is shrunk. (A ball whose
    // contacts are opposed spans a wall already.)
    vtkMedialSampleRecord start = ball;
    if (smooth && ball.Valid && (ball.Shrunk || ball.Angle < WallAngle))
    {
      vtkMedialSolveBall(query, mesh, *smooth, t, p, start, next);
    }
    const std::vector<vtkIdType> faces{ t };
    if (walls.MayGrow(faces, start))
    {
      const double size = std::max({ walls.Size[v[0]], walls.Size[v[1]], walls.Size[v[2]] });
      vtkMedialGrowthLimits limits = GrowthLimits(this->SurfaceTolerance, size);
      limits.MaySlide = [&](const vtkIdType* touched, int count, const double* centre, double radius) {
        return walls.MaySlide(faces, touched, count, centre, radius);
      };
      limits.Across = [&](const vtkIdType* touched, int count, vtkIdType other) {
        return walls.Across(faces, touched, count, other);
      };
      vtkMedialGrowBall(query, p, limits, &t, 1, start, nullptr, nullptr, nullptr, &points);
    }
    if (start.Valid && start.Radius > m.Radius)
    {
      m.Radius = start.Radius;
      std::copy(start.Centre, start.Centre + 3, m.Centre);
    }
    // A corner's ball that comes as near the centroid as to its own vertex (or within the
    // tolerance) is admissible here too: where the cell's own ascent stops early (sliding
    // off a crease along a curved wall), the cell does not read thinner than its corners.
    const double size = std::max({ walls.Size[v[0]], walls.Size[v[1]], walls.Size[v[2]] });
    // The corner's balls by the plain ascent, without the robust rules and without the
    // thorough ones too: where the corner's own ball slid farther from the cell, those
    // may still be admissible here.
    // Each corner's four balls, in this order: its own, the plain, the kept, the prior;
    // the corners in turn within each kind.
    using Ball = std::pair<double Measure::*, double (Measure::*)[3]>;
    static constexpr Ball Kinds[4] = { { &Measure::Radius, &Measure::Centre },
      { &Measure::PlainRadius, &Measure::PlainCentre }, { &Measure::KeptRadius, &Measure::KeptCentre },
      { &Measure::PriorRadius, &Measure::PriorCentre } };
    for (const Ball& kind : Kinds)
    {
      for (int k = 0; k < 3; ++k)
      {
        const Measure& corner = corners[v[k]];
        const double radius = corner.*kind.first;
        const double* centre = corner.*kind.second;
        if (!(radius > m.Radius))
        {
          continue;
        }
        const double toVertex = std::sqrt(G::Distance2(centre, mesh.GetPoint(v[k]))) - radius;
        const double toCentroid = std::sqrt(G::Distance2(centre, p)) - radius;
        if (toCentroid <= std::max(toVertex, this->SurfaceTolerance * size))
        {
          m.Radius = radius;
          std::copy(centre, centre + 3, m.Centre);
        }
      }
    }
    return next;
  };
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  return SolveInLeafOrder(this, query, items, threads, solve);
}

void vtkMedialThickness::ThinRegions(const vtkMedialTriangleMesh& mesh,
  const std::vector<vtkIdType>& start, const std::vector<vtkIdType>& around,
  const std::vector<Measure>& cells)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  auto thin = [&](vtkIdType t) {
    return 2.0 * cells[mesh.SourceCellIds[t]].Radius < this->ThinThreshold; // NaN: not thin
  };
  double thinArea = 0.0;
  std::vector<vtkIdType> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](vtkIdType t) {
    while (parent[t] != t)
    {
      t = parent[t] = parent[parent[t]];
    }
    return t;
  };
  for (vtkIdType t = 0; t < nt; ++t)
  {
    thinArea += thin(t) ? mesh.Areas[t] : 0.0;
  }
  // Thin triangles around one vertex belong to one region.
  for (vtkIdType v = 0; v + 1 < static_cast<vtkIdType>(start.size()); ++v)
  {
    vtkIdType first = -1;
    for (vtkIdType i = start[v]; i < start[v + 1]; ++i)
    {
      if (thin(around[i]))
      {
        if (first < 0)
        {
          first = root(around[i]);
        }
        else
        {
          parent[root(around[i])] = first;
        }
      }
    }
  }
  this->ThinRegionCount = 0;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    this->ThinRegionCount += thin(t) && root(t) == t ? 1 : 0;
  }
  this->ThinAreaFraction = mesh.TotalArea > 0.0 ? thinArea / mesh.TotalArea : 0.0;
}

void vtkMedialThickness::WriteArrays(vtkPolyData* output, const vtkMedialTriangleMesh& mesh,
  const std::vector<Measure>& vertices, const std::vector<Measure>& cells)
{
  // Input point -> prepared vertex: the same coordinates, since the preparation merges
  // exactly coincident points only.
  std::vector<vtkIdType> sorted(mesh.GetNumberOfPoints());
  std::iota(sorted.begin(), sorted.end(), 0);
  std::sort(sorted.begin(), sorted.end(),
    [&](vtkIdType a, vtkIdType b) { return Key(mesh.GetPoint(a)) < Key(mesh.GetPoint(b)); });
  auto write = [](vtkDataSetAttributes* data, const std::vector<Measure>& measures,
                 const std::vector<vtkIdType>& source) {
    const vtkIdType n = static_cast<vtkIdType>(source.size());
    auto make = [&](const char* name, int components) {
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      a->SetNumberOfComponents(components);
      a->SetNumberOfTuples(n);
      data->AddArray(a);
      return a.GetPointer();
    };
    vtkDoubleArray* thickness = make(vtkMedialArrayNames::Thickness, 1);
    vtkDoubleArray* radius = make(vtkMedialArrayNames::MedialRadius, 1);
    vtkDoubleArray* centre = make(vtkMedialArrayNames::MedialCentre, 3);
    vtkDoubleArray* ray = make(vtkMedialArrayNames::RayThickness, 1);
    vtkDoubleArray* tangent = make(vtkMedialArrayNames::TangentThickness, 1);
    const Measure missing{};
    vtkIdType withoutValue = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const Measure& m = source[i] >= 0 ? measures[source[i]] : missing;
      thickness->SetValue(i, 2.0 * m.Radius);
      radius->SetValue(i, m.Radius);
      centre->SetTypedTuple(i, m.Centre);
      ray->SetValue(i, m.Ray);
      tangent->SetValue(i, 2.0 * m.TangentRadius);
      withoutValue += std::isnan(m.Radius) ? 1 : 0;
    }
    data->SetActiveScalars(vtkMedialArrayNames::Thickness);
    return withoutValue;
  };
  std::vector<vtkIdType> vertexOf(output->GetNumberOfPoints(), -1);
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double x[3];
    output->GetPoint(i, x);
    const auto key = Key(x);
    auto it = std::lower_bound(sorted.begin(), sorted.end(), key,
      [&](vtkIdType a, const std::array<double, 3>& k) { return Key(mesh.GetPoint(a)) < k; });
    if (it != sorted.end() && Key(mesh.GetPoint(*it)) == key)
    {
      vertexOf[i] = *it;
    }
  }
  this->MissingPoints = write(output->GetPointData(), vertices, vertexOf);
  if (this->ComputeCellThickness)
  {
    std::vector<vtkIdType> cellOf(cells.size());
    std::iota(cellOf.begin(), cellOf.end(), 0);
    write(output->GetCellData(), cells, cellOf);
  }
}

int vtkMedialThickness::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->SharpVertices = 0;
  this->MissingPoints = 0;
  this->ThinAreaFraction = 0.0;
  this->ThinRegionCount = 0;
  this->SurfaceRepaired = false;
  if (!input)
  {
    vtkErrorMacro(<< "No input.");
    return 0;
  }
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 measures the whole surface
  }

  // Pass 1: the solid and its queries (the sampler's preparation).
  auto aborted = [this]() { return (this->GetAbortExecute() != 0); };
  const bool cellData = this->ComputeCellThickness || this->ThinThreshold > 0.0;
  vtkMedialStages stages(this);
  stages.Begin("Preparing the surface", 0.0, 0.05);
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  // The surface checked and repaired as RepairMode says; from here on `input` is the
  // surface measured (and written out): the repaired one when it was repaired.
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  vtkMedialSolidPreparation preparation;
  if (!preparation.Prepare(input, this->RepairMode, vtkMedialMakeRepairer(this->Repair, threads), threads, mesh,
        query, error, aborted, [&](int s) {
          switch (s)
          {
            case vtkMedialSolidPreparation::MESH:
              stages.Begin("Preparing the surface", 0.0, 0.05);
              break;
            case vtkMedialSolidPreparation::QUERIES:
              stages.Begin("Building the surface queries", 0.05, 0.1);
              break;
            default:
              stages.Begin("Repairing the surface", 0.0, 0.05);
              break;
          }
        }))
  {
    if (aborted())
    {
      return 1;
    }
    vtkErrorMacro(<< "Cannot measure the thickness: " << error << ".");
    return 0;
  }
  input = preparation.GetSurface();
  this->SurfaceRepaired = preparation.GetRepaired();
  for (const std::string& warning : preparation.GetMessages())
  {
    vtkWarningMacro(<< warning);
  }

  const vtkMedialBallParameters param = vtkMedialMakeBallParameters(vtkMedialBallParameters::ONE_PASS,
    1e-6, this->MinimumSeparationAngle, this->MaximumProtrusion, 100, mesh.Diagonal);

  // Passes 2 to 4.
  stages.Begin("Measuring the thickness at the vertices", 0.1, cellData ? 0.65 : 1.0);
  std::vector<vtkIdType> start, around;
  mesh.TrianglesAroundPoints(start, around);
  std::vector<double> normals;
  std::vector<char> sharp;
  this->VertexNormals(mesh, start, around, normals, sharp);
  Walls walls;
  walls.Build(mesh, this->CreaseAngle, start, around);
  std::vector<Measure> vertices, cells;
  if (!this->VertexBalls(mesh, query, param, walls, start, around, normals, sharp, vertices))
  {
    return 1; // aborted: leave the output empty
  }
  if (cellData)
  {
    stages.Begin("Measuring the thickness at the cells", 0.65, 1.0);
    if (!this->CellBalls(mesh, query, param, walls, input->GetNumberOfCells(), vertices, cells))
    {
      return 1;
    }
  }

  output->ShallowCopy(input);
  this->WriteArrays(output, mesh, vertices, cells);
  if (vtkFieldData* report = preparation.GetReport())
  {
    for (int i = 0; i < report->GetNumberOfArrays(); ++i)
    {
      output->GetFieldData()->AddArray(report->GetAbstractArray(i));
    }
  }
  if (this->ThinThreshold > 0.0)
  {
    // Pass 5.
    this->ThinRegions(mesh, start, around, cells);
    for (const auto& field : { std::make_pair(vtkMedialArrayNames::ThinAreaFraction, this->ThinAreaFraction),
           std::make_pair(vtkMedialArrayNames::ThinRegionCount, static_cast<double>(this->ThinRegionCount)) })
    {
      vtkNew<vtkDoubleArray> a;
      a->SetName(field.first);
      a->InsertNextValue(field.second);
      output->GetFieldData()->AddArray(a);
    }
  }
  if (mesh.BoundaryEdges > 0)
  {
    vtkWarningMacro(<< "Input surface is open (" << mesh.BoundaryEdges << " boundary edges): "
                    << this->MissingPoints << " of " << input->GetNumberOfPoints()
                    << " points have no thickness (NaN): their ray escaped through a hole.");
  }
  else if (this->MissingPoints > 0)
  {
    vtkWarningMacro(<< this->MissingPoints << " of " << input->GetNumberOfPoints()
                    << " points have no thickness (NaN): no cell uses them, or their ray met the "
                       "surface from outside.");
  }
  return 1;
}

void vtkMedialThickness::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RepairMode: " << vtkMedialRepairFilter::GetModeName(this->RepairMode) << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "MinimumSeparationAngle: " << this->MinimumSeparationAngle << "\n";
  os << indent << "MaximumProtrusion: " << this->MaximumProtrusion << "\n";
  os << indent << "SurfaceTolerance: " << this->SurfaceTolerance << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "ComputeCellThickness: " << this->ComputeCellThickness << "\n";
  os << indent << "ThinThreshold: " << this->ThinThreshold << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "SharpVertices: " << this->SharpVertices << "\n";
  os << indent << "MissingPoints: " << this->MissingPoints << "\n";
  os << indent << "ThinAreaFraction: " << this->ThinAreaFraction << "\n";
  os << indent << "ThinRegionCount: " << this->ThinRegionCount << "\n";
}
