// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPieces
 * @brief How the medialaxis filters run when the pipeline asks for pieces (ParaView,
 * pvbatch under mpiexec, VTK streaming).
 *
 * Every filter is in one of three cases; each class header says which in its
 * "Pieces:" paragraph.
 *  - Split: the filter asks every piece for its whole input (vtkMedialRequestWholeInput
 *    in vtkMedialPipeline.h: the
 *    rays of the sampler need the whole surface) and computes its share of the work;
 *    the union of the pieces equals a one-piece run (vtkMedialAxisSampler, RANDOM).
 *  - First piece: the result needs all of the input and the work is sequential
 *    (the 2D medial graph, the iterative sampling strategies, a coverage stop, the
 *    measures vtkMedialReconstructionError and vtkMedialBallProtrusion, the 3D
 *    classifier vtkMedialBallClassifier, the wall thickness vtkMedialThickness, the
 *    medial mesh vtkMedialMeshFilter). The
 *    filter asks for the whole input and computes in piece 0; the other pieces stay
 *    empty and skip all work.
 *  - Gather: the result needs all of the input, which upstream pieces hold apart
 *    (the reconstruction of the sampler's balls). With one process per piece (an MPI
 *    controller whose ranks match the pieces) every process keeps its own piece of
 *    the input and GatherToFirst sends it to process 0, which computes; without one
 *    the filter asks for the whole input as in the first-piece case.
 * Pieces are decided from the request on output port 0 and the global controller
 * only, so every process takes the same branch: a gather is a collective call that
 * every process reaches, even one that has nothing to send or failed.
 */
#ifndef vtkMedialPieces_h
#define vtkMedialPieces_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkIdType

#include <string> // for std::string

class vtkDataArray;
class vtkInformation;
class vtkMultiProcessController;
class vtkPointSet;
class vtkPolyData;

class vtkMedialPieces
{
public:
  /// The piece requested on an output port's information (0 of 1 when none is).
  static vtkMedialPieces FromRequest(vtkInformation* outInfo);


  int Piece = 0;
  int NumberOfPieces = 1;

  bool IsFirst() const { return this->Piece == 0; }
  /// This piece's share [first, first + count) of `total` work items (sample
  /// indices): contiguous, in piece order, covering all of them exactly once.
  void GetShare(vtkIdType total, vtkIdType& first, vtkIdType& count) const
  {
    first = total * this->Piece / this->NumberOfPieces;
    count = total * (this->Piece + 1) / this->NumberOfPieces - first;
  }
  /// True when each piece is computed by its own process of the global controller,
  /// so that GatherToFirst reaches every piece.
  bool IsDistributed() const { return this->Controller != nullptr; }

  /// Collective over the controller's processes (call it on every one when
  /// IsDistributed()). Each process sends the points of its piece of `input` and
  /// the values of `values` (one component; may be null when the piece is empty or
  /// lacks the array). On process 0 the result holds every process's points in
  /// rank order, with their values in a double array of that name; elsewhere it is
  /// null. Sets `error` on process 0 when a piece has points but no one-component
  /// values.
  vtkSmartPointer<vtkPolyData> GatherToFirst(
    vtkPointSet* input, vtkDataArray* values, const char* name, std::string& error) const;

private:
  vtkMultiProcessController* Controller = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkMedialPieces.h
