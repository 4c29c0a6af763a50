// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSurfaceNormals.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
namespace G = vtkMedialGeometry;
}

void vtkMedialSurfaceNormals::Build(const vtkMedialTriangleMesh& mesh, double creaseDegrees)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  std::vector<vtkIdType> start, around;
  mesh.TrianglesAroundPoints(start, around);
  const double cosCrease = std::cos(creaseDegrees * 3.14159265358979323846 / 180.0);
  this->Corners.resize(9 * static_cast<size_t>(nt));
#pragma omp parallel for schedule(static)
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
          // Max's weight: the area vector over |b - at|^2 |c - at|^2 (outward: the
          // corners in the mesh's counter-clockwise order).
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
        // A corner without a usable neighbour (degenerate own triangle) keeps the facet's.
        this->Corners[9 * t + 3 * j + k] = static_cast<float>(length > 0.0 ? n[k] / length : own[k]);
      }
    }
  }
}

bool vtkMedialSurfaceNormals::At(vtkIdType t, const double vertices[9], const double facetNormal[3],
  const double p[3], double n[3]) const
{
  G::Copy(facetNormal, n);
  if (this->Corners.empty())
  {
    return true;
  }
  // Barycentric coordinates of p from the sub-triangles' area vectors along the facet normal.
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
  const float* corner = &this->Corners[9 * static_cast<size_t>(t)];
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
  // Within 1e-6 radians of the facet's normal: a flat region; keep the exact normal.
  double d[3];
  G::Sub(s, facetNormal, d);
  if (G::Dot(d, d) < 1e-12)
  {
    return true;
  }
  G::Copy(s, n);
  return false;
}
