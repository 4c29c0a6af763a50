// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes vtkOFFReader. Beyond "no crash": an error leaves an empty output, and a
// successful read gives finite points, polygons of at least three points and
// point ids in range.
#include "FuzzInput.h"

#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkOFFReader.h"
#include "vtkPolyData.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string& path = fuzzinput::TempFile(".off");
  if (!fuzzinput::WriteFile(path, data, size))
  {
    return 0;
  }
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(path.c_str());
  const int ok = reader->GetExecutive()->Update();
  vtkPolyData* mesh = reader->GetOutput();
  if (!ok)
  {
    fuzzinput::Require(mesh->GetNumberOfPoints() == 0 && mesh->GetNumberOfCells() == 0,
      "empty output after an error");
    return 0;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    fuzzinput::Require(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), "finite point");
  }
  fuzzinput::Require(mesh->GetNumberOfCells() == mesh->GetNumberOfPolys(), "polygons only");
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    fuzzinput::Require(count >= 3, "polygon of at least three points");
    for (vtkIdType k = 0; k < count; ++k)
    {
      fuzzinput::Require(ids[k] >= 0 && ids[k] < n, "point id in range");
    }
  }
  return 0;
}
