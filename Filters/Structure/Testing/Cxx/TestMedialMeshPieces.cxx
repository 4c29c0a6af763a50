// SPDX-License-Identifier: BSD-3-Clause
// Pieces: the medial mesh needs every ball and the whole surface, so piece 0 of 3 builds
// the same mesh as one piece does and pieces 1 and 2 are empty (joining the pieces
// duplicates nothing).
#include "MedialPieceTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialShapeSource.h"

#include "vtkCellArray.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialMeshPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> torus;
  torus->SetShapeToTorus();
  vtkNew<vtkMedialMeshFilter> mesh;
  mesh->SetInputConnection(torus->GetOutputPort());
  mesh->GetSampler()->SetNumberOfSamples(2000);
  return CheckFirstPieceOnly(mesh, "medial mesh", [](vtkPolyData* a, vtkPolyData* b) {
    return a->GetNumberOfPolys() == b->GetNumberOfPolys() && a->GetNumberOfLines() == b->GetNumberOfLines() &&
      a->GetNumberOfPolys() > 0 && PointDifferences(a, b) == 0;
  });
}
