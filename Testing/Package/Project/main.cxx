#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cstdio>

int main()
{
  vtkNew<vtkMedialShapeSource> sphere; // a generated unit sphere; or a reader of your mesh
  sphere->SetShapeToSphere();
  sphere->SetResolution(4); // 5120 triangles

  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(sphere->GetOutputPort());
  sampler->SetNumberOfSamples(1000);
  sampler->Update();

  vtkPolyData* balls = sampler->GetOutput(); // centres, with Radius, SurfacePoint, ...
  vtkDataArray* radius = balls->GetPointData()->GetArray("Radius");
  if (!radius)
  {
    return 1; // the sampler failed and said why
  }
  double range[2];
  radius->GetRange(range);
  std::printf("%lld medial balls, radius %.3f to %.3f\n",
    static_cast<long long>(balls->GetNumberOfPoints()), range[0], range[1]);
  // Every ball lies inside the unit sphere.
  return balls->GetNumberOfPoints() == 1000 && range[1] <= 1.0 ? 0 : 1;
}
