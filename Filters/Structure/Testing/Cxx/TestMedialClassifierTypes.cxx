// SPDX-License-Identifier: BSD-3-Clause
// GovernorCount and MedialPointType against closed forms.
//  1. Balls placed by hand in the box [-1.5, 1.5] x [-1, 1] x [-0.65, 0.65]: the
//     middle sheet (2 faces), its edge (a seam, 3), its corner (a junction, 4), a
//     seam from a box corner, a ball touching one face (rim), a vanishing ball at an
//     edge (rim), a ball touching nothing; at theta = 100 degrees two faces 90
//     degrees apart are one governor, chained without the sample point P, or the
//     cap around P when it is given.
//  2. The sampler's balls in the same box at theta = 0 and 45: each ball's count is
//     the number of faces at distance r within the tolerance, two counted once when
//     their edge is within the band too (brute force), its type follows from it, and
//     the two runs agree (the faces are 90 degrees apart). With a band of 1e-2 of
//     the diagonal (the largest allowed), seam, junction and rim balls appear and are checked the same way.
//  3. Smooth shapes at the default theta (a geodesic sphere, a capsule): no ball is a
//     rim, most (85% or more) have two governors, the cap around P and the contact that
//     stopped it (a sheet), and no exact point is solved (a tessellated cap is no
//     single face or edge). A ball centred in a tessellated sphere or tube (the
//     sampler's balls follow the smooth surface's normals) touches facets all around
//     within the rounding of its radius, and those more than theta apart count as more
//     governors: 3.5% of the sphere's balls, 11% of the capsule's.
//  4. The output is the same for 1 and 2 threads.
#include "MedialStructureTestUtilities.h"
#include "MedialShapeTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkMedialShapeSource.h"

using namespace medialtest;

namespace
{
struct Placed
{
  double Centre[3];
  double Radius;
  double SurfacePoint[3]; // NaN: none
  int Count;
  int Type;
};

vtkSmartPointer<vtkPolyData> Balls(const std::vector<Placed>& placed, bool withSurfacePoints)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius, surface;
  radius->SetName("Radius");
  surface->SetName("SurfacePoint");
  surface->SetNumberOfComponents(3);
  for (const Placed& p : placed)
  {
    points->InsertNextPoint(p.Centre);
    radius->InsertNextValue(p.Radius);
    surface->InsertNextTuple(p.SurfacePoint);
  }
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(radius);
  if (withSurfacePoints)
  {
    pd->GetPointData()->AddArray(surface);
  }
  return pd;
}

vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution)
{
  return medialtest::MakeShape(shape, resolution, [](vtkMedialShapeSource* s) { s->SetBoxLengths(3.0, 2.0, 1.3); });
}

int CheckPlaced(vtkPolyData* box, const std::vector<Placed>& placed, double theta, bool withSurfacePoints,
  const char* label)
{
  vtkNew<vtkMedialBallClassifier> classifier;
  classifier->SetInputData(Balls(placed, withSurfacePoints));
  classifier->SetSurfaceData(box);
  classifier->SetMinimumSeparationAngle(theta);
  classifier->Update();
  vtkPolyData* out = classifier->GetOutput();
  for (size_t i = 0; i < placed.size(); ++i)
  {
    const int count = static_cast<int>(Value(out, "GovernorCount", static_cast<vtkIdType>(i)));
    const int type = static_cast<int>(Value(out, "MedialPointType", static_cast<vtkIdType>(i)));
    MEDIAL_CHECK(count == placed[i].Count && type == placed[i].Type,
      "%s: ball %zu has %d governors, type %d; expected %d, type %d", label, i, count, type, placed[i].Count,
      placed[i].Type);
  }
  std::printf("%s: %zu placed balls classified as expected\n", label, placed.size());
  return EXIT_SUCCESS;
}

// The brute-force governor count at theta = 0 in the box: faces at distance r
// within tol, two of them one governor when their common edge is within r + tol.
int FacesTouched(const double c[3], double r, double tol)
{
  const double half[3] = { 1.5, 1.0, 0.65 };
  std::vector<std::pair<int, int>> faces; // (axis, side)
  for (int k = 0; k < 3; ++k)
  {
    for (int side : { -1, 1 })
    {
      if (std::fabs(half[k] - side * c[k] - r) <= tol)
      {
        faces.emplace_back(k, side);
      }
    }
  }
  std::vector<int> group(faces.size());
  for (size_t i = 0; i < faces.size(); ++i)
  {
    group[i] = static_cast<int>(i);
  }
  for (size_t i = 0; i < faces.size(); ++i)
  {
    for (size_t j = i + 1; j < faces.size(); ++j)
    {
      const int a = faces[i].first, b = faces[j].first;
      if (a == b)
      {
        continue;
      }
      const int t = 3 - a - b;
      const double da = half[a] - faces[i].second * c[a];
      const double db = half[b] - faces[j].second * c[b];
      const double dt = std::max(0.0, std::fabs(c[t]) - half[t]);
      if (std::sqrt(da * da + db * db + dt * dt) <= r + tol)
      {
        const int from = group[j], to = group[i];
        for (int& g : group)
        {
          g = g == from ? to : g;
        }
      }
    }
  }
  std::sort(group.begin(), group.end());
  return static_cast<int>(std::unique(group.begin(), group.end()) - group.begin());
}

int CheckSampledBox(vtkPolyData* box, double theta, double tolerance, std::vector<int>& counts)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(box);
  sampler->SetNumberOfSamples(4000);
  sampler->SetMinimumSeparationAngle(theta);
  vtkNew<vtkMedialBallClassifier> classifier;
  classifier->SetInputConnection(sampler->GetOutputPort());
  classifier->SetSurfaceData(box);
  classifier->SetMinimumSeparationAngle(theta);
  classifier->SetTolerance(tolerance);
  classifier->SetComputeExactPoints(false);
  classifier->Update();
  vtkPolyData* out = classifier->GetOutput();
  const double tol = tolerance * Diagonal(box);
  int histogram[4] = { 0, 0, 0, 0 };
  counts.clear();
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[3];
    out->GetPoint(i, c);
    const double r = Value(out, "Radius", i);
    const int count = static_cast<int>(Value(out, "GovernorCount", i));
    const int type = static_cast<int>(Value(out, "MedialPointType", i));
    const int expected = FacesTouched(c, r, tol);
    const int expectedType = r <= tol || expected <= 1 ? 0 : std::min(expected, 4) - 1;
    MEDIAL_CHECK(count == expected && type == expectedType,
      "box, theta %g, tolerance %g: ball %lld (%g %g %g r %g) has %d governors, type %d; %d expected", theta, tolerance,
      static_cast<long long>(i), c[0], c[1], c[2], r, count, type, expected);
    ++histogram[type];
    counts.push_back(count);
  }
  std::printf("box, theta %g, tolerance %g: %lld balls, rim %d, sheet %d, seam %d, junction %d (all as "
              "expected)\n",
    theta, tolerance, static_cast<long long>(out->GetNumberOfPoints()), histogram[0], histogram[1], histogram[2],
    histogram[3]);
  return EXIT_SUCCESS;
}

int CheckSmooth(int shape, int resolution, const char* label)
{
  vtkSmartPointer<vtkPolyData> surface = Shape(shape, resolution);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(2000);
  vtkNew<vtkMedialBallClassifier> classifier;
  classifier->SetInputConnection(sampler->GetOutputPort());
  classifier->SetSurfaceData(surface);
  classifier->Update();
  vtkPolyData* out = classifier->GetOutput();
  vtkIdType sheets = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const double count = Value(out, "GovernorCount", i);
    MEDIAL_CHECK(count >= 2 && Value(out, "MedialPointType", i) == std::min(count, 4.0) - 1,
      "%s: ball %lld has %g governors, type %g", label, static_cast<long long>(i), count,
      Value(out, "MedialPointType", i));
    sheets += count == 2 ? 1 : 0;
  }
  const vtkIdType n = out->GetNumberOfPoints();
  MEDIAL_CHECK(sheets >= 0.85 * n, "%s: only %lld of %lld balls are sheets", label, static_cast<long long>(sheets),
    static_cast<long long>(n));
  MEDIAL_CHECK(classifier->GetOutput(1)->GetNumberOfPoints() == 0, "%s: %lld exact points from compound governors",
    label, static_cast<long long>(classifier->GetOutput(1)->GetNumberOfPoints()));
  std::printf("%s at theta 45: %lld of %lld balls are sheets with 2 governors, the others touch more; no rim, no "
              "exact points\n",
    label, static_cast<long long>(sheets), static_cast<long long>(n));
  return EXIT_SUCCESS;
}

int CheckThreads()
{
  vtkSmartPointer<vtkPolyData> box = Shape(vtkMedialShapeSource::BOX, 2);
  vtkSmartPointer<vtkPolyData> outputs[2][2];
  for (int threads : { 1, 2 })
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(box);
    sampler->SetNumberOfSamples(2000);
    sampler->SetMinimumSeparationAngle(0.0);
    vtkNew<vtkMedialBallClassifier> classifier;
    classifier->SetInputConnection(sampler->GetOutputPort());
    classifier->SetSurfaceData(box);
    classifier->SetMinimumSeparationAngle(0.0);
    classifier->SetNumberOfThreads(threads);
    classifier->Update();
    for (int port = 0; port < 2; ++port)
    {
      outputs[threads - 1][port] = vtkSmartPointer<vtkPolyData>::New();
      outputs[threads - 1][port]->DeepCopy(classifier->GetOutput(port));
    }
  }
  for (int port = 0; port < 2; ++port)
  {
    vtkPolyData* a = outputs[0][port];
    vtkPolyData* b = outputs[1][port];
    MEDIAL_CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints() && a->GetNumberOfPoints() > 0,
      "output %d: %lld and %lld points on 1 and 2 threads", port, static_cast<long long>(a->GetNumberOfPoints()),
      static_cast<long long>(b->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3];
      a->GetPoint(i, x);
      b->GetPoint(i, y);
      MEDIAL_CHECK(x[0] == y[0] && x[1] == y[1] && x[2] == y[2] &&
          Value(a, "MedialPointType", i) == Value(b, "MedialPointType", i) &&
          Value(a, "GovernorCount", i) == Value(b, "GovernorCount", i),
        "output %d, point %lld differs between 1 and 2 threads", port, static_cast<long long>(i));
    }
  }
  std::printf("1 and 2 threads: identical outputs\n");
  return EXIT_SUCCESS;
}
}

int TestMedialClassifierTypes(int, char*[])
{
  vtkSmartPointer<vtkPolyData> box = Shape(vtkMedialShapeSource::BOX, 2);
  const double none = std::nan("");
  const double e = 1e-9;
  // Centre, radius, P, count and type at theta = 0 (and 45: faces are 90 degrees apart).
  const std::vector<Placed> placed = {
    { { 0, 0, 0 }, 0.65, { 0, 0, -0.65 }, 2, 1 },
    { { 0.85, 0, 0 }, 0.65, { 0.85, 0, -0.65 }, 3, 2 },
    { { 0.85, 0.35, 0 }, 0.65, { 0.85, 0.35, -0.65 }, 4, 3 },
    { { 1.3, 0.8, 0.45 }, 0.2, { 1.3, 0.8, 0.65 }, 3, 2 },
    { { 1.2, 0, 0.35 }, 0.3, { 1.2, 0, 0.65 }, 2, 1 },
    { { 0, 0, -0.55 }, 0.1, { 0, 0, -0.65 }, 1, 0 },
    { { 1.5 - e, 0, 0.65 - e }, e, { 1.5, 0, 0.65 - e }, 1, 0 },
    { { 0, 0, 0 }, 0.3, { none, none, none }, 0, 0 },
  };
  int status = EXIT_SUCCESS;
  auto run = [&](int result) { status = result == EXIT_SUCCESS ? status : EXIT_FAILURE; };
  for (bool withP : { false, true })
  {
    run(CheckPlaced(box, placed, 0.0, withP, withP ? "theta 0, with P" : "theta 0"));
    run(CheckPlaced(box, placed, 45.0, withP, withP ? "theta 45, with P" : "theta 45"));
  }
  // theta = 100: contacts on faces 90 degrees apart are one governor. Without P they
  // chain (single linkage): the ball at the middle sheet's edge has one governor. With
  // P on z0 the cap around P takes the faces less than 100 degrees from it and the
  // opposite face stays apart.
  std::vector<Placed> chained = placed, capped = placed;
  for (int i : { 1, 2, 3, 4 })
  {
    chained[i].Count = 1;
    chained[i].Type = 0;
  }
  for (int i : { 1, 2 })
  {
    capped[i].Count = 2; // P's cap {z0, x1 (, y1)} and z1
    capped[i].Type = 1;
  }
  for (int i : { 3, 4 })
  {
    capped[i].Count = 1; // P on z1: the other faces are 90 degrees from it
    capped[i].Type = 0;
  }
  run(CheckPlaced(box, chained, 100.0, false, "theta 100"));
  run(CheckPlaced(box, capped, 100.0, true, "theta 100, with P"));

  // A wide contact band puts sampled balls near seams, junctions and edges too.
  std::vector<int> counts0, counts45, wideBand;
  run(CheckSampledBox(box, 0.0, 1e-6, counts0));
  run(CheckSampledBox(box, 45.0, 1e-6, counts45));
  run(CheckSampledBox(box, 0.0, 1e-2, wideBand));
  MEDIAL_CHECK(std::count(wideBand.begin(), wideBand.end(), 3) > 0 && std::count(wideBand.begin(), wideBand.end(), 4) > 0,
    "box, tolerance 1e-2: no seam or junction ball");
  MEDIAL_CHECK(counts0 == counts45, "box: governor counts differ between theta 0 and 45");
  run(CheckSmooth(vtkMedialShapeSource::SPHERE, 3, "geodesic sphere (1280 triangles)"));
  run(CheckSmooth(vtkMedialShapeSource::CAPSULE, 16, "capsule (6656 triangles)"));
  run(CheckThreads());
  return status;
}
