// SPDX-License-Identifier: BSD-3-Clause
// Pieces: rays need the whole surface, so piece 0 of 3 measures every vertex exactly as
// one piece does and pieces 1 and 2 are empty (joining the pieces duplicates nothing).
#include "MedialPieceTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"

#include <cmath>
#include <cstdlib>

using namespace medialtest;

int TestMedialThicknessPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> torus;
  torus->SetShapeToTorus();
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputConnection(torus->GetOutputPort());
  return CheckFirstPieceOnly(thickness, "thickness", [](vtkPolyData* a, vtkPolyData* b) {
    vtkDataArray* ta = a->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    vtkDataArray* tb = b->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    if (!ta || !tb || ta->GetNumberOfTuples() != tb->GetNumberOfTuples())
    {
      return false;
    }
    for (vtkIdType i = 0; i < ta->GetNumberOfTuples(); ++i)
    {
      const double x = ta->GetTuple1(i);
      const double y = tb->GetTuple1(i);
      if (!(x == y || (std::isnan(x) && std::isnan(y))))
      {
        return false;
      }
    }
    return PointDifferences(a, b) == 0;
  });
}
