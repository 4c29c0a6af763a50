// SPDX-License-Identifier: BSD-3-Clause
// Wall thickness against closed forms, at the default angle and protrusion:
//  - a sphere of radius R: 2R at every vertex and cell, within 2% (Thickness within 1%);
//  - a hollow sphere with radii R1 > R2: R1 - R2 on both shells, within 2%;
//  - a box: TangentThickness is its smallest dimension on the two largest faces,
//    exactly, wherever the ball of that diameter fits (at least half of it from the
//    face's border), never more anywhere, 0 on its convex edges, where no ball touches
//    them; Thickness is the smallest dimension everywhere, edges and corners included
//    (the walls that meet there);
//  - a torus with radii (R, a): 2a at every vertex, within 2%.
// Prints the table of the closed forms (expected, min, median, max).
#include "MedialThicknessTestUtilities.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
// The filter's output; null (and a printed reason) on any error or warning: the closed
// forms, the hollow sphere's cavity included, are valid solids.
vtkSmartPointer<vtkPolyData> Thickness(vtkPolyData* surface, bool cells = true)
{
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputData(surface);
  thickness->SetComputeCellThickness(cells);
  EventLog log;
  log.Watch(thickness);
  thickness->Update();
  if (log.Errors || log.Warnings)
  {
    std::printf("unexpected messages: %s\n", log.Text.c_str());
    return nullptr;
  }
  return thickness->GetOutput();
}

vtkDataArray* PointArray(vtkPolyData* pd, const char* name)
{
  return pd->GetPointData()->GetArray(name);
}
}

int TestMedialThicknessClosedForms(int, char*[])
{
  auto all = [](vtkIdType) { return true; };
  std::printf("| shape | expected | min | median | max | points |\n|---|---|---|---|---|---|\n");

  // The sphere's vertices at 20480 triangles; its cells (a ball each) at 5120, as the
  // balls at a sphere's symmetric points are the slowest to find (every facet is nearly
  // tangent to them).
  const double R = 1.5;
  auto sphere = Thickness(MakeShape(vtkMedialShapeSource::SPHERE, 5, [&](vtkMedialShapeSource* s) { s->SetRadius(R); }), false);
  auto coarse = Thickness(MakeShape(vtkMedialShapeSource::SPHERE, 4, [&](vtkMedialShapeSource* s) { s->SetRadius(R); }));
  MEDIAL_CHECK(sphere && coarse, "sphere");
  const Summary sphereVertices = Summarise(PointArray(sphere, vtkMedialArrayNames::Thickness), all);
  const Summary sphereCells = Summarise(coarse->GetCellData()->GetArray(vtkMedialArrayNames::Thickness), all);
  const Summary sphereRays = Summarise(PointArray(sphere, vtkMedialArrayNames::RayThickness), all);
  PrintRow("sphere R = 1.5, 20480 triangles: vertices", 2 * R, sphereVertices);
  PrintRow("sphere R = 1.5, 5120 triangles: cells", 2 * R, sphereCells);
  PrintRow("sphere, 20480 triangles: RayThickness at the vertices", 2 * R, sphereRays);
  MEDIAL_CHECK(Within(sphereVertices, 2 * R, 0.01), "sphere vertices %g to %g", sphereVertices.Min, sphereVertices.Max);
  MEDIAL_CHECK(Within(sphereCells, 2 * R, 0.01), "sphere cells %g to %g", sphereCells.Min, sphereCells.Max);
  const Summary sphereTangent = Summarise(PointArray(sphere, vtkMedialArrayNames::TangentThickness), all);
  PrintRow("sphere, 20480 triangles: TangentThickness at the vertices", 2 * R, sphereTangent);
  MEDIAL_CHECK(Within(sphereTangent, 2 * R, 0.02), "sphere tangent %g to %g", sphereTangent.Min, sphereTangent.Max);
  MEDIAL_CHECK(Within(sphereRays, 2 * R, 0.02), "sphere rays %g to %g", sphereRays.Min, sphereRays.Max);

  const double R1 = 1.0, R2 = 0.6;
  auto hollow = Thickness(MakeShape(vtkMedialShapeSource::HOLLOW_SPHERE, 4, [&](vtkMedialShapeSource* s) {
    s->SetRadius(R1);
    s->SetInnerRadius(R2);
  }));
  MEDIAL_CHECK(hollow, "hollow sphere");
  auto onShell = [&](double radius) {
    return [hollow, radius](vtkIdType i) {
      double x[3];
      hollow->GetPoint(i, x);
      return std::fabs(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - radius) < 1e-9;
    };
  };
  const Summary outer = Summarise(PointArray(hollow, vtkMedialArrayNames::Thickness), onShell(R1));
  const Summary inner = Summarise(PointArray(hollow, vtkMedialArrayNames::Thickness), onShell(R2));
  PrintRow("hollow sphere 1 / 0.6: outer shell", R1 - R2, outer);
  PrintRow("hollow sphere 1 / 0.6: cavity shell", R1 - R2, inner);
  MEDIAL_CHECK(Within(outer, R1 - R2, 0.02) && outer.Count == hollow->GetNumberOfPoints() / 2,
    "outer shell %g to %g", outer.Min, outer.Max);
  MEDIAL_CHECK(Within(inner, R1 - R2, 0.02) && inner.Count == hollow->GetNumberOfPoints() / 2,
    "cavity shell %g to %g", inner.Min, inner.Max);

  // Box 3 x 2 x 1: on its z faces, a vertex at least 0.5 from the face's border.
  auto box = Thickness(MakeShape(vtkMedialShapeSource::BOX, 12));
  MEDIAL_CHECK(box, "box");
  auto largestFaces = [&](double margin) {
    return [box, margin](vtkIdType i) {
      double x[3];
      box->GetPoint(i, x);
      return std::fabs(std::fabs(x[2]) - 0.5) < 1e-12 && std::fabs(x[0]) <= 1.5 - margin + 1e-12 &&
        std::fabs(x[1]) <= 1.0 - margin + 1e-12;
    };
  };
  const Summary fits = Summarise(PointArray(box, vtkMedialArrayNames::TangentThickness), largestFaces(0.5));
  const Summary faces = Summarise(PointArray(box, vtkMedialArrayNames::TangentThickness), largestFaces(0.0));
  const Summary boxAll = Summarise(PointArray(box, vtkMedialArrayNames::TangentThickness), all);
  const Summary walls = Summarise(PointArray(box, vtkMedialArrayNames::Thickness), all);
  const Summary wallCells = Summarise(box->GetCellData()->GetArray(vtkMedialArrayNames::Thickness), all);
  PrintRow("box 3 x 2 x 1: TangentThickness, largest faces, 0.5 or more from their border", 1.0, fits);
  PrintRow("box: TangentThickness, largest faces, all vertices (less near the border, 0 on the edges)", 1.0, faces);
  PrintRow("box: Thickness, every vertex", 1.0, walls);
  PrintRow("box: Thickness, every cell", 1.0, wallCells);
  MEDIAL_CHECK(Within(fits, 1.0, 1e-9), "box faces %.12g to %.12g", fits.Min, fits.Max);
  MEDIAL_CHECK(boxAll.Max <= 1.0 + 1e-9 && boxAll.Min == 0.0, "box: %g to %g", boxAll.Min, boxAll.Max);
  MEDIAL_CHECK(Within(walls, 1.0, 1e-9) && Within(wallCells, 1.0, 1e-9), "box Thickness: vertices %.12g to %.12g, "
    "cells %.12g to %.12g", walls.Min, walls.Max, wallCells.Min, wallCells.Max);

  const double ring = 1.0, tube = 0.25;
  auto torus = Thickness(MakeShape(vtkMedialShapeSource::TORUS, 48, [&](vtkMedialShapeSource* s) {
    s->SetRadius(ring);
    s->SetTubeRadius(tube);
  }));
  MEDIAL_CHECK(torus, "torus");
  const Summary torusVertices = Summarise(PointArray(torus, vtkMedialArrayNames::Thickness), all);
  PrintRow("torus (1, 0.25), 18432 triangles: vertices", 2 * tube, torusVertices);
  MEDIAL_CHECK(Within(torusVertices, 2 * tube, 0.02), "torus %g to %g", torusVertices.Min, torusVertices.Max);
  // Each ball's centre lies on the torus's core circle.
  double worst = 0.0;
  vtkDataArray* centres = PointArray(torus, vtkMedialArrayNames::MedialCentre);
  for (vtkIdType i = 0; i < centres->GetNumberOfTuples(); ++i)
  {
    double c[3];
    centres->GetTuple(i, c);
    worst = std::max(worst, std::hypot(std::hypot(c[0], c[1]) - ring, c[2]));
  }
  std::printf("torus: largest distance of a MedialCentre from the core circle %.4g (tube radius %g)\n", worst, tube);
  MEDIAL_CHECK(worst <= 0.02 * tube, "centre %g off the core circle", worst);
  return EXIT_SUCCESS;
}
