// SPDX-License-Identifier: BSD-3-Clause
// Two memory savings of the sampler's 1 M-ball job (issue 37) must not change a bit:
//  - vtkMedialSurfaceNormals stores each distinct corner normal of a point once (one per
//    smooth point) instead of one per corner: At must give, bit for bit, what the
//    corners' own normals give (the per-corner sums, recomputed here as issue 39 built
//    them), on a geodesic sphere (smooth: one normal per point), a box (creases: three
//    at each of its corners), a torus and a hollow sphere, as generated and turned, at
//    theta 45 and 10 degrees, with the facets' normals from the mesh and from the query;
//  - the sampler draws each point from the tree's copy of its triangle's corners and
//    the order of their ids (vtkMedialDrawSurfacePointOnCorners): it must be the mesh's
//    point (vtkMedialDrawSurfacePointOnPicked) bit for bit, with double coordinates
//    and with float ones (the tree then keeps float corners), whatever the winding.
#include "MedialTestUtilities.h"
#include "MedialShapeTestUtilities.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialRandom.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceNormals.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
namespace G = vtkMedialGeometry;

vtkSmartPointer<vtkPolyData> Shape(int shape, double turn, bool floats, bool rewind)
{
  vtkSmartPointer<vtkPolyData> surface = Turned(MakeShape(shape, 3), turn);
  if (floats)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    points->DeepCopy(surface->GetPoints());
    surface->SetPoints(points);
  }
  if (rewind)
  {
    // Every other triangle starts at another corner (the same orientation).
    vtkNew<vtkCellArray> polys;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType c = 0;
    for (surface->GetPolys()->InitTraversal(); surface->GetPolys()->GetNextCell(n, ids); ++c)
    {
      const vtkIdType turnedIds[3] = { ids[(c + 1) % 3], ids[(c + 2) % 3], ids[c % 3] };
      polys->InsertNextCell(3, n == 3 ? turnedIds : ids);
    }
    surface->SetPolys(polys);
  }
  return surface;
}

// The corner normals as issue 39 computed them: one sum per corner.
std::vector<float> CornerNormals(const vtkMedialTriangleMesh& mesh, double creaseDegrees)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  std::vector<vtkIdType> start, around;
  mesh.TrianglesAroundPoints(start, around);
  const double cosCrease = std::cos(creaseDegrees * 3.14159265358979323846 / 180.0);
  std::vector<float> corners(9 * static_cast<size_t>(nt));
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const double* own = mesh.GetNormal(t);
    for (int j = 0; j < 3; ++j)
    {
      const vtkIdType v = mesh.GetTriangle(t)[j];
      const double* at = mesh.GetPoint(v);
      double n[3] = { 0, 0, 0 };
      for (vtkIdType i = start[v]; i < start[v + 1]; ++i)
      {
        const vtkIdType u = around[i];
        if (mesh.Areas[u] > 0.0 && G::Dot(own, mesh.GetNormal(u)) >= cosCrease)
        {
          const vtkIdType* tri = mesh.GetTriangle(u);
          const int k = tri[0] == v ? 0 : (tri[1] == v ? 1 : 2);
          double e1[3], e2[3], w[3];
          G::Sub(mesh.GetPoint(tri[(k + 1) % 3]), at, e1);
          G::Sub(mesh.GetPoint(tri[(k + 2) % 3]), at, e2);
          G::Cross(e1, e2, w);
          const double weight = G::Dot(e1, e1) * G::Dot(e2, e2);
          if (weight > 0.0)
          {
            G::AddScaled(n, 1.0 / weight, w, n);
          }
        }
      }
      const double length = std::sqrt(G::Dot(n, n));
      for (int k = 0; k < 3; ++k)
      {
        corners[9 * t + 3 * j + k] = static_cast<float>(length > 0.0 ? n[k] / length : own[k]);
      }
    }
  }
  return corners;
}

// vtkMedialSurfaceNormals::At with the corners' own normals.
bool ReferenceAt(const float* corner, const double vertices[9], const double facetNormal[3], const double p[3],
  double n[3])
{
  G::Copy(facetNormal, n);
  double l[3];
  double total = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    double e1[3], e2[3], w[3];
    G::Sub(vertices + 3 * ((j + 1) % 3), p, e1);
    G::Sub(vertices + 3 * ((j + 2) % 3), p, e2);
    G::Cross(e1, e2, w);
    l[j] = std::max(0.0, G::Dot(w, facetNormal));
    total += l[j];
  }
  if (!(total > 0.0))
  {
    return true;
  }
  double s[3] = { 0, 0, 0 };
  for (int j = 0; j < 3; ++j)
  {
    for (int k = 0; k < 3; ++k)
    {
      s[k] += l[j] / total * corner[3 * j + k];
    }
  }
  const double length = std::sqrt(G::Dot(s, s));
  if (!(length > 0.0))
  {
    return true;
  }
  for (double& x : s)
  {
    x /= length;
  }
  double d[3];
  G::Sub(s, facetNormal, d);
  if (G::Dot(d, d) < 1e-12)
  {
    return true;
  }
  G::Copy(s, n);
  return false;
}
}

int TestMedialSmoothNormalsStorage(int, char*[])
{
  const struct
  {
    int Shape;
    const char* Name;
  } shapes[] = { { vtkMedialShapeSource::SPHERE, "sphere" }, { vtkMedialShapeSource::BOX, "box" },
    { vtkMedialShapeSource::TORUS, "torus" }, { vtkMedialShapeSource::HOLLOW_SPHERE, "hollow sphere" } };
  long long checked = 0, points = 0;
  for (const auto& shape : shapes)
  {
    for (double turn : { 0.0, 37.0 })
    {
      for (bool floats : { false, true })
      {
        const bool rewind = floats;
        vtkSmartPointer<vtkPolyData> surface = Shape(shape.Shape, turn, floats, rewind);
        vtkMedialTriangleMesh mesh;
        vtkMedialSurfaceQuery query;
        std::string error;
        MEDIAL_CHECK(mesh.Build(surface, error) && query.Build(&mesh, error), "%s: %s", shape.Name, error.c_str());
        const vtkIdType nt = mesh.GetNumberOfTriangles();
        for (double theta : { 45.0, 10.0 })
        {
          const std::vector<float> corners = CornerNormals(mesh, theta);
          for (bool fromQuery : { false, true })
          {
            vtkMedialSurfaceNormals normals;
            normals.Build(mesh, theta, fromQuery ? &query : nullptr);
            if (shape.Shape == vtkMedialShapeSource::SPHERE && theta == 45.0)
            {
              // Smooth (neighbouring facets about 10 degrees apart): one normal per point.
              MEDIAL_CHECK(normals.GetNumberOfNormals() == mesh.UsedPoints,
                "%s, theta %g: %lld normals for %lld points", shape.Name, theta,
                static_cast<long long>(normals.GetNumberOfNormals()), static_cast<long long>(mesh.UsedPoints));
            }
            if (shape.Shape == vtkMedialShapeSource::BOX)
            {
              // At least three at each of the box's 8 corners, two along its 12 edges.
              MEDIAL_CHECK(normals.GetNumberOfNormals() >= mesh.UsedPoints + 16,
                "box: %lld normals for %lld points", static_cast<long long>(normals.GetNumberOfNormals()),
                static_cast<long long>(mesh.UsedPoints));
            }
            vtkMedialSampleRandom random(11, static_cast<std::uint64_t>(theta));
            for (vtkIdType t = 0; t < nt; ++t)
            {
              double scratch[9];
              const double* vertices = query.GetTriangleVertices(t, scratch);
              for (int k = 0; k < 4; ++k)
              {
                // A vertex (k = 0) and random points of the triangle.
                double p[3];
                const double a = k == 0 ? 1.0 : random.Uniform(), b = k == 0 ? 0.0 : random.Uniform() * (1.0 - a);
                for (int c = 0; c < 3; ++c)
                {
                  p[c] = a * vertices[c] + b * vertices[3 + c] + (1.0 - a - b) * vertices[6 + c];
                }
                double got[3], expected[3];
                const bool flat = normals.At(t, vertices, query.GetNormal(t), p, got);
                const bool expectedFlat = ReferenceAt(&corners[9 * t], vertices, query.GetNormal(t), p, expected);
                MEDIAL_CHECK(flat == expectedFlat && std::memcmp(got, expected, sizeof(got)) == 0,
                  "%s (turn %g, %s), theta %g, triangle %lld: normal (%.17g %.17g %.17g), the corners' (%.17g "
                  "%.17g %.17g)",
                  shape.Name, turn, floats ? "floats" : "doubles", theta, static_cast<long long>(t), got[0], got[1],
                  got[2], expected[0], expected[1], expected[2]);
                ++checked;
              }
            }
          }
        }
        // The sample points drawn from the tree's corners.
        for (vtkIdType i = 0; i < 20000; ++i)
        {
          const vtkIdType t = vtkMedialPickSampleTriangle(mesh, 5, i);
          double expected[3], got[3], scratch[9];
          vtkMedialDrawSurfacePointOnPicked(mesh, 5, i, t, expected);
          vtkMedialDrawSurfacePointOnCorners(
            5, i, query.GetTriangleVertices(t, scratch), vtkMedialCornerIdOrder(mesh, t), got);
          MEDIAL_CHECK(std::memcmp(got, expected, sizeof(got)) == 0,
            "%s (turn %g, %s): sample %lld at (%.17g %.17g %.17g), the mesh's (%.17g %.17g %.17g)", shape.Name,
            turn, floats ? "floats" : "doubles", static_cast<long long>(i), got[0], got[1], got[2], expected[0],
            expected[1], expected[2]);
          ++points;
        }
      }
    }
  }
  std::printf("%lld normals and %lld sample points checked, bit for bit\n", checked, points);
  return EXIT_SUCCESS;
}
