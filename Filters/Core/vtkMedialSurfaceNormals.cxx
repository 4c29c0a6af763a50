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
  // Normals holds each point's first distinct normal at the point's index, then the
  // others of the points that have several (at creases), point by point. The first
  // pass computes every point's normals and writes the first, the second only those
  // of the points with several, once their offsets are known.
  vtkMedialBuffer<vtkIdType> extra; // after the first pass: the normals beyond the first
  extra.assign(static_cast<size_t>(np) + 1, 0);
  this->CornerNormals.resize(3 * static_cast<size_t>(nt));
  this->Normals.resize(3 * static_cast<size_t>(np));
  for (int pass = 0; pass < 2; ++pass)
  {
    if (pass == 1)
    {
      std::partial_sum(extra.begin(), extra.end(), extra.begin());
      if (extra.back() == 0)
      {
        break; // every point smooth
      }
      vtkMedialBuffer<float> all(3 * static_cast<size_t>(np + extra.back()));
      std::copy(this->Normals.begin(), this->Normals.end(), all.begin());
      this->Normals.swap(all);
    }
#pragma omp parallel
    {
      std::vector<const double*> facets;
      std::vector<char> usable;
      std::vector<float> normals;
      std::vector<int> slot;
#pragma omp for schedule(static)
      for (vtkIdType v = 0; v < np; ++v)
      {
        if (pass == 1 && extra[v + 1] == extra[v])
        {
          continue; // done in the first pass
        }
        const int count = static_cast<int>(start[v + 1] - start[v]);
        const std::int32_t* triangles = &around[static_cast<size_t>(start[v])];
        facets.resize(count);
        usable.resize(count);
        normals.resize(3 * static_cast<size_t>(count));
        slot.resize(count);
        for (int i = 0; i < count; ++i)
        {
          facets[i] = query ? query->GetNormal(triangles[i]) : mesh.GetNormal(triangles[i]);
          usable[i] = mesh.Areas[triangles[i]] > 0.0;
        }
        const int distinct = this->NormalsAtPoint(
          mesh, v, triangles, count, facets.data(), usable.data(), cosCrease, normals.data(), slot.data());
        if (distinct == 0)
        {
          continue; // no triangle uses the point
        }
        if (pass == 0)
        {
          std::copy_n(normals.data(), 3, &this->Normals[3 * static_cast<size_t>(v)]);
          extra[v + 1] = distinct - 1;
        }
        else
        {
          std::copy_n(normals.data() + 3, 3 * (distinct - 1),
            &this->Normals[3 * static_cast<size_t>(np + extra[v])]);
        }
        for (int i = 0; i < count; ++i)
        {
          const vtkIdType* tri = mesh.GetTriangle(triangles[i]);
          for (int j = 0; j < 3; ++j)
          {
            if (tri[j] == v)
            {
              this->CornerNormals[3 * static_cast<size_t>(triangles[i]) + j] =
                static_cast<std::int32_t>(slot[i] == 0 ? v : np + extra[v] + slot[i] - 1);
            }
          }
        }
      }
    }
  }
}

int vtkMedialSurfaceNormals::NormalsAtPoint(const vtkMedialTriangleMesh& mesh, vtkIdType point,
  const std::int32_t* around, int count, const double* const* facetNormals, const char* usable, double cosCrease,
  float* normals, int* slot) const
{
  const double* at = mesh.GetPoint(point);
  // The normal of the corner at `point` of around[own]: the mean of the usable
  // triangles' normals within the crease angle of its own, or its own when none is.
  // `withinCrease`: every usable triangle is known to be within it (a smooth point).
  auto cornerNormal = [&](int own, bool withinCrease, float f[3]) {
    double n[3] = { 0, 0, 0 };
    for (int i = 0; i < count; ++i)
    {
      const vtkIdType u = around[i];
      if (usable[i] && (withinCrease || G::Dot(facetNormals[own], facetNormals[i]) >= cosCrease))
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
  // same terms in the same order and gets the same normal, and corner 0's sum need
  // not test the angles again (its pairs were tested with the same dot products).
  // (The dot product is symmetric, bit for bit: each pair once, failing when either
  // side counts for the other.)
  bool smooth = true;
  for (int own = 0; own < count && smooth; ++own)
  {
    for (int i = own; i < count && smooth; ++i)
    {
      smooth = !(usable[own] || usable[i]) || G::Dot(facetNormals[own], facetNormals[i]) >= cosCrease;
    }
  }
  if (count > 0 && smooth && cornerNormal(0, true, normals))
  {
    std::fill_n(slot, count, 0);
    return 1;
  }
  // Each corner its own sum, stored once per distinct value (bit for bit).
  int distinct = 0;
  for (int own = 0; own < count; ++own)
  {
    float f[3];
    cornerNormal(own, false, f);
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
