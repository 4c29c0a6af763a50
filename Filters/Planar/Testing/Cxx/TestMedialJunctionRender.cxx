// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the medial graph of an irregular polygon with a hole (arcs by
// ArcType, junctions red, end points green, junction disks as circles).
#include "MedialPolygonTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkGlyph3D.h"
#include "vtkLookupTable.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRegularPolygonSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

using namespace medialtest;

namespace
{
void AddNodes(vtkRenderer* renderer, vtkPolyData* graph, int type, double size, double r, double g, double b)
{
  vtkNew<vtkPoints> pts;
  for (const auto& n : NodesOfType(graph, type))
  {
    pts->InsertNextPoint(n.X);
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(size);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(cloud);
  glyphs->SetSourceConnection(ball->GetOutputPort());
  glyphs->ScalingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
}
}

int TestMedialJunctionRender(int argc, char* argv[])
{
  const Loop2 outer = { { 0, 0 }, { 6, -1 }, { 9, 2 }, { 7, 3 }, { 8, 6 }, { 4, 5 }, { 1, 7 }, { -1, 3 } };
  const Loop2 hole = { { 3, 2 }, { 5, 2.5 }, { 4, 3.5 } };
  auto polygon = MakePolygon({ outer, hole }, true);
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(polygon);
  junctions->Update();
  vtkPolyData* graph = junctions->GetOutput();

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputData(polygon);
  vtkNew<vtkActor> outline;
  outline->SetMapper(outlineMapper);
  outline->GetProperty()->SetColor(0.1, 0.1, 0.1);
  outline->GetProperty()->SetLineWidth(3);
  renderer->AddActor(outline);

  vtkNew<vtkLookupTable> arcColours;
  arcColours->SetNumberOfTableValues(2);
  arcColours->SetTableValue(0, 0.15, 0.35, 0.85);
  arcColours->SetTableValue(1, 0.95, 0.55, 0.1);
  arcColours->SetTableRange(0, 1);
  arcColours->Build();
  vtkNew<vtkPolyDataMapper> arcMapper;
  arcMapper->SetInputData(graph);
  arcMapper->SetScalarModeToUseCellFieldData();
  arcMapper->SelectColorArray("ArcType");
  arcMapper->SetLookupTable(arcColours);
  arcMapper->SetScalarRange(0, 1);
  vtkNew<vtkActor> arcs;
  arcs->SetMapper(arcMapper);
  arcs->GetProperty()->SetLineWidth(3);
  renderer->AddActor(arcs);

  for (const auto& j : NodesOfType(graph, vtkMedialJunctionFilter::JUNCTION_POINT))
  {
    vtkNew<vtkRegularPolygonSource> circle;
    circle->SetNumberOfSides(96);
    circle->GeneratePolygonOff();
    circle->SetRadius(j.Radius);
    circle->SetCenter(j.X[0], j.X[1], j.X[2]);
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(circle->GetOutputPort());
    vtkNew<vtkActor> a;
    a->SetMapper(m);
    a->GetProperty()->SetColor(0.6, 0.6, 0.65);
    renderer->AddActor(a);
  }
  AddNodes(renderer, graph, vtkMedialJunctionFilter::JUNCTION_POINT, 0.12, 0.85, 0.1, 0.1);
  AddNodes(renderer, graph, vtkMedialJunctionFilter::END_POINT, 0.09, 0.1, 0.65, 0.2);

  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.3);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(400, 360);
  window->AddRenderer(renderer);
  window->Render();
  return !vtkRegressionTestImage(window);
}
