// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the demo shape (translucent) and its medial points coloured by radius.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
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
  double range[2];
  sampler->GetOutput()->GetPointData()->GetArray("Radius")->GetRange(range);

  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputConnection(jack->GetOutputPort());
  surfaceMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> surface;
  surface->SetMapper(surfaceMapper);
  surface->GetProperty()->SetColor(0.8, 0.82, 0.86);
  surface->GetProperty()->SetOpacity(0.2);

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(range);
  lut->Build();
  vtkNew<vtkPolyDataMapper> medialMapper;
  medialMapper->SetInputConnection(sampler->GetOutputPort());
  medialMapper->SetLookupTable(lut);
  medialMapper->SetScalarRange(range);
  vtkNew<vtkActor> medial;
  medial->SetMapper(medialMapper);
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
