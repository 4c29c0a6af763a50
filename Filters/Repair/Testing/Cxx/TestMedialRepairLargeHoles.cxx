// SPDX-License-Identifier: BSD-3-Clause
// Open shells whose holes are larger than MaximumHoleSize and nothing closed besides
// (a car body with its windows open): the wrap would make a thin solid around the sheet,
// so the repair fills the larger holes too when that closes the surface, and the solid
// is the one the input means. The family, each with its known solid:
//  - a box 2 x 1 x 1 with a window 1.5 x 0.5 in each of its two long sides (the windows'
//    planes are the box's: the filled box has volume 2, largest ball 0.5);
//  - the same box with its two ends open (a square tube: filled, a solid of about the
//    box's volume, the caps faired);
//  - a flat square with a large square hole (an annulus): still no volume, the clear
//    error (filling the inner hole leaves the outer rim open).
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialTriangleMesh.h"

#include <map>

namespace
{
using medialtest::defects::Point;

// The box [0,2] x [0,1] x [0,1], each face a grid of squares 1/n wide, facing out;
// the squares for which skip(face, centre) is true are left out.
vtkSmartPointer<vtkPolyData> Box(int n, const std::function<bool(int face, const double centre[3])>& skip)
{
  std::vector<Point> x;
  std::vector<std::array<vtkIdType, 3>> t;
  std::map<std::array<long, 3>, vtkIdType> ids;
  auto point = [&](long i, long j, long k) {
    const std::array<long, 3> key{ i, j, k };
    const auto at = ids.find(key);
    if (at != ids.end())
    {
      return at->second;
    }
    ids.emplace(key, static_cast<vtkIdType>(x.size()));
    x.push_back({ static_cast<double>(i) / n, static_cast<double>(j) / n, static_cast<double>(k) / n });
    return static_cast<vtkIdType>(x.size() - 1);
  };
  const long size[3] = { 2L * n, n, n };
  // Face f = 2 * axis + side; the square (u, v) of the face, corners counter-clockwise
  // seen from outside.
  for (int axis = 0; axis < 3; ++axis)
  {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (long u = 0; u < size[a]; ++u)
      {
        for (long v = 0; v < size[b]; ++v)
        {
          auto corner = [&](long du, long dv) {
            long g[3];
            g[axis] = side ? size[axis] : 0;
            g[a] = u + du;
            g[b] = v + dv;
            return point(g[0], g[1], g[2]);
          };
          double centre[3];
          centre[axis] = side ? static_cast<double>(size[axis]) / n : 0.0;
          centre[a] = (u + 0.5) / n;
          centre[b] = (v + 0.5) / n;
          if (skip(2 * axis + side, centre))
          {
            continue;
          }
          vtkIdType q[4] = { corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1) };
          if (!side)
          {
            std::swap(q[1], q[3]);
          }
          t.push_back({ q[0], q[1], q[2] });
          t.push_back({ q[0], q[2], q[3] });
        }
      }
    }
  }
  return medialtest::defects::Mesh(x, t);
}

vtkSmartPointer<vtkPolyData> Annulus()
{
  std::vector<Point> x;
  std::vector<std::array<vtkIdType, 3>> t;
  const int n = 10;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      x.push_back({ -1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0 });
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      if (i >= 3 && i < 7 && j >= 3 && j < 7)
      {
        continue; // the hole
      }
      const vtkIdType a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      t.push_back({ a, c, d });
      t.push_back({ a, d, b });
    }
  }
  return medialtest::defects::Mesh(x, t);
}

struct Case
{
  const char* Name;
  vtkSmartPointer<vtkPolyData> Input;
  double Volume, VolumeTolerance; // the true solid's, relative
  double LargestBall;             // the true solid's (0: not checked)
};
}

int TestMedialRepairLargeHoles(int, char*[])
{
  const int n = 8;
  auto windows = [](int face, const double c[3]) {
    return (face == 2 || face == 3) && c[0] > 0.25 && c[0] < 1.75 && c[2] > 0.25 && c[2] < 0.75;
  };
  auto ends = [](int face, const double*) { return face == 0 || face == 1; };
  const Case cases[] = {
    { "box with two windows", Box(n, windows), 2.0, 1e-9, 0.5 },
    { "square tube, both ends open", Box(n, ends), 2.0, 0.25, 0.0 },
  };
  for (const Case& c : cases)
  {
    medialtest::EventLog log;
    vtkNew<vtkMedialRepairFilter> repair;
    log.Watch(repair);
    repair->SetInputData(c.Input);
    repair->Update();
    std::printf("%s: %lld holes filled, wrapped %d, largest distance %g\n", c.Name,
      static_cast<long long>(repair->GetFilledHoles()), repair->GetWrapped() ? 1 : 0, repair->GetMaximumDistance());
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      std::printf("  %s\n", repair->GetReportLine(i));
    }
    MEDIAL_CHECK(log.Errors == 0 && !repair->GetWrapped() && repair->GetFilledHoles() == 2 &&
        repair->GetUnfilledHoles() == 0 && !log.LineWith("filled too").empty(),
      "%s: the large holes are not filled: %s", c.Name, log.Text.c_str());
    MEDIAL_CHECK(repair->GetMaximumDistance() == 0.0, "%s: the input moved by %g", c.Name, repair->GetMaximumDistance());
    vtkMedialTriangleMesh mesh;
    std::string error;
    MEDIAL_CHECK(mesh.Build(repair->GetOutput(), error) && mesh.BoundaryEdges == 0 && mesh.NonManifoldEdges == 0 &&
        mesh.Shells.size() == 1,
      "%s: the output is not one closed shell", c.Name);
    std::printf("  volume %.9g (the solid's %g)\n", mesh.Volume, c.Volume);
    MEDIAL_CHECK(std::fabs(mesh.Volume - c.Volume) <= c.VolumeTolerance * c.Volume, "%s: volume %g, not %g", c.Name,
      mesh.Volume, c.Volume);
    if (c.LargestBall > 0.0)
    {
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(c.Input);
      sampler->SetNumberOfSamples(4000);
      sampler->Update();
      double largest = 0.0;
      vtkDataArray* radius = sampler->GetOutput()->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
      for (vtkIdType i = 0; radius && i < radius->GetNumberOfTuples(); ++i)
      {
        largest = std::max(largest, radius->GetComponent(i, 0));
      }
      std::printf("  sampled: %lld discarded, largest ball %.4f (the solid's %g)\n",
        static_cast<long long>(sampler->GetDiscardedSamples()), largest, c.LargestBall);
      MEDIAL_CHECK(sampler->GetDiscardedSamples() == 0 && std::fabs(largest - c.LargestBall) <= 0.02 * c.LargestBall,
        "%s: sampled %lld discarded, largest ball %g", c.Name, static_cast<long long>(sampler->GetDiscardedSamples()),
        largest);
    }
  }
  // A flat annulus: still no volume.
  {
    medialtest::EventLog log;
    vtkNew<vtkMedialRepairFilter> repair;
    log.Watch(repair);
    repair->SetInputData(Annulus());
    repair->Update();
    MEDIAL_CHECK(log.Errors > 0 && !log.LineWith("bounds no volume").empty(), "the annulus: no clear error: %s",
      log.Text.c_str());
  }
  return EXIT_SUCCESS;
}
