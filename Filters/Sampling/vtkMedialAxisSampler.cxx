// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialAxisSampler.h"
#include "vtkMedialAxisSamplerInternals.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"

#include "vtkMedialBallSolver.h"
#include "vtkMedialIterativeSampling.h"
#include "vtkMedialPlane.h"
#include "vtkMedialRepairCallback.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidPreparation.h"
#include "vtkMedialPolygon.h"
#include "vtkMedialProgress.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <numeric>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialAxisSampler);

namespace
{
// Consecutive samples in leaf order that run on one thread, each hinted with the
// previous one's contact, blockers and deepest cap triangle. (A hint changes the
// visiting order only: the ball is the same up to the search's slack, which can decide
// nearly flat contacts either way, and of equally deep cap points which one is
// reported.) Only a chain's first sample searches cold: chains of 32 (against 8) cut
// the search's work on the 1.55M-triangle horse by about 6%, and longer ones cut it
// further on large runs (1 M samples: sampling 8.89, 9.25, 9.65 s with 32, 8.24, 8.17,
// 8.86 s with 512, alternating). So a run of N samples uses chains of N / 1024 rounded
// down to a power of two, from 32 to 512: at least 1024 chains to spread over the
// threads. A coverage stop keeps 32 (its blocks of 1024 samples hold whole chains).
// Chains start at multiples of the length, which depends on N and the coverage stop
// only, so the output depends neither on the thread count nor on the piece.
vtkIdType HintChainLength(vtkMedialAxisSampler* self)
{
  const bool coverageStop = self->GetCoverageTolerance() > 0.0;
  vtkIdType chain = 32;
  while (!coverageStop && chain < 512 && 2 * chain * 1024 <= self->GetNumberOfSamples())
  {
    chain *= 2;
  }
  return chain;
}
}

vtkMedialAxisSampler::vtkMedialAxisSampler()
{
  this->Repair = vtkMedialRepairFilter::New();
}

vtkMedialAxisSampler::~vtkMedialAxisSampler()
{
  this->SetRepair(nullptr);
}

vtkCxxSetObjectMacro(vtkMedialAxisSampler, Repair, vtkMedialRepairFilter);

vtkMTimeType vtkMedialAxisSampler::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->Repair ? std::max(time, this->Repair->GetMTime()) : time;
}

bool vtkMedialAxisSampler::IsPlanarInput(vtkPolyData* input)
{
  return vtkMedialPlane::IsPlanarLoops(input);
}

bool vtkMedialAxisSampler::IsPlanarInput(vtkPolyData* input, double centre[3], double normal[3])
{
  return vtkMedialPlane::IsPlanarLoops(input, centre, normal);
}

const char* vtkMedialAxisSampler::GetMethodName(int method)
{
  switch (method)
  {
    case BISECTION:
      return "bisection";
    case SHRINKING_BALL:
      return "shrinking-ball";
    case ONE_PASS:
      return "one-pass";
    default:
      return "unknown";
  }
}

const char* vtkMedialAxisSampler::GetSamplingStrategyName(int strategy)
{
  switch (strategy)
  {
    case RANDOM:
      return "random";
    case CLOSEST_NEIGHBOR:
      return "closest-neighbor";
    case FACE_DISTANCE:
      return "face-distance";
    default:
      return "unknown";
  }
}

int vtkMedialAxisSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialAxisSampler::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Rays need the whole surface whatever piece is requested downstream.
  vtkMedialRequestWholeInput(inputVector);
  return 1;
}

int vtkMedialAxisSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->DiscardedSamples = 0;
  this->CappedSamples = 0;
  this->MeanIterations = 0.0;
  this->BoundaryEdges = 0;
  this->NumberOfTriangles = 0;
  this->EvaluatedSamples = 0;
  this->SeedSamples = 0;
  this->CoverageReached = false;
  this->MaxCoverageGap = -1.0;
  this->SurfaceRepaired = false;
  this->MaxProtrusion = -1.0;
  // Pieces (vtkMedialPieces.h): RANDOM splits the samples; the iterative strategies
  // and a coverage stop are sequential, so piece 0 runs them whole and the other
  // pieces skip even the preparation.
  const vtkMedialPieces pieces = vtkMedialPieces::FromRequest(outInfo);
  vtkInternals passes(this);
  // Progress: each stage its share and its name (vtkMedialProgress.h).
  vtkMedialStages stages(this);

  // Planar polygons or closed polylines: the 2D mode (vtkMedialAxisSampler2D.cxx).
  if (IsPlanarInput(input))
  {
    if (this->SamplingStrategy != RANDOM)
    {
      vtkWarningMacro(<< "SamplingStrategy " << GetSamplingStrategyName(this->SamplingStrategy)
                      << " is for 3D surfaces; planar input is sampled at random.");
    }
    return passes.Sample2D(input, pieces, output, stages);
  }
  if ((this->SamplingStrategy != RANDOM || this->CoverageTolerance > 0.0) && !pieces.IsFirst())
  {
    return 1;
  }

  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  int status = 0;
  if (!passes.PrepareSurface(input, mesh, query, status, stages))
  {
    return status;
  }
  if (this->SamplingStrategy != RANDOM)
  {
    stages.Begin(this->SamplingStrategy == CLOSEST_NEIGHBOR ? "Sampling (closest-neighbor strategy)"
                                                            : "Sampling (face-distance strategy)",
      0.1, 1.0);
    status = passes.SampleIterative(mesh, query, output);
  }
  else
  {
    status = passes.SampleRandom(mesh, query, pieces, output, stages);
  }
  // The repair's report, when the balls are those of a repaired surface.
  if (passes.RepairReport)
  {
    for (int i = 0; i < passes.RepairReport->GetNumberOfArrays(); ++i)
    {
      output->GetFieldData()->AddArray(passes.RepairReport->GetAbstractArray(i));
    }
  }
  return status;
}

//------------------------------------------------------------------------------
bool vtkMedialAxisSampler::vtkInternals::PrepareSurface(vtkPolyData* input, vtkMedialTriangleMesh& mesh,
  vtkMedialSurfaceQuery& query, int& status, vtkMedialStages& stages)
{
  vtkMedialAxisSampler* self = this->Self;
  // Preparation takes seconds on big meshes: the abort flag is polled between stages.
  auto aborted = [self]() { return self->GetAbortExecute() != 0; };
  std::string error;
  // Stages: the mesh, the queries (and the check), the repair and again the mesh and
  // the queries of the repaired surface.
  auto stage = [&](int s) {
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
  };
  vtkMedialSolidPreparation preparation;
  const int threads = vtkMedialThreadCount(self->NumberOfThreads);
  if (!preparation.Prepare(input, self->RepairMode, vtkMedialMakeRepairer(self->Repair, threads), threads, mesh,
        query, error, aborted, stage))
  {
    status = aborted() ? 1 : 0; // aborted: leave the output empty
    if (!aborted())
    {
      vtkErrorWithObjectMacro(self, << "Cannot sample the medial axis: " << error << ".");
    }
    return false;
  }
  self->BoundaryEdges = mesh.BoundaryEdges;
  self->NumberOfTriangles = mesh.GetNumberOfTriangles();
  self->SurfaceRepaired = preparation.GetRepaired();
  this->RepairReport = preparation.GetReport();
  for (const std::string& warning : preparation.GetMessages())
  {
    vtkWarningWithObjectMacro(self, << warning);
  }
  if (self->SamplingStrategy == RANDOM && self->CoverageTolerance <= 0.0)
  {
    // Random sampling reads normals from the query's tree only: the mesh's copy goes
    // (before the smooth normals below are built: the peak of the preparation).
    mesh.ReleaseNormals();
  }
  if (self->MinimumSeparationAngle > 0.0 && self->MaximumProtrusion < 1.0 && self->SamplingStrategy == RANDOM)
  {
    // Balls along the smooth surface's normals (vtkMedialSurfaceNormals), with creases
    // where faces meet at more than theta; the facets' normals from the tree.
    this->Normals.Build(mesh, self->MinimumSeparationAngle, &query);
  }
  return true;
}

bool vtkMedialAxisSampler::vtkInternals::CheckMemory(vtkIdType count, double bytesPerSample, const char* advice) const
{
  const double needed = bytesPerSample * static_cast<double>(count);
  const double available = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  if (available > 0 && needed > 0.8 * available)
  {
    vtkErrorWithObjectMacro(this->Self, << "NumberOfSamples " << count << " needs about " << needed / (1 << 30)
                                        << " GiB, more than this machine's memory allows ("
                                        << available / (1 << 30) << " GiB); " << advice << ".");
    return false;
  }
  return true;
}

void vtkMedialAxisSampler::vtkInternals::ReportAllocationFailure(vtkIdType count) const
{
  vtkErrorWithObjectMacro(this->Self, << "Cannot allocate memory for " << count << " samples.");
}

int vtkMedialAxisSampler::vtkInternals::SampleRandom(vtkMedialTriangleMesh& mesh,
  vtkMedialSurfaceQuery& query, const vtkMedialPieces& pieces, vtkPolyData* output, vtkMedialStages& stages)
{
  vtkMedialAxisSampler* self = this->Self;
  const vtkIdType total = self->NumberOfSamples;
  // This piece's share, at most total / pieces rounded up to whole hint chains; sample
  // indices stay global so that the union of the pieces is a one-piece run.
  const vtkIdType chain = HintChainLength(self);
  const vtkIdType share = self->CoverageTolerance > 0.0 ? total
    : std::min(total, ((total + chain - 1) / chain + pieces.NumberOfPieces - 1) / pieces.NumberOfPieces * chain);
  // The per-sample results plus the output arrays, and the leaf order of all samples.
  const double bytesPerSample = sizeof(vtkMedialSampleRecord) + 12 * sizeof(double) + 3 * sizeof(vtkIdType) +
    2.0 * sizeof(vtkIdType) * static_cast<double>(total) / std::max<vtkIdType>(share, 1);
  if (!this->CheckMemory(share, bytesPerSample, "use fewer samples or several pieces"))
  {
    return 0;
  }
  const int threads = vtkMedialThreadCount(self->NumberOfThreads);
  // Optional coverage stop: checked after fixed blocks of 1024 samples, so the
  // stopping point does not depend on the thread count.
  std::unique_ptr<vtkMedialCoverage> coverage;
  if (self->CoverageTolerance > 0.0)
  {
    coverage.reset(new vtkMedialCoverage(mesh, threads));
  }
  std::vector<vtkIdType> index, order;
  SampleTriangles triangles; // each sample's pick, from SelectSamples
  // Picking and ordering the samples is per-sample work, not the surface's preparation.
  stages.Begin("Drawing the samples", 0.1, 0.15);
  try
  {
    this->SelectSamples(mesh, query, pieces, coverage != nullptr, threads, index, order, triangles);
  }
  catch (const std::bad_alloc&)
  {
    this->ReportAllocationFailure(share);
    return 0;
  }
  const vtkIdType count = static_cast<vtkIdType>(triangles.size());
  // Each sample's point is drawn where it is solved, from the tree's copy of its
  // triangle's corners: all it needs of the mesh is the order of those corners' ids,
  // a byte a sample (the points drawn up front took 24 bytes a sample, 24 MB of the
  // 1 M job's peak, beside the records).
  std::vector<std::uint8_t> idOrders;
  if (!this->Allocate(count, idOrders))
  {
    return 0;
  }
  // Solve the samples in the BVH's leaf order: samples close on the surface touch
  // the same nodes, so the caches stay warm. Each result still goes to its own
  // index, so the order cannot change the output.
  // With a coverage stop the order is sorted within each block only, so that the
  // blocks stay prefixes of the sample sequence.
  // With a coverage stop the samples are solved block by block, the coverage
  // checked after each; without one, in one loop (SolveBlocks).
  const vtkIdType block = coverage ? 1024 : count;
  this->DrawSamples(mesh, threads, triangles, idOrders);
  if (self->GetAbortExecute())
  {
    return 1;
  }
  if (coverage)
  {
    SortByLeaf(query, triangles, block, order);
  }
  else
  {
    // The balls read the query's tree only: the mesh's points, triangles and areas
    // (about 90 bytes a triangle; the coverage still reads them) make room for the
    // records, the run's largest allocation.
    mesh.ReleaseGeometry();
  }
  // Not zeroed: every record is written by its solve, in parallel (a serial zero fill
  // of 112 MB, a page fault every 4 kB, took about 0.3 s of the 1M-ball run).
  vtkMedialBuffer<vtkMedialSampleRecord> results;
  if (!this->Allocate(count, results))
  {
    return 0;
  }
  stages.Begin("Sampling", 0.15, 1.0);
  const vtkIdType used =
    this->SolveBlocks(mesh, query, threads, block, index, triangles, idOrders, order, results, coverage.get());
  if (self->GetAbortExecute())
  {
    return 1; // aborted: leave the output empty
  }
  results.resize(static_cast<size_t>(used));
  self->EvaluatedSamples = used;
  query.ReleaseTree(); // the output arrays take its memory

  try
  {
    this->WriteSamples(output, used, results.data(), used);
  }
  catch (const std::bad_alloc&) // the memory check above does not see ulimit -v
  {
    output->Initialize();
    vtkErrorWithObjectMacro(self, << "Cannot allocate memory for the output of " << used << " samples.");
    return 0;
  }
  if (coverage)
  {
    output->GetFieldData()->GetArray(vtkMedialArrayNames::RequestedSamples)->SetTuple1(0, static_cast<double>(count));
    this->WriteCoverage(output);
  }
  if (self->MeasureProtrusion)
  {
    AddField(output, vtkMedialArrayNames::MaxProtrusion, self->MaxProtrusion); // relative to the diagonal
  }
  this->WarnDiscarded(mesh, used);
  return 1;
}

void vtkMedialAxisSampler::vtkInternals::SelectSamples(const vtkMedialTriangleMesh& mesh,
  const vtkMedialSurfaceQuery& query, const vtkMedialPieces& pieces, bool coverage, int threads,
  std::vector<vtkIdType>& index, std::vector<vtkIdType>& order, SampleTriangles& triangles) const
{
  const vtkIdType total = this->Self->NumberOfSamples;
  // Every sample's triangle, picked once (a binary search over the areas): the
  // order comes from it, and DrawSamples takes it from here.
  const std::uint64_t seed = static_cast<std::uint64_t>(this->Self->RandomSeed);
  SampleTriangles allTriangles(static_cast<size_t>(total));
#pragma omp parallel for num_threads(threads) schedule(static)
  for (vtkIdType i = 0; i < total; ++i)
  {
    allTriangles[i] = static_cast<std::int32_t>(vtkMedialPickSampleTriangle(mesh, seed, i));
  }
  if (coverage)
  {
    index.clear(); // sample i is index i
    triangles = std::move(allTriangles);
    order.resize(static_cast<size_t>(total)); // set by SortByLeaf once the points are drawn
    return;
  }
  // All samples in the leaf order of their triangles (a triangle pick is cheap next to
  // a ball); the piece takes a contiguous run of that order cut at multiples of
  // the chain length, so every piece forms the same hint chains as a one-piece run and the
  // union of the pieces is that run bit for bit.
  std::vector<vtkIdType> leafOrder(allTriangles.size());
  SortByLeaf(query, allTriangles, 0, leafOrder);
  vtkIdType firstChain = 0;
  vtkIdType chains = 0;
  const vtkIdType chain = HintChainLength(this->Self);
  pieces.GetShare((total + chain - 1) / chain, firstChain, chains);
  const vtkIdType begin = std::min(total, firstChain * chain);
  const vtkIdType end = std::min(total, (firstChain + chains) * chain);
  if (begin == 0 && end == total)
  {
    // One piece holds every sample: index is 0 .. total - 1 (left empty), so the leaf
    // order is the solve order, and the picks are the triangles as they are.
    index.clear();
    order = std::move(leafOrder);
    triangles = std::move(allTriangles);
    return;
  }
  // The piece's samples in increasing index (the output keeps sample order), and for
  // each the position in that list, by a mark per sample: linear, no sort.
  std::vector<vtkIdType> position(static_cast<size_t>(total), -1);
  for (vtkIdType k = begin; k < end; ++k)
  {
    position[leafOrder[k]] = 0;
  }
  index.clear();
  index.reserve(static_cast<size_t>(end - begin));
  for (vtkIdType i = 0; i < total; ++i)
  {
    if (position[i] == 0)
    {
      position[i] = static_cast<vtkIdType>(index.size());
      index.push_back(i);
    }
  }
  order.resize(index.size());
  for (vtkIdType k = begin; k < end; ++k)
  {
    order[k - begin] = position[leafOrder[k]];
  }
  triangles.resize(index.size());
  for (size_t i = 0; i < index.size(); ++i)
  {
    triangles[i] = allTriangles[index[i]];
  }
}

void vtkMedialAxisSampler::vtkInternals::DrawSamples(const vtkMedialTriangleMesh& mesh, int threads,
  const SampleTriangles& triangles, std::vector<std::uint8_t>& idOrders) const
{
  vtkMedialAxisSampler* self = this->Self;
  const vtkIdType count = static_cast<vtkIdType>(triangles.size());
  // Blocks: progress, and an abort honoured while millions of samples are prepared.
  const vtkIdType block = 1 << 18;
  for (vtkIdType begin = 0; begin < count && !self->GetAbortExecute(); begin += block)
  {
    const vtkIdType end = std::min(count, begin + block);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (vtkIdType i = begin; i < end; ++i)
    {
      idOrders[i] = vtkMedialCornerIdOrder(mesh, triangles[i]);
    }
    self->UpdateProgress(static_cast<double>(end) / static_cast<double>(count));
  }
}

void vtkMedialAxisSampler::vtkInternals::SortByLeaf(const vtkMedialSurfaceQuery& query,
  const SampleTriangles& triangles, vtkIdType block, std::vector<vtkIdType>& order)
{
  const vtkIdType count = static_cast<vtkIdType>(triangles.size());
  const auto& rank = query.GetLeafRanks();
  if (block > 0)
  {
    auto leafOrder = [&](vtkIdType a, vtkIdType b) {
      const std::int32_t ra = rank[triangles[a]], rb = rank[triangles[b]];
      return ra < rb || (ra == rb && a < b);
    };
    for (vtkIdType i = 0; i < count; ++i)
    {
      order[i] = i;
    }
    for (vtkIdType begin = 0; begin < count; begin += block)
    {
      std::sort(order.begin() + begin, order.begin() + std::min(count, begin + block), leafOrder);
    }
    return;
  }
  // Counting sort by leaf rank: linear, and stable, so ties keep index order.
  vtkMedialBuffer<vtkIdType> next; // mapped on its own: freed at once, not kept by malloc
  next.assign(rank.size() + 1, 0);
  for (vtkIdType i = 0; i < count; ++i)
  {
    ++next[rank[triangles[i]] + 1];
  }
  for (size_t r = 1; r < next.size(); ++r)
  {
    next[r] += next[r - 1];
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    order[next[rank[triangles[i]]]++] = i;
  }
}

vtkIdType vtkMedialAxisSampler::vtkInternals::SolveBlocks(const vtkMedialTriangleMesh& mesh,
  const vtkMedialSurfaceQuery& query, int threads, vtkIdType block, const std::vector<vtkIdType>& index,
  const SampleTriangles& triangles, const std::vector<std::uint8_t>& idOrders,
  const std::vector<vtkIdType>& order, vtkMedialBuffer<vtkMedialSampleRecord>& results, vtkMedialCoverage* coverage)
{
  const std::uint64_t seed = static_cast<std::uint64_t>(this->Self->RandomSeed);
  vtkMedialAxisSampler* self = this->Self;
  const vtkMedialBallParameters param = this->MakeBallParameters(mesh.Diagonal);
  const double coverageTolerance = self->CoverageTolerance * mesh.Diagonal;
  const vtkIdType count = static_cast<vtkIdType>(results.size());
  // A hint chain: samples first .. last - 1 in leaf order, each hinted with the previous one.
  const vtkIdType chain = HintChainLength(self);
  // With MeasureProtrusion, each chain's running maximum of its balls' protrusions
  // (chains start at multiples of the chain length); the largest of them at the end.
  std::vector<double> chainProtrusion(self->MeasureProtrusion ? static_cast<size_t>((count + chain - 1) / chain) : 0, 0.0);
  auto solveChain = [&](vtkIdType first, vtkIdType last) {
    vtkMedialTriangleBVH::BlockerChain blockers; // the previous sample's
    double* largest = chainProtrusion.empty() ? nullptr : &chainProtrusion[static_cast<size_t>(first / chain)];
    for (vtkIdType k = first; k < last; ++k)
    {
      const vtkIdType i = order[k];
      const vtkIdType hint = k > first ? results[order[k - 1]].ContactTriangle : -1;
      // Sample index[i]'s point (vtkMedialDrawSurfacePointOnPicked's, bit for bit: the
      // tree's corners are the mesh's).
      double scratch[9], p[3];
      vtkMedialDrawSurfacePointOnCorners(seed, index.empty() ? i : index[i],
        query.GetTriangleVertices(triangles[i], scratch), idOrders[i], p);
      vtkMedialSolveBall(query, mesh, param, triangles[i], p, results[i], hint, &blockers, largest);
    }
  };
  auto largestProtrusion = [&]() {
    if (!chainProtrusion.empty())
    {
      const double largest = *std::max_element(chainProtrusion.begin(), chainProtrusion.end());
      self->MaxProtrusion = largest / mesh.Diagonal; // the chains not solved are 0
    }
  };
  if (!coverage)
  {
    // One loop over every chain, with no barrier every block (in blocks of 2048, the
    // threads waited for each other's last chain 488 times in a 1 M run: 2% of its
    // sampling). The calling thread (the team's first) reports the progress and polls
    // the abort flag after each of its own chains; once it is set, no thread starts
    // another chain.
    const vtkIdType groups = (count + chain - 1) / chain;
    const vtkIdType progressStep = std::max<vtkIdType>(chain, count / 256);
    std::atomic<vtkIdType> solved{ 0 };
    std::atomic<bool> stop{ false };
    vtkIdType reported = 0;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (vtkIdType g = 0; g < groups; ++g)
    {
      if (stop.load(std::memory_order_relaxed))
      {
        continue;
      }
      const vtkIdType first = g * chain, last = std::min(count, first + chain);
      solveChain(first, last);
      const vtkIdType now = solved.fetch_add(last - first, std::memory_order_relaxed) + (last - first);
      if (omp_get_thread_num() == 0)
      {
        if (now / progressStep != reported / progressStep)
        {
          reported = now;
          self->UpdateProgress(static_cast<double>(now) / static_cast<double>(count));
        }
        if (self->GetAbortExecute())
        {
          stop.store(true, std::memory_order_relaxed);
        }
      }
    }
    largestProtrusion();
    return count;
  }
  // With a coverage stop: block by block, the coverage checked after each (blocks are
  // whole chains).
  for (vtkIdType begin = 0; begin < count && !self->GetAbortExecute(); begin += block)
  {
    const vtkIdType end = std::min(count, begin + block);
    const vtkIdType groups = (end - begin + chain - 1) / chain;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (vtkIdType g = 0; g < groups; ++g)
    {
      const vtkIdType first = begin + g * chain;
      solveChain(first, std::min(end, first + chain));
    }
    self->UpdateProgress(static_cast<double>(end) / static_cast<double>(count));
    if (begin == 0)
    {
      coverage->Initialize(std::vector<vtkMedialSampleRecord>(results.begin(), results.begin() + end));
    }
    else
    {
      coverage->AddBalls(results.data() + begin, end - begin, begin);
    }
    const double gap = coverage->MaxGap();
    self->MaxCoverageGap = gap / mesh.Diagonal;
    self->CoverageReached = gap <= coverageTolerance;
    if (self->CoverageReached)
    {
      largestProtrusion();
      return end;
    }
  }
  largestProtrusion();
  return count;
}

// Shared by every 3D strategy: an open surface, or rays that met the surface from
// outside (a surface folded over itself, or shells that touch or intersect).
void vtkMedialAxisSampler::vtkInternals::WarnDiscarded(const vtkMedialTriangleMesh& mesh, vtkIdType count) const
{
  vtkMedialAxisSampler* self = this->Self;
  if (mesh.BoundaryEdges > 0)
  {
    vtkWarningWithObjectMacro(self, << "Input surface is open (" << mesh.BoundaryEdges << " boundary edges): "
                                    << self->DiscardedSamples << " of " << count
                                    << " samples were discarded because their ray escaped through a hole.");
  }
  else if (self->DiscardedSamples > 0 && !mesh.Contacts.empty())
  {
    vtkWarningWithObjectMacro(self, << self->DiscardedSamples << " of " << count
                                    << " samples were discarded: their inward ray met the surface from outside, "
                                       "where shells touch or intersect (see the warning naming them).");
  }
  else if (self->DiscardedSamples > 0)
  {
    // Closed, yet a ray left the solid: a folded-over or self-intersecting patch.
    vtkWarningWithObjectMacro(self, << self->DiscardedSamples << " of " << count
                                    << " samples were discarded: their inward ray met the surface from outside, "
                                       "so the surface folds over or intersects itself (self-intersecting triangles).");
  }
}

// FACE_DISTANCE ran out of faces before the budget and the coverage: say why.
void vtkMedialAxisSampler::vtkInternals::WarnStoppedEarly(const vtkMedialTriangleMesh& mesh,
  const vtkMedialIterativeSettings& settings, const vtkMedialIterativeResult& result) const
{
  const vtkIdType evaluated = static_cast<vtkIdType>(result.Records.size());
  if (settings.Strategy != vtkMedialIterativeSettings::FACE_DISTANCE || evaluated >= settings.Budget ||
    result.CoverageReached || result.WorstFace < 0)
  {
    return;
  }
  vtkWarningWithObjectMacro(this->Self,
    << "face-distance stopped after " << evaluated << " of " << settings.Budget
    << " samples without reaching the coverage: " << result.GivenUpFaces << " faces were given up ("
    << (result.GivenUpFaces == 1 ? "its" : "their") << " own samples failed " << vtkMedialFaceAttempts(settings)
    << " times to cover them"
    << (settings.CoverageTolerance > 0.0 ? ", and further layers of seeds covered no more faces" : "")
    << ": next to a hole, or where no admissible ball reaches). The largest gap, "
    << result.MaxGap / mesh.Diagonal << " of the diagonal, is at (" << result.WorstPoint[0] << ", "
    << result.WorstPoint[1] << ", " << result.WorstPoint[2] << ") on input cell "
    << mesh.SourceCellIds[result.WorstFace] << ".");
}

static_assert(static_cast<int>(vtkMedialAxisSampler::BISECTION) == vtkMedialBallParameters::BISECTION &&
    static_cast<int>(vtkMedialAxisSampler::SHRINKING_BALL) == vtkMedialBallParameters::SHRINKING_BALL &&
    static_cast<int>(vtkMedialAxisSampler::ONE_PASS) == vtkMedialBallParameters::ONE_PASS,
  "the solver's methods are the sampler's");

vtkMedialBallParameters vtkMedialAxisSampler::vtkInternals::MakeBallParameters(double diagonal) const
{
  const vtkMedialAxisSampler* self = this->Self;
  vtkMedialBallParameters param = vtkMedialMakeBallParameters(self->Method, self->Tolerance,
    self->MinimumSeparationAngle, self->MaximumProtrusion, self->MaximumIterations, diagonal);
  param.Normals = this->Normals.IsEmpty() ? nullptr : &this->Normals;
  return param;
}

int vtkMedialAxisSampler::vtkInternals::SampleIterative(
  const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, vtkPolyData* output)
{
  vtkMedialAxisSampler* self = this->Self;
  vtkMedialIterativeSettings settings;
  settings.Strategy = self->SamplingStrategy == CLOSEST_NEIGHBOR ? vtkMedialIterativeSettings::CLOSEST_NEIGHBOR
                                                                 : vtkMedialIterativeSettings::FACE_DISTANCE;
  settings.Budget = self->NumberOfSamples; // sequential: piece 0 only (RequestData)
  settings.SeedFraction = self->SeedFraction;
  settings.CoverageTolerance = self->CoverageTolerance * mesh.Diagonal;
  settings.Seed = static_cast<std::uint64_t>(self->RandomSeed);
  settings.Threads = vtkMedialThreadCount(self->NumberOfThreads);
  settings.Ball = this->MakeBallParameters(mesh.Diagonal);
  // The strategies' coverage counts on each ball touching its own sample: they keep the
  // facets' normals.
  settings.Ball.Normals = nullptr;
  if (!this->CheckMemory(settings.Budget,
        2.0 * sizeof(vtkMedialSampleRecord) + 12 * sizeof(double) + 8 * sizeof(vtkIdType), "use fewer samples"))
  {
    return 0;
  }

  vtkMedialIterativeResult result;
  try
  {
    vtkMedialRunIterativeSampling(mesh, query, settings,
      [self](double fraction) {
        self->UpdateProgress(std::min(1.0, fraction));
        return self->GetAbortExecute() != 0;
      },
      result);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(self, << "Out of memory while sampling " << settings.Budget << " samples.");
    return 0;
  }
  if (result.Aborted || self->GetAbortExecute())
  {
    return 1; // aborted: leave the output empty
  }
  const vtkIdType evaluated = static_cast<vtkIdType>(result.Records.size());
  self->EvaluatedSamples = evaluated;
  self->SeedSamples = result.Seeds;
  self->CoverageReached = result.CoverageReached;
  self->MaxCoverageGap = result.MaxGap / mesh.Diagonal;
  this->WriteSamples(output, evaluated, result.Records.data(), evaluated);
  this->WarnDiscarded(mesh, evaluated);
  this->WarnStoppedEarly(mesh, settings, result);
  // RequestedSamples is the budget; the samples used are EvaluatedSamples.
  output->GetFieldData()->GetArray(vtkMedialArrayNames::RequestedSamples)->SetTuple1(0, static_cast<double>(settings.Budget));
  vtkIdType validSeeds = 0;
  for (vtkIdType i = 0; i < result.Seeds; ++i)
  {
    validSeeds += result.Records[i].Valid ? 1 : 0;
  }
  AddField(output, vtkMedialArrayNames::EvaluatedSamples, static_cast<double>(evaluated));
  AddField(output, vtkMedialArrayNames::SeedSamples, static_cast<double>(validSeeds)); // the first output points
  this->WriteCoverage(output);
  if (settings.Strategy == vtkMedialIterativeSettings::CLOSEST_NEIGHBOR)
  {
    WriteLinks(output, result.Records, result.LinkEnds, result.InitialLink);
  }
  return 1;
}

void vtkMedialAxisSampler::vtkInternals::WriteLinks(vtkPolyData* output,
  const std::vector<vtkMedialSampleRecord>& records, const std::vector<vtkIdType>& linkEnds,
  const std::vector<vtkIdType>& initialLink)
{
  // Record index -> output point id (invalid records are not output, nor linked).
  std::vector<vtkIdType> pointId(records.size(), -1);
  vtkIdType k = 0;
  for (size_t i = 0; i < records.size(); ++i)
  {
    pointId[i] = records[i].Valid ? k++ : -1;
  }
  vtkNew<vtkCellArray> lines;
  const vtkIdType links = static_cast<vtkIdType>(initialLink.size());
  lines->AllocateExact(links, 2 * links);
  vtkNew<vtkIdTypeArray> initial;
  initial->SetName(vtkMedialArrayNames::InitialLink);
  initial->SetNumberOfTuples(output->GetNumberOfVerts() + links);
  for (vtkIdType c = 0; c < output->GetNumberOfVerts(); ++c)
  {
    initial->SetValue(c, -1); // vertex cells
  }
  for (vtkIdType l = 0; l < links; ++l)
  {
    const vtkIdType ends[2] = { pointId[linkEnds[2 * l]], pointId[linkEnds[2 * l + 1]] };
    lines->InsertNextCell(2, ends);
    initial->SetValue(output->GetNumberOfVerts() + l, initialLink[l]);
  }
  output->SetLines(lines);
  output->GetCellData()->AddArray(initial);
}

void vtkMedialAxisSampler::vtkInternals::AddField(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  output->GetFieldData()->AddArray(a);
}

void vtkMedialAxisSampler::vtkInternals::WriteCoverage(vtkPolyData* output) const
{
  AddField(output, vtkMedialArrayNames::CoverageReached, this->Self->CoverageReached ? 1.0 : 0.0);
  AddField(output, vtkMedialArrayNames::MaxCoverageGap, this->Self->MaxCoverageGap); // relative to the diagonal
}

void vtkMedialAxisSampler::vtkInternals::WriteSamples(
  vtkPolyData* output, vtkIdType requested, const vtkMedialSampleRecord* records, vtkIdType count)
{
  vtkMedialAxisSampler* self = this->Self;
  // Where each block's valid records go: counted, then written, block by block in
  // parallel (1M records: a serial pass over 112 MB in, as much out).
  const int threads = vtkMedialThreadCount(self->NumberOfThreads);
  constexpr vtkIdType Block = 1 << 14;
  const vtkIdType blocks = (count + Block - 1) / Block;
  std::vector<vtkIdType> first(static_cast<size_t>(blocks) + 1, 0);
  std::vector<long long> iterations(static_cast<size_t>(blocks), 0);
  std::vector<vtkIdType> capped(static_cast<size_t>(blocks), 0);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    for (vtkIdType i = b * Block; i < std::min(count, (b + 1) * Block); ++i)
    {
      const vtkMedialSampleRecord& r = records[i];
      first[b + 1] += r.Valid ? 1 : 0;
      iterations[b] += r.Iterations;
      capped[b] += r.Capped ? 1 : 0;
    }
  }
  long long allIterations = 0;
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    first[b + 1] += first[b];
    allIterations += iterations[b];
    self->CappedSamples += capped[b];
  }
  const vtkIdType accepted = first[blocks];
  self->DiscardedSamples = requested - accepted;
  self->MeanIterations = requested > 0 ? static_cast<double>(allIterations) / requested : 0.0;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(accepted);
  auto makeArray = [accepted](const char* name, int components) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(accepted);
    return a;
  };
  auto radius = makeArray(vtkMedialArrayNames::Radius, 1);
  auto surface = makeArray(vtkMedialArrayNames::SurfacePoint, 3);
  auto contact = makeArray(vtkMedialArrayNames::ContactPoint, 3);
  auto angle = makeArray(vtkMedialArrayNames::SeparationAngle, 1);
  vtkNew<vtkIdTypeArray> cells;
  cells->SetName(vtkMedialArrayNames::SourceCellId);
  cells->SetNumberOfTuples(accepted);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(accepted);
  double* centres = static_cast<double*>(points->GetData()->GetVoidPointer(0));
#pragma omp parallel for num_threads(threads) schedule(static)
  for (vtkIdType b = 0; b < blocks; ++b)
  {
    vtkIdType k = first[b];
    for (vtkIdType i = b * Block; i < std::min(count, (b + 1) * Block); ++i)
    {
      const vtkMedialSampleRecord& r = records[i];
      if (!r.Valid)
      {
        continue;
      }
      std::copy_n(r.Centre, 3, centres + 3 * k);
      radius->SetValue(k, r.Radius);
      surface->SetTypedTuple(k, r.Surface);
      contact->SetTypedTuple(k, r.Contact);
      angle->SetValue(k, r.Angle);
      cells->SetValue(k, r.SourceCell);
      connectivity->SetValue(k, k);
      ++k;
    }
  }
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(accepted + 1);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (vtkIdType i = 0; i <= accepted; ++i)
  {
    offsets->SetValue(i, i);
  }
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetActiveScalars(vtkMedialArrayNames::Radius);
  output->GetPointData()->AddArray(surface);
  output->GetPointData()->AddArray(contact);
  output->GetPointData()->AddArray(angle);
  output->GetPointData()->AddArray(cells);
  AddField(output, vtkMedialArrayNames::RequestedSamples, static_cast<double>(requested));
  AddField(output, vtkMedialArrayNames::DiscardedSamples, static_cast<double>(self->DiscardedSamples));
  AddField(output, vtkMedialArrayNames::MeanIterations, self->MeanIterations);
  AddField(output, vtkMedialArrayNames::CappedSamples, static_cast<double>(self->CappedSamples));
}

void vtkMedialAxisSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSeparationAngle: " << this->MinimumSeparationAngle << "\n";
  os << indent << "MaximumProtrusion: " << this->MaximumProtrusion << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "SamplingStrategy: " << GetSamplingStrategyName(this->SamplingStrategy) << "\n";
  os << indent << "CoverageTolerance: " << this->CoverageTolerance << "\n";
  os << indent << "SeedFraction: " << this->SeedFraction << "\n";
  os << indent << "RepairMode: " << vtkMedialRepairFilter::GetModeName(this->RepairMode) << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "SurfaceRepaired: " << this->SurfaceRepaired << "\n";
  os << indent << "MeasureProtrusion: " << this->MeasureProtrusion << "\n";
  os << indent << "DiscardedSamples: " << this->DiscardedSamples << "\n";
  os << indent << "CappedSamples: " << this->CappedSamples << "\n";
  os << indent << "MeanIterations: " << this->MeanIterations << "\n";
  os << indent << "BoundaryEdges: " << this->BoundaryEdges << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "EvaluatedSamples: " << this->EvaluatedSamples << "\n";
  os << indent << "SeedSamples: " << this->SeedSamples << "\n";
  os << indent << "CoverageReached: " << this->CoverageReached << "\n";
  os << indent << "MaxCoverageGap: " << this->MaxCoverageGap << "\n";
  os << indent << "MaxProtrusion: " << this->MaxProtrusion << "\n";
}
