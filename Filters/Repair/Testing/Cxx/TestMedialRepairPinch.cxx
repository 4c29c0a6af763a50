// SPDX-License-Identifier: BSD-3-Clause
// Pinched vertices (a point where the surface's triangles form two or more fans): the
// AUTO screen (vtkMedialSolidCheck::Run without allPairs) counts them and says where,
// exactly, on a horn torus (one pinch within one shell), two cubes sharing a corner (one
// pinch between two shells) and a ring torus (none, though its Euler characteristic
// leaves room for two extra fans); the repair filter's output is manifold at every
// vertex (a copy of the pinched point per extra fan, at the same place), wound as the
// input, with a "pinch:" report line; the sampler's preparation keeps the pinch and
// says so, and so does the medial mesh's topology check. Before the AUTO screen counted
// them, the horn torus passed through the repair untouched. The count's two ways (a fan
// walk over the edge neighbours, which the check has; the corners grouped by vertex,
// once they are freed) give a brute-force reference's count and lowest pinched vertex on
// cones sharing their apex (three, and twelve: a vertex of many fans), pinches on a torus
// (genus 1) at several vertices, and large tori without one.
#include "MedialDefectTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkMath.h"

#include <functional>
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

// The brute-force reference on the mesh's own triangles: at each vertex, its triangles
// joined when they share an edge through it (union-find); pinched when they make two
// groups or more. The count, and the lowest pinched vertex (or -1) in `lowest`.
vtkIdType PinchedByReference(const vtkMedialTriangleMesh& mesh, vtkIdType& lowest)
{
  std::vector<std::vector<vtkIdType>> around(static_cast<size_t>(mesh.GetNumberOfPoints()));
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      around[mesh.GetTriangle(t)[k]].push_back(t);
    }
  }
  vtkIdType pinched = 0;
  lowest = -1;
  for (vtkIdType v = 0; v < static_cast<vtkIdType>(around.size()); ++v)
  {
    const std::vector<vtkIdType>& tris = around[v];
    std::vector<size_t> parent(tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
    {
      parent[i] = i;
    }
    std::function<size_t(size_t)> root = [&](size_t i) { return parent[i] == i ? i : parent[i] = root(parent[i]); };
    size_t groups = tris.size();
    for (size_t i = 0; i < tris.size(); ++i)
    {
      for (size_t j = i + 1; j < tris.size(); ++j)
      {
        const vtkIdType *a = mesh.GetTriangle(tris[i]), *b = mesh.GetTriangle(tris[j]);
        bool edge = false; // a vertex other than v in both
        for (int p = 0; p < 3; ++p)
        {
          for (int q = 0; q < 3; ++q)
          {
            edge = edge || (a[p] != v && a[p] == b[q]);
          }
        }
        if (edge && root(i) != root(j))
        {
          parent[root(i)] = root(j);
          --groups;
        }
      }
    }
    if (groups > 1)
    {
      lowest = pinched == 0 ? v : lowest;
      ++pinched;
    }
  }
  return pinched;
}

// A closed cone: apex `apex`, axis `axis` (unit), height 1, base radius 0.2, `sides`
// sides, its base closed by a fan from the base's centre.
vtkSmartPointer<vtkPolyData> Cone(const double apex[3], const double axis[3], int sides)
{
  double u[3], w[3];
  const double any[3] = { std::fabs(axis[0]) < 0.9 ? 1.0 : 0.0, std::fabs(axis[0]) < 0.9 ? 0.0 : 1.0, 0.0 };
  vtkMath::Cross(axis, any, u);
  vtkMath::Normalize(u);
  vtkMath::Cross(axis, u, w);
  std::vector<medialtest::defects::Point> x;
  x.push_back({ apex[0], apex[1], apex[2] });
  x.push_back({ apex[0] + axis[0], apex[1] + axis[1], apex[2] + axis[2] });
  std::vector<std::array<vtkIdType, 3>> tris;
  for (int i = 0; i < sides; ++i)
  {
    const double a = 2.0 * M_PI * i / sides, c = 0.2 * std::cos(a), s = 0.2 * std::sin(a);
    x.push_back({ x[1][0] + c * u[0] + s * w[0], x[1][1] + c * u[1] + s * w[1], x[1][2] + c * u[2] + s * w[2] });
    const vtkIdType b = 2 + i, next = 2 + (i + 1) % sides;
    tris.push_back({ 0, b, next });
    tris.push_back({ 1, next, b });
  }
  return medialtest::defects::Mesh(x, tris);
}

// `surface` with a cone on its point `at` (the same coordinates, merged by the mesh),
// along `axis`.
vtkSmartPointer<vtkPolyData> WithCone(vtkPolyData* surface, vtkIdType at, const double axis[3], int sides = 7)
{
  double apex[3];
  surface->GetPoint(at, apex);
  return medialtest::defects::Append(surface, Cone(apex, axis, sides));
}

// The point of `surface` furthest along `d`.
vtkIdType Extreme(vtkPolyData* surface, const double d[3])
{
  vtkIdType best = 0;
  for (vtkIdType i = 1; i < surface->GetNumberOfPoints(); ++i)
  {
    if (vtkMath::Dot(surface->GetPoint(i), d) > vtkMath::Dot(surface->GetPoint(best), d))
    {
      best = i;
    }
  }
  return best;
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
  // The count against the reference, by both of its ways.
  {
    auto torus = [](int resolution) { return medialtest::defects::Shape(vtkMedialShapeSource::TORUS, resolution); };
    const double up[3] = { 0, 0, 1 }, out[3] = { 1, 0, 0 }, back[3] = { -1, 0, 0 }, side[3] = { 0, 1, 0 };
    // Cones that share their apex, at the origin (one vertex, one fan per cone).
    auto cones = [](int n) {
      vtkSmartPointer<vtkPolyData> all;
      for (int i = 0; i < n; ++i)
      {
        const double a = 2.0 * M_PI * i / n, axis[3] = { std::cos(a), std::sin(a), 0.0 }, apex[3] = { 0, 0, 0 };
        auto cone = Cone(apex, axis, 9);
        all = all ? medialtest::defects::Append(all, cone) : cone;
      }
      return all;
    };
    // A torus (genus 1) with cones on three of its points, three on the top one.
    auto pinchedTorus = [&]() {
      vtkSmartPointer<vtkPolyData> t = torus(24);
      const vtkIdType right = Extreme(t, out), left = Extreme(t, back), top = Extreme(t, up);
      t = WithCone(t, right, out);
      t = WithCone(t, left, back, 11);
      for (int i = 0; i < 3; ++i)
      {
        const double a = 2.0 * M_PI * i / 3, tilted[3] = { 0.5 * std::cos(a), 0.5 * std::sin(a), 1.0 };
        double axis[3] = { tilted[0], tilted[1], tilted[2] };
        vtkMath::Normalize(axis);
        t = WithCone(t, top, axis);
      }
      return t;
    };
    struct Count
    {
      std::string Name;
      vtkSmartPointer<vtkPolyData> Surface;
      vtkIdType Pinched;
    };
    const std::vector<Count> surfaces = {
      { "three cones at a point", cones(3), 1 },
      { "twelve cones at a point", cones(12), 1 },
      { "torus with cones", pinchedTorus(), 3 },
      { "torus with a cone", WithCone(torus(64), Extreme(torus(64), side), side), 1 },
      { "horn torus", medialtest::defects::HornTorus(96, 48).Surface, 1 },
      { "ring torus 16", torus(16), 0 },
      { "ring torus 128", torus(128), 0 },
    };
    for (const Count& s : surfaces)
    {
      vtkMedialTriangleMesh mesh;
      std::string error;
      MEDIAL_CHECK(mesh.Build(s.Surface, error), "%s: %s", s.Name.c_str(), error.c_str());
      MEDIAL_CHECK(mesh.PinchedVertexBound() > 0, "%s: the Euler bound rules pinches out", s.Name.c_str());
      MEDIAL_CHECK(!mesh.EdgeNeighbours.empty(), "%s: no edge neighbours", s.Name.c_str());
      vtkIdType lowest = -1, walked = -1, grouped = -1;
      const vtkIdType reference = PinchedByReference(mesh, lowest);
      const vtkIdType byWalk = mesh.CountPinchedVertices(&walked);
      mesh.FreeEdgeNeighbours();
      const vtkIdType byGroup = mesh.CountPinchedVertices(&grouped);
      std::printf("%-24s %lld triangles: %lld pinched (lowest %lld), fan walk %lld (%lld), grouped %lld (%lld)\n",
        s.Name.c_str(), static_cast<long long>(mesh.GetNumberOfTriangles()), static_cast<long long>(reference),
        static_cast<long long>(lowest), static_cast<long long>(byWalk), static_cast<long long>(walked),
        static_cast<long long>(byGroup), static_cast<long long>(grouped));
      MEDIAL_CHECK(byWalk == reference && walked == lowest, "%s: the fan walk's count differs from the reference",
        s.Name.c_str());
      MEDIAL_CHECK(byGroup == reference && grouped == lowest, "%s: the grouped count differs from the reference",
        s.Name.c_str());
      MEDIAL_CHECK(reference == s.Pinched, "%s: %lld pinched vertices by the reference, expected %lld", s.Name.c_str(),
        static_cast<long long>(reference), static_cast<long long>(s.Pinched));
    }
  }

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

  // Two cubes sharing a corner: the check leaves their pairs at the corner to the exact
  // test, so the preparation asks the repair. The exact test clears them, and what is left
  // (the pinch) is no defect to a filter: the input is kept as it was prepared, not split
  // and prepared again, and the pinch is named as kept.
  vtkNew<vtkMedialAxisSampler> cubes;
  cubes->SetInputData(medialtest::defects::CubesSharingAVertex().Surface);
  cubes->SetNumberOfSamples(2000);
  medialtest::EventLog cubesLog;
  cubesLog.Watch(cubes);
  cubes->Update();
  std::printf("sampler on the cubes: repaired %d; %s\n", cubes->GetSurfaceRepaired() ? 1 : 0,
    cubesLog.LineWith("pinched").c_str());
  MEDIAL_CHECK(!cubes->GetSurfaceRepaired(), "the cubes sharing a corner were split and prepared again");
  MEDIAL_CHECK(!cubesLog.LineWith("1 pinched vertex").empty() && !cubesLog.LineWith(": kept").empty(),
    "the sampler does not name the cubes' pinch as kept");
  MEDIAL_CHECK(cubesLog.LineWith("pinch:").empty(), "the sampler reports a split of the cubes' pinch");
  MEDIAL_CHECK(cubes->GetOutput()->GetNumberOfPoints() == 2000, "the cubes gave %lld balls",
    static_cast<long long>(cubes->GetOutput()->GetNumberOfPoints()));
  return EXIT_SUCCESS;
}
