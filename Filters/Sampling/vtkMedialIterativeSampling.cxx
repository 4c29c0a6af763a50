// SPDX-License-Identifier: BSD-3-Clause
// The iterative sampling strategies and the coverage measure; see the header for the
// algorithms. Everything here runs on the calling thread except the ball solves.
#include "vtkMedialIterativeSampling.h"

#include "vtkMedialBallSolver.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"
#include "vtkMedialUniformGrid.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <queue>
#include <unordered_set>

namespace
{
namespace G = vtkMedialGeometry;

// Distinct random streams for the seeds' darts and the face samples, so that they
// never repeat the Random strategy's stream (seed, i).
constexpr std::uint64_t DartStream = 0x5EEDDA27C0FFEE01ull;
constexpr std::uint64_t FaceStream = 0xFACE5A3B1E0D0C02ull;

double Distance(const double a[3], const double b[3])
{
  double d[3];
  G::Sub(a, b, d);
  return std::sqrt(G::Dot(d, d));
}

// Exact-bits set of surface points: no two samples may share one.
struct PointKeyHash
{
  size_t operator()(const std::array<std::uint64_t, 3>& k) const
  {
    std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
    h ^= k[1] + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
    h ^= k[2] + 0x85157AF5ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};
class SurfacePointSet
{
public:
  /// False when p was already in the set.
  bool Insert(const double p[3])
  {
    std::array<std::uint64_t, 3> key;
    std::memcpy(key.data(), p, sizeof(double) * 3);
    return this->Keys.insert(key).second;
  }

private:
  std::unordered_set<std::array<std::uint64_t, 3>, PointKeyHash> Keys;
};

// Solves the balls of one round in parallel, each into its own slot.
void SolveRound(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const vtkMedialIterativeSettings& s, const std::vector<vtkIdType>& triangles,
  const std::vector<double>& points, std::vector<vtkMedialSampleRecord>& out)
{
  const vtkIdType n = static_cast<vtkIdType>(triangles.size());
  out.resize(triangles.size());
#pragma omp parallel for num_threads(s.Threads) schedule(dynamic, 1)
  for (vtkIdType i = 0; i < n; ++i)
  {
    vtkMedialSolveBall(query, mesh, s.Ball, triangles[i], &points[3 * i], out[i]);
  }
}

// Poisson-disk seeds by dart throwing (see the header); returns their surface points.
void ThrowDarts(const vtkMedialTriangleMesh& mesh, const vtkMedialIterativeSettings& s,
  vtkIdType wanted, std::vector<vtkIdType>& triangles, std::vector<double>& points)
{
  triangles.clear();
  points.clear();
  if (wanted <= 0 || mesh.TotalArea <= 0.0)
  {
    return;
  }
  const double rho = std::sqrt(0.6 * mesh.TotalArea / static_cast<double>(wanted));
  // Accepted seeds by cell; a dart is tested against those in the cells within rho.
  vtkMedialUniformGrid accepted;
  accepted.InitializeCubic(mesh.Bounds, vtkMedialUniformGrid::CubicCellSize(mesh.Bounds, rho));
  const vtkIdType maximumDarts = 30 * wanted;
  for (vtkIdType dart = 0; dart < maximumDarts && static_cast<vtkIdType>(triangles.size()) < wanted; ++dart)
  {
    vtkIdType t;
    double p[3];
    vtkMedialDrawSurfacePoint(mesh, s.Seed ^ DartStream, dart, t, p);
    int lo[3], hi[3];
    accepted.CellBox(p, rho, lo, hi);
    const bool taken =
      accepted.AnyItemInBox(lo, hi, [&](vtkIdType other) { return Distance(p, &points[3 * other]) < rho; });
    if (!taken)
    {
      accepted.Insert(static_cast<vtkIdType>(triangles.size()), accepted.CellOf(p));
      triangles.push_back(t);
      points.insert(points.end(), p, p + 3);
    }
  }
}
}

//------------------------------------------------------------------------------
struct vtkMedialCoverage::Internals
{
  const vtkMedialTriangleMesh* Mesh = nullptr;
  vtkIdType NumberOfVertices = 0;
  std::vector<double> Points;      // vertices, then one centroid per face
  std::vector<char> Used;          // vertices referenced by a face; centroids always
  std::vector<double> Gap;         // per point
  std::vector<vtkIdType> FaceStart; // vertex -> faces (CSR)
  std::vector<vtkIdType> FaceList;
  std::vector<unsigned> Stamp; // per face, dedupes `touched`
  unsigned CurrentStamp = 0;
  vtkMedialUniformGrid Grid;
  double Bound = HUGE_VAL; // upper bound of every gap

  template <class F>
  void ForEachFaceOf(vtkIdType point, F&& f) const
  {
    if (point >= this->NumberOfVertices)
    {
      f(point - this->NumberOfVertices);
      return;
    }
    for (vtkIdType s = this->FaceStart[point]; s < this->FaceStart[point + 1]; ++s)
    {
      f(this->FaceList[s]);
    }
  }
};

vtkMedialCoverage::vtkMedialCoverage(const vtkMedialTriangleMesh& mesh)
  : Impl(new Internals)
{
  Internals& m = *this->Impl;
  m.Mesh = &mesh;
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Points.size() / 3);
  const vtkIdType nf = mesh.GetNumberOfTriangles();
  m.NumberOfVertices = nv;
  m.Points.resize(3 * static_cast<size_t>(nv + nf));
  std::copy(mesh.Points.begin(), mesh.Points.end(), m.Points.begin());
  m.Used.assign(static_cast<size_t>(nv + nf), 0);
  m.FaceStart.assign(static_cast<size_t>(nv + 1), 0);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const vtkIdType* t = mesh.GetTriangle(f);
    double* c = &m.Points[3 * static_cast<size_t>(nv + f)];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = (mesh.GetPoint(t[0])[k] + mesh.GetPoint(t[1])[k] + mesh.GetPoint(t[2])[k]) / 3.0;
      m.Used[t[k]] = 1;
      ++m.FaceStart[t[k] + 1];
    }
    m.Used[nv + f] = 1;
  }
  for (vtkIdType v = 0; v < nv; ++v)
  {
    m.FaceStart[v + 1] += m.FaceStart[v];
  }
  m.FaceList.resize(static_cast<size_t>(m.FaceStart[nv]));
  std::vector<vtkIdType> fill(m.FaceStart.begin(), m.FaceStart.end() - 1);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      m.FaceList[fill[mesh.GetTriangle(f)[k]]++] = f;
    }
  }
  // Unreferenced vertices never count: their gap stays at -infinity.
  m.Gap.assign(m.Used.size(), HUGE_VAL);
  vtkIdType used = 0;
  for (size_t i = 0; i < m.Used.size(); ++i)
  {
    used += m.Used[i] ? 1 : 0;
    if (!m.Used[i])
    {
      m.Gap[i] = -HUGE_VAL;
    }
  }
  m.Stamp.assign(static_cast<size_t>(nf), 0);
  // About 8 points per occupied cell, at most 2^22 cells.
  const double size = std::max(
    std::sqrt(8.0 * std::max(mesh.TotalArea, 1e-300) / std::max<vtkIdType>(used, 1)), 1e-9 * mesh.Diagonal);
  m.Grid.InitializeCubic(mesh.Bounds, vtkMedialUniformGrid::CubicCellSize(mesh.Bounds, size));
  m.Grid.BuildPoints(m.Points, m.Used);
}

vtkMedialCoverage::~vtkMedialCoverage() = default;

void vtkMedialCoverage::Initialize(const std::vector<vtkMedialSampleRecord>& records)
{
  Internals& m = *this->Impl;
  std::vector<double> seeds;
  for (const vtkMedialSampleRecord& r : records)
  {
    if (r.Valid)
    {
      seeds.insert(seeds.end(), r.Surface, r.Surface + 3);
    }
  }
  const size_t n = seeds.size() / 3;
  if (n > 0)
  {
    // Start value: distance to a nearby seed's surface point (an upper bound of the gap).
    vtkMedialUniformGrid seedGrid;
    const double spacing = std::max(std::sqrt(m.Mesh->TotalArea / n), 1e-9 * m.Mesh->Diagonal);
    seedGrid.InitializeCubic(m.Mesh->Bounds, vtkMedialUniformGrid::CubicCellSize(m.Mesh->Bounds, spacing));
    seedGrid.BuildPoints(seeds, std::vector<char>());
    const vtkIdType count = static_cast<vtkIdType>(m.Points.size() / 3);
    for (vtkIdType i = 0; i < count; ++i)
    {
      if (!m.Used[i])
      {
        continue;
      }
      const double* x = &m.Points[3 * i];
      double best = HUGE_VAL;
      int centre[3];
      seedGrid.CellCoordinates(x, centre);
      for (int ring = 1; best == HUGE_VAL && ring <= seedGrid.GetMaximumDimension(); ring *= 2)
      {
        const int lo[3] = { centre[0] - ring, centre[1] - ring, centre[2] - ring };
        const int hi[3] = { centre[0] + ring, centre[1] + ring, centre[2] + ring };
        seedGrid.ForEachItemInBox(lo, hi, [&](vtkIdType s) { best = std::min(best, Distance(x, &seeds[3 * s])); });
      }
      m.Gap[i] = std::min(m.Gap[i], best);
    }
  }
  this->MaxGap();
  for (const vtkMedialSampleRecord& r : records)
  {
    if (r.Valid)
    {
      this->AddBall(r.Centre, r.Radius, nullptr);
    }
  }
}

void vtkMedialCoverage::AddBall(const double c[3], double r, std::vector<vtkIdType>* touched)
{
  Internals& m = *this->Impl;
  ++m.CurrentStamp;
  const double reach = r + std::min(m.Bound, 2.0 * m.Mesh->Diagonal);
  m.Grid.ForEachItemNear(c, reach, [&](vtkIdType i) {
    const double g = Distance(&m.Points[3 * i], c) - r;
    if (g < m.Gap[i])
    {
      m.Gap[i] = g;
      if (touched)
      {
        m.ForEachFaceOf(i, [&](vtkIdType f) {
          if (m.Stamp[f] != m.CurrentStamp)
          {
            m.Stamp[f] = m.CurrentStamp;
            touched->push_back(f);
          }
        });
      }
    }
  });
}

double vtkMedialCoverage::FaceGap(vtkIdType face) const
{
  const Internals& m = *this->Impl;
  const vtkIdType* t = m.Mesh->GetTriangle(face);
  return std::max(std::max(m.Gap[t[0]], m.Gap[t[1]]), std::max(m.Gap[t[2]], m.Gap[m.NumberOfVertices + face]));
}

void vtkMedialCoverage::WorstPoint(vtkIdType face, double x[3]) const
{
  const Internals& m = *this->Impl;
  const vtkIdType* t = m.Mesh->GetTriangle(face);
  vtkIdType best = m.NumberOfVertices + face;
  for (int k = 0; k < 3; ++k)
  {
    if (m.Gap[t[k]] > m.Gap[best])
    {
      best = t[k];
    }
  }
  std::copy(&m.Points[3 * best], &m.Points[3 * best] + 3, x);
}

double vtkMedialCoverage::MaxGap()
{
  Internals& m = *this->Impl;
  double worst = -HUGE_VAL;
  for (double g : m.Gap)
  {
    worst = std::max(worst, g);
  }
  m.Bound = std::max(worst, 0.0);
  return worst;
}

vtkIdType vtkMedialCoverage::WorstFace() const
{
  vtkIdType worst = -1;
  double gap = -HUGE_VAL;
  const vtkIdType nf = this->Impl->Mesh->GetNumberOfTriangles();
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const double g = this->FaceGap(f);
    if (g > gap)
    {
      gap = g;
      worst = f;
    }
  }
  return worst;
}

//------------------------------------------------------------------------------
namespace
{
struct Segment
{
  vtkIdType A, B, Link;
  vtkIdType Child[2];
};
struct SegmentEntry
{
  double Length;
  vtkIdType Index;
  bool operator<(const SegmentEntry& o) const // max-heap on length; ties: older first
  {
    return this->Length < o.Length || (this->Length == o.Length && this->Index > o.Index);
  }
};

struct Runner
{
  const vtkMedialTriangleMesh& Mesh;
  const vtkMedialSurfaceQuery& Query;
  const vtkMedialIterativeSettings& S;
  const std::function<bool(double)>& Progress;
  vtkMedialIterativeResult& R;
  vtkMedialCoverage Coverage;
  SurfacePointSet Taken;

  Runner(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialIterativeSettings& s, const std::function<bool(double)>& progress,
    vtkMedialIterativeResult& r)
    : Mesh(mesh)
    , Query(query)
    , S(s)
    , Progress(progress)
    , R(r)
    , Coverage(mesh)
  {
  }

  vtkIdType Count() const { return static_cast<vtkIdType>(this->R.Records.size()); }

  // Checks coverage, reports progress; true when the run must stop.
  bool EndOfRound()
  {
    this->R.MaxGap = this->Coverage.MaxGap();
    this->R.CoverageReached = this->R.MaxGap <= this->S.CoverageTolerance;
    if (this->Progress(static_cast<double>(this->Count()) / static_cast<double>(this->S.Budget)))
    {
      this->R.Aborted = true;
      return true;
    }
    return this->S.CoverageTolerance > 0.0 && this->R.CoverageReached;
  }

  void Seed()
  {
    // SeedFraction of the budget, at most one per triangle (a coarse mesh is a simple shape).
    const vtkIdType wanted = std::min(std::min(this->S.Budget, this->Mesh.GetNumberOfTriangles()),
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::llround(this->S.SeedFraction * this->S.Budget))));
    std::vector<vtkIdType> triangles;
    std::vector<double> points;
    ThrowDarts(this->Mesh, this->S, wanted, triangles, points);
    SolveRound(this->Query, this->Mesh, this->S, triangles, points, this->R.Records);
    for (size_t i = 0; i < triangles.size(); ++i)
    {
      this->Taken.Insert(&points[3 * i]);
    }
    this->R.Seeds = this->Count();
    this->Coverage.Initialize(this->R.Records);
  }

  void FaceDistance();
  void ClosestNeighbor();

  // CLOSEST_NEIGHBOR's passes (see the header).
  bool ChainSeeds(std::vector<Segment>& segments);
  void SplitLinks(std::vector<Segment>& segments);
  bool LinkMidpoint(const Segment& link, double shortest, vtkIdType& triangle, double point[3]) const;
  void CollectLinks(const std::vector<Segment>& segments, vtkIdType initialLinks);
};

struct FaceEntry
{
  double Gap;
  vtkIdType Face;
  unsigned Version;
  bool operator<(const FaceEntry& o) const // max-heap on Gap; ties: smaller face first
  {
    return this->Gap < o.Gap || (this->Gap == o.Gap && this->Face > o.Face);
  }
};

void Runner::FaceDistance()
{
  const vtkIdType nf = this->Mesh.GetNumberOfTriangles();
  const double tol = this->S.CoverageTolerance;
  std::vector<unsigned> version(static_cast<size_t>(nf), 0);
  std::vector<int> attempts(static_cast<size_t>(nf), 0);
  std::vector<double> key(static_cast<size_t>(nf));
  std::vector<unsigned> round(static_cast<size_t>(nf), 0); // round in which the face was pushed last
  std::priority_queue<FaceEntry> heap;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    key[f] = this->Coverage.FaceGap(f);
    if (key[f] > tol)
    {
      heap.push({ key[f], f, 0 });
    }
  }
  auto push = [&](vtkIdType f) {
    ++version[f];
    if (key[f] > tol && attempts[f] < this->S.MaximumFaceAttempts)
    {
      heap.push({ key[f], f, version[f] });
    }
  };
  vtkIdType drawn = 0; // index of the face-sample stream
  unsigned roundIndex = 0;
  std::vector<vtkIdType> faces, triangles, touched;
  std::vector<double> points;
  std::vector<vtkMedialSampleRecord> solved;
  if (this->EndOfRound())
  {
    return;
  }
  while (this->Count() < this->S.Budget && !heap.empty())
  {
    ++roundIndex;
    faces.clear();
    triangles.clear();
    points.clear();
    const vtkIdType room = std::min<vtkIdType>(this->S.RoundSize, this->S.Budget - this->Count());
    while (static_cast<vtkIdType>(faces.size()) < room && !heap.empty())
    {
      const FaceEntry e = heap.top();
      heap.pop();
      if (e.Version != version[e.Face] || attempts[e.Face] >= this->S.MaximumFaceAttempts)
      {
        continue; // stale (the face's gap changed since), or given up
      }
      ++version[e.Face]; // consumed: no other live entry remains
      faces.push_back(e.Face);
      // A random point on the face, drawn toward its least covered point w.
      vtkMedialSampleRandom random(this->S.Seed ^ FaceStream, static_cast<std::uint64_t>(drawn++));
      const vtkIdType* t = this->Mesh.GetTriangle(e.Face);
      // Each failed attempt halves the neighbourhood of w that is sampled.
      const double s = std::sqrt(random.Uniform()), u = random.Uniform(),
                   pull = std::ldexp(random.Uniform(), -attempts[e.Face]);
      const double wa = 1.0 - s, wb = s * (1.0 - u), wc = s * u;
      double w[3], p[3];
      this->Coverage.WorstPoint(e.Face, w);
      for (int k = 0; k < 3; ++k)
      {
        const double q = wa * this->Mesh.GetPoint(t[0])[k] + wb * this->Mesh.GetPoint(t[1])[k] +
          wc * this->Mesh.GetPoint(t[2])[k];
        p[k] = w[k] + pull * (q - w[k]);
      }
      triangles.push_back(e.Face);
      points.insert(points.end(), p, p + 3);
    }
    SolveRound(this->Query, this->Mesh, this->S, triangles, points, solved);
    for (size_t j = 0; j < faces.size(); ++j)
    {
      const vtkIdType f = faces[j];
      const double before = key[f];
      if (this->Taken.Insert(&points[3 * j]))
      {
        this->R.Records.push_back(solved[j]);
        if (solved[j].Valid)
        {
          touched.clear();
          this->Coverage.AddBall(solved[j].Centre, solved[j].Radius, &touched);
          for (vtkIdType g : touched)
          {
            const double now = this->Coverage.FaceGap(g);
            if (now != key[g])
            {
              key[g] = now;
              round[g] = roundIndex;
              push(g);
            }
          }
        }
      }
      if (key[f] == before)
      {
        ++attempts[f]; // its own sample did not lower it: try again, up to the cap
        if (round[f] != roundIndex)
        {
          round[f] = roundIndex;
          push(f);
        }
      }
    }
    if (this->EndOfRound())
    {
      break;
    }
  }
  this->R.GivenUpFaces = 0;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    this->R.GivenUpFaces += key[f] > tol && attempts[f] >= this->S.MaximumFaceAttempts ? 1 : 0;
  }
}

bool Overlap(const vtkMedialSampleRecord& a, const vtkMedialSampleRecord& b)
{
  return Distance(a.Centre, b.Centre) <= a.Radius + b.Radius;
}

// The seeds' ball centres in a uniform grid, for the closest unlinked,
// non-overlapping neighbour of step 1; linked seeds are removed as they go.
class CentreGrid
{
public:
  CentreGrid(const std::vector<vtkMedialSampleRecord>& rec, vtkIdType n)
    : Rec(rec)
  {
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    vtkIdType valid = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (rec[i].Valid)
      {
        ++valid;
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], rec[i].Centre[k]);
          hi[k] = std::max(hi[k], rec[i].Centre[k]);
        }
      }
    }
    if (valid == 0)
    {
      return;
    }
    // About one seed per cell along the diagonal's scale: cbrt(n) cells on the longest axis.
    const double extent = std::max(hi[0] - lo[0], std::max(hi[1] - lo[1], hi[2] - lo[2]));
    const int perAxis = std::max(1, std::min(256, static_cast<int>(std::cbrt(static_cast<double>(valid)))));
    this->Size = extent > 0.0 ? extent / perAxis : 1.0;
    const double size[3] = { this->Size, this->Size, this->Size };
    int dims[3];
    for (int k = 0; k < 3; ++k)
    {
      dims[k] = std::max(1, std::min(perAxis, static_cast<int>((hi[k] - lo[k]) / this->Size) + 1));
    }
    this->Grid.Initialize(lo, size, dims);
    this->Grid.Build(n, [&](vtkIdType i, auto&& add) {
      if (rec[i].Valid)
      {
        add(this->Grid.CellOf(rec[i].Centre));
      }
    });
    this->Empty = false;
  }

  void Remove(vtkIdType i) { this->Grid.Hide(i); }

  /// The closest remaining centre to p's whose ball does not overlap p's (smaller
  /// index on a tie), or -1. Searches rings of cells until no closer one can exist.
  vtkIdType Closest(vtkIdType p) const
  {
    if (this->Empty)
    {
      return -1;
    }
    const vtkMedialSampleRecord& a = this->Rec[p];
    int c[3];
    this->Grid.CellCoordinates(a.Centre, c);
    vtkIdType best = -1;
    double bestDistance = HUGE_VAL;
    auto visit = [&](vtkIdType q) {
      const double d = Distance(a.Centre, this->Rec[q].Centre);
      if (q != p && d > a.Radius + this->Rec[q].Radius && (d < bestDistance || (d == bestDistance && q < best)))
      {
        bestDistance = d;
        best = q;
      }
    };
    for (int ring = 0; ring <= this->Grid.GetMaximumDimension(); ++ring)
    {
      // Every point of ring `ring` is at least (ring - 1) cells away.
      if (best >= 0 && bestDistance < (ring - 1) * this->Size)
      {
        break;
      }
      this->Grid.ForEachCellInShell(c, ring, [&](const int*, vtkIdType cell) { this->Grid.ForEachItemInCell(cell, visit); });
    }
    return best;
  }

private:
  const std::vector<vtkMedialSampleRecord>& Rec;
  vtkMedialUniformGrid Grid;
  double Size = 1.0;
  bool Empty = true;
};

void Runner::ClosestNeighbor()
{
  std::vector<Segment> segments;
  if (!this->ChainSeeds(segments))
  {
    this->R.Aborted = true;
    return;
  }
  const vtkIdType initialLinks = static_cast<vtkIdType>(segments.size());
  this->SplitLinks(segments);
  this->CollectLinks(segments, initialLinks);
}

// Step 1: chains of closest, unlinked, non-overlapping seeds. False when aborted.
bool Runner::ChainSeeds(std::vector<Segment>& segments)
{
  const std::vector<vtkMedialSampleRecord>& rec = this->R.Records;
  const vtkIdType seeds = this->R.Seeds;
  std::vector<char> linked(static_cast<size_t>(seeds), 0), done(static_cast<size_t>(seeds), 0);
  vtkIdType current = -1, firstFree = 0;
  CentreGrid grid(rec, seeds);
  const double seedsDone = static_cast<double>(seeds) / static_cast<double>(this->S.Budget);
  for (vtkIdType step = 1;; ++step)
  {
    // Late chains may search far: keep the abort check alive.
    if (step % 256 == 0 && this->Progress(seedsDone))
    {
      return false;
    }
    if (current < 0)
    {
      while (firstFree < seeds && (!rec[firstFree].Valid || linked[firstFree] || done[firstFree]))
      {
        ++firstFree;
      }
      if (firstFree >= seeds)
      {
        return true;
      }
      current = firstFree;
    }
    done[current] = 1;
    const vtkIdType best = grid.Closest(current);
    if (best < 0)
    {
      current = -1; // the chain ends
      continue;
    }
    const vtkIdType link = static_cast<vtkIdType>(segments.size());
    segments.push_back({ current, best, link, { -1, -1 } });
    if (!linked[current])
    {
      grid.Remove(current); // a chain start; a continued chain's point left with its first link
    }
    grid.Remove(best);
    linked[current] = linked[best] = 1;
    current = best;
  }
}

// Steps 2 and 3: a max-heap of links by length; the longest links are split at the
// surface point between their ends, round by round.
void Runner::SplitLinks(std::vector<Segment>& segments)
{
  std::vector<vtkMedialSampleRecord>& rec = this->R.Records;
  std::priority_queue<SegmentEntry> heap;
  const double shortest = 1e-9 * this->Mesh.Diagonal;
  auto pushIfApart = [&](vtkIdType i) {
    const Segment& g = segments[i];
    if (!Overlap(rec[g.A], rec[g.B]) && Distance(rec[g.A].Surface, rec[g.B].Surface) > shortest)
    {
      heap.push({ Distance(rec[g.A].Centre, rec[g.B].Centre), i });
    }
  };
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(segments.size()); ++i)
  {
    pushIfApart(i);
  }

  std::vector<vtkIdType> popped, triangles;
  std::vector<double> points;
  std::vector<vtkMedialSampleRecord> solved;
  bool stop = this->EndOfRound();
  while (!stop && this->Count() < this->S.Budget && !heap.empty())
  {
    popped.clear();
    triangles.clear();
    points.clear();
    const vtkIdType room = std::min<vtkIdType>(this->S.RoundSize, this->S.Budget - this->Count());
    while (static_cast<vtkIdType>(popped.size()) < room && !heap.empty())
    {
      const vtkIdType i = heap.top().Index;
      heap.pop();
      vtkIdType triangle;
      double point[3];
      if (this->LinkMidpoint(segments[i], shortest, triangle, point))
      {
        popped.push_back(i);
        triangles.push_back(triangle);
        points.insert(points.end(), point, point + 3);
      }
    }
    SolveRound(this->Query, this->Mesh, this->S, triangles, points, solved);
    for (size_t j = 0; j < popped.size(); ++j)
    {
      if (!this->Taken.Insert(&points[3 * j]))
      {
        continue; // projects onto an existing sample: the link stays as it is
      }
      const vtkIdType m = this->Count();
      rec.push_back(solved[j]);
      if (!solved[j].Valid)
      {
        continue;
      }
      this->Coverage.AddBall(solved[j].Centre, solved[j].Radius, nullptr);
      const vtkIdType i = popped[j];
      const Segment parent = segments[i];
      const vtkIdType left = static_cast<vtkIdType>(segments.size());
      segments.push_back({ parent.A, m, parent.Link, { -1, -1 } });
      segments.push_back({ m, parent.B, parent.Link, { -1, -1 } });
      segments[i].Child[0] = left;
      segments[i].Child[1] = left + 1;
      pushIfApart(left);
      pushIfApart(left + 1);
    }
    stop = this->EndOfRound();
  }
}

// The surface point between a link's ends: the closest surface point to the midpoint
// of their surface points, moved off the triangle's edges. False when none is found.
bool Runner::LinkMidpoint(const Segment& link, double shortest, vtkIdType& triangle, double point[3]) const
{
  const std::vector<vtkMedialSampleRecord>& rec = this->R.Records;
  double mid[3];
  for (int k = 0; k < 3; ++k)
  {
    mid[k] = 0.5 * (rec[link.A].Surface[k] + rec[link.B].Surface[k]);
  }
  vtkMedialSurfaceQuery::ClosestHit hit;
  const double bound = Distance(mid, rec[link.A].Surface) * (1.0 + 1e-9) + shortest + this->Query.GetSlack();
  if (!this->Query.ClosestPoint(mid, bound, hit))
  {
    return false; // cannot happen on a surface through A; the link stays as it is
  }
  // Off the triangle's edges and vertices, where the closest point often lands:
  // the ray from a point exactly on an edge can graze the neighbouring face (the
  // BVH works in float). A shift of 1e-3 of the way to the centroid is far below
  // the sampling density.
  const vtkIdType* t = this->Mesh.GetTriangle(hit.Triangle);
  for (int k = 0; k < 3; ++k)
  {
    const double centroid =
      (this->Mesh.GetPoint(t[0])[k] + this->Mesh.GetPoint(t[1])[k] + this->Mesh.GetPoint(t[2])[k]) / 3.0;
    hit.Point[k] += 1e-3 * (centroid - hit.Point[k]);
  }
  triangle = hit.Triangle;
  std::copy(hit.Point, hit.Point + 3, point);
  return true;
}

// The final links: the leaves of each initial link's split tree, in path order.
void Runner::CollectLinks(const std::vector<Segment>& segments, vtkIdType initialLinks)
{
  std::vector<vtkIdType> stack;
  for (vtkIdType link = 0; link < initialLinks; ++link)
  {
    stack.assign(1, link);
    while (!stack.empty())
    {
      const vtkIdType i = stack.back();
      stack.pop_back();
      if (segments[i].Child[0] < 0)
      {
        this->R.LinkEnds.push_back(segments[i].A);
        this->R.LinkEnds.push_back(segments[i].B);
        this->R.InitialLink.push_back(link);
      }
      else
      {
        stack.push_back(segments[i].Child[1]);
        stack.push_back(segments[i].Child[0]);
      }
    }
  }
}
}

void vtkMedialRunIterativeSampling(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
  const vtkMedialIterativeSettings& settings, const std::function<bool(double)>& progress,
  vtkMedialIterativeResult& result)
{
  result = vtkMedialIterativeResult();
  if (settings.Budget <= 0 || mesh.GetNumberOfTriangles() == 0)
  {
    return;
  }
  Runner runner(mesh, query, settings, progress, result);
  runner.Seed();
  if (settings.Strategy == vtkMedialIterativeSettings::CLOSEST_NEIGHBOR)
  {
    runner.ClosestNeighbor();
    // Coverage asked for, links exhausted, budget left: finish with the faces.
    if (!result.Aborted && settings.CoverageTolerance > 0.0 && !result.CoverageReached &&
      runner.Count() < settings.Budget)
    {
      runner.FaceDistance();
    }
  }
  else
  {
    runner.FaceDistance();
  }
  if (!result.Aborted)
  {
    result.MaxGap = runner.Coverage.MaxGap();
    result.CoverageReached = result.MaxGap <= settings.CoverageTolerance;
    result.WorstFace = runner.Coverage.WorstFace();
    if (result.WorstFace >= 0)
    {
      runner.Coverage.WorstPoint(result.WorstFace, result.WorstPoint);
    }
  }
}
