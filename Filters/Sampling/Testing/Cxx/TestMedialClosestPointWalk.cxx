// SPDX-License-Identifier: BSD-3-Clause
// The tree's closest-point query (and ContainsBall, on the same walk) walks the
// four-lane nodes in float. Its answer must be the brute force's over every triangle to
// the bit: the smallest squared distance from ClosestPointOnTriangle (or, with the
// angle rule, ClosestPointOnClippedTriangle) of any triangle, whichever of several
// tied triangles the walk met first. Checked on a box (ties at shared vertices and
// edges), a geodesic sphere and the jack, from points inside and around each shape,
// without the angle rule, with it and with its cap only, and with bounds below and
// above the distance (at it to within rounding, the answer depends on the rounding of
// the plane prefilter's squared distance against the exact test's: not asked).
#include "MedialTestUtilities.h"
#include "MedialTreeTestUtilities.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include <cmath>
#include <random>
#include <string>

using namespace medialtest;

namespace
{
namespace G = vtkMedialGeometry;

// The smallest squared distance over every triangle but `own`, with the tree's rule.
double BruteForce(const vtkMedialTriangleMesh& mesh, const double x[3], vtkIdType own, const double* s,
  double cosMinAngle, bool capOnly)
{
  const bool capped = cosMinAngle < 1.0 && s;
  double w[3] = { 0, 0, 0 }, k = 0.0;
  if (capped)
  {
    G::Sub(s, x, w);
    k = G::Dot(w, x) + G::Dot(w, w) * cosMinAngle;
    if (capOnly)
    {
      for (double& c : w)
      {
        c = -c;
      }
      k = -k;
    }
  }
  double best = HUGE_VAL;
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (t == own)
    {
      continue;
    }
    const vtkIdType* v = mesh.GetTriangle(t);
    double q[3];
    double d2 = G::ClosestPointOnTriangle(x, mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]), q);
    if (capped)
    {
      d2 = G::ClosestPointOnClippedTriangle(x, mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]), w, k, q);
    }
    best = std::min(best, d2);
  }
  return best;
}

// EXIT_SUCCESS when every query agrees (MEDIAL_CHECK returns EXIT_FAILURE).
int CheckShape(int shape, const char* name, int resolution)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  double lo[3], hi[3];
  MEDIAL_CHECK(BuildShapeMesh(shape, resolution, mesh, lo, hi, error), "%s: %s", name, error.c_str());
  vtkMedialTriangleBVH tree;
  MEDIAL_CHECK(tree.Build(mesh), "%s: no tree", name);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  int queries = 0, found = 0, contained = 0;
  for (int i = 0; i < 200; ++i)
  {
    // Around the shape (a little beyond its box), and a surface point s on a random
    // triangle for the angle rule.
    double x[3], s[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = lo[k] + (-0.1 + 1.2 * unit(random)) * (hi[k] - lo[k]);
    }
    const vtkIdType own = std::min(nt - 1, static_cast<vtkIdType>(unit(random) * nt));
    const vtkIdType* v = mesh.GetTriangle(own);
    double a = unit(random), b = unit(random);
    if (a + b > 1.0)
    {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    for (int k = 0; k < 3; ++k)
    {
      s[k] = (1.0 - a - b) * mesh.GetPoint(v[0])[k] + a * mesh.GetPoint(v[1])[k] + b * mesh.GetPoint(v[2])[k];
    }
    const double cosines[3] = { 1.0, std::cos(0.25 * 3.14159265358979323846), std::cos(0.25 * 3.14159265358979323846) };
    for (int rule = 0; rule < 3; ++rule)
    {
      const bool capOnly = rule == 2;
      const double exact2 = BruteForce(mesh, x, own, s, cosines[rule], capOnly);
      const double exact = std::sqrt(exact2);
      for (double scale : { 0.5, 1.0 - 1e-9, 1.0 + 1e-9, 2.0 })
      {
        const double bound = std::isfinite(exact) ? scale * exact : mesh.Diagonal;
        double q[3], distance = 0.0;
        vtkIdType triangle = -1;
        const bool hit = tree.ClosestPoint(x, bound, own, s, cosines[rule], capOnly, q, distance, triangle);
        // Found exactly when the squared distance is below the squared bound, and then the same value.
        MEDIAL_CHECK(hit == (exact2 < bound * bound), "%s, point %d, rule %d, bound %.17g: found %d, brute force %.17g",
          name, i, rule, bound, hit, exact);
        MEDIAL_CHECK(!hit || distance == exact, "%s, point %d, rule %d: distance %.17g, brute force %.17g", name,
          i, rule, distance, exact);
        const bool empty = tree.ContainsBall(x, bound, own, s, cosines[rule], capOnly);
        MEDIAL_CHECK(empty == !(exact2 < bound * bound), "%s, point %d, rule %d, radius %.17g: ContainsBall %d, "
          "brute force distance %.17g", name, i, rule, bound, empty, exact);
        ++queries;
        found += hit ? 1 : 0;
        contained += empty ? 1 : 0;
      }
    }
  }
  MEDIAL_CHECK(found > queries / 4 && contained > queries / 4, "%s: %d found, %d contained of %d", name, found,
    contained, queries);
  std::printf("%s: %lld triangles, %d queries agree (%d found, %d balls empty)\n", name,
    static_cast<long long>(nt), queries, found, contained);
  return EXIT_SUCCESS;
}
}

int TestMedialClosestPointWalk(int, char*[])
{
  int failed = CheckShape(vtkMedialShapeSource::BOX, "box", 12);
  failed |= CheckShape(vtkMedialShapeSource::SPHERE, "sphere", 5);
  failed |= CheckShape(vtkMedialShapeSource::JACK, "jack", 16);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
