// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialDenoiseFilter:
//  - a geodesic sphere of radius 1 with Gaussian vertex noise (0.5% of the diagonal per
//    coordinate): the smoothing brings the vertices' RMS deviation from the sphere down
//    by more than 3x, without shrinking it (Taubin's windowed sinc: the mean radius
//    stays within 0.5% of 1, where Laplacian smoothing shrinks it);
//  - the same sphere with a point per triangle corner (as OBJ and STL files give it):
//    every copy of a vertex goes where the shared vertex went (welded first);
//  - MaximumDisplacement is the largest vertex move over the input's diagonal, checked
//    against the points themselves; the input's point normals are dropped, its other
//    point data kept; the cells are the input's;
//  - pieces: piece 0 of 2 holds the whole smoothed surface, piece 1 is empty;
//  - the defaults (20 iterations, pass band 0.03);
//  - bad input (no polygons, a NaN coordinate, nothing at all): an error, no output.
#include "MedialTestSupport.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMedialDenoiseFilter.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace
{
// RMS and mean of |x| - 1 over the points (a unit sphere at the origin).
void SphereDeviation(vtkPolyData* surface, double& rms, double& mean)
{
  double sum2 = 0.0, sum = 0.0;
  const vtkIdType n = surface->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    surface->GetPoint(i, x);
    const double d = vtkMath::Norm(x) - 1.0;
    sum2 += d * d;
    sum += d;
  }
  rms = std::sqrt(sum2 / n);
  mean = sum / n;
}

int Sphere()
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShapeToSphere(); // radius 1 at the origin
  source->SetResolution(5);
  source->Update();
  vtkNew<vtkPolyData> noisy;
  noisy->DeepCopy(source->GetOutput());
  std::mt19937_64 random(11);
  std::normal_distribution<double> gauss(0.0, 0.005 * noisy->GetLength());
  vtkNew<vtkFloatArray> normals; // stale after smoothing: must go
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> label; // any other point data stays
  label->SetName("Label");
  for (vtkIdType i = 0; i < noisy->GetNumberOfPoints(); ++i)
  {
    double x[3];
    noisy->GetPoint(i, x);
    normals->InsertNextTuple(x);
    label->InsertNextValue(static_cast<int>(i % 7));
    for (double& c : x)
    {
      c += gauss(random);
    }
    noisy->GetPoints()->SetPoint(i, x);
  }
  noisy->GetPointData()->SetNormals(normals);
  noisy->GetPointData()->AddArray(label);

  vtkNew<vtkMedialDenoiseFilter> denoise;
  MEDIAL_CHECK(denoise->GetNumberOfIterations() == 20 && denoise->GetPassBand() == 0.03,
    "defaults: %d iterations, pass band %g", denoise->GetNumberOfIterations(), denoise->GetPassBand());
  denoise->SetInputData(noisy);
  denoise->Update();
  vtkPolyData* out = denoise->GetOutput();
  MEDIAL_CHECK(out->GetNumberOfPoints() == noisy->GetNumberOfPoints() &&
      out->GetNumberOfPolys() == noisy->GetNumberOfPolys(),
    "%lld points, %lld polygons out of %lld, %lld", static_cast<long long>(out->GetNumberOfPoints()),
    static_cast<long long>(out->GetNumberOfPolys()), static_cast<long long>(noisy->GetNumberOfPoints()),
    static_cast<long long>(noisy->GetNumberOfPolys()));
  double rmsBefore, meanBefore, rmsAfter, meanAfter;
  SphereDeviation(noisy, rmsBefore, meanBefore);
  SphereDeviation(out, rmsAfter, meanAfter);
  std::printf("noisy sphere: RMS deviation %.5f -> %.5f, mean %.5f -> %.5f, largest move %.5f of the diagonal\n",
    rmsBefore, rmsAfter, meanBefore, meanAfter, denoise->GetMaximumDisplacement());
  MEDIAL_CHECK(rmsAfter * 3.0 < rmsBefore, "the RMS deviation went only from %g to %g", rmsBefore, rmsAfter);
  MEDIAL_CHECK(std::fabs(meanAfter) < 0.005, "the sphere's mean radius moved by %g (shrinking)", meanAfter);

  double largest = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    noisy->GetPoint(i, a);
    out->GetPoint(i, b);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  const double expected = largest / noisy->GetLength();
  MEDIAL_CHECK(std::fabs(denoise->GetMaximumDisplacement() - expected) <= 1e-12,
    "MaximumDisplacement %.17g, the points say %.17g", denoise->GetMaximumDisplacement(), expected);
  MEDIAL_CHECK(!out->GetPointData()->GetNormals() && !out->GetPointData()->GetArray("Normals"),
    "the input's normals reached the output");
  MEDIAL_CHECK(out->GetPointData()->GetArray("Label") != nullptr, "the point array Label was dropped");

  // The same surface with every triangle on points of its own (as OBJ and STL files
  // give it): the copies of a vertex must move together, to where the shared vertex went.
  vtkNew<vtkPoints> copies;
  copies->SetDataTypeToDouble();
  vtkNew<vtkCellArray> separate;
  std::vector<vtkIdType> original;
  vtkIdType count;
  const vtkIdType* cell;
  for (noisy->GetPolys()->InitTraversal(); noisy->GetPolys()->GetNextCell(count, cell);)
  {
    vtkIdType ids[3];
    for (int j = 0; j < 3; ++j)
    {
      ids[j] = copies->InsertNextPoint(noisy->GetPoint(cell[j]));
      original.push_back(cell[j]);
    }
    separate->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> exploded;
  exploded->SetPoints(copies);
  exploded->SetPolys(separate);
  vtkNew<vtkMedialDenoiseFilter> again;
  again->SetInputData(exploded);
  again->Update();
  double worst = 0.0;
  for (vtkIdType i = 0; i < exploded->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    again->GetOutput()->GetPoint(i, a);
    out->GetPoint(original[i], b);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  MEDIAL_CHECK(again->GetOutput()->GetNumberOfPoints() == exploded->GetNumberOfPoints() && worst <= 1e-6,
    "a surface with a point per triangle corner: a copy lies %g from where the shared vertex went", worst);

  // Pieces: piece 0 of 2 is the whole smoothed surface, piece 1 is empty.
  vtkNew<vtkMedialDenoiseFilter> pieces;
  pieces->SetInputData(noisy);
  pieces->UpdatePiece(1, 2, 0);
  const vtkIdType second = pieces->GetOutput()->GetNumberOfPoints();
  pieces->UpdatePiece(0, 2, 0);
  MEDIAL_CHECK(second == 0 && pieces->GetOutput()->GetNumberOfPoints() == out->GetNumberOfPoints(),
    "pieces of 2: %lld and %lld points, %lld expected in piece 0", static_cast<long long>(pieces->GetOutput()->GetNumberOfPoints()),
    static_cast<long long>(second), static_cast<long long>(out->GetNumberOfPoints()));
  return 0;
}

int BadInput()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, 2 } };
  for (const auto& f : faces)
  {
    triangles->InsertNextCell(3, f);
  }
  vtkNew<vtkPolyData> lines; // points, no polygons
  lines->SetPoints(points);
  vtkNew<vtkCellArray> segment;
  const vtkIdType ends[2] = { 0, 1 };
  segment->InsertNextCell(2, ends);
  lines->SetLines(segment);
  vtkNew<vtkPolyData> withNaN;
  vtkNew<vtkPoints> nanPoints;
  nanPoints->DeepCopy(points);
  nanPoints->SetPoint(2, 0, std::nan(""), 0);
  withNaN->SetPoints(nanPoints);
  withNaN->SetPolys(triangles);
  vtkNew<vtkPolyData> empty;
  struct Case
  {
    const char* Name;
    vtkPolyData* Input;
    const char* Expected;
  };
  for (const Case& c : { Case{ "lines only", lines, "the input has no polygons" },
         Case{ "a NaN coordinate", withNaN, "point 2 has a non-finite coordinate" },
         Case{ "an empty surface", empty, "the input has no polygons" } })
  {
    vtkNew<vtkMedialDenoiseFilter> denoise;
    medialtest::EventLog log;
    log.Watch(denoise);
    denoise->SetInputData(c.Input);
    const int ok = denoise->GetExecutive()->Update();
    MEDIAL_CHECK(!ok && denoise->GetOutput()->GetNumberOfPoints() == 0 && !log.LineWith(c.Expected).empty(),
      "%s: accepted, or not the expected error (log: %s)", c.Name, log.Text.c_str());
  }
  return 0;
}
}

int TestMedialDenoiseFilter(int, char*[])
{
  int failed = Sphere();
  failed |= BadInput();
  return failed;
}
