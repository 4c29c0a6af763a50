// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the demo shape (translucent) and its medial points coloured by radius.
#include "MedialRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestMedialDemoRender(int argc, char* argv[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(6000);
  sampler->SetRandomSeed(3);
  sampler->Update();
  vtkSmartPointer<vtkActor> surface = medialtest::TranslucentSurface(jack->GetOutputPort());
  vtkSmartPointer<vtkActor> medial = medialtest::RadiusColoured(sampler->GetOutput());
  medial->GetProperty()->SetPointSize(4);
  medial->GetProperty()->RenderPointsAsSpheresOn();

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(surface);
  renderer->AddActor(medial);
  renderer->GetActiveCamera()->SetPosition(3, 4, 7);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0.3, 0);
  renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.7);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  window->Render();
  return !vtkRegressionTestImage(window);
}
