// SPDX-License-Identifier: BSD-3-Clause
// medial-reconstruct-bench: how well the union of medial balls reconstructs a mesh.
//
// For each mesh, sampling strategy and sample count: vtkMedialAxisSampler (default
// settings, bisection, all cores), vtkMedialBallProtrusion, then vtkMedialBallUnion at
// each resolution (N^3 sample dimensions) and vtkMedialReconstructionError: the
// distance between reconstruction and original in both directions, relative to the
// original's bounding-box diagonal. Prints a table: "used" is the samples the strategy
// evaluated (ClosestNeighbor may stop before the budget), "hd_max" / "hd_mean" the
// larger of the two directions from the vertices, "ar_max" / "ar_mean" the same from
// points spread over the surfaces by area.
//
// --compare-locator adds two timings of vtkMedialReconstructionError's vertex measure
// alone (both directions, builds included): "vertex_s" with its default engine, the
// project's BVH, and "locator_s" with vtkStaticCellLocator.
//
// usage: medial-reconstruct-bench [--samples 10000,100000] [--resolutions 128,256]
//                                 [--strategies random,closest-neighbor,face-distance]
//                                 [--threads T] [--min-angle DEG] [--compare-locator] MESH...

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialReconstructionError.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> ParseNames(const char* text)
{
  std::vector<std::string> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    values.push_back(item);
  }
  return values;
}

std::vector<long long> ParseList(const char* text)
{
  std::vector<long long> values;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    values.push_back(std::atoll(item.c_str()));
  }
  return values;
}

vtkSmartPointer<vtkPolyData> Read(const std::string& path)
{
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  return mesh;
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

struct BenchOptions
{
  std::vector<long long> Samples = { 10000, 100000 };
  std::vector<long long> Resolutions = { 128, 256 };
  int Threads = 0;
  double MinAngle = -1.0; // negative: the sampler's default
  std::vector<std::string> Meshes;
  std::vector<int> Strategies = { vtkMedialAxisSampler::RANDOM };
  bool CompareLocator = false;
};

// The sampling strategy of that name, or -1.
int StrategyByName(const std::string& name)
{
  int found = -1;
  for (int k = vtkMedialAxisSampler::RANDOM; k <= vtkMedialAxisSampler::FACE_DISTANCE; ++k)
  {
    found = name == vtkMedialAxisSampler::GetSamplingStrategyName(k) ? k : found;
  }
  return found;
}

// False when the program should stop at once, with `exitCode` (help, usage or an
// unknown strategy, already printed).
bool ParseArgs(int argc, char* argv[], BenchOptions& options, int& exitCode)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--samples" && i + 1 < argc)
    {
      options.Samples = ParseList(argv[++i]);
    }
    else if (a == "--resolutions" && i + 1 < argc)
    {
      options.Resolutions = ParseList(argv[++i]);
    }
    else if (a == "--strategies" && i + 1 < argc)
    {
      options.Strategies.clear();
      for (const std::string& name : ParseNames(argv[++i]))
      {
        const int found = StrategyByName(name);
        if (found < 0)
        {
          std::printf("unknown strategy '%s' (random, closest-neighbor, face-distance)\n", name.c_str());
          exitCode = 1;
          return false;
        }
        options.Strategies.push_back(found);
      }
    }
    else if (a == "--min-angle" && i + 1 < argc)
    {
      options.MinAngle = std::atof(argv[++i]);
    }
    else if (a == "--compare-locator")
    {
      options.CompareLocator = true;
    }
    else if (a == "--threads" && i + 1 < argc)
    {
      options.Threads = std::atoi(argv[++i]);
    }
    else if (a == "-h" || a == "--help" || (!a.empty() && a[0] == '-'))
    {
      std::printf("usage: medial-reconstruct-bench [--samples 10000,100000] [--resolutions 128,256] "
                  "[--strategies random,closest-neighbor,face-distance] [--threads T] [--min-angle DEG] "
                  "[--compare-locator] MESH...\n");
      exitCode = a == "-h" || a == "--help" ? 0 : 1;
      return false;
    }
    else
    {
      options.Meshes.push_back(a);
    }
  }
  return true;
}

// The settings line (threads, angle, load average) and the column names.
void PrintHeader(const BenchOptions& options)
{
  const int used = options.Threads > 0 ? options.Threads : omp_get_num_procs();
  {
    vtkNew<vtkMedialAxisSampler> defaults;
    double load[3] = { 0, 0, 0 };
    if (FILE* f = std::fopen("/proc/loadavg", "r"))
    {
      if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
      {
        load[0] = load[1] = load[2] = -1;
      }
      std::fclose(f);
    }
    std::printf("threads %d, min angle %g, load average at start %.2f %.2f %.2f; errors in %% of the "
                "original's bounding-box diagonal, vertex to surface; times in seconds (wall)\n",
      used, options.MinAngle >= 0.0 ? options.MinAngle : defaults->GetMinimumSeparationAngle(), load[0], load[1],
      load[2]);
  }
  std::printf("%-16s %-16s %8s %8s %5s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s %8s %8s %9s", "mesh", "strategy",
    "samples", "used", "res", "hd_max", "hd_mean", "ar_max", "ar_mean", "rec>orig", "mean", "orig>rec", "mean",
    "voxel%", "protrude", "sample_s", "union_s", "measure_s");
  if (options.CompareLocator)
  {
    std::printf(" %8s %9s", "vertex_s", "locator_s");
  }
  std::printf("\n");
}

// The vertex measure alone (both directions, build included) with each engine:
// prints the two timing columns.
void PrintLocatorComparison(vtkPolyData* mesh, vtkMedialBallUnion* ballUnion, int threads)
{
  double engineSeconds[2];
  double hausdorff[2];
  for (int engine : { vtkMedialReconstructionError::BVH, vtkMedialReconstructionError::CELL_LOCATOR })
  {
    vtkNew<vtkMedialReconstructionError> vertexOnly;
    vertexOnly->SetOriginalData(mesh);
    vertexOnly->SetReconstructionConnection(ballUnion->GetOutputPort());
    vertexOnly->SetNumberOfThreads(threads);
    vertexOnly->SetNumberOfAreaSamples(0);
    vertexOnly->SetDistanceEngine(engine);
    const auto start = std::chrono::steady_clock::now();
    vertexOnly->Update();
    engineSeconds[engine] = Seconds(start);
    hausdorff[engine] = vertexOnly->GetVertexHausdorff();
  }
  const bool same = std::fabs(hausdorff[0] - hausdorff[1]) <= 1e-12;
  std::printf(" %8.2f %9.2f%s", engineSeconds[0], engineSeconds[1], same ? "" : " (DIFFERENT)");
}

// The balls of one sampler run, with their protrusion and the time they took.
struct SampledBalls
{
  std::string MeshName;
  int Strategy;
  long long Count;
  vtkMedialAxisSampler* Sampler;
  vtkMedialBallProtrusion* Protrusion;
  double SampleSeconds;
};

// One table row: the union of the balls at n^3 and its errors against the mesh.
void PrintResolutionRow(vtkPolyData* mesh, const SampledBalls& balls, long long n, const BenchOptions& options)
{
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(balls.Sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(static_cast<int>(n), static_cast<int>(n), static_cast<int>(n));
  ballUnion->SetNumberOfThreads(options.Threads);
  auto start = std::chrono::steady_clock::now();
  ballUnion->Update();
  const double unionSeconds = Seconds(start);
  vtkNew<vtkMedialReconstructionError> e;
  e->SetOriginalData(mesh);
  e->SetReconstructionConnection(ballUnion->GetOutputPort());
  e->SetNumberOfThreads(options.Threads);
  start = std::chrono::steady_clock::now();
  e->Update();
  const double measureSeconds = Seconds(start);
  const double* vertexMax = e->GetVertexMaxError();
  const double* vertexMean = e->GetVertexMeanError();
  std::printf("%-16s %-16s %8lld %8lld %5lld %9.3f %9.4f %9.3f %9.4f %9.3f %9.4f %9.3f %9.4f %9.3f %9.3f "
              "%8.2f %8.2f %9.2f",
    balls.MeshName.c_str(), vtkMedialAxisSampler::GetSamplingStrategyName(balls.Strategy), balls.Count,
    static_cast<long long>(balls.Sampler->GetEvaluatedSamples()), n, 100 * e->GetVertexHausdorff(),
    100 * e->GetVertexMeanHausdorff(), 100 * e->GetAreaHausdorff(), 100 * e->GetAreaMeanHausdorff(),
    100 * vertexMax[0], 100 * vertexMean[0], 100 * vertexMax[1], 100 * vertexMean[1],
    100 * ballUnion->GetVoxelSize() / mesh->GetLength(), 100 * balls.Protrusion->GetMaxProtrusion(),
    balls.SampleSeconds, unionSeconds, measureSeconds);
  if (options.CompareLocator)
  {
    PrintLocatorComparison(mesh, ballUnion, options.Threads);
  }
  std::printf("\n");
  std::fflush(stdout);
}

// Samples `count` balls of the mesh with one strategy, then prints a row per resolution.
void BenchSampling(
  vtkPolyData* mesh, const std::string& name, long long count, int strategy, const BenchOptions& options)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetSamplingStrategy(strategy);
  sampler->SetInputData(mesh);
  sampler->SetNumberOfSamples(count);
  sampler->SetMethodToBisection();
  sampler->SetNumberOfThreads(options.Threads);
  if (options.MinAngle >= 0.0)
  {
    sampler->SetMinimumSeparationAngle(options.MinAngle);
  }
  const auto start = std::chrono::steady_clock::now();
  sampler->Update();
  const double sampleSeconds = Seconds(start);
  // Balls crossing the surface (the sampler's separation angle allows it): the
  // reconstruction cannot be closer than this.
  vtkNew<vtkMedialBallProtrusion> protrusion;
  protrusion->SetSurfaceData(mesh);
  protrusion->SetBallsConnection(sampler->GetOutputPort());
  protrusion->SetNumberOfThreads(options.Threads);
  protrusion->Update();
  const SampledBalls balls{ name, strategy, count, sampler, protrusion, sampleSeconds };
  for (long long n : options.Resolutions)
  {
    PrintResolutionRow(mesh, balls, n, options);
  }
}
}

int main(int argc, char* argv[])
{
  BenchOptions options;
  int exitCode = 0;
  if (!ParseArgs(argc, argv, options, exitCode))
  {
    return exitCode;
  }
  PrintHeader(options);
  for (const std::string& path : options.Meshes)
  {
    vtkSmartPointer<vtkPolyData> mesh = Read(path);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    if (mesh->GetNumberOfPoints() == 0)
    {
      std::printf("%-16s cannot read\n", name.c_str());
      continue;
    }
    for (long long count : options.Samples)
    {
      for (int strategy : options.Strategies)
      {
        BenchSampling(mesh, name, count, strategy, options);
      }
    }
  }
  return 0;
}
