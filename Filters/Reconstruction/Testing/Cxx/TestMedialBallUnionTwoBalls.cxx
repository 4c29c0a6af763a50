// SPDX-License-Identifier: BSD-3-Clause
// Two overlapping balls: every output vertex lies within one voxel of the exact
// boundary of the union (two spherical caps meeting on a circle), the crease
// circle is reached, the volume matches the analytic one, and contouring the
// field output (port 1) downstream gives the same surface.
#include "MedialBallUnionTestUtilities.h"

#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkMassProperties.h"
#include "vtkMedialBallUnion.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
const double Pi = 3.14159265358979323846;

double Norm(const double v[3])
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Exact distance from x to the boundary of B1 u B2: the part of each sphere outside
// the other ball, whose nearest point is either the radial projection or a point of
// the intersection circle.
struct TwoBallUnion
{
  double C1[3], R1, C2[3], R2;
  double Axis[3], CircleCentre[3], CircleRadius;

  TwoBallUnion(const BallSpec& a, const BallSpec& b)
  {
    for (int k = 0; k < 3; ++k)
    {
      C1[k] = a[k];
      C2[k] = b[k];
      Axis[k] = b[k] - a[k];
    }
    R1 = a[3];
    R2 = b[3];
    const double d = Norm(Axis);
    for (double& c : Axis)
    {
      c /= d;
    }
    const double along = (d * d + R1 * R1 - R2 * R2) / (2.0 * d);
    CircleRadius = std::sqrt(R1 * R1 - along * along);
    for (int k = 0; k < 3; ++k)
    {
      CircleCentre[k] = C1[k] + along * Axis[k];
    }
  }
  double DistanceToCircle(const double x[3]) const
  {
    double v[3];
    for (int k = 0; k < 3; ++k)
    {
      v[k] = x[k] - CircleCentre[k];
    }
    const double t = v[0] * Axis[0] + v[1] * Axis[1] + v[2] * Axis[2];
    double radial[3] = { v[0] - t * Axis[0], v[1] - t * Axis[1], v[2] - t * Axis[2] };
    const double q = Norm(radial);
    return std::sqrt(t * t + (q - CircleRadius) * (q - CircleRadius));
  }
  // Distance from x to the part of sphere (c, r) outside ball (o, ro).
  double DistanceToCap(const double x[3], const double c[3], double r, const double o[3], double ro) const
  {
    double v[3];
    for (int k = 0; k < 3; ++k)
    {
      v[k] = x[k] - c[k];
    }
    const double len = Norm(v);
    double projected[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      projected[k] = c[k] + (len > 0 ? r * v[k] / len : (k == 0 ? r : 0.0));
      w[k] = projected[k] - o[k];
    }
    if (Norm(w) >= ro)
    {
      return std::fabs(len - r);
    }
    return DistanceToCircle(x);
  }
  double Distance(const double x[3]) const
  {
    return std::min(DistanceToCap(x, C1, R1, C2, R2), DistanceToCap(x, C2, R2, C1, R1));
  }
  double Volume() const
  {
    const double d = std::sqrt((C2[0] - C1[0]) * (C2[0] - C1[0]) + (C2[1] - C1[1]) * (C2[1] - C1[1]) +
      (C2[2] - C1[2]) * (C2[2] - C1[2]));
    const double lens = Pi * (R1 + R2 - d) * (R1 + R2 - d) *
      (d * d + 2 * d * R2 - 3 * R2 * R2 + 2 * d * R1 + 6 * R1 * R2 - 3 * R1 * R1) / (12 * d);
    return 4.0 / 3.0 * Pi * (R1 * R1 * R1 + R2 * R2 * R2) - lens;
  }
};
}

int TestMedialBallUnionTwoBalls(int, char*[])
{
  const BallSpec a = { 0.0, 0.0, 0.0, 1.0 }, b = { 1.2, 0.3, -0.2, 0.8 };
  const TwoBallUnion exact(a, b);
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(MakeBalls({ a, b }));
  ballUnion->SetSampleDimensions(80, 64, 64);
  ballUnion->Update();
  vtkPolyData* surface = ballUnion->GetOutput();
  const double h = ballUnion->GetVoxelSize();
  double worst = 0.0, nearestToCrease = HUGE_VAL;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    worst = std::max(worst, exact.Distance(p));
    nearestToCrease = std::min(nearestToCrease, exact.DistanceToCircle(p));
  }
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(surface);
  mass->Update();
  const double volumeError = std::fabs(mass->GetVolume() - exact.Volume()) / exact.Volume();
  std::printf("voxel %.4g, %lld points: max distance to the exact boundary %.3g voxels, nearest "
              "vertex to the crease %.3g voxels, volume error %.2g\n",
    h, static_cast<long long>(surface->GetNumberOfPoints()), worst / h, nearestToCrease / h, volumeError);
  MEDIAL_CHECK(ballUnion->GetOutputDimension() == 3, "dimension %d", ballUnion->GetOutputDimension());
  MEDIAL_CHECK(worst <= h, "a vertex is %.3g voxels off the union boundary", worst / h);
  MEDIAL_CHECK(nearestToCrease <= 0.5 * h, "the crease is not reached (%.3g voxels)", nearestToCrease / h);
  MEDIAL_CHECK(OpenEdges(surface) == 0, "surface is not closed");
  MEDIAL_CHECK(volumeError <= 0.01, "volume off by %.3g", volumeError);

  // The field port feeds a downstream contour filter: same surface.
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(ballUnion->GetOutputPort(1));
  contour->SetValue(0, 0.0);
  contour->Update();
  std::printf("downstream contour: %lld points\n",
    static_cast<long long>(contour->GetOutput()->GetNumberOfPoints()));
  MEDIAL_CHECK(contour->GetOutput()->GetNumberOfPoints() == surface->GetNumberOfPoints(),
    "downstream contour has %lld points, output 0 has %lld",
    static_cast<long long>(contour->GetOutput()->GetNumberOfPoints()),
    static_cast<long long>(surface->GetNumberOfPoints()));
  return EXIT_SUCCESS;
}
