// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialDenoiseFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleStrip.h"
#include "vtkWindowedSincPolyDataFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkMedialDenoiseFilter);

namespace
{
// The input's polygons (and strips, as triangles) on points welded where their
// coordinates are equal; `welded[i]` is input point i's welded point.
vtkSmartPointer<vtkPolyData> WeldedSurface(vtkPolyData* input, std::vector<vtkIdType>& welded)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<std::array<double, 3>> x(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, x[i].data());
  }
  std::vector<vtkIdType> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](vtkIdType a, vtkIdType b) { return x[a] < x[b] || (x[a] == x[b] && a < b); });
  // Each point's first copy (the smallest id with its coordinates) stands for all; the
  // welded points keep the input's order and type, so a welded input is smoothed as is.
  std::vector<vtkIdType> first(static_cast<size_t>(n));
  for (size_t k = 0; k < order.size(); ++k)
  {
    first[order[k]] = (k > 0 && x[order[k]] == x[order[k - 1]]) ? first[order[k - 1]] : order[k];
  }
  welded.assign(static_cast<size_t>(n), -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  for (vtkIdType i = 0; i < n; ++i)
  {
    welded[i] = first[i] == i ? points->InsertNextPoint(input->GetPoint(i)) : welded[first[i]];
  }
  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkIdList> ids;
  auto add = [&](vtkIdType count, const vtkIdType* cell) {
    ids->SetNumberOfIds(count);
    for (vtkIdType j = 0; j < count; ++j)
    {
      ids->SetId(j, welded[cell[j]]);
    }
    for (vtkIdType j = 0; j < count; ++j)
    {
      if (ids->GetId(j) == ids->GetId((j + 1) % count))
      {
        return; // collapsed by the welding: it has no area
      }
    }
    polygons->InsertNextCell(ids);
  };
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* cell;
    polys->GetCurrentCell(count, cell);
    add(count, cell);
  }
  vtkNew<vtkCellArray> triangles;
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* cell;
    strips->GetCurrentCell(count, cell);
    triangles->Reset();
    vtkTriangleStrip::DecomposeStrip(static_cast<int>(count), cell, triangles);
    vtkIdType three;
    const vtkIdType* triangle;
    for (triangles->InitTraversal(); triangles->GetNextCell(three, triangle);)
    {
      add(three, triangle);
    }
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polygons);
  return surface;
}
}

int vtkMedialDenoiseFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkMedialRequestWholeInput(inputVector, 1); // a vertex moves by all its neighbours
  return 1;
}

int vtkMedialDenoiseFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->MaximumDisplacement = 0.0;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 holds the whole smoothed surface
  }
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro("Cannot denoise: the input has no polygons.");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    if (!std::isfinite(x[0] + x[1] + x[2]))
    {
      vtkErrorMacro("Cannot denoise: point " << i << " has a non-finite coordinate.");
      return 0;
    }
  }
  std::vector<vtkIdType> welded;
  vtkSmartPointer<vtkPolyData> surface = WeldedSurface(input, welded);
  this->UpdateProgress(0.1);
  vtkNew<vtkWindowedSincPolyDataFilter> smooth;
  smooth->SetInputData(surface);
  smooth->SetNumberOfIterations(this->NumberOfIterations);
  smooth->SetPassBand(this->PassBand);
  smooth->NormalizeCoordinatesOn();
  smooth->BoundarySmoothingOff();
  smooth->FeatureEdgeSmoothingOff();
  smooth->NonManifoldSmoothingOn();
  smooth->Update();
  vtkPoints* smoothed = smooth->GetOutput()->GetPoints();
  if (this->GetAbortExecute())
  {
    return 0;
  }
  if (!smoothed || smoothed->GetNumberOfPoints() != surface->GetNumberOfPoints())
  {
    vtkErrorMacro("Cannot denoise: the windowed sinc filter returned no points.");
    return 0;
  }
  vtkNew<vtkPoints> moved;
  moved->SetDataType(input->GetPoints()->GetDataType());
  moved->SetNumberOfPoints(n);
  double largest = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    smoothed->GetPoint(welded[i], b);
    moved->SetPoint(i, b);
    largest = std::max(largest, vtkMath::Distance2BetweenPoints(a, b));
  }
  output->CopyStructure(input);
  output->SetPoints(moved);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetPointData()->SetNormals(nullptr); // they no longer fit the moved points
  output->GetCellData()->PassData(input->GetCellData());
  const double diagonal = input->GetLength();
  this->MaximumDisplacement = diagonal > 0.0 ? std::sqrt(largest) / diagonal : 0.0;
  return 1;
}

void vtkMedialDenoiseFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfIterations: " << this->NumberOfIterations << "\n";
  os << indent << "PassBand: " << this->PassBand << "\n";
  os << indent << "MaximumDisplacement: " << this->MaximumDisplacement << "\n";
}
