// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the 2D sampler tests.
#ifndef MedialSampler2DTestUtilities_h
#define MedialSampler2DTestUtilities_h

#include "MedialPolygonTestUtilities.h"

#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

namespace medialtest
{
/// A square frame with a rectangular hole, moved into a tilted plane by `tilt`
/// (set here: a rotation of 50 degrees about (0.3, 1, 0.2), then a translation).
inline vtkSmartPointer<vtkPolyData> TiltedFrame(vtkTransform* tilt)
{
  tilt->Translate(1, 2, -3);
  tilt->RotateWXYZ(50, 0.3, 1, 0.2);
  vtkNew<vtkTransformPolyDataFilter> frame;
  frame->SetTransform(tilt);
  frame->SetInputData(MakePolygon({ Rectangle(0, 0, 4, 4), Rectangle(1, 1.5, 2.5, 3) }));
  frame->Update();
  return frame->GetOutput();
}
}

#endif
