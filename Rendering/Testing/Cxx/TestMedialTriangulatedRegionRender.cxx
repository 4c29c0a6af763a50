// SPDX-License-Identifier: BSD-3-Clause
// Image regression: a planar shape given as a triangulated region (a 4 x 4 square frame
// around a 2 x 2 hole, 24 triangles on shared points) is drawn by its outline: the 16
// outer and 8 inner boundary edges, none of the 36 inner triangle edges, under the
// medial graph. Before the outline came from vtkFeatureEdges every triangle was drawn.
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialOutline.h"
#include "vtkMedialScene.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

int TestMedialTriangulatedRegionRender(int argc, char* argv[])
{
  // Grid points (i, j), 0 <= i, j <= 4; the squares but the middle four, two triangles each.
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= 4; ++j)
  {
    for (int i = 0; i <= 4; ++i)
    {
      points->InsertNextPoint(i, j, 0.0);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      if (i >= 1 && i <= 2 && j >= 1 && j <= 2)
      {
        continue;
      }
      const vtkIdType a = 5 * j + i, b = a + 1, c = a + 6, d = a + 5;
      const vtkIdType lower[3] = { a, b, c }, upper[3] = { a, c, d };
      triangles->InsertNextCell(3, lower);
      triangles->InsertNextCell(3, upper);
    }
  }
  vtkNew<vtkPolyData> region;
  region->SetPoints(points);
  region->SetPolys(triangles);

  const vtkIdType edges = vtkMedialOutline::Boundary(region)->GetNumberOfLines();
  if (edges != 24)
  {
    std::cerr << "the frame's outline has " << edges << " edges, expected 16 outer + 8 inner\n";
    return 1;
  }

  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(region);
  junctions->Update();
  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(region);
  scene->SetGraph(junctions->GetOutput());
  scene->SetViewDirection(vtkMedialScene::VIEW_PLUS_Z); // a square: its principal axes are any
  scene->SetWindowSize(360, 360);
  vtkRenderWindow* window = scene->Render();
  return !vtkRegressionTestImage(window);
}
