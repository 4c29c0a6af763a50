// SPDX-License-Identifier: BSD-3-Clause
// Exact junction vertices and seam points at theta = 0 against an independent
// closed form. For each polyhedron the junction vertices of the exact medial axis
// (for a convex one, its 3D straight skeleton) are computed here by brute force:
// every 4-subset of face planes (and the reflex edge's line of an L-shaped prism)
// is solved for the tangent ball, which is kept when it is empty and touches 4 or
// more distinct features. The classifier's junctions must match them within 1e-9
// of the diagonal, none missing and none extra; each seam point it outputs must be
// empty and touch exactly 3 features within 1e-9 of the diagonal. 3000 balls per
// shape (the junctions were also all found from 300 to 20000 balls and 4 seeds).
#include "MedialPolyhedronTestUtilities.h"
#include "MedialStructureTestUtilities.h"

#include "vtkMedialShapeSource.h"

#include <random>
#include <string>

using namespace medialtest;

namespace
{
// `closedForm`: the oracle's subsets cover every junction (at most one reflex edge
// or vertex per junction). Otherwise junctions beyond them (two or more quadratic
// governors, Newton's method) must still be empty and touch 4 or more features.
int CheckShape(vtkPolyData* shape, const std::vector<std::array<Vec3, 2>>& reflexEdges, const char* label,
  vtkIdType samples = 3000, bool closedForm = true)
{
  PolyhedronOracle oracle(shape, reflexEdges);
  const double diagonal = oracle.GetDiagonal();
  const double eps = 1e-9 * diagonal;
  const auto expected = oracle.Junctions(eps, eps);

  auto classifier = ClassifyAtThetaZero(shape, samples, 3);
  vtkPolyData* exact = classifier->GetOutput(1);
  std::vector<char> matched(expected.size(), 0);
  double worst = 0.0, worstSeam = 0.0;
  int found = 0, extra = 0, beyond = 0, seams = 0, badSeams = 0;
  for (vtkIdType i = 0; i < exact->GetNumberOfPoints(); ++i)
  {
    Vec3 x;
    exact->GetPoint(i, x.data());
    const double r = Value(exact, "Radius", i);
    const int type = static_cast<int>(Value(exact, "MedialPointType", i));
    if (type == vtkMedialBallClassifier::SEAM)
    {
      ++seams;
      const double gap = std::max(r - oracle.SurfaceDistance(x), 0.0);
      worstSeam = std::max(worstSeam, gap / diagonal);
      if (gap > eps || oracle.Governors(x, r, eps) != 3)
      {
        if (++badSeams <= 3)
        {
          std::printf("%s: seam point %lld (%.12g %.12g %.12g) r %.12g: gap %g, %d features\n", label,
            static_cast<long long>(i), x[0], x[1], x[2], r, gap / diagonal, oracle.Governors(x, r, eps));
        }
      }
      continue;
    }
    ++found;
    double best = HUGE_VAL;
    size_t which = 0;
    for (size_t j = 0; j < expected.size(); ++j)
    {
      const auto& c = expected[j].Centre;
      const double d = std::sqrt((c[0] - x[0]) * (c[0] - x[0]) + (c[1] - x[1]) * (c[1] - x[1]) +
        (c[2] - x[2]) * (c[2] - x[2]) + (expected[j].Radius - r) * (expected[j].Radius - r));
      if (d < best)
      {
        best = d;
        which = j;
      }
    }
    if (best <= eps)
    {
      matched[which] = 1;
      worst = std::max(worst, best / diagonal);
    }
    else if (!closedForm && oracle.SurfaceDistance(x) >= r - eps && oracle.Governors(x, r, eps) >= 4)
    {
      ++beyond;
    }
    else
    {
      ++extra;
      std::printf("%s: extra junction (%.12g %.12g %.12g) r %.12g, %d governors, nearest expected %g away\n",
        label, x[0], x[1], x[2], r, static_cast<int>(Value(exact, "GovernorCount", i)), best / diagonal);
    }
  }
  int missing = 0;
  for (size_t j = 0; j < expected.size(); ++j)
  {
    if (!matched[j])
    {
      ++missing;
      std::printf("%s: missing junction (%.12g %.12g %.12g) r %.12g, %d governors\n", label,
        expected[j].Centre[0], expected[j].Centre[1], expected[j].Centre[2], expected[j].Radius,
        expected[j].Governors);
    }
  }
  std::printf("%s: %zu faces, junctions expected %zu found %d (missing %d, extra %d, valid beyond the closed "
              "form %d), max error %.3g of the diagonal; %d seam points, %d off the seam, max gap %.3g\n",
    label, oracle.GetNumberOfFaces(), expected.size(), found, missing, extra, beyond, worst, seams, badSeams,
    worstSeam);
  MEDIAL_CHECK(missing == 0 && extra == 0, "%s: %d missing, %d extra junctions", label, missing, extra);
  MEDIAL_CHECK(worst <= 1e-9, "%s: junction error %g of the diagonal", label, worst);
  MEDIAL_CHECK(seams > 0 && badSeams == 0, "%s: %d seam points, %d not on a seam", label, seams, badSeams);
  return EXIT_SUCCESS;
}

vtkSmartPointer<vtkPolyData> Box(double a, double b, double c, int resolution)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShapeToBox();
  source->SetBoxLengths(a, b, c);
  source->SetResolution(resolution);
  source->Update();
  return source->GetOutput();
}
}

int TestMedialClassifierJunctions(int, char*[])
{
  int status = EXIT_SUCCESS;
  auto run = [&](int result) { status = result == EXIT_SUCCESS ? status : EXIT_FAILURE; };
  run(CheckShape(Box(3.0, 2.0, 1.3, 2), {}, "box 3 x 2 x 1.3"));
  run(CheckShape(Box(1.0, 1.0, 1.0, 1), {}, "cube"));
  const double s = std::sqrt(2.0);
  run(CheckShape(ConvexHull({ { 1, 0, -1 / s }, { -1, 0, -1 / s }, { 0, 1, 1 / s }, { 0, -1, 1 / s } }), {},
    "regular tetrahedron"));
  run(CheckShape(ConvexHull({ { 0, 0, 0 }, { 2.1, 0.2, 0 }, { 0.3, 1.7, 0.1 }, { 0.5, 0.4, 1.3 } }), {},
    "irregular tetrahedron"));
  run(CheckShape(Prism({ { 0, 0 }, { 1.5, 0.1 }, { 0.6, 1.2 } }, 2.7), {}, "triangular prism"));
  // Convex hulls of random points on an ellipsoid (20 and 76 faces).
  std::mt19937_64 random(2024);
  std::normal_distribution<double> gauss;
  for (int points : { 12, 40 })
  {
    std::vector<std::array<double, 3>> cloud;
    for (int i = 0; i < points; ++i)
    {
      double v[3] = { gauss(random), gauss(random), gauss(random) };
      const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      cloud.push_back({ 1.6 * v[0] / l, 1.1 * v[1] / l, 0.8 * v[2] / l });
    }
    const std::string label = "convex hull of " + std::to_string(points) + " random points";
    run(CheckShape(ConvexHull(cloud), {}, label.c_str()));
  }
  // L-shaped prisms: arms of widths 1 and 0.8 (and 1.3 and 0.6), reflex edge at (wx, wy).
  for (const auto& dims : { std::array<double, 5>{ 2.2, 1.9, 1.0, 0.8, 0.9 },
         std::array<double, 5>{ 2.5, 1.7, 1.3, 0.6, 1.4 } })
  {
    const double X = dims[0], Y = dims[1], wx = dims[2], wy = dims[3], h = dims[4];
    auto prism = Prism({ { 0, 0 }, { X, 0 }, { X, wy }, { wx, wy }, { wx, Y }, { 0, Y } }, h);
    run(CheckShape(prism, { { Vec3{ wx, wy, 0.0 }, Vec3{ wx, wy, h } } }, h < 1.0 ? "L prism (flat)" : "L prism (tall)"));
  }
  // A notched box: three reflex edges and a reflex vertex (Newton's method where two meet).
  {
    const double A = 2.0, B = 1.6, C = 1.2, a = 1.1, b = 0.9, c = 0.7;
    const Vec3 v{ a, b, c };
    run(CheckShape(NotchedBox(A, B, C, a, b, c),
      { { v, Vec3{ A, b, c } }, { v, Vec3{ a, B, c } }, { v, Vec3{ a, b, C } }, { v, v } }, "notched box", 3000,
      false));
  }
  // Crossed grooves: a channel along x in the top, one along y in the bottom. Junctions
  // under their crossing touch a top edge and a bottom edge, two skew lines (Newton's
  // method; the closed form here is a grid of Newton starts over the two faces' plane).
  {
    // Generic sizes: no two faces exactly a ball's diameter apart (no junction lines).
    const double X = 2.43, Y = 2.07, Z = 1.37;
    const double y1 = 0.83, y2 = 1.31, z1 = 0.71, x1 = 0.93, x2 = 1.52, z2 = 0.47;
    run(CheckShape(CrossedGrooves(X, Y, Z, y1, y2, z1, x1, x2, z2),
      { { Vec3{ 0, y1, z1 }, Vec3{ X, y1, z1 } }, { Vec3{ 0, y2, z1 }, Vec3{ X, y2, z1 } },
        { Vec3{ x1, 0, z2 }, Vec3{ x1, Y, z2 } }, { Vec3{ x2, 0, z2 }, Vec3{ x2, Y, z2 } } },
      "crossed grooves"));
  }
  return status;
}
