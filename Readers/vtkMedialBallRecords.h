// SPDX-License-Identifier: BSD-3-Clause
// Internal to MedialAxis::Readers (not wrapped, not installed): what every ball
// writer (.ma, .ply, .csv) checks and gathers before it touches its file: finite
// points and non-negative radii, the cells as edges and triangles, and
// round-trip exact, locale-independent number text.
#ifndef vtkMedialBallRecords_h
#define vtkMedialBallRecords_h

#include "vtkMedialArrayNames.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleStrip.h"

#include "vtkErrorCode.h"
#include "vtkPointData.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace medialballs
{
/// Appends `value` with max_digits10 significant digits: reading it back gives the
/// same double bit for bit, whatever the locale.
inline void AppendNumber(std::string& out, double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value,
    std::chars_format::general, std::numeric_limits<double>::max_digits10);
  out.append(buffer, result.ptr);
}

inline void AppendNumber(std::string& out, vtkIdType value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

/// Calls visit(n, ids) for every cell of the array.
template <typename Visit>
void ForEachCell(vtkCellArray* cells, Visit&& visit)
{
  if (!cells)
  {
    return;
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    visit(n, ids);
  }
}

using EdgeList = std::vector<std::array<vtkIdType, 2>>;
using FaceList = std::vector<std::array<vtkIdType, 3>>;

/// Why the points and their radii cannot be written, or an empty string.
inline std::string CheckBalls(vtkPolyData* input, vtkDataArray* radius)
{
  if (!radius)
  {
    return "the input has no point-data array 'Radius'";
  }
  if (radius->GetNumberOfComponents() != 1)
  {
    return "the 'Radius' array has " + std::to_string(radius->GetNumberOfComponents()) + " components, expected 1";
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    const double r = radius->GetComponent(i, 0);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(r))
    {
      return "point " + std::to_string(i) + " has a NaN or infinite coordinate or radius";
    }
    if (r < 0.0)
    {
      return "point " + std::to_string(i) + " has a negative radius";
    }
  }
  return std::string();
}

/// The cells as edges (a polyline gives its segments) and triangles (polygons are
/// triangulated by ear cutting, with a fan when that fails; strips are split).
/// Vertex cells are not gathered. `skipped` counts lines of one point and polygons
/// or strips of fewer than three. False when a cell refers to a point id outside
/// the points.
inline bool GatherCells(vtkPolyData* input, EdgeList& edges, FaceList& faces, vtkIdType& skipped)
{
  const vtkIdType nv = input->GetNumberOfPoints();
  bool badIndex = false;
  auto inRange = [&](vtkIdType n, const vtkIdType* ids) {
    for (vtkIdType k = 0; k < n; ++k)
    {
      badIndex = badIndex || ids[k] < 0 || ids[k] >= nv;
    }
    return !badIndex;
  };
  skipped = 0;
  ForEachCell(input->GetLines(), [&](vtkIdType n, const vtkIdType* ids) {
    if (!inRange(n, ids))
    {
      return;
    }
    skipped += n < 2 ? 1 : 0;
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      edges.push_back({ ids[k], ids[k + 1] });
    }
  });
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triangleIds;
  vtkNew<vtkPoints> trianglePoints;
  ForEachCell(input->GetPolys(), [&](vtkIdType n, const vtkIdType* ids) {
    if (!inRange(n, ids))
    {
      return;
    }
    if (n < 3)
    {
      ++skipped;
      return;
    }
    if (n == 3)
    {
      faces.push_back({ ids[0], ids[1], ids[2] });
      return;
    }
    polygon->Initialize(static_cast<int>(n), ids, input->GetPoints());
    triangleIds->Reset();
    if (polygon->Triangulate(0, triangleIds, trianglePoints) && triangleIds->GetNumberOfIds() == 3 * (n - 2))
    {
      for (vtkIdType k = 0; k < triangleIds->GetNumberOfIds(); k += 3)
      {
        faces.push_back({ triangleIds->GetId(k), triangleIds->GetId(k + 1), triangleIds->GetId(k + 2) });
      }
    }
    else // degenerate polygon: a fan keeps every vertex and the face count
    {
      for (vtkIdType k = 1; k + 1 < n; ++k)
      {
        faces.push_back({ ids[0], ids[k], ids[k + 1] });
      }
    }
  });
  vtkNew<vtkCellArray> stripTriangles;
  ForEachCell(input->GetStrips(), [&](vtkIdType n, const vtkIdType* ids) {
    if (inRange(n, ids) && n >= 3)
    {
      vtkTriangleStrip::DecomposeStrip(static_cast<int>(n), ids, stripTriangles);
    }
    skipped += n < 3 ? 1 : 0;
  });
  ForEachCell(stripTriangles, [&](vtkIdType, const vtkIdType* ids) { faces.push_back({ ids[0], ids[1], ids[2] }); });
  return !badIndex;
}

/// What a ball reader gathers before it builds its output.
struct BallMesh
{
  std::vector<double> Coordinates; // x y z per ball
  std::vector<double> Radii;
  std::vector<vtkIdType> Edges;     // 2 per edge
  std::vector<vtkIdType> Faces;     // the faces' point ids, one after the other
  std::vector<vtkIdType> FaceSizes; // points per face; empty: every face is a triangle
};

/// The readers' output: double points, `Radius` (double, the active scalars), one
/// line per edge and one polygon per face, in file order.
inline void ToPolyData(const BallMesh& mesh, vtkPolyData* output)
{
  const vtkIdType nv = static_cast<vtkIdType>(mesh.Radii.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  radius->SetNumberOfTuples(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    points->SetPoint(i, &mesh.Coordinates[3 * i]);
    radius->SetValue(i, mesh.Radii[i]);
  }
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(static_cast<vtkIdType>(mesh.Edges.size() / 2), mesh.Edges.size());
  for (size_t i = 0; i + 1 < mesh.Edges.size(); i += 2)
  {
    lines->InsertNextCell(2, &mesh.Edges[i]);
  }
  vtkNew<vtkCellArray> polys;
  const size_t faces = mesh.FaceSizes.empty() ? mesh.Faces.size() / 3 : mesh.FaceSizes.size();
  polys->AllocateExact(static_cast<vtkIdType>(faces), mesh.Faces.size());
  for (size_t f = 0, at = 0; f < faces; ++f)
  {
    const vtkIdType n = mesh.FaceSizes.empty() ? 3 : mesh.FaceSizes[f];
    polys->InsertNextCell(n, &mesh.Faces[at]);
    at += static_cast<size_t>(n);
  }
  output->SetPoints(points);
  output->GetPointData()->AddArray(radius);
  output->GetPointData()->SetActiveScalars(vtkMedialArrayNames::Radius); // colours by radius, like the sampler
  output->SetLines(lines);
  output->SetPolys(polys);
}

/// What a ball writer writes: the input, its `Radius` array, its edges and faces.
struct BallRecords
{
  vtkPolyData* Input = nullptr;
  vtkDataArray* Radius = nullptr;
  EdgeList Edges;
  FaceList Faces;
  vtkIdType Skipped = 0; // lines or polygons with too few points
};

/// Checks `input` (points, `Radius`, cells) and gathers its records; the reason
/// when it cannot be written, else an empty string.
inline std::string GatherBalls(vtkPolyData* input, BallRecords& records)
{
  if (!input)
  {
    return "no polydata input";
  }
  records.Input = input;
  records.Radius = input->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  std::string problem = CheckBalls(input, records.Radius);
  if (problem.empty() && !GatherCells(input, records.Edges, records.Faces, records.Skipped))
  {
    problem = "a cell refers to a point id outside [0, " + std::to_string(input->GetNumberOfPoints()) + ")";
  }
  return problem;
}

/// Opens `fileName`, calls write(file), and closes it; a file that could not be
/// written completely is removed. Returns a vtkErrorCode, with `why` set on failure.
template <typename Write>
unsigned long WriteWhole(const char* fileName, Write&& write, std::string& why)
{
  std::ofstream file(fileName, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!file)
  {
    why = std::string("Cannot open '") + fileName + "' for writing.";
    return vtkErrorCode::CannotOpenFileError;
  }
  write(file);
  file.close();
  if (!file)
  {
    why = std::string("Error writing '") + fileName + "' (disk full?); the file was removed.";
    std::remove(fileName);
    return vtkErrorCode::OutOfDiskSpaceError;
  }
  return vtkErrorCode::NoError;
}
}

#endif
