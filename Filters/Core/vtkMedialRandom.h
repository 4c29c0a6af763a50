// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialRandom.h
 * @brief Counter-based random streams: one independent stream per sample.
 *
 * Each sample i draws from a stream seeded by (seed, i) through SplitMix64, so
 * a sample's random numbers do not depend on which thread runs it or in which
 * order. That is what makes the filters' output identical for any thread count.
 * vtkMedialDrawSurfacePoint draws sample i's point on a triangle mesh from its stream:
 * the sampler's random surface points, and the area-sampled error measure's.
 * Internal header; not installed.
 */
#ifndef vtkMedialRandom_h
#define vtkMedialRandom_h

#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

class vtkMedialSampleRandom
{
public:
  vtkMedialSampleRandom(std::uint64_t seed, std::uint64_t sampleIndex)
  {
    // Two mixing rounds decorrelate neighbouring (seed, index) pairs.
    this->State = Mix(seed ^ 0x9E3779B97F4A7C15ull) ^ Mix(sampleIndex + 0xD1B54A32D192ED03ull);
  }

  /// Uniform double in [0, 1), 53 random bits.
  double Uniform() { return static_cast<double>(this->Next() >> 11) * 0x1.0p-53; }

  std::uint64_t Next()
  {
    this->State += 0x9E3779B97F4A7C15ull;
    return Mix(this->State);
  }

private:
  static std::uint64_t Mix(std::uint64_t z)
  {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t State;
};

/// Triangle of sample `index` of stream `seed`, the one vtkMedialDrawSurfacePoint picks,
/// without drawing the point (the sampler orders all samples by it to split them by piece).
inline vtkIdType vtkMedialPickSampleTriangle(
  const vtkMedialTriangleMesh& mesh, std::uint64_t seed, vtkIdType index)
{
  vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(index));
  return mesh.PickTriangleByArea(random.Uniform());
}

/// A uniform point on the triangle (a, b, c) drawn from `random`: sqrt warping of two
/// uniforms. The one formula of every surface sample.
inline void vtkMedialDrawPointOnCorners(
  vtkMedialSampleRandom& random, const double a[3], const double b[3], const double c[3], double p[3])
{
  const double s = std::sqrt(random.Uniform());
  const double t = random.Uniform();
  const double wa = 1.0 - s, wb = s * (1.0 - t), wc = s * t;
  for (int k = 0; k < 3; ++k)
  {
    p[k] = wa * a[k] + wb * b[k] + wc * c[k];
  }
}

/// The corners of `triangle` in increasing vertex id, as their positions in the mesh's
/// order packed two bits each (first in the lowest): what the sample points need of
/// the mesh's triangles when they are drawn from a copy of its corners.
inline std::uint8_t vtkMedialCornerIdOrder(const vtkMedialTriangleMesh& mesh, vtkIdType triangle)
{
  const vtkIdType* v = mesh.GetTriangle(triangle);
  int order[3] = { 0, 1, 2 };
  std::sort(order, order + 3, [v](int i, int j) { return v[i] < v[j]; });
  return static_cast<std::uint8_t>(order[0] | (order[1] << 2) | (order[2] << 4));
}

/// The point of vtkMedialDrawSurfacePoint on `triangle`, drawn from `random` after the
/// pick's draw (the vertices are taken in id order, so re-wound input gives the same point).
inline void vtkMedialDrawPointOnTriangle(
  const vtkMedialTriangleMesh& mesh, vtkMedialSampleRandom& random, vtkIdType triangle, double p[3])
{
  vtkIdType v[3] = { mesh.GetTriangle(triangle)[0], mesh.GetTriangle(triangle)[1],
    mesh.GetTriangle(triangle)[2] };
  std::sort(v, v + 3);
  vtkMedialDrawPointOnCorners(random, mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2]), p);
}

/// Surface point of sample `index` of stream `seed`: a triangle picked by area, a uniform
/// point on it. The vertex order of the triangle does not matter (vertices are taken in
/// id order), so re-wound input gives the same point.
inline void vtkMedialDrawSurfacePoint(const vtkMedialTriangleMesh& mesh, std::uint64_t seed,
  vtkIdType index, vtkIdType& triangle, double p[3])
{
  vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(index));
  triangle = mesh.PickTriangleByArea(random.Uniform()); // as vtkMedialPickSampleTriangle
  vtkMedialDrawPointOnTriangle(mesh, random, triangle, p);
}

/// The same point when the triangle is known: `triangle` must be
/// vtkMedialPickSampleTriangle(mesh, seed, index) (the pick is a binary search over
/// the areas, a cache miss per step on a large mesh).
inline void vtkMedialDrawSurfacePointOnPicked(
  const vtkMedialTriangleMesh& mesh, std::uint64_t seed, vtkIdType index, vtkIdType triangle, double p[3])
{
  vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(index));
  random.Next(); // the pick's draw
  vtkMedialDrawPointOnTriangle(mesh, random, triangle, p);
}

/// The same point from a copy of the picked triangle's corners (9 coordinates in the
/// mesh's order, e.g. vtkMedialSurfaceQuery::GetTriangleVertices) and its
/// vtkMedialCornerIdOrder: bit for bit the mesh's point when the copy is exact, with
/// no access to the mesh (which may have released its geometry).
inline void vtkMedialDrawSurfacePointOnCorners(
  std::uint64_t seed, vtkIdType index, const double corners[9], std::uint8_t idOrder, double p[3])
{
  vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(index));
  random.Next(); // the pick's draw
  vtkMedialDrawPointOnCorners(random, corners + 3 * (idOrder & 3), corners + 3 * ((idOrder >> 2) & 3),
    corners + 3 * ((idOrder >> 4) & 3), p);
}

#endif
