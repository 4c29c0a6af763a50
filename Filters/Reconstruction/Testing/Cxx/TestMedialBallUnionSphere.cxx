// SPDX-License-Identifier: BSD-3-Clause
// A single ball reconstructs its sphere: every vertex within one voxel of the
// sphere, a closed outward surface, the enclosed volume within 1%; in both
// resolution modes.
#include "MedialBallUnionTestUtilities.h"

#include "vtkImageData.h"
#include "vtkMassProperties.h"
#include "vtkMedialBallUnion.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialBallUnionSphere(int, char*[])
{
  const BallSpec ball = { 1.0, -2.0, 0.5, 1.3 };
  auto input = MakeBalls({ ball });
  for (int mode : { vtkMedialBallUnion::USE_SAMPLE_DIMENSIONS, vtkMedialBallUnion::USE_SPACING })
  {
    vtkNew<vtkMedialBallUnion> ballUnion;
    ballUnion->SetInputData(input);
    ballUnion->SetResolutionMode(mode);
    ballUnion->SetSampleDimensions(48, 56, 64);
    ballUnion->SetSpacing(1.0 / 60.0);
    ballUnion->Update();
    vtkPolyData* surface = ballUnion->GetOutput();
    vtkImageData* field = ballUnion->GetFieldOutput();
    const double h = ballUnion->GetVoxelSize();
    int dims[3];
    field->GetDimensions(dims);
    double spacing[3];
    field->GetSpacing(spacing);
    double worst = 0.0;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      double p[3];
      surface->GetPoint(i, p);
      const double d[3] = { p[0] - ball[0], p[1] - ball[1], p[2] - ball[2] };
      worst = std::max(worst, std::fabs(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - ball[3]));
    }
    vtkNew<vtkMassProperties> mass;
    mass->SetInputData(surface);
    mass->Update();
    const double exact = 4.0 / 3.0 * 3.14159265358979323846 * std::pow(ball[3], 3);
    const double volumeError = std::fabs(mass->GetVolume() - exact) / exact;
    std::printf("mode %d: grid %dx%dx%d, voxel %.4g, %lld points, max |dist - r| %.3g voxels, "
                "volume error %.2g, signed volume %.4g\n",
      mode, dims[0], dims[1], dims[2], h, static_cast<long long>(surface->GetNumberOfPoints()),
      worst / h, volumeError, mass->GetVolume());
    MEDIAL_CHECK(ballUnion->GetOutputDimension() == 3, "dimension %d", ballUnion->GetOutputDimension());
    MEDIAL_CHECK(surface->GetNumberOfPoints() > 1000, "too few points");
    MEDIAL_CHECK(worst <= h, "vertex %.3g voxels off the sphere", worst / h);
    MEDIAL_CHECK(OpenEdges(surface) == 0, "surface is not closed");
    MEDIAL_CHECK(volumeError <= 0.01, "volume off by %.3g", volumeError);
    // vtkMassProperties reports |volume|: orientation checked through the signed sum.
    double signedVolume = 0.0;
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      surface->GetCellPoints(c, npts, ids);
      double a[3], b[3], q[3];
      surface->GetPoint(ids[0], a);
      surface->GetPoint(ids[1], b);
      surface->GetPoint(ids[2], q);
      signedVolume += (a[0] * (b[1] * q[2] - b[2] * q[1]) - a[1] * (b[0] * q[2] - b[2] * q[0]) +
                        a[2] * (b[0] * q[1] - b[1] * q[0])) / 6.0;
    }
    MEDIAL_CHECK(signedVolume > 0.99 * exact, "surface not oriented outward (%g)", signedVolume);
    if (mode == vtkMedialBallUnion::USE_SAMPLE_DIMENSIONS)
    {
      MEDIAL_CHECK(dims[0] == 48 && dims[1] == 56 && dims[2] == 64, "grid %d %d %d", dims[0], dims[1], dims[2]);
    }
    else
    {
      const double diagonal = 2.0 * ball[3] * std::sqrt(3.0);
      MEDIAL_CHECK(std::fabs(spacing[0] - diagonal / 60.0) < 1e-12 && spacing[0] == spacing[2],
        "spacing %g, expected %g", spacing[0], diagonal / 60.0);
    }
  }
  return EXIT_SUCCESS;
}
