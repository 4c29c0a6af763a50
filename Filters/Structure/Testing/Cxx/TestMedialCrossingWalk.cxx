// SPDX-License-Identifier: BSD-3-Clause
// The medial mesh's containment tests (vtkMedialSurfaceQuery::CrossesSurface with the
// exact predicates) against every surface triangle, one by one: the box walk they take
// their candidates from must miss no triangle that crosses. Segments and triangles are
// drawn at random over the shape's box, short and long, and on the planes where the
// exact signs matter (through the box's faces, edges and corners, and the bisector
// planes of its convex edges, where a medial sheet lies). Also EdgesCrossTriangle
// against Crosses for triangles whose sides cross nothing (how the complex uses it).
// Shapes: a box (coplanar facets, sharp edges), a torus, a capsule.
#include "MedialTestUtilities.h"

#include "vtkMedialExactPredicates.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <array>
#include <random>
#include <string>
#include <vector>

namespace
{
// Every surface triangle tested: the answer the walk must give.
bool BruteForce(const vtkMedialTriangleMesh& mesh, const double* const points[], int n,
  vtkMedialSurfaceQuery::CrossingTest test)
{
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    const double* corners[3] = { mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]) };
    if (test(points, n, corners))
    {
      return true;
    }
  }
  return false;
}

int CheckShape(const char* label, int shape)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->Update();
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  MEDIAL_CHECK(mesh.Build(source->GetOutput(), error) && query.Build(&mesh, error), "%s: %s", label, error.c_str());
  const double* b = mesh.Bounds;
  const double centre[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto inBox = [&](double x[3], double grow) {
    for (int k = 0; k < 3; ++k)
    {
      const double pad = grow * (b[2 * k + 1] - b[2 * k]);
      x[k] = b[2 * k] - pad + unit(random) * (b[2 * k + 1] - b[2 * k] + 2 * pad);
    }
  };
  // A point on a plane through surface features: a random surface vertex or the box's
  // centre, moved within the plane of two axes (a face's plane on the box), or along
  // the diagonal plane x = y about that vertex (the bisector of a convex edge).
  auto onFeaturePlane = [&](double x[3]) {
    const vtkIdType v = static_cast<vtkIdType>(unit(random) * mesh.GetNumberOfPoints()) % mesh.GetNumberOfPoints();
    const double* p = unit(random) < 0.8 ? mesh.GetPoint(v) : centre;
    const double s = (unit(random) - 0.5) * mesh.Diagonal, u = (unit(random) - 0.5) * mesh.Diagonal;
    const int axis = static_cast<int>(unit(random) * 4) % 4;
    for (int k = 0; k < 3; ++k)
    {
      x[k] = p[k];
    }
    if (axis < 3)
    {
      x[(axis + 1) % 3] += s; // stays in the plane x[axis] = p[axis]
      x[(axis + 2) % 3] += u;
    }
    else
    {
      x[0] += s; // stays in the plane x - y = p[0] - p[1]
      x[1] += s;
      x[2] += u;
    }
  };
  long long crossing = 0, clear = 0, halved = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    const int n = 2 + trial % 2;
    const bool onPlane = trial % 3 == 0;
    std::array<std::array<double, 3>, 3> x;
    for (int j = 0; j < n; ++j)
    {
      if (onPlane)
      {
        onFeaturePlane(x[j].data());
      }
      else
      {
        inBox(x[j].data(), 0.1);
      }
    }
    if (onPlane && trial % 6 == 0)
    {
      // Keep every point on the first one's plane: a feature plane shared by the points.
      for (int j = 1; j < n; ++j)
      {
        x[j] = x[0];
        x[j][trial % 4 == 0 ? 0 : 2] += (unit(random) - 0.5) * 0.3 * mesh.Diagonal;
      }
    }
    if (trial % 5 == 0)
    {
      // Short: within a few facets of a point.
      for (int j = 1; j < n; ++j)
      {
        for (int k = 0; k < 3; ++k)
        {
          x[j][k] = x[0][k] + (x[j][k] - x[0][k]) * 0.05;
        }
      }
    }
    const double* points[3] = { x[0].data(), x[1].data(), x[2].data() };
    const bool walk = query.CrossesSurface(points, n, vtkMedialExactPredicates::Crosses);
    const bool all = BruteForce(mesh, points, n, vtkMedialExactPredicates::Crosses);
    MEDIAL_CHECK(walk == all, "%s: trial %d (%d points): the walk says %d, every triangle %d", label, trial, n,
      walk ? 1 : 0, all ? 1 : 0);
    ++(all ? crossing : clear);
    if (n == 3)
    {
      bool sidesClear = true;
      for (int j = 0; j < 3 && sidesClear; ++j)
      {
        const double* side[2] = { points[j], points[(j + 1) % 3] };
        sidesClear = !BruteForce(mesh, side, 2, vtkMedialExactPredicates::Crosses);
      }
      if (sidesClear)
      {
        const bool edges = query.CrossesSurface(points, 3, vtkMedialExactPredicates::EdgesCrossTriangle);
        MEDIAL_CHECK(edges == all, "%s: trial %d: EdgesCrossTriangle says %d, Crosses %d", label, trial,
          edges ? 1 : 0, all ? 1 : 0);
        halved += all ? 1 : 0;
      }
    }
  }
  std::printf("%s: %lld crossing, %lld clear, %lld triangles crossed only by surface edges\n", label, crossing,
    clear, halved);
  MEDIAL_CHECK(crossing > 200 && clear > 200 && halved > 0, "%s: too few cases of a kind", label);
  return EXIT_SUCCESS;
}
}

int TestMedialCrossingWalk(int, char*[])
{
  int result = EXIT_SUCCESS;
  result |= CheckShape("box", vtkMedialShapeSource::BOX);
  result |= CheckShape("torus", vtkMedialShapeSource::TORUS);
  result |= CheckShape("capsule", vtkMedialShapeSource::CAPSULE);
  return result;
}
