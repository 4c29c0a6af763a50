// SPDX-License-Identifier: BSD-3-Clause
// medial-repair-bench: the repair (vtkMedialRepairFilter) and the solid check.
//
// --check [--runs R] MESH...: the cost of RepairMode AUTO on input that needs no repair.
//   For each mesh, R times (default 3): the mesh preparation (vtkMedialTriangleMesh::
//   Build), the surface queries' tree (vtkMedialSurfaceQuery::Build) and the solid check
//   (vtkMedialSolidCheck::Run), wall and CPU seconds (medians); the check as a share of
//   the preparation (mesh + tree); the patches of the tree whose self-tests the pair
//   search's culling skipped, of those it tested (and how many of those skipped had a
//   pinched boundary); what the check found.
// --repair MESH...: the repair of each mesh: its report, its time per stage, the
//   largest distance from the input to the output, the share of the input buried, the
//   triangles in and out, the peak RSS so far.
// --wrap MESH...: the alpha wrap at its default settings (Mode WRAP): time, triangles,
//   largest distance, peak RSS so far.
// --defects [--samples N]: the generated defects of the tests (Testing/Cxx/
//   MedialDefectTestUtilities.h), sampled (N, default 20000) and meshed without and with
//   the repair: discarded samples, largest ball against the true one, balls outside the
//   true solid and stopped short of it, the medial mesh's Euler characteristic against
//   the solid's, the repair's report and time.
// MESH: a file, or generated:NAME for a generated defect. --threads T (default 2).
// Not a test: it checks nothing.
#include "MedialRepairTestUtilities.h"

#include "vtkMedialFileReader.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// CPU seconds of the whole process (every thread): on a loaded machine a fairer
// measure of work than wall time.
double CpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

vtkSmartPointer<vtkPolyData> Load(const std::string& name)
{
  const std::string prefix = "generated:";
  if (name.rfind(prefix, 0) == 0)
  {
    for (medialtest::Defect& d : medialtest::GeneratedDefects())
    {
      if (d.Name == name.substr(prefix.size()))
      {
        return d.Surface;
      }
    }
    return nullptr;
  }
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(name.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(reader->GetOutput());
  return out;
}

double PeakMiB()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

std::string Name(const std::string& mesh)
{
  const size_t slash = mesh.find_last_of('/');
  return slash == std::string::npos ? mesh : mesh.substr(slash + 1);
}

int Repair(const std::vector<std::string>& meshes, int threads, bool wrap)
{
  std::printf("| mesh | triangles in | %s | triangles out | seconds (CPU) | stages: wall s (CPU s) | largest distance (rel.) | buried area | peak RSS MiB | report |\n",
    wrap ? "mode" : "valid");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& name : meshes)
  {
    vtkSmartPointer<vtkPolyData> surface = Load(name);
    if (!surface)
    {
      std::printf("| %s | cannot read |\n", name.c_str());
      continue;
    }
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(surface);
    repair->SetNumberOfThreads(threads);
    repair->SetReportSteps(false);
    if (wrap)
    {
      repair->SetModeToWrap();
    }
    const double cpu = CpuSeconds();
    repair->Update();
    const double repairCpu = CpuSeconds() - cpu;
    std::string stages, report;
    for (int i = 0; i < repair->GetNumberOfTimedStages(); ++i)
    {
      char buf[96];
      std::snprintf(buf, sizeof(buf), "%s%s %.3f (%.3f)", i ? ", " : "", repair->GetTimedStageName(i),
        repair->GetTimedStageSeconds(i), repair->GetTimedStageCpuSeconds(i));
      stages += buf;
    }
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      report += std::string(i ? "; " : "") + repair->GetReportLine(i);
    }
    std::printf("| %s | %lld | %s | %lld | %.3f (%.3f) | %s | %.2e | %.4f | %.0f | %s |\n", Name(name).c_str(),
      static_cast<long long>(surface->GetNumberOfCells()), wrap ? "wrap" : (repair->GetInputWasValid() ? "yes" : "no"),
      static_cast<long long>(repair->GetOutput()->GetNumberOfCells()), repair->GetSeconds(), repairCpu, stages.c_str(),
      repair->GetMaximumDistance(), repair->GetBuriedArea(), PeakMiB(), report.empty() ? "untouched" : report.c_str());
  }
  return 0;
}

int Defects(int threads, vtkIdType samples)
{
  std::printf("| defect | repair | discarded | largest ball (true) | balls outside / short of the true solid | medial mesh Euler (solid's) | repair (s) | report |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const medialtest::Defect& d : medialtest::GeneratedDefects())
  {
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(d.Surface);
    repair->SetNumberOfThreads(threads);
    repair->SetReportSteps(false);
    repair->Update();
    std::string report;
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      report += std::string(i ? "; " : "") + repair->GetReportLine(i);
    }
    for (int mode : { vtkMedialRepairFilter::NONE, vtkMedialRepairFilter::AUTO })
    {
      const medialtest::DefectResult r = medialtest::MeasureDefect(d, mode, samples);
      std::printf("| %s | %s | %lld | %.4f (%.4f) | %lld / %lld of %lld | %lld (%d) | %s | %s |\n", d.Name.c_str(),
        vtkMedialRepairFilter::GetModeName(mode), static_cast<long long>(r.Discarded), r.LargestBall, d.LargestBall,
        static_cast<long long>(r.Outside), static_cast<long long>(r.Short), static_cast<long long>(r.Balls),
        static_cast<long long>(r.Euler), d.Euler, mode == vtkMedialRepairFilter::AUTO ? std::to_string(repair->GetSeconds()).c_str() : "",
        mode == vtkMedialRepairFilter::AUTO ? (report.empty() ? "untouched (valid solid)" : report.c_str()) : "");
    }
  }
  return 0;
}

int Check(const std::vector<std::string>& meshes, int threads, int runs)
{
  std::printf("| mesh | triangles | mesh s | tree s | check s | check / preparation | CPU s: mesh, tree, check | check / preparation (CPU) | patches culled / tested (pinched) | found |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& name : meshes)
  {
    vtkSmartPointer<vtkPolyData> surface = Load(name);
    if (!surface)
    {
      std::printf("| %s | cannot read | | | | | |\n", name.c_str());
      continue;
    }
    std::vector<double> meshTimes, treeTimes, checkTimes, meshCpu, treeCpu, checkCpu;
    vtkMedialSolidCheck check;
    vtkIdType triangles = 0, bound = 0;
    for (int r = 0; r < runs; ++r)
    {
      vtkMedialTriangleMesh mesh;
      vtkMedialSurfaceQuery query;
      std::string error;
      Clock::time_point start = Clock::now();
      double cpu = CpuSeconds();
      if (!mesh.Build(surface, error))
      {
        std::printf("| %s | %s | | | | | |\n", name.c_str(), error.c_str());
        break;
      }
      meshTimes.push_back(Seconds(start));
      meshCpu.push_back(CpuSeconds() - cpu);
      start = Clock::now();
      cpu = CpuSeconds();
      query.Build(&mesh, error);
      treeTimes.push_back(Seconds(start));
      treeCpu.push_back(CpuSeconds() - cpu);
      start = Clock::now();
      cpu = CpuSeconds();
      check.Run(mesh, query, threads);
      checkTimes.push_back(Seconds(start));
      checkCpu.push_back(CpuSeconds() - cpu);
      triangles = mesh.GetNumberOfTriangles();
      bound = mesh.PinchedVertexBound();
    }
    if (checkTimes.empty())
    {
      continue;
    }
    std::string found;
    for (const std::string& line : check.Problems())
    {
      found += (found.empty() ? "" : "; ") + line;
    }
    if (check.PinchedVertices > 0)
    {
      found += (found.empty() ? "" : "; ") + check.PinchedClause();
    }
    // The Euler bound: 0 means the pinch count cost nothing.
    found = (found.empty() ? std::string("valid solid") : found) + " (Euler bound " +
      std::to_string(bound) + ")";

    const double m = Median(meshTimes), t = Median(treeTimes), c = Median(checkTimes);
    const double mc = Median(meshCpu), tc = Median(treeCpu), cc = Median(checkCpu);
    std::printf("| %s | %lld | %.3f | %.3f | %.4f | %.1f%% | %.3f, %.3f, %.4f | %.1f%% | %lld / %lld (%lld) | %s |\n",
      name.c_str(), static_cast<long long>(triangles), m, t, c, 100.0 * c / (m + t), mc, tc, cc,
      100.0 * cc / (mc + tc), check.PatchesCulled, check.PatchesTested, check.PinchedPatchesCulled, found.c_str());
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
  int threads = 2, runs = 3;
  vtkIdType samples = 20000;
  std::string mode;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (arg == "--runs" && i + 1 < argc)
    {
      runs = std::max(1, std::atoi(argv[++i]));
    }
    else if (arg == "--samples" && i + 1 < argc)
    {
      samples = std::atoll(argv[++i]);
    }
    else if (arg == "--check" || arg == "--repair" || arg == "--wrap" || arg == "--defects")
    {
      mode = arg;
    }
    else
    {
      meshes.push_back(arg);
    }
  }
  omp_set_num_threads(threads);
  if (mode == "--check")
  {
    return Check(meshes, threads, runs);
  }
  if (mode == "--repair" || mode == "--wrap")
  {
    return Repair(meshes, threads, mode == "--wrap");
  }
  if (mode == "--defects")
  {
    return Defects(threads, samples);
  }
  std::fprintf(stderr, "usage: medial-repair-bench [--threads T] --check [--runs R] MESH... | --repair MESH... | "
                       "--wrap MESH... | --defects [--samples N]\n");
  return 1;
}
