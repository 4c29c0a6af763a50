// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialPipeline.h
 * @brief Internal: pipeline requests shared by the filters (header only; the
 * including module links VTK::CommonExecutionModel).
 */
#ifndef vtkMedialPipeline_h
#define vtkMedialPipeline_h

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

/// Asks for the whole of inputs 0 .. numberOfPorts - 1 (one piece, no ghost levels)
/// whatever piece is requested downstream: every part of a surface or of a set of
/// balls can reach every part of the output.
inline void vtkMedialRequestWholeInput(vtkInformationVector** inputVector, int numberOfPorts = 1)
{
  for (int port = 0; port < numberOfPorts; ++port)
  {
    if (vtkInformation* inInfo = inputVector[port]->GetInformationObject(0))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
  }
}

#endif
