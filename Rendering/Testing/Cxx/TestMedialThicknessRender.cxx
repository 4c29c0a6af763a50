// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene with SurfaceScalars, the demo shape coloured by its
// wall thickness (vtkMedialThickness), with the scale: the thin arm blue, the ball red.
#include "vtkMedialArrayNames.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestMedialThicknessRender(int argc, char* argv[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputConnection(jack->GetOutputPort());
  thickness->ComputeCellThicknessOff();
  thickness->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(thickness->GetOutput());
  scene->SetSurfaceScalars(vtkMedialArrayNames::Thickness);
  const double position[3] = { 3, 4, 7 }, focalPoint[3] = { 0, 0.3, 0 }, viewUp[3] = { 0, 1, 0 };
  scene->SetView(position, focalPoint, viewUp);
  scene->SetWindowSize(400, 300);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
