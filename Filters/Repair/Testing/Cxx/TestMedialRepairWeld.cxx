// SPDX-License-Identifier: BSD-3-Clause
// The repair's weld (step 1) merges the same points every time, into the clusters that
// the tolerance defines: all the points joined by chains of pairs at most the tolerance
// apart (vtkMedialRepairWeld). Cases, each an unwelded triangle soup whose welded
// surface is known (every triangle has its own corners):
//  - the jittered box of GeneratedDefects (corners moved by up to 1e-7, the tolerance is
//    1e-6 of the diagonal);
//  - a box and a sphere with three holes whose copies of each point lie on a chain, one
//    copy every 0.8 of the tolerance: a copy is within the tolerance of its neighbours
//    on the chain only, so a merge that is not transitive (each point into the first
//    point found near it, as vtkStaticCleanPolyData does) splits the chain and leaves
//    cracks; the weld must make each chain one point.
// Each is repaired `runs` times (default 20), on 1 and 2 threads of the repair and under
// VTK's SMP backends (TBB; STDThread with 2 and 1 threads; Sequential) in turn. Every
// run must weld exactly the soup's points less the surface's (also found here by brute
// force over all pairs), give the closed box without filling a hole, and give the first
// run's bytes.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialRepairFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

namespace
{
using medialtest::defects::Point;

// Points less clusters when every pair at most `tolerance` apart is merged, transitively:
// all pairs, by brute force (the reference the weld must match).
vtkIdType MergedByBruteForce(vtkPolyData* pd, double tolerance)
{
  const std::vector<Point> x = medialtest::defects::Points(pd);
  std::vector<size_t> parent(x.size());
  std::iota(parent.begin(), parent.end(), size_t(0));
  auto find = [&](size_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  vtkIdType merged = 0;
  for (size_t i = 0; i < x.size(); ++i)
  {
    for (size_t j = i + 1; j < x.size(); ++j)
    {
      const double d2 = vtkMath::Distance2BetweenPoints(x[i].data(), x[j].data());
      const size_t a = find(i), b = find(j);
      if (d2 <= tolerance * tolerance && a != b)
      {
        parent[std::max(a, b)] = std::min(a, b);
        ++merged;
      }
    }
  }
  return merged;
}

// `surface`'s triangles, each with its own corners; the k-th copy of a point is moved by
// k * step along `direction` (a unit vector).
vtkSmartPointer<vtkPolyData> ChainedSoup(vtkPolyData* surface, double step)
{
  const std::vector<Point> x = medialtest::defects::Points(surface);
  const double direction[3] = { 1.0 / std::sqrt(14.0), 2.0 / std::sqrt(14.0), 3.0 / std::sqrt(14.0) };
  std::vector<int> copies(x.size(), 0);
  std::vector<Point> soup;
  std::vector<std::array<vtkIdType, 3>> tris;
  for (const auto& t : medialtest::defects::Triangles(surface))
  {
    std::array<vtkIdType, 3> own;
    for (int i = 0; i < 3; ++i)
    {
      Point p = x[t[i]];
      const int k = copies[t[i]]++;
      for (int c = 0; c < 3; ++c)
      {
        p[c] += k * step * direction[c];
      }
      own[i] = static_cast<vtkIdType>(soup.size());
      soup.push_back(p);
    }
    tris.push_back(own);
  }
  return medialtest::defects::Mesh(soup, tris);
}

vtkIdType UsedPoints(vtkPolyData* pd)
{
  std::vector<char> used(pd->GetNumberOfPoints(), 0);
  for (const auto& t : medialtest::defects::Triangles(pd))
  {
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  return std::accumulate(used.begin(), used.end(), vtkIdType(0));
}
}

int TestMedialRepairWeld(int argc, char* argv[])
{
  using medialtest::defects::Shape;
  int runs = 20;
  for (int i = 1; i < argc; ++i)
  {
    if (std::atoi(argv[i]) > 0)
    {
      runs = std::atoi(argv[i]);
    }
  }
  const double tolerance = 1e-6; // the repair's default, relative to the diagonal
  auto box = Shape(vtkMedialShapeSource::BOX, 6, [](vtkMedialShapeSource* s) { s->SetBoxLengths(1.0, 0.8, 0.6); });
  const medialtest::Defect holed = medialtest::defects::SphereWithHoles();
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkPolyData> Soup;
    vtkIdType SurfacePoints; // of the welded surface
    bool Closed;             // the welded surface is closed: no hole is filled
  };
  const double boxStep = 0.8 * tolerance * box->GetLength();
  const double holedStep = 0.8 * tolerance * holed.Surface->GetLength();
  const std::vector<Case> cases = {
    { "jittered box", medialtest::defects::JitteredSoup().Surface, UsedPoints(box), true },
    { "chained box", ChainedSoup(box, boxStep), UsedPoints(box), true },
    { "chained sphere with holes", ChainedSoup(holed.Surface, holedStep), UsedPoints(holed.Surface), false },
  };
  struct Smp
  {
    const char* Backend;
    int Threads;
  };
  // TBB at its default only: once limited to fewer threads it ignores later requests
  // for more (and says so).
  const Smp smp[] = { { "TBB", 2 }, { "STDThread", 2 }, { "STDThread", 1 }, { "Sequential", 1 } };
  for (const Case& c : cases)
  {
    const vtkIdType soupPoints = c.Soup->GetNumberOfPoints();
    const vtkIdType expected = soupPoints - c.SurfacePoints;
    const vtkIdType brute = MergedByBruteForce(c.Soup, tolerance * c.Soup->GetLength());
    MEDIAL_CHECK(brute == expected, "%s: %lld points within the tolerance by brute force, %lld expected", c.Name.c_str(),
      static_cast<long long>(brute), static_cast<long long>(expected));
    std::vector<unsigned char> first;
    int differ = 0, miscounted = 0, open = 0;
    vtkIdType lowest = soupPoints, highest = -soupPoints;
    for (int run = 0; run < runs; ++run)
    {
      const Smp& s = smp[run % (sizeof(smp) / sizeof(smp[0]))];
      vtkNew<vtkMedialRepairFilter> repair;
      repair->SetInputData(c.Soup);
      repair->SetReportSteps(false);
      repair->SetNumberOfThreads(1 + run % 2);
      vtkSMPTools::LocalScope(vtkSMPTools::Config(s.Threads, s.Backend, false), [&]() { repair->Update(); });
      vtkPolyData* out = repair->GetOutput();
      const vtkIdType welded = repair->GetWeldedPoints();
      lowest = std::min(lowest, welded);
      highest = std::max(highest, welded);
      miscounted += welded != expected ? 1 : 0;
      // The welded box is closed: nothing to fill, the box's points and triangles out.
      open += repair->GetWrapped() ||
          (c.Closed &&
            (repair->GetFilledHoles() > 0 || out->GetNumberOfPoints() != c.SurfacePoints ||
              out->GetNumberOfPolys() != box->GetNumberOfPolys()))
        ? 1
        : 0;
      const std::vector<unsigned char> bytes = medialtest::SurfaceBytes(out);
      if (run == 0)
      {
        first = bytes;
      }
      else if (bytes != first)
      {
        ++differ;
      }
    }
    std::printf("%s: %lld soup points, %lld to weld; welded %lld to %lld, %d of %d runs miscounted, %d not closed, "
                "%d differ from the first\n",
      c.Name.c_str(), static_cast<long long>(soupPoints), static_cast<long long>(expected),
      static_cast<long long>(lowest), static_cast<long long>(highest), miscounted, runs, open, differ);
    MEDIAL_CHECK(miscounted == 0 && open == 0 && differ == 0, "%s: the weld is not the same every time", c.Name.c_str());
  }
  return EXIT_SUCCESS;
}
