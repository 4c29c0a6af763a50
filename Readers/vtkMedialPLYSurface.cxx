// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPLYSurface.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// The file's bytes after the header, through a buffer of 1 MiB: no copy of the whole
// face block, whose faces are read one by one.
class ByteStream
{
public:
  explicit ByteStream(std::FILE* file)
    : File(file)
    , Buffer(1 << 20)
  {
  }

  // Copies the next n bytes to `to`; false at the end of the file.
  bool Read(void* to, size_t n)
  {
    char* out = static_cast<char*>(to);
    while (n > 0)
    {
      if (this->Next == this->End && !this->Fill())
      {
        return false;
      }
      const size_t take = std::min(n, this->End - this->Next);
      std::memcpy(out, this->Buffer.data() + this->Next, take);
      this->Next += take;
      out += take;
      n -= take;
    }
    return true;
  }

private:
  bool Fill()
  {
    this->Next = 0;
    this->End = std::fread(this->Buffer.data(), 1, this->Buffer.size(), this->File);
    return this->End > 0;
  }

  std::FILE* File;
  std::vector<char> Buffer;
  size_t Next = 0, End = 0;
};

struct FileCloser
{
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// The header's facts the fast path needs; Parse is false for any other layout.
struct Header
{
  long long Vertices = -1, Faces = -1;
  bool Normals = false;
  int CountBytes = 0;        // size of a face's vertex count: 1, 2 or 4

  bool Parse(std::FILE* file)
  {
    char line[1024];
    std::vector<std::string> vertexProperties;
    bool faceList = false, format = false;
    int element = 0; // 0 none yet, 1 vertex, 2 face
    for (int lines = 0; lines < 4096; ++lines)
    {
      if (!std::fgets(line, sizeof(line), file) || !std::strchr(line, '\n'))
      {
        return false; // ended early, or a line longer than any this layout has
      }
      std::istringstream words(line);
      std::string word;
      words >> word;
      if (lines == 0)
      {
        if (word != "ply" || (words >> word))
        {
          return false;
        }
        continue;
      }
      if (word == "comment" || word == "obj_info")
      {
        continue;
      }
      std::vector<std::string> rest;
      for (std::string w; words >> w;)
      {
        rest.push_back(w);
      }
      if (word == "format")
      {
        format = rest.size() == 2 && rest[0] == "binary_little_endian" && rest[1] == "1.0";
        if (!format || element != 0)
        {
          return false;
        }
      }
      else if (word == "element" && rest.size() == 2)
      {
        const long long count = std::strtoll(rest[1].c_str(), nullptr, 10);
        if (count <= 0 || count >= std::numeric_limits<std::int32_t>::max() ||
          rest[1].find_first_not_of("0123456789") != std::string::npos)
        {
          return false;
        }
        if (element == 0 && rest[0] == "vertex")
        {
          element = 1;
          this->Vertices = count;
        }
        else if (element == 1 && rest[0] == "face")
        {
          element = 2;
          this->Faces = count;
        }
        else
        {
          return false; // another element, or another order
        }
      }
      else if (word == "property" && element == 1)
      {
        if (rest.size() != 2 || (rest[0] != "float" && rest[0] != "float32"))
        {
          return false;
        }
        vertexProperties.push_back(rest[1]);
      }
      else if (word == "property" && element == 2)
      {
        if (faceList || rest.size() != 4 || rest[0] != "list" || rest[3] != "vertex_indices" ||
          !this->ParseCount(rest[1]) || !this->ParseIndex(rest[2]))
        {
          return false;
        }
        faceList = true;
      }
      else if (word == "end_header" && rest.empty())
      {
        const std::vector<std::string> xyz = { "x", "y", "z" };
        const std::vector<std::string> normals = { "x", "y", "z", "nx", "ny", "nz" };
        this->Normals = vertexProperties == normals;
        return format && element == 2 && faceList && (vertexProperties == xyz || this->Normals);
      }
      else
      {
        return false;
      }
    }
    return false;
  }

private:
  bool ParseCount(const std::string& type)
  {
    this->CountBytes = type == "uchar" || type == "uint8" ? 1
      : type == "ushort" || type == "uint16"               ? 2
      : type == "uint" || type == "uint32" || type == "int" || type == "int32" ? 4
                                                                               : 0;
    return this->CountBytes > 0;
  }
  static bool ParseIndex(const std::string& type)
  {
    return type == "int" || type == "int32" || type == "uint" || type == "uint32";
  }
};

bool LittleEndianHost()
{
  const std::uint32_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}
}

bool vtkMedialReadPLYSurface(const char* fileName, vtkPolyData* output)
{
  if (!fileName || !LittleEndianHost())
  {
    return false;
  }
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(fileName, "rb"));
  Header header;
  if (!file || !header.Parse(file.get()))
  {
    return false;
  }
  const vtkIdType nv = header.Vertices, nf = header.Faces;
  ByteStream in(file.get());

  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(nv);
  float* xyz = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  vtkNew<vtkFloatArray> normals;
  if (!header.Normals)
  {
    if (!in.Read(xyz, 3 * sizeof(float) * static_cast<size_t>(nv)))
    {
      return false;
    }
  }
  else
  {
    normals->SetName("Normals"); // vtkPLYReader's name
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(nv);
    float* n = normals->GetPointer(0);
    float vertex[6];
    for (vtkIdType i = 0; i < nv; ++i)
    {
      if (!in.Read(vertex, sizeof(vertex)))
      {
        return false;
      }
      std::memcpy(xyz + 3 * i, vertex, 3 * sizeof(float));
      std::memcpy(n + 3 * i, vertex + 3, 3 * sizeof(float));
    }
  }

  // Faces: a count, then that many indices, each checked. Triangles (nearly always)
  // fill the connectivity as it was sized; larger polygons grow it.
  vtkNew<vtkTypeInt32Array> offsets, connectivity;
  offsets->SetNumberOfValues(nf + 1);
  connectivity->SetNumberOfValues(3 * nf);
  std::int32_t* offset = offsets->GetPointer(0);
  std::int32_t* ids = connectivity->GetPointer(0);
  vtkIdType room = 3 * nf, used = 0;
  offset[0] = 0;
  for (vtkIdType f = 0; f < nf; ++f)
  {
    std::uint32_t count = 0; // little endian: the count's bytes are its low bytes
    if (!in.Read(&count, static_cast<size_t>(header.CountBytes)))
    {
      return false;
    }
    if (count < 3 || count > 255)
    {
      return false; // vtkPLYReader's own limits: leave such files to it
    }
    if (used + count > room)
    {
      room = 2 * room + count;
      connectivity->Resize(room); // keeps the values so far
      ids = connectivity->GetPointer(0);
    }
    std::int32_t* face = ids + used;
    if (!in.Read(face, 4 * static_cast<size_t>(count)))
    {
      return false;
    }
    for (std::uint32_t k = 0; k < count; ++k)
    {
      // int or uint alike: a valid index is below the vertex count, itself below 2^31.
      if (static_cast<std::uint32_t>(face[k]) >= static_cast<std::uint32_t>(nv))
      {
        return false;
      }
    }
    used += count;
    if (used > std::numeric_limits<std::int32_t>::max())
    {
      return false;
    }
    offset[f + 1] = static_cast<std::int32_t>(used);
  }
  if (used != 3 * nf)
  {
    connectivity->SetNumberOfValues(used);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
  if (header.Normals)
  {
    output->GetPointData()->SetNormals(normals);
  }
  return true;
}
