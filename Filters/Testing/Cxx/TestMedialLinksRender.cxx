// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the ClosestNeighbor links of spot.obj (from ../shared; skipped
// when absent) over the translucent surface, lines and points coloured by radius.
#include "MedialTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkMedialAxisSampler.h"
#include "vtkOBJReader.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestMedialLinksRender(int argc, char* argv[])
{
  const std::string spot = medialtest::SharedMesh("spot.obj");
  if (spot.empty())
  {
    std::printf("shared meshes absent: skipped\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(spot.c_str());
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(reader->GetOutputPort());
  sampler->SetNumberOfSamples(4000);
  sampler->SetSeedFraction(0.1);
  sampler->SetSamplingStrategyToClosestNeighbor();
  sampler->SetRandomSeed(2);
  sampler->Update();
  vtkPolyData* links = sampler->GetOutput();
  std::printf("%lld medial points, %lld links\n", static_cast<long long>(links->GetNumberOfPoints()),
    static_cast<long long>(links->GetNumberOfLines()));
  if (links->GetNumberOfLines() < 1000)
  {
    std::printf("FAILED: too few links\n");
    return EXIT_FAILURE;
  }
  double range[2];
  links->GetPointData()->GetArray("Radius")->GetRange(range);

  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputConnection(reader->GetOutputPort());
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
  medialMapper->SetInputData(links);
  medialMapper->SetLookupTable(lut);
  medialMapper->SetScalarRange(range);
  medialMapper->SetScalarModeToUsePointFieldData();
  medialMapper->SelectColorArray("Radius");
  vtkNew<vtkActor> medial;
  medial->SetMapper(medialMapper);
  medial->GetProperty()->SetPointSize(3);
  medial->GetProperty()->SetLineWidth(1.5);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(surface);
  renderer->AddActor(medial);
  renderer->GetActiveCamera()->SetPosition(2.5, 1.2, 3.0);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.15);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(500, 400);
  window->AddRenderer(renderer);
  window->Render();
  return !vtkRegressionTestImage(window);
}
