// SPDX-License-Identifier: BSD-3-Clause
// Image regression: the ClosestNeighbor links of spot.obj (from ../shared; skipped
// when absent) over the translucent surface, lines and points coloured by radius.
#include "MedialRenderTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMedialAxisSampler.h"
#include "vtkOBJReader.h"
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
  vtkSmartPointer<vtkActor> surface = medialtest::TranslucentSurface(reader->GetOutputPort());
  vtkSmartPointer<vtkActor> medial = medialtest::RadiusColoured(links);
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
