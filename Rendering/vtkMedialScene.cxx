// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialScene.h"
#include "vtkMedialPlane.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMessageRelay.h"

#include "vtkActor.h"
#include "vtkAutoInit.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkGlyph3D.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRegularPolygonSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

// The OpenGL render window and the scalar bar's text need their factories, whoever
// links this library (a program, a test, Python).
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);

vtkStandardNewMacro(vtkMedialScene);
vtkCxxSetObjectMacro(vtkMedialScene, Surface, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialScene, Medial, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialScene, Graph, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialScene, Reconstruction, vtkPolyData);

namespace
{
vtkSmartPointer<vtkActor> ActorOf(vtkPolyData* data, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

// The loops of polygon cells and polylines as closed polylines.
vtkSmartPointer<vtkPolyData> Outline(vtkPolyData* shape)
{
  vtkNew<vtkCellArray> edges;
  for (vtkCellArray* cells : { shape->GetPolys(), shape->GetLines() })
  {
    vtkIdType npts;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
    {
      std::vector<vtkIdType> loop(ids, ids + npts);
      if (cells == shape->GetPolys())
      {
        loop.push_back(ids[0]);
      }
      edges->InsertNextCell(static_cast<vtkIdType>(loop.size()), loop.data());
    }
  }
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  outline->SetPoints(shape->GetPoints());
  outline->SetLines(edges);
  return outline;
}

// The points of the graph with one MedialPointType, as spheres of radius `size`.
vtkSmartPointer<vtkActor> NodeActor(vtkPolyData* graph, int type, double size, const double rgb[3])
{
  vtkNew<vtkPoints> pts;
  vtkDataArray* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  for (vtkIdType i = 0; types && i < graph->GetNumberOfPoints(); ++i)
  {
    if (static_cast<int>(types->GetTuple1(i)) == type)
    {
      pts->InsertNextPoint(graph->GetPoint(i));
    }
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(size);
  ball->SetThetaResolution(16);
  ball->SetPhiResolution(12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(cloud);
  glyphs->SetSourceConnection(ball->GetOutputPort());
  glyphs->ScalingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

// Unit normal of the points' least-squares plane, its largest component positive.
void PlaneNormal(vtkPolyData* shape, double normal[3])
{
  normal[0] = normal[1] = 0.0;
  normal[2] = 1.0;
  if (!shape || shape->GetNumberOfPoints() < 3)
  {
    return;
  }
  double centre[3], values[3], axes[3][3];
  vtkMedialPlane::FitPoints(
    shape->GetNumberOfPoints(), [shape](vtkIdType i, double p[3]) { shape->GetPoint(i, p); }, centre, values, axes);
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = axes[k][2];
  }
  vtkMath::Normalize(normal);
  vtkMedialPlane::CanonicalSign(normal);
}
}

vtkMedialScene::vtkMedialScene() = default;

vtkMedialScene::~vtkMedialScene()
{
  this->SetSurface(nullptr);
  this->SetMedial(nullptr);
  this->SetGraph(nullptr);
  this->SetReconstruction(nullptr);
}

void vtkMedialScene::SetView(const double position[3], const double focalPoint[3], const double viewUp[3])
{
  std::copy(position, position + 3, this->ViewPosition);
  std::copy(focalPoint, focalPoint + 3, this->ViewFocalPoint);
  std::copy(viewUp, viewUp + 3, this->ViewUp);
  this->CustomView = true;
  this->Modified();
}

vtkRenderWindow* vtkMedialScene::GetRenderWindow()
{
  return this->Window;
}

namespace
{
// MedialPointType's four 3D codes through an indexed table whose annotations name them
// in the legend.
void PointTypeTable(vtkLookupTable* lut, double range[2])
{
  const double colours[4][3] = { { 0.20, 0.45, 0.85 }, { 0.78, 0.78, 0.75 }, { 0.95, 0.55, 0.10 },
    { 0.85, 0.10, 0.10 } };
  const char* names[4] = { "rim", "sheet", "seam", "junction" };
  lut->SetNumberOfTableValues(4);
  lut->SetTableRange(0, 3);
  for (int t = 0; t < 4; ++t)
  {
    lut->SetTableValue(t, colours[t][0], colours[t][1], colours[t][2]);
    lut->SetAnnotation(t, names[t]);
  }
  lut->IndexedLookupOn();
  range[0] = 0;
  range[1] = 3;
}
}

// Colours what `mapper` draws by the point array `name` of `data`, blue (low) to red
// (high) over its range (MedialPointType: one named colour per 3D code), and adds the
// scale (with ScalarBarVisibility).
void vtkMedialScene::ColourBy(vtkPolyDataMapper* mapper, vtkPolyData* data, const char* name, vtkRenderer* renderer)
{
  double range[2] = { 0.0, 1.0 };
  vtkDataArray* values = data->GetPointData()->GetArray(name);
  if (values && values->GetNumberOfTuples() > 0)
  {
    values->GetRange(range);
  }
  vtkNew<vtkLookupTable> lut;
  if (std::string(name) == vtkMedialArrayNames::MedialPointType)
  {
    PointTypeTable(lut, range);
  }
  else
  {
    lut->SetHueRange(0.667, 0.0); // blue (thin) to red (thick)
    lut->SetTableRange(range);
    lut->Build();
  }
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(name);
  mapper->SetScalarRange(range);
  mapper->ScalarVisibilityOn();
  if (this->ScalarBarVisibility)
  {
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetTitle(name);
    bar->SetNumberOfLabels(5);
    bar->SetWidth(0.09);
    bar->SetHeight(0.6);
    bar->SetPosition(0.89, 0.2);
    bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
    bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    renderer->AddActor2D(bar);
  }
}

// The translucent surface, the medial points (or mesh) coloured by radius or point type
// and the scale; or,
// with SurfaceScalars, the opaque surface coloured by that array and its scale.
void vtkMedialScene::AddBalls(vtkRenderer* renderer)
{
  if (this->Surface && !this->SurfaceScalars.empty())
  {
    vtkNew<vtkPolyDataNormals> normals; // smooth shading
    normals->SetInputData(this->Surface);
    normals->SplittingOff();
    normals->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    this->ColourBy(mapper, normals->GetOutput(), this->SurfaceScalars.c_str(), renderer);
    vtkNew<vtkActor> surface;
    surface->SetMapper(mapper);
    renderer->AddActor(surface);
    return;
  }
  if (this->Surface)
  {
    vtkSmartPointer<vtkActor> surface = ActorOf(this->Surface, 0.80, 0.82, 0.86);
    surface->GetProperty()->SetOpacity(this->SurfaceOpacity);
    renderer->AddActor(surface);
  }
  if (!this->Medial)
  {
    return;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(this->Medial);
  const bool byType = this->ColorBy == POINT_TYPE &&
    this->Medial->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  this->ColourBy(mapper, this->Medial,
    byType ? vtkMedialArrayNames::MedialPointType : vtkMedialArrayNames::Radius, renderer);
  vtkNew<vtkActor> medial;
  medial->SetMapper(mapper);
  medial->GetProperty()->SetPointSize(this->PointSize);
  medial->GetProperty()->SetLineWidth(this->LineWidth);
  medial->GetProperty()->RenderPointsAsSpheresOn();
  renderer->AddActor(medial);
}

// The polygon (black), the arcs (blue linear, orange parabolic), the maximal disks of
// the (up to) six largest junctions (grey circles), junctions (red), end points (green).
void vtkMedialScene::AddGraph(vtkRenderer* renderer, const double normal[3])
{
  vtkPolyData* graph = this->Graph;
  const double diagonal = this->Surface ? this->Surface->GetLength() : graph->GetLength();
  if (this->Surface)
  {
    vtkSmartPointer<vtkActor> outline = ActorOf(Outline(this->Surface), 0.1, 0.1, 0.1);
    outline->GetProperty()->SetLineWidth(3);
    renderer->AddActor(outline);
  }

  vtkNew<vtkLookupTable> arcColours;
  arcColours->SetNumberOfTableValues(2);
  arcColours->SetTableValue(0, 0.15, 0.35, 0.85);
  arcColours->SetTableValue(1, 0.95, 0.55, 0.1);
  arcColours->SetTableRange(0, 1);
  arcColours->Build();
  vtkNew<vtkPolyDataMapper> arcMapper;
  arcMapper->SetInputData(graph);
  arcMapper->SetScalarModeToUseCellFieldData();
  arcMapper->SelectColorArray(vtkMedialArrayNames::ArcType);
  arcMapper->SetLookupTable(arcColours);
  arcMapper->SetScalarRange(0, 1);
  arcMapper->ScalarVisibilityOn();
  vtkNew<vtkActor> arcs;
  arcs->SetMapper(arcMapper);
  arcs->GetProperty()->SetLineWidth(3);
  renderer->AddActor(arcs);

  std::vector<std::pair<double, vtkIdType>> junctions; // (-radius, point), largest first
  vtkDataArray* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  vtkDataArray* radius = graph->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  for (vtkIdType i = 0; types && radius && i < graph->GetNumberOfPoints(); ++i)
  {
    if (static_cast<int>(types->GetTuple1(i)) == vtkMedialJunctionFilter::JUNCTION_POINT)
    {
      junctions.emplace_back(-radius->GetTuple1(i), i);
    }
  }
  std::sort(junctions.begin(), junctions.end());
  for (size_t k = 0; k < junctions.size() && k < 6; ++k)
  {
    vtkNew<vtkRegularPolygonSource> circle;
    circle->SetNumberOfSides(96);
    circle->GeneratePolygonOff();
    circle->SetRadius(-junctions[k].first);
    circle->SetCenter(graph->GetPoint(junctions[k].second));
    circle->SetNormal(normal[0], normal[1], normal[2]);
    circle->Update();
    vtkSmartPointer<vtkActor> disk = ActorOf(circle->GetOutput(), 0.55, 0.55, 0.6);
    disk->GetProperty()->SetLineWidth(1.5);
    renderer->AddActor(disk);
  }
  const double red[3] = { 0.85, 0.1, 0.1 }, green[3] = { 0.1, 0.65, 0.2 };
  renderer->AddActor(NodeActor(graph, vtkMedialJunctionFilter::JUNCTION_POINT, 0.012 * diagonal, red));
  renderer->AddActor(NodeActor(graph, vtkMedialJunctionFilter::END_POINT, 0.009 * diagonal, green));
}

// The input on the left, the reconstruction on the right through the same camera.
void vtkMedialScene::AddReconstructionView(vtkRenderWindow* window, vtkRenderer* left)
{
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(this->Reconstruction);
  normals->SplittingOff();
  normals->Update();
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(1, 1, 1);
  right->AddActor(ActorOf(normals->GetOutput(), 0.90, 0.62, 0.40));
  right->SetActiveCamera(left->GetActiveCamera());
  window->AddRenderer(right);
  int* size = window->GetSize();
  window->SetSize(2 * size[0], size[1]);
}

// 3D: from 30 degrees azimuth and 20 elevation; 2D: straight at the plane; or the
// chosen view. Then framed and zoomed.
void vtkMedialScene::Frame(vtkRenderer* renderer, const double normal[3])
{
  vtkCamera* camera = renderer->GetActiveCamera();
  if (this->CustomView)
  {
    camera->SetPosition(this->ViewPosition);
    camera->SetFocalPoint(this->ViewFocalPoint);
    camera->SetViewUp(this->ViewUp);
  }
  else if (this->Graph)
  {
    double bounds[6], centre[3];
    (this->Surface ? this->Surface : this->Graph)->GetBounds(bounds);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    }
    camera->SetFocalPoint(centre);
    camera->SetPosition(centre[0] + normal[0], centre[1] + normal[1], centre[2] + normal[2]);
    const bool flat = std::abs(normal[1]) > 0.9;
    camera->SetViewUp(flat ? 1.0 : 0.0, flat ? 0.0 : 1.0, 0.0);
  }
  else
  {
    renderer->ResetCamera();
    camera->Azimuth(30);
    camera->Elevation(20);
  }
  renderer->ResetCamera();
  camera->Zoom(this->Zoom > 0.0 ? this->Zoom : (this->Graph ? 1.3 : 1.6));
}

vtkRenderWindow* vtkMedialScene::Render()
{
  this->Window = nullptr;
  if (!this->Surface && !this->Medial && !this->Graph)
  {
    vtkErrorMacro("Nothing to draw: set a Surface, Medial balls or a Graph.");
    return nullptr;
  }
  const bool planar = this->Graph != nullptr;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  double normal[3] = { 0.0, 0.0, 1.0 };
  if (planar)
  {
    PlaneNormal(this->Surface ? this->Surface : this->Graph, normal);
    this->AddGraph(renderer, normal);
  }
  else
  {
    this->AddBalls(renderer);
  }
  this->Frame(renderer, normal); // before the window: framed as a square view
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  if (this->WindowSize[0] > 0 && this->WindowSize[1] > 0)
  {
    window->SetSize(this->WindowSize[0], this->WindowSize[1]);
  }
  else
  {
    window->SetSize(900, planar ? 700 : 640);
  }
  window->AddRenderer(renderer);
  if (this->Reconstruction && !planar)
  {
    this->AddReconstructionView(window, renderer);
  }
  window->Render();
  this->Window = window;
  return window;
}

int vtkMedialScene::WritePNG(const char* fileName)
{
  vtkRenderWindow* window = this->Render();
  if (!window)
  {
    return 0;
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  vtkNew<vtkMedialMessageRelay> relay; // the writer's errors are this scene's
  relay->Outer = this;
  relay->Relay(png);
  relay->Mute(png->GetExecutive());
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(fileName);
  png->Write();
  return relay->Errors == 0 && png->GetErrorCode() == 0 ? 1 : 0;
}

void vtkMedialScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Surface: " << this->Surface << "\n";
  os << indent << "Medial: " << this->Medial << "\n";
  os << indent << "Graph: " << this->Graph << "\n";
  os << indent << "Reconstruction: " << this->Reconstruction << "\n";
  os << indent << "SurfaceOpacity: " << this->SurfaceOpacity << "\n";
  os << indent << "SurfaceScalars: " << this->SurfaceScalars << "\n";
  os << indent << "PointSize: " << this->PointSize << "\n";
  os << indent << "LineWidth: " << this->LineWidth << "\n";
  os << indent << "ScalarBarVisibility: " << this->ScalarBarVisibility << "\n";
  os << indent << "ColorBy: " << (this->ColorBy == POINT_TYPE ? "PointType" : "Radius") << "\n";
  os << indent << "WindowSize: " << this->WindowSize[0] << " " << this->WindowSize[1] << "\n";
  os << indent << "Zoom: " << this->Zoom << "\n";
  os << indent << "CustomView: " << this->CustomView << "\n";
  os << indent << "ViewPosition: " << this->ViewPosition[0] << " " << this->ViewPosition[1] << " "
     << this->ViewPosition[2] << "\n";
  os << indent << "ViewFocalPoint: " << this->ViewFocalPoint[0] << " " << this->ViewFocalPoint[1] << " "
     << this->ViewFocalPoint[2] << "\n";
  os << indent << "ViewUp: " << this->ViewUp[0] << " " << this->ViewUp[1] << " " << this->ViewUp[2] << "\n";
  os << indent << "RenderWindow: " << this->Window.Get() << "\n";
}
