// SPDX-License-Identifier: BSD-3-Clause
// The inside test counts a ray's crossings from one walk over the ray
// (vtkMedialTriangleBVH::RayCrossings) instead of restarting the ray past each hit. The
// answer must be the same bits as the restarts': on generated solids (a box, whose rays
// run along its edges and in its faces; a geodesic sphere; a torus; a hollow sphere; the
// genus rings; a contoured torus) and rays from random points, from exactly on vertices,
// edges and faces and from just off them (1e-12 to 1e-6 of the diagonal, either side),
// along random directions, axes, towards vertices and along IsInside's own directions:
//  - FirstCrossing equals IntersectRay at every restart the counting makes and at
//    random starts, t and triangle, for both walks (a unit direction takes the
//    four-lane walk, the same scaled by 4 the binary one);
//  - CountCrossings equals Intersect() restarted CrossingStep() past each hit, to a
//    finite end and to infinity;
//  - IsInside equals the two-of-three parity of those restarted counts.
#include "MedialTestUtilities.h"
#include "MedialTreeTestUtilities.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
namespace G = vtkMedialGeometry;

// vtkMedialSurfaceQuery::IsInside's directions (its reference below must use the same).
const double InsideDirections[3][3] = { { 0.5773502691896258, 0.6172133998483676, 0.5345224838248488 },
  { -0.7071067811865476, 0.2672612419124244, 0.6546536707079771 },
  { 0.2182178902359924, -0.8728715609439696, 0.4364357804719848 } };

// The crossings counted the way they used to be: Intersect() from 0, restarted past each hit.
int RestartedCount(const vtkMedialSurfaceQuery& query, const double o[3], const double d[3], double tMax,
  std::vector<double>& starts)
{
  int count = 0;
  double start = 0.0;
  vtkMedialSurfaceQuery::RayHit hit;
  starts.assign(1, 0.0);
  while (count < 100000 && query.Intersect(o, d, start, tMax, -1, hit))
  {
    ++count;
    start = std::max(hit.Distance, start) + query.CrossingStep();
    starts.push_back(start);
  }
  return count;
}

bool RestartedInside(const vtkMedialSurfaceQuery& query, const double x[3])
{
  const double* b = query.GetMesh()->Bounds;
  if (x[0] < b[0] || x[0] > b[1] || x[1] < b[2] || x[1] > b[3] || x[2] < b[4] || x[2] > b[5])
  {
    return false;
  }
  std::vector<double> starts;
  const int first = RestartedCount(query, x, InsideDirections[0], HUGE_VAL, starts) % 2;
  const int second = RestartedCount(query, x, InsideDirections[1], HUGE_VAL, starts) % 2;
  return first == second ? first == 1 : RestartedCount(query, x, InsideDirections[2], HUGE_VAL, starts) % 2 == 1;
}

struct Counts
{
  int Rays = 0, Starts = 0, Crossings = 0, InPlane = 0, Inside = 0, Points = 0;
};

// One ray: the list's first hit at each start against IntersectRay on both walks, and
// the counts. False (after a message) on the first disagreement.
bool CheckRay(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleBVH& tree, const double o[3],
  const double d[3], const char* shape, const char* kind, int index, std::mt19937_64& random, Counts& counts)
{
  const double diagonal = query.GetMesh()->Diagonal;
  std::vector<vtkMedialTriangleBVH::RayCrossing> crossings, crossings4;
  tree.RayCrossings(o, d, 0.0, -1, crossings);
  const double d4[3] = { 4.0 * d[0], 4.0 * d[1], 4.0 * d[2] };
  tree.RayCrossings(o, d4, 0.0, -1, crossings4);
  for (const auto& c : crossings)
  {
    counts.InPlane += c.InPlane ? 1 : 0;
  }
  std::vector<double> starts;
  const double tMax = 0.5 * diagonal;
  for (double end : { HUGE_VAL, tMax })
  {
    const int restarted = RestartedCount(query, o, d, end, starts);
    const int counted = query.CountCrossings(o, d, end);
    if (restarted != counted)
    {
      std::fprintf(stderr, "%s, %s ray %d (to %g): %d crossings restarted, %d from one walk\n", shape, kind, index,
        end, restarted, counted);
      return false;
    }
    counts.Crossings += end == HUGE_VAL ? counted : 0;
  }
  // The starts the counting made (the first 48 and the last 16: a ray along a face
  // restarts up to the cap), their neighbours, and random ones.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> tried;
  for (size_t i = 0; i < starts.size(); ++i)
  {
    if (i < 48 || i + 16 >= starts.size())
    {
      const double s = starts[i];
      tried.insert(tried.end(), { s, std::nextafter(s, HUGE_VAL), std::nextafter(s, 0.0) });
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    tried.push_back(unit(random) * diagonal);
  }
  for (double s : tried)
  {
    if (!(s >= 0.0))
    {
      continue;
    }
    for (int walk = 0; walk < 2; ++walk)
    {
      const double* dir = walk ? d4 : d;
      const double start = walk ? 0.25 * s : s; // the same points along the ray
      const double end = walk ? 0.25 * tMax : tMax;
      for (double limit : { HUGE_VAL, end })
      {
        double t0 = 0.0, t1 = 0.0;
        vtkIdType a = -1, b = -1;
        const bool hit0 = tree.IntersectRay(o, dir, start, limit, -1, t0, a);
        const bool hit1 = vtkMedialTriangleBVH::FirstCrossing(walk ? crossings4 : crossings, start, limit, t1, b);
        if (hit0 != hit1 || a != b || (hit0 && t0 != t1))
        {
          std::fprintf(stderr,
            "%s, %s ray %d, %s walk from %.17g: IntersectRay %d (triangle %lld, t %.17g), the list %d (%lld, %.17g)\n",
            shape, kind, index, walk ? "binary" : "four-lane", start, hit0, static_cast<long long>(a), t0, hit1,
            static_cast<long long>(b), t1);
          return false;
        }
        ++counts.Starts;
      }
    }
  }
  ++counts.Rays;
  return true;
}

bool CheckPoint(const vtkMedialSurfaceQuery& query, const double x[3], const char* shape, int index, Counts& counts)
{
  const bool restarted = RestartedInside(query, x), counted = query.IsInside(x);
  if (restarted != counted)
  {
    std::fprintf(stderr, "%s, point %d (%.17g %.17g %.17g): inside %d restarted, %d from one walk\n", shape, index,
      x[0], x[1], x[2], restarted, counted);
    return false;
  }
  counts.Inside += counted ? 1 : 0;
  ++counts.Points;
  return true;
}

int CheckShape(int shape, const char* name, int resolution)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  double lo[3], hi[3];
  MEDIAL_CHECK(BuildShapeMesh(shape, resolution, mesh, lo, hi, error), "%s: %s", name, error.c_str());
  vtkMedialSurfaceQuery query;
  MEDIAL_CHECK(query.Build(&mesh, error), "%s: %s", name, error.c_str());
  vtkMedialTriangleBVH tree;
  MEDIAL_CHECK(tree.Build(mesh), "%s: no tree", name);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  auto normalize = [](double d[3]) {
    const double l = std::sqrt(G::Dot(d, d));
    for (int k = 0; k < 3; ++k)
    {
      d[k] /= l;
    }
  };
  Counts counts;
  const double offsets[] = { 0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6 };
  for (int i = 0; i < 120; ++i)
  {
    // A point: random in the box, or on (and just off) a vertex, an edge or a face.
    const vtkIdType t = static_cast<vtkIdType>(unit(random) * mesh.GetNumberOfTriangles());
    const vtkIdType* v = mesh.GetTriangle(t);
    const double* p[3] = { mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]) };
    double w[3] = { unit(random), unit(random), 0.0 };
    switch (i % 4)
    {
      case 0: // random: barycentric weights unused
        break;
      case 1: // a vertex
        w[0] = 1.0;
        w[1] = 0.0;
        break;
      case 2: // an edge
        w[1] = 1.0 - w[0];
        break;
      default: // a face
        if (w[0] + w[1] > 1.0)
        {
          w[0] = 1.0 - w[0];
          w[1] = 1.0 - w[1];
        }
    }
    w[2] = 1.0 - w[0] - w[1];
    double base[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      base[k] = i % 4 == 0 ? lo[k] + (-0.02 + 1.04 * unit(random)) * (hi[k] - lo[k])
                           : w[0] * p[0][k] + w[1] * p[1][k] + w[2] * p[2][k];
    }
    const double* n = query.GetNormal(t);
    for (double offset : offsets)
    {
      if (i % 4 == 0 && offset != 0.0)
      {
        continue;
      }
      double x[3];
      G::AddScaled(base, offset * mesh.Diagonal, n, x);
      MEDIAL_CHECK(CheckPoint(query, x, name, i, counts), "see above");
      for (int k = 0; k < 3; ++k)
      {
        MEDIAL_CHECK(CheckRay(query, tree, x, InsideDirections[k], name, "inside-test", i, random, counts),
          "see above");
      }
    }
    // Rays from the point: random, to a vertex, along an axis (in the box's faces).
    double d[3] = { gauss(random), gauss(random), gauss(random) };
    normalize(d);
    MEDIAL_CHECK(CheckRay(query, tree, base, d, name, "random", i, random, counts), "see above");
    const double* u = mesh.GetPoint(static_cast<vtkIdType>(unit(random) * mesh.GetNumberOfPoints()));
    G::Sub(u, base, d);
    if (G::Dot(d, d) > 0.0)
    {
      normalize(d);
      MEDIAL_CHECK(CheckRay(query, tree, base, d, name, "vertex", i, random, counts), "see above");
    }
    double e[3] = { 0.0, 0.0, 0.0 };
    e[i % 3] = (i / 3) % 2 ? 1.0 : -1.0;
    double a[3] = { u[0], u[1], u[2] };
    a[i % 3] = 0.5 * (lo[i % 3] + hi[i % 3]);
    MEDIAL_CHECK(CheckRay(query, tree, a, e, name, "axis", i, random, counts), "see above");
  }
  // The family must exercise what it claims: crossings, points on both sides.
  MEDIAL_CHECK(counts.Crossings > counts.Rays, "%s: only %d crossings on %d rays", name, counts.Crossings, counts.Rays);
  MEDIAL_CHECK(counts.Inside > 0 && counts.Inside < counts.Points, "%s: %d of %d points inside", name, counts.Inside,
    counts.Points);
  std::printf("%s: %lld triangles, %d rays (%d crossings, %d met in a face's plane), %d starts, %d of %d points "
              "inside: agree\n",
    name, static_cast<long long>(mesh.GetNumberOfTriangles()), counts.Rays, counts.Crossings, counts.InPlane,
    counts.Starts, counts.Inside, counts.Points);
  return EXIT_SUCCESS;
}
}

int TestMedialRayCrossings(int, char*[])
{
  int failed = CheckShape(vtkMedialShapeSource::BOX, "box", 6);
  failed |= CheckShape(vtkMedialShapeSource::SPHERE, "sphere", 4);
  failed |= CheckShape(vtkMedialShapeSource::TORUS, "torus", 24);
  failed |= CheckShape(vtkMedialShapeSource::HOLLOW_SPHERE, "hollow sphere", 3);
  failed |= CheckShape(vtkMedialShapeSource::RINGS, "rings", 24);
  failed |= CheckShape(vtkMedialShapeSource::CONTOURED_TORUS, "contoured torus", 16);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
