// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallPLYWriter.h"
#include "vtkMedialBallRecords.h"

#include "vtkByteSwap.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>

vtkStandardNewMacro(vtkMedialBallPLYWriter);

namespace
{
// Binary records are gathered in a buffer and written little endian.
class BinaryRecords
{
public:
  explicit BinaryRecords(std::ostream& file)
    : File(file)
  {
  }
  ~BinaryRecords() { this->Flush(); }
  void Add(double value) { this->Append(&value, sizeof(value)); }
  void Add(std::int32_t value) { this->Append(&value, sizeof(value)); }
  void Add(std::uint8_t value) { this->Append(&value, sizeof(value)); }
  void Flush()
  {
    this->File.write(this->Bytes.data(), static_cast<std::streamsize>(this->Bytes.size()));
    this->Bytes.clear();
  }

private:
  void Append(const void* value, size_t size)
  {
    char bytes[8];
    std::memcpy(bytes, value, size);
    if (size == 8)
    {
      vtkByteSwap::Swap8LE(bytes);
    }
    else if (size == 4)
    {
      vtkByteSwap::Swap4LE(bytes);
    }
    this->Bytes.append(bytes, size);
    if (this->Bytes.size() > (1 << 20))
    {
      this->Flush();
    }
  }
  std::ostream& File;
  std::string Bytes;
};

std::string Header(const medialballs::BallRecords& records, bool binary)
{
  std::string text = "ply\nformat ";
  text += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
  text += "comment medial balls written by medialaxis (vtkMedialBallPLYWriter)\n";
  text += "element vertex " + std::to_string(records.Input->GetNumberOfPoints()) + "\n";
  text += "property double x\nproperty double y\nproperty double z\nproperty double radius\n";
  if (!records.Edges.empty())
  {
    text += "element edge " + std::to_string(records.Edges.size()) + "\n";
    text += "property int vertex1\nproperty int vertex2\n";
  }
  if (!records.Faces.empty())
  {
    text += "element face " + std::to_string(records.Faces.size()) + "\n";
    text += "property list uchar int vertex_indices\n";
  }
  return text + "end_header\n";
}

void WriteBinary(std::ostream& file, const medialballs::BallRecords& records)
{
  BinaryRecords out(file);
  for (vtkIdType i = 0; i < records.Input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    records.Input->GetPoint(i, p);
    out.Add(p[0]);
    out.Add(p[1]);
    out.Add(p[2]);
    out.Add(records.Radius->GetComponent(i, 0));
  }
  for (const auto& e : records.Edges)
  {
    out.Add(static_cast<std::int32_t>(e[0]));
    out.Add(static_cast<std::int32_t>(e[1]));
  }
  for (const auto& f : records.Faces)
  {
    out.Add(static_cast<std::uint8_t>(3));
    for (vtkIdType id : f)
    {
      out.Add(static_cast<std::int32_t>(id));
    }
  }
}

void WriteASCII(std::ostream& file, const medialballs::BallRecords& records)
{
  using medialballs::AppendNumber;
  std::string text;
  auto endLine = [&]() {
    text += '\n';
    if (text.size() > (1 << 20))
    {
      file.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  };
  for (vtkIdType i = 0; i < records.Input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    records.Input->GetPoint(i, p);
    AppendNumber(text, p[0]);
    for (double value : { p[1], p[2], records.Radius->GetComponent(i, 0) })
    {
      text += ' ';
      AppendNumber(text, value);
    }
    endLine();
  }
  for (const auto& e : records.Edges)
  {
    AppendNumber(text, e[0]);
    text += ' ';
    AppendNumber(text, e[1]);
    endLine();
  }
  for (const auto& f : records.Faces)
  {
    text += '3';
    for (vtkIdType id : f)
    {
      text += ' ';
      AppendNumber(text, id);
    }
    endLine();
  }
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
}
}

void vtkMedialBallPLYWriter::WriteData()
{
  vtkPolyData* input = this->GetInput();
  if (input && input->GetNumberOfPoints() > std::numeric_limits<std::int32_t>::max())
  {
    vtkErrorMacro("Cannot write PLY balls '" << (this->FileName ? this->FileName : "")
                                             << "': more points than an int index can hold; nothing written.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  this->Superclass::WriteData();
}

void vtkMedialBallPLYWriter::WriteRecords(std::ostream& file, const medialballs::BallRecords& records)
{
  const bool binary = this->FileType == VTK_BINARY;
  const std::string header = Header(records, binary);
  file.write(header.data(), static_cast<std::streamsize>(header.size()));
  if (binary)
  {
    WriteBinary(file, records);
  }
  else
  {
    WriteASCII(file, records);
  }
}

void vtkMedialBallPLYWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileType: " << (this->FileType == VTK_BINARY ? "BINARY" : "ASCII") << "\n";
}
