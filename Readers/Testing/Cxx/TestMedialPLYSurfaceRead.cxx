// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialFileReader reads a PLY surface of the common binary layout directly: the
// same output as vtkPLYReader, value for value (float points, Normals, the polygons),
// for a family of files written byte by byte: triangles with and without normals,
// mixed polygons, every count and index type the direct read takes. Files outside the
// layout (ASCII, big endian, double or extra vertex properties, colours, another
// element, a bad index, a face of 2 vertices, a truncated face block) go to
// vtkPLYReader, and the result is again vtkPLYReader's own.
#include "ReaderTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <cstdint>
#include <cstring>
#include <sstream>

using namespace readertest;

namespace
{
// A PLY file: `vertexProperties` are the header lines of the vertex element, each
// vertex written as `perVertex` floats; faces with the given count and index types.
struct PLYFile
{
  std::string Format = "binary_little_endian";
  std::string VertexProperties = "property float x\nproperty float y\nproperty float z\n";
  int PerVertex = 3;
  std::string CountType = "uchar", IndexType = "int";
  std::string Extra; // header lines after the face element
  std::vector<std::vector<std::int64_t>> Faces;
  bool BigEndian = false;
  size_t Truncate = 0; // bytes cut off the end

  std::string Bytes(int vertices) const
  {
    std::ostringstream out;
    out << "ply\nformat " << this->Format << " 1.0\ncomment written by the test\nelement vertex " << vertices << "\n"
        << this->VertexProperties << "element face " << this->Faces.size() << "\nproperty list " << this->CountType
        << " " << this->IndexType << " vertex_indices\n"
        << this->Extra << "end_header\n";
    std::string data = out.str();
    if (this->Format == "ascii")
    {
      std::ostringstream text;
      for (int i = 0; i < vertices; ++i)
      {
        text << 0.25 * i << " " << 0.25 * i + 0.125 + 1.0 / 3.0 << " " << 0.25 * i + 0.25 << "\n";
      }
      for (const auto& face : this->Faces)
      {
        text << face.size();
        for (std::int64_t id : face)
        {
          text << " " << id;
        }
        text << "\n";
      }
      return data + text.str();
    }
    auto put = [&](const void* p, size_t n) {
      std::string bytes(static_cast<const char*>(p), n);
      if (this->BigEndian)
      {
        std::reverse(bytes.begin(), bytes.end());
      }
      data += bytes;
    };
    for (int i = 0; i < vertices; ++i)
    {
      for (int k = 0; k < this->PerVertex; ++k)
      {
        const float v = static_cast<float>(0.25 * i + 0.125 * k) + (k == 1 ? 1.0f / 3.0f : 0.0f);
        put(&v, sizeof(v));
      }
    }
    const int countBytes = this->CountType == "uchar" ? 1 : this->CountType == "ushort" ? 2 : 4;
    for (const auto& face : this->Faces)
    {
      const std::uint32_t count = static_cast<std::uint32_t>(face.size());
      put(&count, static_cast<size_t>(countBytes));
      for (std::int64_t id : face)
      {
        const std::int32_t v = static_cast<std::int32_t>(id);
        put(&v, sizeof(v));
      }
    }
    data.resize(data.size() - this->Truncate);
    return data;
  }
};

// Counts the values where two outputs differ (points, polygons, every point, cell and
// field array); -1 when their shapes differ.
long long Differences(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfCells() != b->GetNumberOfCells() ||
    (a->GetPoints() == nullptr) != (b->GetPoints() == nullptr) ||
    a->GetPointData()->GetNumberOfArrays() != b->GetPointData()->GetNumberOfArrays() ||
    a->GetCellData()->GetNumberOfArrays() != b->GetCellData()->GetNumberOfArrays() ||
    a->GetFieldData()->GetNumberOfArrays() != b->GetFieldData()->GetNumberOfArrays())
  {
    return -1;
  }
  long long diff = 0;
  if (a->GetPoints())
  {
    diff += a->GetPoints()->GetDataType() != b->GetPoints()->GetDataType();
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double x[3], y[3];
      a->GetPoint(i, x);
      b->GetPoint(i, y);
      diff += std::memcmp(x, y, sizeof(x)) != 0;
    }
  }
  diff += CellsOf(a->GetPolys()) != CellsOf(b->GetPolys());
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* u = a->GetPointData()->GetArray(i);
    vtkDataArray* v = b->GetPointData()->GetArray(u->GetName());
    if (!v || u->GetDataType() != v->GetDataType() || u->GetNumberOfComponents() != v->GetNumberOfComponents())
    {
      return -1;
    }
    for (vtkIdType t = 0; t < u->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < u->GetNumberOfComponents(); ++c)
      {
        diff += u->GetComponent(t, c) != v->GetComponent(t, c);
      }
    }
  }
  diff += (a->GetPointData()->GetNormals() == nullptr) != (b->GetPointData()->GetNormals() == nullptr);
  return diff;
}
}

int TestMedialPLYSurfaceRead(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "no temporary folder");
  const std::vector<std::vector<std::int64_t>> triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 1 }, { 1, 3, 2 } };
  const std::vector<std::vector<std::int64_t>> mixed = { { 0, 1, 2 }, { 0, 2, 3, 4 }, { 4, 3, 1, 0, 2 }, { 1, 3, 2 } };
  const std::string normals =
    "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n";

  struct Case
  {
    const char* Name;
    PLYFile File;
    int Vertices;
    bool Direct; // the direct read takes it
  };
  std::vector<Case> cases;
  auto add = [&](const char* name, bool direct, int vertices, auto change) {
    PLYFile file;
    file.Faces = triangles;
    change(file);
    cases.push_back({ name, file, vertices, direct });
  };
  add("triangles", true, 4, [](PLYFile&) {});
  add("normals", true, 4, [&](PLYFile& f) {
    f.VertexProperties = normals;
    f.PerVertex = 6;
  });
  add("polygons, uint indices", true, 5, [&](PLYFile& f) {
    f.Faces = mixed;
    f.IndexType = "uint";
  });
  add("ushort counts", true, 5, [&](PLYFile& f) {
    f.Faces = mixed;
    f.CountType = "ushort";
  });
  add("int counts, int32 indices", true, 4, [](PLYFile& f) {
    f.CountType = "int";
    f.IndexType = "int32";
  });
  add("uint counts", true, 4, [](PLYFile& f) { f.CountType = "uint"; });
  add("ascii", false, 4, [](PLYFile& f) { f.Format = "ascii"; });
  add("big endian", false, 4, [](PLYFile& f) {
    f.Format = "binary_big_endian";
    f.BigEndian = true;
  });
  add("double vertices", false, 4, [](PLYFile& f) {
    f.VertexProperties = "property double x\nproperty double y\nproperty double z\n";
    f.PerVertex = 6; // the same bytes as 3 doubles
  });
  add("extra vertex property", false, 4, [](PLYFile& f) {
    f.VertexProperties += "property float confidence\n";
    f.PerVertex = 4;
  });
  add("texture coordinates", false, 4, [](PLYFile& f) {
    f.VertexProperties += "property float u\nproperty float v\n";
    f.PerVertex = 5;
  });
  add("another element", false, 4, [](PLYFile& f) { f.Extra = "element material 0\nproperty float shine\n"; });
  add("index out of range", false, 4, [](PLYFile& f) { f.Faces[2][1] = 4; });
  add("a face of 2 vertices", false, 4, [](PLYFile& f) { f.Faces[1] = { 0, 1 }; });
  add("negative index", false, 4, [](PLYFile& f) { f.Faces[3][0] = -1; });

  int failures = 0;
  for (const Case& c : cases)
  {
    const std::string path = dir.Write(std::string("case") + std::to_string(&c - cases.data()) + ".ply", c.File.Bytes(c.Vertices));
    vtkNew<vtkMedialFileReader> reader;
    EventLog log;
    log.Watch(reader);
    reader->SetFileName(path.c_str());
    const bool ok = reader->GetExecutive()->Update() == 1;
    vtkNew<vtkPLYReader> stock;
    stock->SetFileName(path.c_str());
    stock->Update();
    const long long diff = ok ? Differences(reader->GetOutput(), stock->GetOutput()) : -2;
    std::printf("%-28s read %s, %lld points, %lld cells, differences from vtkPLYReader: %lld\n", c.Name,
      reader->GetReadDirectly() ? "directly" : "by vtkPLYReader",
      static_cast<long long>(reader->GetOutput()->GetNumberOfPoints()),
      static_cast<long long>(reader->GetOutput()->GetNumberOfCells()), diff);
    if (reader->GetReadDirectly() != c.Direct || diff != 0 ||
      (c.Direct && reader->GetOutput()->GetNumberOfCells() != static_cast<vtkIdType>(c.File.Faces.size())))
    {
      std::printf("FAILED: %s\n", c.Name);
      ++failures;
    }
  }
  // A truncated face block: not read directly (vtkPLYReader then reads what it can).
  {
    PLYFile file;
    file.Faces = triangles;
    file.Truncate = 3;
    const std::string path = dir.Write("truncated.ply", file.Bytes(4));
    vtkNew<vtkMedialFileReader> reader;
    EventLog log;
    log.Watch(reader);
    reader->SetFileName(path.c_str());
    reader->GetExecutive()->Update();
    std::printf("truncated: read %s\n", reader->GetReadDirectly() ? "directly" : "by vtkPLYReader");
    failures += reader->GetReadDirectly() ? 1 : 0;
  }
  // A real scan with normals (the shared horse.ply), when the shared meshes are there.
  const std::string horse = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/horse.ply";
  if (std::FILE* f = std::fopen(horse.c_str(), "rb"))
  {
    std::fclose(f);
    vtkNew<vtkMedialFileReader> reader;
    reader->SetFileName(horse.c_str());
    reader->Update();
    vtkNew<vtkPLYReader> stock;
    stock->SetFileName(horse.c_str());
    stock->Update();
    const long long diff = Differences(reader->GetOutput(), stock->GetOutput());
    std::printf("horse.ply: read %s, %lld cells, differences from vtkPLYReader: %lld\n",
      reader->GetReadDirectly() ? "directly" : "by vtkPLYReader",
      static_cast<long long>(reader->GetOutput()->GetNumberOfCells()), diff);
    failures += reader->GetReadDirectly() && diff == 0 ? 0 : 1;
  }
  MEDIAL_CHECK(failures == 0, "%d cases failed", failures);
  return EXIT_SUCCESS;
}
