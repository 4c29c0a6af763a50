// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialFileReader.h"

#include "vtkMedialBallCSVReader.h"
#include "vtkMedialBallPLYReader.h"
#include "vtkMedialMeshReader.h"
#include "vtkMedialFormatTable.h"
#include "vtkMedialMessageRelay.h"
#include "vtkMedialOFFReader.h"
#include "vtkMedialPLYSurface.h"

#include "vtkCellArray.h"
#include "vtkDataSetReader.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExecutive.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <string>

vtkStandardNewMacro(vtkMedialFileReader);

namespace
{
template <class Reader>
vtkAlgorithm* NewNamed(const char* fileName)
{
  Reader* reader = Reader::New();
  reader->SetFileName(fileName);
  return reader;
}

struct Format
{
  const char* Extension;
  int Content;
  vtkAlgorithm* (*NewReader)(const char* fileName);
  bool ExtractSurface; // the reader gives any dataset: keep its outer surface
  // Reads the format's common layout directly, or returns false for NewReader's reader.
  bool (*ReadDirect)(const char* fileName, vtkPolyData* output);
};

// Every file format the tools read, in the order GetExtensions() lists them.
const Format Formats[] = {
  { ".vtp", vtkMedialFileReader::SURFACE, &NewNamed<vtkXMLPolyDataReader>, false },
  { ".vtk", vtkMedialFileReader::SURFACE, &NewNamed<vtkDataSetReader>, true },
  { ".ply", vtkMedialFileReader::SURFACE, &NewNamed<vtkPLYReader>, false, &vtkMedialReadPLYSurface },
  { ".stl", vtkMedialFileReader::SURFACE, &NewNamed<vtkSTLReader>, false },
  { ".obj", vtkMedialFileReader::SURFACE, &NewNamed<vtkOBJReader>, false },
  { ".off", vtkMedialFileReader::SURFACE, &NewNamed<vtkMedialOFFReader>, false },
  { ".ma", vtkMedialFileReader::BALLS, &NewNamed<vtkMedialMeshReader>, false },
  { ".ply", vtkMedialFileReader::BALLS, &NewNamed<vtkMedialBallPLYReader>, false },
  { ".vtp", vtkMedialFileReader::BALLS, &NewNamed<vtkXMLPolyDataReader>, false },
  { ".vtk", vtkMedialFileReader::BALLS, &NewNamed<vtkPolyDataReader>, false },
  { ".csv", vtkMedialFileReader::BALLS, &NewNamed<vtkMedialBallCSVReader>, false },
};

const Format* FindFormat(const char* fileName, int content)
{
  return vtkMedialFindFormat(Formats, fileName, content);
}
}

vtkAlgorithm* vtkMedialFileReader::NewReader(const char* fileName, int content)
{
  const Format* format = FindFormat(fileName, content);
  return format ? format->NewReader(fileName) : nullptr;
}

std::string vtkMedialFileReader::GetExtensions(int content)
{
  return vtkMedialFormatExtensions(Formats, content);
}

int vtkMedialFileReader::CanReadExtension(const char* fileName, int content)
{
  return FindFormat(fileName, content) ? 1 : 0;
}

std::string vtkMedialFileReader::GetExtension(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  const size_t dot = name.find_last_of('.');
  const size_t slash = name.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  std::string extension = name.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

int vtkMedialFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  this->ReadDirectly = false;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  const Format* format = FindFormat(this->FileName, this->Content);
  this->SetProgressText(this->Content == BALLS ? "Reading the balls" : "Reading the surface");
  if (!format)
  {
    vtkErrorMacro("unsupported input extension '" << GetExtension(this->FileName) << "' ("
                                                  << GetExtensions(this->Content) << ")");
    return 0;
  }
  // The stage starts now for observers that time it (the direct read reports no
  // progress of its own before it ends).
  this->UpdateProgress(0.0);
  this->ReadDirectly = format->ReadDirect && format->ReadDirect(this->FileName, output);
  if (this->ReadDirectly)
  {
    this->UpdateProgress(1.0);
    return 1;
  }
  vtkSmartPointer<vtkAlgorithm> reader;
  reader.TakeReference(format->NewReader(this->FileName));
  // The chosen reader's messages are this reader's; its executive's failure note repeats them.
  vtkNew<vtkMedialMessageRelay> relay;
  relay->Outer = this;
  relay->Relay(reader);
  relay->Mute(reader->GetExecutive());
  relay->RelayProgress(reader, 0.0, format->ExtractSurface ? 0.9 : 1.0);
  vtkSmartPointer<vtkAlgorithm> last = reader;
  if (format->ExtractSurface)
  {
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputConnection(reader->GetOutputPort());
    relay->Relay(surface);
    relay->Mute(surface->GetExecutive());
    last = surface;
  }
  last->Update();
  if (relay->Errors > 0)
  {
    return 0;
  }
  vtkPolyData* data = vtkPolyData::SafeDownCast(last->GetOutputDataObject(0));
  if (!data)
  {
    vtkErrorMacro("'" << this->FileName << "' holds no polygonal data");
    return 0;
  }
  output->ShallowCopy(data);
  // 32-bit cell storage where the ids fit: half the memory of a large surface's
  // connectivity, which the pipeline holds while every later filter runs. (The
  // arrays converted belong to the inner reader, which is about to go away; empty
  // ones are skipped, as vtkPolyData hands out one shared empty array for all.)
  for (vtkCellArray* cells : { output->GetVerts(), output->GetLines(), output->GetPolys(), output->GetStrips() })
  {
    if (cells && cells->GetNumberOfCells() > 0 && cells->IsStorage64Bit() && cells->CanConvertTo32BitStorage())
    {
      cells->ConvertTo32BitStorage();
    }
  }
  return 1;
}

void vtkMedialFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent); // FileName
  os << indent << "Content: " << (this->Content == SURFACE ? "SURFACE" : "BALLS") << "\n";
  os << indent << "ReadDirectly: " << this->ReadDirectly << "\n";
}
