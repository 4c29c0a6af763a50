// SPDX-License-Identifier: BSD-3-Clause
// The repair gives the same bytes every time it runs in one process, whatever ran before
// it and on any number of threads: a pipeline that executes again (ParaView) must get the
// surface it got the first time. Cases: the generated defects whose repair runs CGAL's
// exact steps (the union of overlapping shells, the resolution of a shell crossing
// itself), two overlapping UV spheres (48 x 48 facets, centres 1.2 apart, as a user
// would make them with vtkSphereSource), and those spheres wrapped (RepairMode WRAP). Each is repaired `runs` times on 1 and 2 threads
// in turn, with the heap left in a different state before each run (blocks of several
// sizes held or released: CGAL's corefinement ordered its work by the addresses of its
// boxes, so the first union in a process differed from the next ones). Every run's points
// and triangles must be the first run's, bit for bit.
#include "MedialDefectTestUtilities.h"

#include "vtkMedialRepairFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> UvSpheres()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkTransform> move;
  move->Translate(1.2, 0.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(sphere->GetOutputPort());
  moved->SetTransform(move);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(sphere->GetOutputPort());
  both->AddInputConnection(moved->GetOutputPort());
  both->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(both->GetOutput());
  return out;
}
}

int TestMedialRepairRepeat(int argc, char* argv[])
{
  // Arguments: the number of runs per case (default 6); a word keeps only the cases whose
  // name contains it (e.g. "spheres", to run under valgrind).
  int runs = 6;
  std::string only;
  for (int i = 1; i < argc; ++i)
  {
    if (std::atoi(argv[i]) > 0)
    {
      runs = std::atoi(argv[i]);
    }
    else if (std::string(argv[i]).find_first_of("-/") == std::string::npos)
    {
      only = argv[i];
    }
  }
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkPolyData> Surface;
    int Mode;
  };
  std::vector<Case> cases;
  const vtkSmartPointer<vtkPolyData> uv = UvSpheres();
  cases.push_back({ "uv spheres 48 x 48", uv, vtkMedialRepairFilter::AUTO });
  for (const medialtest::Defect& d : medialtest::GeneratedDefects())
  {
    if (d.Name == "overlapping spheres" || d.Name == "crossing shell")
    {
      cases.push_back({ d.Name, d.Surface, vtkMedialRepairFilter::AUTO });
    }
  }
  cases.push_back({ "uv spheres wrapped", uv, vtkMedialRepairFilter::WRAP });
  int failures = 0;
  // Blocks held between runs, so that each run starts on a different heap.
  std::vector<std::unique_ptr<char[]>> held;
  for (const Case& c : cases)
  {
    if (!only.empty() && c.Name.find(only) == std::string::npos)
    {
      continue;
    }
    std::vector<unsigned char> first;
    int differ = 0;
    for (int run = 0; run < runs; ++run)
    {
      vtkNew<vtkMedialRepairFilter> repair;
      repair->SetInputData(c.Surface);
      repair->SetReportSteps(false);
      repair->SetNumberOfThreads(1 + run % 2);
      repair->SetMode(c.Mode);
      repair->Update();
      const std::vector<unsigned char> bytes = medialtest::SurfaceBytes(repair->GetOutput());
      if (run == 0)
      {
        first = bytes;
        if (repair->GetWrapped() != (c.Mode == vtkMedialRepairFilter::WRAP) || !repair->GetChanged())
        {
          std::printf("  FAILED %s: not repaired as asked (wrapped %d, changed %d)\n", c.Name.c_str(),
            repair->GetWrapped() ? 1 : 0, repair->GetChanged() ? 1 : 0);
          ++failures;
        }
      }
      else if (bytes != first)
      {
        ++differ;
      }
      // A different heap for the next run: hold one more block (64 kB to 4 MB), release
      // every third.
      held.emplace_back(new char[size_t(1) << (16 + run % 7)]);
      std::memset(held.back().get(), run, size_t(1) << 16);
      if (run % 3 == 2)
      {
        held.erase(held.begin());
      }
    }
    std::printf("%-20s %d of %d runs differ from the first (%zu bytes)\n", c.Name.c_str(), differ, runs - 1, first.size());
    if (differ > 0)
    {
      std::printf("  FAILED %s: the repair is not the same bytes from run to run\n", c.Name.c_str());
      ++failures;
    }
  }
  std::printf("%d failures\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
