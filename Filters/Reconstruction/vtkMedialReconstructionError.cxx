// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialReconstructionError.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialProgress.h"
#include "vtkMedialBoundaryDistance.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialThreads.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
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
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialReconstructionError);

namespace
{
struct Summary
{
  double Max = 0.0;
  double Mean = 0.0;
};

// Largest and mean distance divided by `scale`, summed in point order.
Summary Summarize(const std::vector<double>& distance, double scale)
{
  Summary s;
  double sum = 0.0;
  for (double d : distance)
  {
    s.Max = std::max(s.Max, d);
    sum += d;
  }
  s.Max /= scale;
  s.Mean = distance.empty() ? 0.0 : sum / static_cast<double>(distance.size()) / scale;
  return s;
}

// A shallow copy of `shape` with the point data array `SurfaceDistance`.
void CopyWithDistances(vtkPolyData* shape, const std::vector<double>& distance, vtkPolyData* output)
{
  output->ShallowCopy(shape);
  vtkNew<vtkDoubleArray> array;
  array->SetName(vtkMedialArrayNames::SurfaceDistance);
  array->SetNumberOfValues(static_cast<vtkIdType>(distance.size()));
  std::copy(distance.begin(), distance.end(), array->GetPointer(0));
  output->GetPointData()->AddArray(array);
}

void AddPair(vtkFieldData* field, const char* name, const double values[2])
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(2);
  array->SetComponentName(0, "ReconstructionToOriginal");
  array->SetComponentName(1, "OriginalToReconstruction");
  array->InsertNextTuple(values);
  field->AddArray(array);
}
}

vtkMedialReconstructionError::vtkMedialReconstructionError()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->ResetResults();
}

void vtkMedialReconstructionError::ResetResults()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int d = 0; d < 2; ++d)
  {
    this->VertexMaxError[d] = this->VertexMeanError[d] = nan;
    this->AreaMaxError[d] = this->AreaMeanError[d] = nan;
  }
  this->Diagonal = nan;
}

int vtkMedialReconstructionError::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialReconstructionError::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Distances need entire shapes, whatever piece is requested downstream.
  vtkMedialRequestWholeInput(inputVector, 2);
  return 1;
}

int vtkMedialReconstructionError::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->ResetResults();
  vtkPolyData* original = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* reconstruction = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* originalOutput = vtkPolyData::GetData(outputVector, 1);
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 measures the whole shapes
  }
  if (!original || !reconstruction)
  {
    vtkErrorMacro("Cannot measure the reconstruction error: both inputs are required "
                  "(port 0 the original, port 1 the reconstruction).");
    return 0;
  }
  const bool curves = vtkMedialBoundaryDistance::IsPlanar(original);
  const int engine = this->DistanceEngine == CELL_LOCATOR ? vtkMedialBoundaryDistance::CELL_LOCATOR
                                                          : vtkMedialBoundaryDistance::OWN_BVH;
  vtkMedialBoundaryDistance toOriginal, toReconstruction;
  std::string error;
  vtkMedialStages stages(this);
  stages.Begin("Building the distance queries", 0.0, 0.2);
  if (!toOriginal.Build(original, curves, engine, error))
  {
    vtkErrorMacro("Cannot measure the reconstruction error: the original: " << error << ".");
    return 0;
  }
  if (!toReconstruction.Build(reconstruction, curves, engine, error))
  {
    vtkErrorMacro("Cannot measure the reconstruction error: the reconstruction: " << error << ".");
    return 0;
  }
  stages.Begin("Measuring from the vertices", 0.2, 0.5);
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  const double diagonal = original->GetLength();

  // Vertex measure.
  const std::vector<double> reconstructionVertices = toOriginal.Distances(reconstruction->GetPoints(), threads);
  const std::vector<double> originalVertices = toReconstruction.Distances(original->GetPoints(), threads);
  const Summary vertex[2] = { Summarize(reconstructionVertices, diagonal), Summarize(originalVertices, diagonal) };
  stages.Begin("Measuring from area samples", 0.5, 1.0);
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // Area measure: points spread over one boundary, distances to the other.
  Summary area[2];
  if (this->NumberOfAreaSamples > 0)
  {
    area[RECONSTRUCTION_TO_ORIGINAL] = Summarize(toOriginal.Distances(
      toReconstruction.SamplePoints(this->NumberOfAreaSamples, static_cast<std::uint64_t>(this->RandomSeed), threads), threads), diagonal);
    this->UpdateProgress(0.5);
    area[ORIGINAL_TO_RECONSTRUCTION] = Summarize(toReconstruction.Distances(
      toOriginal.SamplePoints(this->NumberOfAreaSamples, static_cast<std::uint64_t>(this->RandomSeed), threads), threads), diagonal);
  }
  for (int d = 0; d < 2; ++d)
  {
    this->VertexMaxError[d] = vertex[d].Max;
    this->VertexMeanError[d] = vertex[d].Mean;
    this->AreaMaxError[d] = this->NumberOfAreaSamples > 0 ? area[d].Max : std::numeric_limits<double>::quiet_NaN();
    this->AreaMeanError[d] = this->NumberOfAreaSamples > 0 ? area[d].Mean : std::numeric_limits<double>::quiet_NaN();
  }
  this->Diagonal = diagonal;

  CopyWithDistances(reconstruction, reconstructionVertices, output);
  CopyWithDistances(original, originalVertices, originalOutput);
  vtkNew<vtkFieldData> field;
  field->ShallowCopy(reconstruction->GetFieldData());
  AddPair(field, vtkMedialArrayNames::VertexMaxError, this->VertexMaxError);
  AddPair(field, vtkMedialArrayNames::VertexMeanError, this->VertexMeanError);
  AddPair(field, vtkMedialArrayNames::AreaMaxError, this->AreaMaxError);
  AddPair(field, vtkMedialArrayNames::AreaMeanError, this->AreaMeanError);
  output->SetFieldData(field);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialReconstructionError::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DistanceEngine: " << (this->DistanceEngine == BVH ? "BVH" : "CELL_LOCATOR") << "\n";
  os << indent << "NumberOfAreaSamples: " << this->NumberOfAreaSamples << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "VertexMaxError: " << this->VertexMaxError[0] << " " << this->VertexMaxError[1] << "\n";
  os << indent << "VertexMeanError: " << this->VertexMeanError[0] << " " << this->VertexMeanError[1] << "\n";
  os << indent << "AreaMaxError: " << this->AreaMaxError[0] << " " << this->AreaMaxError[1] << "\n";
  os << indent << "AreaMeanError: " << this->AreaMeanError[0] << " " << this->AreaMeanError[1] << "\n";
  os << indent << "Diagonal: " << this->Diagonal << "\n";
}
