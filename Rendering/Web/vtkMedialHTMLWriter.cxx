// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialHTMLWriter.h"
#include "vtkMedialViewerBundle.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialJson.h"
#include "vtkMedialMessageRelay.h"
#include "vtkMedialOutline.h"
#include "vtkMedialPlane.h"
#include "vtkMedialScene.h"

#include "vtkArchiver.h"
#include "vtkBase64Utilities.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkJSONDataSetWriter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkZLibDataCompressor.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialHTMLWriter);
vtkCxxSetObjectMacro(vtkMedialHTMLWriter, Surface, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialHTMLWriter, Balls, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialHTMLWriter, MedialMesh, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialHTMLWriter, Graph, vtkPolyData);
vtkCxxSetObjectMacro(vtkMedialHTMLWriter, Reconstruction, vtkPolyData);

namespace
{
// The files vtkJSONDataSetWriter writes (index.json, data/<hash>), kept in memory.
class MemoryArchive : public vtkArchiver
{
public:
  static MemoryArchive* New();
  vtkTypeMacro(MemoryArchive, vtkArchiver);
  void OpenArchive() override {}
  void CloseArchive() override {}
  void InsertIntoArchive(const std::string& relativePath, const char* data, std::size_t size) override
  {
    this->Files[relativePath].assign(data, size);
  }
  bool Contains(const std::string& relativePath) override { return this->Files.count(relativePath) > 0; }
  std::map<std::string, std::string> Files;
};
vtkStandardNewMacro(MemoryArchive);

std::string Base64(const std::string& bytes)
{
  std::string out(4 * ((bytes.size() + 2) / 3) + 4, '\0');
  const unsigned long n = vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(bytes.data()),
    static_cast<unsigned long>(bytes.size()), reinterpret_cast<unsigned char*>(&out[0]), 0);
  out.resize(n);
  return out;
}

std::string Deflate(const std::string& bytes)
{
  vtkNew<vtkZLibDataCompressor> zlib;
  zlib->SetCompressionLevel(9);
  std::string out(zlib->GetMaximumCompressionSpace(bytes.size()), '\0');
  const size_t n = zlib->Compress(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
    reinterpret_cast<unsigned char*>(&out[0]), out.size());
  out.resize(n);
  return out;
}

// JSON string literals here sit inside a <script> element.
std::string Json(const std::string& s)
{
  return vtkMedialJsonString(s, /*scriptSafe=*/true);
}

std::string Html(const std::string& s)
{
  std::string out;
  for (const char c : s)
  {
    switch (c)
    {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Number(double v)
{
  if (!std::isfinite(v))
  {
    return "null";
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

std::string Vector(const double v[3])
{
  return "[" + Number(v[0]) + ", " + Number(v[1]) + ", " + Number(v[2]) + "]";
}

// The points of `source` (those of `keep`, when given) as float32, the page's precision.
vtkSmartPointer<vtkPoints> FloatPoints(vtkPolyData* source, const std::vector<vtkIdType>* keep = nullptr)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  const vtkIdType n = keep ? static_cast<vtkIdType>(keep->size()) : source->GetNumberOfPoints();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, source->GetPoint(keep ? (*keep)[i] : i));
  }
  return points;
}

// A copy of the array `from` (its tuples in `keep`, when given) as float32 or, for
// codes, uint8, added to `to`.
void CopyArray(vtkDataArray* from, vtkDataSetAttributes* to, bool codes, const std::vector<vtkIdType>* keep = nullptr)
{
  if (!from)
  {
    return;
  }
  vtkSmartPointer<vtkDataArray> copy;
  if (codes)
  {
    copy = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  else
  {
    copy = vtkSmartPointer<vtkFloatArray>::New();
  }
  copy->SetName(from->GetName());
  copy->SetNumberOfComponents(from->GetNumberOfComponents());
  const vtkIdType n = keep ? static_cast<vtkIdType>(keep->size()) : from->GetNumberOfTuples();
  copy->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType source = keep ? (*keep)[i] : i;
    for (int c = 0; c < from->GetNumberOfComponents(); ++c)
    {
      copy->SetComponent(i, c, from->GetComponent(source, c));
    }
  }
  to->AddArray(copy);
}

// The page's copy of a dataset: float32 points, the given cells and point arrays
// (`codes` as uint8), and `cellCodes` as uint8 cell arrays.
vtkSmartPointer<vtkPolyData> Slim(vtkPolyData* source, bool lines, bool polys,
  std::initializer_list<const char*> values, std::initializer_list<const char*> codes,
  std::initializer_list<const char*> cellCodes = {})
{
  auto slim = vtkSmartPointer<vtkPolyData>::New();
  slim->SetPoints(FloatPoints(source));
  if (lines && source->GetNumberOfLines() > 0)
  {
    slim->SetLines(source->GetLines());
  }
  if (polys && source->GetNumberOfPolys() > 0)
  {
    slim->SetPolys(source->GetPolys());
  }
  for (const char* name : values)
  {
    CopyArray(source->GetPointData()->GetArray(name), slim->GetPointData(), false);
  }
  for (const char* name : codes)
  {
    CopyArray(source->GetPointData()->GetArray(name), slim->GetPointData(), true);
  }
  for (const char* name : cellCodes)
  {
    CopyArray(source->GetCellData()->GetArray(name), slim->GetCellData(), true);
  }
  return slim;
}

// The page's data: one vtk.js dataset per layer, its arrays shared by content hash.
struct PageData
{
  std::map<std::string, std::string> Resources; // data-url -> base64 (or JSON text)
  std::string Error;

  // Writes `data` as "<name>.json" and its arrays as "data/<hash>.gz".
  bool Add(const std::string& name, vtkPolyData* data, vtkObject* owner)
  {
    vtkNew<MemoryArchive> archive;
    vtkNew<vtkJSONDataSetWriter> writer;
    vtkNew<vtkMedialMessageRelay> relay;
    relay->Outer = owner;
    relay->Relay(writer);
    writer->SetArchiver(archive);
    writer->SetInputData(data);
    writer->Write();
    auto index = archive->Files.find("index.json");
    if (relay->Errors > 0 || index == archive->Files.end())
    {
      this->Error = "vtkJSONDataSetWriter could not export the " + name;
      return false;
    }
    for (const auto& file : archive->Files)
    {
      if (file.first != "index.json")
      {
        this->Resources[file.first + ".gz"] = Base64(Deflate(file.second));
      }
    }
    this->Resources[name + ".json"] = index->second;
    return true;
  }
};

// The viewer's script, safe inside a <script> element.
std::string ScriptText(const char* text, size_t size)
{
  std::string out;
  out.reserve(size + 64);
  for (size_t i = 0; i < size; ++i)
  {
    if (text[i] == '<' && i + 1 < size && (text[i + 1] == '/' || text[i + 1] == '!'))
    {
      out += "<\\"; // "<\/script" and "<\!--" mean the same to JavaScript
      continue;
    }
    out += text[i];
  }
  return out;
}
}

vtkMedialHTMLWriter::vtkMedialHTMLWriter() = default;

vtkMedialHTMLWriter::~vtkMedialHTMLWriter()
{
  this->SetSurface(nullptr);
  this->SetBalls(nullptr);
  this->SetMedialMesh(nullptr);
  this->SetGraph(nullptr);
  this->SetReconstruction(nullptr);
}

bool vtkMedialHTMLWriter::HasViewer()
{
  return vtkMedialViewerBundle::Size > 0;
}

const char* vtkMedialHTMLWriter::GetViewerStatus()
{
  return vtkMedialViewerBundle::Status;
}

const char* vtkMedialHTMLWriter::GetViewerVersion()
{
  return vtkMedialViewerBundle::VtkJsVersion;
}

int vtkMedialHTMLWriter::Write()
{
  this->NumberOfBytes = this->NumberOfViewerBytes = this->NumberOfDataBytes = 0;
  this->NumberOfDisplayedBalls = this->NumberOfBalls = 0;
  this->OutputString.clear();
  if (!HasViewer())
  {
    vtkErrorMacro("This build has no web viewer: " << GetViewerStatus());
    return 0;
  }
  if (!this->Surface && !this->Balls && !this->MedialMesh && !this->Graph)
  {
    vtkErrorMacro("Nothing to show: set a Surface, Balls, a MedialMesh or a Graph.");
    return 0;
  }
  if (!this->WriteToOutputString && this->FileName.empty())
  {
    vtkErrorMacro("No FileName to write.");
    return 0;
  }
  for (vtkPolyData* data : { this->Balls, this->MedialMesh, this->Graph })
  {
    if (data && data->GetNumberOfPoints() > 0 && !data->GetPointData()->GetArray(vtkMedialArrayNames::Radius))
    {
      vtkErrorMacro("Balls, MedialMesh and Graph need the point array 'Radius'.");
      return 0;
    }
  }

  const bool planar = this->Graph != nullptr || (this->Surface && vtkMedialPlane::IsPlanarLoops(this->Surface));
  PageData page;
  std::ostringstream layers;
  const char* separator = "";
  auto layer = [&](const std::string& name, vtkPolyData* data, const std::string& extra) {
    if (!page.Add(name, data, this))
    {
      return false;
    }
    layers << separator << "\n    " << Json(name) << ": {\"url\": " << Json(name + ".json")
           << ", \"points\": " << data->GetNumberOfPoints() << ", \"cells\": " << data->GetNumberOfCells() << extra
           << "}";
    separator = ",";
    return true;
  };

  bool ok = true;
  if (this->Surface && this->Surface->GetNumberOfPoints() > 0)
  {
    vtkSmartPointer<vtkPolyData> surface;
    if (planar)
    {
      vtkSmartPointer<vtkPolyData> outline = vtkMedialOutline::Boundary(this->Surface);
      surface = Slim(outline, true, false, {}, {});
    }
    else
    {
      surface = Slim(this->Surface, false, true,
        { vtkMedialArrayNames::Thickness, vtkMedialArrayNames::MedialRadius }, {});
    }
    const bool thickness = !planar && this->Surface->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    ok = ok && layer("surface", surface,
      std::string(", \"outline\": ") + (planar ? "true" : "false") + ", \"thickness\": " + (thickness ? "true" : "false"));
  }
  if (ok && this->Balls && this->Balls->GetNumberOfPoints() > 0)
  {
    const vtkIdType n = this->Balls->GetNumberOfPoints();
    const vtkIdType stride = (n + this->MaximumNumberOfBalls - 1) / this->MaximumNumberOfBalls;
    std::vector<vtkIdType> keep;
    for (vtkIdType i = 0; i < n; i += stride)
    {
      keep.push_back(i);
    }
    auto balls = vtkSmartPointer<vtkPolyData>::New();
    balls->SetPoints(FloatPoints(this->Balls, &keep));
    CopyArray(this->Balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius), balls->GetPointData(), false, &keep);
    CopyArray(
      this->Balls->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType), balls->GetPointData(), true, &keep);
    this->NumberOfBalls = n;
    this->NumberOfDisplayedBalls = static_cast<vtkIdType>(keep.size());
    ok = layer("balls", balls,
      ", \"total\": " + std::to_string(n) + ", \"stride\": " + std::to_string(stride) +
        ", \"maximum\": " + std::to_string(this->MaximumNumberOfBalls));
  }
  if (ok && this->MedialMesh && this->MedialMesh->GetNumberOfPoints() > 0)
  {
    ok = layer("mesh",
      Slim(this->MedialMesh, true, true, { vtkMedialArrayNames::Radius }, { vtkMedialArrayNames::MedialPointType }), "");
  }
  if (ok && this->Graph && this->Graph->GetNumberOfPoints() > 0)
  {
    ok = layer("graph",
      Slim(this->Graph, true, false, { vtkMedialArrayNames::Radius }, { vtkMedialArrayNames::MedialPointType },
        { vtkMedialArrayNames::ArcType }),
      "");
  }
  if (ok && this->Reconstruction && this->Reconstruction->GetNumberOfPolys() > 0)
  {
    ok = layer("reconstruction", Slim(this->Reconstruction, false, true, {}, {}), "");
  }
  if (!ok)
  {
    vtkErrorMacro(<< page.Error);
    return 0;
  }

  // The opening view: vtkMedialScene's, for the same data.
  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(this->Surface);
  scene->SetMedial(this->MedialMesh ? this->MedialMesh : this->Balls);
  scene->SetGraph(this->Graph);
  scene->SetViewDirection(this->ViewDirection);
  double right[3], up[3], toward[3];
  scene->GetViewAxes(right, up, toward);

  std::ostringstream manifest;
  manifest << "{\n  \"title\": " << Json(this->Title) << ",\n  \"details\": " << Json(this->Details)
           << ",\n  \"planar\": " << (planar ? "true" : "false") << ",\n  \"vtkjs\": "
           << Json(vtkMedialViewerBundle::VtkJsVersion) << ",\n  \"view\": {\"up\": " << Vector(up)
           << ", \"toward\": " << Vector(toward) << "},\n  \"layers\": {" << layers.str() << "\n  }\n}\n";

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
       << "<meta name=\"generator\" content=\"medialaxis vtkMedialHTMLWriter, vtk.js "
       << Html(vtkMedialViewerBundle::VtkJsVersion) << "\">\n<title>" << Html(this->Title) << "</title>\n</head>\n<body>\n"
       << "<noscript>This page shows a medialaxis result with vtk.js: it needs JavaScript and WebGL.</noscript>\n"
       << "<script type=\"application/json\" id=\"medial-manifest\">" << manifest.str() << "</script>\n";
  size_t dataBytes = 0;
  for (const auto& resource : page.Resources)
  {
    html << "<script type=\"application/octet-stream\" class=\"webResource\" data-url=\"" << Html(resource.first)
         << "\">" << resource.second << "</script>\n";
    dataBytes += resource.second.size();
  }
  const std::string script = ScriptText(vtkMedialViewerBundle::Text, vtkMedialViewerBundle::Size);
  html << "<script>\n" << script << "\n</script>\n</body>\n</html>\n";
  const std::string text = html.str();
  this->NumberOfBytes = static_cast<vtkIdType>(text.size());
  this->NumberOfViewerBytes = static_cast<vtkIdType>(script.size());
  this->NumberOfDataBytes = static_cast<vtkIdType>(dataBytes);

  if (this->WriteToOutputString)
  {
    this->OutputString = text;
    return 1;
  }
  std::ofstream file(this->FileName, std::ios::binary);
  if (!file)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "' for writing.");
    return 0;
  }
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
  file.close();
  if (!file)
  {
    vtkErrorMacro("Cannot write '" << this->FileName << "' (disk full?).");
    return 0;
  }
  return 1;
}

void vtkMedialHTMLWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Surface: " << this->Surface << "\n";
  os << indent << "Balls: " << this->Balls << "\n";
  os << indent << "MedialMesh: " << this->MedialMesh << "\n";
  os << indent << "Graph: " << this->Graph << "\n";
  os << indent << "Reconstruction: " << this->Reconstruction << "\n";
  os << indent << "Title: " << this->Title << "\n";
  os << indent << "Details: " << this->Details << "\n";
  os << indent << "MaximumNumberOfBalls: " << this->MaximumNumberOfBalls << "\n";
  os << indent << "ViewDirection: " << vtkMedialScene::GetViewDirectionName(this->ViewDirection) << "\n";
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "WriteToOutputString: " << this->WriteToOutputString << "\n";
  os << indent << "NumberOfBytes: " << this->NumberOfBytes << "\n";
  os << indent << "NumberOfDisplayedBalls: " << this->NumberOfDisplayedBalls << " of " << this->NumberOfBalls << "\n";
  os << indent << "Viewer: " << (HasViewer() ? GetViewerVersion() : GetViewerStatus()) << "\n";
}
