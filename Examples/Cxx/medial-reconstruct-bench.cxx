// SPDX-License-Identifier: BSD-3-Clause
// medial-reconstruct-bench: how well the union of medial balls reconstructs a mesh.
//
// For each mesh, sampling strategy and sample count: vtkMedialAxisSampler (default
// settings, bisection, all cores), then vtkMedialBallUnion at each resolution (N^3
// sample dimensions), and the vertex-to-surface distance between reconstruction and
// original in both directions, relative to the original's bounding-box diagonal.
// Prints a table: "used" is the samples the strategy evaluated (ClosestNeighbor may
// stop before the budget), "hd_max" / "hd_mean" the larger of the two directions.
//
// usage: medial-reconstruct-bench [--samples 10000,100000] [--resolutions 128,256]
//                                 [--strategies random,closest-neighbor,face-distance]
//                                 [--threads T] [--min-angle DEG] MESH...

#include "MedialReconstructionError.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"

#include "vtkAlgorithm.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <chrono>
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
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == "ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == "stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  reader->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0)));
  return mesh;
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}
}

int main(int argc, char* argv[])
{
  std::vector<long long> samples = { 10000, 100000 };
  std::vector<long long> resolutions = { 128, 256 };
  int threads = 0;
  double minAngle = -1.0; // negative: the sampler's default
  std::vector<std::string> meshes;
  std::vector<int> strategies = { vtkMedialAxisSampler::RANDOM };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--samples" && i + 1 < argc)
    {
      samples = ParseList(argv[++i]);
    }
    else if (a == "--resolutions" && i + 1 < argc)
    {
      resolutions = ParseList(argv[++i]);
    }
    else if (a == "--strategies" && i + 1 < argc)
    {
      strategies.clear();
      for (const std::string& name : ParseNames(argv[++i]))
      {
        int found = -1;
        for (int k = vtkMedialAxisSampler::RANDOM; k <= vtkMedialAxisSampler::FACE_DISTANCE; ++k)
        {
          found = name == vtkMedialAxisSampler::GetSamplingStrategyName(k) ? k : found;
        }
        if (found < 0)
        {
          std::printf("unknown strategy '%s' (random, closest-neighbor, face-distance)\n", name.c_str());
          return 1;
        }
        strategies.push_back(found);
      }
    }
    else if (a == "--min-angle" && i + 1 < argc)
    {
      minAngle = std::atof(argv[++i]);
    }
    else if (a == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (a == "-h" || a == "--help" || (!a.empty() && a[0] == '-'))
    {
      std::printf("usage: medial-reconstruct-bench [--samples 10000,100000] [--resolutions 128,256] "
                  "[--strategies random,closest-neighbor,face-distance] [--threads T] [--min-angle DEG] MESH...\n");
      return a == "-h" || a == "--help" ? 0 : 1;
    }
    else
    {
      meshes.push_back(a);
    }
  }
  const int used = threads > 0 ? threads : omp_get_num_procs();
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
      used, minAngle >= 0.0 ? minAngle : defaults->GetMinimumSeparationAngle(), load[0], load[1], load[2]);
  }
  std::printf("%-16s %-16s %8s %8s %5s %9s %9s %9s %9s %9s %9s %9s %9s %8s %8s %8s\n", "mesh", "strategy",
    "samples", "used", "res", "hd_max", "hd_mean", "rec>orig", "mean", "orig>rec", "mean", "voxel%", "protrude",
    "sample_s", "union_s", "measure_s");
  for (const std::string& path : meshes)
  {
    vtkSmartPointer<vtkPolyData> mesh = Read(path);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    if (mesh->GetNumberOfPoints() == 0)
    {
      std::printf("%-16s cannot read\n", name.c_str());
      continue;
    }
    for (long long count : samples)
    {
      for (int strategy : strategies)
      {
        vtkNew<vtkMedialAxisSampler> sampler;
        sampler->SetSamplingStrategy(strategy);
        sampler->SetInputData(mesh);
        sampler->SetNumberOfSamples(count);
        sampler->SetMethodToBisection();
        sampler->SetNumberOfThreads(threads);
        if (minAngle >= 0.0)
        {
          sampler->SetMinimumSeparationAngle(minAngle);
        }
        auto start = std::chrono::steady_clock::now();
        sampler->Update();
        const double sampleSeconds = Seconds(start);
        // Balls crossing the surface (the sampler's separation angle allows it): the
        // reconstruction cannot be closer than this.
        const double protrusion =
          medialbench::BallProtrusion(sampler->GetOutput(), mesh, mesh->GetLength(), used);
        for (long long n : resolutions)
        {
          vtkNew<vtkMedialBallUnion> ballUnion;
          ballUnion->SetInputConnection(sampler->GetOutputPort());
          ballUnion->SetSampleDimensions(static_cast<int>(n), static_cast<int>(n), static_cast<int>(n));
          ballUnion->SetNumberOfThreads(threads);
          start = std::chrono::steady_clock::now();
          ballUnion->Update();
          const double unionSeconds = Seconds(start);
          start = std::chrono::steady_clock::now();
          const medialbench::ReconstructionError e =
            medialbench::MeasureReconstruction(mesh, ballUnion->GetOutput(), used);
          const double measureSeconds = Seconds(start);
          std::printf("%-16s %-16s %8lld %8lld %5lld %9.3f %9.4f %9.3f %9.4f %9.3f %9.4f %9.3f %9.3f %8.2f %8.2f %8.2f\n",
            name.c_str(), vtkMedialAxisSampler::GetSamplingStrategyName(strategy), count,
            static_cast<long long>(sampler->GetEvaluatedSamples()), n, 100 * e.MaxRel(), 100 * e.MeanRel(),
            100 * e.ToOriginal.Max, 100 * e.ToOriginal.Mean, 100 * e.ToReconstruction.Max,
            100 * e.ToReconstruction.Mean, 100 * ballUnion->GetVoxelSize() / mesh->GetLength(),
            100 * protrusion, sampleSeconds, unionSeconds, measureSeconds);
          std::fflush(stdout);
        }
      }
    }
  }
  return 0;
}
