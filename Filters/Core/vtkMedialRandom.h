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

/// The point of vtkMedialDrawSurfacePoint on `triangle`, drawn from `random` after the
/// pick's draw (the vertices are taken in id order, so re-wound input gives the same point).
inline void vtkMedialDrawPointOnTriangle(
  const vtkMedialTriangleMesh& mesh, vtkMedialSampleRandom& random, vtkIdType triangle, double p[3])
{
  vtkIdType v[3] = { mesh.GetTriangle(triangle)[0], mesh.GetTriangle(triangle)[1],
    mesh.GetTriangle(triangle)[2] };
  std::sort(v, v + 3);
  // Uniform on the triangle: sqrt warping of two uniforms.
  const double s = std::sqrt(random.Uniform());
  const double t = random.Uniform();
  const double wa = 1.0 - s, wb = s * (1.0 - t), wc = s * t;
  const double* a = mesh.GetPoint(v[0]);
  const double* b = mesh.GetPoint(v[1]);
  const double* c = mesh.GetPoint(v[2]);
  for (int k = 0; k < 3; ++k)
  {
    p[k] = wa * a[k] + wb * b[k] + wc * c[k];
  }
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

#endif
