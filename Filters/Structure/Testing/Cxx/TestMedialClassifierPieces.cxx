// SPDX-License-Identifier: BSD-3-Clause
// Pieces: contacts need the whole surface and the exact points neighbouring balls, so
// piece 0 of 3 classifies every ball exactly as one piece does and pieces 1 and 2 are
// empty (joining the pieces duplicates nothing).
#include "MedialPieceTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialClassifierPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->SetResolution(2);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(box->GetOutputPort());
  sampler->SetNumberOfSamples(1000);
  sampler->SetMinimumSeparationAngle(0);
  vtkNew<vtkMedialBallClassifier> classifier;
  classifier->SetInputConnection(sampler->GetOutputPort());
  classifier->SetSurfaceConnection(box->GetOutputPort());
  classifier->SetMinimumSeparationAngle(0);
  return CheckFirstPieceOnly(classifier, "classifier", [](vtkPolyData* a, vtkPolyData* b) {
    vtkDataArray* ta = a->GetPointData()->GetArray("MedialPointType");
    vtkDataArray* tb = b->GetPointData()->GetArray("MedialPointType");
    if (!ta || !tb || ta->GetNumberOfTuples() != tb->GetNumberOfTuples())
    {
      return false;
    }
    for (vtkIdType i = 0; i < ta->GetNumberOfTuples(); ++i)
    {
      if (ta->GetTuple1(i) != tb->GetTuple1(i))
      {
        return false;
      }
    }
    return PointDifferences(a, b) == 0;
  });
}
