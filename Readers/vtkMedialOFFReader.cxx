// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialOFFReader.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "vtkMedialTextParsing.h"

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

vtkStandardNewMacro(vtkMedialOFFReader);

namespace
{
using medialreaders::Quote;

struct PolygonMesh
{
  std::vector<double> Coordinates; // x y z per vertex
  std::vector<vtkIdType> Offsets{ 0 };
  std::vector<vtkIdType> Connectivity;
};

bool StartsLikeNumber(std::string_view token)
{
  const char c = token[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

// The header keyword, including variants that start with a digit such as 4OFF.
bool IsKeyword(std::string_view token)
{
  return !StartsLikeNumber(token) ||
    (token.size() >= 3 && token.substr(token.size() - 3) == "OFF");
}

class OFFParser : public medialreaders::RecordParser
{
public:
  /// Opens the file and reads the header: keyword (optional) and counts.
  bool ParseHeader(const std::string& path)
  {
    if (!this->Open(path))
    {
      return false;
    }
    if (!this->Lines.NextRecord())
    {
      return this->Fail("the file is empty: expected the 'OFF' header");
    }
    // The counts follow the keyword, on its line or the next; or stand alone.
    size_t first = 0;
    if (IsKeyword(this->Lines.GetTokens()[0]))
    {
      if (!this->ParseKeyword())
      {
        return false;
      }
      if (this->Lines.GetTokens().size() > 1)
      {
        first = 1;
      }
      else if (!this->Lines.NextRecord())
      {
        return this->Fail("the file ends before the counts 'nv nf ne'");
      }
      else if (IsKeyword(this->Lines.GetTokens()[0]))
      {
        return this->Fail("expected the counts 'nv nf ne', found " +
          Quote(this->Lines.GetTokens()[0]));
      }
    }
    const auto& header = this->Lines.GetTokens();
    const size_t given = header.size() - first;
    if (given < 2 || given > 3)
    {
      return this->Fail("expected the counts 'nv nf ne' (ne optional), found " +
        std::to_string(given) + " value(s)");
    }
    vtkIdType ne = 0;
    vtkIdType* counts[3] = { &this->VertexCount, &this->FaceCount, &ne };
    const char* names[3] = { "nv", "nf", "ne" };
    for (size_t i = 0; i < given; ++i)
    {
      if (!medialreaders::ParseIndex(header[first + i], VTK_ID_MAX, *counts[i]))
      {
        return this->Fail(std::string("count ") + names[i] + " " + Quote(header[first + i]) +
          " is not a non-negative integer");
      }
    }
    return true;
  }

  /// The whole file: the header, then the vertex and face records.
  bool Parse(const std::string& path, PolygonMesh& mesh)
  {
    if (!this->ParseHeader(path))
    {
      return false;
    }
    const vtkIdType nv = this->VertexCount, nf = this->FaceCount;
    // Shortest records: "0 0 0\n" and "3 0 0 0\n".
    mesh.Coordinates.reserve(3 * this->Lines.CapReserve(nv, 6));
    mesh.Offsets.reserve(this->Lines.CapReserve(nf, 8) + 1);
    mesh.Connectivity.reserve(3 * this->Lines.CapReserve(nf, 8));
    const size_t vertexColumns = 3 + (this->HasNormals ? 3 : 0) + (this->HasColours ? 3 : 0);
    for (vtkIdType k = 0; k < nv; ++k)
    {
      if (!this->Lines.NextRecord())
      {
        return this->Fail("the file ends before vertex " + std::to_string(k + 1) + " of " +
          std::to_string(nv) + " (truncated file or wrong counts)");
      }
      const auto& tokens = this->Lines.GetTokens();
      if (tokens.size() < vertexColumns)
      {
        return this->Fail("a vertex of " + this->Variant + " needs " +
          std::to_string(vertexColumns) + " values, found " + std::to_string(tokens.size()) +
          " (truncated line or wrong counts?)");
      }
      double value = 0.0;
      for (size_t c = 0; c < tokens.size(); ++c)
      {
        if (!medialreaders::ParseFinite(tokens[c], value))
        {
          return this->Fail("vertex value " + Quote(tokens[c]) + " " +
            medialreaders::WhyNotFinite(tokens[c]));
        }
        if (c < 3)
        {
          mesh.Coordinates.push_back(value);
        }
      }
    }

    for (vtkIdType k = 0; k < nf; ++k)
    {
      if (!this->Lines.NextRecord())
      {
        return this->Fail("the file ends before face " + std::to_string(k + 1) + " of " +
          std::to_string(nf) + " (truncated file or wrong counts)");
      }
      const auto& tokens = this->Lines.GetTokens();
      vtkIdType size = 0;
      if (!medialreaders::ParseIndex(tokens[0], VTK_ID_MAX, size) || size < 3)
      {
        return this->Fail("a face starts with its number of vertices, at least 3; found " +
          Quote(tokens[0]) + " (wrong vertex count?)");
      }
      if (static_cast<size_t>(size) > tokens.size() - 1)
      {
        return this->Fail("a face of " + std::to_string(size) + " vertices has only " +
          std::to_string(tokens.size() - 1) + " value(s) on its line");
      }
      for (size_t c = 1; c < tokens.size(); ++c)
      {
        vtkIdType id = 0;
        double ignored = 0.0;
        if (c <= static_cast<size_t>(size) && !medialreaders::ParseIndex(tokens[c], nv, id))
        {
          return this->Fail("vertex index " + Quote(tokens[c]) + " is not an integer in [0, " +
            std::to_string(nv) + ")");
        }
        if (c > static_cast<size_t>(size) && !medialreaders::ParseFinite(tokens[c], ignored))
        {
          return this->Fail("face colour value " + Quote(tokens[c]) + " " +
            medialreaders::WhyNotFinite(tokens[c]));
        }
        if (c <= static_cast<size_t>(size))
        {
          mesh.Connectivity.push_back(id);
        }
      }
      mesh.Offsets.push_back(static_cast<vtkIdType>(mesh.Connectivity.size()));
    }
    if (this->Lines.NextRecord())
    {
      return this->Fail("unexpected data " + Quote(this->Lines.GetTokens()[0]) + " after the " +
        std::to_string(nv) + " vertices and " + std::to_string(nf) +
        " faces the header declares (wrong counts?)");
    }
    return true;
  }

private:
  bool ParseKeyword()
  {
    const auto& tokens = this->Lines.GetTokens();
    const std::string keyword(tokens[0].substr(0, 40));
    if (keyword == "OFF" || keyword == "COFF" || keyword == "NOFF" || keyword == "CNOFF")
    {
      this->Variant = keyword;
      this->HasColours = keyword[0] == 'C';
      this->HasNormals = keyword.find('N') != std::string::npos;
      if (tokens.size() > 1 && !StartsLikeNumber(tokens[1]))
      {
        return this->Fail("unsupported OFF variant '" + keyword + " " +
          std::string(tokens[1].substr(0, 20)) + "' (only text OFF, COFF, NOFF, CNOFF are read)");
      }
      return true;
    }
    if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0)
    {
      return this->Fail("unsupported OFF variant " + Quote(keyword) +
        " (only text OFF, COFF, NOFF, CNOFF are read)");
    }
    return this->Fail("not an OFF file: expected the 'OFF' header, found " + Quote(tokens[0]));
  }

  std::string Variant = "OFF";
  vtkIdType VertexCount = 0;
  vtkIdType FaceCount = 0;
  bool HasColours = false;
  bool HasNormals = false;
};
}

int vtkMedialOFFReader::CanReadFile(const char* fileName)
{
  return medialreaders::CanReadHeader<OFFParser>(fileName);
}

int vtkMedialOFFReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  PolygonMesh mesh;
  if (!medialreaders::ParseFile<OFFParser>(this, this->FileName, "OFF file", mesh))
  {
    return 0;
  }

  const vtkIdType nv = static_cast<vtkIdType>(mesh.Coordinates.size() / 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    points->SetPoint(i, &mesh.Coordinates[3 * i]);
  }
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.Offsets.size()));
  std::copy(mesh.Offsets.begin(), mesh.Offsets.end(), offsets->GetPointer(0));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.Connectivity.size()));
  std::copy(mesh.Connectivity.begin(), mesh.Connectivity.end(), connectivity->GetPointer(0));
  vtkNew<vtkCellArray> polygons;
  polygons->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polygons);
  return 1;
}

void vtkMedialOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent); // FileName
}
