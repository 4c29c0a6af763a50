// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPruneFilter.h"
#include "vtkMedialArrayNames.h"

#include "vtkMedialComplexPruning.h"
#include "vtkMedialGraphPruning.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialSimplicialComplex.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkMedialPruneFilter);

namespace
{
// Diagonal of the bounding box of the balls (centres +- radii): the shape's size.
double BallsDiagonal(vtkPolyData* input, vtkDataArray* radius)
{
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    const double r = radius->GetComponent(i, 0);
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], x[k] - r);
      hi[k] = std::max(hi[k], x[k] + r);
    }
  }
  double d = 0.0;
  for (int k = 0; k < 3 && input->GetNumberOfPoints() > 0; ++k)
  {
    d += (hi[k] - lo[k]) * (hi[k] - lo[k]);
  }
  return std::sqrt(d);
}

// Copies the used points (point data too) into the output; returns the map old -> new.
std::vector<vtkIdType> CopyUsedPoints(vtkPolyData* input, const std::vector<char>& used, vtkPolyData* output)
{
  std::vector<vtkIdType> map(used.size(), -1);
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->CopyAllocate(inPD);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(used.size()); ++i)
  {
    if (used[i])
    {
      map[i] = points->InsertNextPoint(input->GetPoint(i));
      outPD->CopyData(inPD, i, map[i]);
    }
  }
  output->SetPoints(points);
  return map;
}

// The 2D point types from the kept segments: 0 end, 1 regular, 2 junction.
void UpdatePointTypes(vtkPolyData* output)
{
  vtkDataArray* types = output->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  if (!types)
  {
    return;
  }
  std::vector<int> degree(static_cast<size_t>(output->GetNumberOfPoints()), 0);
  auto it = vtk::TakeSmartPointer(output->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      ++degree[ids[k]];
      ++degree[ids[k + 1]];
    }
  }
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    if (degree[i] > 0)
    {
      types->SetTuple1(i, degree[i] == 1 ? 0 : (degree[i] == 2 ? 1 : 2));
    }
  }
}
}

vtkMedialPruneFilter::vtkMedialPruneFilter()
{
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkMedialArrayNames::Radius);
}

const char* vtkMedialPruneFilter::GetMeasureName(int measure)
{
  switch (measure)
  {
    case EROSION_THICKNESS:
      return "erosion-thickness";
    case TUBULARITY:
      return "tubularity";
    case LAMBDA:
      return "lambda";
    case SEPARATION_ANGLE:
      return "separation-angle";
    case SCALE_AXIS:
      return "scale-axis";
    default:
      return "unknown";
  }
}

double vtkMedialPruneFilter::GetDefaultThreshold(int measure)
{
  switch (measure)
  {
    case EROSION_THICKNESS:
      return 0.01;
    case TUBULARITY:
      return 0.05;
    case LAMBDA:
      return 0.005;
    case SEPARATION_ANGLE:
      return 30.0;
    default:
      return 0.05;
  }
}

double vtkMedialPruneFilter::GetMeasureUpperBound(int measure)
{
  return measure == SEPARATION_ANGLE ? 180.0 : 1.0;
}

double vtkMedialPruneFilter::GetEffectiveThreshold() const
{
  return this->Threshold >= 0.0 ? this->Threshold : GetDefaultThreshold(this->Measure);
}

int vtkMedialPruneFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

int vtkMedialPruneFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Branches run across pieces: prune the whole axis.
  vtkMedialRequestWholeInput(inputVector, 1);
  return 1;
}

int vtkMedialPruneFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfPrunedBranches = this->NumberOfPrunedCells = 0;
  const vtkIdType n = input->GetNumberOfPoints();
  if (n == 0)
  {
    return 1;
  }
  vtkDataArray* radius = this->GetInputArrayToProcess(0, inputVector);
  if (!radius || radius->GetNumberOfComponents() != 1 || radius->GetNumberOfTuples() != n)
  {
    vtkErrorMacro(<< "Cannot prune: the medial axis needs a point data array of one radius per point (by "
                     "default '"
                  << vtkMedialArrayNames::Radius << "').");
    return 0;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double r = radius->GetComponent(i, 0);
    if (!std::isfinite(r) || r < 0.0)
    {
      vtkErrorMacro(<< "Cannot prune: point " << i << " has radius " << r << " (radii must be finite and >= 0).");
      return 0;
    }
  }
  if (input->GetNumberOfStrips() > 0)
  {
    vtkErrorMacro(<< "Cannot prune: triangle strips are not supported (triangulate the medial mesh first).");
    return 0;
  }
  const double diagonal = BallsDiagonal(input, radius);
  return input->GetNumberOfPolys() > 0 ? this->PruneMesh(input, radius, diagonal, output)
                                       : this->PruneGraph(input, radius, diagonal, output);
}

int vtkMedialPruneFilter::PruneGraph(vtkPolyData* input, vtkDataArray* radius, double diagonal, vtkPolyData* output)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<double> points(static_cast<size_t>(3 * n)), radii(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &points[3 * i]);
    radii[i] = radius->GetComponent(i, 0);
  }
  // Segments of the lines, in cell order.
  std::vector<std::array<vtkIdType, 2>> segments;
  std::vector<vtkIdType> firstSegment; // per line: its first segment (segments of a line are consecutive)
  std::vector<vtkIdType> lineSize;
  auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    it->GetCurrentCell(count, ids);
    firstSegment.push_back(static_cast<vtkIdType>(segments.size()));
    lineSize.push_back(count);
    for (vtkIdType k = 0; k + 1 < count; ++k)
    {
      segments.push_back({ ids[k], ids[k + 1] });
    }
  }
  vtkMedialGraphPruning pruning;
  if (!pruning.Run({ &points, &radii, &segments }, this->Measure, diagonal,
        [this]() { return this->GetAbortExecute() != 0; }))
  {
    return 1;
  }
  const double threshold = this->GetEffectiveThreshold();
  this->NumberOfPrunedBranches = pruning.CountRemovedBelow(threshold);

  // Points used by a kept segment or a vertex cell.
  std::vector<char> used(static_cast<size_t>(n), 0);
  for (size_t s = 0; s < segments.size(); ++s)
  {
    if (pruning.SegmentLevels[s] >= threshold)
    {
      used[segments[s][0]] = used[segments[s][1]] = 1;
    }
  }
  auto vit = vtk::TakeSmartPointer(input->GetVerts()->NewIterator());
  for (vit->GoToFirstCell(); !vit->IsDoneWithTraversal(); vit->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    vit->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k < count; ++k)
    {
      used[ids[k]] = 1;
    }
  }
  const std::vector<vtkIdType> map = CopyUsedPoints(input, used, output);

  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD);
  vtkNew<vtkDoubleArray> significance;
  significance->SetName(vtkMedialArrayNames::Significance);
  vtkNew<vtkCellArray> verts, lines;
  vtkIdType outCell = 0;
  vtkIdType inCell = 0;
  for (vit->GoToFirstCell(); !vit->IsDoneWithTraversal(); vit->GoToNextCell(), ++inCell)
  {
    vtkIdType count;
    const vtkIdType* ids;
    vit->GetCurrentCell(count, ids);
    verts->InsertNextCell(count);
    for (vtkIdType k = 0; k < count; ++k)
    {
      verts->InsertCellPoint(map[ids[k]]);
    }
    outCD->CopyData(inCD, inCell, outCell++);
    significance->InsertNextValue(GetMeasureUpperBound(this->Measure));
  }
  // Each line becomes its runs of kept segments.
  for (size_t line = 0; line < firstSegment.size(); ++line, ++inCell)
  {
    const vtkIdType first = firstSegment[line];
    const vtkIdType last = first + std::max<vtkIdType>(0, lineSize[line] - 1);
    bool keptAny = false;
    for (vtkIdType s = first; s < last;)
    {
      if (pruning.SegmentLevels[s] < threshold)
      {
        ++s;
        continue;
      }
      std::vector<vtkIdType> run{ map[segments[s][0]] };
      double level = pruning.SegmentLevels[s];
      for (; s < last && pruning.SegmentLevels[s] >= threshold; ++s)
      {
        run.push_back(map[segments[s][1]]);
        level = std::min(level, pruning.SegmentLevels[s]);
      }
      lines->InsertNextCell(static_cast<vtkIdType>(run.size()), run.data());
      outCD->CopyData(inCD, inCell, outCell++);
      significance->InsertNextValue(level);
      keptAny = true;
    }
    this->NumberOfPrunedCells += keptAny || lineSize[line] < 2 ? 0 : 1;
  }
  output->SetVerts(verts);
  output->SetLines(lines);
  outCD->AddArray(significance);
  UpdatePointTypes(output);
  output->GetFieldData()->PassData(input->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

int vtkMedialPruneFilter::PruneMesh(vtkPolyData* input, vtkDataArray* radius, double diagonal, vtkPolyData* output)
{
  vtkMedialSimplicialComplex complex;
  std::string error;
  if (!complex.Read(input, radius, error))
  {
    vtkErrorMacro(<< "Cannot prune: " << error << ".");
    return 0;
  }
  vtkMedialComplexPruning pruning;
  if (!pruning.Run(complex, this->Measure, diagonal, [this]() { return this->GetAbortExecute() != 0; }))
  {
    return 1;
  }
  const double threshold = this->GetEffectiveThreshold();
  this->NumberOfPrunedBranches = pruning.CountRemovedPieces(threshold);

  const vtkIdType nv = complex.GetNumberOfVertices();
  std::vector<char> used(static_cast<size_t>(nv));
  for (vtkIdType v = 0; v < nv; ++v)
  {
    used[v] = pruning.VertexLevels[v] >= threshold ? 1 : 0;
  }
  const std::vector<vtkIdType> map = CopyUsedPoints(input, used, output);
  std::vector<std::array<vtkIdType, 2>> edges;
  std::vector<vtkIdType> edgeSource;
  std::vector<vtkIdType> edgeIndex(complex.Edges.size(), -1);
  for (size_t e = 0; e < complex.Edges.size(); ++e)
  {
    if (pruning.EdgeLevels[e] >= threshold)
    {
      edgeIndex[e] = static_cast<vtkIdType>(edges.size());
      edges.push_back({ map[complex.Edges[e][0]], map[complex.Edges[e][1]] });
      edgeSource.push_back(static_cast<vtkIdType>(e));
    }
  }
  std::vector<int> edgeTriangles(edges.size(), 0);
  std::vector<std::array<vtkIdType, 3>> triangles;
  std::vector<double> triangleLevels;
  for (size_t t = 0; t < complex.Triangles.size(); ++t)
  {
    if (pruning.TriangleLevels[t] >= threshold)
    {
      const auto& c = complex.Triangles[t];
      triangles.push_back({ map[c[0]], map[c[1]], map[c[2]] });
      triangleLevels.push_back(pruning.TriangleLevels[t]);
      for (vtkIdType e : complex.TriangleEdges[t])
      {
        ++edgeTriangles[edgeIndex[e]];
      }
    }
  }
  this->NumberOfPrunedCells = static_cast<vtkIdType>(complex.Edges.size() + complex.Triangles.size() -
    edges.size() - triangles.size());
  const auto cells =
    vtkMedialSimplicialComplex::WriteCells(output->GetNumberOfPoints(), edges, edgeTriangles, triangles, output);

  vtkNew<vtkDoubleArray> significance;
  significance->SetName(vtkMedialArrayNames::Significance);
  significance->SetNumberOfTuples(output->GetNumberOfCells());
  vtkIdType cell = 0;
  for (vtkIdType k = 0; k < output->GetNumberOfVerts(); ++k)
  {
    significance->SetValue(cell++, GetMeasureUpperBound(this->Measure));
  }
  for (vtkIdType e : cells.LineEdges)
  {
    significance->SetValue(cell++, pruning.EdgeLevels[edgeSource[e]]);
  }
  for (double level : triangleLevels)
  {
    significance->SetValue(cell++, level);
  }
  output->GetCellData()->AddArray(significance);
  if (vtkDataArray* types = output->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType))
  {
    for (vtkIdType k = 0; k < output->GetNumberOfPoints(); ++k)
    {
      types->SetTuple1(k, cells.PointTypes[k]);
    }
  }
  output->GetFieldData()->PassData(input->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMedialPruneFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Measure: " << GetMeasureName(this->Measure) << "\n";
  os << indent << "Threshold: " << this->Threshold << " (effective " << this->GetEffectiveThreshold() << ")\n";
  os << indent << "NumberOfPrunedBranches: " << this->NumberOfPrunedBranches << "\n";
  os << indent << "NumberOfPrunedCells: " << this->NumberOfPrunedCells << "\n";
}
