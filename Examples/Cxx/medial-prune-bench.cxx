// SPDX-License-Identifier: BSD-3-Clause
// medial-prune-bench: pruning (vtkMedialPruneFilter) and simplification to K balls
// (vtkMedialSimplifyFilter), measured. Not a test: it checks nothing. Prints three tables:
//
//  1. 2D: the medial graph (vtkMedialJunctionFilter) of generated polygons, pruned with
//     each measure at its default threshold: end points, junctions and cycles left,
//     beside what the smooth curve (or the exact polygon) has.
//  2. Noisy horse: horse.ply with Gaussian vertex noise (per coordinate, sigma = 0.1% and
//     0.5% of the diagonal; fixed seed), sampled (vtkMedialAxisSampler defaults, T
//     threads), meshed (vtkMedialMeshFilter), pruned with each measure at its default
//     threshold. Per row: medial vertices kept; the one-sided Hausdorff distance from the
//     kept vertices to the clean horse's (unpruned) medial vertices, % of the diagonal;
//     the reconstruction (vtkMedialBallUnion MEDIAL_MESH envelope at N^3) against the
//     CLEAN surface (vtkMedialReconstructionError: vertex Hausdorff, the larger of both
//     directions, and the mean), and its ratio to the clean unpruned reconstruction's.
//     Three more rows per noise level smooth the surface first, as `medial-axis --denoise`
//     does (vtkMedialDenoiseFilter; its default pass band unless --denoise-passband X):
//     "denoised s=1.3" and "s=1.5" (the scale axis of the balls, then the mesh) and
//     "--denoise --prune" (s = 1.3, then the mesh pruned by the scale axis measure too).
//  3. K balls: horse, fandisk, rocker-arm and spot (not tuned on) meshed, then simplified to K = 500, 100, 30
//     vertices by each method (quadric with its guard, the default; quadric unguarded, ErrorTolerance 0; coverage)
//     (and, K = all, the unsimplified mesh); the envelope's two-sided vertex
//     Hausdorff to the original (% of the diagonal), and the seconds of sampling + meshing + simplifying (the pipeline from
//     mesh to K balls) and of simplifying alone.
//
// usage: medial-prune-bench [--threads T] [--resolution N] [--tables 123] [--denoise-passband X]

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialDenoiseFilter.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialPruneFilter.h"
#include "vtkMedialScaleAxisFilter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSimplifyFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace
{
double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::string SharedMesh(const char* name)
{
  const std::string path = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/" + name;
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? path : std::string();
}

// The output of `algorithm`, updated, as a polydata of its own.
vtkSmartPointer<vtkPolyData> Output(vtkPolyDataAlgorithm* algorithm)
{
  algorithm->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(algorithm->GetOutput());
  return out;
}

vtkSmartPointer<vtkPolyData> Read(const std::string& path)
{
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  return Output(reader);
}

// End points, junctions and cycles (E - V + C) of a graph's lines.
struct GraphFigures
{
  int Ends = 0, Junctions = 0, Cycles = 0;
};

GraphFigures Describe(vtkPolyData* graph)
{
  const vtkIdType n = graph->GetNumberOfPoints();
  std::vector<int> degree(static_cast<size_t>(n), 0);
  std::vector<vtkIdType> parent(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    parent[i] = i;
  }
  auto find = [&](vtkIdType x) {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  vtkIdType segments = 0;
  auto it = vtk::TakeSmartPointer(graph->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    it->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k + 1 < count; ++k)
    {
      ++degree[ids[k]];
      ++degree[ids[k + 1]];
      ++segments;
      parent[find(ids[k])] = find(ids[k + 1]);
    }
  }
  GraphFigures f;
  vtkIdType used = 0, components = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (degree[i] > 0)
    {
      ++used;
      f.Ends += degree[i] == 1;
      f.Junctions += degree[i] >= 3;
      components += find(i) == i;
    }
  }
  f.Cycles = static_cast<int>(segments - used + components);
  return f;
}

void PlanarTable()
{
  struct Shape
  {
    const char* Name;
    int Kind;
    int Resolution;
    double Lengths[2];
    const char* Expected;
  };
  const Shape shapes[] = { { "ellipse 2:1 (208 v)", vtkMedialShapeSource::ELLIPSE, 13, { 4, 2 }, "2/0/0" },
    { "ellipse 3:1 (592 v)", vtkMedialShapeSource::ELLIPSE, 37, { 6, 2 }, "2/0/0" },
    { "trefoil (608 v)", vtkMedialShapeSource::TREFOIL, 38, { 3, 2 }, "3/1/0" },
    { "rectangle 3 x 2", vtkMedialShapeSource::RECTANGLE, 16, { 3, 2 }, "4/2/0" },
    { "L-shape", vtkMedialShapeSource::L_SHAPE, 16, { 3, 2 }, "exact" },
    { "square frame", vtkMedialShapeSource::SQUARE_FRAME, 16, { 3, 2 }, "4/4/1" },
    { "star (16 spikes)", vtkMedialShapeSource::STAR, 16, { 3, 2 }, "exact" } };
  std::printf("\n2D: end points / junctions / cycles after pruning at each measure's default threshold\n");
  std::printf("%-22s %-8s %-9s", "shape", "expected", "unpruned");
  for (int m = vtkMedialPruneFilter::EROSION_THICKNESS; m <= vtkMedialPruneFilter::SCALE_AXIS; ++m)
  {
    std::printf(" %-17s", vtkMedialPruneFilter::GetMeasureName(m));
  }
  std::printf("\n");
  for (const Shape& s : shapes)
  {
    vtkNew<vtkMedialShapeSource> source;
    source->SetShape(s.Kind);
    source->SetResolution(s.Resolution);
    source->SetBoxLengths(s.Lengths[0], s.Lengths[1], 1.0);
    vtkNew<vtkMedialJunctionFilter> graph;
    graph->SetInputConnection(source->GetOutputPort());
    graph->Update();
    const GraphFigures u = Describe(graph->GetOutput());
    std::printf("%-22s %-8s %3d/%d/%d  ", s.Name, s.Expected, u.Ends, u.Junctions, u.Cycles);
    for (int m = vtkMedialPruneFilter::EROSION_THICKNESS; m <= vtkMedialPruneFilter::SCALE_AXIS; ++m)
    {
      vtkNew<vtkMedialPruneFilter> prune;
      prune->SetInputConnection(graph->GetOutputPort());
      prune->SetMeasure(m);
      prune->Update();
      const GraphFigures f = Describe(prune->GetOutput());
      char cell[32];
      std::snprintf(cell, sizeof(cell), "%d/%d/%d", f.Ends, f.Junctions, f.Cycles);
      std::printf(" %-17s", cell);
    }
    std::printf("\n");
  }
  std::fflush(stdout);
}

// The horse with Gaussian noise of sigma = fraction * diagonal on every coordinate.
vtkSmartPointer<vtkPolyData> AddNoise(vtkPolyData* surface, double fraction, unsigned seed)
{
  auto noisy = vtkSmartPointer<vtkPolyData>::New();
  noisy->DeepCopy(surface);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, fraction * surface->GetLength());
  vtkPoints* points = noisy->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    for (double& c : x)
    {
      c += gauss(random);
    }
    points->SetPoint(i, x);
  }
  points->Modified();
  return noisy;
}

// The sampler's default balls on `surface`.
vtkSmartPointer<vtkPolyData> DefaultBalls(vtkPolyData* surface, int threads)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfThreads(threads);
  return Output(sampler);
}

// The medial mesh of `balls` inside `surface`; with scaleAxis > 0, of the balls
// vtkMedialScaleAxisFilter keeps at that scale.
vtkSmartPointer<vtkPolyData> MeshOf(vtkPolyData* surface, vtkPolyData* balls, int threads, double scaleAxis = 0.0)
{
  vtkNew<vtkMedialMeshFilter> mesh;
  mesh->SetInputData(surface);
  mesh->SetNumberOfThreads(threads);
  if (scaleAxis > 0.0)
  {
    vtkNew<vtkMedialScaleAxisFilter> scale;
    scale->SetInputData(balls);
    scale->SetScaleFactor(scaleAxis);
    scale->SetNumberOfThreads(threads);
    mesh->SetBallsData(Output(scale));
  }
  else
  {
    mesh->SetBallsData(balls);
  }
  return Output(mesh);
}

// The medial mesh of the sampler's default balls, and the seconds of both steps.
vtkSmartPointer<vtkPolyData> MedialMesh(vtkPolyData* surface, int threads, double* seconds = nullptr)
{
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyData> mesh = MeshOf(surface, DefaultBalls(surface, threads), threads);
  if (seconds)
  {
    *seconds = Seconds(start);
  }
  return mesh;
}

struct Reconstruction
{
  double Hausdorff = 0.0, Mean = 0.0;
};

// The envelope of a medial mesh against `original` (relative to its diagonal).
Reconstruction Rebuild(vtkPolyData* mesh, vtkPolyData* original, int resolution, int threads)
{
  vtkNew<vtkMedialBallUnion> rebuild;
  rebuild->SetInputData(mesh);
  rebuild->SetPrimitives(vtkMedialBallUnion::MEDIAL_MESH);
  rebuild->SetSampleDimensions(resolution, resolution, resolution);
  rebuild->SetNumberOfThreads(threads);
  vtkNew<vtkMedialReconstructionError> measure;
  measure->SetOriginalData(original);
  measure->SetReconstructionConnection(rebuild->GetOutputPort());
  measure->SetNumberOfThreads(threads);
  measure->Update();
  return { measure->GetVertexHausdorff(), measure->GetVertexMeanHausdorff() };
}

// Largest distance from a point of `from` to the nearest point of `to`.
double OneSidedHausdorff(vtkPolyData* from, vtkPolyData* to)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  double worst = 0.0;
  for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
  {
    double x[3], y[3];
    from->GetPoint(i, x);
    to->GetPoint(locator->FindClosestPoint(x), y);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(x, y)));
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> Prune(vtkPolyData* mesh, int measure, double threshold = -1.0)
{
  vtkNew<vtkMedialPruneFilter> prune;
  prune->SetInputData(mesh);
  prune->SetMeasure(measure);
  if (threshold >= 0.0)
  {
    prune->SetThreshold(threshold);
  }
  return Output(prune);
}

// `medial-axis --denoise --prune`'s scale (MedialAxisOptions: the smoothing leaves less
// noise for the scale axis to cover); --denoise-passband X overrides the filter's default.
const double DenoisedPruneScale = vtkMedialScaleAxisFilter::GetDenoisedScaleFactor();
double DenoisePassBand = -1.0;

// The surface smoothed as `medial-axis --denoise` smooths it.
vtkSmartPointer<vtkPolyData> Denoise(vtkPolyData* surface)
{
  vtkNew<vtkMedialDenoiseFilter> denoise;
  denoise->SetInputData(surface);
  if (DenoisePassBand > 0.0)
  {
    denoise->SetPassBand(DenoisePassBand);
  }
  return Output(denoise);
}

void NoisyHorseTable(int threads, int resolution)
{
  const std::string path = SharedMesh("horse.ply");
  if (path.empty())
  {
    std::printf("\nhorse.ply absent: noisy-horse table skipped\n");
    return;
  }
  vtkSmartPointer<vtkPolyData> clean = Read(path);
  const double diagonal = clean->GetLength();
  vtkSmartPointer<vtkPolyData> cleanBalls = DefaultBalls(clean, threads);
  vtkSmartPointer<vtkPolyData> cleanMesh = MeshOf(clean, cleanBalls, threads);
  // The clean horse's medial points densely: 100,000 default balls (the mesh's 10,000
  // vertices are up to ~1% apart, which the one-sided Hausdorff would count as error).
  vtkNew<vtkMedialAxisSampler> dense;
  dense->SetInputData(clean);
  dense->SetNumberOfSamples(100000);
  dense->SetNumberOfThreads(threads);
  dense->Update();
  const Reconstruction reference = Rebuild(cleanMesh, clean, resolution, threads);
  vtkNew<vtkMedialScaleAxisFilter> defaults;
  const double scale = defaults->GetScaleFactor();
  std::printf("\nnoisy horse (%lld medial vertices clean); Hausdorff and errors in %% of the diagonal; "
              "to_clean: one-sided Hausdorff to the clean mesh's vertices, to_dense: to 100,000 clean balls; "
              "reconstruction at %d^3 against the clean surface; clean unpruned reconstruction: %.3f (mean %.4f); "
              "'balls s=%g': vtkMedialScaleAxisFilter (default scale) before meshing\n",
    static_cast<long long>(cleanMesh->GetNumberOfPoints()), resolution, 100 * reference.Hausdorff,
    100 * reference.Mean, scale);
  std::printf("%-7s %-18s %8s %8s %10s %10s %9s %9s %7s\n", "noise%", "measure", "V", "F", "to_clean%",
    "to_dense%", "rec_hd%", "rec_mean%", "ratio");
  for (double noise : { 0.0, 0.001, 0.005 })
  {
    vtkSmartPointer<vtkPolyData> surface = noise > 0.0 ? AddNoise(clean, noise, 7) : clean;
    vtkSmartPointer<vtkPolyData> balls = noise > 0.0 ? DefaultBalls(surface, threads) : cleanBalls;
    vtkSmartPointer<vtkPolyData> mesh = noise > 0.0 ? MeshOf(surface, balls, threads) : cleanMesh;
    vtkSmartPointer<vtkPolyData> smoothed = Denoise(surface);
    vtkSmartPointer<vtkPolyData> smoothedBalls = DefaultBalls(smoothed, threads);
    vtkSmartPointer<vtkPolyData> smoothedMesh; // at DenoisedPruneScale, pruned again by the last row
    // -1: unpruned; the prune filter's measures on the mesh; then the scale axis on the
    // balls; then on the smoothed surface at both scales, and `--denoise --prune` (its
    // scale, then the mesh pruned by the scale axis measure at the same threshold).
    const int scaleOnBalls = vtkMedialPruneFilter::SCALE_AXIS + 1, denoisedLast = scaleOnBalls + 3;
    for (int m = -1; m <= denoisedLast; ++m)
    {
      vtkSmartPointer<vtkPolyData> kept;
      std::string name = "balls s=" + std::to_string(scale).substr(0, 4);
      if (m < 0)
      {
        kept = mesh;
        name = "(unpruned)";
      }
      else if (m < scaleOnBalls)
      {
        kept = Prune(mesh, m);
        name = vtkMedialPruneFilter::GetMeasureName(m);
      }
      else if (m == scaleOnBalls)
      {
        kept = MeshOf(surface, balls, threads, scale);
      }
      else if (m < denoisedLast)
      {
        const bool denoisedScale = m == scaleOnBalls + 1;
        const double s = denoisedScale ? DenoisedPruneScale : scale;
        kept = MeshOf(smoothed, smoothedBalls, threads, s);
        if (denoisedScale)
        {
          smoothedMesh = kept;
        }
        name = "denoised s=" + std::to_string(s).substr(0, 4);
      }
      else
      {
        kept = Prune(smoothedMesh, vtkMedialPruneFilter::SCALE_AXIS, 1.0 - 1.0 / DenoisedPruneScale);
        name = "--denoise --prune";
      }
      const Reconstruction r = Rebuild(kept, clean, resolution, threads);
      std::printf("%-7.1f %-18s %8lld %8lld %10.3f %10.3f %9.3f %9.4f %7.2f\n", 100 * noise, name.c_str(),
        static_cast<long long>(kept->GetNumberOfPoints()), static_cast<long long>(kept->GetNumberOfPolys()),
        100 * OneSidedHausdorff(kept, cleanMesh) / diagonal,
        100 * OneSidedHausdorff(kept, dense->GetOutput()) / diagonal, 100 * r.Hausdorff, 100 * r.Mean,
        r.Hausdorff / reference.Hausdorff);
      std::fflush(stdout);
    }
  }
}

void SimplifyTable(int threads, int resolution)
{
  std::printf("\nsimplification to K balls: envelope (at %d^3) against the original, vertex Hausdorff "
              "(larger direction) and mean, %% of the diagonal; seconds on %d threads\n",
    resolution, threads);
  std::printf("%-16s %-9s %6s %5s %6s %6s %9s %9s %10s %11s\n", "mesh", "method", "V_in", "K", "V_out", "F_out",
    "hd%", "mean%", "simplify_s", "pipeline_s");
  for (const char* name : { "horse.ply", "fandisk.obj", "rocker-arm.obj", "spot.obj" })
  {
    const std::string path = SharedMesh(name);
    if (path.empty())
    {
      std::printf("%-16s absent\n", name);
      continue;
    }
    vtkSmartPointer<vtkPolyData> surface = Read(path);
    double meshSeconds = 0.0;
    vtkSmartPointer<vtkPolyData> mesh = MedialMesh(surface, threads, &meshSeconds);
    const Reconstruction whole = Rebuild(mesh, surface, resolution, threads);
    std::printf("%-16s %-9s %6lld %5s %6lld %6lld %9.3f %9.4f %10s %11.2f\n", name, "-",
      static_cast<long long>(mesh->GetNumberOfPoints()), "all", static_cast<long long>(mesh->GetNumberOfPoints()),
      static_cast<long long>(mesh->GetNumberOfPolys()), 100 * whole.Hausdorff, 100 * whole.Mean, "-", meshSeconds);
    for (vtkIdType k : { 500, 100, 30 })
    {
      // The quadric (guarded, the default), the quadric unguarded (ErrorTolerance 0), coverage.
      for (int variant = 0; variant < 3; ++variant)
      {
        const int method = variant == 2 ? vtkMedialSimplifyFilter::COVERAGE : vtkMedialSimplifyFilter::QUADRIC;
        vtkNew<vtkMedialSimplifyFilter> simplify;
        simplify->SetInputData(mesh);
        simplify->SetSurfaceData(surface);
        simplify->SetNumberOfBalls(k);
        simplify->SetMethod(method);
        if (variant == 1)
        {
          simplify->SetErrorTolerance(0.0);
        }
        simplify->SetNumberOfThreads(threads);
        const auto start = std::chrono::steady_clock::now();
        simplify->Update();
        const double simplifySeconds = Seconds(start);
        vtkPolyData* out = simplify->GetOutput();
        const Reconstruction r = Rebuild(out, surface, resolution, threads);
        std::printf("%-16s %-9s %6lld %5lld %6lld %6lld %9.3f %9.4f %10.2f %11.2f\n", name,
          variant == 1 ? "unguarded" : vtkMedialSimplifyFilter::GetMethodName(method), static_cast<long long>(mesh->GetNumberOfPoints()),
          static_cast<long long>(k), static_cast<long long>(out->GetNumberOfPoints()),
          static_cast<long long>(out->GetNumberOfPolys()), 100 * r.Hausdorff, 100 * r.Mean, simplifySeconds,
          meshSeconds + simplifySeconds);
        std::fflush(stdout);
      }
    }
  }
}
}

int main(int argc, char* argv[])
{
  int threads = 2;
  int resolution = 128;
  std::string tables = "123";
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (a == "--resolution" && i + 1 < argc)
    {
      resolution = std::atoi(argv[++i]);
    }
    else if (a == "--tables" && i + 1 < argc)
    {
      tables = argv[++i];
    }
    else if (a == "--denoise-passband" && i + 1 < argc)
    {
      DenoisePassBand = std::atof(argv[++i]);
    }
    else
    {
      std::printf("usage: medial-prune-bench [--threads T] [--resolution N] [--tables 123] [--denoise-passband X]\n");
      return a == "-h" || a == "--help" ? 0 : 1;
    }
  }
  double load[3] = { -1, -1, -1 };
  if (FILE* f = std::fopen("/proc/loadavg", "r"))
  {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
    {
      load[0] = -1;
    }
    std::fclose(f);
  }
  std::printf("threads %d; load average at start %.2f %.2f %.2f\n", threads, load[0], load[1], load[2]);
  if (tables.find('1') != std::string::npos)
  {
    PlanarTable();
  }
  if (tables.find('2') != std::string::npos)
  {
    NoisyHorseTable(threads, resolution);
  }
  if (tables.find('3') != std::string::npos)
  {
    SimplifyTable(threads, resolution);
  }
  return 0;
}
