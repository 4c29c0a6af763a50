// SPDX-License-Identifier: BSD-3-Clause
// Fuzzes vtkMedialOFFReader. Beyond "no crash": an error leaves an empty output, and a
// successful read gives finite points, polygons of at least three points and
// point ids in range.
#include "FuzzInput.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkMedialOFFReader.h"
#include "vtkPolyData.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  vtkNew<vtkMedialOFFReader> reader;
  vtkPolyData* mesh = fuzzinput::Read(reader.Get(), ".off", data, size);
  if (!mesh)
  {
    return 0;
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  fuzzinput::RequireFinitePoints(mesh);
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
