// SPDX-License-Identifier: BSD-3-Clause
// The medial mesh is the same, bit for bit, on 1, 2 and 4 threads where the regular
// triangulation is most degenerate: balls on a cubic lattice inside a box (every cell's
// eight centres cospherical, radii equal in whole layers), some of them given twice. The
// triangulation is unique only through CGAL's symbolic perturbation; its simplices are
// indexed canonically (vtkMedialPowerComplex, groups sorted in parallel) and the complex's
// query loops run in a thread-independent order. Then a sampled torus at 12,000 balls.
// Each mesh also has the solid's topology.
#include "MedialMeshTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkMedialBallClassifier.h"
#include "vtkPoints.h"

namespace
{
// Balls at the nodes of an n^3 lattice strictly inside the box [0, 1]^3, each inscribed
// (its radius the distance to the nearest face); every `repeat`-th ball given twice.
vtkSmartPointer<vtkPolyData> LatticeBalls(int n, int repeat)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  std::vector<std::array<double, 4>> balls;
  for (int i = 1; i <= n; ++i)
  {
    for (int j = 1; j <= n; ++j)
    {
      for (int k = 1; k <= n; ++k)
      {
        const double c[3] = { i / (n + 1.0), j / (n + 1.0), k / (n + 1.0) };
        double r = 1.0;
        for (double x : c)
        {
          r = std::min({ r, x, 1.0 - x });
        }
        balls.push_back({ c[0], c[1], c[2], r });
      }
    }
  }
  const size_t distinct = balls.size();
  for (size_t b = 0; b < distinct; b += repeat)
  {
    balls.push_back(balls[b]);
  }
  for (const auto& b : balls)
  {
    points->InsertNextPoint(b.data());
    radius->InsertNextValue(b[3]);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->GetPointData()->AddArray(radius);
  return out;
}

// The unit box as a closed triangle surface.
vtkSmartPointer<vtkPolyData> UnitBox()
{
  vtkSmartPointer<vtkPolyData> box = medialtest::MakeSolid(vtkMedialShapeSource::BOX, 1, 4);
  double b[6];
  box->GetBounds(b);
  vtkPoints* points = box->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (p[k] - b[2 * k]) / (b[2 * k + 1] - b[2 * k]);
    }
    points->SetPoint(i, p);
  }
  return box;
}

struct Run
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkIdType Euler = 0, Components = 0;
};

Run MeshOf(vtkPolyData* solid, vtkPolyData* balls, int threads, vtkIdType samples)
{
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(solid);
  vtkNew<vtkMedialAxisSampler> sampler;
  if (balls)
  {
    filter->SetInputData(1, balls);
    filter->SetClassifier(nullptr); // lattice balls have no contacts to classify
  }
  else
  {
    sampler->SetInputData(solid);
    sampler->SetNumberOfSamples(samples);
    sampler->SetNumberOfThreads(threads);
    filter->SetBallsConnection(sampler->GetOutputPort());
  }
  filter->SetNumberOfThreads(threads);
  filter->Update();
  Run run;
  run.Mesh = vtkSmartPointer<vtkPolyData>::New();
  run.Mesh->DeepCopy(filter->GetOutput());
  run.Euler = filter->GetEulerCharacteristic();
  run.Components = filter->GetNumberOfComponents();
  return run;
}
}

int TestMedialMeshThreads(int, char*[])
{
  vtkSmartPointer<vtkPolyData> box = UnitBox();
  for (int n : { 9, 14 })
  {
    vtkSmartPointer<vtkPolyData> balls = LatticeBalls(n, 5);
    const Run one = MeshOf(box, balls, 1, 0);
    MEDIAL_CHECK(one.Mesh->GetNumberOfPolys() > 0, "lattice %d: no triangles", n);
    MEDIAL_CHECK(one.Euler == 1 && one.Components == 1, "lattice %d: chi %lld, %lld component(s); the box's: 1, 1",
      n, static_cast<long long>(one.Euler), static_cast<long long>(one.Components));
    for (int threads : { 2, 4 })
    {
      const Run other = MeshOf(box, balls, threads, 0);
      MEDIAL_CHECK(medialtest::SameMesh(one.Mesh, other.Mesh), "lattice %d: %d threads give another mesh than 1", n,
        threads);
    }
  }
  vtkSmartPointer<vtkPolyData> torus = medialtest::MakeSolid(vtkMedialShapeSource::TORUS, 1, 24);
  const Run one = MeshOf(torus, nullptr, 1, 12000);
  const Run two = MeshOf(torus, nullptr, 2, 12000);
  MEDIAL_CHECK(one.Euler == 0 && one.Components == 1, "torus: chi %lld, %lld component(s); the solid's: 0, 1",
    static_cast<long long>(one.Euler), static_cast<long long>(one.Components));
  MEDIAL_CHECK(medialtest::SameMesh(one.Mesh, two.Mesh), "torus: 2 threads give another mesh than 1");
  return EXIT_SUCCESS;
}
