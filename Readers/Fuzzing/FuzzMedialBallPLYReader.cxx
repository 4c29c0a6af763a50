// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes vtkMedialBallPLYReader. Beyond "no crash": a successful read gives
// consistent balls (a Radius per point, finite values, non-negative radii, ids in
// range, faces of 3 or more points), and writing them with vtkMedialBallPLYWriter
// and reading them back gives the same balls bit for bit.
#include "FuzzInput.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMedialBallPLYReader.h"
#include "vtkMedialBallPLYWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstring>

namespace
{
void CheckCells(vtkCellArray* cells, vtkIdType minimum, vtkIdType numberOfPoints)
{
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    fuzzinput::Require(n >= minimum, "cell size");
    for (vtkIdType k = 0; k < n; ++k)
    {
      fuzzinput::Require(ids[k] >= 0 && ids[k] < numberOfPoints, "point id in range");
    }
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkNew<vtkMedialBallPLYReader> reader;
  vtkPolyData* balls = fuzzinput::Read(reader.Get(), ".ply", data, size);
  if (!balls)
  {
    return 0;
  }
  const vtkIdType n = balls->GetNumberOfPoints();
  vtkDataArray* radius = balls->GetPointData()->GetArray("Radius");
  fuzzinput::Require(radius && radius->GetNumberOfTuples() == n, "a Radius per point");
  fuzzinput::RequireFinitePoints(balls);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double r = radius->GetComponent(i, 0);
    fuzzinput::Require(std::isfinite(r) && r >= 0.0, "finite non-negative radius");
  }
  CheckCells(balls->GetLines(), 2, n);
  CheckCells(balls->GetPolys(), 3, n);

  // Round trip of the balls through the writer (faces come back triangulated).
  const std::string& copy = fuzzinput::TempFile(".copy.ply");
  vtkNew<vtkMedialBallPLYWriter> writer;
  writer->SetInputData(balls);
  writer->SetFileName(copy.c_str());
  fuzzinput::Require(writer->Write() == 1, "writer accepts what the reader produced");
  vtkNew<vtkMedialBallPLYReader> again;
  again->SetFileName(copy.c_str());
  fuzzinput::Require(again->GetExecutive()->Update() == 1, "reader accepts what the writer wrote");
  vtkPolyData* back = again->GetOutput();
  fuzzinput::Require(back->GetNumberOfPoints() == n, "round trip point count");
  fuzzinput::Require(back->GetNumberOfLines() == balls->GetNumberOfLines(), "round trip edges");
  vtkDataArray* backRadius = back->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    balls->GetPoint(i, p);
    back->GetPoint(i, q);
    const double r = radius->GetComponent(i, 0), s = backRadius->GetComponent(i, 0);
    fuzzinput::Require(std::memcmp(p, q, sizeof(p)) == 0, "round trip point");
    fuzzinput::Require(std::memcmp(&r, &s, sizeof(r)) == 0, "round trip radius");
  }
  return 0;
}
