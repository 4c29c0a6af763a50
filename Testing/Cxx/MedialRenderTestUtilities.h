// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the image regression tests that show a surface with its medial
// points: the surface as a light translucent shell, the points coloured by Radius.
#ifndef MedialRenderTestUtilities_h
#define MedialRenderTestUtilities_h

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSmartPointer.h"

namespace medialtest
{
/// The surface as a light grey shell, 80% transparent.
inline vtkSmartPointer<vtkActor> TranslucentSurface(vtkAlgorithmOutput* surface)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(surface);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.8, 0.82, 0.86);
  actor->GetProperty()->SetOpacity(0.2);
  return actor;
}

/// The medial points (and any lines) coloured by their Radius array, blue to red.
inline vtkSmartPointer<vtkActor> RadiusColoured(vtkPolyData* medial)
{
  double range[2];
  medial->GetPointData()->GetArray("Radius")->GetRange(range);
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(range);
  lut->Build();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(medial);
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(range);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Radius");
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
}

#endif
