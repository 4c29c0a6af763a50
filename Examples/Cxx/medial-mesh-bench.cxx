// SPDX-License-Identifier: BSD-3-Clause
// medial-mesh-bench: the medial mesh (vtkMedialMeshFilter) of the shared meshes.
//
// For each mesh (default: the five shared meshes, then generated solids: sphere, box,
// torus, hollow sphere, and RINGS of genus 1, 2 and 3): vtkMedialAxisSampler with its defaults (10000 samples, theta 45,
// one-pass) on T threads (default 2), then vtkMedialMeshFilter on those balls, both
// timed (wall); the mesh's V, E, F, Euler characteristic and components beside the
// solid's; the balls dropped and the largest radius reduction (inscribing). Prints a
// table. Then the shape rebuilt from the mesh by vtkMedialBallUnion at N^3 grid points:
// the interpolated envelope (MEDIAL_MESH primitives) and, for comparison, the union of
// the same (inscribed) balls, each against the original with vtkMedialReconstructionError
// (vertex to surface, both directions, and the two-sided area measure; % of the
// diagonal).
//
// --check-solids: instead, whether each mesh bounds a valid solid (vtkMedialSolidCheck,
// its pairs decided by CGAL's exact predicates: manifold and oriented, closed, outward,
// collapsed triangles, intersecting triangle pairs) beside its surface's and solid's Euler
// characteristics.
//
// --sweep: instead, for every sample count of --counts and every seed of --seeds, the
// sampling time, the medial mesh time and their ratio (the target: at most 4, or a mesh
// time of at most 0.5 s), and the mesh's Euler characteristic and components against
// the solid's (the expected values; "ok" when equal), measured in the same run.
// Not a test: it checks nothing.
//
// usage: medial-mesh-bench [--threads T] [--samples N] [--resolution N] [--protrusion E] [MESH...]
//        [--no-classifier] (--protrusion: the filter's ProtrusionTolerance; -1 turns the
//        pruning off; --no-classifier: no governors, exact junctions or point types from them)
//        [--check-solids] [--sweep [--counts N1,N2,...] [--seeds S1,S2,...]]
//        (MESH: a file, or generated:sphere|box|torus|hollow-sphere|rings1|rings2|rings3, with
//        "@R" for vtkMedialShapeSource's Resolution R instead of the bench's default)

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// Points of the mesh with the given MedialPointType.
vtkIdType CountType(vtkPolyData* mesh, int type)
{
  vtkDataArray* types = mesh->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  vtkIdType n = 0;
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    n += static_cast<int>(types->GetTuple1(i)) == type;
  }
  return n;
}

// A generated solid by name ("generated:torus", ...), or null for a file name.
vtkSmartPointer<vtkPolyData> Generated(const std::string& name)
{
  const std::string prefix = "generated:";
  if (name.rfind(prefix, 0) != 0)
  {
    return nullptr;
  }
  std::string shape = name.substr(prefix.size());
  int resolution = 0; // "@R": this resolution instead of the default below
  const size_t at = shape.find('@');
  if (at != std::string::npos)
  {
    resolution = std::atoi(shape.c_str() + at + 1);
    shape = shape.substr(0, at);
  }
  vtkNew<vtkMedialShapeSource> source;
  if (shape == "sphere")
  {
    source->SetShapeToSphere();
    source->SetResolution(4);
  }
  else if (shape == "box")
  {
    source->SetShapeToBox();
    source->SetResolution(8);
  }
  else if (shape == "torus")
  {
    source->SetShapeToTorus();
    source->SetResolution(16);
  }
  else if (shape == "hollow-sphere")
  {
    source->SetShapeToHollowSphere();
    source->SetResolution(4);
  }
  else if (shape.rfind("rings", 0) == 0)
  {
    source->SetShapeToRings();
    source->SetGenus(std::atoi(shape.c_str() + 5));
  }
  else
  {
    return nullptr;
  }
  if (resolution > 0)
  {
    source->SetResolution(resolution);
  }
  source->Update();
  return source->GetOutput();
}

struct BenchOptions
{
  int Threads = 2;
  vtkIdType Samples = 10000;
  int Resolution = 128;
  double Protrusion = -2.0; // below -1: the filter's default
  bool Classify = true;
  bool CheckSolids = false;
  bool Sweep = false;
  std::vector<long long> Counts = { 10000, 20000, 50000, 100000, 200000 };
  std::vector<long long> Seeds = { 1, 7, 42 };
  std::vector<std::string> Meshes;
};

// "1,2,3" as numbers.
std::vector<long long> ParseList(const char* text)
{
  std::vector<long long> values;
  for (const char* p = text; *p;)
  {
    char* end = nullptr;
    values.push_back(std::strtoll(p, &end, 10));
    p = *end == ',' ? end + 1 : end + std::strlen(end);
  }
  return values;
}

// False when the program should stop at once with `exitCode` (help or usage, printed).
bool ParseArgs(int argc, char* argv[], BenchOptions& options, int& exitCode)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc)
    {
      options.Threads = std::atoi(argv[++i]);
    }
    else if (a == "--samples" && i + 1 < argc)
    {
      options.Samples = std::atoll(argv[++i]);
    }
    else if (a == "--resolution" && i + 1 < argc)
    {
      options.Resolution = std::atoi(argv[++i]);
    }
    else if (a == "--protrusion" && i + 1 < argc)
    {
      options.Protrusion = std::atof(argv[++i]);
    }
    else if (a == "--no-classifier")
    {
      options.Classify = false;
    }
    else if (a == "--check-solids")
    {
      options.CheckSolids = true;
    }
    else if (a == "--sweep")
    {
      options.Sweep = true;
    }
    else if (a == "--counts" && i + 1 < argc)
    {
      options.Counts = ParseList(argv[++i]);
    }
    else if (a == "--seeds" && i + 1 < argc)
    {
      options.Seeds = ParseList(argv[++i]);
    }
    else if (!a.empty() && a[0] == '-')
    {
      std::printf("usage: medial-mesh-bench [--threads T] [--samples N] [--resolution N] [--protrusion E] "
                  "[--no-classifier] [--check-solids] [--sweep [--counts N1,N2,...] [--seeds S1,S2,...]] [MESH...]\n");
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

// The shared meshes that are present, then the generated solids.
std::vector<std::string> DefaultMeshes()
{
  std::vector<std::string> meshes;
  for (const char* name : { "horse.ply", "rocker-arm.obj", "fandisk.obj", "spot.obj", "stanford-bunny.obj" })
  {
    const std::string path = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/" + name;
    struct stat st;
    if (stat(path.c_str(), &st) == 0)
    {
      meshes.push_back(path);
    }
  }
  for (const char* name : { "sphere", "box", "torus", "hollow-sphere", "rings1", "rings2", "rings3" })
  {
    meshes.push_back(std::string("generated:") + name);
  }
  return meshes;
}

// The settings line (with the load average).
void PrintSettings(const BenchOptions& options)
{
  double load[3] = { -1, -1, -1 };
  if (FILE* f = std::fopen("/proc/loadavg", "r"))
  {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3)
    {
      load[0] = -1;
    }
    std::fclose(f);
  }
  std::printf("classifier %s, threads %d, %lld samples, sampler defaults otherwise; load average at start %.2f %.2f "
              "%.2f; times in seconds (wall)\n",
    options.Classify ? "on" : "off", options.Threads, static_cast<long long>(options.Samples), load[0], load[1],
    load[2]);
}

// The medial mesh table's column names.
void PrintHeader()
{
  std::printf("%-20s %6s %6s %6s %4s %5s %8s %5s %6s %6s %7s %9s %8s %8s %8s\n", "mesh", "V", "E", "F",
    "chi", "comp", "solid_chi", "solid", "seams", "junct", "dropped", "shrink%", "sample_s", "mesh_s",
    "total_s");
}

// Samples the surface's balls, builds their medial mesh with `filter` and prints its row.
void BenchMedialMesh(
  vtkPolyData* surface, const std::string& name, vtkMedialMeshFilter* filter, const BenchOptions& options)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(options.Samples);
  sampler->SetNumberOfThreads(options.Threads);
  auto start = std::chrono::steady_clock::now();
  sampler->Update();
  const double sampleSeconds = Seconds(start);
  filter->SetInputData(surface);
  filter->SetBallsConnection(sampler->GetOutputPort());
  filter->SetNumberOfThreads(options.Threads);
  if (!options.Classify)
  {
    filter->SetClassifier(nullptr);
  }
  if (options.Protrusion >= -1.0)
  {
    filter->SetProtrusionTolerance(options.Protrusion);
  }
  start = std::chrono::steady_clock::now();
  filter->Update();
  const double meshSeconds = Seconds(start);
  vtkPolyData* mesh = filter->GetOutput();
  std::printf("%-20s %6lld %6lld %6lld %4lld %5lld %8s %5s %6lld %6lld %7lld %9.4f %8.2f %8.2f %8.2f\n",
    name.c_str(), static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(filter->GetNumberOfEdges()), static_cast<long long>(mesh->GetNumberOfPolys()),
    static_cast<long long>(filter->GetEulerCharacteristic()),
    static_cast<long long>(filter->GetNumberOfComponents()),
    filter->GetHasSolidTopology() ? std::to_string(filter->GetSolidEulerCharacteristic()).c_str() : "-",
    filter->GetHasSolidTopology() ? std::to_string(filter->GetSolidComponents()).c_str() : "-",
    static_cast<long long>(CountType(mesh, 2)), static_cast<long long>(CountType(mesh, 3)),
    static_cast<long long>(filter->GetDroppedBalls()), 100 * filter->GetMaximumRadiusReduction(),
    sampleSeconds, meshSeconds, sampleSeconds + meshSeconds);
  std::fflush(stdout);
}

// --check-solids: the valid-solid verdict (vtkMedialSolidCheck, decided with CGAL's
// predicates) on the prepared surface; the seconds are the check's (the tree included).
void CheckSolid(vtkPolyData* surface, const std::string& name, int threads)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  if (!mesh.Build(surface, error))
  {
    std::printf("%-20s cannot be prepared: %s\n", name.c_str(), error.c_str());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  vtkMedialSurfaceQuery query;
  query.Build(&mesh, error);
  vtkMedialSolidCheck r;
  r.Run(mesh, query, threads, true);
  r.Decide(mesh, vtkMedialRepairFilter::ExactPairTest);
  const double seconds = Seconds(start);
  const vtkIdType chi = mesh.GetEulerCharacteristic();
  const bool manifold = r.NonManifoldEdges == 0 && r.NonOrientableShells == 0;
  const bool closed = r.BoundaryEdges == 0;
  std::printf("%-20s %9lld %8s %6s %8s %9lld %10lld %9lld %9s %-5s %7.2f\n", name.c_str(),
    static_cast<long long>(mesh.GetNumberOfTriangles()), manifold ? "yes" : "no", manifold ? (closed ? "yes" : "no") : "-",
    closed && r.Intersecting.empty() && r.DegenerateTriangles == 0 ? (!r.NoVolume && r.ShellContacts == 0 ? "yes" : "no") : "-",
    static_cast<long long>(r.DegenerateTriangles), static_cast<long long>(r.Intersecting.size()),
    static_cast<long long>(chi), chi % 2 == 0 ? std::to_string(chi / 2).c_str() : "-",
    r.IsValidSolid() ? "yes" : "NO", seconds);
  std::fflush(stdout);
}

// Peak resident memory of this process so far (MiB), from /proc/self/status.
double PeakResidentMiB()
{
  double kib = -1.0;
  if (FILE* f = std::fopen("/proc/self/status", "r"))
  {
    char line[256];
    while (std::fgets(line, sizeof(line), f))
    {
      if (std::strncmp(line, "VmHWM:", 6) == 0)
      {
        kib = std::atof(line + 6);
      }
    }
    std::fclose(f);
  }
  return kib / 1024.0;
}

// --sweep: one row per sample count and seed: the times and their ratio, the topology
// against the solid's.
void Sweep(vtkPolyData* surface, const std::string& name, const BenchOptions& options)
{
  for (long long count : options.Counts)
  {
    for (long long seed : options.Seeds)
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(surface);
      sampler->SetNumberOfSamples(count);
      sampler->SetNumberOfThreads(options.Threads);
      sampler->SetRandomSeed(seed);
      auto start = std::chrono::steady_clock::now();
      sampler->Update();
      const double sampleSeconds = Seconds(start);
      vtkNew<vtkMedialMeshFilter> filter;
      filter->SetInputData(surface);
      filter->SetBallsConnection(sampler->GetOutputPort());
      filter->SetNumberOfThreads(options.Threads);
      if (!options.Classify)
      {
        filter->SetClassifier(nullptr);
      }
      start = std::chrono::steady_clock::now();
      filter->Update();
      const double meshSeconds = Seconds(start);
      const double ratio = meshSeconds / sampleSeconds;
      const bool fast = ratio <= 4.0 || meshSeconds <= 0.5;
      const bool solid = filter->GetHasSolidTopology();
      const bool right = solid && filter->GetEulerCharacteristic() == filter->GetSolidEulerCharacteristic() &&
        filter->GetNumberOfComponents() == filter->GetSolidComponents();
      std::printf("%-20s %7lld %5lld %8.2f %8.2f %6.2f %-4s %5lld %5s %5lld %5s %-4s %8.0f\n", name.c_str(), count,
        seed, sampleSeconds, meshSeconds, ratio, fast ? "ok" : "SLOW",
        static_cast<long long>(filter->GetEulerCharacteristic()),
        solid ? std::to_string(filter->GetSolidEulerCharacteristic()).c_str() : "-",
        static_cast<long long>(filter->GetNumberOfComponents()),
        solid ? std::to_string(filter->GetSolidComponents()).c_str() : "-", solid ? (right ? "ok" : "BAD") : "-",
        PeakResidentMiB());
      std::fflush(stdout);
    }
  }
}

struct Error
{
  double Max[2], Mean[2], Area, Seconds;
};
struct ErrorRow
{
  std::string Name;
  Error Envelope, Union;
};

// The shape rebuilt from the medial mesh (envelope, then the union of its balls) and
// each one's error against the surface.
ErrorRow MeasureReconstruction(
  vtkPolyData* surface, vtkPolyData* mesh, const std::string& name, const BenchOptions& options)
{
  ErrorRow row{ name, {}, {} };
  for (int primitives : { vtkMedialBallUnion::MEDIAL_MESH, vtkMedialBallUnion::BALLS })
  {
    vtkNew<vtkMedialBallUnion> rebuild;
    rebuild->SetInputData(mesh);
    rebuild->SetPrimitives(primitives);
    rebuild->SetSampleDimensions(options.Resolution, options.Resolution, options.Resolution);
    rebuild->SetNumberOfThreads(options.Threads);
    const auto start = std::chrono::steady_clock::now();
    rebuild->Update();
    Error& e = primitives == vtkMedialBallUnion::BALLS ? row.Union : row.Envelope;
    e.Seconds = Seconds(start);
    vtkNew<vtkMedialReconstructionError> measure;
    measure->SetOriginalData(surface);
    measure->SetReconstructionConnection(rebuild->GetOutputPort());
    measure->SetNumberOfThreads(options.Threads);
    measure->Update();
    for (int k = 0; k < 2; ++k)
    {
      e.Max[k] = measure->GetVertexMaxError()[k];
      e.Mean[k] = measure->GetVertexMeanError()[k];
    }
    e.Area = measure->GetAreaHausdorff();
  }
  return row;
}

void PrintErrors(const std::vector<ErrorRow>& errors, int resolution)
{
  std::printf("\nreconstruction at %d^3, %% of the diagonal (max / mean), rebuilt -> original and "
              "original -> rebuilt\n",
    resolution);
  std::printf("%-20s %-9s %9s %9s %9s %9s %9s %8s\n", "mesh", "shape", "rec>max", "rec>mean", "orig>max",
    "orig>mean", "area_hd", "seconds");
  for (const ErrorRow& row : errors)
  {
    for (int k = 0; k < 2; ++k)
    {
      const Error& e = k == 0 ? row.Envelope : row.Union;
      std::printf("%-20s %-9s %9.3f %9.4f %9.3f %9.4f %9.3f %8.2f\n", row.Name.c_str(), k == 0 ? "envelope" : "balls",
        100 * e.Max[0], 100 * e.Mean[0], 100 * e.Max[1], 100 * e.Mean[1], 100 * e.Area, e.Seconds);
    }
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
  if (options.Meshes.empty())
  {
    options.Meshes = DefaultMeshes();
  }
  if (options.CheckSolids)
  {
    std::printf("The valid-solid check on the prepared surface (vtkMedialSolidCheck, CGAL's predicates); seconds for the check\n");
    std::printf("%-20s %9s %8s %6s %8s %9s %10s %9s %9s %-5s %7s\n", "mesh", "triangles", "manifold", "closed",
      "outward", "collapsed", "intersect", "surf_chi", "solid_chi", "valid", "seconds");
  }
  else if (options.Sweep)
  {
    PrintSettings(options);
    std::printf("%-20s %7s %5s %8s %8s %6s %-4s %5s %5s %5s %5s %-4s %8s\n", "mesh", "samples", "seed", "sample_s",
      "mesh_s", "ratio", "<=4x", "chi", "want", "comp", "want", "topo", "peak_MiB");
  }
  else
  {
    PrintSettings(options);
    PrintHeader();
  }
  std::vector<ErrorRow> errors;
  for (const std::string& path : options.Meshes)
  {
    vtkSmartPointer<vtkPolyData> surface = Generated(path);
    if (!surface)
    {
      vtkNew<vtkMedialFileReader> reader;
      reader->SetFileName(path.c_str());
      reader->Update();
      surface = reader->GetOutput();
    }
    const std::string name = path.substr(path.find_last_of("/:") + 1);
    if (options.CheckSolids)
    {
      CheckSolid(surface, name, options.Threads);
      continue;
    }
    if (options.Sweep)
    {
      Sweep(surface, name, options);
      continue;
    }
    vtkNew<vtkMedialMeshFilter> filter;
    BenchMedialMesh(surface, name, filter, options);
    errors.push_back(MeasureReconstruction(surface, filter->GetOutput(), name, options));
  }
  if (!errors.empty())
  {
    PrintErrors(errors, options.Resolution);
  }
  return 0;
}
