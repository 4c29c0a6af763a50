// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialAxisSampler::IsPlanarInput, the one public answer to "2D or 3D?" (the CLI
// asks it too): planar polygons in a tilted plane (with that plane), closed or
// chainable polylines are 2D; a closed surface, collinear polygons, a single open
// polyline, a mixture of lines and polygons, strips and NaN coordinates are not. The
// sampler takes the mode it announces. In 2D, ONE_PASS and SHRINKING_BALL are one
// method (documented): their outputs are bit-identical.
#include "MedialSampler2DTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdio>
#include <cstdlib>
#include <limits>

using namespace medialtest;

int TestMedialSamplerPlanarity(int, char*[])
{
  // A frame with a hole, rotated into a tilted plane: its normal is R (0, 0, 1).
  vtkNew<vtkTransform> tilt;
  auto tiltedFrame = TiltedFrame(tilt);
  double expectedNormal[3] = { 0, 0, 1 };
  tilt->TransformNormal(expectedNormal, expectedNormal);
  double centre[3], normal[3];
  MEDIAL_CHECK(vtkMedialAxisSampler::IsPlanarInput(tiltedFrame, centre, normal), "tilted frame not planar");
  const double alignment = std::fabs(vtkMath::Dot(normal, expectedNormal));
  MEDIAL_CHECK(alignment > 1.0 - 1e-12, "tilted frame: normal off by %.3g", 1.0 - alignment);
  double onPlane[3];
  tiltedFrame->GetPoint(0, onPlane);
  const double offset = (onPlane[0] - centre[0]) * normal[0] + (onPlane[1] - centre[1]) * normal[1] +
    (onPlane[2] - centre[2]) * normal[2];
  MEDIAL_CHECK(std::fabs(offset) < 1e-12, "tilted frame: centre %.3g off the plane", offset);

  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->Update();
  auto collinear = MakePolygon({ { { 0, 0 }, { 1, 0 }, { 2, 0 } } });
  auto mixed = MakePolygon({ Rectangle(0, 0, 1, 1) });
  mixed->SetLines(MakePolylines({ { { 0, 0, 0 }, { 1, 1, 0 } } })->GetLines());
  auto nan = MakePolygon({ Rectangle(0, 0, 1, 1) });
  nan->GetPoints()->SetPoint(2, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  vtkNew<vtkCellArray> strip;
  const vtkIdType stripIds[4] = { 0, 1, 3, 2 };
  strip->InsertNextCell(4, stripIds);
  auto withStrip = MakePolygon({ Rectangle(0, 0, 1, 1) });
  withStrip->SetPolys(nullptr);
  withStrip->SetStrips(strip);
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    bool Planar;
  };
  const Case cases[] = {
    { "tilted frame", tiltedFrame, true },
    { "closed polyline", MakePolygon({ Rectangle(0, 0, 2, 1) }, true), true },
    { "three open pieces", MakePolylines({ { { 0, 0, 0 }, { 1, 0, 0 } }, { { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 0 }, { 0, 0, 0 } } }),
      true },
    { "box surface", box->GetOutput(), false },
    { "collinear polygon", collinear, false },
    { "one open polyline", MakePolylines({ { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 1 } } }), false },
    { "lines and polygons", mixed, false },
    { "triangle strip", withStrip, false },
    { "NaN coordinate", nan, false },
  };
  for (const Case& c : cases)
  {
    const bool planar = vtkMedialAxisSampler::IsPlanarInput(c.Input);
    std::printf("%-20s %s\n", c.Name, planar ? "2D" : "not 2D");
    MEDIAL_CHECK(planar == c.Planar, "%s: IsPlanarInput says %d", c.Name, planar);
    if (c.Name == std::string("box surface") || c.Planar)
    {
      // The sampler takes the announced mode: triangles are counted in 3D only.
      vtkNew<vtkMedialAxisSampler> sampler;
      sampler->SetInputData(c.Input);
      sampler->SetNumberOfSamples(50);
      sampler->Update();
      MEDIAL_CHECK(sampler->GetOutput()->GetNumberOfPoints() > 0 && (sampler->GetNumberOfTriangles() == 0) == c.Planar,
        "%s: sampled in the other mode", c.Name);
    }
  }

  // 2D: ONE_PASS is the shrinking ball, bit for bit.
  vtkSmartPointer<vtkPolyData> runs[2];
  const int methods[2] = { vtkMedialAxisSampler::ONE_PASS, vtkMedialAxisSampler::SHRINKING_BALL };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputData(tiltedFrame);
    sampler->SetNumberOfSamples(500);
    sampler->SetMethod(methods[i]);
    sampler->Update();
    runs[i] = vtkSmartPointer<vtkPolyData>::New();
    runs[i]->DeepCopy(sampler->GetOutput());
  }
  const long long differ = BitDifferences(runs[0], runs[1]);
  std::printf("2D ONE_PASS vs SHRINKING_BALL: %lld values differ\n", differ);
  MEDIAL_CHECK(differ == 0 && runs[0]->GetNumberOfPoints() == 500, "2D ONE_PASS differs from SHRINKING_BALL");
  return EXIT_SUCCESS;
}
