// SPDX-License-Identifier: BSD-3-Clause
// The interpolated envelope of a medial mesh (vtkMedialBallUnion with MEDIAL_MESH
// primitives):
//  1. the closed-form cone and slab fields (vtkMedialEnvelope.h) equal a brute-force
//     minimum over the interpolated balls, at random points around random primitives,
//     and no point of a primitive lies further from its vertex balls than its excess
//     bound (EdgeExcess, TriangleExcess);
//  2. two balls joined by an edge give the cone between them (not two spheres): the
//     surface's vertices lie on the exact cone-sphere within a voxel, and its waist is
//     filled where the union of the two balls has none;
//  3. a triangle of balls gives the slab: the mid-point of the triangle is covered;
//  4. a point set without cells is the union of balls as before.
#include "MedialBallUnionTestUtilities.h"

#include "vtkMedialBallUnion.h"
#include "vtkMedialEnvelope.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"

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

  // Excess bounds: overlapping balls, points of the primitive on a grid.
  std::uniform_real_distribution<double> near(-0.15, 0.15), big(0.2, 0.4);
  int tight = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    double centres[3][3], r[3];
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        centres[j][k] = near(random);
      }
      r[j] = big(random);
    }
    const double* c[3] = { centres[0], centres[1], centres[2] };
    const double edgeBound = E::EdgeExcess(c[0], r[0], c[1], r[1]);
    const double triangleBound = E::TriangleExcess(c, r);
    double edgeWorst = 0.0, triangleWorst = 0.0;
    for (int i = 0; i < 40; ++i)
    {
      for (int j = 0; j < 40; ++j)
      {
        for (int k = 0; k < 40; ++k)
        {
          const double x[3] = { -0.6 + 0.03 * i, -0.6 + 0.03 * j, -0.6 + 0.03 * k };
          double outside = HUGE_VAL; // distance to the union of the vertex balls
          for (int v = 0; v < 3; ++v)
          {
            outside = std::min(outside, E::BallField(x, c[v], r[v]));
          }
          const double twoBalls = std::min(E::BallField(x, c[0], r[0]), E::BallField(x, c[1], r[1]));
          if (E::EdgeField(x, c[0], r[0], c[1], r[1]) <= 0.0)
          {
            edgeWorst = std::max(edgeWorst, twoBalls);
          }
          // The triangle's field, closed form (checked against brute force above).
          const double slab = std::min({ E::TriangleField(x, c, r), E::EdgeField(x, c[0], r[0], c[1], r[1]),
            E::EdgeField(x, c[1], r[1], c[2], r[2]), E::EdgeField(x, c[0], r[0], c[2], r[2]) });
          if (slab <= 0.0)
          {
            triangleWorst = std::max(triangleWorst, outside);
          }
        }
      }
    }
    MEDIAL_CHECK(edgeWorst <= edgeBound + 1e-12 && triangleWorst <= triangleBound + 1e-12,
      "trial %d: excess edge %.3g (bound %.3g), triangle %.3g (bound %.3g)", trial, edgeWorst, edgeBound,
      triangleWorst, triangleBound);
    tight += triangleWorst > 0.25 * triangleBound;
  }
  std::printf("excess bounds hold on 60 primitives (%d triangles within a factor 4)\n", tight);
  return EXIT_SUCCESS;
}

// Reconstructs `mesh` and returns the largest |field| of `exact` over the surface's
// vertices, in voxels.
template <class Exact>
double WorstVertex(vtkPolyData* mesh, int primitives, Exact exact, vtkIdType& vertices)
{
  vtkNew<vtkMedialBallUnion> envelope;
  envelope->SetInputData(mesh);
  envelope->SetPrimitives(primitives);
  envelope->SetDimension(vtkMedialBallUnion::DIMENSION_3D);
  envelope->SetSampleDimensions(96, 96, 96);
  envelope->Update();
  vtkPolyData* surface = envelope->GetOutput();
  vertices = surface->GetNumberOfPoints();
  double worst = 0.0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double x[3];
    surface->GetPoint(i, x);
    worst = std::max(worst, std::fabs(exact(x)));
  }
  return worst / envelope->GetVoxelSize();
}

int CheckShapes()
{
  // An edge: the cone-sphere between the two balls, not their union.
  vtkSmartPointer<vtkPolyData> edge = medialtest::MakeBalls({ { 0, 0, 0, 0.5 }, { 2, 0.1, 0, 0.3 } });
  vtkNew<vtkCellArray> line;
  const vtkIdType ends[2] = { 0, 1 };
  line->InsertNextCell(2, ends);
  edge->SetLines(line);
  const double c0[3] = { 0, 0, 0 }, c1[3] = { 2, 0.1, 0 };
  auto cone = [&](const double x[3]) { return E::EdgeField(x, c0, 0.5, c1, 0.3); };
  vtkIdType n = 0;
  const double coneError = WorstVertex(edge, vtkMedialBallUnion::MEDIAL_MESH, cone, n);
  const double unionError = WorstVertex(edge, vtkMedialBallUnion::BALLS, cone, n);
  std::printf("edge: %lld vertices within %.3f voxels of the cone (the union of its balls: %.1f)\n",
    static_cast<long long>(n), coneError, unionError);
  MEDIAL_CHECK(coneError < 1.0 && unionError > 5.0, "the edge's envelope is not the cone");

  // A triangle: the slab between three balls.
  vtkSmartPointer<vtkPolyData> slab =
    medialtest::MakeBalls({ { 0, 0, 0, 0.4 }, { 2, 0, 0.2, 0.25 }, { 0.5, 1.8, 0, 0.3 } });
  vtkNew<vtkCellArray> triangle;
  const vtkIdType corners[3] = { 0, 1, 2 };
  triangle->InsertNextCell(3, corners);
  slab->SetPolys(triangle);
  const double a[3] = { 0, 0, 0 }, b[3] = { 2, 0, 0.2 }, c[3] = { 0.5, 1.8, 0 };
  const double* centres[3] = { a, b, c };
  const double radii[3] = { 0.4, 0.25, 0.3 };
  auto field = [&](const double x[3]) {
    return std::min({ E::TriangleField(x, centres, radii), E::EdgeField(x, a, 0.4, b, 0.25),
      E::EdgeField(x, b, 0.25, c, 0.3), E::EdgeField(x, a, 0.4, c, 0.3) });
  };
  const double slabError = WorstVertex(slab, vtkMedialBallUnion::MEDIAL_MESH, field, n);
  std::printf("triangle: %lld vertices within %.3f voxels of the slab\n", static_cast<long long>(n), slabError);
  MEDIAL_CHECK(slabError < 1.0, "the triangle's envelope is not the slab");

  // Points without cells: the same field image as the union of balls.
  vtkSmartPointer<vtkPolyData> loose =
    medialtest::MakeBalls({ { 0, 0, 0, 0.5 }, { 1, 0.2, 0, 0.4 }, { 0.3, 1, 0.4, 0.3 } });
  vtkNew<vtkMedialBallUnion> asBalls, asMesh;
  for (vtkMedialBallUnion* u : { asBalls.Get(), asMesh.Get() })
  {
    u->SetInputData(loose);
    u->SetSampleDimensions(48, 48, 48);
    u->SetPrimitives(u == asMesh.Get() ? vtkMedialBallUnion::MEDIAL_MESH : vtkMedialBallUnion::BALLS);
    u->Update();
  }
  vtkDataArray* f = asBalls->GetFieldOutput()->GetPointData()->GetScalars();
  vtkDataArray* g = asMesh->GetFieldOutput()->GetPointData()->GetScalars();
  double difference = 0.0;
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
  {
    difference = std::max(difference, std::fabs(f->GetTuple1(i) - g->GetTuple1(i)));
  }
  MEDIAL_CHECK(difference <= 1e-12, "balls without cells: the fields differ by %g", difference);
  return EXIT_SUCCESS;
}
}

int TestMedialBallUnionEnvelope(int, char*[])
{
  return CheckClosedForms() == EXIT_SUCCESS ? CheckShapes() : EXIT_FAILURE;
}
