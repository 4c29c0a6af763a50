// SPDX-License-Identifier: BSD-3-Clause
// Pieces: the medial graph needs the whole polygon, so piece 0 of 3 is the one-piece
// graph and pieces 1 and 2 are empty (no duplicated graph when the pieces are joined).
#include "MedialPolygonTestUtilities.h"
#include "MedialPieceTestUtilities.h"

#include "vtkMedialJunctionFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialJunctionPieces(int, char*[])
{
  vtkSmartPointer<vtkPolyData> frame =
    MakePolygon({ Rectangle(-2, -2, 2, 2), Rectangle(-1, -1, 1, 1) });
  vtkNew<vtkMedialJunctionFilter> filter;
  filter->SetInputData(frame);
  return CheckFirstPieceOnly(filter, "2D graph", [](vtkPolyData* a, vtkPolyData* b) {
    return a->GetNumberOfLines() == b->GetNumberOfLines() && PointDifferences(a, b) == 0;
  });
}
