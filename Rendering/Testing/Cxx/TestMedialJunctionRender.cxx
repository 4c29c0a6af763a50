// SPDX-License-Identifier: BSD-3-Clause
// Image regression: vtkMedialScene's 2D scene, the medial graph of an irregular polygon
// with a hole (arcs by ArcType, junctions red, end points green, junction disks as
// circles).
#include "MedialPolygonTestUtilities.h"

#include "vtkMedialJunctionFilter.h"
#include "vtkMedialScene.h"

#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

using namespace medialtest;

int TestMedialJunctionRender(int argc, char* argv[])
{
  const Loop2 outer = { { 0, 0 }, { 6, -1 }, { 9, 2 }, { 7, 3 }, { 8, 6 }, { 4, 5 }, { 1, 7 }, { -1, 3 } };
  const Loop2 hole = { { 3, 2 }, { 5, 2.5 }, { 4, 3.5 } };
  auto polygon = MakePolygon({ outer, hole }, true);
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(polygon);
  junctions->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(polygon);
  scene->SetGraph(junctions->GetOutput());
  scene->SetWindowSize(400, 360);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
