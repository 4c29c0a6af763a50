// SPDX-License-Identifier: BSD-3-Clause
// Pieces without MPI (serial streaming): every ball can reach every part of the
// union, so piece 0 of 3 is the one-piece surface, point for point, and pieces 1 and
// 2 are empty (no duplicated surface when the pieces are joined). The MPI case, where
// the balls are gathered to process 0, is the pvbatch test of the ParaView build.
#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialBallUnionPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(8);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(1000);
  vtkNew<vtkMedialBallUnion> union_;
  union_->SetInputConnection(sampler->GetOutputPort());
  union_->SetSampleDimensions(40, 40, 40);
  union_->UpdatePiece(0, 1, 0);
  vtkNew<vtkPolyData> whole;
  whole->DeepCopy(union_->GetOutput());
  MEDIAL_CHECK(whole->GetNumberOfPolys() > 100, "only %lld triangles",
    static_cast<long long>(whole->GetNumberOfPolys()));

  union_->UpdatePiece(0, 3, 0);
  vtkPolyData* first = union_->GetOutput();
  MEDIAL_CHECK(first->GetNumberOfPolys() == whole->GetNumberOfPolys(), "piece 0 of 3: %lld triangles, one piece %lld",
    static_cast<long long>(first->GetNumberOfPolys()), static_cast<long long>(whole->GetNumberOfPolys()));
  const long long differ = PointDifferences(whole, first);
  MEDIAL_CHECK(differ == 0, "piece 0 of 3 differs from one piece in %lld points (-1: count)", differ);
  for (int p : { 1, 2 })
  {
    union_->UpdatePiece(p, 3, 0);
    MEDIAL_CHECK(union_->GetOutput()->GetNumberOfPoints() == 0, "piece %d of 3 is not empty", p);
  }
  std::printf("piece 0 of 3: the whole union (%lld triangles); pieces 1 and 2 empty\n",
    static_cast<long long>(whole->GetNumberOfPolys()));
  return EXIT_SUCCESS;
}
