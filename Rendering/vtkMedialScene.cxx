// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialScene.h"
#include "vtkMedialPlane.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMessageRelay.h"
#include "vtkMedialOutline.h"

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
#include "vtkRendererCollection.h"
#include "vtkRenderingOpenGLConfigure.h" // VTK_USE_X
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSphereSource.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
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

// The balls with one vertex cell per point when they have none (a .ma file's
// centres), so that every centre is drawn.
vtkSmartPointer<vtkPolyData> WithVertices(vtkPolyData* balls)
{
  auto drawn = vtkSmartPointer<vtkPolyData>::New();
  drawn->ShallowCopy(balls);
  if (balls->GetNumberOfVerts() == 0 && balls->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkCellArray> verts;
    verts->AllocateExact(balls->GetNumberOfPoints(), balls->GetNumberOfPoints());
    for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
    {
      verts->InsertNextCell(1, &i);
    }
    drawn->SetVerts(verts);
  }
  return drawn;
}

// Calls visit(point) for every point of everything drawn.
template <class Visit>
void ForEachDrawnPoint(std::initializer_list<vtkPolyData*> data, Visit&& visit)
{
  for (vtkPolyData* pd : data)
  {
    for (vtkIdType i = 0; pd && i < pd->GetNumberOfPoints(); ++i)
    {
      double p[3];
      pd->GetPoint(i, p);
      visit(p);
    }
  }
}

// The index of the largest-magnitude component.
int MajorComponent(const double v[3])
{
  int major = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::abs(v[k]) > std::abs(v[major]))
    {
      major = k;
    }
  }
  return major;
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

const char* const ViewNames[] = { "auto", "+x", "-x", "+y", "-y", "+z", "-z", "iso" };

vtkMedialScene::vtkMedialScene() = default;

vtkMedialScene::~vtkMedialScene()
{
  this->SetSurface(nullptr);
  this->SetMedial(nullptr);
  this->SetGraph(nullptr);
  this->SetReconstruction(nullptr);
}

void vtkMedialScene::SetViewDirection(int direction)
{
  direction = std::min(std::max(direction, static_cast<int>(VIEW_AUTO)), static_cast<int>(VIEW_ISO));
  if (direction != this->ViewDirection || this->CustomView)
  {
    this->ViewDirection = direction;
    this->CustomView = false;
    this->Modified();
  }
}

const char* vtkMedialScene::GetViewDirectionName(int direction)
{
  return direction >= VIEW_AUTO && direction <= VIEW_ISO ? ViewNames[direction] : nullptr;
}

int vtkMedialScene::GetViewDirectionFromName(const char* name)
{
  for (int d = VIEW_AUTO; d <= VIEW_ISO; ++d)
  {
    if (name && std::string(name) == ViewNames[d])
    {
      return d;
    }
  }
  return -1;
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
// (high) over its range (MedialPointType: one named colour per 3D code); returns the
// renderer of the scale (nullptr without ScalarBarVisibility), to be given a strip of
// its own beside the model.
vtkSmartPointer<vtkRenderer> vtkMedialScene::ColourBy(vtkPolyDataMapper* mapper, vtkPolyData* data, const char* name)
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
  if (!this->ScalarBarVisibility)
  {
    return nullptr;
  }
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle(name);
  bar->SetNumberOfLabels(5);
  bar->SetPosition(0.1, 0.12); // in the strip's own viewport
  bar->SetWidth(0.8);
  bar->SetHeight(0.76);
  bar->SetBarRatio(0.3);
  this->LegendPixels = 120;
  if (lut->GetIndexedLookup())
  {
    // The names are drawn beside the bar, outside the actor's box, on the side opposite
    // the title: put the bar at the left of a wider strip so that they are not clipped.
    bar->SetTextPositionToPrecedeScalarBar();
    bar->SetPosition(0.02, 0.12);
    bar->SetWidth(0.55);
    this->LegendPixels = 170;
  }
  bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetAnnotationTextProperty()->SetColor(0.1, 0.1, 0.1);
  auto strip = vtkSmartPointer<vtkRenderer>::New();
  strip->SetBackground(1, 1, 1);
  strip->AddActor2D(bar);
  return strip;
}

// The translucent surface and the medial points (or mesh) coloured by radius or point
// type; or, with SurfaceScalars, the opaque surface coloured by that array. Returns the
// renderer of the scale (nullptr without one).
vtkSmartPointer<vtkRenderer> vtkMedialScene::AddBalls(vtkRenderer* renderer)
{
  if (this->Surface && !this->SurfaceScalars.empty())
  {
    vtkNew<vtkPolyDataNormals> normals; // smooth shading
    normals->SetInputData(this->Surface);
    normals->SplittingOff();
    normals->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    vtkSmartPointer<vtkRenderer> strip = this->ColourBy(mapper, normals->GetOutput(), this->SurfaceScalars.c_str());
    vtkNew<vtkActor> surface;
    surface->SetMapper(mapper);
    renderer->AddActor(surface);
    return strip;
  }
  if (this->Surface)
  {
    vtkSmartPointer<vtkActor> surface = ActorOf(this->Surface, 0.80, 0.82, 0.86);
    surface->GetProperty()->SetOpacity(this->SurfaceOpacity);
    renderer->AddActor(surface);
  }
  if (!this->Medial)
  {
    return nullptr;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(WithVertices(this->Medial));
  const bool byType = this->ColorBy == POINT_TYPE &&
    this->Medial->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  vtkSmartPointer<vtkRenderer> strip = this->ColourBy(
    mapper, this->Medial, byType ? vtkMedialArrayNames::MedialPointType : vtkMedialArrayNames::Radius);
  vtkNew<vtkActor> medial;
  medial->SetMapper(mapper);
  medial->GetProperty()->SetPointSize(this->PointSize);
  medial->GetProperty()->SetLineWidth(this->LineWidth);
  medial->GetProperty()->RenderPointsAsSpheresOn();
  renderer->AddActor(medial);
  return strip;
}

// The polygon's outline (black: its boundary edges, not a triangulated region's
// inner edges), the arcs (blue linear, orange parabolic), the maximal disks of
// the (up to) six largest junctions (grey circles), junctions (red), end points (green).
void vtkMedialScene::AddGraph(vtkRenderer* renderer, const double normal[3])
{
  vtkPolyData* graph = this->Graph;
  const double diagonal = this->Surface ? this->Surface->GetLength() : graph->GetLength();
  if (this->Surface)
  {
    vtkSmartPointer<vtkActor> outline = ActorOf(vtkMedialOutline::Boundary(this->Surface), 0.1, 0.1, 0.1);
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

// The reconstruction, seen through the camera of `left` (the input).
vtkSmartPointer<vtkRenderer> vtkMedialScene::AddReconstructionView(vtkRenderer* left)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(this->Reconstruction);
  normals->SplittingOff();
  normals->Update();
  auto right = vtkSmartPointer<vtkRenderer>::New();
  right->SetBackground(1, 1, 1);
  right->AddActor(ActorOf(normals->GetOutput(), 0.90, 0.62, 0.40));
  right->SetActiveCamera(left->GetActiveCamera());
  return right;
}

// The camera's frame: right across the picture, up, and toward the camera (see the
// class comment for how each view direction chooses them).
void vtkMedialScene::ViewAxes(double right[3], double up[3], double toward[3]) const
{
  const auto drawn = { this->Surface, this->Medial, this->Graph, this->Reconstruction };
  // Extent of everything drawn along a unit direction.
  auto extent = [&](const double d[3]) {
    double lo = VTK_DOUBLE_MAX, hi = -VTK_DOUBLE_MAX;
    ForEachDrawnPoint(drawn, [&](const double p[3]) {
      const double t = vtkMath::Dot(p, d);
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    });
    return hi >= lo ? hi - lo : 0.0;
  };
  const double worldAxes[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  double axes[3][3]; // candidates, sorted by decreasing extent below
  if (this->CustomView)
  {
    for (int k = 0; k < 3; ++k)
    {
      toward[k] = this->ViewPosition[k] - this->ViewFocalPoint[k];
      up[k] = this->ViewUp[k];
    }
    vtkMath::Normalize(toward);
    const double along = vtkMath::Dot(up, toward);
    for (int k = 0; k < 3; ++k)
    {
      up[k] -= along * toward[k];
    }
    vtkMath::Normalize(up);
    vtkMath::Cross(up, toward, right);
    return;
  }
  // The principal axes, or the world axes when each principal axis lies within 20
  // degrees of one.
  std::vector<double> xyz;
  ForEachDrawnPoint(drawn, [&](const double p[3]) { xyz.insert(xyz.end(), p, p + 3); });
  double centre[3], values[3], pca[3][3];
  vtkMedialPlane::FitPoints(static_cast<vtkIdType>(xyz.size() / 3),
    [&xyz](vtkIdType i, double p[3]) { std::copy_n(&xyz[3 * i], 3, p); }, centre, values, pca);
  bool aligned = true;
  for (int a = 0; a < 3; ++a)
  {
    const double column[3] = { pca[0][a], pca[1][a], pca[2][a] };
    std::copy_n(column, 3, axes[a]);
    aligned = aligned && std::abs(column[MajorComponent(column)]) > std::cos(vtkMath::RadiansFromDegrees(20.0));
  }
  if (aligned || xyz.size() < 9)
  {
    std::copy_n(&worldAxes[0][0], 9, &axes[0][0]);
  }
  int order[3] = { 0, 1, 2 };
  double extents[3] = { extent(axes[0]), extent(axes[1]), extent(axes[2]) };
  std::stable_sort(order, order + 3, [&](int a, int b) { return extents[a] > extents[b]; });
  const int direction = this->ViewDirection;
  if (direction >= VIEW_PLUS_X && direction <= VIEW_MINUS_Z)
  {
    // Look along a world axis; of the other two, the longer one runs across.
    const int look = (direction - VIEW_PLUS_X) / 2;
    const double sign = (direction - VIEW_PLUS_X) % 2 == 0 ? 1.0 : -1.0;
    const int a = (look + 1) % 3, b = (look + 2) % 3;
    const int vertical = extent(worldAxes[a]) >= extent(worldAxes[b]) ? b : a;
    for (int k = 0; k < 3; ++k)
    {
      toward[k] = -sign * worldAxes[look][k];
      up[k] = worldAxes[vertical][k];
    }
  }
  else
  {
    std::copy_n(axes[order[1]], 3, up);
    std::copy_n(axes[order[2]], 3, toward);
    vtkMedialPlane::CanonicalSign(up);
    vtkMedialPlane::CanonicalSign(toward);
    if (direction == VIEW_ISO)
    {
      // Up: the world axis nearest the automatic view's, made perpendicular to the view.
      const int major = MajorComponent(up);
      for (int k = 0; k < 3; ++k)
      {
        toward[k] = 1.0 / std::sqrt(3.0);
        up[k] = worldAxes[major][k] - toward[k] / std::sqrt(3.0);
      }
      vtkMath::Normalize(up);
    }
  }
  vtkMath::Cross(up, toward, right);
}

// Points the camera along the view axes, fits the projected extent of everything
// drawn into a view of `aspect` (width / height) less the margins, then zooms.
void vtkMedialScene::Frame(vtkRenderer* renderer, double aspect)
{
  double right[3], up[3], toward[3];
  this->ViewAxes(right, up, toward);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  ForEachDrawnPoint({ this->Surface, this->Medial, this->Graph, this->Reconstruction }, [&](const double p[3]) {
    const double t[3] = { vtkMath::Dot(p, right), vtkMath::Dot(p, up), vtkMath::Dot(p, toward) };
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], t[k]);
      hi[k] = std::max(hi[k], t[k]);
    }
  });
  double centre[3] = { 0, 0, 0 };
  double size[3];
  for (int k = 0; k < 3; ++k)
  {
    size[k] = hi[k] - lo[k];
    const double mid = 0.5 * (lo[k] + hi[k]);
    const double* axis = k == 0 ? right : (k == 1 ? up : toward);
    for (int c = 0; c < 3; ++c)
    {
      centre[c] += mid * axis[c];
    }
  }
  const double span = std::max({ size[0], size[1], size[2] }) > 0.0 ? std::max({ size[0], size[1], size[2] }) : 1.0;
  const double fill = 1.0 - 2.0 * this->Margin;
  // Half the visible height: the larger of what the height and the width need.
  double halfHeight = 0.5 * std::max(size[1], size[0] / aspect) / fill;
  if (!(halfHeight > 0.0))
  {
    halfHeight = 0.5 * span;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + span * toward[0], centre[1] + span * toward[1], centre[2] + span * toward[2]);
  camera->SetViewUp(up);
  camera->SetParallelScale(halfHeight / this->Zoom);
  renderer->ResetCameraClippingRange();
}

bool vtkMedialScene::NeedsDisplay()
{
#ifdef VTK_USE_X
  return true;
#else
  return false;
#endif
}

vtkRenderWindow* vtkMedialScene::Render()
{
  if (!this->Surface && !this->Medial && !this->Graph)
  {
    this->Window = nullptr;
    vtkErrorMacro("Nothing to draw: set a Surface, Medial balls or a Graph.");
    return nullptr;
  }
  const bool planar = this->Graph != nullptr;
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  vtkSmartPointer<vtkRenderer> bar;
  if (planar)
  {
    double normal[3];
    PlaneNormal(this->Surface ? this->Surface : this->Graph, normal);
    this->AddGraph(renderer, normal);
  }
  else
  {
    bar = this->AddBalls(renderer);
  }
  vtkSmartPointer<vtkRenderer> rebuilt = this->Reconstruction && !planar ? this->AddReconstructionView(renderer) : nullptr;

  // Layout: the view (and the reconstruction's, as wide), then the scale's strip.
  int size[2] = { this->WindowSize[0], this->WindowSize[1] };
  if (size[0] <= 0 || size[1] <= 0)
  {
    size[0] = (rebuilt ? 1800 : 900);
    size[1] = planar ? 700 : 640;
  }
  const double strip = bar ? std::min(0.4, this->LegendPixels / static_cast<double>(size[0])) : 0.0;
  const double viewWidth = (1.0 - strip) / (rebuilt ? 2.0 : 1.0);
  renderer->SetViewport(0.0, 0.0, viewWidth, 1.0);
  // One window per scene, emptied for each render: an X connection is not free.
  vtkSmartPointer<vtkRenderWindow> window = this->Window;
  if (!window)
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
  }
  while (window->GetRenderers()->GetNumberOfItems() > 0)
  {
    window->RemoveRenderer(window->GetRenderers()->GetFirstRenderer());
  }
  window->SetSize(size[0], size[1]);
  window->AddRenderer(renderer);
  if (rebuilt)
  {
    rebuilt->SetViewport(viewWidth, 0.0, 2.0 * viewWidth, 1.0);
    window->AddRenderer(rebuilt);
  }
  if (bar)
  {
    bar->SetViewport(1.0 - strip, 0.0, 1.0, 1.0);
    window->AddRenderer(bar);
  }
  this->Frame(renderer, viewWidth * size[0] / static_cast<double>(size[1]));
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
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "ViewDirection: " << GetViewDirectionName(this->ViewDirection) << "\n";
  os << indent << "CustomView: " << this->CustomView << "\n";
  os << indent << "ViewPosition: " << this->ViewPosition[0] << " " << this->ViewPosition[1] << " "
     << this->ViewPosition[2] << "\n";
  os << indent << "ViewFocalPoint: " << this->ViewFocalPoint[0] << " " << this->ViewFocalPoint[1] << " "
     << this->ViewFocalPoint[2] << "\n";
  os << indent << "ViewUp: " << this->ViewUp[0] << " " << this->ViewUp[1] << " " << this->ViewUp[2] << "\n";
  os << indent << "RenderWindow: " << this->Window.Get() << "\n";
}
