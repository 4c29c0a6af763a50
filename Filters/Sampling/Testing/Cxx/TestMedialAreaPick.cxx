// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialTriangleMesh::PickTriangleByArea searches only the run of the area CDF between
// two guide entries. It must pick exactly the triangle of a binary search over the whole
// CDF (the first entry above u, the last one for u past the end): checked on a
// 90,000-triangle sphere (pole triangles far smaller than the others) and a
// 6-triangle one, for 200,000 random u, for every CDF value and its neighbours on
// either side, for every guide boundary j / guides and the double just below it, and
// for 0 and the largest double below 1.
#include "MedialTestUtilities.h"

#include "vtkMedialRandom.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkNew.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
vtkIdType ReferencePick(const vtkMedialTriangleMesh& mesh, double u)
{
  auto it = std::upper_bound(mesh.AreaCdf.begin(), mesh.AreaCdf.end(), u);
  if (it == mesh.AreaCdf.end())
  {
    --it;
  }
  return static_cast<vtkIdType>(it - mesh.AreaCdf.begin());
}

// The number of u for which the two picks differ (the first few are printed).
long long Mismatches(const vtkMedialTriangleMesh& mesh)
{
  std::vector<double> us = { 0.0, std::nextafter(1.0, 0.0) };
  vtkMedialSampleRandom random(7, 0);
  for (int i = 0; i < 200000; ++i)
  {
    us.push_back(random.Uniform());
  }
  for (double c : mesh.AreaCdf)
  {
    us.insert(us.end(), { c, std::nextafter(c, 0.0), std::nextafter(c, 2.0) });
  }
  const size_t guides = mesh.AreaGuide.empty() ? 0 : mesh.AreaGuide.size() - 1;
  for (size_t j = 0; j < guides; ++j)
  {
    const double step = static_cast<double>(j) / static_cast<double>(guides);
    us.insert(us.end(), { step, std::nextafter(step, 0.0) });
  }
  long long wrong = 0;
  for (double u : us)
  {
    if (!(u >= 0.0 && u < 1.0))
    {
      continue; // outside the pick's domain
    }
    const vtkIdType got = mesh.PickTriangleByArea(u), expected = ReferencePick(mesh, u);
    if (got != expected && ++wrong <= 5)
    {
      std::printf("u = %.17g: picked %lld, the binary search picks %lld\n", u, static_cast<long long>(got),
        static_cast<long long>(expected));
    }
  }
  std::printf("%lld triangles, %zu guides, %zu values of u: %lld mismatches\n",
    static_cast<long long>(mesh.GetNumberOfTriangles()), guides, us.size(), wrong);
  return wrong;
}
}

int TestMedialAreaPick(int, char*[])
{
  for (int resolution : { 3, 300 })
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(resolution);
    sphere->SetPhiResolution(resolution / 2 + 1);
    sphere->Update();
    vtkMedialTriangleMesh mesh;
    std::string error;
    MEDIAL_CHECK(mesh.Build(sphere->GetOutput(), error), "mesh: %s", error.c_str());
    MEDIAL_CHECK(mesh.AreaGuide.size() >= 2, "no guide for %lld triangles",
      static_cast<long long>(mesh.GetNumberOfTriangles()));
    MEDIAL_CHECK(Mismatches(mesh) == 0, "the guided pick differs from the binary search");
  }
  return EXIT_SUCCESS;
}
