// SPDX-License-Identifier: BSD-3-Clause
// The check shared by the piece tests of the filters that compute in piece 0 only
// (vtkMedialPieces.h): piece 0 of 3 is the one-piece output and pieces 1 and 2 are empty.
#ifndef MedialPieceTestUtilities_h
#define MedialPieceTestUtilities_h

#include "MedialTestUtilities.h"

#include "vtkPolyDataAlgorithm.h"

#include <cstdlib>

namespace medialtest
{
/// EXIT_SUCCESS when piece 0 of 3 of `filter` matches its one-piece output according
/// to `same(whole, piece0)` and pieces 1 and 2 have no points.
template <typename Same>
int CheckFirstPieceOnly(vtkPolyDataAlgorithm* filter, const char* what, Same same)
{
  filter->UpdatePiece(0, 1, 0);
  vtkNew<vtkPolyData> whole;
  whole->DeepCopy(filter->GetOutput());
  MEDIAL_CHECK(whole->GetNumberOfPoints() > 0, "%s: the one-piece output is empty", what);
  filter->UpdatePiece(0, 3, 0);
  MEDIAL_CHECK(same(whole.Get(), filter->GetOutput()), "%s: piece 0 of 3 differs from one piece", what);
  for (int p : { 1, 2 })
  {
    filter->UpdatePiece(p, 3, 0);
    MEDIAL_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0, "%s: piece %d of 3 is not empty", what, p);
  }
  std::printf("%s: piece 0 of 3 is the whole output (%lld points); pieces 1 and 2 are empty\n", what,
    static_cast<long long>(whole->GetNumberOfPoints()));
  return EXIT_SUCCESS;
}
}

#endif
