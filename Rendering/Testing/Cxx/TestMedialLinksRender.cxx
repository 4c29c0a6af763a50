// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene's 3D scene with the ClosestNeighbor links of
// spot.obj (from ../shared; skipped when absent), lines and points coloured by radius.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialScene.h"

#include "vtkOBJReader.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestMedialLinksRender(int argc, char* argv[])
{
  const std::string spot = medialtest::SharedMesh("spot.obj");
  if (spot.empty())
  {
    std::printf("shared meshes absent: skipped\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(spot.c_str());
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(reader->GetOutputPort());
  sampler->SetNumberOfSamples(4000);
  sampler->SetSeedFraction(0.1);
  sampler->SetSamplingStrategyToClosestNeighbor();
  sampler->SetRandomSeed(2);
  sampler->Update();
  vtkPolyData* links = sampler->GetOutput();
  std::printf("%lld medial points, %lld links\n", static_cast<long long>(links->GetNumberOfPoints()),
    static_cast<long long>(links->GetNumberOfLines()));
  if (links->GetNumberOfLines() < 1000)
  {
    std::printf("FAILED: too few links\n");
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(reader->GetOutput());
  scene->SetMedial(links);
  scene->ScalarBarVisibilityOff();
  scene->SetPointSize(3);
  scene->SetLineWidth(1.5);
  const double position[3] = { 2.5, 1.2, 3.0 }, focalPoint[3] = { 0, 0, 0 }, viewUp[3] = { 0, 1, 0 };
  scene->SetView(position, focalPoint, viewUp);
  scene->SetWindowSize(500, 400);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
