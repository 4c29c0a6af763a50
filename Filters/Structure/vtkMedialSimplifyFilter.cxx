// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSimplifyFilter.h"
#include "vtkMedialArrayNames.h"

#include "vtkMedialCoverageSelection.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialQuadricSimplification.h"
#include "vtkMedialRandom.h"
#include "vtkMedialRepairCallback.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidPreparation.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialSimplicialComplex.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <string>
#include <vector>

#include <omp.h>

vtkStandardNewMacro(vtkMedialSimplifyFilter);

namespace
{
// COVERAGE: choices made again with the balls no collapse could remove.
constexpr int CoverageAttempts = 6;
// QUADRIC: the surface vertices that guard the collapses, at most.
constexpr vtkIdType MaximumGuardPoints = 20000;
}

vtkMedialSimplifyFilter::vtkMedialSimplifyFilter()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
  this->Repair = vtkMedialRepairFilter::New();
}

vtkMedialSimplifyFilter::~vtkMedialSimplifyFilter()
{
  this->SetRepair(nullptr);
}

vtkCxxSetObjectMacro(vtkMedialSimplifyFilter, Repair, vtkMedialRepairFilter);

vtkMTimeType vtkMedialSimplifyFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->Repair ? std::max(time, this->Repair->GetMTime()) : time;
}

const char* vtkMedialSimplifyFilter::GetMethodName(int method)
{
  return method == COVERAGE ? "coverage" : (method == QUADRIC ? "quadric" : "unknown");
}

int vtkMedialSimplifyFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkMedialSimplifyFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Collapses run across pieces: simplify the whole mesh (and cover the whole surface).
  vtkMedialRequestWholeInput(inputVector, 2);
  return 1;
}

int vtkMedialSimplifyFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfBlockedCollapses = this->EulerCharacteristic = this->NumberOfComponents = 0;
  this->CoveredDilation = 0.0;
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0)
  {
    return 1;
  }
  vtkDataArray* radius = this->GetInputArrayToProcess(0, inputVector);
  if (!radius || radius->GetNumberOfComponents() != 1 || radius->GetNumberOfTuples() != n)
  {
    vtkErrorMacro(<< "Cannot simplify: the medial mesh needs a point data array of one radius per point (by "
                     "default '"
                  << vtkMedialArrayNames::Radius << "').");
    return 0;
  }
  if (input->GetNumberOfLines() + input->GetNumberOfPolys() == 0 && n > this->NumberOfBalls)
  {
    vtkErrorMacro(<< "Cannot simplify: the input has balls but no edges or triangles; simplification works on a "
                     "medial mesh (vtkMedialMeshFilter).");
    return 0;
  }
  vtkMedialSimplicialComplex complex;
  std::string error;
  if (!complex.Read(input, radius, error))
  {
    vtkErrorMacro(<< "Cannot simplify: " << error << ".");
    return 0;
  }
  const auto aborted = [this]() { return this->GetAbortExecute() != 0; };
  vtkMedialQuadricSimplification simplification;
  simplification.RimWeight = this->Method == QUADRIC ? this->RimWeight : 0.0;
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[1], 0);
  const bool guarded = surface && this->Method == QUADRIC && this->ErrorTolerance > 0.0;
  vtkMedialTriangleMesh mesh;
  if (surface && (guarded || this->Method == COVERAGE))
  {
    // The surface as RepairMode says (NONE: the mesh alone, as before).
    std::string surfaceError;
    vtkMedialSurfaceQuery query;
    vtkMedialSolidPreparation preparation;
    const int prepareThreads = vtkMedialThreadCount(this->NumberOfThreads);
    const bool prepared = this->RepairMode == vtkMedialRepairFilter::NONE
      ? mesh.Build(surface, surfaceError, aborted)
      : preparation.Prepare(surface, this->RepairMode, vtkMedialMakeRepairer(this->Repair, prepareThreads),
          prepareThreads, mesh, query, surfaceError, aborted);
    for (const std::string& message : preparation.GetMessages())
    {
      if (message.rfind("Repair: ", 0) == 0)
      {
        vtkWarningMacro(<< message);
      }
    }
    if (!prepared)
    {
      if (this->GetAbortExecute())
      {
        return 1;
      }
      vtkErrorMacro(<< "Cannot simplify: the surface on input 1: " << surfaceError << ".");
      return 0;
    }
  }
  else if (this->Method == COVERAGE)
  {
    vtkErrorMacro(<< "Cannot simplify by coverage: connect the surface to input 1 (SetSurfaceConnection).");
    return 0;
  }
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  if (guarded)
  {
    this->SetGuardPoints(mesh, simplification);
    simplification.NumberOfThreads = threads;
  }
  if (this->Method == COVERAGE && n > this->NumberOfBalls)
  {
    // Balls that no collapse can remove are chosen in the next attempt, so that the
    // chosen balls stay; the last attempt lets chosen balls go instead.
    std::vector<char> forced(static_cast<size_t>(n), 0);
    for (int attempt = 0; attempt < CoverageAttempts; ++attempt)
    {
      std::vector<char> kept;
      if (!this->ChooseByCoverage(complex, mesh, threads, forced, kept))
      {
        return this->GetAbortExecute() ? 1 : 0;
      }
      this->UpdateProgress(0.5);
      if (!simplification.RunKeeping(complex, kept, attempt + 1 == CoverageAttempts, aborted))
      {
        return 1;
      }
      vtkIdType stuck = 0;
      for (vtkIdType v : simplification.Source)
      {
        stuck += !kept[v] && !forced[v];
        forced[v] = forced[v] || !kept[v];
      }
      if (stuck == 0)
      {
        break;
      }
    }
  }
  else if (!simplification.Run(complex, this->NumberOfBalls, aborted))
  {
    return 1;
  }
  const vtkIdType kept = static_cast<vtkIdType>(simplification.Radii.size());
  if (kept > this->NumberOfBalls)
  {
    this->NumberOfBlockedCollapses = simplification.BlockedCollapses;
    vtkWarningMacro(<< kept << " balls are left instead of " << this->NumberOfBalls
                    << ": every remaining collapse would change the topology.");
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(kept);
  vtkNew<vtkDoubleArray> radii;
  radii->SetName(vtkMedialArrayNames::Radius);
  radii->SetNumberOfTuples(kept);
  for (vtkIdType v = 0; v < kept; ++v)
  {
    points->SetPoint(v, &simplification.Points[3 * v]);
    radii->SetValue(v, simplification.Radii[v]);
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(radii);
  output->GetPointData()->SetActiveScalars(vtkMedialArrayNames::Radius);
  const auto cells = vtkMedialSimplicialComplex::WriteCells(
    kept, simplification.Edges, simplification.EdgeTriangles, simplification.Triangles, output);
  vtkNew<vtkIntArray> types;
  types->SetName(vtkMedialArrayNames::MedialPointType);
  types->SetNumberOfTuples(kept);
  for (vtkIdType v = 0; v < kept; ++v)
  {
    types->SetValue(v, cells.PointTypes[v]);
  }
  output->GetPointData()->AddArray(types);

  // The topology of the result, counted from its own complex.
  vtkMedialSimplicialComplex result;
  result.Points = simplification.Points;
  result.Radii = simplification.Radii;
  result.Assemble(kept, simplification.Edges, simplification.Triangles);
  const std::vector<char> allVertices(static_cast<size_t>(kept), 1);
  const std::vector<char> allEdges(result.Edges.size(), 1);
  const std::vector<char> allTriangles(result.Triangles.size(), 1);
  this->EulerCharacteristic = vtkMedialSimplicialComplex::EulerCharacteristic(allVertices, allEdges, allTriangles);
  this->NumberOfComponents = result.CountComponents(allVertices, allEdges);
  // Collapses keep the topology: the input's figures (the medial mesh's and the solid's) hold.
  output->GetFieldData()->PassData(input->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialSimplifyFilter::SetGuardPoints(
  const vtkMedialTriangleMesh& mesh, vtkMedialQuadricSimplification& simplification) const
{
  // The surface's vertices (those of its triangles), where its corners are; at most
  // MaximumGuardPoints of them, every k-th, on very fine meshes.
  std::vector<char> used(static_cast<size_t>(mesh.GetNumberOfPoints()), 0);
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      used[mesh.GetTriangle(t)[k]] = 1;
    }
  }
  const vtkIdType count = static_cast<vtkIdType>(std::count(used.begin(), used.end(), 1));
  const vtkIdType stride = (count + MaximumGuardPoints - 1) / MaximumGuardPoints;
  vtkIdType seen = 0;
  for (vtkIdType i = 0; i < mesh.GetNumberOfPoints(); ++i)
  {
    if (used[i] && seen++ % stride == 0)
    {
      const double* x = mesh.GetPoint(i);
      simplification.GuardPoints.insert(simplification.GuardPoints.end(), x, x + 3);
    }
  }
  simplification.GuardTolerance = this->ErrorTolerance * mesh.Diagonal;
}

bool vtkMedialSimplifyFilter::ChooseByCoverage(const vtkMedialSimplicialComplex& complex,
  const vtkMedialTriangleMesh& mesh, int threads, const std::vector<char>& forced, std::vector<char>& kept)
{
  const auto aborted = [this]() { return this->GetAbortExecute() != 0; };
  std::vector<double> samples(static_cast<size_t>(3 * this->NumberOfSurfaceSamples));
  for (vtkIdType i = 0; i < this->NumberOfSurfaceSamples; ++i)
  {
    vtkIdType triangle;
    vtkMedialDrawSurfacePoint(mesh, static_cast<std::uint64_t>(this->RandomSeed), i, triangle, &samples[3 * i]);
  }
  vtkMedialCoverageSelection selection;
  selection.Forced = forced;
  if (!selection.Select(complex.Points, complex.Radii, samples, this->NumberOfBalls, this->Dilation * mesh.Diagonal,
        threads, aborted))
  {
    return false;
  }
  this->CoveredDilation = selection.FinalDilation / mesh.Diagonal;
  kept = std::move(selection.Chosen);
  return true;
}

void vtkMedialSimplifyFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RepairMode: " << vtkMedialRepairFilter::GetModeName(this->RepairMode) << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "NumberOfBalls: " << this->NumberOfBalls << "\n";
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "RimWeight: " << this->RimWeight << "\n";
  os << indent << "ErrorTolerance: " << this->ErrorTolerance << "\n";
  os << indent << "Dilation: " << this->Dilation << "\n";
  os << indent << "NumberOfSurfaceSamples: " << this->NumberOfSurfaceSamples << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfBlockedCollapses: " << this->NumberOfBlockedCollapses << "\n";
  os << indent << "EulerCharacteristic: " << this->EulerCharacteristic << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "CoveredDilation: " << this->CoveredDilation << "\n";
}
