// SPDX-License-Identifier: BSD-3-Clause
// The iterative sampling strategies and the coverage measure; see the header for the
// algorithms. The choices are made on the calling thread; the ball solves, the darts and
// the coverage's passes run in parallel.
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
#include <exception>
#include <numeric>
#include <queue>
#include <unordered_set>

namespace
{
namespace G = vtkMedialGeometry;

// Distinct random streams for the seeds' darts and the face samples, so that they
// never repeat the Random strategy's stream (seed, i).
constexpr std::uint64_t DartStream = 0x5EEDDA27C0FFEE01ull;
constexpr std::uint64_t FaceStream = 0xFACE5A3B1E0D0C02ull;

// Consecutive solves in leaf order on one thread, hinted with the previous one (as
// vtkMedialAxisSampler's Random strategy does).
constexpr vtkIdType HintChain = 32;

// CLOSEST_NEIGHBOR without a coverage stop ends with face-distance rounds for this
// fraction (1 / ClosingShare) more samples: its links leave holes where no chain
// passes, which the worst faces then close.
constexpr vtkIdType ClosingShare = 16;

// With a coverage stop the budget is only a cap: the run plans for this many samples
// (or the budget, if smaller) and doubles the plan whenever it is used up before the
// coverage is reached. Seeds and round sizes follow the plan, not the budget, so a
// budget of at least this many that is not reached changes nothing (a quarter of a
// generous cap spent on seeds took face-distance on horse.ply to 96,966 samples for a
// gap that 2,643 reach now).
constexpr vtkIdType CoveragePlanStart = 10000;
constexpr vtkIdType LargestPlan = vtkIdType(1) << 40;
// Seed layers in a row that may leave as many faces above the stop, and the largest
// gap within 1%, before the run gives up: on spot.obj, asked for the gap Random leaves
// at 20k samples, two such layers in a row came before the one that reached it (random
// seed 2), and the runs that cannot reach it stop after three.
constexpr int FruitlessLayerLimit = 3;
// With a coverage stop a face is given up after this many failed samples (at most
// MaximumFaceAttempts): a seed layer gives it as many again, and on the smooth, finely
// faceted shapes (capsule, torus, sphere) a face's own further samples were wasted
// (vtkMedialShapeSource's sphere: 31,498 to 56,877 samples to Random's 20k-sample gap
// with 8, 21,701 to 30,456 with 3).
constexpr int CoverageStopFaceAttempts = 3;

// A box as 6 doubles, low then high corner: EmptyBox holds nothing, AddToBox widens it to x.
void EmptyBox(double box[6])
{
  std::fill(box, box + 3, HUGE_VAL);
  std::fill(box + 3, box + 6, -HUGE_VAL);
}
void AddToBox(double box[6], const double x[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    box[axis] = std::min(box[axis], x[axis]);
    box[3 + axis] = std::max(box[3 + axis], x[axis]);
  }
}

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

// One round's samples, slot by slot: surface point and triangle, ball, and the
// coverage points the ball lowers (Runner::SolveRound fills them in parallel).
struct Round
{
  std::vector<vtkIdType> Triangles;
  std::vector<double> Points;
  std::vector<char> Used; // false: the slot got no sample
  std::vector<vtkMedialSampleRecord> Balls;
  std::vector<std::vector<vtkMedialCoverage::Lowering>> Lowered;

  void Resize(size_t n)
  {
    this->Triangles.resize(n);
    this->Points.resize(3 * n);
    this->Used.resize(n);
    this->Balls.resize(n);
    this->Lowered.resize(std::max(this->Lowered.size(), n)); // keeps the lists' storage
  }
};

// near[k] = 1 when the point (xs[k], ys[k], zs[k]) of gap gs[k] may come within its
// gap of the sphere (c, r): a square test with a margin, without branches so that it
// vectorises. True when any may.
bool MayBeLowered(const double* xs, const double* ys, const double* zs, const double* gs, vtkIdType n,
  const double c[3], double r, std::int64_t* near)
{
  const double cx = c[0], cy = c[1], cz = c[2];
  std::int64_t any = 0;
#pragma omp simd reduction(| : any)
  for (vtkIdType k = 0; k < n; ++k)
  {
    const double dx = xs[k] - cx, dy = ys[k] - cy, dz = zs[k] - cz;
    const double within = r + gs[k];
    near[k] = (within > 0.0 && dx * dx + dy * dy + dz * dz <= within * within * (1.0 + 1e-9)) ? 1 : 0;
    any |= near[k];
  }
  return any != 0;
}

// Poisson-disk seeds by dart throwing (see the header); returns their surface points.
// A later layer (`layer` > 0) throws its own darts, at the spacing of `spacingCount`
// seeds, and keeps away from the surface points in `existing` (3 per point); it
// accepts at most `wanted` new seeds.
void ThrowDarts(const vtkMedialTriangleMesh& mesh, const vtkMedialIterativeSettings& s,
  vtkIdType wanted, std::vector<vtkIdType>& triangles, std::vector<double>& points, unsigned layer = 0,
  vtkIdType spacingCount = 0, const std::vector<double>& existing = {})
{
  triangles.clear();
  points.assign(existing.begin(), existing.end());
  const vtkIdType kept = static_cast<vtkIdType>(existing.size() / 3);
  if (wanted <= 0 || mesh.TotalArea <= 0.0)
  {
    points.clear();
    return;
  }
  const double rho = std::sqrt(0.5 * mesh.TotalArea / static_cast<double>(std::max(wanted, spacingCount)));
  // Accepted seeds (and the points kept away from) by cell; a dart is tested against
  // those in the cells within rho.
  vtkMedialUniformGrid accepted;
  accepted.InitializeCubic(mesh.Bounds, vtkMedialUniformGrid::CubicCellSize(mesh.Bounds, 2.0 * rho));
  for (vtkIdType i = 0; i < kept; ++i)
  {
    accepted.Insert(i, accepted.CellOf(&points[3 * i]));
  }
  const vtkIdType maximumDarts = 30 * wanted;
  const std::uint64_t firstDart = static_cast<std::uint64_t>(layer) << 40;
  // Darts are drawn in parallel blocks, each from its own index of the stream, and
  // tested against the seeds accepted before the block; the survivors are tested
  // again in index order, so the seeds are those of one dart after another.
  constexpr vtkIdType Block = 8192;
  std::vector<vtkIdType> dartTriangles(Block);
  std::vector<double> darts(3 * Block);
  std::vector<char> survives(Block);
  auto taken = [&](const double p[3]) {
    int lo[3], hi[3];
    accepted.CellBox(p, rho, lo, hi);
    return accepted.AnyItemInBox(lo, hi, [&](vtkIdType other) { return Distance(p, &points[3 * other]) < rho; });
  };
  for (vtkIdType first = 0; first < maximumDarts && static_cast<vtkIdType>(triangles.size()) < wanted; first += Block)
  {
    const vtkIdType n = std::min(Block, maximumDarts - first);
#pragma omp parallel for num_threads(s.Threads) schedule(static)
    for (vtkIdType j = 0; j < n; ++j)
    {
      vtkMedialDrawSurfacePoint(mesh, s.Seed ^ DartStream, firstDart + first + j, dartTriangles[j], &darts[3 * j]);
      survives[j] = !taken(&darts[3 * j]);
    }
    for (vtkIdType j = 0; j < n && static_cast<vtkIdType>(triangles.size()) < wanted; ++j)
    {
      const double* p = &darts[3 * j];
      if (survives[j] && !taken(p))
      {
        accepted.Insert(kept + static_cast<vtkIdType>(triangles.size()), accepted.CellOf(p));
        triangles.push_back(dartTriangles[j]);
        points.insert(points.end(), p, p + 3);
      }
    }
  }
  points.erase(points.begin(), points.begin() + 3 * kept);
}
}

//------------------------------------------------------------------------------
struct vtkMedialCoverage::Internals
{
  const vtkMedialTriangleMesh* Mesh = nullptr;
  int Threads = 1;
  vtkIdType NumberOfVertices = 0;
  vtkMedialUniformGrid Grid; // over the used points; its item order is the slot order
  std::vector<vtkIdType> SlotOf;  // point (vertices, then one centroid per face) -> slot, -1 if unused
  std::vector<vtkIdType> PointOf; // slot -> point
  std::vector<double> X, Y, Z, Gap; // per slot
  std::vector<vtkIdType> Owner;     // per slot: the ball (record index) that set its gap, or -1
  std::vector<vtkIdType> CellOfSlot;
  std::vector<double> CellMax; // per cell: the largest gap of its points (-infinity if none)
  // Each cell's slots in blocks of up to BlockSize, compact (a Morton order within the
  // cell): FindLowered tests a block's box and largest gap before its points (a
  // ball lowers about 4 of the 1,700 points of the cells it reaches).
  static constexpr vtkIdType BlockSize = 8;
  std::vector<vtkIdType> CellBlock;  // per cell (and one more): its first block
  std::vector<vtkIdType> BlockFirst; // per block (and one more): its first slot
  std::vector<double> BlockBox;      // per block: x, y, z low, then x, y, z high
  std::vector<double> BlockMax;      // per block: an upper bound of its gaps
  // Per row of cells (fixed y and z): an upper bound of its cells' CellMax (gaps only
  // fall, so a bound from an earlier refresh stays valid), and its non-empty cells' x
  // (CSR): FindLowered skips whole rows, and the empty cells of the others (most of
  // a large ball's cells are empty).
  std::vector<double> RowMax;
  std::vector<vtkIdType> RowCellStart;
  std::vector<int> RowCells;
  double Bound = HUGE_VAL; // upper bound of every gap
  double Worst = -HUGE_VAL; // MaxGapInTeam's result
  std::vector<std::vector<vtkMedialCoverage::Lowering>> Pending; // AddBallsInTeam: one batch's lowerings
  static constexpr vtkIdType Batch = 1024; // AddBallsInTeam: bounds the memory of the lowerings waiting
  double Pad = 0.0;        // added to the search reach: cell binning and slab bounds may differ by an ulp

  double GapOf(vtkIdType point) const { return this->Gap[this->SlotOf[point]]; }

  // The *InTeam passes are orphaned worksharing loops: every thread of the enclosing
  // parallel region calls them (outside one, the calling thread does all the work).
  void UpdateAllCellMaxInTeam()
  {
    const vtkIdType cells = this->Grid.GetNumberOfCells();
#pragma omp for schedule(static, 4096)
    for (vtkIdType c = 0; c < cells; ++c)
    {
      this->UpdateCellMax(c);
    }
    this->UpdateAllRowMaxInTeam();
  }
  void UpdateAllRowMaxInTeam()
  {
    const vtkIdType rows = static_cast<vtkIdType>(this->RowMax.size());
    const vtkIdType rowLength = this->Grid.GetDimension(0);
#pragma omp for schedule(static, 1024)
    for (vtkIdType row = 0; row < rows; ++row)
    {
      double worst = -HUGE_VAL;
      for (vtkIdType k = this->RowCellStart[row]; k < this->RowCellStart[row + 1]; ++k)
      {
        worst = std::max(worst, this->CellMax[row * rowLength + this->RowCells[k]]);
      }
      this->RowMax[row] = worst;
    }
  }
  /// Largest gap; sets Bound and refreshes RowMax. Every thread gets the result.
  double MaxGapInTeam()
  {
    const vtkIdType slots = static_cast<vtkIdType>(this->Gap.size());
#pragma omp single
    this->Worst = -HUGE_VAL;
    double worst = -HUGE_VAL;
#pragma omp for schedule(static) nowait
    for (vtkIdType s = 0; s < slots; ++s)
    {
      worst = std::max(worst, this->Gap[s]);
    }
#pragma omp critical(vtkMedialCoverageMaxGap)
    this->Worst = std::max(this->Worst, worst);
#pragma omp barrier
#pragma omp single
    this->Bound = std::max(this->Worst, 0.0);
    this->UpdateAllRowMaxInTeam();
    return this->Worst;
  }
  void StartValuesInTeam(const std::vector<double>& balls, const vtkMedialUniformGrid& seedGrid);
  /// Lowers this thread's range of slots by lowered[j] for each j < n with ballOf(j) >= 0, in j order.
  template <class BallOf>
  void ApplyInTeam(const std::vector<std::vector<Lowering>>& lowered, vtkIdType n, BallOf&& ballOf)
  {
    const vtkIdType slots = static_cast<vtkIdType>(this->Gap.size());
    const int threads = omp_get_num_threads();
    const int thread = omp_get_thread_num();
    const vtkIdType lo = slots * thread / threads, hi = slots * (thread + 1) / threads;
    for (vtkIdType j = 0; j < n; ++j)
    {
      const vtkIdType ball = ballOf(j);
      if (ball < 0)
      {
        continue;
      }
      for (const Lowering& l : lowered[j])
      {
        if (l.Slot >= lo && l.Slot < hi && l.Gap < this->Gap[l.Slot])
        {
          this->Gap[l.Slot] = l.Gap;
          this->Owner[l.Slot] = ball;
        }
      }
    }
  }
  void AddBallsInTeam(const vtkMedialCoverage& coverage, const vtkMedialSampleRecord* records, vtkIdType count,
    vtkIdType firstBall);
  void UpdateCellMax(vtkIdType cell)
  {
    double worst = -HUGE_VAL;
    for (vtkIdType b = this->CellBlock[cell]; b < this->CellBlock[cell + 1]; ++b)
    {
      double block = -HUGE_VAL;
      for (vtkIdType s = this->BlockFirst[b]; s < this->BlockFirst[b + 1]; ++s)
      {
        block = std::max(block, this->Gap[s]);
      }
      this->BlockMax[b] = block;
      worst = std::max(worst, block);
    }
    this->CellMax[cell] = worst;
  }
  void BuildSlots(const std::vector<double>& points, const std::vector<char>& used);
  void OrderCellsInBlocks(const std::vector<double>& points);
  void BuildBlockBoxes();
  /// Appends the points of the block that the ball (c, r) lowers (FindLowered has
  /// tested the block's box).
  void FindLoweredInBlock(vtkIdType block, const double c[3], double r, std::vector<Lowering>& lowered) const;
};

// The grid over the used points, and the points' coordinates in its item order.
void vtkMedialCoverage::Internals::BuildSlots(const std::vector<double>& points, const std::vector<char>& used)
{
  const vtkMedialTriangleMesh& mesh = *this->Mesh;
  const vtkIdType count = static_cast<vtkIdType>(used.size());
  const vtkIdType nused = static_cast<vtkIdType>(std::count(used.begin(), used.end(), 1));
  // About 32 points per occupied cell, at most 2^22 cells: a ball's search then
  // visits few rows of cells, and the points of a row are one contiguous run.
  const double size =
    std::max(std::sqrt(32.0 * std::max(mesh.TotalArea, 1e-300) / std::max<vtkIdType>(nused, 1)), 1e-9 * mesh.Diagonal);
  this->Grid.InitializeCubic(mesh.Bounds, vtkMedialUniformGrid::CubicCellSize(mesh.Bounds, size));
  this->Grid.BuildPoints(points, used);
  const vtkIdType slots = this->Grid.ItemOffset(this->Grid.GetNumberOfCells());
  const vtkIdType* order = this->Grid.CellBegin(0);
  this->PointOf.assign(order, order + slots);
  this->OrderCellsInBlocks(points);
  this->SlotOf.assign(static_cast<size_t>(count), -1);
  this->X.resize(static_cast<size_t>(slots));
  this->Y.resize(static_cast<size_t>(slots));
  this->Z.resize(static_cast<size_t>(slots));
  for (vtkIdType s = 0; s < slots; ++s)
  {
    const vtkIdType p = this->PointOf[s];
    this->SlotOf[p] = s;
    this->X[s] = points[3 * p];
    this->Y[s] = points[3 * p + 1];
    this->Z[s] = points[3 * p + 2];
  }
  this->BuildBlockBoxes();
  this->Gap.assign(static_cast<size_t>(slots), HUGE_VAL);
  this->Owner.assign(static_cast<size_t>(slots), -1);
  const vtkIdType cells = this->Grid.GetNumberOfCells();
  this->CellMax.assign(static_cast<size_t>(cells), HUGE_VAL);
  this->CellOfSlot.resize(static_cast<size_t>(slots));
  for (vtkIdType c = 0; c < cells; ++c)
  {
    std::fill(this->CellOfSlot.begin() + this->Grid.ItemOffset(c), this->CellOfSlot.begin() + this->Grid.ItemOffset(c + 1), c);
  }
  this->Pad = 1e-9 * mesh.Diagonal;
  const int rowLength = this->Grid.GetDimension(0);
  const vtkIdType rows = cells / rowLength;
  this->RowMax.assign(static_cast<size_t>(rows), HUGE_VAL);
  this->RowCellStart.assign(static_cast<size_t>(rows + 1), 0);
  this->RowCells.clear();
  for (vtkIdType row = 0; row < rows; ++row)
  {
    for (int i = 0; i < rowLength; ++i)
    {
      if (!this->Grid.IsCellEmpty(row * rowLength + i))
      {
        this->RowCells.push_back(i);
      }
    }
    this->RowCellStart[row + 1] = static_cast<vtkIdType>(this->RowCells.size());
  }
}

// Sorts each cell's slots along a Morton curve of 8^3 sub-cells (ties: point id) and
// cuts them into blocks.
void vtkMedialCoverage::Internals::OrderCellsInBlocks(const std::vector<double>& points)
{
  const vtkIdType cells = this->Grid.GetNumberOfCells();
  std::vector<std::pair<std::uint32_t, vtkIdType>> keyed;
  this->CellBlock.resize(static_cast<size_t>(cells + 1));
  this->BlockFirst.clear();
  for (vtkIdType cell = 0; cell < cells; ++cell)
  {
    const vtkIdType first = this->Grid.ItemOffset(cell), end = this->Grid.ItemOffset(cell + 1);
    this->CellBlock[cell] = static_cast<vtkIdType>(this->BlockFirst.size());
    keyed.clear();
    for (vtkIdType s = first; s < end; ++s)
    {
      const double* x = &points[3 * this->PointOf[s]];
      int ijk[3];
      this->Grid.CellCoordinates(x, ijk);
      std::uint32_t key = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        const double local = 8.0 * (x[axis] - this->Grid.CellLow(axis, ijk[axis])) / this->Grid.GetCellSize(axis);
        const std::uint32_t q = static_cast<std::uint32_t>(std::min(7.0, std::max(0.0, local)));
        for (int bit = 0; bit < 3; ++bit)
        {
          key |= ((q >> bit) & 1u) << (3 * bit + axis);
        }
      }
      keyed.emplace_back(key, this->PointOf[s]);
    }
    std::sort(keyed.begin(), keyed.end());
    for (vtkIdType k = 0; k < end - first; ++k)
    {
      this->PointOf[first + k] = keyed[k].second;
    }
    for (vtkIdType s = first; s < end; s += BlockSize)
    {
      this->BlockFirst.push_back(s);
    }
  }
  this->CellBlock[cells] = static_cast<vtkIdType>(this->BlockFirst.size());
  this->BlockFirst.push_back(this->Grid.ItemOffset(cells));
}

void vtkMedialCoverage::Internals::BuildBlockBoxes()
{
  const vtkIdType blocks = static_cast<vtkIdType>(this->BlockFirst.size()) - 1;
  this->BlockBox.resize(static_cast<size_t>(6 * blocks));
  this->BlockMax.assign(static_cast<size_t>(blocks), HUGE_VAL);
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    double* box = &this->BlockBox[6 * b];
    EmptyBox(box);
    for (vtkIdType s = this->BlockFirst[b]; s < this->BlockFirst[b + 1]; ++s)
    {
      const double x[3] = { this->X[s], this->Y[s], this->Z[s] };
      AddToBox(box, x);
    }
  }
}

vtkMedialCoverage::vtkMedialCoverage(const vtkMedialTriangleMesh& mesh, int threads)
  : Impl(new Internals)
{
  Internals& m = *this->Impl;
  m.Mesh = &mesh;
  m.Threads = std::max(1, threads);
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Points.size() / 3);
  const vtkIdType nf = mesh.GetNumberOfTriangles();
  m.NumberOfVertices = nv;
  // Vertices referenced by a face, and every centroid; unreferenced vertices never count.
  std::vector<double> points(3 * static_cast<size_t>(nv + nf));
  std::copy(mesh.Points.begin(), mesh.Points.end(), points.begin());
  std::vector<char> used(static_cast<size_t>(nv + nf), 0);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const vtkIdType* t = mesh.GetTriangle(f);
    double* c = &points[3 * static_cast<size_t>(nv + f)];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = (mesh.GetPoint(t[0])[k] + mesh.GetPoint(t[1])[k] + mesh.GetPoint(t[2])[k]) / 3.0;
      used[t[k]] = 1;
    }
    used[nv + f] = 1;
  }
  m.BuildSlots(points, used);
}

vtkMedialCoverage::~vtkMedialCoverage() = default;

void vtkMedialCoverage::Initialize(
  const std::vector<vtkMedialSampleRecord>& records, const std::function<void()>& alongside)
{
  Internals& m = *this->Impl;
  std::vector<double> seeds, balls; // surface points; centres and radii
  for (const vtkMedialSampleRecord& r : records)
  {
    if (r.Valid)
    {
      seeds.insert(seeds.end(), r.Surface, r.Surface + 3);
      balls.insert(balls.end(), r.Centre, r.Centre + 3);
      balls.push_back(r.Radius);
    }
  }
  vtkMedialUniformGrid seedGrid;
  if (!seeds.empty())
  {
    const double spacing = std::max(std::sqrt(m.Mesh->TotalArea / (seeds.size() / 3)), 1e-9 * m.Mesh->Diagonal);
    seedGrid.InitializeCubic(m.Mesh->Bounds, vtkMedialUniformGrid::CubicCellSize(m.Mesh->Bounds, spacing));
    seedGrid.BuildPoints(seeds, std::vector<char>());
  }
  m.Pending.resize(std::max(m.Pending.size(), std::min<size_t>(Internals::Batch, records.size())));
  // One team: the calling thread first runs `alongside`, then joins the others, which
  // meanwhile take the dynamically scheduled start values.
  std::exception_ptr failure; // an exception must not leave the parallel region
#pragma omp parallel num_threads(m.Threads)
  {
    if (alongside && omp_get_thread_num() == 0)
    {
      try
      {
        alongside();
      }
      catch (...)
      {
        failure = std::current_exception();
      }
    }
    if (!seeds.empty())
    {
      m.StartValuesInTeam(balls, seedGrid);
    }
    m.UpdateAllCellMaxInTeam();
    m.MaxGapInTeam();
    m.AddBallsInTeam(*this, records.data(), static_cast<vtkIdType>(records.size()), 0);
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

// Start value: the gap to the balls of the seeds whose surface points are nearest (an
// upper bound of the gap to all balls, and a tight one: the seeds' balls then search
// few points).
void vtkMedialCoverage::Internals::StartValuesInTeam(
  const std::vector<double>& balls, const vtkMedialUniformGrid& seedGrid)
{
  const vtkIdType slots = static_cast<vtkIdType>(this->Gap.size());
#pragma omp for schedule(dynamic, 1024)
  for (vtkIdType s = 0; s < slots; ++s)
  {
    const double x[3] = { this->X[s], this->Y[s], this->Z[s] };
    double best = HUGE_VAL;
    int centre[3];
    seedGrid.CellCoordinates(x, centre);
    for (int ring = 1; best == HUGE_VAL && ring <= seedGrid.GetMaximumDimension(); ring *= 2)
    {
      const int lo[3] = { centre[0] - ring, centre[1] - ring, centre[2] - ring };
      const int hi[3] = { centre[0] + ring, centre[1] + ring, centre[2] + ring };
      seedGrid.ForEachItemInBox(
        lo, hi, [&](vtkIdType i) { best = std::min(best, Distance(x, &balls[4 * i]) - balls[4 * i + 3]); });
    }
    this->Gap[s] = std::min(this->Gap[s], best);
  }
}

void vtkMedialCoverage::FindLowered(const double c[3], double r, std::vector<Lowering>& lowered) const
{
  const Internals& m = *this->Impl;
  lowered.clear();
  const double reach = r + std::min(m.Bound, 2.0 * m.Mesh->Diagonal) + m.Pad;
  const double* cellMax = m.CellMax.data();
  const int rowLength = m.Grid.GetDimension(0);
  m.Grid.ForEachRowNear(c, reach, [&](int cy, int cz, int x0, int x1, double d2) {
    const vtkIdType row = m.Grid.CellId(0, cy, cz);
    // The row's bound first: most rows near a large ball are empty or covered.
    const vtkIdType rowIndex = row / rowLength;
    const double rowTop = r + m.RowMax[rowIndex] + m.Pad;
    if (!(rowTop > 0.0) || d2 > rowTop * rowTop)
    {
      return;
    }
    const double dx = std::sqrt(rowTop * rowTop - d2);
    const int first = std::max(x0, m.Grid.Coordinate(c[0] - dx, 0));
    const int last = std::min(x1, m.Grid.Coordinate(c[0] + dx, 0));
    const int* cells = m.RowCells.data();
    for (vtkIdType k = m.RowCellStart[rowIndex]; k < m.RowCellStart[rowIndex + 1] && cells[k] <= last; ++k)
    {
      const int i = cells[k];
      if (i < first)
      {
        continue;
      }
      // A point is lowered only within r + its gap of c: skip the cells too far for their largest gap.
      const double top = r + cellMax[row + i] + m.Pad;
      const double dx = m.Grid.SlabDistance(c[0], i, 0);
      if (!(top > 0.0) || dx * dx + d2 > top * top)
      {
        continue;
      }
      for (vtkIdType b = m.CellBlock[row + i]; b < m.CellBlock[row + i + 1]; ++b)
      {
        // The block's box first (here, not in the call: about 3 of 4 blocks stop here).
        const double blockTop = r + m.BlockMax[b] + m.Pad;
        const double* box = &m.BlockBox[6 * b];
        double b2 = 0.0;
        for (int axis = 0; axis < 3; ++axis)
        {
          const double d = std::max(std::max(box[axis] - c[axis], c[axis] - box[3 + axis]), 0.0);
          b2 += d * d;
        }
        if (blockTop > 0.0 && b2 <= blockTop * blockTop)
        {
          m.FindLoweredInBlock(b, c, r, lowered);
        }
      }
    }
  });
}

void vtkMedialCoverage::Internals::FindLoweredInBlock(
  vtkIdType block, const double c[3], double r, std::vector<Lowering>& lowered) const
{
  // A square test with a margin (branch-free), the exact gap only for the few that pass.
  const vtkIdType first = this->BlockFirst[block], n = this->BlockFirst[block + 1] - first;
  std::int64_t near[BlockSize];
  if (!MayBeLowered(&this->X[first], &this->Y[first], &this->Z[first], &this->Gap[first], n, c, r, near))
  {
    return;
  }
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType s = first + k;
    const double d[3] = { this->X[s] - c[0], this->Y[s] - c[1], this->Z[s] - c[2] };
    const double g = std::sqrt(G::Dot(d, d)) - r;
    if (near[k] && g < this->Gap[s])
    {
      lowered.push_back({ s, g });
    }
  }
}

void vtkMedialCoverage::Apply(const std::vector<Lowering>& lowered, vtkIdType ball)
{
  Internals& m = *this->Impl;
  vtkIdType changedCell = -1; // lowerings come in slot order, so mostly cell by cell
  for (const Lowering& l : lowered)
  {
    if (!(l.Gap < m.Gap[l.Slot]))
    {
      continue;
    }
    m.Gap[l.Slot] = l.Gap;
    m.Owner[l.Slot] = ball;
    if (m.CellOfSlot[l.Slot] != changedCell)
    {
      if (changedCell >= 0)
      {
        m.UpdateCellMax(changedCell);
      }
      changedCell = m.CellOfSlot[l.Slot];
    }
  }
  if (changedCell >= 0)
  {
    m.UpdateCellMax(changedCell);
  }
}

void vtkMedialCoverage::ApplyRound(
  const std::vector<std::vector<Lowering>>& lowered, const std::vector<vtkIdType>& balls)
{
  Internals& m = *this->Impl;
  const vtkIdType n = static_cast<vtkIdType>(balls.size());
  if (n < 32)
  {
    // A few balls (closest-neighbor's last rounds): waking the team would cost more.
    for (vtkIdType j = 0; j < n; ++j)
    {
      if (balls[j] >= 0)
      {
        this->Apply(lowered[j], balls[j]);
      }
    }
    return;
  }
#pragma omp parallel num_threads(m.Threads)
  {
    m.ApplyInTeam(lowered, n, [&](vtkIdType j) { return balls[j]; });
#pragma omp barrier
    m.UpdateAllCellMaxInTeam();
  }
}

void vtkMedialCoverage::AddBalls(const vtkMedialSampleRecord* records, vtkIdType count, vtkIdType firstBall)
{
  Internals& m = *this->Impl;
  m.Pending.resize(std::max(m.Pending.size(), static_cast<size_t>(std::min(Internals::Batch, count))));
#pragma omp parallel num_threads(m.Threads)
  m.AddBallsInTeam(*this, records, count, firstBall);
}

void vtkMedialCoverage::Internals::AddBallsInTeam(
  const vtkMedialCoverage& coverage, const vtkMedialSampleRecord* records, vtkIdType count, vtkIdType firstBall)
{
  std::vector<std::vector<Lowering>>& lowered = this->Pending;
  for (vtkIdType begin = 0; begin < count; begin += Batch)
  {
    const vtkIdType n = std::min(Batch, count - begin);
#pragma omp for schedule(dynamic, 4)
    for (vtkIdType j = 0; j < n; ++j)
    {
      const vtkMedialSampleRecord& r = records[begin + j];
      lowered[j].clear();
      if (r.Valid)
      {
        coverage.FindLowered(r.Centre, r.Radius, lowered[j]);
      }
    }
    // Each thread applies the lowerings of its own range of slots, in ball order.
    this->ApplyInTeam(lowered, n, [&](vtkIdType j) { return firstBall + begin + j; });
#pragma omp barrier
  }
  this->UpdateAllCellMaxInTeam();
}

double vtkMedialCoverage::FaceGap(vtkIdType face) const
{
  const Internals& m = *this->Impl;
  const vtkIdType* t = m.Mesh->GetTriangle(face);
  return std::max(std::max(m.GapOf(t[0]), m.GapOf(t[1])), std::max(m.GapOf(t[2]), m.GapOf(m.NumberOfVertices + face)));
}

vtkIdType vtkMedialCoverage::WorstPoint(vtkIdType face, double x[3]) const
{
  const Internals& m = *this->Impl;
  const vtkIdType* t = m.Mesh->GetTriangle(face);
  vtkIdType best = m.SlotOf[m.NumberOfVertices + face];
  for (int k = 0; k < 3; ++k)
  {
    const vtkIdType s = m.SlotOf[t[k]];
    if (m.Gap[s] > m.Gap[best])
    {
      best = s;
    }
  }
  x[0] = m.X[best];
  x[1] = m.Y[best];
  x[2] = m.Z[best];
  return m.Owner[best];
}

double vtkMedialCoverage::MaxGap(bool parallel)
{
  Internals& m = *this->Impl;
#pragma omp parallel num_threads(m.Threads) if (parallel)
  m.MaxGapInTeam();
  return m.Worst;
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
  Round Current;
  vtkIdType CountAtLastRound = 0;    // EndOfRound: samples at the previous round's end
  vtkIdType CountAtLastRefresh = -1; // and at the maximum's last refresh (-1: never)
  std::vector<vtkIdType> SolveOrder, Near, Balls;
  std::vector<int> Attempts; // FACE_DISTANCE: per face, own samples that failed to lower it
  std::vector<double> FaceGaps; // FACE_DISTANCE: per face, its gap before the round
  std::vector<vtkIdType> Candidates;
  std::vector<unsigned> Picked; // FACE_DISTANCE: per vertex, the last round a face of it was picked
  vtkIdType Plan; // the samples the run plans for: the budget, or with a coverage stop see CoveragePlanStart
  std::vector<double> SeedPoints; // the seeds' surface points, every layer (3 per seed)
  unsigned SeedLayers = 0;   // layers after the first (AddSeedLayer)
  vtkIdType OpenFacesAtLastLayer = 0; // faces above the coverage stop when the last layer was added
  double GapAtLastLayer = HUGE_VAL;   // and the largest gap then
  int FruitlessLayers = 0;            // layers in a row after which neither fell
  const int FaceAttempts;             // vtkMedialFaceAttempts(S)

  Runner(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialIterativeSettings& s, const std::function<bool(double)>& progress,
    vtkMedialIterativeResult& r)
    : Mesh(mesh)
    , Query(query)
    , S(s)
    , Progress(progress)
    , R(r)
    , Coverage(mesh, s.Threads)
    , Plan(s.CoverageTolerance > 0.0 ? std::min(s.Budget, CoveragePlanStart) : s.Budget)
    , FaceAttempts(vtkMedialFaceAttempts(s))
  {
  }

  // With a coverage stop, doubles the plan until it exceeds the samples taken.
  void GrowPlan()
  {
    while (this->S.CoverageTolerance > 0.0 && this->Count() >= this->Plan && this->Plan < LargestPlan)
    {
      this->Plan *= 2;
    }
  }

  vtkIdType Count() const { return static_cast<vtkIdType>(this->R.Records.size()); }
  // CLOSEST_NEIGHBOR chooses nothing by the coverage: without a coverage stop, its
  // balls are added once, at the end, all in parallel.
  bool DeferCoverage() const
  {
    return this->S.Strategy == vtkMedialIterativeSettings::CLOSEST_NEIGHBOR && !(this->S.CoverageTolerance > 0.0);
  }
  vtkIdType RoundSize() const
  {
    return this->S.RoundSize > 0 ? this->S.RoundSize : std::max<vtkIdType>(64, this->Plan / 64);
  }

  // Checks coverage, reports progress; true when the run must stop. Without a
  // coverage stop the maximum (which also tightens the coverage's search bound) is
  // refreshed every 8 RoundSize samples only: it changes no choice then. A round of a
  // few samples (closest-neighbor's last ones) refreshes it on the calling thread:
  // waking the team, on a loaded machine, can cost more than the scan.
  bool EndOfRound()
  {
    const vtkIdType added = this->Count() - this->CountAtLastRound;
    this->CountAtLastRound = this->Count();
    if (!this->DeferCoverage() &&
      (this->S.CoverageTolerance > 0.0 || this->CountAtLastRefresh < 0 ||
        this->Count() - this->CountAtLastRefresh >= 8 * this->RoundSize()))
    {
      this->CountAtLastRefresh = this->Count();
      this->R.MaxGap = this->Coverage.MaxGap(added >= 32);
      this->R.CoverageReached = this->R.MaxGap <= this->S.CoverageTolerance;
    }
    if (this->Progress(static_cast<double>(this->Count()) / static_cast<double>(this->S.Budget)))
    {
      this->R.Aborted = true;
      return true;
    }
    return this->S.CoverageTolerance > 0.0 && this->R.CoverageReached;
  }

  void Seed()
  {
    // SeedFraction of the plan, at most one per triangle (a coarse mesh is a simple shape).
    const vtkIdType wanted = std::min(std::min(this->Plan, this->Mesh.GetNumberOfTriangles()),
      std::max<vtkIdType>(1, static_cast<vtkIdType>(std::llround(this->S.SeedFraction * this->Plan))));
    std::vector<vtkIdType> triangles;
    std::vector<double> points;
    ThrowDarts(this->Mesh, this->S, wanted, triangles, points);
    this->SolveSeeds(triangles, points, 0, static_cast<vtkIdType>(triangles.size()), false);
    this->R.Records.assign(this->Current.Balls.begin(), this->Current.Balls.end());
    for (size_t i = 0; i < triangles.size(); ++i)
    {
      this->Taken.Insert(&points[3 * i]);
    }
    this->R.Seeds = this->Count();
    this->SeedPoints = std::move(points);
  }

  // Solves seeds [first, first + count) of `triangles` and `points` (3 a seed) as a round.
  void SolveSeeds(const std::vector<vtkIdType>& triangles, const std::vector<double>& points, vtkIdType first,
    vtkIdType count, bool lowered)
  {
    this->Near.assign(triangles.begin() + first, triangles.begin() + first + count);
    this->SolveRound(count, lowered, this->Near, [&](vtkIdType j, vtkIdType& t, double p[3], vtkIdType&) {
      t = triangles[first + j];
      std::copy(&points[3 * (first + j)], &points[3 * (first + j)] + 3, p);
      return true;
    });
  }

  // The round's first n samples that are new surface points become records, in slot
  // order; balls[j] gets slot j's record index, or -1.
  void KeepRound(vtkIdType n, std::vector<vtkIdType>& balls)
  {
    balls.assign(static_cast<size_t>(n), -1);
    for (vtkIdType j = 0; j < n; ++j)
    {
      if (this->Taken.Insert(&this->Current.Points[3 * j]))
      {
        balls[j] = this->Count();
        this->R.Records.push_back(this->Current.Balls[j]);
      }
    }
  }

  // With a coverage stop, when every face still above it has been given up: the faces'
  // own samples cannot reach their worst points (where balls are shrunk to stay
  // inside, they no longer touch their own sample point), but balls from elsewhere may,
  // as a denser seeding showed. Doubles the plan, adds Poisson-disk seeds up to
  // SeedFraction of it (the darts keep the new, smaller spacing from every seed so
  // far), and gives the faces given up another FaceAttempts. False at the budget,
  // or after FruitlessLayerLimit layers in a row after which neither the faces above
  // the stop became fewer nor the largest gap 1% smaller (next to a hole, say, where no
  // ball can cover: seeds elsewhere still bring its gap down by a few parts in 1e5).
  // Reads FaceGaps, fresh from PickFaces, and the largest gap of the last EndOfRound.
  bool AddSeedLayer(vtkIdType budget)
  {
    if (!(this->S.CoverageTolerance > 0.0) || this->Count() >= budget)
    {
      return false;
    }
    const vtkIdType open = std::count_if(
      this->FaceGaps.begin(), this->FaceGaps.end(), [&](double gap) { return gap > this->S.CoverageTolerance; });
    const bool fruitless =
      this->SeedLayers > 0 && open >= this->OpenFacesAtLastLayer && !(this->R.MaxGap < 0.99 * this->GapAtLastLayer);
    this->FruitlessLayers = fruitless ? this->FruitlessLayers + 1 : 0;
    if (this->FruitlessLayers >= FruitlessLayerLimit)
    {
      return false;
    }
    this->OpenFacesAtLastLayer = open;
    this->GapAtLastLayer = this->R.MaxGap;
    this->Plan = std::min(LargestPlan, 2 * std::max(this->Plan, this->Count()));
    const vtkIdType spacing = std::max<vtkIdType>(1, std::llround(this->S.SeedFraction * this->Plan));
    const vtkIdType seeds = static_cast<vtkIdType>(this->SeedPoints.size() / 3);
    const vtkIdType wanted = std::min(budget - this->Count(), std::max<vtkIdType>(1, spacing - seeds));
    std::vector<vtkIdType> triangles;
    std::vector<double> points;
    ThrowDarts(this->Mesh, this->S, wanted, triangles, points, ++this->SeedLayers, spacing, this->SeedPoints);
    const vtkIdType n = static_cast<vtkIdType>(triangles.size());
    this->SeedPoints.insert(this->SeedPoints.end(), points.begin(), points.end());
    // In rounds of an eighth of the layer (at least RoundSize), in dart order, each
    // checked for the stop: a layer doubles the seeds, and the stop may come early in it.
    const vtkIdType round = std::max(this->RoundSize(), (n + 7) / 8);
    for (vtkIdType first = 0; first < n; first += round)
    {
      const vtkIdType count = std::min(round, n - first);
      this->SolveSeeds(triangles, points, first, count, true);
      this->KeepRound(count, this->Balls);
      this->Coverage.ApplyRound(this->Current.Lowered, this->Balls);
      if (this->EndOfRound())
      {
        return true; // covered, or aborted: FaceDistance reads which from R
      }
    }
    bool retried = false;
    for (int& attempts : this->Attempts)
    {
      retried = retried || attempts >= this->FaceAttempts;
      attempts = attempts >= this->FaceAttempts ? 0 : attempts;
    }
    return n > 0 || retried;
  }

  // Fills this->Current's n slots in parallel, in the order of near[j] (a triangle
  // near slot j, or -1) in the tree's leaves: prepare(j, triangle, point, hint) sets
  // slot j's sample and a neighbouring ball's contact triangle as the solver's hint
  // (false: no sample), then its ball is solved and, when `lowered`, the coverage
  // points the ball lowers are found (against the gaps before the round). As in the
  // Random strategy, runs of HintChain consecutive slots in that order go to one
  // thread, each solve after the first hinted with the previous one's contact and
  // blockers (the runs do not depend on the thread count).
  template <class Prepare>
  void SolveRound(vtkIdType n, bool lowered, const std::vector<vtkIdType>& near, Prepare&& prepare)
  {
    Round& round = this->Current;
    round.Resize(static_cast<size_t>(n));
    // Solved in the leaf order of a triangle near each slot, for the caches (the
    // slots are independent: the order changes nothing else).
    std::vector<vtkIdType>& order = this->SolveOrder;
    order.resize(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    const auto& rank = this->Query.GetLeafRanks();
    auto rankOf = [&](vtkIdType j) { return near[j] >= 0 ? rank[near[j]] : INT32_MAX; };
    std::sort(order.begin(), order.end(),
      [&](vtkIdType a, vtkIdType b) { return rankOf(a) < rankOf(b) || (rankOf(a) == rankOf(b) && a < b); });
    // A small round (closest-neighbor's last ones, when few links are left) runs on
    // the calling thread: waking the team would cost more than it saves.
    const vtkIdType chains = (n + HintChain - 1) / HintChain;
#pragma omp parallel for num_threads(this->S.Threads) schedule(dynamic, 1) if (n >= 32)
    for (vtkIdType g = 0; g < chains; ++g)
    {
      vtkMedialTriangleBVH::BlockerChain blockers; // the previous solve's
      vtkIdType previous = -1;                     // its contact triangle
      for (vtkIdType k = g * HintChain; k < std::min(n, (g + 1) * HintChain); ++k)
      {
        const vtkIdType j = order[k];
        double* p = &round.Points[3 * j];
        vtkIdType hint = -1;
        round.Used[j] = prepare(j, round.Triangles[j], p, hint);
        round.Lowered[j].clear();
        if (!round.Used[j])
        {
          continue;
        }
        vtkMedialSampleRecord& ball = round.Balls[j];
        vtkMedialSolveBall(this->Query, this->Mesh, this->S.Ball, round.Triangles[j], p, ball,
          previous >= 0 ? previous : hint, &blockers);
        previous = ball.Valid ? ball.ContactTriangle : -1;
        if (lowered && ball.Valid)
        {
          this->Coverage.FindLowered(ball.Centre, ball.Radius, round.Lowered[j]);
        }
      }
    }
  }

  void FaceDistance(vtkIdType budget);
  void PickFaces(vtkIdType room, unsigned roundIndex, std::vector<vtkIdType>& faces);
  void ClosestNeighbor();

  // CLOSEST_NEIGHBOR's passes (see the header).
  bool ChainSeeds(std::vector<Segment>& segments);
  void SplitLinks(std::vector<Segment>& segments);
  bool LinkMidpoint(const Segment& link, double shortest, vtkIdType& triangle, double point[3]) const;
  vtkIdType DrawFacePoint(vtkIdType face, vtkIdType draw, double point[3]) const;
  void CollectLinks(const std::vector<Segment>& segments, vtkIdType initialLinks);
};

// A random point on the face, drawn toward its least covered point w from the
// face-sample stream at index `draw`; each failed attempt halves the neighbourhood
// of w that is sampled. Returns the ball that covers w best (-1 if none).
vtkIdType Runner::DrawFacePoint(vtkIdType face, vtkIdType draw, double p[3]) const
{
  vtkMedialSampleRandom random(this->S.Seed ^ FaceStream, static_cast<std::uint64_t>(draw));
  const vtkIdType* t = this->Mesh.GetTriangle(face);
  const double s = std::sqrt(random.Uniform()), u = random.Uniform(),
               pull = std::ldexp(random.Uniform(), -this->Attempts[face]);
  const double wa = 1.0 - s, wb = s * (1.0 - u), wc = s * u;
  double w[3];
  const vtkIdType owner = this->Coverage.WorstPoint(face, w);
  for (int k = 0; k < 3; ++k)
  {
    const double q =
      wa * this->Mesh.GetPoint(t[0])[k] + wb * this->Mesh.GetPoint(t[1])[k] + wc * this->Mesh.GetPoint(t[2])[k];
    p[k] = w[k] + pull * (q - w[k]);
  }
  return owner;
}

// The worst faces, at most `room`, none sharing a vertex with another (one ball
// covers around its face: a neighbour waits for the next round, up to 4 room of
// them); faces within the tolerance or given up are not candidates.
void Runner::PickFaces(vtkIdType room, unsigned roundIndex, std::vector<vtkIdType>& faces)
{
  const vtkIdType nf = this->Mesh.GetNumberOfTriangles();
  std::vector<double>& gap = this->FaceGaps;
  std::vector<vtkIdType>& candidates = this->Candidates;
  gap.resize(static_cast<size_t>(nf));
  candidates.clear();
#pragma omp parallel num_threads(this->S.Threads)
  {
    std::vector<vtkIdType> mine;
#pragma omp for schedule(static) nowait
    for (vtkIdType f = 0; f < nf; ++f)
    {
      gap[f] = this->Coverage.FaceGap(f);
      if (gap[f] > this->S.CoverageTolerance && this->Attempts[f] < this->FaceAttempts)
      {
        mine.push_back(f);
      }
    }
#pragma omp critical(vtkMedialPickFaces)
    candidates.insert(candidates.end(), mine.begin(), mine.end());
  }
  // Worst first, lower face ids first among ties: the order does not depend on the
  // threads' merge order above.
  const auto worse = [&](vtkIdType a, vtkIdType b) { return gap[a] > gap[b] || (gap[a] == gap[b] && a < b); };
  const size_t keep = std::min(candidates.size(), static_cast<size_t>(5 * room));
  std::nth_element(candidates.begin(), candidates.begin() + keep, candidates.end(), worse);
  std::sort(candidates.begin(), candidates.begin() + keep, worse);
  faces.clear();
  vtkIdType deferred = 0;
  for (size_t k = 0; k < keep && static_cast<vtkIdType>(faces.size()) < room && deferred < 4 * room; ++k)
  {
    const vtkIdType f = candidates[k];
    const vtkIdType* t = this->Mesh.GetTriangle(f);
    if (this->Picked[t[0]] == roundIndex || this->Picked[t[1]] == roundIndex || this->Picked[t[2]] == roundIndex)
    {
      ++deferred;
      continue;
    }
    this->Picked[t[0]] = this->Picked[t[1]] = this->Picked[t[2]] = roundIndex;
    faces.push_back(f);
  }
}

void Runner::FaceDistance(vtkIdType budget)
{
  const vtkIdType nf = this->Mesh.GetNumberOfTriangles();
  const double tol = this->S.CoverageTolerance;
  this->Attempts.assign(static_cast<size_t>(nf), 0);
  this->Picked.assign(this->Mesh.Points.size() / 3, 0);
  vtkIdType drawn = 0; // index of the face-sample stream
  unsigned roundIndex = 0;
  std::vector<vtkIdType> faces, balls;
  std::vector<double> before;
  if (this->EndOfRound())
  {
    return;
  }
  while (this->Count() < budget)
  {
    // Half of what is left of the plan, at least RoundSize: the first rounds are large
    // (their samples lie close together, so the solves share caches and hints, and the
    // team wakes up less often), the last ones RoundSize, where the choice of the very
    // worst faces matters most.
    this->GrowPlan();
    const vtkIdType left = (this->S.CoverageTolerance > 0.0 ? this->Plan : budget) - this->Count();
    const vtkIdType room = std::min(
      std::min<vtkIdType>(std::max<vtkIdType>(this->RoundSize(), left / 2), left), budget - this->Count());
    this->PickFaces(room, ++roundIndex, faces);
    if (faces.empty())
    {
      // A layer ends with EndOfRound's check (its rounds each make one).
      if (this->AddSeedLayer(budget) && !this->R.Aborted && !this->R.CoverageReached)
      {
        continue;
      }
      break;
    }
    const vtkIdType firstDraw = drawn;
    drawn += static_cast<vtkIdType>(faces.size());
    this->SolveRound(static_cast<vtkIdType>(faces.size()), true, faces, [&](vtkIdType j, vtkIdType& t, double p[3], vtkIdType& hint) {
      t = faces[j];
      const vtkIdType owner = this->DrawFacePoint(t, firstDraw + j, p);
      hint = owner >= 0 ? this->R.Records[owner].ContactTriangle : -1;
      return true;
    });
    // The balls in sample order (numbered as they are kept), then their lowerings at once.
    this->KeepRound(static_cast<vtkIdType>(faces.size()), balls);
    before.resize(faces.size());
    for (size_t j = 0; j < faces.size(); ++j)
    {
      before[j] = this->FaceGaps[faces[j]];
    }
    this->Coverage.ApplyRound(this->Current.Lowered, balls);
    // A face whose gap the round left as it was counts a failed attempt.
    for (size_t j = 0; j < faces.size(); ++j)
    {
      if (this->Coverage.FaceGap(faces[j]) == before[j])
      {
        ++this->Attempts[faces[j]];
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
    this->R.GivenUpFaces += this->Attempts[f] >= this->FaceAttempts && this->Coverage.FaceGap(f) > tol ? 1 : 0;
  }
}

bool Overlap(const vtkMedialSampleRecord& a, const vtkMedialSampleRecord& b)
{
  return Distance(a.Centre, b.Centre) <= a.Radius + b.Radius;
}

// The seeds' ball centres in a uniform grid, for the closest unlinked,
// non-overlapping neighbour of step 1. Linked seeds leave their cell's list of
// remaining ones. Each cell keeps the box and the smallest radius of its seeds: a
// cell whose farthest point is within r_p + (its smallest radius) of c_p holds only
// balls that overlap p's, one whose nearest point is beyond the best so far holds no
// closer one; neither is read.
// The answer is the smallest (distance, index) over the seeds, whatever the grid.
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
    this->BuildCellLists(n);
    this->Empty = false;
  }

  /// Takes seed i out of its cell's remaining ones.
  void Remove(vtkIdType i)
  {
    const vtkIdType cell = this->CellOfItem[i];
    const vtkIdType last = this->Grid.ItemOffset(cell) + --this->Remaining[cell];
    const vtkIdType moved = this->Items[last];
    std::swap(this->Items[this->Position[i]], this->Items[last]);
    this->Position[moved] = this->Position[i];
    this->Position[i] = last;
  }

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
    constexpr double Margin = 1e-9; // relative: the cell tests must not drop what the exact test would keep
    for (int ring = 0; ring <= this->Grid.GetMaximumDimension(); ++ring)
    {
      // Every point of ring `ring` is at least (ring - 1) cells away.
      if (best >= 0 && bestDistance < (ring - 1) * this->Size)
      {
        break;
      }
      this->Grid.ForEachCellInShell(c, ring, [&](const int*, vtkIdType cell) {
        if (this->Remaining[cell] == 0)
        {
          return;
        }
        double nearest, farthest;
        this->CellRange(cell, a.Centre, nearest, farthest);
        if (farthest * (1.0 + Margin) <= a.Radius + this->MinimumRadius[cell] ||
          nearest * (1.0 - Margin) > bestDistance)
        {
          return;
        }
        const vtkIdType first = this->Grid.ItemOffset(cell);
        for (vtkIdType k = first; k < first + this->Remaining[cell]; ++k)
        {
          visit(this->Items[k]);
        }
      });
    }
    return best;
  }

private:
  // Each cell's seeds (remaining ones first), their box and smallest radius.
  void BuildCellLists(vtkIdType n)
  {
    const vtkIdType cells = this->Grid.GetNumberOfCells();
    this->Items.assign(this->Grid.CellBegin(0), this->Grid.CellBegin(0) + this->Grid.ItemOffset(cells));
    this->Position.assign(static_cast<size_t>(n), -1);
    this->CellOfItem.assign(static_cast<size_t>(n), -1);
    this->Remaining.resize(static_cast<size_t>(cells));
    this->MinimumRadius.assign(static_cast<size_t>(cells), HUGE_VAL);
    this->Box.resize(static_cast<size_t>(6 * cells));
    for (vtkIdType cell = 0; cell < cells; ++cell)
    {
      double* box = &this->Box[6 * cell];
      EmptyBox(box);
      this->Remaining[cell] = this->Grid.ItemOffset(cell + 1) - this->Grid.ItemOffset(cell);
      for (vtkIdType k = this->Grid.ItemOffset(cell); k < this->Grid.ItemOffset(cell + 1); ++k)
      {
        const vtkMedialSampleRecord& r = this->Rec[this->Items[k]];
        this->Position[this->Items[k]] = k;
        this->CellOfItem[this->Items[k]] = cell;
        this->MinimumRadius[cell] = std::min(this->MinimumRadius[cell], r.Radius);
        AddToBox(box, r.Centre);
      }
    }
  }
  // Distances from x to the nearest and the farthest point of the cell's seed box.
  void CellRange(vtkIdType cell, const double x[3], double& nearest, double& farthest) const
  {
    const double* box = &this->Box[6 * cell];
    double near2 = 0.0, far2 = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double below = box[axis] - x[axis], above = x[axis] - box[3 + axis];
      const double d = std::max(std::max(below, above), 0.0);
      const double f = std::max(std::fabs(below), std::fabs(above));
      near2 += d * d;
      far2 += f * f;
    }
    nearest = std::sqrt(near2);
    farthest = std::sqrt(far2);
  }

  const std::vector<vtkMedialSampleRecord>& Rec;
  vtkMedialUniformGrid Grid;
  std::vector<vtkIdType> Items;      // per cell, from Grid.ItemOffset: its remaining seeds first
  std::vector<vtkIdType> Remaining;  // per cell
  std::vector<vtkIdType> Position;   // per seed: its place in Items
  std::vector<vtkIdType> CellOfItem; // per seed
  std::vector<double> MinimumRadius; // per cell, over all its seeds
  std::vector<double> Box;           // per cell: its seeds' box, low then high
  double Size = 1.0;
  bool Empty = true;
};

void Runner::ClosestNeighbor()
{
  std::vector<Segment> segments;
  // The chains (one thread) and the coverage's start (the others, then all) at once.
  bool chained = false;
  this->Coverage.Initialize(this->R.Records, [&]() { chained = this->ChainSeeds(segments); });
  if (!chained)
  {
    this->R.Aborted = true;
    return;
  }
  const vtkIdType initialLinks = static_cast<vtkIdType>(segments.size());
  this->SplitLinks(segments);
  this->CollectLinks(segments, initialLinks);
  if (this->DeferCoverage() && !this->R.Aborted)
  {
    this->Coverage.AddBalls(this->R.Records.data() + this->R.Seeds, this->Count() - this->R.Seeds, this->R.Seeds);
  }
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

  std::vector<vtkIdType> popped;
  const Round& round = this->Current;
  bool stop = this->EndOfRound();
  while (!stop && this->Count() < this->S.Budget && !heap.empty())
  {
    popped.clear();
    this->GrowPlan();
    const vtkIdType room = std::min<vtkIdType>(this->RoundSize(), this->S.Budget - this->Count());
    while (static_cast<vtkIdType>(popped.size()) < room && !heap.empty())
    {
      popped.push_back(heap.top().Index);
      heap.pop();
    }
    // A link whose midpoint has no surface point stays as it is (its slot stays empty).
    this->Near.clear();
    for (vtkIdType i : popped)
    {
      this->Near.push_back(rec[segments[i].A].ContactTriangle);
    }
    this->SolveRound(static_cast<vtkIdType>(popped.size()), !this->DeferCoverage(), this->Near,
      [&](vtkIdType j, vtkIdType& t, double p[3], vtkIdType& hint) {
        hint = rec[segments[popped[j]].A].ContactTriangle;
        return this->LinkMidpoint(segments[popped[j]], shortest, t, p);
      });
    this->Balls.assign(popped.size(), -1);
    for (size_t j = 0; j < popped.size(); ++j)
    {
      if (!round.Used[j] || !this->Taken.Insert(&round.Points[3 * j]))
      {
        continue; // projects onto an existing sample: the link stays as it is
      }
      const vtkIdType m = this->Count();
      rec.push_back(round.Balls[j]);
      if (!round.Balls[j].Valid)
      {
        continue;
      }
      this->Balls[j] = m;
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
    if (!this->DeferCoverage())
    {
      this->Coverage.ApplyRound(round.Lowered, this->Balls);
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

int vtkMedialFaceAttempts(const vtkMedialIterativeSettings& settings)
{
  return settings.CoverageTolerance > 0.0 ? std::min(settings.MaximumFaceAttempts, CoverageStopFaceAttempts)
                                          : settings.MaximumFaceAttempts;
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
    // Links exhausted, budget left: finish with the faces, until the coverage asked
    // for, else for 1 / ClosingShare more samples (the closing rounds).
    if (!result.Aborted && !result.CoverageReached && runner.Count() < settings.Budget)
    {
      runner.FaceDistance(settings.CoverageTolerance > 0.0
          ? settings.Budget
          : std::min(settings.Budget, runner.Count() + runner.Count() / ClosingShare));
    }
  }
  else
  {
    runner.Coverage.Initialize(result.Records);
    runner.FaceDistance(settings.Budget);
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
