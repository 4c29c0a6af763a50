// SPDX-License-Identifier: BSD-3-Clause
// medial-bench: throughput of the medial sampler and of its BVH queries.
//
// Input: horse.ply from ../shared/data/meshes, Loop-subdivided twice (>= 1.5 M
// triangles); without the shared data, a generated demo shape of the same size.
// Measures, in one run: BVH build time, ray throughput, closest-point and
// contains-ball throughput on the tree (vtkMedialTriangleBVH),
// each method with 1 and 2 threads (with mean iterations), each method's ratios to
// the "limit" (one ray plus one bounded closest-point query per sample) and to the
// bisection method with the same thread count, peak RSS,
// and a 327k-triangle sphere as the worst case; then the 3D classification
// (vtkMedialBallClassifier) of horse.ply's default balls, without and with the exact
// seams and junctions, at theta = 45 and 0 (--structure runs only these rows); and
// the sampling strategies' wall time per sample on horse.ply against Random's, in
// the same run, and Random's with a coverage stop that is never reached, which keeps
// the same exact coverage as the strategies (--strategies runs only these rows).
// --cli-run runs only the command-line rows: the CLI itself, as a user runs it, on
// the horse Loop-subdivided twice written as a binary PLY (or --surface FILE), 1M
// balls written to a .vtp, without and with --stats, in alternating rounds: wall and
// CPU seconds, peak RSS and preparation of each run against issue 37's targets (6 s,
// 500 MiB, 0.7 s), and what --stats costs against the same round's run without it
// (target: 10%).
// Prints a table, or one JSON object with --json. Not a test: it checks nothing.
#include "MedialAxisRuntime.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialBuffer.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialRandom.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <omp.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace
{
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// User + system CPU seconds of the process so far (all threads): on a shared machine
// a stage's CPU time varies less than its wall time.
double CpuSeconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Resident size now (Linux /proc/self/statm; 0 elsewhere).
double CurrentRssMiB()
{
  long pages = 0, resident = 0;
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f)
  {
    return 0.0;
  }
  const int read = std::fscanf(f, "%ld %ld", &pages, &resident);
  std::fclose(f);
  return read == 2 ? resident * (sysconf(_SC_PAGESIZE) / 1048576.0) : 0.0;
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
  double ToBisection = 0; // against the bisection row with the same thread count, same run
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

// When a sampler's surface preparation ended: the start of the stage that follows
// "Building the surface queries", seen through the stage names the sampler gives as
// its progress text.
struct PreparationEnd
{
  double Time = 0.0; // 0 until seen
  bool Building = false;
  static void OnProgress(vtkObject* caller, unsigned long, void* clientData, void*)
  {
    PreparationEnd* self = static_cast<PreparationEnd*>(clientData);
    const char* text = static_cast<vtkAlgorithm*>(caller)->GetProgressText();
    const bool building = text && std::strcmp(text, "Building the surface queries") == 0;
    if (self->Building && !building && self->Time == 0.0)
    {
      self->Time = Now();
    }
    self->Building = self->Building || building;
  }
};

// Updates the sampler; returns its wall seconds, and in `solving` those after its
// surface preparation (drawing, solving, the output), from its own stages.
double UpdateTimed(vtkMedialAxisSampler* sampler, double& solving)
{
  PreparationEnd prepared;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(PreparationEnd::OnProgress);
  observer->SetClientData(&prepared);
  const unsigned long tag = sampler->AddObserver(vtkCommand::ProgressEvent, observer);
  const double t0 = Now();
  sampler->Update();
  const double t1 = Now();
  sampler->RemoveObserver(tag);
  if (prepared.Time == 0.0)
  {
    // The stage was renamed or the run failed early: say so rather than count the
    // preparation as sampling without a word.
    std::fprintf(stderr, "medial-bench: no \"Building the surface queries\" stage seen; the row includes the "
                         "preparation\n");
  }
  solving = t1 - (prepared.Time > 0.0 ? prepared.Time : t0);
  return t1 - t0;
}

// Runs the sampler; returns its wall seconds with the preparation, and in `solving`
// those after it (drawing, solving, the output).
double TimeSampler(vtkPolyData* mesh, int method, int threads, vtkIdType samples, double& iterations,
  vtkIdType& capped, double& solving)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(mesh);
  sampler->SetMethod(method);
  sampler->SetNumberOfThreads(threads);
  sampler->SetNumberOfSamples(samples);
  const double seconds = UpdateTimed(sampler, solving);
  iterations = sampler->GetMeanIterations();
  capped = sampler->GetCappedSamples();
  return seconds;
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

// One row per sampling strategy: wall time per evaluated sample without the
// preparation (timed from the sampler's own stages), the median of 3 rounds that
// alternate the strategies, and the median of the per-round ratios to Random. One more
// row runs Random with a coverage stop that is never reached (tolerance 1e-12): the
// same samples with the exact coverage (vtkMedialCoverage) that both iterative
// strategies keep, added after each block of 1024 samples. Its blocks are solved in
// leaf order within each block only, so it also loses some of Random's cache and hint
// sharing: a bound on what keeping the coverage costs, not that cost alone.
struct StrategyRow
{
  std::string Name;
  vtkIdType Evaluated;
  double MicrosecondsPerSample;
  double RatioToRandom;
};

// The same rounds also compare at equal coverage, what a user who asks for a coverage
// waits for: the target is the largest gap Random leaves with the samples asked (the
// row above that keeps the coverage), and each strategy runs with that coverage stop
// (a cap of 40 times the samples asked). Random's time is taken with the stop (what
// the user runs) and without it at exactly the count the stop needed (the least Random
// could cost, knowing the count in advance); each ratio is the strategy's wall time
// over Random's in the same round (median of 3).
struct EqualCoverageRow
{
  std::string Name;
  vtkIdType Evaluated;
  bool Reached;
  double Seconds; // without the preparation
  double RatioToStop, RatioToPlain;
};

struct StrategyFigures
{
  std::vector<StrategyRow> Rows;
  double TargetGap = 0.0;   // relative to the diagonal
  double RandomPlainSeconds = 0.0; // Random without a stop, at the count its stop needed
  std::vector<EqualCoverageRow> EqualCoverage;
};

double Median3(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

StrategyFigures RunStrategies(vtkPolyData* mesh, vtkIdType samples)
{
  constexpr int Rows = 4;
  const int strategies[Rows] = { vtkMedialAxisSampler::RANDOM, vtkMedialAxisSampler::CLOSEST_NEIGHBOR,
    vtkMedialAxisSampler::FACE_DISTANCE, vtkMedialAxisSampler::RANDOM };
  const double coverageStop[Rows] = { 0.0, 0.0, 0.0, 1e-12 };
  struct Run
  {
    double Seconds = 0.0, Gap = -1.0;
    vtkIdType Evaluated = 0;
    bool Reached = false;
  };
  auto timed = [&](int strategy, double stop, vtkIdType n) {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(mesh);
    sampler->SetSamplingStrategy(strategy);
    sampler->SetCoverageTolerance(stop);
    sampler->SetNumberOfThreads(2);
    sampler->SetNumberOfSamples(n);
    Run run;
    UpdateTimed(sampler, run.Seconds);
    run.Evaluated = sampler->GetEvaluatedSamples(); // a coverage stop may end a run early
    run.Gap = sampler->GetMaxCoverageGap();
    run.Reached = sampler->GetCoverageReached();
    return run;
  };
  std::vector<double> micro[Rows], ratio[Rows];
  vtkIdType evaluated[Rows] = { 0, 0, 0, 0 };
  constexpr int Equal = 3; // random, closest-neighbor, face-distance (strategies[0..2])
  std::vector<double> equalSeconds[Equal], toStop[Equal], toPlain[Equal], plainSeconds;
  Run equal[Equal];
  StrategyFigures figures;
  for (int round = 0; round < 3; ++round)
  {
    Run runs[Rows];
    for (int k = 0; k < Rows; ++k)
    {
      runs[k] = timed(strategies[k], coverageStop[k], samples);
      evaluated[k] = runs[k].Evaluated;
      micro[k].push_back(1e6 * runs[k].Seconds / std::max<vtkIdType>(evaluated[k], 1));
      ratio[k].push_back(micro[k].back() / micro[0].back());
    }
    figures.TargetGap = runs[3].Gap; // the same every round: the runs are deterministic
    for (int k = 0; k < Equal; ++k)
    {
      equal[k] = timed(strategies[k], figures.TargetGap, 40 * samples);
    }
    const Run plain = timed(vtkMedialAxisSampler::RANDOM, 0.0, equal[0].Evaluated);
    plainSeconds.push_back(plain.Seconds);
    for (int k = 0; k < Equal; ++k)
    {
      equalSeconds[k].push_back(equal[k].Seconds);
      toStop[k].push_back(equal[k].Seconds / equal[0].Seconds);
      toPlain[k].push_back(equal[k].Seconds / plain.Seconds);
    }
  }
  for (int k = 0; k < Rows; ++k)
  {
    const std::string name = vtkMedialAxisSampler::GetSamplingStrategyName(strategies[k]);
    figures.Rows.push_back({ coverageStop[k] > 0.0 ? name + "-keeping-coverage" : name, evaluated[k],
      Median3(micro[k]), Median3(ratio[k]) });
  }
  figures.RandomPlainSeconds = Median3(plainSeconds);
  for (int k = 0; k < Equal; ++k)
  {
    figures.EqualCoverage.push_back({ vtkMedialAxisSampler::GetSamplingStrategyName(strategies[k]),
      equal[k].Evaluated, equal[k].Reached, Median3(equalSeconds[k]), Median3(toStop[k]), Median3(toPlain[k]) });
  }
  return figures;
}

void PrintStrategies(const StrategyFigures& figures, const std::string& label, vtkIdType samples, bool json,
  std::ostringstream& js)
{
  if (json)
  {
    js << ", \"strategies_mesh\": \"" << label << "\", \"strategies_samples\": " << samples;
    for (const StrategyRow& r : figures.Rows)
    {
      js << ", \"strategy_" << r.Name << "\": {\"evaluated\": " << r.Evaluated
         << ", \"us_per_sample\": " << r.MicrosecondsPerSample << ", \"ratio_to_random\": " << r.RatioToRandom
         << "}";
    }
    js << ", \"equal_coverage_gap\": " << figures.TargetGap
       << ", \"equal_coverage_random_plain_seconds\": " << figures.RandomPlainSeconds;
    for (const EqualCoverageRow& r : figures.EqualCoverage)
    {
      js << ", \"equal_coverage_" << r.Name << "\": {\"evaluated\": " << r.Evaluated
         << ", \"reached\": " << (r.Reached ? "true" : "false") << ", \"seconds\": " << r.Seconds
         << ", \"ratio_to_random\": " << r.RatioToStop << ", \"ratio_to_random_plain\": " << r.RatioToPlain
         << "}";
    }
    return;
  }
  std::printf("\nSampling strategies on %s, %lld samples asked, 2 threads: wall time per evaluated sample without "
              "the preparation, median of 3 alternating rounds; ratio to Random in the same round (median):\n",
    label.c_str(), static_cast<long long>(samples));
  std::printf("| strategy | samples evaluated | us per sample | ratio to random |\n");
  std::printf("|---|---|---|---|\n");
  for (const StrategyRow& r : figures.Rows)
  {
    std::printf("| %s | %lld | %.2f | %.2f |\n", r.Name.c_str(), static_cast<long long>(r.Evaluated),
      r.MicrosecondsPerSample, r.RatioToRandom);
  }
  std::printf("\nAt equal coverage, same rounds: each strategy with a coverage stop at %.6g of the diagonal (the "
              "largest gap Random leaves with %lld samples), wall seconds without the preparation; ratio to Random "
              "with the same stop, and to Random without it at the count its stop needed (%.3f s) (medians):\n",
    figures.TargetGap, static_cast<long long>(samples), figures.RandomPlainSeconds);
  std::printf("| strategy | samples evaluated | coverage reached | seconds | ratio to random | "
              "ratio to random without the stop |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const EqualCoverageRow& r : figures.EqualCoverage)
  {
    std::printf("| %s | %lld | %s | %.3f | %.2f | %.2f |\n", r.Name.c_str(), static_cast<long long>(r.Evaluated),
      r.Reached ? "yes" : "no", r.Seconds, r.RatioToStop, r.RatioToPlain);
  }
}

// Microseconds per sample (wall), without the preparation (merge, orientation, tree
// build), timed from the sampler's own stages in the same run. (Subtracting a separate
// 1-sample run, as before, let the preparation's first-touch page faults, which vary
// by up to 0.5 s between runs on this project's VM, swing a 50k-sample row by 10 us.)
double RunSampler(vtkPolyData* mesh, int method, int threads, vtkIdType samples, double& iterations,
  vtkIdType& capped, double* totalSeconds = nullptr)
{
  double solving = 0.0;
  const double seconds = TimeSampler(mesh, method, threads, samples, iterations, capped, solving);
  if (totalSeconds)
  {
    *totalSeconds = seconds;
  }
  return 1e6 * solving / samples;
}

struct BenchOptions
{
  bool Json = false;
  bool StructureOnly = false;
  std::string PreparationFile; // --preparation: only the preparation rows, on this surface
  bool CliRun = false;         // --cli-run: only the command-line rows
  std::string CliSurface;      // --surface: their input (default: the subdivided horse as PLY)
  std::string Cli;             // --cli: the medial-axis program (default: next to this one)
  int CliRounds = 3;           // --rounds
  bool StrategiesOnly = false;
  vtkIdType StrategySamples = 50000;
  vtkIdType Samples = 200000;
  vtkIdType DefaultSamples = 1000000;
  std::string SharedDir = MEDIALAXIS_SHARED_MESH_DIR;
};

// False (after printing the usage) on an unknown or incomplete argument.
bool ParseArgs(int argc, char* argv[], BenchOptions& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--json")
    {
      options.Json = true;
    }
    else if (a == "--structure")
    {
      options.StructureOnly = true;
    }
    else if (a == "--strategies")
    {
      options.StrategiesOnly = true;
    }
    else if (a == "--strategy-samples" && i + 1 < argc)
    {
      options.StrategySamples = std::atoll(argv[++i]);
    }
    else if (a == "--samples" && i + 1 < argc)
    {
      options.Samples = std::atoll(argv[++i]);
    }
    else if (a == "--default-samples" && i + 1 < argc)
    {
      options.DefaultSamples = std::atoll(argv[++i]);
    }
    else if (a == "--preparation" && i + 1 < argc)
    {
      options.PreparationFile = argv[++i];
    }
    else if (a == "--shared" && i + 1 < argc)
    {
      options.SharedDir = argv[++i];
    }
    else if (a == "--cli-run")
    {
      options.CliRun = true;
    }
    else if (a == "--surface" && i + 1 < argc)
    {
      options.CliSurface = argv[++i];
    }
    else if (a == "--cli" && i + 1 < argc)
    {
      options.Cli = argv[++i];
    }
    else if (a == "--rounds" && i + 1 < argc)
    {
      options.CliRounds = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::fprintf(stderr,
        "usage: medial-bench [--json] [--samples N (per method run, default 200000)]\n"
        "                    [--default-samples N (default method, 2 threads; default 1000000)]\n"
        "                    [--shared DIR] [--structure (only the 3D classification rows)]\n"
        "                    [--preparation SURFACE (only the preparation rows, on that file)]\n"
        "                    [--strategies (only the sampling-strategy rows)]\n"
        "                    [--strategy-samples N (per strategy run, default 50000)]\n"
        "                    [--cli-run (only the command-line rows: 1M balls, --stats) [--surface FILE]\n"
        "                     [--cli MEDIAL_AXIS] [--rounds N (default 3)]]\n");
      return false;
    }
  }
  return true;
}

// The engines the query rows measure. main owns them for the whole run, so that the
// peak RSS counts them while the methods run.
struct QueryEngines
{
  vtkMedialTriangleMesh Prepared;
  vtkMedialSurfaceQuery Query;
  vtkMedialTriangleBVH OwnTree;
  vtkNew<vtkMedialAxisSampler> Probe; // medial centres for the point queries
};

// Point-query times on one engine, microseconds per query.
struct EngineRow
{
  double Closest, Yes, No;
};

// Everything a full run measures, for PrintJson and PrintTables.
struct BenchFigures
{
  std::string Label;
  vtkIdType Triangles = 0;
  double LoadSeconds = 0, PrepareSeconds = 0, BvhSeconds = 0, TreeSeconds = 0;
  vtkIdType TreeNodes = 0;
  double RayMicro = 0, ClosestMicro = 0, LimitMicro = 0;
  EngineRow Points = {};
  std::vector<Row> Rows;
  int DefaultMethod = 0;
  double DefaultIterations = 0;
  vtkIdType DefaultCapped = 0;
  double DefaultSeconds = 0; // including the preparation
  double DefaultToBisection = 0, DefaultToLimit = 0; // 2-thread method rows, same run
  double DefaultMicro = 0;
  vtkIdType SphereTriangles = 0;
  double SphereMicro = 0;
  double PeakRss = 0;
};

// Preparation and BVH build, timed apart from sampling. False (after printing the
// error) when the mesh cannot be prepared.
bool BuildEngines(vtkPolyData* mesh, QueryEngines& engines, BenchFigures& figures)
{
  std::string error;
  const double tPrep = Now();
  if (!engines.Prepared.Build(mesh, error))
  {
    std::fprintf(stderr, "medial-bench: %s\n", error.c_str());
    return false;
  }
  figures.PrepareSeconds = Now() - tPrep;
  const double tBvh = Now();
  if (!engines.Query.Build(&engines.Prepared, error))
  {
    std::fprintf(stderr, "medial-bench: %s\n", error.c_str());
    return false;
  }
  figures.BvhSeconds = Now() - tBvh;
  // The tree alone (query.Build makes it and little else).
  const double tTree = Now();
  engines.OwnTree.Build(engines.Prepared);
  figures.TreeSeconds = Now() - tTree;
  figures.Triangles = engines.Prepared.GetNumberOfTriangles();
  figures.TreeNodes = engines.OwnTree.GetNumberOfNodes();
  return true;
}

// Ray throughput on 2 threads, microseconds per ray: rays from random surface points
// along the inward normal; intersect(p, n, t, hit) casts one. The hits go to `hits`
// (triangle, or -1) when given.
template <class Intersect>
double MeasureRays(const vtkMedialTriangleMesh& prepared, Intersect intersect, std::vector<vtkIdType>* hits = nullptr)
{
  const int queries = 200000;
  std::vector<vtkIdType> hitTriangles(queries);
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
    hitTriangles[i] = intersect(p, n, t, hit) ? hit.Triangle : -1;
  }
  const double micro = 1e6 * (Now() - tRay) / queries;
  if (hits)
  {
    *hits = std::move(hitTriangles);
  }
  return micro;
}
double MeasureRays(const vtkMedialTriangleMesh& prepared, vtkMedialSurfaceQuery& query)
{
  return MeasureRays(prepared, [&](const double* p, const double* n, vtkIdType t, vtkMedialSurfaceQuery::RayHit& hit) {
    return query.Intersect(p, n, 1e-9 * prepared.Diagonal, HUGE_VAL, t, hit);
  });
}

// Point queries from the medial centres of a short default run, on each engine:
// bounded closest point, and contains-ball just inside ("yes", must see every
// candidate) and just outside ("no", may stop at the first blocker) the medial radius.
void MeasurePointQueries(vtkPolyData* mesh, QueryEngines& engines, BenchFigures& figures)
{
  vtkMedialAxisSampler* probe = engines.Probe;
  probe->SetInputData(mesh);
  probe->SetNumberOfSamples(20000);
  probe->SetNumberOfThreads(2);
  probe->Update();
  vtkPolyData* medial = probe->GetOutput();
  const int probes = static_cast<int>(medial->GetNumberOfPoints());
  vtkDataArray* probeRadius = medial->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  vtkMedialSurfaceQuery& query = engines.Query;
  const double diagonal = engines.Prepared.Diagonal;
  {
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
          query.ClosestPoint(c, r + 1e-6 * diagonal, hit);
        }
        else
        {
          query.ContainsBall(c, kind == 1 ? r * (1 - 1e-6) : r * 1.01);
        }
      }
      return 1e6 * (Now() - t0) / probes;
    };
    figures.Points = { timed(0), timed(1), timed(2) };
  }
}

// The query rows: rays, then point queries from medial centres; the "limit" is one
// ray plus one bounded closest-point query (own tree) per sample.
void MeasureQueries(vtkPolyData* mesh, QueryEngines& engines, BenchFigures& figures)
{
  figures.RayMicro = MeasureRays(engines.Prepared, engines.Query);
  MeasurePointQueries(mesh, engines, figures);
  figures.ClosestMicro = figures.Points.Closest;
  figures.LimitMicro = figures.RayMicro + figures.ClosestMicro;
}

// Each method with 1 and 2 threads, the default method with the default sample
// count, and the worst case; then the peak RSS.
void MeasureMethods(vtkPolyData* mesh, const BenchOptions& options, BenchFigures& figures)
{
  vtkNew<vtkMedialAxisSampler> defaults;
  figures.DefaultMethod = defaults->GetMethod();
  double bisection[2] = { 0, 0 }; // BISECTION comes first: 1 and 2 threads
  for (int method = vtkMedialAxisSampler::BISECTION; method <= vtkMedialAxisSampler::ONE_PASS; ++method)
  {
    double it1, it2;
    vtkIdType capped1, capped2;
    const double one = RunSampler(mesh, method, 1, options.Samples, it1, capped1);
    const double two = RunSampler(mesh, method, 2, options.Samples, it2, capped2);
    if (method == vtkMedialAxisSampler::BISECTION)
    {
      bisection[0] = one;
      bisection[1] = two;
    }
    const std::string name = vtkMedialAxisSampler::GetMethodName(method);
    figures.Rows.push_back({ name + ", 1 thread", one, it1, 0, one / bisection[0] });
    figures.Rows.push_back({ name + ", 2 threads", two, it2, one / two, two / bisection[1] });
    if (method == figures.DefaultMethod)
    {
      figures.DefaultToBisection = two / bisection[1];
      figures.DefaultToLimit = two / figures.LimitMicro;
    }
  }
  figures.DefaultMicro = RunSampler(mesh, figures.DefaultMethod, 2, options.DefaultSamples,
    figures.DefaultIterations, figures.DefaultCapped, &figures.DefaultSeconds);

  // Worst case: a 327k-triangle sphere (every closest-point query sees many equidistant facets).
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(7);
  sphere->Update();
  double itSphere;
  vtkIdType cappedSphere;
  figures.SphereMicro = RunSampler(sphere->GetOutput(), figures.DefaultMethod, 2, 5000, itSphere, cappedSphere);
  figures.SphereTriangles = sphere->GetOutput()->GetNumberOfCells();
  figures.PeakRss = PeakRssMiB();
}

void PrintJson(const BenchFigures& f, const BenchOptions& options, const std::vector<StructureRow>& structure,
  const std::string& structureLabel, const std::string& strategiesJson)
{
  std::ostringstream js;
  js << "{\"mesh\": \"" << f.Label << "\", \"triangles\": " << f.Triangles << ", \"load_seconds\": " << f.LoadSeconds
     << ", \"prepare_seconds\": " << f.PrepareSeconds << ", \"bvh_seconds\": " << f.BvhSeconds
     << ", \"own_tree_seconds\": " << f.TreeSeconds << ", \"own_tree_nodes\": " << f.TreeNodes
     << ", \"ray_us\": " << f.RayMicro << ", \"closest_point_us\": " << f.ClosestMicro
     << ", \"limit_us\": " << f.LimitMicro;
  js << ", \"own_tree\": {\"closest_point_us\": " << f.Points.Closest
     << ", \"contains_ball_yes_us\": " << f.Points.Yes << ", \"contains_ball_no_us\": " << f.Points.No << "}";
  for (const Row& r : f.Rows)
  {
    js << ", \"" << r.Name << "\": {\"us_per_sample\": " << r.MicrosecondsPerSample
       << ", \"iterations\": " << r.Iterations << ", \"ratio_to_limit\": " << r.MicrosecondsPerSample / f.LimitMicro
       << ", \"ratio_to_bisection\": " << r.ToBisection << "}";
  }
  js << ", \"default_method\": \"" << vtkMedialAxisSampler::GetMethodName(f.DefaultMethod)
     << "\", \"default_to_bisection\": " << f.DefaultToBisection << ", \"default_to_limit\": " << f.DefaultToLimit
     << ", \"default_samples\": " << options.DefaultSamples << ", \"default_seconds\": " << f.DefaultSeconds
     << ", \"default_us_per_sample\": " << f.DefaultMicro << ", \"sphere_us_per_sample\": " << f.SphereMicro
     << ", \"sphere_to_horse\": " << f.SphereMicro / f.DefaultMicro << ", \"peak_rss_mib\": " << f.PeakRss;
  PrintStructure(structure, structureLabel, true, js);
  js << strategiesJson << "}";
  std::printf("%s\n", js.str().c_str());
}

// Which page size the large buffers used, and what a first touch costs now in each
// (vtkMedialBuffer.h). The restart passes the first process's decision on as
// MEDIALAXIS_HUGE_PAGES, so this process measures again, for the record only.
void PrintPages()
{
  const char* value = std::getenv("MEDIALAXIS_HUGE_PAGES");
  const vtkMedialFirstTouchCosts costs = vtkMedialFirstTouchProbe();
  std::printf("pages: %s for the large buffers (MEDIALAXIS_HUGE_PAGES=%s); first touch measured at the end: "
              "huge pages %.3f ms per MiB, 4 kB pages %.3f ms per MiB\n",
    vtkMedialBufferHugePages() ? "huge pages" : "4 kB pages", value ? value : "(unset)", costs.HugePages,
    costs.SmallPages);
}

void PrintTables(const BenchFigures& f, const BenchOptions& options, const std::vector<StructureRow>& structure,
  const std::string& structureLabel)
{
  std::printf("mesh: %s, %lld triangles\n", f.Label.c_str(), static_cast<long long>(f.Triangles));
  std::printf("load %.2f s, prepare (merge, orient) %.2f s, surface queries (the tree) %.2f s, "
              "tree alone %.2f s (%lld nodes)\n",
    f.LoadSeconds, f.PrepareSeconds, f.BvhSeconds, f.TreeSeconds, static_cast<long long>(f.TreeNodes));
  std::printf("\n| point query from a medial centre (2 threads, own tree) | us |\n|---|---|\n");
  std::printf("| bounded closest point | %.2f |\n| contains ball, yes (r - 1e-6 r) | %.2f |\n"
              "| contains ball, no (1.01 r) | %.2f |\n",
    f.Points.Closest, f.Points.Yes, f.Points.No);
  std::printf("\nMethod rows: wall time per sample without the preparation (timed from the end of the sampler's \"Building the surface queries\" stage).\n");
  std::printf("| query or method | us per sample | mean iterations | ratio to limit | ratio to bisection | "
              "2-thread speed-up |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::printf("| ray (2 threads) | %.2f | - | - | - | - |\n", f.RayMicro);
  std::printf("| bounded closest point from a medial centre (2 threads, own tree) | %.2f | - | - | - | - |\n",
    f.ClosestMicro);
  std::printf("| limit: ray + closest point | %.2f | - | 1.00 | - | - |\n", f.LimitMicro);
  for (const Row& r : f.Rows)
  {
    std::printf("| %s (%lld samples) | %.2f | %.2f | %.2f | %.2f | %s |\n", r.Name.c_str(),
      static_cast<long long>(options.Samples), r.MicrosecondsPerSample, r.Iterations,
      r.MicrosecondsPerSample / f.LimitMicro, r.ToBisection,
      r.Extra > 0 ? std::to_string(r.Extra).substr(0, 4).c_str() : "-");
  }
  std::printf("\ndefault method against the others, 2 threads, same run: %.2fx the bisection method, "
              "%.2fx the ray + closest point limit\n",
    f.DefaultToBisection, f.DefaultToLimit);
  std::printf("\ndefault method (%s), %lld samples, 2 threads: %.2f s with the preparation (sampling "
              "alone %.2f us per sample, %.2f iterations, %lld capped)\n",
    vtkMedialAxisSampler::GetMethodName(f.DefaultMethod), static_cast<long long>(options.DefaultSamples),
    f.DefaultSeconds, f.DefaultMicro, f.DefaultIterations, static_cast<long long>(f.DefaultCapped));
  std::printf("worst case, sphere %lld triangles, default method, 2 threads: %.2f us per sample "
              "(%.1fx the horse)\n",
    static_cast<long long>(f.SphereTriangles), f.SphereMicro, f.SphereMicro / f.DefaultMicro);
  std::printf("peak RSS: %.0f MiB\n", f.PeakRss);
  PrintPages();
  std::ostringstream unused;
  PrintStructure(structure, structureLabel, false, unused);
}
}

// The target of a symbolic link (e.g. /proc/self/exe), else `fallback`.
std::string ReadLink(const char* link, const char* fallback)
{
  char path[4096];
  const ssize_t n = readlink(link, path, sizeof(path) - 1);
  return n > 0 ? std::string(path, static_cast<size_t>(n)) : std::string(fallback);
}

// The stages before sampling on `file`, each the median of three runs: reading, the
// mesh preparation (merge, adjacency, orientation, normals, CDF) and the surface
// queries' build (the tree); then the ray throughput and the peak RSS of the run.
int RunPreparation(const std::string& file)
{
  // The first run is the one a user's process pays: every page it touches is new to the
  // process, and on a virtual machine possibly to the host (issue 18: about 3 ms per MB
  // for memory the host took back). Later runs reuse the pages the earlier ones freed,
  // so their median shows the work without that cost; both are printed.
  constexpr int Runs = 4;
  // One stage over the runs: wall and CPU seconds of each run, the RSS after it and
  // the peak RSS so far in the first run.
  struct Stage
  {
    std::vector<double> Wall, Cpu;
    double Rss = 0, Peak = 0;
  };
  Stage read, prepare, queries;
  auto timed = [](Stage& stage, int run, auto&& work) {
    const double t0 = Now(), c0 = CpuSeconds();
    const bool ok = work();
    stage.Wall.push_back(Now() - t0);
    stage.Cpu.push_back(CpuSeconds() - c0);
    if (run == 0)
    {
      stage.Peak = PeakRssMiB();
      stage.Rss = CurrentRssMiB();
    }
    return ok;
  };
  std::unique_ptr<vtkMedialTriangleMesh> kept;
  std::unique_ptr<vtkMedialSurfaceQuery> keptQuery;
  vtkIdType triangles = 0;
  for (int run = 0; run < Runs; ++run)
  {
    keptQuery.reset(); // one mesh at a time: the peak RSS is one run's
    kept.reset();
    std::string error;
    vtkNew<vtkMedialFileReader> reader;
    vtkPolyData* surface = nullptr;
    if (!timed(read, run, [&]() {
          reader->SetFileName(file.c_str());
          reader->Update();
          surface = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
          return surface && surface->GetNumberOfCells() > 0;
        }))
    {
      std::fprintf(stderr, "medial-bench: cannot read %s\n", file.c_str());
      return 1;
    }
    auto mesh = std::make_unique<vtkMedialTriangleMesh>();
    auto query = std::make_unique<vtkMedialSurfaceQuery>();
    if (!timed(prepare, run, [&]() { return mesh->Build(surface, error); }) ||
      !timed(queries, run, [&]() { return query->Build(mesh.get(), error); }))
    {
      std::fprintf(stderr, "medial-bench: %s\n", error.c_str());
      return 1;
    }
    triangles = mesh->GetNumberOfTriangles();
    kept = std::move(mesh);
    keptQuery = std::move(query);
  }
  auto laterMedian = [](const std::vector<double>& all) {
    std::vector<double> v(all.begin() + 1, all.end());
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  Stage both, whole;
  for (int run = 0; run < Runs; ++run)
  {
    both.Wall.push_back(prepare.Wall[run] + queries.Wall[run]);
    both.Cpu.push_back(prepare.Cpu[run] + queries.Cpu[run]);
    whole.Wall.push_back(read.Wall[run] + both.Wall[run]);
    whole.Cpu.push_back(read.Cpu[run] + both.Cpu[run]);
  }
  std::printf("preparation of %s, %lld triangles, %d threads; the first run (a fresh process) and the median "
              "of the %d later ones:\n",
    file.c_str(), static_cast<long long>(triangles), omp_get_max_threads(), Runs - 1);
  std::printf("| stage | first run: seconds | CPU seconds (user + sys) | later runs: seconds | CPU seconds | RSS "
              "after it, first run (MiB) | peak RSS so far (MiB) |\n|---|---|---|---|---|---|---|\n");
  for (const auto& row : { std::make_pair("read", &read), std::make_pair("mesh preparation", &prepare),
         std::make_pair("surface queries (the tree)", &queries), std::make_pair("preparation (mesh + tree)", &both),
         std::make_pair("read + preparation", &whole) })
  {
    const Stage& stage = *row.second;
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f |", row.first, stage.Wall[0], stage.Cpu[0], laterMedian(stage.Wall),
      laterMedian(stage.Cpu));
    if (stage.Peak > 0)
    {
      std::printf(" %.0f | %.0f |\n", stage.Rss, stage.Peak);
    }
    else
    {
      std::printf(" | |\n");
    }
  }
  std::printf("ray (2 threads, 200000 rays): %.3f us\n", MeasureRays(*kept, *keptQuery));
  std::printf("peak RSS: %.0f MiB\n", PeakRssMiB());
  PrintPages();
  return 0;
}

// One run of another program: its wall and CPU seconds (user + system, its own and
// its children's), peak RSS, and what it wrote on stdout and stderr.
struct ProcessRun
{
  bool Ok = false;
  double Wall = 0, Cpu = 0, PeakMiB = 0;
  std::string Out, Err;
};

std::string ReadWhole(const std::string& path)
{
  std::string text;
  if (FILE* f = std::fopen(path.c_str(), "rb"))
  {
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof(buffer), f)) > 0;)
    {
      text.append(buffer, n);
    }
    std::fclose(f);
  }
  return text;
}

ProcessRun RunProcess(const std::vector<std::string>& args, const std::string& scratch)
{
  ProcessRun run;
  const std::string out = scratch + "/stdout.txt", err = scratch + "/stderr.txt";
  const double t0 = Now();
  const pid_t pid = fork();
  if (pid == 0)
  {
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr))
    {
      _exit(127);
    }
    std::vector<char*> argv;
    for (const std::string& a : args)
    {
      argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid)
  {
    return run;
  }
  run.Wall = Now() - t0;
  run.Cpu = usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  run.PeakMiB = usage.ru_maxrss / 1024.0;
  run.Ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  run.Out = ReadWhole(out);
  run.Err = ReadWhole(err);
  return run;
}

// The seconds the CLI printed for a stage ("<stage>: done (S s)"), 0 when absent.
double StageSeconds(const std::string& err, const std::string& stage)
{
  const std::string key = stage + ": done (";
  const size_t at = err.rfind(key);
  return at == std::string::npos ? 0.0 : std::atof(err.c_str() + at + key.size());
}

std::string LoadAverage()
{
  std::string text = ReadWhole("/proc/loadavg");
  const size_t third = text.find(' ', text.find(' ', text.find(' ') + 1) + 1);
  return third == std::string::npos ? "?" : text.substr(0, third);
}

// The command-line rows (--cli-run): see the header. Returns the exit code.
int RunCli(const BenchOptions& options, const char* self)
{
  char pattern[] = "/tmp/medial-bench-XXXXXX";
  if (!mkdtemp(pattern))
  {
    std::fprintf(stderr, "medial-bench: no temporary folder\n");
    return 1;
  }
  const std::string scratch = pattern;
  std::string cli = options.Cli;
  if (cli.empty())
  {
    const std::string me = ReadLink("/proc/self/exe", self);
    cli = me.substr(0, me.find_last_of('/') + 1) + "medial-axis";
  }
  std::string surface = options.CliSurface, label = surface;
  if (surface.empty())
  {
    // The horse Loop-subdivided twice, written as a user would have it: binary PLY.
    vtkSmartPointer<vtkPolyData> mesh = LoadBenchMesh(options.SharedDir, 2, 230, label);
    surface = scratch + "/horse-loop2.ply";
    vtkNew<vtkPLYWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(surface.c_str());
    writer->SetFileTypeToBinary();
    if (!writer->Write())
    {
      std::fprintf(stderr, "medial-bench: cannot write %s\n", surface.c_str());
      return 1;
    }
    label += " (binary PLY)";
  }
  const std::string balls = scratch + "/balls.vtp";
  const std::vector<std::string> plain = { cli, surface, "-n", "1M", "-o", balls };
  std::vector<std::string> stats = plain;
  stats.push_back("--stats");
  const std::string loadBefore = LoadAverage();
  struct Figures
  {
    std::vector<double> Wall, Cpu, Peak, Prepare, Read, Sample, Write;
  } figures[2];
  std::vector<double> wallCost, cpuCost;
  std::string json;
  for (int round = 0; round < options.CliRounds; ++round)
  {
    ProcessRun runs[2];
    for (int k = 0; k < 2; ++k)
    {
      const int which = round % 2 == 0 ? k : 1 - k; // alternate which goes first
      runs[which] = RunProcess(which == 0 ? plain : stats, scratch);
      if (!runs[which].Ok)
      {
        std::fprintf(stderr, "medial-bench: %s failed:\n%s\n", cli.c_str(), runs[which].Err.c_str());
        return 1;
      }
    }
    for (int k = 0; k < 2; ++k)
    {
      const ProcessRun& r = runs[k];
      figures[k].Wall.push_back(r.Wall);
      figures[k].Cpu.push_back(r.Cpu);
      figures[k].Peak.push_back(r.PeakMiB);
      figures[k].Prepare.push_back(
        StageSeconds(r.Err, "Preparing the surface") + StageSeconds(r.Err, "Building the surface queries"));
      figures[k].Read.push_back(StageSeconds(r.Err, "Reading the surface"));
      figures[k].Sample.push_back(StageSeconds(r.Err, "Drawing the samples") + StageSeconds(r.Err, "Sampling"));
      figures[k].Write.push_back(StageSeconds(r.Err, "Writing " + balls));
    }
    wallCost.push_back(runs[1].Wall / runs[0].Wall - 1.0);
    cpuCost.push_back(runs[1].Cpu / runs[0].Cpu - 1.0);
    json = runs[1].Out;
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const std::string loadAfter = LoadAverage();
  const char* names[2] = { "medial-axis SURFACE -n 1M -o balls.vtp", "the same with --stats" };
  const double wall = median(figures[0].Wall), peak = std::max(median(figures[0].Peak), median(figures[1].Peak));
  const double prepare = median(figures[0].Prepare), statsWall = median(wallCost), statsCpu = median(cpuCost);
  if (options.Json)
  {
    std::ostringstream js;
    js << "{\"cli_surface\": \"" << label << "\", \"cli_rounds\": " << options.CliRounds << ", \"load_before\": \""
       << loadBefore << "\", \"load_after\": \"" << loadAfter << "\"";
    const char* keys[2] = { "cli_1m", "cli_1m_stats" };
    for (int k = 0; k < 2; ++k)
    {
      js << ", \"" << keys[k] << "\": {\"wall_seconds\": " << median(figures[k].Wall)
         << ", \"cpu_seconds\": " << median(figures[k].Cpu) << ", \"peak_rss_mib\": " << median(figures[k].Peak)
         << ", \"preparation_seconds\": " << median(figures[k].Prepare)
         << ", \"read_seconds\": " << median(figures[k].Read)
         << ", \"sampling_seconds\": " << median(figures[k].Sample)
         << ", \"write_seconds\": " << median(figures[k].Write) << "}";
    }
    js << ", \"wall_to_target\": " << wall / 6.0 << ", \"peak_rss_to_target\": " << peak / 500.0
       << ", \"preparation_to_target\": " << prepare / 0.7 << ", \"stats_cost_wall\": " << statsWall
       << ", \"stats_cost_cpu\": " << statsCpu << ", \"stats_cost_to_target\": " << statsWall / 0.10 << "}";
    std::printf("%s\n", js.str().c_str());
  }
  else
  {
    std::printf("command-line runs on %s, %d threads, median of %d alternating rounds; load average before %s, "
                "after %s:\n",
      label.c_str(), omp_get_num_procs(), options.CliRounds, loadBefore.c_str(), loadAfter.c_str());
    std::printf("| run | wall s | CPU s (user + sys) | peak RSS MiB | preparation s | reading s | drawing + "
                "sampling s | writing s |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < 2; ++k)
    {
      const Figures& f = figures[k];
      std::printf("| %s | %.2f | %.2f | %.0f | %.2f | %.2f | %.2f | %.2f |\n", names[k], median(f.Wall),
        median(f.Cpu), median(f.Peak), median(f.Prepare), median(f.Read), median(f.Sample), median(f.Write));
    }
    std::printf("\nagainst issue 37's targets, same run:\n| figure | measured | target | ratio to target |\n"
                "|---|---|---|---|\n");
    std::printf("| wall, 1M balls with reading and writing | %.2f s | 6 s | %.2f |\n", wall, wall / 6.0);
    std::printf("| peak RSS (the larger of the two runs) | %.0f MiB | 500 MiB | %.2f |\n", peak, peak / 500.0);
    std::printf("| preparation (merge, orient, normals, tree) | %.2f s | 0.7 s | %.2f |\n", prepare, prepare / 0.7);
    std::printf("| --stats cost, wall (per round, median) | %.1f%% | 10%% | %.2f |\n", 100.0 * statsWall,
      statsWall / 0.10);
    std::printf("| --stats cost, CPU (per round, median) | %.1f%% | 10%% | %.2f |\n", 100.0 * statsCpu,
      statsCpu / 0.10);
    std::printf("\nlast --stats line: %s", json.c_str());
    std::printf("commands: %s %s -n 1M -o balls.vtp [--stats]\n", cli.c_str(), surface.c_str());
  }
  std::remove(balls.c_str());
  std::remove((scratch + "/stdout.txt").c_str());
  std::remove((scratch + "/stderr.txt").c_str());
  if (options.CliSurface.empty())
  {
    std::remove(surface.c_str());
  }
  rmdir(scratch.c_str());
  return 0;
}

int main(int argc, char* argv[])
{
  medialaxis::RestartWithRuntimeSettings(argv);
  BenchOptions options;
  if (!ParseArgs(argc, argv, options))
  {
    return 1;
  }
  if (!options.PreparationFile.empty())
  {
    return RunPreparation(options.PreparationFile);
  }
  if (options.CliRun)
  {
    return RunCli(options, argv[0]);
  }
  // The 3D classification rows (first: they are short).
  std::string structureLabel;
  vtkSmartPointer<vtkPolyData> structureMesh = LoadBenchMesh(options.SharedDir, 0, 16, structureLabel);
  // The strategy rows (same mesh).
  std::ostringstream strategiesJson;
  const StrategyFigures strategyFigures =
    options.StructureOnly ? StrategyFigures() : RunStrategies(structureMesh, options.StrategySamples);
  if (options.StrategiesOnly)
  {
    PrintStrategies(strategyFigures, structureLabel, options.StrategySamples, options.Json, strategiesJson);
    if (options.Json)
    {
      std::printf("{%s}\n", strategiesJson.str().substr(2).c_str());
    }
    return 0;
  }
  const std::vector<StructureRow> structure = { RunStructure(structureMesh, 45.0), RunStructure(structureMesh, 0.0) };
  if (options.StructureOnly)
  {
    std::ostringstream js;
    PrintStructure(structure, structureLabel, options.Json, js);
    if (options.Json)
    {
      std::printf("{%s}\n", js.str().substr(2).c_str());
    }
    return 0;
  }

  BenchFigures figures;
  const double tLoad = Now();
  vtkSmartPointer<vtkPolyData> mesh = LoadBenchMesh(options.SharedDir, 2, 230, figures.Label);
  figures.LoadSeconds = Now() - tLoad;
  QueryEngines engines;
  if (!BuildEngines(mesh, engines, figures))
  {
    return 1;
  }
  MeasureQueries(mesh, engines, figures);
  MeasureMethods(mesh, options, figures);
  if (options.Json)
  {
    PrintStrategies(strategyFigures, structureLabel, options.StrategySamples, true, strategiesJson);
    PrintJson(figures, options, structure, structureLabel, strategiesJson.str());
  }
  else
  {
    PrintTables(figures, options, structure, structureLabel);
    PrintStrategies(strategyFigures, structureLabel, options.StrategySamples, false, strategiesJson);
  }
  return 0;
}
