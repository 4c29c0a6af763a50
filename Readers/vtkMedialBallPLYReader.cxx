// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallPLYReader.h"
#include "vtkMedialBallRecords.h"
#include "vtkMedialTextParsing.h"

#include "vtkByteSwap.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkMedialBallPLYReader);

namespace
{
using medialreaders::Quote;

enum class Scalar
{
  INT8,
  UINT8,
  INT16,
  UINT16,
  INT32,
  UINT32,
  FLOAT32,
  FLOAT64
};

bool ScalarOf(const std::string& name, Scalar& type)
{
  static const struct
  {
    const char* Name;
    Scalar Type;
  } names[] = { { "char", Scalar::INT8 }, { "int8", Scalar::INT8 }, { "uchar", Scalar::UINT8 },
    { "uint8", Scalar::UINT8 }, { "short", Scalar::INT16 }, { "int16", Scalar::INT16 },
    { "ushort", Scalar::UINT16 }, { "uint16", Scalar::UINT16 }, { "int", Scalar::INT32 },
    { "int32", Scalar::INT32 }, { "uint", Scalar::UINT32 }, { "uint32", Scalar::UINT32 },
    { "float", Scalar::FLOAT32 }, { "float32", Scalar::FLOAT32 }, { "double", Scalar::FLOAT64 },
    { "float64", Scalar::FLOAT64 } };
  for (const auto& n : names)
  {
    if (name == n.Name)
    {
      type = n.Type;
      return true;
    }
  }
  return false;
}

bool IsInteger(Scalar type)
{
  return type != Scalar::FLOAT32 && type != Scalar::FLOAT64;
}

struct Property
{
  std::string Name;
  Scalar Type = Scalar::FLOAT64; // of the items, for a list
  bool List = false;
  Scalar CountType = Scalar::UINT8;
};

struct Element
{
  std::string Name;
  vtkIdType Count = 0;
  std::vector<Property> Properties;

  int Find(const char* name) const
  {
    for (size_t i = 0; i < this->Properties.size(); ++i)
    {
      if (this->Properties[i].Name == name)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  }
};

// A whole token as a double; "nan" and "inf" are numbers here (checked where used).
bool ParseNumber(const std::string& token, double& value)
{
  const char* begin = token.data() + (!token.empty() && token[0] == '+' ? 1 : 0);
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(begin, end, value);
  return begin != end && result.ec == std::errc() && result.ptr == end;
}

void SplitWords(const std::string& line, std::vector<std::string>& words)
{
  words.clear();
  size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
    {
      ++i;
    }
    const size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
    {
      ++i;
    }
    if (i > start)
    {
      words.push_back(line.substr(start, i - start));
    }
  }
}

enum class Format
{
  ASCII,
  BINARY_LE,
  BINARY_BE
};

// Reads the header, then the body element by element.
class PLYBallParser
{
public:
  std::string Error;

  bool ParseHeader(const std::string& path)
  {
    struct stat info;
    if (stat(path.c_str(), &info) != 0)
    {
      return this->Fail(std::string("cannot open the file: ") + std::strerror(errno));
    }
    if (S_ISDIR(info.st_mode))
    {
      return this->Fail("cannot open the file: it is a directory");
    }
    this->FileSize = S_ISREG(info.st_mode) ? static_cast<vtkTypeInt64>(info.st_size) : 0;
    this->Stream.open(path, std::ios::in | std::ios::binary);
    if (!this->Stream)
    {
      return this->Fail("cannot open the file");
    }
    std::string line;
    if (!this->HeaderLine(line) || line != "ply")
    {
      return this->Fail("not a PLY file (the first line is not 'ply')");
    }
    bool formatSeen = false;
    while (this->HeaderLine(line))
    {
      SplitWords(line, this->Words);
      if (this->Words.empty() || this->Words[0] == "comment" || this->Words[0] == "obj_info")
      {
        continue;
      }
      if (this->Words[0] == "end_header")
      {
        return formatSeen ? this->CheckVertices() : this->Fail("the header has no 'format' line");
      }
      if (!(this->Words[0] == "format" ? this->ReadFormat(formatSeen) : this->ReadDeclaration()))
      {
        return false;
      }
    }
    return this->Error.empty() ? this->Fail("the header does not end with 'end_header'") : false;
  }

  bool Parse(const std::string& path, medialballs::BallMesh& mesh, const std::function<void(double)>& progress)
  {
    if (!this->ParseHeader(path))
    {
      return false;
    }
    vtkIdType total = 0, done = 0;
    for (const Element& e : this->Elements)
    {
      total += e.Count;
    }
    const vtkIdType step = std::max<vtkIdType>(1, total / 100);
    for (const Element& element : this->Elements)
    {
      this->Reserve(element, mesh);
      for (vtkIdType k = 0; k < element.Count; ++k, ++done)
      {
        if (!this->ReadRecord(element, k, mesh))
        {
          return false;
        }
        if (progress && done % step == 0)
        {
          progress(static_cast<double>(done) / static_cast<double>(total));
        }
      }
    }
    return true;
  }

private:
  bool Fail(const std::string& message)
  {
    if (this->Error.empty())
    {
      this->Error = message;
    }
    return false;
  }

  // A header line without its '\r'; false at the end of the file or past a sane size.
  bool HeaderLine(std::string& line)
  {
    if (++this->HeaderLines > 100000 || !std::getline(this->Stream, line))
    {
      return false;
    }
    if (line.size() > 4096)
    {
      return this->Fail("a header line is longer than 4096 characters (not a PLY header?)");
    }
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return true;
  }

  bool ReadFormat(bool& seen)
  {
    const auto& w = this->Words;
    if (w.size() != 3 || w[2] != "1.0")
    {
      return this->Fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
    }
    if (w[1] == "ascii")
    {
      this->Kind = Format::ASCII;
    }
    else if (w[1] == "binary_little_endian")
    {
      this->Kind = Format::BINARY_LE;
    }
    else if (w[1] == "binary_big_endian")
    {
      this->Kind = Format::BINARY_BE;
    }
    else
    {
      return this->Fail("unknown PLY format " + Quote(w[1]));
    }
    seen = true;
    return true;
  }

  // 'element NAME COUNT' or 'property TYPE NAME' / 'property list COUNT ITEM NAME'.
  bool ReadDeclaration()
  {
    const auto& w = this->Words;
    if (w[0] == "element")
    {
      Element e;
      if (w.size() != 3 || !medialreaders::ParseIndex(w[2], VTK_ID_MAX, e.Count))
      {
        return this->Fail("expected 'element NAME COUNT' with a non-negative count");
      }
      e.Name = w[1];
      this->Elements.push_back(e);
      return true;
    }
    if (w[0] != "property")
    {
      return this->Fail("unexpected header line starting with " + Quote(w[0]));
    }
    if (this->Elements.empty())
    {
      return this->Fail("a 'property' line comes before any 'element'");
    }
    Property p;
    const bool list = w.size() == 5 && w[1] == "list";
    if (!(list ? ScalarOf(w[2], p.CountType) && ScalarOf(w[3], p.Type) : w.size() == 3 && ScalarOf(w[1], p.Type)))
    {
      return this->Fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME' with PLY types");
    }
    if (list && !IsInteger(p.CountType))
    {
      return this->Fail("a list's count type must be an integer type");
    }
    p.List = list;
    p.Name = w.back();
    this->Elements.back().Properties.push_back(p);
    return true;
  }

  // The vertex element must give x, y, z and a radius as scalars; edges and faces
  // their indices. Records where each one is.
  bool CheckVertices()
  {
    bool found = false;
    for (const Element& e : this->Elements)
    {
      if (e.Name == "vertex")
      {
        found = true;
        this->Vertices = e.Count;
        const int radius = e.Find("radius") >= 0 ? e.Find("radius") : e.Find("r");
        const int at[4] = { e.Find("x"), e.Find("y"), e.Find("z"), radius };
        const char* names[4] = { "x", "y", "z", "radius" };
        for (int c = 0; c < 4; ++c)
        {
          if (at[c] < 0 || e.Properties[at[c]].List)
          {
            return this->Fail(std::string("the vertices have no scalar '") + names[c] +
              "' property (medial balls need x, y, z and radius)");
          }
          this->VertexColumns[c] = at[c];
        }
      }
    }
    return found || this->Fail("the file has no 'vertex' element");
  }

  void Reserve(const Element& e, medialballs::BallMesh& mesh) const
  {
    // At least one byte per property and record: a header cannot make us allocate more.
    const vtkIdType records =
      std::min<vtkIdType>(e.Count, this->FileSize / std::max<vtkIdType>(1, static_cast<vtkIdType>(e.Properties.size())));
    if (e.Name == "vertex")
    {
      mesh.Coordinates.reserve(3 * static_cast<size_t>(records));
      mesh.Radii.reserve(static_cast<size_t>(records));
    }
    else if (e.Name == "edge")
    {
      mesh.Edges.reserve(2 * static_cast<size_t>(records));
    }
  }

  // One record of `element` (number k); the parts the balls need are kept.
  bool ReadRecord(const Element& element, vtkIdType k, medialballs::BallMesh& mesh)
  {
    const bool vertex = element.Name == "vertex", edge = element.Name == "edge", face = element.Name == "face";
    double ball[4] = { 0, 0, 0, 0 };
    vtkIdType ends[2] = { -1, -1 };
    bool faceRead = false;
    for (size_t i = 0; i < element.Properties.size(); ++i)
    {
      const Property& p = element.Properties[i];
      const std::string where = element.Name + " " + std::to_string(k) + ", property '" + p.Name + "'";
      if (p.List)
      {
        const bool indices = face && !faceRead && (p.Name == "vertex_indices" || p.Name == "vertex_index");
        if (!this->ReadList(p, where, indices ? &mesh : nullptr))
        {
          return false;
        }
        faceRead = faceRead || indices;
        continue;
      }
      double value = 0.0;
      if (!this->ReadValue(p.Type, where, value))
      {
        return false;
      }
      for (int c = 0; vertex && c < 4; ++c)
      {
        if (static_cast<int>(i) == this->VertexColumns[c])
        {
          ball[c] = value;
        }
      }
      if (edge && (p.Name == "vertex1" || p.Name == "vertex2"))
      {
        if (!this->CheckIndex(value, where, ends[p.Name == "vertex1" ? 0 : 1]))
        {
          return false;
        }
      }
    }
    if (vertex)
    {
      if (!std::isfinite(ball[0]) || !std::isfinite(ball[1]) || !std::isfinite(ball[2]) || !std::isfinite(ball[3]))
      {
        return this->Fail("vertex " + std::to_string(k) + " has a NaN or infinite coordinate or radius");
      }
      if (ball[3] < 0.0)
      {
        return this->Fail("vertex " + std::to_string(k) + " has a negative radius");
      }
      mesh.Coordinates.insert(mesh.Coordinates.end(), ball, ball + 3);
      mesh.Radii.push_back(ball[3]);
    }
    if (edge)
    {
      if (ends[0] < 0 || ends[1] < 0)
      {
        return this->Fail("the edges need 'vertex1' and 'vertex2' properties");
      }
      mesh.Edges.insert(mesh.Edges.end(), ends, ends + 2);
    }
    return !face || faceRead || this->Fail("the faces need a 'vertex_indices' list property");
  }

  // A list: its count, then its items; as a face's point ids when `mesh` is given.
  bool ReadList(const Property& p, const std::string& where, medialballs::BallMesh* mesh)
  {
    double count = 0.0;
    if (!this->ReadValue(p.CountType, where, count))
    {
      return false;
    }
    if (count < 0.0 || count > static_cast<double>(this->FileSize))
    {
      return this->Fail(where + ": list length " + std::to_string(count) + " is impossible for this file");
    }
    const vtkIdType n = static_cast<vtkIdType>(count);
    if (mesh && n < 3)
    {
      return this->Fail(where + ": a face needs at least 3 points, found " + std::to_string(n));
    }
    for (vtkIdType j = 0; j < n; ++j)
    {
      double value = 0.0;
      vtkIdType id = 0;
      if (!this->ReadValue(p.Type, where, value) || (mesh && !this->CheckIndex(value, where, id)))
      {
        return false;
      }
      if (mesh)
      {
        mesh->Faces.push_back(id);
      }
    }
    if (mesh)
    {
      mesh->FaceSizes.push_back(n);
    }
    return true;
  }

  bool CheckIndex(double value, const std::string& where, vtkIdType& id)
  {
    if (!(value >= 0.0 && value < static_cast<double>(this->Vertices)) || value != std::floor(value))
    {
      std::ostringstream text;
      text << where << ": index " << value << " is not a vertex in [0, " << this->Vertices << ")";
      return this->Fail(text.str());
    }
    id = static_cast<vtkIdType>(value);
    return true;
  }

  bool ReadValue(Scalar type, const std::string& where, double& value)
  {
    const bool ok = this->Kind == Format::ASCII ? this->ReadText(type, value) : this->ReadBinary(type, value);
    if (!ok)
    {
      return this->Fail(where + ": " + (this->Stream.eof() ? "the file ends early (truncated?)" : "not a valid number"));
    }
    return true;
  }

  bool ReadText(Scalar type, double& value)
  {
    if (!(this->Stream >> this->Token))
    {
      return false;
    }
    if (!ParseNumber(this->Token, value))
    {
      this->Stream.clear(); // not at the end: a bad token
      return false;
    }
    return !IsInteger(type) || value == std::floor(value);
  }

  bool ReadBinary(Scalar type, double& value)
  {
    static const int sizes[] = { 1, 1, 2, 2, 4, 4, 4, 8 };
    const int size = sizes[static_cast<int>(type)];
    unsigned char bytes[8];
    if (!this->Stream.read(reinterpret_cast<char*>(bytes), size))
    {
      return false;
    }
    if (size > 1)
    {
      const bool little = this->Kind == Format::BINARY_LE;
      if (size == 2)
      {
        little ? vtkByteSwap::Swap2LE(bytes) : vtkByteSwap::Swap2BE(bytes);
      }
      else if (size == 4)
      {
        little ? vtkByteSwap::Swap4LE(bytes) : vtkByteSwap::Swap4BE(bytes);
      }
      else
      {
        little ? vtkByteSwap::Swap8LE(bytes) : vtkByteSwap::Swap8BE(bytes);
      }
    }
    value = Decode(type, bytes);
    return true;
  }

  static double Decode(Scalar type, const unsigned char* bytes)
  {
    auto as = [bytes](auto sample) {
      decltype(sample) v;
      std::memcpy(&v, bytes, sizeof(v));
      return static_cast<double>(v);
    };
    switch (type)
    {
      case Scalar::INT8:
        return as(std::int8_t());
      case Scalar::UINT8:
        return as(std::uint8_t());
      case Scalar::INT16:
        return as(std::int16_t());
      case Scalar::UINT16:
        return as(std::uint16_t());
      case Scalar::INT32:
        return as(std::int32_t());
      case Scalar::UINT32:
        return as(std::uint32_t());
      case Scalar::FLOAT32:
        return as(float());
      default:
        return as(double());
    }
  }

  std::ifstream Stream;
  std::vector<std::string> Words;
  std::string Token;
  std::vector<Element> Elements;
  Format Kind = Format::ASCII;
  vtkTypeInt64 FileSize = 0;
  vtkIdType Vertices = 0;
  int VertexColumns[4] = { -1, -1, -1, -1 };
  int HeaderLines = 0;
};
}

int vtkMedialBallPLYReader::CanReadFile(const char* fileName)
{
  PLYBallParser parser;
  return fileName && parser.ParseHeader(fileName) ? 1 : 0;
}

int vtkMedialBallPLYReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  PLYBallParser parser;
  medialballs::BallMesh mesh;
  if (!parser.Parse(this->FileName, mesh, [this](double fraction) { this->UpdateProgress(fraction); }))
  {
    vtkErrorMacro("Cannot read PLY balls '" << this->FileName << "': " << parser.Error);
    return 0;
  }
  medialballs::ToPolyData(mesh, output);
  return 1;
}

void vtkMedialBallPLYReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent); // FileName
}
