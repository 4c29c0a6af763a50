// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBoundaryDistance.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPlane.h"
#include "vtkMedialPolygon.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>

struct vtkMedialBoundaryDistance::Surface
{
  vtkMedialTriangleMesh Mesh;
  std::unique_ptr<vtkMedialSurfaceQuery> Query; // refers to Mesh; none with the cell locator
  double Centre[3] = { 0, 0, 0 };
  double Reach = 0.0; // every triangle lies within Reach of Centre
};

struct vtkMedialBoundaryDistance::Curves
{
  std::vector<vtkIdType> Ends;   // 2 point ids per segment
  vtkNew<vtkPolyData> Segments;  // the same segments as line cells
  std::vector<double> LengthCdf; // normalised cumulative length, last entry 1
};

struct vtkMedialBoundaryDistance::Locator
{
  vtkSmartPointer<vtkPolyData> Cells;
  vtkNew<vtkStaticCellLocator> Tree;

  explicit Locator(vtkPolyData* cells)
    : Cells(cells)
  {
    this->Tree->SetDataSet(cells);
    this->Tree->BuildLocator();
    cells->BuildCells(); // before the threads: GetCell must not build lazily in parallel
  }
};

vtkMedialBoundaryDistance::vtkMedialBoundaryDistance() = default;
vtkMedialBoundaryDistance::~vtkMedialBoundaryDistance() = default;

namespace
{
// The edges of every polygon (closed) and the segments of every polyline (open), as
// pairs of point ids.
std::vector<vtkIdType> BoundarySegments(vtkPolyData* shape)
{
  std::vector<vtkIdType> ends;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = shape->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      ends.push_back(ids[k]);
      ends.push_back(ids[(k + 1) % n]);
    }
  }
  vtkCellArray* lines = shape->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      ends.push_back(ids[k]);
      ends.push_back(ids[k + 1]);
    }
  }
  return ends;
}
}

bool vtkMedialBoundaryDistance::Build(vtkPolyData* shape, bool curves, int engine, std::string& error)
{
  this->SurfaceEngine.reset();
  this->CurveEngine.reset();
  this->LocatorEngine.reset();
  if (!curves)
  {
    auto surface = std::make_unique<Surface>();
    if (!surface->Mesh.Build(shape, error))
    {
      return false;
    }
    if (engine == OWN_BVH)
    {
      surface->Query = std::make_unique<vtkMedialSurfaceQuery>();
      if (!surface->Query->Build(&surface->Mesh, error))
      {
        return false;
      }
    }
    else
    {
      auto cells = vtkSmartPointer<vtkPolyData>::New();
      cells->ShallowCopy(shape);
      this->LocatorEngine = std::make_unique<Locator>(cells);
    }
    const double* b = surface->Mesh.Bounds;
    for (int k = 0; k < 3; ++k)
    {
      surface->Centre[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
    }
    surface->Reach = 0.5 * surface->Mesh.Diagonal;
    this->SurfaceEngine = std::move(surface);
    return true;
  }

  auto boundary = std::make_unique<Curves>();
  boundary->Ends = BoundarySegments(shape);
  const vtkIdType count = static_cast<vtkIdType>(boundary->Ends.size() / 2);
  vtkNew<vtkCellArray> segments;
  double total = 0.0;
  boundary->LengthCdf.reserve(static_cast<size_t>(count));
  for (vtkIdType e = 0; e < count; ++e)
  {
    const vtkIdType* ends = &boundary->Ends[2 * e];
    segments->InsertNextCell(2, ends);
    double a[3], b[3];
    shape->GetPoint(ends[0], a);
    shape->GetPoint(ends[1], b);
    total += std::sqrt(vtkMedialGeometry::Distance2(a, b));
    boundary->LengthCdf.push_back(total);
  }
  if (!(total > 0.0) || !std::isfinite(total))
  {
    error = count == 0 ? "input has no polygons or lines" : "input boundary has no length";
    return false;
  }
  for (double& c : boundary->LengthCdf)
  {
    c /= total;
  }
  boundary->LengthCdf.back() = 1.0;
  boundary->Segments->SetPoints(shape->GetPoints());
  boundary->Segments->SetLines(segments);
  this->LocatorEngine = std::make_unique<Locator>(boundary->Segments);
  this->CurveEngine = std::move(boundary);
  return true;
}

std::vector<double> vtkMedialBoundaryDistance::Distances(vtkPoints* points, int threads, const double* near) const
{
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::vector<double> distance(static_cast<size_t>(n), HUGE_VAL);
  const Surface* s = this->SurfaceEngine.get();
  if (s && s->Query)
  {
    // Room beyond a hint: rounding of a distance that equals it (a ball's contact).
    const double room = 1e-9 * s->Mesh.Diagonal;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024)
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      vtkMedialSurfaceQuery::ClosestHit hit;
      // Any upper bound is exact where something lies within it; the tree narrows it at
      // each point it finds, but a loose first bound costs a wide first descent.
      const double hint = near ? near[i] : -1.0;
      if (hint >= 0.0 && std::isfinite(hint) && s->Query->ClosestPoint(x, hint * (1.0 + 1e-9) + room, hit))
      {
        distance[i] = hit.Distance;
        continue;
      }
      const double bound = 2.0 * (std::sqrt(vtkMedialGeometry::Distance2(x, s->Centre)) + s->Reach) + 1e-300;
      if (s->Query->ClosestPoint(x, bound, hit))
      {
        distance[i] = hit.Distance;
      }
    }
  }
  else if (const Locator* locator = this->LocatorEngine.get())
  {
#pragma omp parallel num_threads(threads)
    {
      vtkNew<vtkGenericCell> cell;
#pragma omp for schedule(dynamic, 1024)
      for (vtkIdType i = 0; i < n; ++i)
      {
        double x[3], closest[3], d2 = 0.0;
        vtkIdType cellId = -1;
        int subId = 0;
        points->GetPoint(i, x);
        locator->Tree->FindClosestPoint(x, closest, cell, cellId, subId, d2);
        distance[i] = cellId >= 0 ? std::sqrt(d2) : HUGE_VAL;
      }
    }
  }
  return distance;
}

double vtkMedialBoundaryDistance::LargestExcess(vtkPoints* points, const double* radius, int threads) const
{
  const Surface* s = this->SurfaceEngine.get();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (!s || !s->Query)
  {
    const std::vector<double> distance = this->Distances(points, threads);
    double largest = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      largest = std::max(largest, radius[i] - distance[i]);
    }
    return largest;
  }
  // Each thread's running maximum: a point is measured only where its excess would
  // raise it, and the largest of them is exact whatever the order.
  double largest = 0.0;
#pragma omp parallel num_threads(threads)
  {
    double mine = 0.0;
#pragma omp for schedule(dynamic, 1024)
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double reach = radius[i] - mine;
      if (!(reach > 0.0))
      {
        continue;
      }
      double x[3];
      points->GetPoint(i, x);
      vtkMedialSurfaceQuery::ClosestHit hit;
      if (s->Query->ClosestPoint(x, reach, hit))
      {
        mine = std::max(mine, radius[i] - hit.Distance);
      }
    }
#pragma omp critical
    largest = std::max(largest, mine);
  }
  return largest;
}

vtkSmartPointer<vtkPoints> vtkMedialBoundaryDistance::SamplePoints(
  vtkIdType count, vtkTypeUInt64 seed, int threads) const
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(std::max<vtkIdType>(0, count));
  double* xyz = static_cast<double*>(points->GetVoidPointer(0));
  const Surface* s = this->SurfaceEngine.get();
  const Curves* c = this->CurveEngine.get();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (vtkIdType i = 0; i < count; ++i)
  {
    double* p = xyz + 3 * i;
    if (s)
    {
      vtkIdType triangle = -1;
      vtkMedialDrawSurfacePoint(s->Mesh, seed, i, triangle, p);
    }
    else if (c)
    {
      vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(i));
      const double pick = random.Uniform();
      const vtkIdType segment = std::min<vtkIdType>(static_cast<vtkIdType>(c->LengthCdf.size()) - 1,
        std::upper_bound(c->LengthCdf.begin(), c->LengthCdf.end(), pick) - c->LengthCdf.begin());
      const double t = random.Uniform();
      double a[3], b[3];
      c->Segments->GetPoint(c->Ends[2 * segment], a);
      c->Segments->GetPoint(c->Ends[2 * segment + 1], b);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = a[k] + t * (b[k] - a[k]);
      }
    }
  }
  return points;
}

bool vtkMedialBoundaryDistance::IsPlanar(vtkPolyData* shape)
{
  return vtkMedialPlane::IsPlanarLoops(shape);
}

