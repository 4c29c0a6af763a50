// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialDenoiseFilter.h"

#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkMedialDenoiseFilter);

vtkMedialDenoiseFilter::vtkMedialDenoiseFilter()
{
  this->SetNumberOfIterations(20);
  this->SetPassBand(0.03);
  this->NormalizeCoordinatesOn();
  this->BoundarySmoothingOff();
  this->FeatureEdgeSmoothingOff();
  this->NonManifoldSmoothingOn();
}

int vtkMedialDenoiseFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->MaximumDisplacement = 0.0;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
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
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  if (output->GetNumberOfPoints() != n)
  {
    vtkErrorMacro("Cannot denoise: the smoothing returned " << output->GetNumberOfPoints() << " points for " << n
                                                            << ".");
    output->Initialize();
    return 0;
  }
  output->GetPointData()->SetNormals(nullptr); // the input's normals no longer fit
  double largest = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    output->GetPoint(i, b);
    largest = std::max(largest, vtkMath::Distance2BetweenPoints(a, b));
  }
  const double diagonal = input->GetLength();
  this->MaximumDisplacement = diagonal > 0.0 ? std::sqrt(largest) / diagonal : 0.0;
  return 1;
}

void vtkMedialDenoiseFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumDisplacement: " << this->MaximumDisplacement << "\n";
}
