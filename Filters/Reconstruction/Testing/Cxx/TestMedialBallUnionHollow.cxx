// SPDX-License-Identifier: BSD-3-Clause
// A hollow part end to end: the sampler's balls of a hollow sphere (radii 1 and 0.7,
// its shells as a naive export winds them) rebuild both walls: the union's surface is
// two closed shells, one on each sphere (every vertex within a voxel and the
// protrusion of it), and its volume is the shell's, 4/3 pi (1 - 0.7^3), within 3%.
#include "MedialBallUnionTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkMassProperties.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialShapeSource.h"
#include "vtkPolyDataConnectivityFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialBallUnionHollow(int, char*[])
{
  vtkNew<vtkAppendPolyData> shells;
  for (double radius : { 1.0, 0.7 })
  {
    vtkNew<vtkMedialShapeSource> sphere;
    sphere->SetShapeToSphere();
    sphere->SetResolution(5);
    sphere->SetRadius(radius);
    sphere->Update();
    shells->AddInputData(sphere->GetOutput());
  }
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(shells->GetOutputPort());
  sampler->SetNumberOfSamples(30000);
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(96, 96, 96);
  ballUnion->Update();
  vtkPolyData* surface = ballUnion->GetOutput();
  const double h = ballUnion->GetVoxelSize();

  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputData(surface);
  regions->SetExtractionModeToAllRegions();
  regions->Update();
  vtkIdType outer = 0, inner = 0;
  double worst = 0.0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const bool onOuter = r > 0.85;
    (onOuter ? outer : inner)++;
    worst = std::max(worst, std::fabs(r - (onOuter ? 1.0 : 0.7)));
  }
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(surface);
  mass->Update();
  const double exact = 4.0 / 3.0 * 3.14159265358979323846 * (1.0 - 0.7 * 0.7 * 0.7);
  const double volumeError = std::fabs(mass->GetVolume() - exact) / exact;
  std::printf("hollow sphere: %d regions, %lld vertices on the outer sphere, %lld on the cavity, "
              "worst %.3g voxels off, volume %.4f (exact %.4f, error %.3f)\n",
    regions->GetNumberOfExtractedRegions(), static_cast<long long>(outer), static_cast<long long>(inner),
    worst / h, mass->GetVolume(), exact, volumeError);
  MEDIAL_CHECK(sampler->GetDiscardedSamples() == 0, "%lld discarded", static_cast<long long>(sampler->GetDiscardedSamples()));
  MEDIAL_CHECK(regions->GetNumberOfExtractedRegions() == 2 && outer > 1000 && inner > 500,
    "%d regions, %lld outer and %lld inner vertices", regions->GetNumberOfExtractedRegions(),
    static_cast<long long>(outer), static_cast<long long>(inner));
  MEDIAL_CHECK(OpenEdges(surface) == 0, "surface is not closed");
  MEDIAL_CHECK(worst <= 1.5 * h, "a vertex is %.3g voxels off its sphere", worst / h);
  MEDIAL_CHECK(volumeError <= 0.03, "volume off by %.3g", volumeError);
  return EXIT_SUCCESS;
}
