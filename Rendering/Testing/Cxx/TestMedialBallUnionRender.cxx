// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene's reconstruction view, the demo shape (left, opaque)
// and the union of its medial balls (right), 6000 samples reconstructed on a 96^3 grid.
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestMedialBallUnionRender(int argc, char* argv[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(6000);
  sampler->SetRandomSeed(3);
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(96, 96, 96);
  ballUnion->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(jack->GetOutput());
  scene->SetSurfaceOpacity(1.0);
  scene->SetReconstruction(ballUnion->GetOutput());
  const double position[3] = { 3, 4, 7 }, focalPoint[3] = { 0, 0.3, 0 }, viewUp[3] = { 0, 1, 0 };
  scene->SetView(position, focalPoint, viewUp);
  scene->SetWindowSize(300, 300);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
