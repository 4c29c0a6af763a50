// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialAxisSampler.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialPolygon.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialAxisSampler);

namespace
{
namespace G = vtkMedialGeometry;

using SampleResult = vtkMedialSampleRecord;

struct BallParameters
{
  int Method;
  double Tolerance; // absolute
  double CosMinAngle;
  int MaximumIterations;
};

// Draws sample `index` on the surface; the vertex order of the triangle does not
// matter (vertices are taken in id order), so re-wound input gives the same point.
void DrawSurfacePoint(const vtkMedialTriangleMesh& mesh, vtkTypeUInt64 seed, vtkIdType index,
  vtkIdType& triangle, double p[3])
{
  vtkMedialSampleRandom random(seed, static_cast<std::uint64_t>(index));
  triangle = mesh.PickTriangleByArea(random.Uniform());
  vtkIdType v[3] = { mesh.GetTriangle(triangle)[0], mesh.GetTriangle(triangle)[1],
    mesh.GetTriangle(triangle)[2] };
  std::sort(v, v + 3);
  // Uniform on the triangle: sqrt warping of two uniforms.
  const double s = std::sqrt(random.Uniform());
  const double t = random.Uniform();
  const double wa = 1.0 - s, wb = s * (1.0 - t), wc = s * t;
  const double* a = mesh.GetPoint(v[0]);
  const double* b = mesh.GetPoint(v[1]);
  const double* c = mesh.GetPoint(v[2]);
  for (int k = 0; k < 3; ++k)
  {
    p[k] = wa * a[k] + wb * b[k] + wc * c[k];
  }
}

// Finds the maximal admissible ball tangent at p (on `triangle`) along the inward normal.
void SolveBall(const vtkMedialSurfaceQuery& query, const vtkMedialTriangleMesh& mesh,
  const BallParameters& param, vtkIdType triangle, const double p[3], SampleResult& out)
{
  out.Valid = false;
  out.Capped = false;
  out.Iterations = 0;
  out.SourceCell = mesh.SourceCellIds[triangle];
  std::copy(p, p + 3, out.Surface);
  const double* outward = mesh.GetNormal(triangle);
  const double n[3] = { -outward[0], -outward[1], -outward[2] };

  vtkMedialSurfaceQuery::RayHit hit;
  if (!query.Intersect(p, n, 1e-9 * mesh.Diagonal, HUGE_VAL, triangle, hit))
  {
    return; // escaped through a hole
  }
  if (G::Dot(mesh.GetNormal(hit.Triangle), n) <= 0.0)
  {
    return; // hit a face from outside: the ray left through a hole
  }
  double q[3];
  G::AddScaled(p, hit.Distance, n, q);

  vtkMedialSurfaceQuery::ContactFilter filter;
  filter.OwnTriangle = triangle;
  std::copy(p, p + 3, filter.SamplePoint);
  filter.CosMinAngle = param.CosMinAngle;

  double centre[3];
  double radius = 0.5 * hit.Distance;
  bool haveContact = false;
  vtkMedialSurfaceQuery::ClosestHit closest;

  if (param.Method == vtkMedialAxisSampler::SHRINKING_BALL)
  {
    for (;;)
    {
      G::AddScaled(p, radius, n, centre);
      if (out.Iterations >= param.MaximumIterations)
      {
        out.Capped = true;
        break;
      }
      ++out.Iterations;
      if (!query.ClosestPoint(centre, radius - query.GetSlack(), closest, &filter))
      {
        break; // empty: maximal, touching the previous blocker
      }
      double pq[3];
      G::Sub(closest.Point, p, pq);
      const double along = G::Dot(n, pq);
      if (!(along > 0.0))
      {
        break; // flat region: the blocker lies on the tangent plane
      }
      const double next = G::Dot(pq, pq) / (2.0 * along);
      if (!(next < radius))
      {
        break; // no progress left at double precision
      }
      radius = next;
      haveContact = true;
    }
  }
  else
  {
    G::AddScaled(p, radius, n, centre);
    ++out.Iterations;
    if (!query.ContainsBall(centre, radius, &filter))
    {
      double lo = 0.0, hi = radius;
      while (hi - lo > param.Tolerance)
      {
        const double mid = 0.5 * (lo + hi);
        G::AddScaled(p, mid, n, centre);
        ++out.Iterations;
        if (query.ContainsBall(centre, mid, &filter))
        {
          lo = mid;
        }
        else
        {
          hi = mid;
        }
      }
      radius = lo;
      G::AddScaled(p, radius, n, centre);
    }
  }

  // Second touching point: the closest blocking point, just beyond the empty ball.
  const double reach = radius + 2.0 * param.Tolerance + 4.0 * query.GetSlack();
  if (!query.ClosestPoint(centre, reach, closest, &filter) &&
    !(haveContact && query.ClosestPoint(centre, radius * (1.0 + 1e-9) + reach, closest, &filter)))
  {
    std::copy(q, q + 3, closest.Point);
  }
  std::copy(centre, centre + 3, out.Centre);
  out.Radius = radius;
  std::copy(closest.Point, closest.Point + 3, out.Contact);
  out.Angle = G::AngleDegrees(centre, p, closest.Point);
  out.Valid = true;
}
}

vtkMedialAxisSampler::vtkMedialAxisSampler() = default;

const char* vtkMedialAxisSampler::GetMethodName(int method)
{
  switch (method)
  {
    case BISECTION:
      return "bisection";
    case SHRINKING_BALL:
      return "shrinking-ball";
    default:
      return "unknown";
  }
}

int vtkMedialAxisSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialAxisSampler::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Rays need the whole surface whatever piece is requested downstream.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int vtkMedialAxisSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->DiscardedSamples = 0;
  this->CappedSamples = 0;
  this->MeanIterations = 0.0;
  this->BoundaryEdges = 0;
  this->NumberOfTriangles = 0;

  // Planar polygons or closed polylines: the 2D mode (vtkMedialAxisSampler2D.cxx).
  if (vtkMedialPolygon::LooksPlanarLoops(input))
  {
    return this->RequestData2D(input, outInfo, output);
  }

  vtkMedialTriangleMesh mesh;
  std::string error;
  if (!mesh.Build(input, error))
  {
    vtkErrorMacro(<< "Cannot sample the medial axis: " << error << ".");
    return 0;
  }
  this->BoundaryEdges = mesh.BoundaryEdges;
  this->NumberOfTriangles = mesh.GetNumberOfTriangles();
  if (mesh.DuplicateTriangles > 0)
  {
    vtkWarningMacro(<< "Input has " << mesh.DuplicateTriangles << " duplicate triangles; they were ignored.");
  }
  if (mesh.NonManifoldEdges > 0)
  {
    vtkWarningMacro(<< "Input has " << mesh.NonManifoldEdges
                    << " non-manifold edges; inside and outside may be ambiguous there.");
  }
  if (mesh.NonOrientableComponents > 0)
  {
    vtkWarningMacro(<< mesh.NonOrientableComponents
                    << " component(s) cannot be oriented consistently (non-orientable surface).");
  }

  vtkMedialSurfaceQuery query;
  if (!query.Build(&mesh, error))
  {
    vtkErrorMacro(<< "Cannot build the surface queries: " << error << ".");
    return 0;
  }

  // This piece's share of the samples; sample indices stay global so that the
  // union of all pieces equals a single-piece run.
  const int piece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
    : 1;
  const vtkIdType total = this->NumberOfSamples;
  const vtkIdType first = total * piece / pieces;
  const vtkIdType last = total * (piece + 1) / pieces;
  const vtkIdType count = last - first;

  // Refuse up front what cannot fit: the per-sample results plus the output arrays.
  const double bytesPerSample = sizeof(SampleResult) + 12 * sizeof(double) + 3 * sizeof(vtkIdType);
  const double needed = bytesPerSample * static_cast<double>(count);
  const double available = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
  if (available > 0 && needed > 0.8 * available)
  {
    vtkErrorMacro(<< "NumberOfSamples " << count << " needs about " << needed / (1 << 30)
                  << " GiB, more than this machine's memory allows (" << available / (1 << 30)
                  << " GiB); use fewer samples or several pieces.");
    return 0;
  }
  std::vector<SampleResult> results;
  try
  {
    results.resize(static_cast<size_t>(count));
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Cannot allocate memory for " << count << " samples.");
    return 0;
  }

  BallParameters param;
  param.Method = this->Method;
  param.Tolerance = this->Tolerance * mesh.Diagonal;
  param.CosMinAngle = this->MinimumSeparationAngle > 0.0
    ? std::cos(this->MinimumSeparationAngle * 3.14159265358979323846 / 180.0)
    : 1.0;
  param.MaximumIterations = this->MaximumIterations;
  const int threads = this->NumberOfThreads > 0 ? this->NumberOfThreads : omp_get_num_procs();

  // Blocks keep UpdateProgress and the abort check on the calling thread; small
  // enough that an abort is honoured within a fraction of a second.
  const vtkIdType block = 256 * threads;
  for (vtkIdType begin = 0; begin < count && !this->GetAbortExecute(); begin += block)
  {
    const vtkIdType end = std::min(count, begin + block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
    for (vtkIdType i = begin; i < end; ++i)
    {
      vtkIdType triangle;
      double p[3];
      DrawSurfacePoint(mesh, this->RandomSeed, first + i, triangle, p);
      SolveBall(query, mesh, param, triangle, p, results[i]);
    }
    this->UpdateProgress(static_cast<double>(end) / static_cast<double>(count));
  }
  if (this->GetAbortExecute())
  {
    return 1; // aborted: leave the output empty
  }

  try
  {
    this->WriteSamples(output, count, results);
  }
  catch (const std::bad_alloc&) // the memory check above does not see ulimit -v
  {
    output->Initialize();
    vtkErrorMacro(<< "Cannot allocate memory for the output of " << count << " samples.");
    return 0;
  }

  if (mesh.BoundaryEdges > 0)
  {
    vtkWarningMacro(<< "Input surface is open (" << mesh.BoundaryEdges << " boundary edges): "
                    << this->DiscardedSamples << " of " << count
                    << " samples were discarded because their ray escaped through a hole.");
  }
  return 1;
}

void vtkMedialAxisSampler::WriteSamples(
  vtkPolyData* output, vtkIdType requested, const std::vector<vtkMedialSampleRecord>& records)
{
  vtkIdType accepted = 0;
  long long iterations = 0;
  for (const vtkMedialSampleRecord& r : records)
  {
    accepted += r.Valid ? 1 : 0;
    iterations += r.Iterations;
    this->CappedSamples += r.Capped ? 1 : 0;
  }
  this->DiscardedSamples = requested - accepted;
  this->MeanIterations = requested > 0 ? static_cast<double>(iterations) / requested : 0.0;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(accepted);
  auto makeArray = [accepted](const char* name, int components) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(accepted);
    return a;
  };
  auto radius = makeArray("Radius", 1);
  auto surface = makeArray("SurfacePoint", 3);
  auto contact = makeArray("ContactPoint", 3);
  auto angle = makeArray("SeparationAngle", 1);
  vtkNew<vtkIdTypeArray> cells;
  cells->SetName("SourceCellId");
  cells->SetNumberOfTuples(accepted);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(accepted);
  vtkIdType k = 0;
  for (const vtkMedialSampleRecord& r : records)
  {
    if (!r.Valid)
    {
      continue;
    }
    points->SetPoint(k, r.Centre);
    radius->SetValue(k, r.Radius);
    surface->SetTypedTuple(k, r.Surface);
    contact->SetTypedTuple(k, r.Contact);
    angle->SetValue(k, r.Angle);
    cells->SetValue(k, r.SourceCell);
    connectivity->SetValue(k, k);
    ++k;
  }
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(accepted + 1);
  for (vtkIdType i = 0; i <= accepted; ++i)
  {
    offsets->SetValue(i, i);
  }
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetActiveScalars("Radius");
  output->GetPointData()->AddArray(surface);
  output->GetPointData()->AddArray(contact);
  output->GetPointData()->AddArray(angle);
  output->GetPointData()->AddArray(cells);

  auto addField = [output](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    output->GetFieldData()->AddArray(a);
  };
  addField("RequestedSamples", static_cast<double>(requested));
  addField("DiscardedSamples", static_cast<double>(this->DiscardedSamples));
  addField("MeanIterations", this->MeanIterations);
  addField("CappedSamples", static_cast<double>(this->CappedSamples));
}

void vtkMedialAxisSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSeparationAngle: " << this->MinimumSeparationAngle << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "DiscardedSamples: " << this->DiscardedSamples << "\n";
  os << indent << "CappedSamples: " << this->CappedSamples << "\n";
  os << indent << "MeanIterations: " << this->MeanIterations << "\n";
}
