// SPDX-License-Identifier: BSD-3-Clause
// VisitWithinIfEmpty reads a ball's contacts and whether a smaller concentric ball is
// empty in one walk, in place of ContainsBall then VisitWithin (the medial mesh's
// classifier and seam tracer ask both of every ball). Its answers must be those of
// the two queries to the bit: the same emptiness and, when empty, the same visits
// (squared distance, closest point, triangle) in the same order. Checked on a box
// (ties at shared edges and vertices), a geodesic sphere and the jack, from points
// inside, around and far beyond each shape (where the tree walks in double), with
// the empty radius below, at (to the bit) and above the brute-force distance, and
// contact distances at and beyond it. The same queries read from a list of the
// triangles near a point beside x (vtkMedialTriangleBVH::Nearby, the seam solver's
// bisections) give the same answers and visits (in leaf order, so compared by
// triangle), whether the list covers the query or is ignored for not covering it.
// Asked for the nearest point of a blocked ball, the walk goes on as ClosestPoint's
// from the bound it gives, and finds ClosestPoint's point, distance and triangle.
#include "MedialTestUtilities.h"
#include "MedialTreeTestUtilities.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
namespace G = vtkMedialGeometry;
using Visit = std::array<double, 5>; // d2, q, triangle

double BruteForce2(const vtkMedialTriangleMesh& mesh, const double x[3])
{
  double best = HUGE_VAL;
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    double q[3];
    best = std::min(best, G::ClosestPointOnTriangle(x, mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]), q));
  }
  return best;
}

int CheckShape(int shape, const char* name, int resolution)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  double lo[3], hi[3];
  MEDIAL_CHECK(BuildShapeMesh(shape, resolution, mesh, lo, hi, error), "%s: %s", name, error.c_str());
  vtkMedialTriangleBVH tree;
  MEDIAL_CHECK(tree.Build(mesh), "%s: no tree", name);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int queries = 0, empty = 0, blocked = 0, covered = 0, nearestInWalk = 0;
  for (int i = 0; i < 300; ++i)
  {
    // Around the shape, or (one point in ten) far beyond its box.
    const double spread = i % 10 == 9 ? 12.0 : 1.2;
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = lo[k] + (0.5 - 0.5 * spread + spread * unit(random)) * (hi[k] - lo[k]);
    }
    const double exact2 = BruteForce2(mesh, x);
    const double exact = std::sqrt(exact2);
    // Radii whose squares fall on either side of the nearest squared distance, and on it.
    std::vector<double> radii = { 0.0, 0.5 * exact, std::nextafter(exact, 0.0), exact,
      std::nextafter(exact, HUGE_VAL), exact * (1.0 + 1e-9), 2.0 * exact };
    for (double radius : radii)
    {
      for (double extra : { 0.0, 1e-9 * mesh.Diagonal, 0.1 * mesh.Diagonal })
      {
        const double distance = radius + extra;
        std::vector<Visit> expected, got;
        auto into = [](std::vector<Visit>& list) {
          return [&list](double d2, const double* q, vtkIdType t) {
            list.push_back({ d2, q[0], q[1], q[2], static_cast<double>(t) });
          };
        };
        const bool reference = !(radius > 0.0) || tree.ContainsBall(x, radius, -1, nullptr, 1.0, false);
        if (reference)
        {
          tree.VisitWithin(x, distance, nullptr, 1.0, into(expected));
        }
        const bool answer = tree.VisitWithinIfEmpty(x, distance, radius, into(got));
        MEDIAL_CHECK(answer == reference, "%s, point %d, radius %.17g (nearest %.17g): one walk says %s, two %s", name,
          i, radius, exact, answer ? "empty" : "blocked", reference ? "empty" : "blocked");
        MEDIAL_CHECK(!answer || got == expected, "%s, point %d, radius %.17g, distance %.17g: %zu visits, expected %zu",
          name, i, radius, distance, got.size(), expected.size());
        // Asked for the nearest point too: when blocked, the walk goes on as ClosestPoint's
        // from the bound it gives, and must find that walk's point, distance and triangle.
        {
          std::vector<Visit> ignored;
          double bound = HUGE_VAL;
          vtkMedialTriangleBVH::NearestPoint nearest;
          const bool again = tree.VisitWithinIfEmpty(x, distance, radius, into(ignored), &bound, nullptr, &nearest);
          MEDIAL_CHECK(again == reference, "%s, point %d, radius %.17g: asked for the nearest, says %s", name, i,
            radius, again ? "empty" : "blocked");
          MEDIAL_CHECK(!again || nearest.Triangle < 0, "%s, point %d: an empty ball has a nearest point", name, i);
          if (!again && nearest.Triangle >= 0)
          {
            double q[3], d;
            vtkIdType t;
            MEDIAL_CHECK(tree.ClosestPoint(x, bound, -1, nullptr, 1.0, false, q, d, t), "%s, point %d: no closest point",
              name, i);
            MEDIAL_CHECK(t == nearest.Triangle && d == nearest.Distance && q[0] == nearest.Point[0] &&
                q[1] == nearest.Point[1] && q[2] == nearest.Point[2],
              "%s, point %d, radius %.17g: nearest on triangle %lld at %.17g, ClosestPoint's on %lld at %.17g", name,
              i, radius, static_cast<long long>(nearest.Triangle), nearest.Distance, static_cast<long long>(t), d);
            ++nearestInWalk;
          }
        }
        // A list gathered about a point beside x: wide enough to cover the query, or
        // (one query in three) just too narrow, when it must be ignored.
        vtkMedialTriangleBVH::Nearby nearby;
        const double shift = 0.01 * mesh.Diagonal;
        const double beside[3] = { x[0] + shift, x[1], x[2] };
        const bool narrow = queries % 3 == 2;
        tree.GatherNearby(beside, distance + (narrow ? 0.5 : 2.0) * shift, nearby);
        covered += tree.Covers(nearby, x, distance) ? 1 : 0;
        MEDIAL_CHECK(!narrow || !tree.Covers(nearby, x, distance), "%s, point %d: a narrow list covers", name, i);
        std::vector<Visit> listed;
        const bool fromList = tree.VisitWithinIfEmpty(x, distance, radius, into(listed), nullptr, &nearby);
        auto byTriangle = [](std::vector<Visit>& list) {
          std::sort(list.begin(), list.end(), [](const Visit& a, const Visit& b) { return a[4] < b[4]; });
          return list;
        };
        MEDIAL_CHECK(fromList == reference, "%s, point %d, radius %.17g: the list says %s", name, i, radius,
          fromList ? "empty" : "blocked");
        MEDIAL_CHECK(!fromList || byTriangle(listed) == byTriangle(expected),
          "%s, point %d, radius %.17g: %zu visits from the list, expected %zu", name, i, radius, listed.size(),
          expected.size());
        listed.clear();
        tree.VisitWithin(x, distance, nullptr, 1.0, into(listed), &nearby);
        if (reference)
        {
          MEDIAL_CHECK(byTriangle(listed) == byTriangle(expected), "%s, point %d: VisitWithin from the list differs",
            name, i);
        }
        ++queries;
        (answer ? empty : blocked) += 1;
      }
    }
  }
  MEDIAL_CHECK(empty > queries / 4 && blocked > queries / 4, "%s: %d empty, %d blocked of %d", name, empty,
    blocked, queries);
  MEDIAL_CHECK(covered > queries / 2, "%s: %d of %d queries read from a list", name, covered, queries);
  MEDIAL_CHECK(nearestInWalk > blocked / 2, "%s: %d of %d blocked queries found their nearest point in the walk",
    name, nearestInWalk, blocked);
  std::printf("%s: %d queries agree (%d empty, %d blocked, %d nearest in the walk, %d from a list)\n", name,
    queries, empty, blocked, nearestInWalk, covered);
  return EXIT_SUCCESS;
}
}

int TestMedialContactsIfEmpty(int, char*[])
{
  int failed = CheckShape(vtkMedialShapeSource::BOX, "box", 12);
  failed |= CheckShape(vtkMedialShapeSource::SPHERE, "sphere", 5);
  failed |= CheckShape(vtkMedialShapeSource::JACK, "jack", 16);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
