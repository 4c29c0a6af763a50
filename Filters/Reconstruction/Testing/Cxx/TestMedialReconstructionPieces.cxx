// SPDX-License-Identifier: BSD-3-Clause
// Pieces without MPI (serial streaming). Every ball can reach every part of the union,
// and the measures need entire shapes, so piece 0 of 3 is the one-piece output (point
// for point for the union, the same figures for the measures) and pieces 1 and 2 are
// empty: joining the pieces duplicates nothing. The MPI case, where the union gathers
// the balls to process 0, is the pvbatch test of the ParaView build.
#include "MedialPieceTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialReconstructionPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(8);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(1000);
  vtkNew<vtkMedialBallUnion> union_;
  union_->SetInputConnection(sampler->GetOutputPort());
  union_->SetSampleDimensions(40, 40, 40);
  if (CheckFirstPieceOnly(union_, "union", [](vtkPolyData* a, vtkPolyData* b) {
        return a->GetNumberOfPolys() == b->GetNumberOfPolys() && PointDifferences(a, b) == 0;
      }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialReconstructionError> error;
  error->SetOriginalConnection(jack->GetOutputPort());
  error->SetReconstructionConnection(union_->GetOutputPort());
  error->SetNumberOfAreaSamples(500);
  auto sameField = [](const char* name) {
    return [name](vtkPolyData* a, vtkPolyData* b) {
      return FieldValue(a, name) == FieldValue(b, name) && !std::isnan(FieldValue(a, name));
    };
  };
  if (CheckFirstPieceOnly(error, "reconstruction error", sameField("VertexMaxError")) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialBallProtrusion> protrusion;
  protrusion->SetSurfaceConnection(jack->GetOutputPort());
  protrusion->SetBallsConnection(sampler->GetOutputPort());
  if (CheckFirstPieceOnly(protrusion, "protrusion", sameField("MaxProtrusion")) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
