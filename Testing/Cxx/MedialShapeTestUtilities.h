// SPDX-License-Identifier: BSD-3-Clause
// The tests' one maker of generated shapes (vtkMedialShapeSource): every test family that
// needs a sphere, box, torus, rings, jack... at a resolution builds it here, so the shapes
// of the sampler, structure, thickness and repair tests are made the same way.
#ifndef MedialShapeTestUtilities_h
#define MedialShapeTestUtilities_h

#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <functional>

namespace medialtest
{
/// A generated shape at `resolution`, with any other settings applied by `set`. The copy is
/// detached from the source, so a test may edit its points and cells.
inline vtkSmartPointer<vtkPolyData> MakeShape(
  int shape, int resolution, const std::function<void(vtkMedialShapeSource*)>& set = {})
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->SetResolution(resolution);
  if (set)
  {
    set(source);
  }
  source->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(source->GetOutput());
  return out;
}
}

#endif
