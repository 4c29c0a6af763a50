// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene coloured by MedialPointType, the demo shape's medial
// mesh with its legend. The legend names the four codes (rim, sheet, seam, junction)
// beside the bar; the baseline fails if they are clipped by the strip, as they were when
// the names were drawn on the left of a bar at the strip's left edge.
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestMedialPointTypeRender(int argc, char* argv[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(3000);
  sampler->SetRandomSeed(1);
  sampler->SetNumberOfThreads(1);
  vtkNew<vtkMedialMeshFilter> mesh;
  mesh->SetInputConnection(0, jack->GetOutputPort());
  mesh->SetInputConnection(1, sampler->GetOutputPort());
  mesh->SetNumberOfThreads(1);
  mesh->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(jack->GetOutput());
  scene->SetMedial(mesh->GetOutput());
  scene->SetColorByToPointType();
  const double position[3] = { 3, 4, 7 }, focalPoint[3] = { 0, 0.3, 0 }, viewUp[3] = { 0, 1, 0 };
  scene->SetView(position, focalPoint, viewUp);
  scene->SetWindowSize(500, 320);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
