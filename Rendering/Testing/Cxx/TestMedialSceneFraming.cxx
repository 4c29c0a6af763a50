// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialScene frames any model, checked from the pictures themselves: a tall
// Z-up capsule (and its medial balls) in every view direction, its reconstruction
// beside it, and a 2D graph. Three renders of each scene: the picture; the model
// alone (the scale's actors hidden); the scale alone (the model's hidden). Model
// pixels are the non-white pixels of the second, the scale's box the bounding box
// of the non-white pixels of the third. Checks: no model pixel on the picture's
// border; the scale's box holds no model pixel; the model fills at least 60% of
// the view's width or height (framed, not lost); in the automatic view the
// longest extent (z) runs across the picture. A zoom of 3 must touch the border
// (the check can fail).
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"

#include "vtkActor2D.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace
{
struct Box
{
  int X0 = 1 << 30, Y0 = 1 << 30, X1 = -1, Y1 = -1;
  bool Empty() const { return X1 < X0; }
  bool Contains(int x, int y) const { return x >= X0 && x <= X1 && y >= Y0 && y <= Y1; }
};

// The rendered picture with only some props visible: `keep(prop, isScaleProp)`.
template <class Keep>
vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window, Keep&& keep)
{
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* r = renderers->GetNextItem())
  {
    vtkPropCollection* props = r->GetViewProps();
    props->InitTraversal();
    while (vtkProp* p = props->GetNextProp())
    {
      p->SetVisibility(keep(p, vtkActor2D::SafeDownCast(p) != nullptr) ? 1 : 0);
    }
  }
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

// Bounding box of the non-white pixels; `border` counts those on the outermost rows and columns.
Box NonWhite(vtkImageData* image, int& border)
{
  int dims[3];
  image->GetDimensions(dims);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const int nc = rgb->GetNumberOfComponents();
  Box box;
  border = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const unsigned char* p = rgb->GetPointer(static_cast<vtkIdType>(nc) * (y * dims[0] + x));
      if (p[0] == 255 && p[1] == 255 && p[2] == 255)
      {
        continue;
      }
      box.X0 = std::min(box.X0, x);
      box.X1 = std::max(box.X1, x);
      box.Y0 = std::min(box.Y0, y);
      box.Y1 = std::max(box.Y1, y);
      border += (x == 0 || y == 0 || x == dims[0] - 1 || y == dims[1] - 1) ? 1 : 0;
    }
  }
  return box;
}

// Model pixels inside `box`.
int PixelsInside(vtkImageData* image, const Box& box)
{
  int dims[3];
  image->GetDimensions(dims);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const int nc = rgb->GetNumberOfComponents();
  int count = 0;
  for (int y = std::max(0, box.Y0); y <= std::min(dims[1] - 1, box.Y1); ++y)
  {
    for (int x = std::max(0, box.X0); x <= std::min(dims[0] - 1, box.X1); ++x)
    {
      const unsigned char* p = rgb->GetPointer(static_cast<vtkIdType>(nc) * (y * dims[0] + x));
      count += (p[0] != 255 || p[1] != 255 || p[2] != 255) ? 1 : 0;
    }
  }
  return count;
}

struct Framing
{
  Box Model, Scale;
  int BorderPixels = 0;
  int Overlap = 0;
  int Width = 0, Height = 0;
};

Framing Measure(vtkMedialScene* scene)
{
  Framing f;
  vtkRenderWindow* window = scene->Render();
  f.Width = window->GetSize()[0];
  f.Height = window->GetSize()[1];
  vtkSmartPointer<vtkImageData> model = Grab(window, [](vtkProp*, bool scale) { return !scale; });
  vtkSmartPointer<vtkImageData> scale = Grab(window, [](vtkProp*, bool isScale) { return isScale; });
  int ignored = 0;
  f.Model = NonWhite(model, f.BorderPixels);
  f.Scale = NonWhite(scale, ignored);
  f.Overlap = f.Scale.Empty() ? 0 : PixelsInside(model, f.Scale);
  return f;
}

void Print(const char* what, const Framing& f)
{
  std::printf("%-26s model x %4d..%4d y %4d..%4d, scale x %4d..%4d y %4d..%4d, border pixels %d, "
              "model pixels under the scale %d\n",
    what, f.Model.X0, f.Model.X1, f.Model.Y0, f.Model.Y1, f.Scale.X0, f.Scale.X1, f.Scale.Y0, f.Scale.Y1,
    f.BorderPixels, f.Overlap);
}

// A tall Z-up model: a capsule along z, 1.5 times wider in x than in y.
vtkSmartPointer<vtkPolyData> TallModel()
{
  vtkNew<vtkMedialShapeSource> capsule;
  capsule->SetShapeToCapsule();
  capsule->SetLength(8.0); // 10 tall, 3 by 2 across
  vtkNew<vtkTransform> stretch;
  stretch->Translate(10, -5, 100);
  stretch->Scale(1.5, 1.0, 1.0);
  vtkNew<vtkTransformPolyDataFilter> transform;
  transform->SetInputConnection(capsule->GetOutputPort());
  transform->SetTransform(stretch);
  transform->Update();
  return transform->GetOutput();
}
}

int TestMedialSceneFraming(int, char*[])
{
  std::setvbuf(stdout, nullptr, _IONBF, 0); // lines reach the log even if rendering aborts
  vtkSmartPointer<vtkPolyData> tall = TallModel();
  double bounds[6];
  tall->GetBounds(bounds);
  MEDIAL_CHECK(bounds[5] - bounds[4] > 2.0 * (bounds[1] - bounds[0]), "the model is not tall");
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(tall);
  sampler->SetNumberOfSamples(4000);
  sampler->Update();

  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(tall);
  scene->SetMedial(sampler->GetOutput());
  scene->SetWindowSize(600, 400);
  for (int view = vtkMedialScene::VIEW_AUTO; view <= vtkMedialScene::VIEW_ISO; ++view)
  {
    scene->SetViewDirection(view);
    const Framing f = Measure(scene);
    const std::string what = std::string("view ") + vtkMedialScene::GetViewDirectionName(view);
    Print(what.c_str(), f);
    const int viewWidth = f.Width - 120;
    MEDIAL_CHECK(!f.Model.Empty() && f.BorderPixels == 0, "%s: the model touches the border", what.c_str());
    MEDIAL_CHECK(!f.Scale.Empty() && f.Overlap == 0, "%s: the scale covers the model", what.c_str());
    MEDIAL_CHECK(f.Model.X1 - f.Model.X0 >= 0.6 * viewWidth || f.Model.Y1 - f.Model.Y0 >= 0.6 * f.Height,
      "%s: the model is not framed tightly", what.c_str());
    if (view == vtkMedialScene::VIEW_AUTO)
    {
      MEDIAL_CHECK(f.Model.X1 - f.Model.X0 > 2 * (f.Model.Y1 - f.Model.Y0),
        "auto: the longest extent does not run across the picture");
    }
  }

  // Zoomed in, the model leaves the picture: the border check sees it.
  scene->SetViewDirection(vtkMedialScene::VIEW_AUTO);
  scene->SetZoom(3.0);
  const Framing zoomed = Measure(scene);
  Print("zoom 3", zoomed);
  MEDIAL_CHECK(zoomed.BorderPixels > 0, "a zoom of 3 still fits: the border check cannot fail");
  scene->SetZoom(1.0);

  // With the reconstruction beside the input.
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(48, 48, 48);
  ballUnion->Update();
  scene->SetReconstruction(ballUnion->GetOutput());
  scene->SetWindowSize(900, 400);
  const Framing both = Measure(scene);
  Print("with reconstruction", both);
  MEDIAL_CHECK(both.BorderPixels == 0 && both.Overlap == 0, "reconstruction view: border or scale overlap");
  MEDIAL_CHECK(both.Model.X1 > 0.5 * (both.Width - 120), "the reconstruction is not drawn on the right");
  scene->SetReconstruction(nullptr);

  // The 2D graph of a star, which has no scale.
  vtkNew<vtkMedialShapeSource> star;
  star->SetShapeToStar();
  star->SetResolution(7);
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputConnection(star->GetOutputPort());
  junctions->Update();
  vtkNew<vtkMedialScene> planar;
  planar->SetSurface(star->GetOutput());
  planar->SetGraph(junctions->GetOutput());
  planar->SetWindowSize(500, 300);
  const Framing graph = Measure(planar);
  Print("2D graph", graph);
  MEDIAL_CHECK(!graph.Model.Empty() && graph.BorderPixels == 0 && graph.Scale.Empty(), "2D graph framing");
  MEDIAL_CHECK(graph.Model.Y1 - graph.Model.Y0 >= 0.6 * graph.Height, "2D graph: not framed tightly");
  return EXIT_SUCCESS;
}
