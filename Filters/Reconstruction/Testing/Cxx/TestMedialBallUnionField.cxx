// SPDX-License-Identifier: BSD-3-Clause
// The field image equals the brute-force min_i(|x - c_i| - r_i) wherever it is
// within the band (|f| < B), and exactly -B or +B beyond it; in 3D and in 2D. The
// image and the surface are identical for 1, 2 and 3 threads.
#include "MedialBallUnionTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialRandom.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
std::vector<BallSpec> RandomBalls(int count, bool planar, vtkTypeUInt64 seed)
{
  std::vector<BallSpec> balls;
  for (int i = 0; i < count; ++i)
  {
    vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(i));
    const double x = random.Uniform(), y = random.Uniform(), z = planar ? 0.5 : random.Uniform();
    // Mostly small balls and a few large ones, as on a medial axis.
    const double r = i % 17 == 0 ? 0.1 + 0.15 * random.Uniform() : 0.01 + 0.05 * random.Uniform();
    balls.push_back({ x, y, z, r });
  }
  return balls;
}

int CheckField(const std::vector<BallSpec>& balls, const char* name, int expectedDimension)
{
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(MakeBalls(balls));
  ballUnion->SetSampleDimensions(41, 37, 45);
  ballUnion->SetNumberOfThreads(1);
  ballUnion->Update();
  vtkImageData* image = ballUnion->GetFieldOutput();
  const double band = ballUnion->GetBandWidth() * ballUnion->GetVoxelSize();
  vtkDataArray* values = image->GetPointData()->GetArray("Distance");
  MEDIAL_CHECK(values && values == image->GetPointData()->GetScalars(), "%s: no Distance scalars", name);
  MEDIAL_CHECK(ballUnion->GetOutputDimension() == expectedDimension, "%s: dimension %d", name,
    ballUnion->GetOutputDimension());
  vtkIdType inBand = 0, wrong = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    const double exact = UnionField(balls, x);
    const double stored = values->GetTuple1(i);
    const double expected = std::max(-band, std::min(band, exact));
    const double error = std::fabs(stored - expected);
    worst = std::max(worst, error);
    wrong += error > 1e-12 ? 1 : 0;
    inBand += std::fabs(exact) < band ? 1 : 0;
  }
  std::printf("%s: %lld voxels, %lld in the band |f| < %.3g, %lld differ from clamp(f), worst %.3g\n",
    name, static_cast<long long>(image->GetNumberOfPoints()), static_cast<long long>(inBand), band,
    static_cast<long long>(wrong), worst);
  MEDIAL_CHECK(inBand > image->GetNumberOfPoints() / 50, "%s: band too thin to test", name);
  MEDIAL_CHECK(wrong == 0, "%s: %lld voxels differ from the exact clamped field", name, static_cast<long long>(wrong));

  // Identical output for other thread counts.
  for (int threads : { 2, 3 })
  {
    vtkNew<vtkMedialBallUnion> other;
    other->SetInputData(MakeBalls(balls));
    other->SetSampleDimensions(41, 37, 45);
    other->SetNumberOfThreads(threads);
    other->Update();
    vtkDataArray* otherValues = other->GetFieldOutput()->GetPointData()->GetScalars();
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      differ += otherValues->GetTuple1(i) != values->GetTuple1(i) ? 1 : 0;
    }
    vtkPolyData* a = ballUnion->GetOutput();
    vtkPolyData* b = other->GetOutput();
    bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() && a->GetNumberOfCells() == b->GetNumberOfCells();
    for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      a->GetPoint(i, p);
      b->GetPoint(i, q);
      same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    }
    MEDIAL_CHECK(differ == 0 && same, "%s: %d threads: %lld voxels differ, surface %s", name, threads,
      static_cast<long long>(differ), same ? "same" : "differs");
  }
  return EXIT_SUCCESS;
}
}

int TestMedialBallUnionField(int, char*[])
{
  if (CheckField(RandomBalls(400, false, 7), "3D", 3) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return CheckField(RandomBalls(150, true, 9), "2D", 2);
}
