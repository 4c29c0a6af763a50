// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshWriter.h"
#include "vtkMedialArrayNames.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleStrip.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <unordered_set>
#include <vector>

vtkStandardNewMacro(vtkMedialMeshWriter);

namespace
{
// Locale-independent, round-trip exact.
void AppendNumber(std::string& out, double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value,
    std::chars_format::general, std::numeric_limits<double>::max_digits10);
  out.append(buffer, result.ptr);
}

void AppendNumber(std::string& out, vtkIdType value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

// Calls visit(n, ids) for every cell of the array.
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

// Why the points and their radii cannot be written, or an empty string.
std::string CheckPoints(vtkPolyData* input, vtkDataArray* radius)
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

// The cells as edges (a polyline gives its segments) and triangles (polygons are
// triangulated, strips split). `skipped` counts cells with too few points. False
// when a cell refers to a point id outside the points.
bool GatherCells(vtkPolyData* input, EdgeList& edges, FaceList& faces, vtkIdType& skipped)
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

// The .ma text: a header line, then one line per vertex, edge and face, written in
// chunks so that the whole file need not fit in memory twice.
// Q-MAT's form: the edges made unique, then every triangle side not among them yet
// (sides a-b, b-c, c-a), in order; edges of one point are dropped.
void AddTriangleSides(const FaceList& faces, vtkIdType points, EdgeList& edges)
{
  std::unordered_set<std::uint64_t> seen;
  const auto key = [points](vtkIdType a, vtkIdType b) {
    return static_cast<std::uint64_t>(std::min(a, b)) * static_cast<std::uint64_t>(points) +
      static_cast<std::uint64_t>(std::max(a, b));
  };
  EdgeList unique;
  auto add = [&](vtkIdType a, vtkIdType b) {
    if (a != b && seen.insert(key(a, b)).second)
    {
      unique.push_back({ a, b });
    }
  };
  for (const auto& e : edges)
  {
    add(e[0], e[1]);
  }
  for (const auto& f : faces)
  {
    add(f[0], f[1]);
    add(f[1], f[2]);
    add(f[2], f[0]);
  }
  edges.swap(unique);
}

void WriteText(std::ofstream& file, vtkPolyData* input, vtkDataArray* radius, const EdgeList& edges,
  const FaceList& faces)
{
  const vtkIdType nv = input->GetNumberOfPoints();
  std::string text;
  AppendNumber(text, nv);
  text += ' ';
  AppendNumber(text, static_cast<vtkIdType>(edges.size()));
  text += ' ';
  AppendNumber(text, static_cast<vtkIdType>(faces.size()));
  text += '\n';
  auto flush = [&]() {
    if (text.size() > (1 << 20))
    {
      file.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  };
  for (vtkIdType i = 0; i < nv; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    text += 'v';
    for (double value : { p[0], p[1], p[2], radius->GetComponent(i, 0) })
    {
      text += ' ';
      AppendNumber(text, value);
    }
    text += '\n';
    flush();
  }
  // A record line: the tag, then the ids.
  auto appendIds = [&](char tag, const vtkIdType* ids, int count) {
    text += tag;
    for (int k = 0; k < count; ++k)
    {
      text += ' ';
      AppendNumber(text, ids[k]);
    }
    text += '\n';
    flush();
  };
  for (const auto& e : edges)
  {
    appendIds('e', e.data(), 2);
  }
  for (const auto& f : faces)
  {
    appendIds('f', f.data(), 3);
  }
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
}
}

vtkMedialMeshWriter::vtkMedialMeshWriter() = default;

vtkMedialMeshWriter::~vtkMedialMeshWriter()
{
  this->SetFileName(nullptr);
}

vtkPolyData* vtkMedialMeshWriter::GetInput()
{
  return vtkPolyData::SafeDownCast(this->Superclass::GetInput());
}

int vtkMedialMeshWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkMedialMeshWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkPolyData* input = this->GetInput();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  auto reject = [this](const std::string& why) {
    vtkErrorMacro("Cannot write medial mesh '" << this->FileName << "': " << why << "; nothing written.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
  };
  if (!input)
  {
    return reject("no polydata input");
  }
  // Validate everything and gather the records before the file is touched.
  vtkDataArray* radius = input->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  const std::string problem = CheckPoints(input, radius);
  if (!problem.empty())
  {
    return reject(problem);
  }
  EdgeList edges;
  FaceList faces;
  vtkIdType skipped = 0;
  if (!GatherCells(input, edges, faces, skipped))
  {
    return reject("a cell refers to a point id outside [0, " + std::to_string(input->GetNumberOfPoints()) + ")");
  }
  AddTriangleSides(faces, input->GetNumberOfPoints(), edges);
  if (skipped > 0)
  {
    vtkWarningMacro("Skipped " << skipped << " line(s) or polygon(s) with too few points.");
  }

  std::ofstream file(this->FileName, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!file)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "' for writing.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  WriteText(file, input, radius, edges, faces);
  file.close();
  if (!file)
  {
    vtkErrorMacro("Error writing '" << this->FileName << "' (disk full?); the file was removed.");
    std::remove(this->FileName);
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
  }
}

void vtkMedialMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
