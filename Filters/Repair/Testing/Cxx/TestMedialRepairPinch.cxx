// SPDX-License-Identifier: BSD-3-Clause
// Pinched vertices (a point where the surface's triangles form two or more fans): the
// AUTO screen (vtkMedialSolidCheck::Run without allPairs) counts them and says where,
// exactly, on a horn torus (one pinch within one shell), two cubes sharing a corner (one
// pinch between two shells) and a ring torus (none, though its Euler characteristic
// leaves room for two extra fans); the repair filter's output is manifold at every
// vertex (a copy of the pinched point per extra fan, at the same place), wound as the
// input, with a "pinch:" report line; the sampler's preparation keeps the pinch and
// says so, and so does the medial mesh's topology check. Before the AUTO screen counted
// them, the horn torus passed through the repair untouched.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <map>
#include <string>

namespace
{
// Points (by id, not by place) whose triangles form more than one fan.
vtkIdType PinchedById(vtkPolyData* surface)
{
  const auto tris = medialtest::defects::Triangles(surface);
  std::map<vtkIdType, std::map<vtkIdType, vtkIdType>> link; // point: link edge from -> to
  for (const auto& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      link[t[k]][t[(k + 1) % 3]] = t[(k + 2) % 3];
    }
  }
  vtkIdType pinched = 0;
  for (const auto& l : link)
  {
    const auto& edges = l.second;
    size_t steps = 1;
    vtkIdType at = edges.begin()->second;
    while (at != edges.begin()->first && steps < edges.size())
    {
      const auto next = edges.find(at);
      if (next == edges.end())
      {
        break;
      }
      at = next->second;
      ++steps;
    }
    pinched += steps < edges.size() ? 1 : 0;
  }
  return pinched;
}

double SignedVolume(vtkPolyData* surface)
{
  const auto x = medialtest::defects::Points(surface);
  double volume = 0.0;
  for (const auto& t : medialtest::defects::Triangles(surface))
  {
    const auto &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
  }
  return volume;
}
}

int TestMedialRepairPinch(int, char*[])
{
  struct Case
  {
    std::string Name;
    vtkSmartPointer<vtkPolyData> Surface;
    vtkIdType Pinched;  // by the screen
    vtkIdType Bound;    // 2 shells - Euler characteristic
    bool Valid;         // the screen's IsValid (pinches are no defect to it)
    double Where[3];
  };
  const std::vector<Case> cases = {
    { "horn torus", medialtest::defects::HornTorus().Surface, 1, 1, true, { 0, 0, 0 } },
    { "cubes sharing a vertex", medialtest::defects::CubesSharingAVertex().Surface, 1, 1, false, { 1, 1, 1 } },
    { "ring torus", medialtest::defects::Shape(vtkMedialShapeSource::TORUS, 16), 0, 2, true, { 0, 0, 0 } },
    { "sphere", medialtest::defects::Shape(vtkMedialShapeSource::SPHERE, 3), 0, 0, true, { 0, 0, 0 } },
  };
  for (const Case& c : cases)
  {
    vtkMedialTriangleMesh mesh;
    vtkMedialSurfaceQuery query;
    std::string error;
    MEDIAL_CHECK(mesh.Build(c.Surface, error) && query.Build(&mesh, error), "%s: %s", c.Name.c_str(), error.c_str());
    MEDIAL_CHECK(mesh.PinchedVertexBound() == c.Bound, "%s: Euler bound %lld, expected %lld", c.Name.c_str(),
      static_cast<long long>(mesh.PinchedVertexBound()), static_cast<long long>(c.Bound));
    // The AUTO screen (no allPairs) and the diagnosis agree.
    for (bool allPairs : { false, true })
    {
      vtkMedialSolidCheck check;
      check.Run(mesh, query, 2, allPairs);
      std::printf("%-24s allPairs %d: valid %d, %s\n", c.Name.c_str(), allPairs ? 1 : 0, check.IsValid() ? 1 : 0,
        check.PinchedVertices ? check.PinchedClause().c_str() : "no pinched vertex");
      // With other defects the AUTO screen skips the pair search and the count (the
      // repair runs anyway).
      const vtkIdType expected = allPairs || c.Valid ? c.Pinched : 0;
      MEDIAL_CHECK(check.PinchedVertices == expected, "%s: %lld pinched vertices, expected %lld", c.Name.c_str(),
        static_cast<long long>(check.PinchedVertices), static_cast<long long>(expected));
      MEDIAL_CHECK(check.IsValid() == c.Valid, "%s: IsValid %d", c.Name.c_str(), check.IsValid() ? 1 : 0);
      for (int k = 0; k < 3 && expected > 0; ++k)
      {
        MEDIAL_CHECK(std::fabs(check.PinchedVertex[k] - c.Where[k]) < 1e-12, "%s: pinch not at the expected point",
          c.Name.c_str());
      }
    }

    // The repair's output: manifold at every vertex, wound as the input (outward).
    vtkNew<vtkMedialRepairFilter> repair;
    repair->SetInputData(c.Surface);
    repair->SetReportSteps(false);
    repair->Update();
    vtkPolyData* out = repair->GetOutput();
    bool pinchLine = false;
    for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
    {
      std::printf("  %s\n", repair->GetReportLine(i));
      pinchLine = pinchLine || std::string(repair->GetReportLine(i)).rfind("pinch:", 0) == 0;
    }
    MEDIAL_CHECK(PinchedById(out) == 0, "%s: the repair's output has %lld pinched points", c.Name.c_str(),
      static_cast<long long>(PinchedById(out)));
    MEDIAL_CHECK(pinchLine == (c.Pinched > 0), "%s: 'pinch:' line %d", c.Name.c_str(), pinchLine ? 1 : 0);
    MEDIAL_CHECK(repair->GetInputWasValid() == (c.Pinched == 0 && c.Valid), "%s: InputWasValid %d",
      c.Name.c_str(), repair->GetInputWasValid() ? 1 : 0);
    MEDIAL_CHECK(SignedVolume(out) > 0.0, "%s: the output is wound inward", c.Name.c_str());
    if (c.Pinched > 0)
    {
      MEDIAL_CHECK(out->GetNumberOfPoints() == c.Surface->GetNumberOfPoints() + c.Pinched,
        "%s: %lld points out, %lld in", c.Name.c_str(), static_cast<long long>(out->GetNumberOfPoints()),
        static_cast<long long>(c.Surface->GetNumberOfPoints()));
      MEDIAL_CHECK(std::fabs(SignedVolume(out) - SignedVolume(c.Surface)) <= 1e-12 * std::fabs(SignedVolume(c.Surface)),
        "%s: the split moved the surface", c.Name.c_str());
    }
  }

  // The sampler keeps the horn torus's pinch (the same balls) and says where it is.
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(medialtest::defects::HornTorus().Surface);
  sampler->SetNumberOfSamples(2000);
  medialtest::EventLog log;
  log.Watch(sampler);
  sampler->Update();
  std::printf("sampler: %s\n", log.LineWith("pinched").c_str());
  MEDIAL_CHECK(!log.LineWith("1 pinched vertex").empty(), "the sampler does not name the pinched vertex");
  // The medial mesh's topology check names it too (the surface's Euler characteristic,
  // 1, is odd: its solid's topology is not half of it).
  vtkNew<vtkMedialMeshFilter> medial;
  medial->SetInputData(medialtest::defects::HornTorus().Surface);
  medial->SetBallsConnection(sampler->GetOutputPort());
  medialtest::EventLog meshLog;
  meshLog.Watch(medial);
  medial->Update();
  std::printf("medial mesh: %s\n", meshLog.LineWith("pinched").c_str());
  MEDIAL_CHECK(!meshLog.LineWith("The surface has 1 pinched vertex").empty(),
    "the medial mesh's topology check does not name the pinched vertex");
  return EXIT_SUCCESS;
}
