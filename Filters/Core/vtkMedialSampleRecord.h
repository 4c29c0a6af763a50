// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialSampleRecord.h
 * @brief One medial sample as the sampler's 2D and 3D paths produce it, before it
 * becomes a vertex of the output (see vtkMedialAxisSampler::WriteSamples).
 * Internal header; not installed.
 */
#ifndef vtkMedialSampleRecord_h
#define vtkMedialSampleRecord_h

#include "vtkType.h"

struct vtkMedialSampleRecord
{
  double Centre[3];
  double Radius;
  double Surface[3]; // the sample P
  double Contact[3]; // the second touching point
  double Angle;      // P-centre-contact, degrees
  vtkIdType SourceCell;
  vtkIdType ContactTriangle; // ONE_PASS: the triangle where the angle rule's ball stopped
                             // (a hint for the next sample), else -1
  int Iterations;
  bool Valid; // false: discarded (ray escaped, degenerate start)
  bool Capped;
  bool Shrunk; // the cap's surface entered it: shrunk about its centre to be inscribed
};

#endif
