// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshReader.h"
#include "vtkMedialArrayNames.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "vtkMedialBallRecords.h"
#include "vtkMedialTextParsing.h"

#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialMeshReader);

namespace
{
using medialreaders::Quote;

using MedialMesh = medialballs::BallMesh; // faces: 3 ids each

class MedialMeshParser : public medialreaders::RecordParser
{
public:
  /// Opens the file and reads the header 'nv ne nf'.
  bool ParseHeader(const std::string& path)
  {
    if (!this->Open(path))
    {
      return false;
    }
    if (!this->Lines.NextRecord())
    {
      return this->Fail("the file is empty: expected the header 'nv ne nf'");
    }
    const auto& header = this->Lines.GetTokens();
    if (header.size() != 3)
    {
      return this->Fail("expected the header 'nv ne nf' (3 counts), found " +
        std::to_string(header.size()) + " token(s) starting with " + Quote(header[0]));
    }
    const char* names[3] = { "nv", "ne", "nf" };
    for (int i = 0; i < 3; ++i)
    {
      if (!medialreaders::ParseIndex(header[i], VTK_ID_MAX, this->Counts[i]))
      {
        return this->Fail(std::string("header count ") + names[i] + " " + Quote(header[i]) +
          " is not a non-negative integer");
      }
    }
    return true;
  }

  /// The whole file: the header, then the v, e and f records.
  bool Parse(const std::string& path, MedialMesh& mesh)
  {
    if (!this->ParseHeader(path))
    {
      return false;
    }
    const vtkIdType nv = this->Counts[0], ne = this->Counts[1], nf = this->Counts[2];
    // Header counts only bound the reservation by what the file can hold.
    // Shortest records: "v 0 0 0 0\n", "e 0 0\n", "f 0 0 0\n".
    mesh.Coordinates.reserve(3 * this->Lines.CapReserve(nv, 10));
    mesh.Radii.reserve(this->Lines.CapReserve(nv, 10));
    mesh.Edges.reserve(2 * this->Lines.CapReserve(ne, 6));
    mesh.Faces.reserve(3 * this->Lines.CapReserve(nf, 8));

    for (vtkIdType k = 0; k < nv; ++k)
    {
      if (!this->Expect("v", k, nv))
      {
        return false;
      }
      const auto& tokens = this->Lines.GetTokens();
      if (tokens.size() < 5)
      {
        return this->Fail("a 'v' record needs 'v x y z r', found " +
          std::to_string(tokens.size() - 1) + " value(s)");
      }
      double values[4];
      const char* what[4] = { "x", "y", "z", "radius" };
      for (int c = 0; c < 4; ++c)
      {
        if (!medialreaders::ParseFinite(tokens[c + 1], values[c]))
        {
          return this->Fail(std::string("vertex ") + what[c] + " " + Quote(tokens[c + 1]) + " " +
            medialreaders::WhyNotFinite(tokens[c + 1]));
        }
      }
      if (values[3] < 0.0)
      {
        return this->Fail("negative radius " + Quote(tokens[4]));
      }
      mesh.Coordinates.insert(mesh.Coordinates.end(), values, values + 3);
      mesh.Radii.push_back(values[3]);
    }
    if (!this->ReadCells("e", ne, 2, nv, mesh.Edges) ||
      !this->ReadCells("f", nf, 3, nv, mesh.Faces))
    {
      return false;
    }
    if (this->Lines.NextRecord())
    {
      return this->Fail("unexpected record " + Quote(this->Lines.GetTokens()[0]) +
        " after the " + std::to_string(nv) + " vertices, " + std::to_string(ne) + " edges and " +
        std::to_string(nf) + " faces the header declares");
    }
    return true;
  }

private:
  // Moves to record k (0-based) of the `count` records of this kind.
  bool Expect(const char* kind, vtkIdType k, vtkIdType count)
  {
    const std::string where = std::to_string(k + 1) + " of " + std::to_string(count);
    if (!this->Lines.NextRecord())
    {
      return this->Fail(std::string("the file ends before '") + kind + "' record " + where +
        " (truncated file or wrong header counts)");
    }
    if (this->Lines.GetTokens()[0] != kind)
    {
      return this->Fail(std::string("expected '") + kind + "' record " + where + ", found " +
        Quote(this->Lines.GetTokens()[0]) + " (wrong header counts?)");
    }
    return true;
  }

  bool ReadCells(const char* kind, vtkIdType count, size_t size, vtkIdType nv,
    std::vector<vtkIdType>& ids)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      if (!this->Expect(kind, k, count))
      {
        return false;
      }
      const auto& tokens = this->Lines.GetTokens();
      if (tokens.size() != size + 1)
      {
        return this->Fail(std::string("an '") + kind + "' record needs " + std::to_string(size) +
          " vertex indices, found " + std::to_string(tokens.size() - 1) + " value(s)");
      }
      for (size_t c = 1; c <= size; ++c)
      {
        vtkIdType id = 0;
        if (!medialreaders::ParseIndex(tokens[c], nv, id))
        {
          return this->Fail("vertex index " + Quote(tokens[c]) + " is not an integer in [0, " +
            std::to_string(nv) + ")");
        }
        ids.push_back(id);
      }
    }
    return true;
  }

  vtkIdType Counts[3] = { 0, 0, 0 }; // nv ne nf
};
}

int vtkMedialMeshReader::CanReadFile(const char* fileName)
{
  return medialreaders::CanReadHeader<MedialMeshParser>(fileName);
}

int vtkMedialMeshReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  MedialMesh mesh;
  if (!medialreaders::ParseFile<MedialMeshParser>(this, this->FileName, "medial mesh", mesh))
  {
    return 0;
  }

  medialballs::ToPolyData(mesh, output);
  return 1;
}

void vtkMedialMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent); // FileName
}
