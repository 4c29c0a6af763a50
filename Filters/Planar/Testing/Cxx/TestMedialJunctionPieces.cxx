// SPDX-License-Identifier: BSD-3-Clause
// Pieces: the medial graph needs the whole polygon, so piece 0 of 3 is the one-piece
// graph and pieces 1 and 2 are empty (no duplicated graph when the pieces are joined).
#include "MedialPolygonTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkMedialJunctionFilter.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialJunctionPieces(int, char*[])
{
  vtkSmartPointer<vtkPolyData> frame =
    MakePolygon({ Rectangle(-2, -2, 2, 2), Rectangle(-1, -1, 1, 1) });
  vtkNew<vtkMedialJunctionFilter> filter;
  filter->SetInputData(frame);
  filter->UpdatePiece(0, 1, 0);
  vtkNew<vtkPolyData> whole;
  whole->DeepCopy(filter->GetOutput());
  MEDIAL_CHECK(whole->GetNumberOfPoints() > 0 && whole->GetNumberOfLines() > 0, "empty graph");

  filter->UpdatePiece(0, 3, 0);
  vtkPolyData* first = filter->GetOutput();
  MEDIAL_CHECK(first->GetNumberOfPoints() == whole->GetNumberOfPoints() &&
      first->GetNumberOfLines() == whole->GetNumberOfLines(),
    "piece 0 of 3 has %lld points and %lld arcs, one piece %lld and %lld",
    static_cast<long long>(first->GetNumberOfPoints()), static_cast<long long>(first->GetNumberOfLines()),
    static_cast<long long>(whole->GetNumberOfPoints()), static_cast<long long>(whole->GetNumberOfLines()));
  for (int p : { 1, 2 })
  {
    filter->UpdatePiece(p, 3, 0);
    MEDIAL_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0, "piece %d of 3 is not empty", p);
  }
  std::printf("piece 0 of 3: the whole graph (%lld points, %lld arcs); pieces 1 and 2 empty\n",
    static_cast<long long>(whole->GetNumberOfPoints()), static_cast<long long>(whole->GetNumberOfLines()));
  return EXIT_SUCCESS;
}
