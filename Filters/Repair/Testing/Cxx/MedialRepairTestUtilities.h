// SPDX-License-Identifier: BSD-3-Clause
// What the repair tests and medial-repair-bench measure on a defect: the sampler's balls
// against the true solid (inside it, not stopped short, the largest) and the medial
// mesh's topology, each pipeline stage with the given RepairMode.
#ifndef MedialRepairTestUtilities_h
#define MedialRepairTestUtilities_h

#include "MedialDefectTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialRepairFilter.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace medialtest
{
struct DefectResult
{
  vtkIdType Balls = 0;
  vtkIdType Discarded = 0;
  double LargestBall = 0.0;
  vtkIdType Outside = 0;     // balls that cross the true solid's boundary by more than the tolerance
  vtkIdType Short = 0;       // balls smaller than the true solid allows at their centre (stopped by buried surface)
  double WorstOutside = 0.0; // the deepest crossing of the true boundary, absolute
  double WorstShort = 0.0;   // the largest shortfall, absolute
  vtkIdType Euler = 0;       // the medial mesh's
  vtkIdType Components = 0;
  double SampleSeconds = 0.0;
  double MeshSeconds = 0.0;
};

/// Samples `defect` (20k samples by default) and builds its medial mesh, both with
/// `mode`; measures the balls against the true solid with its tolerance plus the
/// sampler's protrusion allowance.
inline DefectResult MeasureDefect(const Defect& defect, int mode, vtkIdType samples = 20000, bool mesh = true)
{
  using Clock = std::chrono::steady_clock;
  DefectResult r;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(defect.Surface);
  sampler->SetNumberOfSamples(samples);
  sampler->SetRepairMode(mode);
  auto start = Clock::now();
  sampler->Update();
  r.SampleSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  vtkPolyData* balls = sampler->GetOutput();
  r.Balls = balls->GetNumberOfPoints();
  r.Discarded = sampler->GetDiscardedSamples();
  vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  const double tolerance = defect.Tolerance + 2e-4 * defect.Surface->GetLength();
  for (vtkIdType i = 0; radius && i < r.Balls; ++i)
  {
    double c[3];
    balls->GetPoint(i, c);
    const double radiusHere = radius->GetComponent(i, 0);
    const double depth = defect.Depth(c);
    r.LargestBall = std::max(r.LargestBall, radiusHere);
    if (radiusHere > depth + tolerance)
    {
      // Depth is exact in sign but only a lower bound of the distance for a union (the
      // tube's own wall can be buried in the other tube): the ball's sphere, sampled at
      // 2000 Fibonacci points, must then stay inside.
      double worst = 0.0;
      const int points = 2000;
      for (int k = 0; k < points; ++k)
      {
        const double z = 1.0 - (2.0 * k + 1.0) / points, rho = std::sqrt(1.0 - z * z);
        const double phi = 2.399963229728653 * k;
        const double p[3] = { c[0] + radiusHere * rho * std::cos(phi), c[1] + radiusHere * rho * std::sin(phi),
          c[2] + radiusHere * z };
        worst = std::max(worst, -defect.Depth(p));
      }
      if (worst > tolerance)
      {
        ++r.Outside;
        r.WorstOutside = std::max(r.WorstOutside, worst);
      }
    }
    if (radiusHere < depth - tolerance)
    {
      ++r.Short;
      r.WorstShort = std::max(r.WorstShort, depth - radiusHere);
    }
  }
  if (mesh)
  {
    vtkNew<vtkMedialMeshFilter> filter;
    filter->SetInputData(defect.Surface);
    filter->SetBallsConnection(sampler->GetOutputPort());
    filter->SetRepairMode(mode);
    start = Clock::now();
    filter->Update();
    r.MeshSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.Euler = filter->GetEulerCharacteristic();
    r.Components = filter->GetNumberOfComponents();
  }
  return r;
}
}

#endif
