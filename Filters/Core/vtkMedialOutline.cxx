// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialOutline.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkFeatureEdges.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

vtkSmartPointer<vtkPolyData> vtkMedialOutline::Boundary(vtkPolyData* shape)
{
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  if (!shape || !shape->GetPoints())
  {
    return outline;
  }
  vtkNew<vtkAppendPolyData> append;
  if (shape->GetNumberOfPolys() > 0)
  {
    vtkNew<vtkPolyData> polygons;
    polygons->SetPoints(shape->GetPoints());
    polygons->SetPolys(shape->GetPolys());
    // A triangle soup shares no points: merged, its inner edges have two cells.
    vtkNew<vtkCleanPolyData> merge;
    merge->SetInputData(polygons);
    merge->PointMergingOn();
    merge->SetTolerance(0.0);
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputConnection(merge->GetOutputPort());
    edges->BoundaryEdgesOn();
    edges->FeatureEdgesOff();
    edges->NonManifoldEdgesOff();
    edges->ManifoldEdgesOff();
    edges->ColoringOff();
    append->AddInputConnection(edges->GetOutputPort());
  }
  if (shape->GetNumberOfLines() > 0)
  {
    vtkNew<vtkPolyData> lines;
    lines->SetPoints(shape->GetPoints());
    lines->SetLines(shape->GetLines());
    append->AddInputData(lines);
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return outline;
  }
  append->Update();
  outline->SetPoints(append->GetOutput()->GetPoints());
  outline->SetLines(append->GetOutput()->GetLines());
  return outline;
}
