// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes vtkMedialMeshReader. Beyond "no crash": a successful read gives a
// consistent mesh (a Radius per point, finite values, ids in range), and writing
// it with vtkMedialMeshWriter and reading it back gives the same data exactly.
#include "FuzzInput.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMedialMeshReader.h"
#include "vtkMedialMeshWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstring>

namespace
{
bool CellsEqual(vtkCellArray* a, vtkCellArray* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells() ||
    a->GetNumberOfConnectivityIds() != b->GetNumberOfConnectivityIds())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfConnectivityIds(); ++i)
  {
    if (a->GetConnectivityArray()->GetComponent(i, 0) != b->GetConnectivityArray()->GetComponent(i, 0))
    {
      return false;
    }
  }
  return true;
}

void CheckCells(vtkCellArray* cells, vtkIdType size, vtkIdType numberOfPoints)
{
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    fuzzinput::Require(n == size, "cell size");
    for (vtkIdType k = 0; k < n; ++k)
    {
      fuzzinput::Require(ids[k] >= 0 && ids[k] < numberOfPoints, "point id in range");
    }
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkNew<vtkMedialMeshReader> reader;
  vtkPolyData* mesh = fuzzinput::Read(reader.Get(), ".ma", data, size);
  if (!mesh)
  {
    return 0;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* radius = mesh->GetPointData()->GetArray("Radius");
  fuzzinput::Require(radius && radius->GetNumberOfTuples() == n, "a Radius per point");
  fuzzinput::RequireFinitePoints(mesh);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double r = radius->GetComponent(i, 0);
    fuzzinput::Require(std::isfinite(r) && r >= 0.0, "finite non-negative radius");
  }
  CheckCells(mesh->GetLines(), 2, n);
  CheckCells(mesh->GetPolys(), 3, n);

  // Round trip through the writer.
  const std::string& copy = fuzzinput::TempFile(".copy.ma");
  vtkNew<vtkMedialMeshWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(copy.c_str());
  fuzzinput::Require(writer->Write() == 1, "writer accepts what the reader produced");
  vtkNew<vtkMedialMeshReader> again;
  again->SetFileName(copy.c_str());
  fuzzinput::Require(again->GetExecutive()->Update() == 1, "reader accepts what the writer wrote");
  vtkPolyData* back = again->GetOutput();
  fuzzinput::Require(back->GetNumberOfPoints() == n, "round trip point count");
  vtkDataArray* backRadius = back->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    mesh->GetPoint(i, p);
    back->GetPoint(i, q);
    const double r = radius->GetComponent(i, 0), s = backRadius->GetComponent(i, 0);
    // Bit for bit, so that -0 and 0 count as different.
    fuzzinput::Require(std::memcmp(p, q, sizeof(p)) == 0, "round trip point");
    fuzzinput::Require(std::memcmp(&r, &s, sizeof(r)) == 0, "round trip radius");
  }
  fuzzinput::Require(CellsEqual(mesh->GetLines(), back->GetLines()), "round trip edges");
  fuzzinput::Require(CellsEqual(mesh->GetPolys(), back->GetPolys()), "round trip faces");
  return 0;
}
