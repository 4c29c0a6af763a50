// SPDX-License-Identifier: BSD-3-Clause
// Distance between a reconstruction and the original surface, both directions,
// shared by the medial-axis CLI and medial-reconstruct-bench.
//
// Each direction measures the exact distance from every vertex of one surface to
// the triangles of the other (vtkStaticCellLocator closest point), relative to the
// bounding-box diagonal of the original. Vertices only: between vertices a surface
// may stray further, by at most its edge length.
#ifndef MedialReconstructionError_h
#define MedialReconstructionError_h

#include "vtkMedialArrayNames.h"
#include "vtkGenericCell.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace medialbench
{
struct DirectionalError
{
  double Max = 0.0;
  double Mean = 0.0;
};

struct ReconstructionError
{
  DirectionalError ToOriginal;       // reconstruction vertices -> original surface
  DirectionalError ToReconstruction; // original vertices -> reconstruction
  double MaxRel() const { return std::max(ToOriginal.Max, ToReconstruction.Max); }
  double MeanRel() const { return std::max(ToOriginal.Mean, ToReconstruction.Mean); }
};

/// Distance from every point of `points` to the surface `to`, computed in parallel.
inline std::vector<double> DistancesToSurface(vtkPolyData* points, vtkPolyData* to, int threads)
{
  const vtkIdType n = points->GetNumberOfPoints();
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  to->BuildCells(); // before the threads: GetCell must not build lazily in parallel
  std::vector<double> distance(static_cast<size_t>(n));
#pragma omp parallel num_threads(threads)
  {
    vtkNew<vtkGenericCell> cell;
#pragma omp for schedule(dynamic, 1024)
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3], closest[3], d2 = 0.0;
      vtkIdType cellId = -1;
      int subId = 0;
      points->GetPoint(i, p);
      locator->FindClosestPoint(p, closest, cell, cellId, subId, d2);
      distance[i] = std::sqrt(d2);
    }
  }
  return distance;
}

/// Vertex-to-surface distances from `from` to `to`, divided by `scale`.
inline DirectionalError VertexToSurface(vtkPolyData* from, vtkPolyData* to, double scale, int threads)
{
  DirectionalError e;
  const vtkIdType n = from->GetNumberOfPoints();
  if (n == 0 || to->GetNumberOfCells() == 0)
  {
    e.Max = e.Mean = HUGE_VAL;
    return e;
  }
  double sum = 0.0;
  for (double d : DistancesToSurface(from, to, threads)) // fixed order: the mean does not depend on the threads
  {
    e.Max = std::max(e.Max, d);
    sum += d;
  }
  e.Max /= scale;
  e.Mean = sum / n / scale;
  return e;
}

/// How far the balls cross the surface: max over balls of (radius - distance from the
/// centre to the surface), divided by `scale`; 0 when every ball is empty. Centres are
/// assumed inside. The union can leave the surface by exactly this much.
inline double BallProtrusion(vtkPolyData* balls, vtkPolyData* surface, double scale, int threads)
{
  vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  const vtkIdType n = balls->GetNumberOfPoints();
  if (!radius || n == 0)
  {
    return 0.0;
  }
  const std::vector<double> distance = DistancesToSurface(balls, surface, threads);
  double worst = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    worst = std::max(worst, radius->GetTuple1(i) - distance[i]);
  }
  return worst / scale;
}

/// Both directions, relative to the diagonal of `original`.
inline ReconstructionError MeasureReconstruction(vtkPolyData* original, vtkPolyData* reconstruction, int threads)
{
  const double diagonal = original->GetLength();
  ReconstructionError r;
  r.ToOriginal = VertexToSurface(reconstruction, original, diagonal, threads);
  r.ToReconstruction = VertexToSurface(original, reconstruction, diagonal, threads);
  return r;
}
}

#endif
