// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshFilter.h"
#include "vtkMedialArrayNames.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialDisjointSets.h"
#include "vtkMedialEnvelopeRefinement.h"
#include "vtkMedialMeshComplex.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialPowerComplex.h"
#include "vtkMedialSimplicialComplex.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSpatialOrder.h"
#include "vtkMedialProgress.h"
#include "vtkMedialRepairCallback.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialSolidPreparation.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialMeshFilter);
vtkCxxSetObjectMacro(vtkMedialMeshFilter, Sampler, vtkMedialAxisSampler);
vtkCxxSetObjectMacro(vtkMedialMeshFilter, Classifier, vtkMedialBallClassifier);
vtkCxxSetObjectMacro(vtkMedialMeshFilter, Repair, vtkMedialRepairFilter);

// The balls the mesh is built on: centres, inscribed radii, and the index of each in
// the ball input.
struct vtkMedialMeshFilter::BallSet
{
  std::vector<double> Centres;
  std::vector<double> Radii;
  std::vector<vtkIdType> Source;
  std::vector<vtkIdType> SolidComponent; // the surface component nearest to the centre
};

namespace
{
// The solid body of each triangle of the prepared surface: its shell, or for a cavity
// (a closed shell at odd depth) the shell enclosing it, so that a hollow solid is one.
std::vector<vtkIdType> TriangleBodies(const vtkMedialTriangleMesh& mesh)
{
  const vtkIdType nt = mesh.GetNumberOfTriangles();
  std::vector<vtkIdType> bodies(nt);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const int shell = mesh.ShellOfTriangle[t];
    const vtkMedialTriangleMesh::Shell& s = mesh.Shells[shell];
    bodies[t] = s.Closed && s.Depth % 2 == 1 && s.Parent >= 0 ? s.Parent : shell;
  }
  return bodies;
}

// Why the medial mesh's topology differs from the one the surface gives its solid: the
// surface is not a valid solid (vtkMedialSolidCheck, decided with CGAL's predicates), or
// else the mesh is at fault. Run only on a mismatch.
std::string TopologyMismatchCause(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads)
{
  vtkMedialSolidCheck check;
  check.Run(mesh, query, threads, true);
  check.Decide(mesh, vtkMedialRepairFilter::ExactPairTest);
  std::ostringstream cause;
  if (check.IsValidSolid() && check.PinchedVertices > 0)
  {
    cause << "the surface bounds a valid solid but has " << check.PinchedClause()
          << ": the solid's inside is open there, and its topology is not the one the surface's Euler "
             "characteristic gives (a horn torus's inside is a solid torus, its surface a pinched sphere); "
             "this is the shape, not the mesh's fault.";
    return cause.str();
  }
  if (check.IsValidSolid())
  {
    cause << "the surface bounds a valid solid (closed, manifold, oriented, no intersecting triangles), so the "
             "medial mesh is at fault; please report the input and the settings.";
    return cause.str();
  }
  cause << "the surface is not a valid solid (" << check.Cause() << "), so the topology its Euler characteristic gives is not the shape's and the inside tests the mesh "
           "relies on are ambiguous where it is broken; repair the surface (more samples do not help).";
  return cause.str();
}

// The balls followed by the exact seam and junction balls: every point array of the
// balls, the exact ones' values where they have the array (same name and width),
// NaN (or -1 for integer arrays) where they do not.
vtkSmartPointer<vtkPolyData> AppendExactBalls(vtkPolyData* balls, vtkPolyData* exact)
{
  const vtkIdType n = balls->GetNumberOfPoints(), m = exact ? exact->GetNumberOfPoints() : 0;
  auto all = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n + m);
  for (vtkIdType i = 0; i < n + m; ++i)
  {
    points->SetPoint(i, i < n ? balls->GetPoint(i) : exact->GetPoint(i - n));
  }
  all->SetPoints(points);
  vtkPointData* in = balls->GetPointData();
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = in->GetArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    const int width = array->GetNumberOfComponents();
    vtkDataArray* other = m ? exact->GetPointData()->GetArray(array->GetName()) : nullptr;
    other = other && other->GetNumberOfComponents() == width ? other : nullptr;
    const double missing = array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE
      ? std::nan("")
      : -1.0;
    auto joined = vtk::TakeSmartPointer(array->NewInstance());
    joined->SetName(array->GetName());
    joined->SetNumberOfComponents(width);
    joined->SetNumberOfTuples(n + m);
    for (vtkIdType i = 0; i < n + m; ++i)
    {
      for (int c = 0; c < width; ++c)
      {
        joined->SetComponent(i, c,
          i < n ? array->GetComponent(i, c) : (other ? other->GetComponent(i - n, c) : missing));
      }
    }
    all->GetPointData()->AddArray(joined);
  }
  return all;
}

// NaN (or -1 for integer arrays) in every array at point k.
void SetMissing(vtkPointData* pd, vtkIdType k)
{
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array)
    {
      continue;
    }
    const double missing =
      array->GetDataType() == VTK_FLOAT || array->GetDataType() == VTK_DOUBLE ? std::nan("") : -1.0;
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      array->InsertComponent(k, c, missing);
    }
  }
}

void AddCount(vtkFieldData* fd, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}
}

vtkMedialMeshFilter::vtkMedialMeshFilter()
{
  this->SetNumberOfInputPorts(2);
  this->Sampler = vtkMedialAxisSampler::New();
  this->Classifier = vtkMedialBallClassifier::New();
  this->Repair = vtkMedialRepairFilter::New();
}

vtkMedialMeshFilter::~vtkMedialMeshFilter()
{
  this->SetSampler(nullptr);
  this->SetClassifier(nullptr);
  this->SetRepair(nullptr);
}

vtkMTimeType vtkMedialMeshFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Sampler)
  {
    time = std::max(time, this->Sampler->GetMTime());
  }
  if (this->Classifier)
  {
    time = std::max(time, this->Classifier->GetMTime());
  }
  if (this->Repair)
  {
    time = std::max(time, this->Repair->GetMTime());
  }
  return time;
}

int vtkMedialMeshFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkMedialMeshFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole surface and every ball, whatever piece is requested downstream.
  vtkMedialRequestWholeInput(inputVector, 2);
  return 1;
}

int vtkMedialMeshFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* surface = vtkPolyData::GetData(inputVector[0], 0);
  vtkPointSet* ballInput = vtkPointSet::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->EulerCharacteristic = this->NumberOfComponents = this->NumberOfEdges = 0;
  this->HasSolidTopology = false;
  this->SurfaceRepaired = false;
  this->SolidEulerCharacteristic = this->SolidComponents = 0;
  this->DroppedBalls = this->DetachedBalls = this->RemainingTetrahedra = this->PrunedTriangles = 0;
  this->RefinementBalls = 0;
  this->EnvelopeProtrusion = 0.0;
  this->MaximumRadiusReduction = 0.0;
  const int threads = vtkMedialThreadCount(this->NumberOfThreads);
  auto aborted = [this]() { return this->GetAbortExecute() != 0; };

  // The surface, prepared as the sampler does, for the inside and crossing tests.
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: input 0 has no surface.");
    return 0;
  }
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 builds the whole mesh; the other pieces stay empty
  }
  vtkMedialStages stages(this);
  stages.Begin("Preparing the surface", 0.0, 0.05);
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  // The surface, checked and repaired as RepairMode says; from here on `surface` is
  // the one prepared (the repaired one when it was repaired).
  vtkMedialSolidPreparation preparation;
  if (!preparation.Prepare(surface, this->RepairMode, vtkMedialMakeRepairer(this->Repair, threads), threads, mesh,
        query, error, aborted, [&](int s) {
          stages.Begin(s == vtkMedialSolidPreparation::REPAIR ? "Repairing the surface" : "Preparing the surface", 0.0, 0.05);
        }))
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Cannot build the medial mesh: " << error << ".");
    }
    return this->GetAbortExecute() ? 1 : 0;
  }
  surface = preparation.GetSurface();
  this->SurfaceRepaired = preparation.GetRepaired();
  if (preparation.GetRepaired() || this->RepairMode != vtkMedialRepairFilter::NONE)
  {
    // The preparation's messages: the repair's steps (the mesh's own warnings were
    // never this filter's, the sampler prints them).
    for (const std::string& message : preparation.GetMessages())
    {
      if (message.rfind("Repair: ", 0) == 0)
      {
        vtkWarningMacro(<< message);
      }
    }
  }
  const bool closed = mesh.BoundaryEdges == 0;
  if (!closed)
  {
    vtkWarningMacro(<< "The surface has " << mesh.BoundaryEdges
                    << " boundary edges: it bounds no solid, so the medial mesh's topology is "
                       "not checked and inside tests near the holes are unreliable.");
  }

  // 1. Balls.
  vtkSmartPointer<vtkPointSet> balls = ballInput;
  if (!balls)
  {
    stages.Begin("Sampling", 0.05, 0.55);
    balls = this->RunSampler(surface);
    if (!balls)
    {
      return this->GetAbortExecute() ? 1 : 0;
    }
  }
  vtkDataArray* radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  if (!radius || radius->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: the balls have no one-component point-data "
                     "array named 'Radius'.");
    return 0;
  }
  if (this->Classifier)
  {
    stages.Begin("Classifying the balls", 0.55, 0.65);
    balls = this->Classify(balls, surface, query, !ballInput);
    if (!balls)
    {
      return this->GetAbortExecute() ? 1 : 0;
    }
    radius = balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  }

  // 2. Inscribed balls.
  stages.Begin("Inscribing the balls", 0.65, 0.7);
  BallSet set;
  if (!this->InscribeBalls(balls, radius, query, closed, threads, set))
  {
    return 0;
  }

  // 3. The regular triangulation and the union's dual complex.
  stages.Begin("Building the regular triangulation", 0.7, 0.75);
  vtkMedialPowerComplex power;
  if (!power.Build(set.Centres, set.Radii, threads, error))
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: " << error << " (" << set.Radii.size()
                  << " balls); a medial mesh needs balls spanning three dimensions.");
    return 0;
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // 4. The complex.
  stages.Begin("Building the medial mesh", 0.75, 0.9);
  vtkMedialMeshComplex complex;
  vtkMedialMeshComplex::Balls ballData;
  ballData.Centres = &set.Centres;
  ballData.Radii = &set.Radii;
  ballData.SolidComponents = &set.SolidComponent;
  const double tolerance =
    this->ProtrusionTolerance >= 0.0 ? this->ProtrusionTolerance * mesh.Diagonal : -1.0;
  if (!complex.Build(power, query, ballData, tolerance, threads, aborted))
  {
    return 1; // aborted: empty output
  }

  // 4b. Envelope refinement.
  if (this->EnvelopeTolerance >= 0.0)
  {
    stages.Begin("Refining the envelope", 0.9, 0.95);
    vtkMedialEnvelopeRefinement refinement;
    const vtkMedialEnvelopeRefinement::Mesh refined = { &set.Centres, &set.Radii, &complex.Vertices,
      &complex.Edges, &complex.EdgeTriangles, &complex.Triangles };
    this->RefinementBalls =
      refinement.Refine(refined, query, this->EnvelopeTolerance * mesh.Diagonal, threads, aborted);
    this->EnvelopeProtrusion = refinement.WorstProtrusion / mesh.Diagonal;
    set.Source.resize(set.Radii.size(), -1);
    set.SolidComponent.resize(set.Radii.size(), -1);
    complex.CountComponents(); // the figures below are the output's, counted again
    if (this->GetAbortExecute())
    {
      return 1;
    }
  }

  // 5. Output.
  stages.Begin("Writing the mesh", 0.95, 1.0);
  this->WriteMesh(balls, set, complex, output);
  this->EulerCharacteristic = complex.GetEulerCharacteristic();
  this->NumberOfComponents = complex.GetNumberOfComponents();
  this->NumberOfEdges = static_cast<vtkIdType>(complex.Edges.size());
  this->RemainingTetrahedra = complex.Stats.RemainingTetrahedra;
  this->DetachedBalls = complex.Stats.DetachedBalls;
  this->PrunedTriangles = complex.Stats.PrunedTriangles;
  vtkFieldData* fd = output->GetFieldData();
  if (vtkFieldData* report = preparation.GetReport())
  {
    for (int i = 0; i < report->GetNumberOfArrays(); ++i)
    {
      fd->AddArray(report->GetAbstractArray(i));
    }
  }
  AddCount(fd, vtkMedialArrayNames::EulerCharacteristic, this->EulerCharacteristic);
  AddCount(fd, vtkMedialArrayNames::Components, this->NumberOfComponents);
  if (closed && mesh.NonManifoldEdges == 0 && mesh.GetEulerCharacteristic() % 2 == 0)
  {
    this->HasSolidTopology = true;
    this->SolidEulerCharacteristic = mesh.GetEulerCharacteristic() / 2;
    this->SolidComponents = mesh.Bodies;
    AddCount(fd, vtkMedialArrayNames::SolidEulerCharacteristic, this->SolidEulerCharacteristic);
    AddCount(fd, vtkMedialArrayNames::SolidComponents, this->SolidComponents);
    if (this->SolidEulerCharacteristic != this->EulerCharacteristic ||
      this->SolidComponents != this->NumberOfComponents)
    {
      vtkWarningMacro(<< "The medial mesh has Euler characteristic " << this->EulerCharacteristic
                      << " and " << this->NumberOfComponents << " component(s), the solid "
                      << this->SolidEulerCharacteristic << " and " << this->SolidComponents << ": "
                      << TopologyMismatchCause(mesh, query, threads));
    }
  }
  else if (closed && mesh.NonManifoldEdges == 0 && mesh.NonOrientableComponents == 0)
  {
    // An odd Euler characteristic of a closed, edge-manifold, oriented surface: it is
    // pinched (PinchedVertexBound is odd), and its solid's topology is not half of it.
    vtkMedialSolidCheck pinches;
    pinches.CountPinches(mesh);
    if (pinches.PinchedVertices > 0)
    {
      vtkWarningMacro(<< "The surface has " << pinches.PinchedClause()
                      << ": at a pinch the solid's inside is open, so its topology is not the one the surface's "
                         "Euler characteristic gives, and the medial mesh's (Euler characteristic "
                      << this->EulerCharacteristic << ", " << this->NumberOfComponents
                      << " component(s)) is not checked against it.");
    }
  }
  if (this->RemainingTetrahedra > 0)
  {
    vtkWarningMacro(<< this->RemainingTetrahedra
                    << " tetrahedra could not be collapsed and were dropped (their triangles stay).");
  }
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkMedialMeshFilter::RunStage(vtkAlgorithm* stage)
{
  vtkNew<vtkCallbackCommand> forward;
  forward->SetClientData(this);
  forward->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
    auto* self = static_cast<vtkMedialMeshFilter*>(client);
    self->UpdateProgress(*static_cast<double*>(data));
    if (self->GetAbortExecute())
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  const unsigned long tag = stage->AddObserver(vtkCommand::ProgressEvent, forward);
  const int ok = stage->UpdatePiece(0, 1, 0);
  stage->RemoveObserver(tag);
  return ok && !this->GetAbortExecute();
}

vtkSmartPointer<vtkPointSet> vtkMedialMeshFilter::RunSampler(vtkPolyData* surface)
{
  if (!this->Sampler)
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: no balls on input 1 and no Sampler.");
    return nullptr;
  }
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(surface);
  this->Sampler->SetInputData(copy);
  // The surface is this filter's prepared one: the sampler must not repair it again.
  const int repairMode = this->Sampler->GetRepairMode();
  this->Sampler->SetRepairMode(vtkMedialRepairFilter::NONE);
  const bool ok = this->RunStage(this->Sampler);
  this->Sampler->SetRepairMode(repairMode);
  auto balls = vtkSmartPointer<vtkPolyData>::New();
  balls->ShallowCopy(this->Sampler->GetOutput());
  this->Sampler->SetInputData(nullptr);
  if (this->GetAbortExecute())
  {
    return nullptr;
  }
  if (!ok || balls->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: the sampler gave no balls.");
    return nullptr;
  }
  return balls;
}

vtkSmartPointer<vtkPointSet> vtkMedialMeshFilter::Classify(
  vtkPointSet* balls, vtkPolyData* surface, const vtkMedialSurfaceQuery& query, bool sampled)
{
  vtkNew<vtkPolyData> points; // the classifier takes polydata
  points->SetPoints(balls->GetPoints());
  points->GetPointData()->ShallowCopy(balls->GetPointData());
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(surface);
  this->Classifier->SetInputData(0, points);
  this->Classifier->SetSurfaceData(copy);
  this->Classifier->SetNumberOfThreads(this->NumberOfThreads);
  if (sampled && this->Sampler)
  {
    this->Classifier->SetMinimumSeparationAngle(this->Sampler->GetMinimumSeparationAngle());
  }
  this->Classifier->PreparedSurface = &query; // prepared from `surface` above
  const bool ok = this->RunStage(this->Classifier);
  this->Classifier->PreparedSurface = nullptr;
  vtkSmartPointer<vtkPolyData> result =
    ok ? AppendExactBalls(this->Classifier->GetOutput(0), this->Classifier->GetOutput(1)) : nullptr;
  this->Classifier->SetInputData(0, nullptr);
  this->Classifier->SetSurfaceData(nullptr);
  if (!ok && !this->GetAbortExecute())
  {
    vtkErrorMacro(<< "Cannot build the medial mesh: the ball classifier failed.");
  }
  return result;
}

bool vtkMedialMeshFilter::InscribeBalls(vtkPointSet* balls, vtkDataArray* radius,
  const vtkMedialSurfaceQuery& query, bool closed, int threads, BallSet& set)
{
  const vtkIdType n = balls->GetNumberOfPoints();
  std::vector<double> centres(3 * n), radii(n);
  std::vector<char> keep(n, 1);
  for (vtkIdType i = 0; i < n; ++i)
  {
    balls->GetPoint(i, &centres[3 * i]);
    radii[i] = radius->GetComponent(i, 0);
    const double* c = &centres[3 * i];
    if (!std::isfinite(radii[i]) || radii[i] < 0.0 || !std::isfinite(c[0] + c[1] + c[2]))
    {
      vtkErrorMacro(<< "Cannot build the medial mesh: ball " << i
                    << " has a NaN, infinite or negative radius or coordinate.");
      return false;
    }
  }
  // Closest surface point of each centre: the inscribed radius, and the surface (hence
  // solid) component the ball belongs to.
  const vtkMedialTriangleMesh& mesh = *query.GetMesh();
  const std::vector<vtkIdType> triangleBody = TriangleBodies(mesh);
  std::vector<double> reduction(n, 0.0);
  std::vector<vtkIdType> component(n, -1);
  const std::vector<vtkIdType> order = vtkMedialSpatialOrder::Order(
    n, [&](vtkIdType i) { return vtkMedialSpatialOrder::Key(&centres[3 * i], mesh.Bounds); }, threads);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType i = order[k];
    const double* c = &centres[3 * i];
    if (closed && !query.IsInside(c))
    {
      keep[i] = 0;
      continue;
    }
    vtkMedialSurfaceQuery::ClosestHit hit;
    // A sampler's ball touches the surface at distance r: look just beyond it first.
    if (query.ClosestPoint(c, radii[i] * (1.0 + 1e-9) + 1e-12 * mesh.Diagonal, hit) ||
      query.ClosestPoint(c, 2.0 * mesh.Diagonal, hit))
    {
      reduction[i] = std::max(0.0, radii[i] - hit.Distance);
      radii[i] = std::min(radii[i], hit.Distance);
      component[i] = triangleBody[hit.Triangle];
    }
  }
  BallSet& out = set;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!keep[i])
    {
      ++this->DroppedBalls;
      continue;
    }
    out.Centres.insert(out.Centres.end(), &centres[3 * i], &centres[3 * i] + 3);
    out.Radii.push_back(radii[i]);
    out.Source.push_back(i);
    out.SolidComponent.push_back(component[i]);
    this->MaximumRadiusReduction = std::max(this->MaximumRadiusReduction, reduction[i]);
  }
  this->MaximumRadiusReduction /= query.GetMesh()->Diagonal;
  if (this->DroppedBalls > 0)
  {
    vtkWarningMacro(<< this->DroppedBalls << " ball(s) with a centre outside the surface were dropped.");
  }
  return true;
}

void vtkMedialMeshFilter::WriteMesh(
  vtkPointSet* balls, const BallSet& set, const vtkMedialMeshComplex& complex, vtkPolyData* output)
{
  const vtkIdType nv = static_cast<vtkIdType>(complex.Vertices.size());
  std::vector<vtkIdType> pointOf(set.Radii.size(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  vtkPointData* inPD = balls->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD, nv);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  radius->SetNumberOfTuples(nv);
  for (vtkIdType k = 0; k < nv; ++k)
  {
    const vtkIdType ball = complex.Vertices[k];
    pointOf[ball] = k;
    points->SetPoint(k, &set.Centres[3 * ball]);
    if (set.Source[ball] >= 0)
    {
      outPD->CopyData(inPD, set.Source[ball], k);
    }
    else
    {
      SetMissing(outPD, k); // a ball of the envelope refinement
    }
    radius->SetValue(k, set.Radii[ball]);
  }
  outPD->RemoveArray(vtkMedialArrayNames::Radius);
  outPD->AddArray(radius);
  output->SetPoints(points);

  // Cells on the output's point ids (vtkMedialSimplicialComplex::WriteCells: vertices,
  // curve and seam lines, triangles, MedialCellType, the point types from the mesh).
  std::vector<std::array<vtkIdType, 2>> edges(complex.Edges.size());
  for (size_t e = 0; e < complex.Edges.size(); ++e)
  {
    edges[e] = { pointOf[complex.Edges[e][0]], pointOf[complex.Edges[e][1]] };
  }
  std::vector<std::array<vtkIdType, 3>> triangles(complex.Triangles.size());
  for (size_t t = 0; t < complex.Triangles.size(); ++t)
  {
    const auto& c = complex.Triangles[t];
    triangles[t] = { pointOf[c[0]], pointOf[c[1]], pointOf[c[2]] };
  }
  const auto cells = vtkMedialSimplicialComplex::WriteCells(nv, edges, complex.EdgeTriangles, triangles, output);
  vtkDataArray* classified = outPD->GetArray(vtkMedialArrayNames::MedialPointType);
  if (!classified)
  {
    vtkNew<vtkIntArray> types;
    types->SetName(vtkMedialArrayNames::MedialPointType);
    types->SetNumberOfTuples(nv);
    for (vtkIdType k = 0; k < nv; ++k)
    {
      types->SetValue(k, cells.PointTypes[k]);
    }
    outPD->AddArray(types);
    return;
  }
  for (vtkIdType k = 0; k < nv; ++k)
  {
    if (set.Source[complex.Vertices[k]] < 0)
    {
      classified->SetComponent(k, 0, cells.PointTypes[k]); // refinement balls: from the mesh
    }
  }
}

void vtkMedialMeshFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Sampler: " << this->Sampler << "\n";
  os << indent << "Classifier: " << this->Classifier << "\n";
  os << indent << "RepairMode: " << vtkMedialRepairFilter::GetModeName(this->RepairMode) << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "ProtrusionTolerance: " << this->ProtrusionTolerance << "\n";
  os << indent << "EnvelopeTolerance: " << this->EnvelopeTolerance << "\n";
  os << indent << "RefinementBalls: " << this->RefinementBalls << "\n";
  os << indent << "EnvelopeProtrusion: " << this->EnvelopeProtrusion << "\n";
  os << indent << "PrunedTriangles: " << this->PrunedTriangles << "\n";
  os << indent << "EulerCharacteristic: " << this->EulerCharacteristic << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "NumberOfEdges: " << this->NumberOfEdges << "\n";
  os << indent << "HasSolidTopology: " << this->HasSolidTopology << "\n";
  os << indent << "SolidEulerCharacteristic: " << this->SolidEulerCharacteristic << "\n";
  os << indent << "SolidComponents: " << this->SolidComponents << "\n";
  os << indent << "DroppedBalls: " << this->DroppedBalls << "\n";
  os << indent << "DetachedBalls: " << this->DetachedBalls << "\n";
  os << indent << "MaximumRadiusReduction: " << this->MaximumRadiusReduction << "\n";
  os << indent << "RemainingTetrahedra: " << this->RemainingTetrahedra << "\n";
}
