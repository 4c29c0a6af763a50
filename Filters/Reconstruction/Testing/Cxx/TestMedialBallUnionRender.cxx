// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the demo shape (left) and the union of its medial balls
// (right), 6000 samples reconstructed on a 96^3 grid.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

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
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(ballUnion->GetOutputPort());
  normals->SplittingOff();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(600, 300);
  vtkAlgorithm* sources[2] = { jack, normals };
  const double colours[2][3] = { { 0.80, 0.82, 0.86 }, { 0.90, 0.62, 0.40 } };
  for (int side = 0; side < 2; ++side)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sources[side]->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colours[side][0], colours[side][1], colours[side][2]);
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(0.5 * side, 0.0, 0.5 * side + 0.5, 1.0);
    renderer->SetBackground(1, 1, 1);
    renderer->AddActor(actor);
    renderer->GetActiveCamera()->SetPosition(3, 4, 7);
    renderer->GetActiveCamera()->SetFocalPoint(0, 0.3, 0);
    renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Zoom(1.1);
    window->AddRenderer(renderer);
  }
  window->Render();
  return !vtkRegressionTestImage(window);
}
