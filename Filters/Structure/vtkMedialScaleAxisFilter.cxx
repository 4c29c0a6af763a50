// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialScaleAxisFilter.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialThreads.h"
#include "vtkMedialUniformGrid.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkMedialScaleAxisFilter);

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr vtkIdType Block = 4096; // balls between progress reports and abort checks

// The balls' centres in a uniform grid, and the smallest scale at which one of them
// covers a given ball.
class CoveringScales
{
public:
  CoveringScales(const std::vector<double>& centres, const std::vector<double>& radii)
    : Centres(centres)
    , Radii(radii)
  {
    const size_t n = radii.size();
    double bounds[6] = { Infinity, -Infinity, Infinity, -Infinity, Infinity, -Infinity };
    for (size_t i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        bounds[2 * k] = std::min(bounds[2 * k], centres[3 * i + k]);
        bounds[2 * k + 1] = std::max(bounds[2 * k + 1], centres[3 * i + k]);
      }
      this->LargestRadius = std::max(this->LargestRadius, radii[i]);
    }
    // About two centres per cell if they filled the box (a flat side counts as a
    // billionth of the longest, so that a planar set of centres still gets cells).
    const double extent = std::max(
      { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
    double volume = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      volume *= std::max(bounds[2 * k + 1] - bounds[2 * k], 1e-9 * extent);
    }
    const double size = std::cbrt(2.0 * volume / static_cast<double>(std::max<size_t>(n, 1)));
    this->CellSize = vtkMedialUniformGrid::CubicCellSize(bounds, size > 0.0 ? size : 1.0);
    this->Grid.InitializeCubic(bounds, this->CellSize);
    this->Grid.BuildPoints(centres, {});
  }

  // s_i, or +infinity when no ball covers ball i at a scale up to `maximum`.
  double Of(vtkIdType i, double maximum) const
  {
    const double r = this->Radii[i];
    const double room = this->LargestRadius - r; // no ball covers at a scale below d / room
    if (!(room > 0.0))
    {
      return Infinity;
    }
    const double* c = &this->Centres[3 * i];
    double best = Infinity;
    for (double rho = this->CellSize;; rho *= 2.0)
    {
      this->Grid.ForEachItemNear(c, rho, [&](vtkIdType j) {
        const double gap = this->Radii[j] - r;
        if (gap > 0.0)
        {
          const double* q = &this->Centres[3 * j];
          const double d = std::sqrt((c[0] - q[0]) * (c[0] - q[0]) + (c[1] - q[1]) * (c[1] - q[1]) +
            (c[2] - q[2]) * (c[2] - q[2]));
          best = std::min(best, d / gap);
        }
      });
      // Every ball not visited yet lies farther than rho.
      const double bound = rho / room;
      if (best <= bound)
      {
        return best <= maximum ? best : Infinity;
      }
      if (bound > maximum)
      {
        return Infinity;
      }
    }
  }

private:
  const std::vector<double>& Centres;
  const std::vector<double>& Radii;
  double LargestRadius = 0.0;
  double CellSize = 1.0;
  vtkMedialUniformGrid Grid;
};
}

vtkMedialScaleAxisFilter::vtkMedialScaleAxisFilter()
{
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
}

int vtkMedialScaleAxisFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialScaleAxisFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // A ball may be covered by any other: every piece needs all of them.
  vtkMedialRequestWholeInput(inputVector, 1);
  return 1;
}

int vtkMedialScaleAxisFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->NumberOfRemovedBalls = 0;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 holds every kept ball
  }
  if (!input)
  {
    vtkErrorMacro("Cannot compute the scale axis: no input balls.");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0)
  {
    return 1; // no balls: an empty output, no error
  }
  vtkDataArray* radius = this->GetInputArrayToProcess(0, inputVector);
  if (!radius || radius->GetNumberOfComponents() != 1 || radius->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("Cannot compute the scale axis: the balls need a point data array of one radius per point "
                  "(by default '"
      << vtkMedialArrayNames::Radius << "').");
    return 0;
  }
  std::vector<double> centres(3 * static_cast<size_t>(n)), radii(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &centres[3 * i]);
    radii[i] = radius->GetTuple1(i);
    const double* c = &centres[3 * i];
    if (!std::isfinite(radii[i]) || radii[i] < 0.0 || !std::isfinite(c[0] + c[1] + c[2]))
    {
      vtkErrorMacro("Cannot compute the scale axis: ball " << i << " has a negative or non-finite radius ("
                                                           << radii[i] << ") or a non-finite centre.");
      return 0;
    }
  }

  const CoveringScales scales(centres, radii);
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  std::vector<double> scale(static_cast<size_t>(n));
  for (vtkIdType begin = 0; begin < n; begin += Block)
  {
    const vtkIdType end = std::min(n, begin + Block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16)
    for (vtkIdType i = begin; i < end; ++i)
    {
      scale[i] = scales.Of(i, MaximumScale);
    }
    this->UpdateProgress(static_cast<double>(end) / static_cast<double>(n));
    if (this->GetAbortExecute())
    {
      return 0;
    }
  }

  // The kept balls, in input order, with every point array and Significance.
  vtkNew<vtkIdList> kept;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (scale[i] > this->ScaleFactor)
    {
      kept->InsertNextId(i);
    }
  }
  this->NumberOfRemovedBalls = n - kept->GetNumberOfIds();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  input->GetPoints()->GetPoints(kept, points);
  output->SetPoints(points);
  output->GetPointData()->CopyAllocate(input->GetPointData(), kept->GetNumberOfIds());
  for (vtkIdType k = 0; k < kept->GetNumberOfIds(); ++k)
  {
    output->GetPointData()->CopyData(input->GetPointData(), kept->GetId(k), k);
  }
  vtkNew<vtkDoubleArray> significance;
  significance->SetName(vtkMedialArrayNames::Significance);
  significance->SetNumberOfValues(kept->GetNumberOfIds());
  vtkNew<vtkCellArray> vertices;
  vertices->AllocateExact(kept->GetNumberOfIds(), kept->GetNumberOfIds());
  for (vtkIdType k = 0; k < kept->GetNumberOfIds(); ++k)
  {
    const double s = scale[kept->GetId(k)];
    significance->SetValue(k, std::isfinite(s) ? std::max(0.0, 1.0 - 1.0 / s) : 1.0);
    vertices->InsertNextCell(1, &k);
  }
  output->GetPointData()->AddArray(significance);
  output->SetVerts(vertices);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  return 1;
}

void vtkMedialScaleAxisFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfRemovedBalls: " << this->NumberOfRemovedBalls << "\n";
}
