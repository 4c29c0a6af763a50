// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallProtrusion.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialProgress.h"
#include "vtkMedialBoundaryDistance.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialThreads.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialBallProtrusion);

vtkMedialBallProtrusion::vtkMedialBallProtrusion()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
}

int vtkMedialBallProtrusion::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialBallProtrusion::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Distances need entire shapes, whatever piece is requested downstream.
  vtkMedialRequestWholeInput(inputVector, 2);
  return 1;
}

int vtkMedialBallProtrusion::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->MaxProtrusion = std::numeric_limits<double>::quiet_NaN();
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* balls = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    this->MaxProtrusion = 0.0;
    return 1; // piece 0 measures every ball
  }
  if (!surface || !balls)
  {
    vtkErrorMacro("Cannot measure the protrusion: both inputs are required (port 0 the surface, port 1 the balls).");
    return 0;
  }
  const vtkIdType n = balls->GetNumberOfPoints();
  vtkDataArray* radius = n > 0 ? this->GetInputArrayToProcess(0, inputVector) : nullptr;
  if (n > 0 && (!radius || radius->GetNumberOfComponents() != 1 || radius->GetNumberOfTuples() != n))
  {
    vtkErrorMacro("Cannot measure the protrusion: the balls need a point data array of one radius per "
                  "point (by default '"
      << vtkMedialArrayNames::Radius << "').");
    return 0;
  }
  vtkMedialBoundaryDistance boundary;
  std::string error;
  vtkMedialStages stages(this);
  stages.Begin("Building the distance queries", 0.0, 0.3);
  if (!boundary.Build(
        surface, vtkMedialBoundaryDistance::IsPlanar(surface), vtkMedialBoundaryDistance::OWN_BVH, error))
  {
    vtkErrorMacro("Cannot measure the protrusion: the surface: " << error << ".");
    return 0;
  }
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  stages.Begin("Measuring the balls", 0.3, 1.0);
  std::vector<double> radii(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    radii[i] = radius->GetComponent(i, 0);
  }
  output->ShallowCopy(balls);
  double worst = 0.0;
  if (this->MaximumOnly)
  {
    worst = boundary.LargestExcess(balls->GetPoints(), radii.data(), threads);
  }
  else
  {
    // The radii as hints: a ball that touches or crosses the surface has d(c) <= r.
    const std::vector<double> distance = boundary.Distances(balls->GetPoints(), threads, radii.data());
    vtkNew<vtkDoubleArray> protrusion;
    protrusion->SetName(vtkMedialArrayNames::Protrusion);
    protrusion->SetNumberOfValues(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double p = radii[i] - distance[i];
      protrusion->SetValue(i, p);
      worst = std::max(worst, p);
    }
    output->GetPointData()->AddArray(protrusion);
  }
  this->MaxProtrusion = worst / surface->GetLength();

  vtkNew<vtkFieldData> field;
  field->ShallowCopy(balls->GetFieldData());
  vtkNew<vtkDoubleArray> largest;
  largest->SetName(vtkMedialArrayNames::MaxProtrusion);
  largest->InsertNextValue(this->MaxProtrusion);
  field->AddArray(largest);
  output->SetFieldData(field);
  return 1;
}

void vtkMedialBallProtrusion::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumOnly: " << this->MaximumOnly << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MaxProtrusion: " << this->MaxProtrusion << "\n";
}
