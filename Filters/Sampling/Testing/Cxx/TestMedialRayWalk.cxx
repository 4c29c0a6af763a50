// SPDX-License-Identifier: BSD-3-Clause
// The tree's ray query walks the four-lane nodes in float for a ray of about unit
// length from near the mesh, and the binary nodes in double otherwise. A direction
// scaled by 4 (a power of two: every t scales exactly) takes the double walk, so on a
// box (rays through its vertices and along its edges and faces: ties between
// triangles), a geodesic sphere and the jack, each ray must give the same triangle
// with both walks, t within a factor of exactly 4, and agree with a brute force over
// every triangle: no hit nearer than the one found, and the point found on its triangle.
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

// Nearest t > tMin where the ray meets a triangle's plane at least `margin` inside the
// triangle (from each edge's line), over every triangle not parallel to the ray;
// HUGE_VAL if none. The margin keeps grazing rays, which may miss exactly, out.
double BruteForce(const vtkMedialTriangleMesh& mesh, const double o[3], const double d[3], double tMin, double margin)
{
  double best = HUGE_VAL;
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    const double* p[3] = { mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]) };
    double ab[3], ac[3], n[3], ao[3];
    G::Sub(p[1], p[0], ab);
    G::Sub(p[2], p[0], ac);
    G::Cross(ab, ac, n);
    const double area2 = std::sqrt(G::Dot(n, n));
    const double denom = G::Dot(n, d);
    if (std::fabs(denom) <= 1e-12 * area2)
    {
      continue;
    }
    G::Sub(p[0], o, ao);
    const double s = G::Dot(n, ao) / denom;
    if (!(s > tMin && s < best))
    {
      continue;
    }
    double x[3];
    G::AddScaled(o, s, d, x);
    bool inside = true;
    for (int i = 0; i < 3 && inside; ++i)
    {
      double e[3], w[3], c[3];
      G::Sub(p[(i + 1) % 3], p[i], e);
      G::Sub(x, p[i], w);
      G::Cross(e, w, c);
      // Distance of x from the edge's line, signed positive inside.
      inside = G::Dot(c, n) / area2 >= margin * std::sqrt(G::Dot(e, e));
    }
    best = inside ? s : best;
  }
  return best;
}

// Checks one ray; returns false (after a message) on the first disagreement.
bool CheckRay(const vtkMedialTriangleMesh& mesh, const vtkMedialTriangleBVH& tree, const double o[3],
  const double d[3], const char* shape, const char* kind, int index)
{
  const double tol = 1e-9 * mesh.Diagonal;
  double tWide = 0.0, tDouble = 0.0;
  vtkIdType wide = -1, binary = -1;
  const double d4[3] = { 4.0 * d[0], 4.0 * d[1], 4.0 * d[2] };
  const bool hitWide = tree.IntersectRay(o, d, 0.0, HUGE_VAL, -1, tWide, wide);
  const bool hitDouble = tree.IntersectRay(o, d4, 0.0, HUGE_VAL, -1, tDouble, binary);
  // A ray from a point of a face along it meets it at the first double above 0, whatever its length.
  const double first = std::nextafter(0.0, 1.0);
  const bool sameT = tWide == 4.0 * tDouble || (tWide == first && tDouble == first);
  if (hitWide != hitDouble || wide != binary || (hitWide && !sameT))
  {
    std::fprintf(stderr, "%s, %s ray %d: float walk %d (triangle %lld, t %.17g), double walk %d (%lld, 4t %.17g)\n",
      shape, kind, index, hitWide, static_cast<long long>(wide), tWide, hitDouble, static_cast<long long>(binary),
      4.0 * tDouble);
    return false;
  }
  const double brute = BruteForce(mesh, o, d, 0.0, tol);
  if (std::isfinite(brute) && !(hitWide && tWide <= brute + tol))
  {
    std::fprintf(stderr, "%s, %s ray %d: a triangle at t = %.17g, the tree found %s %.17g\n", shape, kind, index,
      brute, hitWide ? "t =" : "nothing, t =", tWide);
    return false;
  }
  if (hitWide)
  {
    const vtkIdType* v = mesh.GetTriangle(wide);
    double x[3], q[3];
    G::AddScaled(o, tWide, d, x);
    const double gap = std::sqrt(G::ClosestPointOnTriangle(x, mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]), q));
    if (gap > tol)
    {
      std::fprintf(stderr, "%s, %s ray %d: the point at t = %.17g is %g off triangle %lld\n", shape, kind, index,
        tWide, gap, static_cast<long long>(wide));
      return false;
    }
  }
  return true;
}

// EXIT_SUCCESS when every ray agrees (MEDIAL_CHECK returns EXIT_FAILURE).
int CheckShape(int shape, const char* name, int resolution)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  double lo[3], hi[3];
  MEDIAL_CHECK(BuildShapeMesh(shape, resolution, mesh, lo, hi, error), "%s: %s", name, error.c_str());
  vtkMedialTriangleBVH tree;
  MEDIAL_CHECK(tree.Build(mesh), "%s: no tree", name);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss;
  auto inside = [&](double x[3]) {
    for (int k = 0; k < 3; ++k)
    {
      x[k] = lo[k] + (0.05 + 0.9 * unit(random)) * (hi[k] - lo[k]);
    }
  };
  auto normalize = [](double d[3]) {
    const double l = std::sqrt(G::Dot(d, d));
    for (int k = 0; k < 3; ++k)
    {
      d[k] /= l;
    }
  };
  int rays = 0, hits = 0;
  for (int i = 0; i < 300; ++i)
  {
    // Random origin in the box around the shape, random direction.
    double o[3], d[3] = { gauss(random), gauss(random), gauss(random) };
    inside(o);
    normalize(d);
    MEDIAL_CHECK(CheckRay(mesh, tree, o, d, name, "random", i), "see above");
    // Exactly at a vertex: a tie between the triangles around it.
    const double* v = mesh.GetPoint(static_cast<vtkIdType>(unit(random) * mesh.GetNumberOfPoints()));
    G::Sub(v, o, d);
    normalize(d);
    MEDIAL_CHECK(CheckRay(mesh, tree, o, d, name, "vertex", i), "see above");
    // Along an axis through a vertex's other two coordinates: zero direction
    // components, and on the box rays through vertices, along edges and in faces.
    const int axis = i % 3;
    double a[3] = { v[0], v[1], v[2] }, e[3] = { 0.0, 0.0, 0.0 };
    e[axis] = (i / 3) % 2 ? 1.0 : -1.0;
    a[axis] = 0.5 * (lo[axis] + hi[axis]);
    MEDIAL_CHECK(CheckRay(mesh, tree, a, e, name, "axis", i), "see above");
    double t;
    vtkIdType hit;
    hits += tree.IntersectRay(a, e, 0.0, HUGE_VAL, -1, t, hit) ? 1 : 0;
    rays += 3;
  }
  MEDIAL_CHECK(hits > 200, "%s: only %d of 300 axis rays hit", name, hits);
  std::printf("%s: %lld triangles, %d rays agree\n", name, static_cast<long long>(mesh.GetNumberOfTriangles()), rays);
  return EXIT_SUCCESS;
}
}

int TestMedialRayWalk(int, char*[])
{
  int failed = CheckShape(vtkMedialShapeSource::BOX, "box", 12);
  failed |= CheckShape(vtkMedialShapeSource::SPHERE, "sphere", 5);
  failed |= CheckShape(vtkMedialShapeSource::JACK, "jack", 16);
  return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
