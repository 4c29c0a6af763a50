// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPointCloud.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

namespace vtkMedialPointCloud
{
vtkSmartPointer<vtkStaticPointLocator> Locator(const double* xyz, vtkIdType count)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  // save = 1: the array reads the caller's memory and never frees it. The locator only
  // reads the points, so the const_cast does not let anything write through it.
  coordinates->SetArray(const_cast<double*>(xyz), 3 * count, 1);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(cloud); // the locator keeps the cloud alive
  locator->BuildLocator();
  return locator;
}
}
