// SPDX-License-Identifier: BSD-3-Clause
// ONE_PASS against brute force over every triangle, on non-convex shapes where no
// closed form exists: each ball must be empty (no admissible surface point inside
// by more than 1e-10 of the diagonal), maximal (the ball 1e-7 of the diagonal
// larger along the same normal is entered), and its ContactPoint must lie on its
// sphere and be admissible. "Admissible" is the sampler's rule: q counts for a
// ball (c, r) tangent at P when (q - c).(P - c) <= r^2 cos(theta). Checked for
// theta = 0 and the default theta with MaximumProtrusion 1 (the angle rule alone),
// on the demo shape, a capsule and, when present, 300 samples of horse.ply.
// Then the defaults (balls along the smooth surface's normals, shrunk about their
// centre where the surface crosses them deeper than MaximumProtrusion): no ball
// crosses the surface (all of it, by brute force) by more than MaximumProtrusion, and
// a ball that no longer touches its surface point touches the surface.
// First, the search alone on a four-triangle surface (one leaf of the tree) built so
// that the cap's surface inside the ball is reached only as a triangle of a leaf that
// lies in the cone: a bump in the cap beside a wall that rises into the cone. The
// search must list that triangle for the cap on the way (no lane is set aside for
// it), and the ball it inscribes must touch the surface where brute force says.
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"
#include "vtkPoints.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <cstdlib>
#include <string>

using namespace medialtest;
namespace G = vtkMedialGeometry;

namespace
{
struct Triangles
{
  std::vector<double> Vertices; // 9 per triangle
};

Triangles Collect(vtkPolyData* surface)
{
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputData(surface);
  tri->Update();
  Triangles all;
  vtkPolyData* t = tri->GetOutput();
  vtkIdType npts;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(t->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(npts, ids);
    for (int j = 0; j < 3; ++j)
    {
      double x[3];
      t->GetPoint(ids[j], x);
      all.Vertices.insert(all.Vertices.end(), x, x + 3);
    }
  }
  return all;
}

// Smallest distance from c to an admissible point of any triangle, skipping the
// triangles that contain P (they touch every tangent ball at P only).
double AdmissibleDistance(
  const Triangles& all, const double c[3], const double p[3], double cosTheta, double onSurface)
{
  double w[3];
  G::Sub(p, c, w);
  const double k = G::Dot(w, c) + G::Dot(w, w) * cosTheta;
  double best = HUGE_VAL;
  const size_t n = all.Vertices.size() / 9;
  for (size_t i = 0; i < n; ++i)
  {
    const double* a = &all.Vertices[9 * i];
    double q[3];
    if (G::ClosestPointOnTriangle(p, a, a + 3, a + 6, q) <= onSurface * onSurface)
    {
      continue;
    }
    const double d2 = cosTheta < 1.0 ? G::ClosestPointOnClippedTriangle(c, a, a + 3, a + 6, w, k, q)
                                     : G::ClosestPointOnTriangle(c, a, a + 3, a + 6, q);
    best = std::min(best, d2);
  }
  return std::sqrt(best);
}

int Check(vtkPolyData* surface, const char* label, vtkIdType samples)
{
  const Triangles all = Collect(surface);
  const double diag = Diagonal(surface);
  vtkNew<vtkMedialAxisSampler> defaults;
  for (double theta : { 0.0, defaults->GetMinimumSeparationAngle() })
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(surface);
    sampler->SetMethodToOnePass();
    sampler->SetNumberOfSamples(samples);
    sampler->SetRandomSeed(5);
    sampler->SetMinimumSeparationAngle(theta);
    sampler->SetMaximumProtrusion(1.0);
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    MEDIAL_CHECK(out->GetNumberOfPoints() == samples, "%s: %lld of %lld samples", label,
      static_cast<long long>(out->GetNumberOfPoints()), static_cast<long long>(samples));
    const double cosTheta = theta > 0 ? std::cos(theta * 3.14159265358979323846 / 180.0) : 1.0;
    double worstIntrusion = -HUGE_VAL, worstContact = 0.0, widestMiss = -HUGE_VAL;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double c[3], p[3], contact[3], n[3];
      out->GetPoint(i, c);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = Value(out, "SurfacePoint", i, k);
        contact[k] = Value(out, "ContactPoint", i, k);
      }
      const double r = Value(out, "Radius", i);
      for (int k = 0; k < 3; ++k)
      {
        n[k] = (c[k] - p[k]) / r;
      }
      // Empty.
      const double d = AdmissibleDistance(all, c, p, cosTheta, 1e-12 * diag);
      worstIntrusion = std::max(worstIntrusion, (r - d) / diag);
      // Maximal: a slightly larger ball along the same normal is entered.
      const double bigger = r + 1e-7 * diag;
      double c2[3];
      G::AddScaled(p, bigger, n, c2);
      const double d2 = AdmissibleDistance(all, c2, p, cosTheta, 1e-12 * diag);
      widestMiss = std::max(widestMiss, (d2 - bigger) / diag);
      // The contact is on the sphere and admissible.
      double pc[3], qc[3];
      G::Sub(p, c, pc);
      G::Sub(contact, c, qc);
      const double onSphere = std::fabs(std::sqrt(G::Distance2(contact, c)) - r) / diag;
      const double admissible = G::Dot(qc, pc) - r * r * cosTheta; // <= 0
      worstContact = std::max({ worstContact, onSphere, admissible / (r * diag) });
    }
    std::printf("%s, theta %.0f, %lld balls: worst intrusion %.2e, worst gap of the 1e-7 larger "
                "ball %.2e, worst contact %.2e (all / diagonal)\n",
      label, theta, static_cast<long long>(out->GetNumberOfPoints()), worstIntrusion, widestMiss,
      worstContact);
    MEDIAL_CHECK(worstIntrusion <= 1e-10, "%s theta %g: a ball is not empty (%g)", label, theta, worstIntrusion);
    MEDIAL_CHECK(widestMiss < 0.0, "%s theta %g: a ball is not maximal (%g)", label, theta, widestMiss);
    MEDIAL_CHECK(worstContact <= 1e-9, "%s theta %g: a contact is off its sphere or in the cap (%g)",
      label, theta, worstContact);
  }
  return EXIT_SUCCESS;
}

// Distance from c to the surface, every triangle counted.
double SurfaceDistance(const Triangles& all, const double c[3])
{
  return AdmissibleDistance(all, c, c, 1.0, 0.0);
}

// The defaults: every ball crosses the surface by at most MaximumProtrusion, and each
// one that no longer touches its surface point (a shrunk one) touches the surface.
int CheckInscribed(vtkPolyData* surface, const char* label, vtkIdType samples)
{
  const Triangles all = Collect(surface);
  const double diag = Diagonal(surface);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(samples);
  sampler->SetRandomSeed(5);
  sampler->Update();
  vtkPolyData* out = sampler->GetOutput();
  const double allowed = sampler->GetMaximumProtrusion() * diag;
  vtkIdType shrunk = 0;
  double worstCross = -HUGE_VAL, worstTouch = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[3], p[3];
    out->GetPoint(i, c);
    out->GetPointData()->GetArray("SurfacePoint")->GetTuple(i, p);
    const double r = Value(out, "Radius", i);
    const double d = SurfaceDistance(all, c);
    worstCross = std::max(worstCross, (r - d - allowed) / diag); // <= 0: crossed by at most `allowed`
    if (std::sqrt(G::Distance2(c, p)) - r > 1e-12 * diag)
    {
      ++shrunk;
      worstTouch = std::max(worstTouch, std::fabs(r - d) / diag);
    }
  }
  std::printf("%s, defaults, %lld balls: %lld shrunk; every ball crosses the surface by at most "
              "MaximumProtrusion %+.2e, shrunk balls touch it within %.2e (/ diagonal)\n",
    label, static_cast<long long>(out->GetNumberOfPoints()), static_cast<long long>(shrunk), worstCross, worstTouch);
  MEDIAL_CHECK(worstCross <= 1e-12, "%s: a ball crosses the surface by %g more than allowed", label, worstCross);
  MEDIAL_CHECK(worstTouch <= 1e-10, "%s: a shrunk ball is %g off the surface", label, worstTouch);
  return EXIT_SUCCESS;
}

// The tangent ball at p = 0 along n = +z, radius 1 (bounded by the ceiling z = 2), with
// theta 45 and a small allowed protrusion. The four triangles fit one leaf, whose box
// holds p and rises above the cap's plane: the walk opens it and meets each triangle.
// The bump (z = 0.1, 0.35 to 0.45 from the axis) lies inside the ball, below the cone
// n.(q - p) >= sin(theta / 2) |q - p| where blockers can lie, so the angle rule drops it
// as a triangle; only the list kept for the cap brings it back, and the ball about the
// same centre must shrink to touch it. The wall (x = 1.1) lies in the cone, outside the ball.
int CheckCapInConeLeaf()
{
  const double corners[4][9] = {
    { -0.3, -0.3, 0, 0.3, -0.3, 0, 0, 0.4, 0 },          // p's own triangle (the floor)
    { 0.35, -0.05, 0.1, 0.45, -0.05, 0.1, 0.4, 0.05, 0.1 }, // the bump, in the cap
    { 1.1, -0.1, 0.1, 1.1, 0.1, 0.1, 1.1, 0, 0.6 },      // the wall, in the cone
    { -0.5, -0.5, 2, 0.5, -0.5, 2, 0, 0.5, 2 },          // the ceiling, touching the ball
  };
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (const auto& t : corners)
  {
    const vtkIdType ids[3] = { points->InsertNextPoint(t), points->InsertNextPoint(t + 3),
      points->InsertNextPoint(t + 6) };
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(cells);
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  MEDIAL_CHECK(mesh.Build(surface, error) && query.Build(&mesh, error), "cap case: %s", error.c_str());
  MEDIAL_CHECK(mesh.GetNumberOfTriangles() == 4, "cap case: %lld triangles",
    static_cast<long long>(mesh.GetNumberOfTriangles()));

  const double p[3] = { 0, 0, 0 }, n[3] = { 0, 0, 1 }, c[3] = { 0, 0, 1 };
  const double cosTheta = std::cos(45.0 * 3.14159265358979323846 / 180.0);
  const double diag = mesh.Diagonal, allowed = 1e-4 * diag;
  vtkMedialSurfaceQuery::TangentBall ball;
  ball.Radius = 1.0;
  ball.Contact[2] = 2.0;
  ball.ContactTriangle = 3;
  vtkMedialSurfaceQuery::ContactFilter filter;
  filter.OwnTriangle = 0;
  filter.CosMinAngle = cosTheta;
  query.MaximalTangentBall(p, n, filter, allowed, ball);

  const Triangles all = Collect(surface);
  const double empty = AdmissibleDistance(all, c, p, cosTheta, 1e-12 * diag);
  const double touch = SurfaceDistance(all, c);
  std::printf("cap reached through a leaf in the cone: radius %.17g (admissible surface at %.17g), shrunk %d "
              "to %.17g on triangle %lld (the surface at %.17g)\n",
    ball.Radius, empty, ball.Shrunk ? 1 : 0, ball.InscribedRadius, static_cast<long long>(ball.InscribedTriangle),
    touch);
  MEDIAL_CHECK(ball.Radius == 1.0 && empty >= 1.0 - 1e-12 * diag, "cap case: the ball is %.17g, the admissible "
    "surface %.17g away", ball.Radius, empty);
  MEDIAL_CHECK(touch < ball.Radius - allowed, "cap case: the bump no longer enters the ball (the case is void)");
  MEDIAL_CHECK(ball.Shrunk && ball.InscribedTriangle == 1, "cap case: the bump %.3g deep in the cap was missed",
    ball.Radius - touch);
  MEDIAL_CHECK(std::fabs(ball.InscribedRadius - touch) <= 1e-12 * diag,
    "cap case: the inscribed ball is %.17g, the surface %.17g from its centre", ball.InscribedRadius, touch);
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerOnePassBruteForce(int, char*[])
{
  if (CheckCapInConeLeaf() != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(24);
  jack->Update();
  std::printf("demo shape: %lld triangles\n", static_cast<long long>(jack->GetOutput()->GetNumberOfCells()));
  if (Check(jack->GetOutput(), "demo shape", 400) != EXIT_SUCCESS ||
    CheckInscribed(jack->GetOutput(), "demo shape", 400) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialShapeSource> capsule;
  capsule->SetShapeToCapsule();
  capsule->SetResolution(12);
  capsule->Update();
  if (Check(capsule->GetOutput(), "capsule", 400) != EXIT_SUCCESS ||
    CheckInscribed(capsule->GetOutput(), "capsule", 400) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkPolyData> horse = ReadSharedPLY("horse.ply");
  return horse && (Check(horse, "horse", 300) != EXIT_SUCCESS || CheckInscribed(horse, "horse", 300) != EXIT_SUCCESS)
    ? EXIT_FAILURE
    : EXIT_SUCCESS;
}
