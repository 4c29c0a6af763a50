// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallClassifier.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialProgress.h"

#include "vtkMedialGovernors.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialSeamSolver.h"
#include "vtkMedialSpatialOrder.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <omp.h>

#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialBallClassifier);

namespace
{
// Output 1: one vertex per exact point, with Radius, MedialPointType and GovernorCount.
void WriteExactPoints(const std::vector<vtkMedialSeamSolver::ExactPoint>& exactPoints, vtkPolyData* exact)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  vtkNew<vtkIntArray> type, count;
  type->SetName(vtkMedialArrayNames::MedialPointType);
  count->SetName(vtkMedialArrayNames::GovernorCount);
  for (const auto& p : exactPoints)
  {
    const vtkIdType id = points->InsertNextPoint(p.Centre);
    vertices->InsertNextCell(1, &id);
    radius->InsertNextValue(p.Radius);
    type->InsertNextValue(p.Type);
    count->InsertNextValue(p.GovernorCount);
  }
  exact->SetPoints(points);
  exact->SetVerts(vertices);
  exact->GetPointData()->AddArray(radius);
  exact->GetPointData()->SetActiveScalars(vtkMedialArrayNames::Radius);
  exact->GetPointData()->AddArray(type);
  exact->GetPointData()->AddArray(count);
}

// The surface engines, built once per execution (the mesh and queries unless lent).
struct Surface
{
  vtkMedialTriangleMesh OwnMesh;
  vtkMedialSurfaceQuery OwnQuery;
  const vtkMedialSurfaceQuery* Query = nullptr;
  vtkMedialGovernors Governors;
  const vtkMedialTriangleMesh& Mesh() const { return *this->Query->GetMesh(); }
};
}

vtkMedialBallClassifier::vtkMedialBallClassifier()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
}

int vtkMedialBallClassifier::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialBallClassifier::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Contacts need the whole surface, and neighbours all the balls, whatever piece is requested.
  vtkMedialRequestWholeInput(inputVector, 2);
  return 1;
}

int vtkMedialBallClassifier::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* balls = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* surfaceData = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* exact = vtkPolyData::GetData(outputVector, 1);
  this->NumberOfRimBalls = this->NumberOfSheetBalls = this->NumberOfSeamBalls = 0;
  this->NumberOfJunctionBalls = this->NumberOfUntouchedBalls = 0;
  this->NumberOfSeamPoints = this->NumberOfJunctionVertices = this->NumberOfTracedSeams = 0;
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 classifies every ball
  }

  if (!surfaceData)
  {
    vtkErrorMacro(<< "No surface on input port 1 (SetSurfaceConnection).");
    return 0;
  }
  const vtkIdType n = balls->GetNumberOfPoints();
  vtkDataArray* radius = n > 0 ? this->GetInputArrayToProcess(0, inputVector) : nullptr;
  if (n > 0 && (!radius || radius->GetNumberOfComponents() != 1 || radius->GetNumberOfTuples() != n))
  {
    vtkErrorMacro(<< "Cannot classify the balls: they need a point data array of one radius per point (by "
                     "default '"
                  << vtkMedialArrayNames::Radius << "').");
    return 0;
  }
  vtkDataArray* surfacePoint = balls->GetPointData()->GetArray(vtkMedialArrayNames::SurfacePoint);
  if (surfacePoint && surfacePoint->GetNumberOfComponents() != 3)
  {
    surfacePoint = nullptr;
  }

  auto aborted = [this]() { return this->GetAbortExecute() != 0; };
  Surface surface;
  std::string error;
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  vtkMedialStages stages(this);
  stages.Begin("Preparing the surface and its governors", 0.0, 0.1);
  surface.Query = this->PreparedSurface;
  if (!surface.Query && surface.OwnMesh.Build(surfaceData, error, aborted) &&
    surface.OwnQuery.Build(&surface.OwnMesh, error, aborted))
  {
    surface.Query = &surface.OwnQuery;
  }
  if (!surface.Query ||
    !surface.Governors.Build(surface.Mesh(), *surface.Query, { this->Tolerance, this->MinimumSeparationAngle, threads }, error))
  {
    if (aborted())
    {
      return 1;
    }
    vtkErrorMacro(<< "Cannot classify the balls: " << error << ".");
    return 0;
  }
  if (surface.Mesh().BoundaryEdges > 0)
  {
    vtkWarningMacro(<< "The surface has " << surface.Mesh().BoundaryEdges
                    << " boundary edges; governors near its holes are not meaningful.");
  }

  // 1. Governors of every ball.
  stages.Begin("Classifying the balls", 0.1, this->ComputeExactPoints ? 0.5 : 1.0);
  std::vector<vtkMedialSeamSolver::Ball> records(static_cast<size_t>(n));
  // Balls in a spatially coherent order (nearby balls read the same tree nodes).
  const std::vector<vtkIdType> order = vtkMedialSpatialOrder::Order(n, [&](vtkIdType i) {
    double c[3];
    balls->GetPoint(i, c);
    return vtkMedialSpatialOrder::Key(c, surface.Mesh().Bounds);
  }, threads);
  const vtkIdType block = 4096;
  for (vtkIdType begin = 0; begin < n && !aborted(); begin += block)
  {
    const vtkIdType end = std::min(n, begin + block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
    for (vtkIdType k = begin; k < end; ++k)
    {
      const vtkIdType i = order[k];
      auto& record = records[i];
      balls->GetPoint(i, record.Centre);
      record.Radius = radius->GetComponent(i, 0);
      double p[3];
      if (surfacePoint)
      {
        for (int k = 0; k < 3; ++k)
        {
          p[k] = surfacePoint->GetComponent(i, k);
        }
      }
      // An inscribed ball the sampler shrank away from its cap no longer reaches P; its
      // contacts are those of the angle-rule ball through P, which the cap rule reads.
      double contactRadius = record.Radius;
      if (surfacePoint)
      {
        contactRadius = std::max(contactRadius, std::sqrt(vtkMath::Distance2BetweenPoints(record.Centre, p)));
      }
      surface.Governors.Classify(record.Centre, contactRadius, surfacePoint ? p : nullptr, record.Governors);
    }
    this->UpdateProgress(static_cast<double>(end) / n);
  }
  if (aborted())
  {
    return 1;
  }
  vtkNew<vtkIntArray> count, type;
  count->SetName(vtkMedialArrayNames::GovernorCount);
  type->SetName(vtkMedialArrayNames::MedialPointType);
  count->SetNumberOfValues(n);
  type->SetNumberOfValues(n);
  vtkIdType* tally[4] = { &this->NumberOfRimBalls, &this->NumberOfSheetBalls, &this->NumberOfSeamBalls,
    &this->NumberOfJunctionBalls };
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int g = records[i].Governors.Count();
    const int t = surface.Governors.PointType(g, records[i].Radius);
    count->SetValue(i, g);
    type->SetValue(i, t);
    ++*tally[t];
    this->NumberOfUntouchedBalls += g == 0 ? 1 : 0;
  }
  output->ShallowCopy(balls);
  output->GetPointData()->AddArray(count);
  output->GetPointData()->AddArray(type);

  // 2. Exact seam points and junction vertices.
  vtkMedialSeamSolver::Result result;
  if (this->ComputeExactPoints && n > 1)
  {
    stages.Begin("Solving seams and junctions", 0.5, 1.0);
    std::vector<double> centres(static_cast<size_t>(3 * n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      std::copy(records[i].Centre, records[i].Centre + 3, &centres[3 * i]);
    }
    const auto pairs = vtkMedialSeamSolver::NearestPairs(centres.data(), n, this->NumberOfNeighbors, threads);
    vtkMedialSeamSolver solver(surface.Governors);
    solver.SetMaximumTracedSeams(this->MaximumTracedSeams);
    if (!solver.Solve(records, pairs, threads, aborted, result))
    {
      return 1;
    }
    this->NumberOfTracedSeams = result.TracedSeams;
    if (result.TracingStopped && this->MaximumTracedSeams > 0)
    {
      vtkWarningMacro(<< "Seam tracing stopped at MaximumTracedSeams (" << this->MaximumTracedSeams
                      << "); junction vertices beyond may be missing.");
    }
  }
  for (const auto& p : result.Points)
  {
    ++(p.Type == JUNCTION ? this->NumberOfJunctionVertices : this->NumberOfSeamPoints);
  }
  WriteExactPoints(result.Points, exact);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialBallClassifier::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MinimumSeparationAngle: " << this->MinimumSeparationAngle << "\n";
  os << indent << "ComputeExactPoints: " << this->ComputeExactPoints << "\n";
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "MaximumTracedSeams: " << this->MaximumTracedSeams << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "PreparedSurface: " << (this->PreparedSurface ? "lent" : "none") << "\n";
  os << indent << "NumberOfRimBalls: " << this->NumberOfRimBalls << "\n";
  os << indent << "NumberOfSheetBalls: " << this->NumberOfSheetBalls << "\n";
  os << indent << "NumberOfSeamBalls: " << this->NumberOfSeamBalls << "\n";
  os << indent << "NumberOfJunctionBalls: " << this->NumberOfJunctionBalls << "\n";
  os << indent << "NumberOfUntouchedBalls: " << this->NumberOfUntouchedBalls << "\n";
  os << indent << "NumberOfSeamPoints: " << this->NumberOfSeamPoints << "\n";
  os << indent << "NumberOfJunctionVertices: " << this->NumberOfJunctionVertices << "\n";
  os << indent << "NumberOfTracedSeams: " << this->NumberOfTracedSeams << "\n";
}
