// SPDX-License-Identifier: BSD-3-Clause
// medial-bench: throughput of the medial sampler and of its BVH queries (Embree and the own tree).
//
// Input: horse.ply from ../shared/data/meshes, Loop-subdivided twice (>= 1.5 M
// triangles); without the shared data, a generated demo shape of the same size.
// Measures, in one run: BVH build time, ray throughput, closest-point and
// contains-ball throughput on Embree and on the own tree side by side,
// each method with 1 and 2 threads (with mean iterations), each method's ratio to
// the "limit" (one ray plus one bounded closest-point query per sample), peak RSS,
// and a 327k-triangle sphere as the worst case; then the 3D classification
// (vtkMedialBallClassifier) of horse.ply's default balls, without and with the exact
// seams and junctions, at theta = 45 and 0 (--structure runs only these rows).
// Prints a table, or one JSON object with --json. Not a test: it checks nothing.
#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialRandom.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <omp.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace
{
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double PeakRssMiB()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

struct Row
{
  std::string Name;
  double MicrosecondsPerSample;
  double Iterations;
  double Extra; // speed-up or ratio, depending on the row
};

// horse.ply from the shared meshes, Loop-subdivided `subdivisions` times; without the
// shared data, the generated demo shape at `resolution`.
vtkSmartPointer<vtkPolyData> LoadBenchMesh(
  const std::string& sharedDir, int subdivisions, int resolution, std::string& label)
{
  const std::string horse = sharedDir + "/horse.ply";
  struct stat st;
  if (stat(horse.c_str(), &st) == 0)
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(horse.c_str());
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(reader->GetOutputPort());
    triangles->Update();
    label = "horse.ply";
    if (subdivisions == 0)
    {
      return triangles->GetOutput();
    }
    vtkNew<vtkLoopSubdivisionFilter> loop;
    loop->SetInputConnection(triangles->GetOutputPort());
    loop->SetNumberOfSubdivisions(subdivisions);
    loop->Update();
    label += ", Loop x" + std::to_string(subdivisions);
    return loop->GetOutput();
  }
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(resolution);
  jack->Update();
  label = "generated demo shape (shared data absent)";
  return jack->GetOutput();
}

double TimeSampler(vtkPolyData* mesh, int method, int threads, vtkIdType samples, double& iterations,
  vtkIdType& capped)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetMethod(method);
  sampler->SetNumberOfThreads(threads);
  sampler->SetNumberOfSamples(samples);
  const double t0 = Now();
  sampler->Update();
  iterations = sampler->GetMeanIterations();
  capped = sampler->GetCappedSamples();
  return Now() - t0;
}

struct StructureRow
{
  double Theta;
  vtkIdType Balls;
  double PrepareSeconds;  // surface preparation alone (one ball classified)
  double ClassifySeconds; // governors of every ball, with the preparation
  double ExactSeconds;    // the same plus exact seams and junctions
  vtkIdType Types[4];
  vtkIdType SeamPoints, Junctions, TracedSeams;
};

// Classifies the default sampler's balls of `mesh` (2 threads) at theta.
StructureRow RunStructure(vtkPolyData* mesh, double theta)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetMinimumSeparationAngle(theta);
  sampler->SetNumberOfThreads(2);
  sampler->Update();
  vtkNew<vtkPoints> first;
  first->InsertNextPoint(sampler->GetOutput()->GetPoint(0));
  vtkNew<vtkPolyData> oneBall;
  oneBall->SetPoints(first);
  vtkNew<vtkDoubleArray> oneRadius;
  oneRadius->SetName(vtkMedialArrayNames::Radius);
  oneRadius->InsertNextValue(sampler->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::Radius)->GetComponent(0, 0));
  oneBall->GetPointData()->AddArray(oneRadius);
  StructureRow row;
  row.Theta = theta;
  row.Balls = sampler->GetOutput()->GetNumberOfPoints();
  auto timed = [&](vtkPolyData* balls, bool exact) {
    vtkNew<vtkMedialBallClassifier> classifier;
    classifier->SetInputData(balls);
    classifier->SetSurfaceData(mesh);
    classifier->SetMinimumSeparationAngle(theta);
    classifier->SetComputeExactPoints(exact);
    classifier->SetNumberOfThreads(2);
    const double t0 = Now();
    classifier->Update();
    const double seconds = Now() - t0;
    row.Types[0] = classifier->GetNumberOfRimBalls();
    row.Types[1] = classifier->GetNumberOfSheetBalls();
    row.Types[2] = classifier->GetNumberOfSeamBalls();
    row.Types[3] = classifier->GetNumberOfJunctionBalls();
    row.SeamPoints = classifier->GetNumberOfSeamPoints();
    row.Junctions = classifier->GetNumberOfJunctionVertices();
    row.TracedSeams = classifier->GetNumberOfTracedSeams();
    return seconds;
  };
  row.PrepareSeconds = timed(oneBall, false);
  row.ClassifySeconds = timed(sampler->GetOutput(), false);
  row.ExactSeconds = timed(sampler->GetOutput(), true);
  return row;
}

void PrintStructure(const std::vector<StructureRow>& rows, const std::string& label, bool json, std::ostringstream& js)
{
  if (json)
  {
    js << ", \"structure_mesh\": \"" << label << "\"";
    for (const StructureRow& r : rows)
    {
      js << ", \"structure_theta_" << r.Theta << "\": {\"balls\": " << r.Balls
         << ", \"prepare_seconds\": " << r.PrepareSeconds << ", \"classify_seconds\": " << r.ClassifySeconds
         << ", \"exact_seconds\": " << r.ExactSeconds << ", \"rim\": " << r.Types[0] << ", \"sheet\": " << r.Types[1]
         << ", \"seam\": " << r.Types[2] << ", \"junction\": " << r.Types[3] << ", \"seam_points\": " << r.SeamPoints
         << ", \"junction_vertices\": " << r.Junctions << ", \"traced_seams\": " << r.TracedSeams << "}";
    }
    return;
  }
  std::printf("\n3D classification of %s's default balls (vtkMedialBallClassifier, 2 threads), seconds with the "
              "surface preparation:\n",
    label.c_str());
  std::printf("| theta | balls | preparation | + governors | + exact seams and junctions | rim / sheet / seam / "
              "junction balls | seam points | junction vertices | traced seams |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const StructureRow& r : rows)
  {
    std::printf("| %g | %lld | %.2f | %.2f | %.2f | %lld / %lld / %lld / %lld | %lld | %lld | %lld |\n", r.Theta,
      static_cast<long long>(r.Balls), r.PrepareSeconds, r.ClassifySeconds, r.ExactSeconds,
      static_cast<long long>(r.Types[0]), static_cast<long long>(r.Types[1]), static_cast<long long>(r.Types[2]),
      static_cast<long long>(r.Types[3]), static_cast<long long>(r.SeamPoints), static_cast<long long>(r.Junctions),
      static_cast<long long>(r.TracedSeams));
  }
}

// Microseconds per sample (wall), without the preparation (merge, orientation,
// BVH builds): the time of a 1-sample run with the same settings is subtracted.
double RunSampler(vtkPolyData* mesh, int method, int threads, vtkIdType samples, double& iterations,
  vtkIdType& capped, double* totalSeconds = nullptr)
{
  double it;
  vtkIdType cap;
  const double preparation = TimeSampler(mesh, method, threads, 1, it, cap);
  const double seconds = TimeSampler(mesh, method, threads, samples, iterations, capped);
  if (totalSeconds)
  {
    *totalSeconds = seconds;
  }
  return 1e6 * (seconds - preparation) / samples;
}
}

int main(int argc, char* argv[])
{
  bool json = false;
  bool structureOnly = false;
  vtkIdType samples = 200000;
  vtkIdType defaultSamples = 1000000;
  std::string sharedDir = MEDIALAXIS_SHARED_MESH_DIR;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--json")
    {
      json = true;
    }
    else if (a == "--structure")
    {
      structureOnly = true;
    }
    else if (a == "--samples" && i + 1 < argc)
    {
      samples = std::atoll(argv[++i]);
    }
    else if (a == "--default-samples" && i + 1 < argc)
    {
      defaultSamples = std::atoll(argv[++i]);
    }
    else if (a == "--shared" && i + 1 < argc)
    {
      sharedDir = argv[++i];
    }
    else
    {
      std::fprintf(stderr,
        "usage: medial-bench [--json] [--samples N (per method run, default 200000)]\n"
        "                    [--default-samples N (default method, 2 threads; default 1000000)]\n"
        "                    [--shared DIR] [--structure (only the 3D classification rows)]\n");
      return 1;
    }
  }
  // The 3D classification rows (first: they are short).
  std::string structureLabel;
  vtkSmartPointer<vtkPolyData> structureMesh = LoadBenchMesh(sharedDir, 0, 16, structureLabel);
  const std::vector<StructureRow> structure = { RunStructure(structureMesh, 45.0), RunStructure(structureMesh, 0.0) };
  if (structureOnly)
  {
    std::ostringstream js;
    PrintStructure(structure, structureLabel, json, js);
    if (json)
    {
      std::printf("{%s}\n", js.str().substr(2).c_str());
    }
    return 0;
  }

  std::string label;
  const double tLoad = Now();
  vtkSmartPointer<vtkPolyData> mesh = LoadBenchMesh(sharedDir, 2, 230, label);
  const double loadSeconds = Now() - tLoad;

  // Preparation and BVH build, timed apart from sampling.
  vtkMedialTriangleMesh prepared;
  std::string error;
  const double tPrep = Now();
  if (!prepared.Build(mesh, error))
  {
    std::fprintf(stderr, "medial-bench: %s\n", error.c_str());
    return 1;
  }
  const double prepSeconds = Now() - tPrep;
  vtkMedialSurfaceQuery query;
  const double tBvh = Now();
  if (!query.Build(&prepared, error))
  {
    std::fprintf(stderr, "medial-bench: %s\n", error.c_str());
    return 1;
  }
  const double bvhSeconds = Now() - tBvh;
  // The own tree alone (query.Build makes both it and Embree's scene).
  vtkMedialTriangleBVH ownTree;
  const double tTree = Now();
  ownTree.Build(prepared);
  const double treeSeconds = Now() - tTree;

  // Query throughput on 2 threads: rays from random surface points, then bounded
  // closest-point queries from medial centres (radius as the bound).
  const int queries = 200000;
  std::vector<double> centres(3 * queries), radii(queries);
  const double tRay = Now();
#pragma omp parallel for num_threads(2) schedule(dynamic, 256)
  for (int i = 0; i < queries; ++i)
  {
    vtkMedialSampleRandom random(7, i);
    const vtkIdType t = prepared.PickTriangleByArea(random.Uniform());
    const double s = std::sqrt(random.Uniform()), u = random.Uniform();
    const vtkIdType* v = prepared.GetTriangle(t);
    double p[3], n[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (1 - s) * prepared.GetPoint(v[0])[k] + s * (1 - u) * prepared.GetPoint(v[1])[k] +
        s * u * prepared.GetPoint(v[2])[k];
      n[k] = -prepared.GetNormal(t)[k];
    }
    vtkMedialSurfaceQuery::RayHit hit;
    const bool ok = query.Intersect(p, n, 1e-9 * prepared.Diagonal, HUGE_VAL, t, hit);
    radii[i] = ok ? 0.5 * hit.Distance : 0.0;
    for (int k = 0; k < 3; ++k)
    {
      centres[3 * i + k] = p[k] + radii[i] * n[k];
    }
  }
  const double rayMicro = 1e6 * (Now() - tRay) / queries;

  // Closest-point queries from the medial points of a short default run.
  vtkNew<vtkMedialAxisSampler> probe;
  probe->SetInputData(mesh);
  probe->SetNumberOfSamples(20000);
  probe->SetNumberOfThreads(2);
  probe->Update();
  vtkPolyData* medial = probe->GetOutput();
  const int probes = static_cast<int>(medial->GetNumberOfPoints());
  vtkDataArray* probeRadius = medial->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  // Point queries from the medial centres, on each engine: bounded closest point,
  // and contains-ball just inside ("yes", must see every candidate) and just
  // outside ("no", may stop at the first blocker) the medial radius.
  struct EngineRow
  {
    double Closest, Yes, No;
  } engines[2];
  for (int engine : { vtkMedialSurfaceQuery::EMBREE, vtkMedialSurfaceQuery::OWN_TREE })
  {
    query.SetPointQueryEngine(engine);
    auto timed = [&](int kind) {
      const double t0 = Now();
#pragma omp parallel for num_threads(2) schedule(dynamic, 64)
      for (int i = 0; i < probes; ++i)
      {
        double c[3];
        medial->GetPoint(i, c);
        const double r = probeRadius->GetComponent(i, 0);
        vtkMedialSurfaceQuery::ClosestHit hit;
        if (kind == 0)
        {
          query.ClosestPoint(c, r + 1e-6 * prepared.Diagonal, hit);
        }
        else
        {
          query.ContainsBall(c, kind == 1 ? r * (1 - 1e-6) : r * 1.01);
        }
      }
      return 1e6 * (Now() - t0) / probes;
    };
    engines[engine] = { timed(0), timed(1), timed(2) };
  }
  query.SetPointQueryEngine(vtkMedialSurfaceQuery::OWN_TREE);
  const double closestMicro = engines[vtkMedialSurfaceQuery::OWN_TREE].Closest;
  const double limitMicro = rayMicro + closestMicro;

  // Each method with 1 and 2 threads.
  std::vector<Row> rows;
  vtkNew<vtkMedialAxisSampler> defaults;
  const int defaultMethod = defaults->GetMethod();
  for (int method = vtkMedialAxisSampler::BISECTION; method <= vtkMedialAxisSampler::ONE_PASS; ++method)
  {
    double it1, it2;
    vtkIdType capped1, capped2;
    const double one = RunSampler(mesh, method, 1, samples, it1, capped1);
    const double two = RunSampler(mesh, method, 2, samples, it2, capped2);
    rows.push_back({ std::string(vtkMedialAxisSampler::GetMethodName(method)) + ", 1 thread", one, it1, 0 });
    rows.push_back({ std::string(vtkMedialAxisSampler::GetMethodName(method)) + ", 2 threads", two, it2, one / two });
  }
  double itDefault;
  vtkIdType cappedDefault;
  double defaultSeconds; // including the preparation
  const double defaultMicro =
    RunSampler(mesh, defaultMethod, 2, defaultSamples, itDefault, cappedDefault, &defaultSeconds);

  // Worst case: a 327k-triangle sphere (every closest-point query sees many equidistant facets).
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(7);
  sphere->Update();
  double itSphere;
  vtkIdType cappedSphere;
  const double sphereMicro = RunSampler(sphere->GetOutput(), defaultMethod, 2, 5000, itSphere, cappedSphere);
  const double rss = PeakRssMiB();

  if (json)
  {
    std::ostringstream js;
    js << "{\"mesh\": \"" << label << "\", \"triangles\": " << prepared.GetNumberOfTriangles()
       << ", \"load_seconds\": " << loadSeconds << ", \"prepare_seconds\": " << prepSeconds
       << ", \"bvh_seconds\": " << bvhSeconds << ", \"own_tree_seconds\": " << treeSeconds
       << ", \"own_tree_nodes\": " << ownTree.GetNumberOfNodes() << ", \"ray_us\": " << rayMicro
       << ", \"closest_point_us\": " << closestMicro << ", \"limit_us\": " << limitMicro;
    for (int e : { 0, 1 })
    {
      js << ", \"" << (e ? "own_tree" : "embree") << "\": {\"closest_point_us\": " << engines[e].Closest
         << ", \"contains_ball_yes_us\": " << engines[e].Yes << ", \"contains_ball_no_us\": " << engines[e].No << "}";
    }
    for (const Row& r : rows)
    {
      js << ", \"" << r.Name << "\": {\"us_per_sample\": " << r.MicrosecondsPerSample
         << ", \"iterations\": " << r.Iterations << ", \"ratio_to_limit\": " << r.MicrosecondsPerSample / limitMicro << "}";
    }
    js << ", \"default_method\": \"" << vtkMedialAxisSampler::GetMethodName(defaultMethod)
       << "\", \"default_samples\": " << defaultSamples << ", \"default_seconds\": " << defaultSeconds
       << ", \"default_us_per_sample\": " << defaultMicro << ", \"sphere_us_per_sample\": " << sphereMicro
       << ", \"sphere_to_horse\": " << sphereMicro / defaultMicro << ", \"peak_rss_mib\": " << rss;
    PrintStructure(structure, structureLabel, json, js);
    js << "}";
    std::printf("%s\n", js.str().c_str());
    return 0;
  }
  std::printf("mesh: %s, %lld triangles\n", label.c_str(), static_cast<long long>(prepared.GetNumberOfTriangles()));
  std::printf("load %.2f s, prepare (merge, orient) %.2f s, BVH build (Embree + own tree) %.2f s, "
              "own tree alone %.2f s (%lld nodes)\n",
    loadSeconds, prepSeconds, bvhSeconds, treeSeconds, static_cast<long long>(ownTree.GetNumberOfNodes()));
  std::printf("\n| point query from a medial centre (2 threads), us | Embree | own tree | speed-up |\n");
  std::printf("|---|---|---|---|\n");
  const char* kinds[3] = { "bounded closest point", "contains ball, yes (r - 1e-6 r)", "contains ball, no (1.01 r)" };
  for (int k = 0; k < 3; ++k)
  {
    const double e = k == 0 ? engines[0].Closest : k == 1 ? engines[0].Yes : engines[0].No;
    const double o = k == 0 ? engines[1].Closest : k == 1 ? engines[1].Yes : engines[1].No;
    std::printf("| %s | %.2f | %.2f | %.1fx |\n", kinds[k], e, o, e / o);
  }
  std::printf("\nMethod rows: wall time per sample without the preparation (a 1-sample run is subtracted).\n");
  std::printf("| query or method | us per sample | mean iterations | ratio to limit | 2-thread speed-up |\n");
  std::printf("|---|---|---|---|---|\n");
  std::printf("| ray (2 threads) | %.2f | - | - | - |\n", rayMicro);
  std::printf("| bounded closest point from a medial centre (2 threads, own tree) | %.2f | - | - | - |\n", closestMicro);
  std::printf("| limit: ray + closest point | %.2f | - | 1.00 | - |\n", limitMicro);
  for (const Row& r : rows)
  {
    std::printf("| %s (%lld samples) | %.2f | %.2f | %.2f | %s |\n", r.Name.c_str(),
      static_cast<long long>(samples), r.MicrosecondsPerSample, r.Iterations,
      r.MicrosecondsPerSample / limitMicro, r.Extra > 0 ? std::to_string(r.Extra).substr(0, 4).c_str() : "-");
  }
  std::printf("\ndefault method (%s), %lld samples, 2 threads: %.2f s with the preparation (sampling "
              "alone %.2f us per sample, %.2f iterations, %lld capped)\n",
    vtkMedialAxisSampler::GetMethodName(defaultMethod), static_cast<long long>(defaultSamples),
    defaultSeconds, defaultMicro, itDefault, static_cast<long long>(cappedDefault));
  std::printf("worst case, sphere %lld triangles, default method, 2 threads: %.2f us per sample "
              "(%.1fx the horse)\n",
    static_cast<long long>(sphere->GetOutput()->GetNumberOfCells()), sphereMicro, sphereMicro / defaultMicro);
  std::printf("peak RSS: %.0f MiB\n", rss);
  std::ostringstream unused;
  PrintStructure(structure, structureLabel, json, unused);
  return 0;
}
