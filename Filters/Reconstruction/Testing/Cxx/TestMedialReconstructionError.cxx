// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialReconstructionError against closed forms and against VTK's cell locator:
//  - two nested boxes (half-width 1 and 1.1): every vertex and area figure has a
//    closed form (the area mean by numerical integration);
//  - two nested squares in 2D: distances go to the boundary curves, not to the
//    filled polygon (a vertex inside the original is not at distance 0);
//  - the jack and its union of balls: the vertex figures of the own BVH equal those of
//    the CELL_LOCATOR engine (vtkStaticCellLocator, the measure the command line used
//    before) to 1e-12, and the results are the same with 1 and 2 threads;
//  - missing or empty inputs are errors.
#include "MedialTestSupport.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialShapeSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <vector>

using medialtest::EventLog;

namespace
{
vtkSmartPointer<vtkPolyData> Box(double half, int resolution)
{
  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->SetBoxLengths(2 * half, 2 * half, 2 * half);
  box->SetResolution(resolution);
  box->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(box->GetOutput());
  return pd;
}

// Distance from x to the surface of the cube [-h, h]^3.
double CubeDistance(const double x[3], double h)
{
  double outside = 0.0, inside = -HUGE_VAL;
  for (int k = 0; k < 3; ++k)
  {
    const double q = std::fabs(x[k]) - h;
    outside += q > 0 ? q * q : 0.0;
    inside = std::max(inside, q);
  }
  return outside > 0 ? std::sqrt(outside) : -inside;
}

// Mean distance from a uniform point on the cube of half-width `outer` to the cube of
// half-width `inner`: one face, by the midpoint rule.
double MeanFaceDistance(double outer, double inner)
{
  const int n = 2000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double x[3] = { outer, -outer + (i + 0.5) * 2 * outer / n, -outer + (j + 0.5) * 2 * outer / n };
      sum += CubeDistance(x, inner);
    }
  }
  return sum / (static_cast<double>(n) * n);
}

vtkSmartPointer<vtkPolyData> Square(double half, bool asLines)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(-half, -half, 0);
  points->InsertNextPoint(half, -half, 0);
  points->InsertNextPoint(half, half, 0);
  points->InsertNextPoint(-half, half, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType loop[5] = { 0, 1, 2, 3, 0 };
  cells->InsertNextCell(asLines ? 5 : 4, loop);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  asLines ? pd->SetLines(cells) : pd->SetPolys(cells);
  return pd;
}

bool Near(double value, double expected, double tolerance)
{
  return std::fabs(value - expected) <= tolerance;
}
}

int TestMedialReconstructionError(int, char*[])
{
  using E = vtkMedialReconstructionError;
  // Nested boxes.
  {
    auto inner = Box(1.0, 8), outer = Box(1.1, 8);
    vtkNew<E> measure;
    measure->SetOriginalData(inner);
    measure->SetReconstructionData(outer);
    measure->SetNumberOfAreaSamples(200000);
    measure->Update();
    const double diagonal = 2 * std::sqrt(3.0);
    const double* vmax = measure->GetVertexMaxError();
    const double* vmean = measure->GetVertexMeanError();
    const double* amax = measure->GetAreaMaxError();
    const double* amean = measure->GetAreaMeanError();
    std::printf("boxes: vertex max %.6g %.6g mean %.6g %.6g; area max %.6g %.6g mean %.6g %.6g (x diagonal)\n",
      vmax[0] * diagonal, vmax[1] * diagonal, vmean[0] * diagonal, vmean[1] * diagonal, amax[0] * diagonal,
      amax[1] * diagonal, amean[0] * diagonal, amean[1] * diagonal);
    MEDIAL_CHECK(Near(measure->GetDiagonal(), diagonal, 1e-12), "diagonal %g", measure->GetDiagonal());
    // Outer vertices to the inner box: exactly CubeDistance; the corners are the farthest.
    double sum = 0.0;
    for (vtkIdType i = 0; i < outer->GetNumberOfPoints(); ++i)
    {
      sum += CubeDistance(outer->GetPoint(i), 1.0);
    }
    MEDIAL_CHECK(Near(vmax[E::RECONSTRUCTION_TO_ORIGINAL] * diagonal, 0.1 * std::sqrt(3.0), 1e-12), "vertex max %g",
      vmax[0] * diagonal);
    MEDIAL_CHECK(Near(vmean[E::RECONSTRUCTION_TO_ORIGINAL] * diagonal, sum / outer->GetNumberOfPoints(), 1e-12),
      "vertex mean %g", vmean[0] * diagonal);
    // Inner vertices to the outer box: 0.1 everywhere.
    MEDIAL_CHECK(Near(vmax[E::ORIGINAL_TO_RECONSTRUCTION] * diagonal, 0.1, 1e-12) &&
        Near(vmean[E::ORIGINAL_TO_RECONSTRUCTION] * diagonal, 0.1, 1e-12),
      "inner vertices %g %g", vmax[1] * diagonal, vmean[1] * diagonal);
    MEDIAL_CHECK(Near(measure->GetVertexHausdorff(), vmax[0], 0.0), "two-sided vertex figure");
    // Area samples: at most the corner distance; the mean by integration (1e-3: sampling noise).
    const double expectedMean = MeanFaceDistance(1.1, 1.0);
    MEDIAL_CHECK(amax[0] * diagonal <= 0.1 * std::sqrt(3.0) + 1e-12 && amax[0] * diagonal > 0.16,
      "area max %g", amax[0] * diagonal);
    MEDIAL_CHECK(Near(amean[0] * diagonal, expectedMean, 1e-3), "area mean %g, expected %g", amean[0] * diagonal,
      expectedMean);
    MEDIAL_CHECK(Near(amax[1] * diagonal, 0.1, 1e-12) && Near(amean[1] * diagonal, 0.1, 1e-12), "inner area %g %g",
      amax[1] * diagonal, amean[1] * diagonal);
    // Outputs: per-vertex distances and the field data.
    vtkDataArray* perVertex = measure->GetOutput(0)->GetPointData()->GetArray(vtkMedialArrayNames::SurfaceDistance);
    vtkDataArray* field = measure->GetOutput(0)->GetFieldData()->GetArray(vtkMedialArrayNames::VertexMaxError);
    MEDIAL_CHECK(perVertex && perVertex->GetNumberOfTuples() == outer->GetNumberOfPoints() &&
        Near(perVertex->GetTuple1(0), CubeDistance(outer->GetPoint(0), 1.0), 1e-12),
      "SurfaceDistance on output 0");
    MEDIAL_CHECK(field && field->GetNumberOfComponents() == 2 && field->GetComponent(0, 1) == vmax[1],
      "VertexMaxError field data");
    MEDIAL_CHECK(measure->GetOutput(1)->GetPointData()->GetArray(vtkMedialArrayNames::SurfaceDistance),
      "SurfaceDistance on output 1");
  }

  // 2D: a square polygon and a smaller square polyline inside it.
  {
    vtkNew<E> measure;
    measure->SetOriginalData(Square(1.0, false));
    measure->SetReconstructionData(Square(0.9, true));
    measure->Update();
    const double diagonal = 2 * std::sqrt(2.0);
    const double* vmax = measure->GetVertexMaxError();
    std::printf("squares: vertex max %.6g %.6g, area max %.6g %.6g (x diagonal)\n", vmax[0] * diagonal,
      vmax[1] * diagonal, measure->GetAreaMaxError()[0] * diagonal, measure->GetAreaMaxError()[1] * diagonal);
    MEDIAL_CHECK(Near(vmax[0] * diagonal, 0.1, 1e-12), "inner square to the outer boundary %g", vmax[0] * diagonal);
    MEDIAL_CHECK(Near(vmax[1] * diagonal, 0.1 * std::sqrt(2.0), 1e-12), "outer corners %g", vmax[1] * diagonal);
    MEDIAL_CHECK(Near(measure->GetAreaMaxError()[0] * diagonal, 0.1, 1e-12), "inner square, area %g",
      measure->GetAreaMaxError()[0] * diagonal);
  }

  // The jack and its union of balls: the same vertex figures as VTK's cell locator,
  // and the same results with 1 and 2 threads.
  {
    vtkNew<vtkMedialShapeSource> jack;
    jack->Update();
    vtkNew<vtkMedialAxisSampler> sampler;
    sampler->SetInputConnection(jack->GetOutputPort());
    sampler->SetNumberOfSamples(2000);
    vtkNew<vtkMedialBallUnion> ballUnion;
    ballUnion->SetInputConnection(sampler->GetOutputPort());
    ballUnion->SetSampleDimensions(64, 64, 64);
    ballUnion->Update();
    double results[3][8]; // BVH on 1 and 2 threads, the cell locator on 2
    for (int run = 0; run < 3; ++run)
    {
      vtkNew<E> measure;
      measure->SetOriginalConnection(jack->GetOutputPort());
      measure->SetReconstructionConnection(ballUnion->GetOutputPort());
      measure->SetNumberOfThreads(run == 0 ? 1 : 2);
      measure->SetDistanceEngine(run == 2 ? E::CELL_LOCATOR : E::BVH);
      measure->Update();
      for (int d = 0; d < 2; ++d)
      {
        results[run][d] = measure->GetVertexMaxError()[d];
        results[run][2 + d] = measure->GetVertexMeanError()[d];
        results[run][4 + d] = measure->GetAreaMaxError()[d];
        results[run][6 + d] = measure->GetAreaMeanError()[d];
      }
    }
    std::printf("jack: vertex max %.9g %.9g (locator %.9g %.9g), mean %.9g %.9g (locator %.9g %.9g); area max "
                "%.6g %.6g mean %.6g %.6g\n",
      results[0][0], results[0][1], results[2][0], results[2][1], results[0][2], results[0][3], results[2][2],
      results[2][3], results[0][4], results[0][5], results[0][6], results[0][7]);
    for (int k = 0; k < 8; ++k)
    {
      MEDIAL_CHECK(Near(results[0][k], results[2][k], 1e-12), "figure %d differs from the cell locator's", k);
    }
    MEDIAL_CHECK(std::equal(results[0], results[0] + 8, results[1]), "1 and 2 threads differ");
    MEDIAL_CHECK(results[0][4] >= results[0][0] * 0.5 && results[0][6] > 0, "area figures %g %g", results[0][4],
      results[0][6]);
  }

  // Bad input: a missing reconstruction, an empty one.
  {
    vtkNew<E> measure;
    EventLog log;
    log.Watch(measure);
    measure->SetOriginalData(Box(1.0, 2));
    measure->SetReconstructionData(vtkSmartPointer<vtkPolyData>::New());
    MEDIAL_CHECK(measure->GetExecutive()->Update() == 0, "an empty reconstruction is accepted");
    std::printf("empty reconstruction: %s\n", log.LineWith("Cannot measure").c_str());
    MEDIAL_CHECK(log.LineWith("the reconstruction: input has no points or no cells") != "", "%s", log.Text.c_str());
    MEDIAL_CHECK(std::isnan(measure->GetVertexHausdorff()), "no result after a failed update");
  }
  return EXIT_SUCCESS;
}
