// SPDX-License-Identifier: BSD-3-Clause
// The 2D mode of vtkMedialAxisSampler: planar polygons or closed polylines. Kept in
// its own file, with vtkMedialPolygon as the query backend (the 2D counterpart of
// vtkMedialSurfaceQuery), so the 3D path in vtkMedialAxisSampler.cxx is untouched.
#include "vtkMedialAxisSampler.h"
#include "vtkMedialAxisSamplerInternals.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPolygon.h"
#include "vtkMedialProgress.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialRandom.h"
#include "vtkMedialThreads.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
struct PlanarSample
{
  double Centre[2];
  double Radius;
  double Surface[2];
  double Contact[2];
  double Angle;
  int Edge;
  int Iterations;
  bool Valid;
  bool Capped;
};

// Blockers of the disk (c, r) tangent at p on `edge`: not the own edge, and with a
// separation angle theta > 0 not the cap (q - c).(p - c) > r^2 cos(theta) around p.
vtkMedialPolygon::ContactFilter MakeFilter(
  int edge, const double p[2], const double c[2], double r, double cosMinAngle)
{
  vtkMedialPolygon::ContactFilter f;
  f.IgnoreEdge[0] = edge;
  if (cosMinAngle < 1.0)
  {
    f.UseCap = true;
    f.Cap[0] = p[0] - c[0];
    f.Cap[1] = p[1] - c[1];
    f.CapLimit = r * r * cosMinAngle + f.Cap[0] * c[0] + f.Cap[1] * c[1];
  }
  return f;
}

void Solve2D(const vtkMedialPolygon& poly, int method, double tolerance, double cosMinAngle,
  int maxIterations, int edge, const double p[2], PlanarSample& out)
{
  out.Valid = false;
  out.Capped = false;
  out.Iterations = 0;
  out.Edge = edge;
  out.Surface[0] = p[0];
  out.Surface[1] = p[1];
  const double* n = poly.GetEdge(edge).Normal;
  const double slack = 1e-12 * poly.GetDiagonal();
  vtkMedialPolygon::ContactFilter own;
  own.IgnoreEdge[0] = edge;
  double hit;
  int hitEdge;
  if (!poly.Intersect(p, n, slack, HUGE_VAL, &own, hit, hitEdge))
  {
    return; // cannot happen inside a closed polygon; counted as discarded
  }
  const double q[2] = { p[0] + hit * n[0], p[1] + hit * n[1] };
  double r = 0.5 * hit;
  double c[2] = { p[0] + r * n[0], p[1] + r * n[1] };
  double blocker[2] = { q[0], q[1] };
  bool haveBlocker = false;
  if (method != vtkMedialAxisSampler::BISECTION) // ONE_PASS and SHRINKING_BALL: one method in 2D
  {
    for (;;)
    {
      c[0] = p[0] + r * n[0];
      c[1] = p[1] + r * n[1];
      if (out.Iterations >= maxIterations)
      {
        out.Capped = true;
        break;
      }
      ++out.Iterations;
      const auto filter = MakeFilter(edge, p, c, r, cosMinAngle);
      double x[2], d;
      int g;
      if (!poly.ClosestPoint(c, r - slack, &filter, x, d, g))
      {
        break;
      }
      const double w[2] = { x[0] - p[0], x[1] - p[1] };
      const double along = w[0] * n[0] + w[1] * n[1];
      if (!(along > 0.0))
      {
        break;
      }
      const double next = (w[0] * w[0] + w[1] * w[1]) / (2.0 * along);
      if (!(next < r))
      {
        break;
      }
      r = next;
      blocker[0] = x[0];
      blocker[1] = x[1];
      haveBlocker = true;
    }
  }
  else
  {
    ++out.Iterations;
    const auto first = MakeFilter(edge, p, c, r, cosMinAngle);
    if (!poly.ContainsBall(c, r, &first))
    {
      r = vtkMedialGeometry::BisectLargestEmpty(0.0, r, tolerance,
        [&](double mid) {
          const double m[2] = { p[0] + mid * n[0], p[1] + mid * n[1] };
          const auto filter = MakeFilter(edge, p, m, mid, cosMinAngle);
          return poly.ContainsBall(m, mid, &filter);
        },
        out.Iterations);
    }
    c[0] = p[0] + r * n[0];
    c[1] = p[1] + r * n[1];
  }
  // Second touching point: the closest admissible blocker just beyond the disk.
  const auto filter = MakeFilter(edge, p, c, r, cosMinAngle);
  double x[2], d;
  int g;
  if (poly.ClosestPoint(c, r + 2.0 * tolerance + 4.0 * slack, &filter, x, d, g) ||
    (haveBlocker && poly.ClosestPoint(c, r * (1.0 + 1e-9) + 2.0 * tolerance + 4.0 * slack, &filter, x, d, g)))
  {
    blocker[0] = x[0];
    blocker[1] = x[1];
  }
  out.Centre[0] = c[0];
  out.Centre[1] = c[1];
  out.Radius = r;
  out.Contact[0] = blocker[0];
  out.Contact[1] = blocker[1];
  const double u[2] = { p[0] - c[0], p[1] - c[1] }, v[2] = { blocker[0] - c[0], blocker[1] - c[1] };
  out.Angle = std::atan2(std::abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]) *
    (180.0 / 3.14159265358979323846);
  out.Valid = true;
}
}

int vtkMedialAxisSampler::vtkInternals::Sample2D(
  vtkPolyData* input, const vtkMedialPieces& pieces, vtkPolyData* output, vtkMedialStages& stages)
{
  vtkMedialAxisSampler* self = this->Self;
  vtkMedialPolygon poly;
  std::string error;
  stages.Begin("Preparing the polygon", 0.0, 0.05);
  if (!poly.Build(input, error))
  {
    vtkErrorWithObjectMacro(self, << "Cannot sample the medial axis: " << error << ".");
    return 0;
  }
  self->NumberOfTriangles = 0;
  self->BoundaryEdges = 0;
  const vtkIdType total = self->NumberOfSamples;
  vtkIdType first = 0;
  vtkIdType count = total;
  pieces.GetShare(total, first, count); // disks are solved independently: any split will do

  // Edges are drawn with probability proportional to their length.
  std::vector<double> cumulative(static_cast<size_t>(poly.GetNumberOfEdges()));
  double length = 0.0;
  for (int e = 0; e < poly.GetNumberOfEdges(); ++e)
  {
    length += poly.GetEdge(e).Length;
    cumulative[e] = length;
  }
  std::vector<PlanarSample> results;
  if (!this->Allocate(count, results))
  {
    return 0;
  }
  const double tolerance = self->Tolerance * poly.GetDiagonal();
  const double cosMinAngle = self->MinimumSeparationAngle > 0.0
    ? std::cos(self->MinimumSeparationAngle * 3.14159265358979323846 / 180.0)
    : 1.0;
  const int threads = vtkMedialThreadCount(self->NumberOfThreads);
  const vtkIdType block = 8192;
  stages.Begin("Sampling", 0.05, 1.0);
  for (vtkIdType begin = 0; begin < count && !self->GetAbortExecute(); begin += block)
  {
    const vtkIdType end = std::min(count, begin + block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
    for (vtkIdType i = begin; i < end; ++i)
    {
      vtkMedialSampleRandom random(static_cast<std::uint64_t>(self->RandomSeed), static_cast<std::uint64_t>(first + i));
      const double pick = random.Uniform() * length;
      const int e = static_cast<int>(
        std::min<size_t>(cumulative.size() - 1,
          std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
      const double t = random.Uniform();
      const double* a = poly.GetPoint(poly.GetEdge(e).A);
      const double* b = poly.GetPoint(poly.GetEdge(e).B);
      const double p[2] = { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) };
      Solve2D(poly, self->Method, tolerance, cosMinAngle, self->MaximumIterations, e, p, results[i]);
    }
    self->UpdateProgress(static_cast<double>(end) / static_cast<double>(count));
  }
  if (self->GetAbortExecute())
  {
    return 1;
  }

  // Back to 3D coordinates, then the output shared with the 3D path.
  std::vector<vtkMedialSampleRecord> records(results.size());
  for (size_t i = 0; i < results.size(); ++i)
  {
    const PlanarSample& r = results[i];
    vtkMedialSampleRecord& record = records[i];
    record.Valid = r.Valid;
    record.Capped = r.Capped;
    record.Iterations = r.Iterations;
    if (!r.Valid)
    {
      continue;
    }
    poly.To3D(r.Centre, record.Centre);
    poly.To3D(r.Surface, record.Surface);
    poly.To3D(r.Contact, record.Contact);
    record.Radius = r.Radius;
    record.Angle = r.Angle;
    record.SourceCell = poly.GetEdge(r.Edge).SourceCell;
  }
  this->WriteSamples(output, count, records.data(), static_cast<vtkIdType>(records.size()));
  return 1;
}
