// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSurfaceNormals.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

namespace
{
namespace G = vtkMedialGeometry;
}

void vtkMedialSurfaceNormals::Build(
  const vtkMedialTriangleMesh& mesh, double creaseDegrees, const vtkMedialSurfaceQuery* query)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  const vtkIdType np = mesh.GetNumberOfPoints();
  // Buffers, not vectors: mapped on their own, so their memory goes back when freed.
  vtkMedialBuffer<vtkIdType> start;
  vtkMedialBuffer<std::int32_t> around; // 32-bit: 12 bytes a triangle instead of 24
  mesh.TrianglesAroundPoints(start, around);
  const double cosCrease = std::cos(creaseDegrees * 3.14159265358979323846 / 180.0);
  // Two passes over the points: how many distinct normals each has, then (after the
  // offsets) the normals and the corners' indices. A smooth point costs a few dot
  // products and one sum, so computing twice is cheaper than keeping every corner's.
  vtkMedialBuffer<vtkIdType> first;
  first.assign(static_cast<size_t>(np) + 1, 0);
  this->CornerNormals.resize(3 * static_cast<size_t>(nt));
  for (int pass = 0; pass < 2; ++pass)
  {
    if (pass == 1)
    {
      std::partial_sum(first.begin(), first.end(), first.begin());
      this->Normals.resize(3 * static_cast<size_t>(first.back()));
    }
#pragma omp parallel
    {
      std::vector<const double*> facets;
      std::vector<float> normals;
      std::vector<int> slot;
#pragma omp for schedule(static)
      for (vtkIdType v = 0; v < np; ++v)
      {
        const int count = static_cast<int>(start[v + 1] - start[v]);
        const std::int32_t* triangles = &around[static_cast<size_t>(start[v])];
        facets.resize(count);
        normals.resize(3 * static_cast<size_t>(count));
        slot.resize(count);
        for (int i = 0; i < count; ++i)
        {
          facets[i] = query ? query->GetNormal(triangles[i]) : mesh.GetNormal(triangles[i]);
        }
        const int distinct =
          this->NormalsAtPoint(mesh, v, triangles, count, facets.data(), cosCrease, normals.data(), slot.data());
        if (pass == 0)
        {
          first[v + 1] = distinct;
          continue;
        }
        std::copy_n(normals.data(), 3 * distinct, &this->Normals[3 * static_cast<size_t>(first[v])]);
        for (int i = 0; i < count; ++i)
        {
          const vtkIdType* tri = mesh.GetTriangle(triangles[i]);
          for (int j = 0; j < 3; ++j)
          {
            if (tri[j] == v)
            {
              this->CornerNormals[3 * static_cast<size_t>(triangles[i]) + j] =
                static_cast<std::int32_t>(first[v] + slot[i]);
            }
          }
        }
      }
    }
  }
}

int vtkMedialSurfaceNormals::NormalsAtPoint(const vtkMedialTriangleMesh& mesh, vtkIdType point,
  const std::int32_t* around, int count, const double* const* facetNormals, double cosCrease, float* normals,
  int* slot) const
{
  const double* at = mesh.GetPoint(point);
  // The normal of the corner at `point` of around[own]: the mean of the usable
  // triangles' normals within the crease angle of its own, or its own when none is.
  auto cornerNormal = [&](int own, float f[3]) {
    double n[3] = { 0, 0, 0 };
    for (int i = 0; i < count; ++i)
    {
      const vtkIdType u = around[i];
      if (mesh.Areas[u] > 0.0 && G::Dot(facetNormals[own], facetNormals[i]) >= cosCrease)
      {
        // Max's weight: the area vector over |b - at|^2 |c - at|^2 (outward: the
        // corners in the mesh's counter-clockwise order).
        const vtkIdType* tri = mesh.GetTriangle(u);
        const int k = tri[0] == point ? 0 : (tri[1] == point ? 1 : 2);
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
      f[k] = static_cast<float>(length > 0.0 ? n[k] / length : facetNormals[own][k]);
    }
    return length > 0.0;
  };
  // Smooth: every usable triangle counts for every corner, so every corner sums the
  // same terms in the same order and gets the same normal.
  bool smooth = true;
  for (int own = 0; own < count && smooth; ++own)
  {
    for (int i = 0; i < count && smooth; ++i)
    {
      smooth = !(mesh.Areas[around[i]] > 0.0) || G::Dot(facetNormals[own], facetNormals[i]) >= cosCrease;
    }
  }
  if (count > 0 && smooth && cornerNormal(0, normals))
  {
    std::fill_n(slot, count, 0);
    return 1;
  }
  // Each corner its own sum, stored once per distinct value (bit for bit).
  int distinct = 0;
  for (int own = 0; own < count; ++own)
  {
    float f[3];
    cornerNormal(own, f);
    int s = 0;
    while (s < distinct && std::memcmp(normals + 3 * s, f, sizeof(f)) != 0)
    {
      ++s;
    }
    if (s == distinct)
    {
      std::copy_n(f, 3, normals + 3 * distinct++);
    }
    slot[own] = s;
  }
  return distinct;
}

bool vtkMedialSurfaceNormals::At(vtkIdType t, const double vertices[9], const double facetNormal[3],
  const double p[3], double n[3]) const
{
  G::Copy(facetNormal, n);
  if (this->CornerNormals.empty())
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
  const std::int32_t* corners = &this->CornerNormals[3 * static_cast<size_t>(t)];
  for (int j = 0; j < 3; ++j)
  {
    const float* corner = &this->Normals[3 * static_cast<size_t>(corners[j])];
    for (int k = 0; k < 3; ++k)
    {
      s[k] += l[j] / total * corner[k];
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
