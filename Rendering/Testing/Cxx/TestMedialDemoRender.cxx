// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene's 3D scene, the demo shape (translucent) and its
// medial points coloured by radius.
#include "vtkMedialAxisSampler.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestMedialDemoRender(int argc, char* argv[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(6000);
  sampler->SetRandomSeed(3);
  sampler->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(jack->GetOutput());
  scene->SetMedial(sampler->GetOutput());
  scene->ScalarBarVisibilityOff();
  const double position[3] = { 3, 4, 7 }, focalPoint[3] = { 0, 0.3, 0 }, viewUp[3] = { 0, 1, 0 };
  scene->SetView(position, focalPoint, viewUp);
  scene->SetWindowSize(400, 300);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
