// SPDX-License-Identifier: BSD-3-Clause
// medial-solids-bench: how inscribed the balls are, and how fast wall thickness is.
//
//   medial-solids-bench [--samples N] [--threads T] [--protrusion 1,3e-4] [--shared DIR]
//                       [--no-shapes] [--no-meshes] [--no-thickness]
//
// Protrusion table: for every shared mesh (horse, bunny, fandisk, spot, rocker-arm) and
// generated shape (geodesic spheres of 5k to 327k triangles, a hollow sphere, a torus, a
// box, a capsule, the demo shape) and every MaximumProtrusion setting, runs the sampler
// (default method and angle) and measures each ball's protrusion exactly: its radius
// minus the distance from its centre to the prepared surface (a bounded closest-point
// query in double), relative to the bounding-box diagonal. Also the sampling time per
// sample on one thread without the preparation (a 1-sample run is subtracted; the
// least of --repeat runs, as processor time of the calling thread) and, on the spheres,
// the largest radius error |r - R| / R.
// Thickness rows: vtkMedialThickness on horse.ply (every vertex; then with the cell
// data too), seconds including the preparation.
// Prints Markdown tables. Not a test: it checks nothing.
#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThickness.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <omp.h>
#include <time.h>
#include <sys/stat.h>

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
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Input
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Surface;
  double SphereRadius = 0.0; // > 0: a sphere, report the radius error
};

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> reader;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".ply")
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(path.c_str());
    reader = ply;
  }
  else
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    reader = obj;
  }
  reader->Update();
  return reader->GetOutput();
}

vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->SetResolution(resolution);
  source->Update();
  return source->GetOutput();
}

std::vector<Input> Inputs(const std::string& shared, bool meshes, bool shapes, const std::string& only)
{
  std::vector<Input> inputs;
  for (const char* name : { "horse.ply", "stanford-bunny.obj", "fandisk.obj", "spot.obj", "rocker-arm.obj" })
  {
    struct stat st;
    const std::string path = shared + "/" + name;
    if (meshes && stat(path.c_str(), &st) == 0)
    {
      inputs.push_back({ name, ReadMesh(path) });
    }
  }
  if (shapes)
  {
    for (int level = 4; level <= 7; ++level)
    {
      Input sphere{ "sphere", Shape(vtkMedialShapeSource::SPHERE, level), 1.0 };
      sphere.Name += " " + std::to_string(sphere.Surface->GetNumberOfCells() / 1000) + "k";
      inputs.push_back(sphere);
    }
    inputs.push_back({ "hollow sphere 1 / 0.7", Shape(vtkMedialShapeSource::HOLLOW_SPHERE, 5) });
    inputs.push_back({ "torus 1 / 0.3", Shape(vtkMedialShapeSource::TORUS, 32) });
    inputs.push_back({ "box 3 x 2 x 1", Shape(vtkMedialShapeSource::BOX, 16) });
    inputs.push_back({ "capsule", Shape(vtkMedialShapeSource::CAPSULE, 16) });
    inputs.push_back({ "demo (jack)", Shape(vtkMedialShapeSource::JACK, 16) });
  }
  if (!only.empty())
  {
    std::vector<Input> kept;
    for (const Input& input : inputs)
    {
      if (("," + only + ",").find("," + input.Name + ",") != std::string::npos)
      {
        kept.push_back(input);
      }
    }
    inputs.swap(kept);
  }
  return inputs;
}

// Seconds of processor time of the calling thread: on one thread it times the work
// itself, much less disturbed than the wall clock by other processes on a shared machine.
double ThreadSeconds()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// One thread: the processor time of the run.
double RunSampler(vtkPolyData* surface, double protrusion, vtkIdType samples, vtkSmartPointer<vtkPolyData>& balls)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetMaximumProtrusion(protrusion);
  sampler->SetNumberOfThreads(1);
  sampler->SetNumberOfSamples(samples);
  const double t0 = ThreadSeconds();
  sampler->Update();
  const double seconds = ThreadSeconds() - t0;
  balls = sampler->GetOutput();
  return seconds;
}

// Largest protrusion of the balls through the prepared surface, relative to the diagonal.
double MaximumProtrusion(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
  vtkPolyData* balls, int threads)
{
  vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  double worst = 0.0;
#pragma omp parallel for num_threads(threads) reduction(max : worst) schedule(dynamic, 64)
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    double c[3];
    balls->GetPoint(i, c);
    const double r = radius->GetComponent(i, 0);
    vtkMedialSurfaceQuery::ClosestHit hit;
    if (query.ClosestPoint(c, r, hit))
    {
      worst = std::max(worst, r - hit.Distance);
    }
  }
  return worst / mesh.Diagonal;
}

void ProtrusionTable(const std::vector<Input>& inputs, const std::vector<double>& settings,
  vtkIdType samples, int threads, int repeat)
{
  std::printf("| input | triangles | MaximumProtrusion | max protrusion (%% of diagonal) | median r "
              "/ diagonal | max abs(r - R) / R | CPU us per sample (1 thread) |\n|---|---|---|---|---|---|---|\n");
  for (const Input& input : inputs)
  {
    vtkMedialTriangleMesh mesh;
    vtkMedialSurfaceQuery query;
    std::string error;
    if (!mesh.Build(input.Surface, error) || !query.Build(&mesh, error))
    {
      std::printf("| %s | cannot prepare: %s |\n", input.Name.c_str(), error.c_str());
      continue;
    }
    for (double setting : settings)
    {
      vtkSmartPointer<vtkPolyData> balls, one;
      // The least of `repeat` runs: other processes on the machine only ever add time.
      double preparation = HUGE_VAL, seconds = HUGE_VAL;
      for (int r = 0; r < repeat; ++r)
      {
        preparation = std::min(preparation, RunSampler(input.Surface, setting, 1, one));
        seconds = std::min(seconds, RunSampler(input.Surface, setting, samples, balls));
      }
      vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
      std::vector<double> radii;
      double radiusError = 0.0;
      for (vtkIdType i = 0; i < radius->GetNumberOfTuples(); ++i)
      {
        radii.push_back(radius->GetComponent(i, 0));
        radiusError = std::max(radiusError, std::fabs(radii.back() - input.SphereRadius));
      }
      std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
      std::ostringstream sphere;
      sphere.precision(4);
      if (input.SphereRadius > 0.0)
      {
        sphere << std::fixed << radiusError / input.SphereRadius;
      }
      std::printf("| %s | %lld | %g | %.4f | %.4f | %s | %.1f |\n", input.Name.c_str(),
        static_cast<long long>(mesh.GetNumberOfTriangles()), setting,
        100.0 * MaximumProtrusion(mesh, query, balls, threads), radii[radii.size() / 2] / mesh.Diagonal,
        input.SphereRadius > 0.0 ? sphere.str().c_str() : "-", 1e6 * (seconds - preparation) / samples);
      std::fflush(stdout);
    }
  }
}

void ThicknessRows(const std::string& shared, int threads)
{
  const std::string path = shared + "/horse.ply";
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
  {
    std::printf("thickness: %s is absent, skipped\n", path.c_str());
    return;
  }
  vtkSmartPointer<vtkPolyData> horse = ReadMesh(path);
  std::printf("\n| vtkMedialThickness on horse.ply (%lld vertices, %lld triangles), %d threads | "
              "seconds (with the preparation) | sharp vertices | median Thickness / diagonal |\n"
              "|---|---|---|---|\n",
    static_cast<long long>(horse->GetNumberOfPoints()), static_cast<long long>(horse->GetNumberOfCells()),
    threads);
  for (bool cells : { false, true })
  {
    vtkNew<vtkMedialThickness> thickness;
    thickness->SetInputData(horse);
    thickness->SetNumberOfThreads(threads);
    thickness->SetComputeCellThickness(cells);
    const double t0 = Now();
    thickness->Update();
    const double seconds = Now() - t0;
    vtkDataArray* values = thickness->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    std::vector<double> v;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      v.push_back(values->GetComponent(i, 0));
    }
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    std::printf("| every vertex%s | %.3f | %lld | %.4f |\n", cells ? " and every cell" : "", seconds,
      static_cast<long long>(thickness->GetSharpVertices()), v[v.size() / 2] / horse->GetLength());
  }
}
}

int main(int argc, char* argv[])
{
  vtkIdType samples = 5000;
  int threads = 2;
  int repeat = 3;
  std::string settingList = "1,3e-4";
  std::string shared = MEDIALAXIS_SHARED_MESH_DIR;
  std::string only; // comma-separated input names
  bool meshes = true, shapes = true, thickness = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--samples" && i + 1 < argc)
    {
      samples = std::atoll(argv[++i]);
    }
    else if (a == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (a == "--protrusion" && i + 1 < argc)
    {
      settingList = argv[++i];
    }
    else if (a == "--shared" && i + 1 < argc)
    {
      shared = argv[++i];
    }
    else if (a == "--repeat" && i + 1 < argc)
    {
      repeat = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--only" && i + 1 < argc)
    {
      only = argv[++i];
    }
    else if (a == "--no-shapes" || a == "--no-meshes" || a == "--no-thickness")
    {
      (a == "--no-shapes" ? shapes : a == "--no-meshes" ? meshes : thickness) = false;
    }
    else
    {
      std::fprintf(stderr,
        "usage: medial-solids-bench [--samples N] [--threads T] [--protrusion 1,3e-4] [--shared DIR]\n"
        "                           [--repeat R] [--only NAME,NAME] [--no-shapes] [--no-meshes]\n"
        "                           [--no-thickness]\n");
      return 1;
    }
  }
  std::vector<double> settings;
  std::stringstream list(settingList);
  for (std::string item; std::getline(list, item, ',');)
  {
    settings.push_back(std::atof(item.c_str()));
  }
  if (meshes || shapes)
  {
    ProtrusionTable(Inputs(shared, meshes, shapes, only), settings, samples, threads, repeat);
  }
  if (thickness)
  {
    ThicknessRows(shared, threads);
  }
  return 0;
}
