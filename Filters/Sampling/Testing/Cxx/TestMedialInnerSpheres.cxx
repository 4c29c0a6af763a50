// SPDX-License-Identifier: BSD-3-Clause
// The tree's inner spheres (vtkMedialTriangleBVH::WideSphere) drop subtrees from the
// one-pass search only where nothing in them could change the ball, so the default
// balls are the same bits with and without them. Every sample's ball is solved as the
// sampler solves it (smooth normals, theta 45, protrusion 1e-4 of the diagonal, the
// previous sample's contact and blockers as hints, the running protrusion measured)
// with the spheres on and off, on a family of tessellated shapes whose balls lie within
// rounding of most of their surface (geodesic spheres at four resolutions, a UV sphere,
// a hollow sphere, a torus, a capsule, the contoured torus) and on the jack, at two
// seeds; with the shared meshes present, on horse.ply too. Every field of every record,
// the blocker chains and the running protrusion must agree bit for bit, and every inner
// sphere's bound must hold against an exact closest point of each triangle under it.
// The cost guard counts triangles, not time (TangentBall::Visited): inside the geodesic
// sphere of 81,920 triangles a search looked at nearly all of them without the spheres;
// with them it must look at fewer than 2% on average, and without them it must look at
// more than half (the case stays hard, so the guard keeps meaning something).
#include "MedialTestUtilities.h"

#include "vtkMedialBallSolver.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceNormals.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
constexpr double Theta = 45.0;

struct Solver
{
  vtkMedialTriangleMesh Mesh;
  vtkMedialSurfaceQuery Query;
  vtkMedialSurfaceNormals Normals;
  vtkMedialBallParameters Param{};

  bool Build(vtkPolyData* surface, std::string& error)
  {
    if (!this->Mesh.Build(surface, error) || !this->Query.Build(&this->Mesh, error))
    {
      return false;
    }
    this->Normals.Build(this->Mesh, Theta, &this->Query);
    this->Param =
      vtkMedialMakeBallParameters(vtkMedialBallParameters::ONE_PASS, 1e-6, Theta, 1e-4, 100, this->Mesh.Diagonal);
    this->Param.Normals = &this->Normals;
    return true;
  }
};

bool SameRecord(const vtkMedialSampleRecord& a, const vtkMedialSampleRecord& b)
{
  return std::memcmp(a.Centre, b.Centre, sizeof(a.Centre)) == 0 &&
    std::memcmp(&a.Radius, &b.Radius, sizeof(double)) == 0 &&
    std::memcmp(a.Contact, b.Contact, sizeof(a.Contact)) == 0 &&
    std::memcmp(&a.Angle, &b.Angle, sizeof(double)) == 0 && a.SourceCell == b.SourceCell &&
    a.ContactTriangle == b.ContactTriangle && a.Iterations == b.Iterations && a.Valid == b.Valid &&
    a.Capped == b.Capped && a.Shrunk == b.Shrunk;
}

bool SameChain(const vtkMedialTriangleBVH::BlockerChain& a, const vtkMedialTriangleBVH::BlockerChain& b)
{
  return a.Count == b.Count && a.Deepest == b.Deepest &&
    std::equal(a.Triangles, a.Triangles + a.Count, b.Triangles);
}

// The balls of `samples` samples of stream `seed`, with the spheres on and off.
int CompareBalls(Solver& s, const char* label, std::uint64_t seed, vtkIdType samples)
{
  std::vector<vtkMedialSampleRecord> balls[2];
  std::vector<vtkMedialTriangleBVH::BlockerChain> chains[2];
  double largest[2] = { 0.0, 0.0 };
  for (int on = 0; on < 2; ++on)
  {
    s.Query.SetInnerSpheres(on == 1);
    balls[on].resize(samples);
    chains[on].resize(samples);
    vtkMedialTriangleBVH::BlockerChain chain;
    vtkIdType hint = -1;
    for (vtkIdType i = 0; i < samples; ++i)
    {
      vtkIdType triangle;
      double p[3];
      vtkMedialDrawSurfacePoint(s.Mesh, seed, i, triangle, p);
      vtkMedialSolveBall(s.Query, s.Mesh, s.Param, triangle, p, balls[on][i], hint, &chain, &largest[on]);
      chains[on][i] = chain;
      hint = balls[on][i].Valid ? balls[on][i].ContactTriangle : -1;
    }
  }
  s.Query.SetInnerSpheres(true);
  vtkIdType differ = 0, first = -1;
  for (vtkIdType i = 0; i < samples; ++i)
  {
    if (!SameRecord(balls[0][i], balls[1][i]) || !SameChain(chains[0][i], chains[1][i]))
    {
      first = first < 0 ? i : first;
      ++differ;
    }
  }
  std::printf("%s (%lld triangles), seed %llu: %lld of %lld balls differ; largest protrusion %.17g / %.17g\n",
    label, static_cast<long long>(s.Mesh.GetNumberOfTriangles()), static_cast<unsigned long long>(seed),
    static_cast<long long>(differ), static_cast<long long>(samples), largest[0], largest[1]);
  MEDIAL_CHECK(differ == 0, "%s seed %llu: sample %lld's ball differs with the inner spheres (radius %.17g / %.17g)",
    label, static_cast<unsigned long long>(seed), static_cast<long long>(first),
    first >= 0 ? balls[0][first].Radius : 0.0, first >= 0 ? balls[1][first].Radius : 0.0);
  MEDIAL_CHECK(std::memcmp(&largest[0], &largest[1], sizeof(double)) == 0,
    "%s seed %llu: the measured protrusion differs", label, static_cast<unsigned long long>(seed));
  return EXIT_SUCCESS;
}

// Mean triangles a search looks at, over `samples` samples, solved as vtkMedialSolveBall
// does (the smooth normal at p, the ray's far hit as the bound, the previous contact).
double MeanVisited(Solver& s, bool spheres, vtkIdType samples)
{
  s.Query.SetInnerSpheres(spheres);
  vtkMedialTriangleBVH::BlockerChain chain;
  vtkIdType hint = -1;
  double largest = 0.0, total = 0.0;
  for (vtkIdType i = 0; i < samples; ++i)
  {
    vtkIdType triangle;
    double p[3], smooth[3], scratch[9];
    vtkMedialDrawSurfacePoint(s.Mesh, 1, i, triangle, p);
    const double* outward = s.Query.GetNormal(triangle);
    double n[3] = { -outward[0], -outward[1], -outward[2] };
    vtkIdType own = triangle;
    if (!s.Normals.At(triangle, s.Query.GetTriangleVertices(triangle, scratch), outward, p, smooth))
    {
      n[0] = -smooth[0];
      n[1] = -smooth[1];
      n[2] = -smooth[2];
      own = -1;
    }
    vtkMedialSurfaceQuery::RayHit hit;
    if (!s.Query.IntersectFromInside(p, n, 1e-9 * s.Mesh.Diagonal, own, hit))
    {
      continue;
    }
    vtkMedialSurfaceQuery::TangentBall ball;
    ball.Radius = 0.5 * hit.Distance;
    for (int k = 0; k < 3; ++k)
    {
      ball.Contact[k] = p[k] + hit.Distance * n[k];
    }
    ball.ContactTriangle = hit.Triangle;
    ball.HintTriangle = hint;
    ball.Blockers = chain;
    ball.MeasureProtrusion = true;
    ball.LargestProtrusion = largest;
    vtkMedialSurfaceQuery::ContactFilter filter;
    filter.OwnTriangle = own;
    std::copy(p, p + 3, filter.SamplePoint);
    filter.CosMinAngle = s.Param.CosMinAngle;
    s.Query.MaximalTangentBall(p, n, filter, s.Param.MaximumProtrusion, ball);
    largest = ball.LargestProtrusion;
    chain = ball.Blockers;
    hint = ball.ContactTriangle;
    total += ball.Visited;
  }
  s.Query.SetInnerSpheres(true);
  return total / static_cast<double>(samples);
}

vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  if (resolution > 0)
  {
    source->SetResolution(resolution);
  }
  source->Update();
  return source->GetOutput();
}
}

int TestMedialInnerSpheres(int, char*[])
{
  struct Case
  {
    std::string Label;
    vtkSmartPointer<vtkPolyData> Surface;
  };
  std::vector<Case> cases;
  for (int resolution : { 2, 3, 4, 5 })
  {
    cases.push_back({ "geodesic sphere " + std::to_string(resolution), Shape(vtkMedialShapeSource::SPHERE, resolution) });
  }
  vtkNew<vtkSphereSource> uv;
  uv->SetThetaResolution(90);
  uv->SetPhiResolution(90);
  uv->SetRadius(0.3);
  uv->Update();
  cases.push_back({ "UV sphere 90 x 90", uv->GetOutput() });
  cases.push_back({ "hollow sphere", Shape(vtkMedialShapeSource::HOLLOW_SPHERE, 3) });
  cases.push_back({ "torus", Shape(vtkMedialShapeSource::TORUS, 24) });
  cases.push_back({ "capsule", Shape(vtkMedialShapeSource::CAPSULE, 24) });
  cases.push_back({ "contoured torus", Shape(vtkMedialShapeSource::CONTOURED_TORUS, 60) });
  cases.push_back({ "jack", Shape(vtkMedialShapeSource::JACK, 0) });
  if (vtkSmartPointer<vtkPolyData> horse = ReadSharedPLY("horse.ply"))
  {
    cases.push_back({ "horse.ply", horse });
  }
  for (const Case& c : cases)
  {
    Solver s;
    std::string error;
    MEDIAL_CHECK(s.Build(c.Surface, error), "%s: %s", c.Label.c_str(), error.c_str());
    const vtkIdType violations = s.Query.CountInnerSphereViolations();
    MEDIAL_CHECK(violations == 0, "%s: %lld inner spheres claim more room than they have", c.Label.c_str(),
      static_cast<long long>(violations));
    for (std::uint64_t seed : { 1u, 7u })
    {
      if (CompareBalls(s, c.Label.c_str(), seed, 400) != EXIT_SUCCESS)
      {
        return EXIT_FAILURE;
      }
    }
  }

  Solver sphere;
  std::string error;
  MEDIAL_CHECK(sphere.Build(Shape(vtkMedialShapeSource::SPHERE, 6), error), "sphere: %s", error.c_str());
  const double triangles = static_cast<double>(sphere.Mesh.GetNumberOfTriangles());
  const double with = MeanVisited(sphere, true, 200), without = MeanVisited(sphere, false, 50);
  std::printf("geodesic sphere of %.0f triangles: %.1f triangles looked at per search with the inner spheres, "
              "%.1f without\n",
    triangles, with, without);
  MEDIAL_CHECK(with < 0.02 * triangles, "the inner spheres leave %.1f triangles a search (%.2f%%)", with,
    100.0 * with / triangles);
  MEDIAL_CHECK(without > 0.5 * triangles, "without the inner spheres a search looked at only %.1f triangles: "
    "the case no longer tests the spheres", without);
  return EXIT_SUCCESS;
}
