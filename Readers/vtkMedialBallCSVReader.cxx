// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallCSVReader.h"
#include "vtkMedialBallRecords.h"
#include "vtkMedialTextParsing.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

vtkStandardNewMacro(vtkMedialBallCSVReader);

namespace
{
// The fields of a line, without surrounding spaces and quotes.
void SplitFields(const std::string& line, char separator, std::vector<std::string_view>& fields)
{
  fields.clear();
  std::string_view rest(line);
  while (true)
  {
    const size_t at = rest.find(separator);
    std::string_view field = rest.substr(0, at);
    while (!field.empty() && (std::isspace(static_cast<unsigned char>(field.front())) || field.front() == '"'))
    {
      field.remove_prefix(1);
    }
    while (!field.empty() && (std::isspace(static_cast<unsigned char>(field.back())) || field.back() == '"'))
    {
      field.remove_suffix(1);
    }
    fields.push_back(field);
    if (at == std::string_view::npos)
    {
      return;
    }
    rest.remove_prefix(at + 1);
  }
}

std::string Lower(std::string_view text)
{
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

class CSVBallParser
{
public:
  std::string Error;
  vtkIdType Line = 0;

  bool Parse(const std::string& path, medialballs::BallMesh& mesh, const std::function<void(double)>& progress)
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
    std::ifstream stream(path, std::ios::in | std::ios::binary);
    std::string text;
    if (!stream || !this->NextLine(stream, text))
    {
      return this->Fail("the file is empty: expected a header line naming the columns x, y, z, radius");
    }
    if (!this->ReadHeader(text))
    {
      return false;
    }
    const double size = std::max<double>(1.0, static_cast<double>(info.st_size));
    while (this->NextLine(stream, text))
    {
      if (!this->ReadRow(text, mesh))
      {
        return false;
      }
      if (progress && this->Line % 4096 == 0)
      {
        progress(std::min(1.0, static_cast<double>(stream.tellg()) / size));
      }
    }
    return true;
  }

private:
  bool Fail(const std::string& message)
  {
    this->Error = message;
    return false;
  }

  // The next non-blank line, without its '\r'.
  bool NextLine(std::ifstream& stream, std::string& text)
  {
    while (std::getline(stream, text))
    {
      ++this->Line;
      if (!text.empty() && text.back() == '\r')
      {
        text.pop_back();
      }
      if (text.find_first_not_of(" \t") != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }

  bool ReadHeader(const std::string& text)
  {
    this->Separator = text.find(',') != std::string::npos ? ',' : (text.find(';') != std::string::npos ? ';' : '\t');
    SplitFields(text, this->Separator, this->Fields);
    const char* names[4] = { "x", "y", "z", "radius" };
    for (int c = 0; c < 4; ++c)
    {
      for (size_t f = 0; f < this->Fields.size(); ++f)
      {
        const std::string name = Lower(this->Fields[f]);
        if (name == names[c] || (c == 3 && name == "r"))
        {
          this->Columns[c] = f;
        }
      }
      if (this->Columns[c] == std::string::npos)
      {
        return this->Fail(std::string("the header has no '") + names[c] +
          "' column (medial balls need the columns x, y, z and radius)");
      }
    }
    this->Needed = 1 + *std::max_element(this->Columns, this->Columns + 4);
    return true;
  }

  bool ReadRow(const std::string& text, medialballs::BallMesh& mesh)
  {
    SplitFields(text, this->Separator, this->Fields);
    if (this->Fields.size() < this->Needed)
    {
      return this->Fail("the row has " + std::to_string(this->Fields.size()) + " field(s), the header needs " +
        std::to_string(this->Needed));
    }
    double ball[4];
    for (int c = 0; c < 4; ++c)
    {
      const std::string_view field = this->Fields[this->Columns[c]];
      if (!medialreaders::ParseFinite(field, ball[c]))
      {
        return this->Fail(std::string("field ") + medialreaders::Quote(field) + " " + medialreaders::WhyNotFinite(field));
      }
    }
    if (ball[3] < 0.0)
    {
      return this->Fail("negative radius " + medialreaders::Quote(this->Fields[this->Columns[3]]));
    }
    mesh.Coordinates.insert(mesh.Coordinates.end(), ball, ball + 3);
    mesh.Radii.push_back(ball[3]);
    return true;
  }

  char Separator = ',';
  std::vector<std::string_view> Fields;
  size_t Columns[4] = { std::string::npos, std::string::npos, std::string::npos, std::string::npos };
  size_t Needed = 4;
};
}

int vtkMedialBallCSVReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    return 0;
  }
  CSVBallParser parser;
  medialballs::BallMesh mesh;
  if (!parser.Parse(this->FileName, mesh, [this](double fraction) { this->UpdateProgress(fraction); }))
  {
    vtkErrorMacro("Cannot read CSV balls '" << this->FileName << "'"
                                            << (parser.Line > 0 ? ", line " + std::to_string(parser.Line) : "")
                                            << ": " << parser.Error);
    return 0;
  }
  medialballs::ToPolyData(mesh, output);
  return 1;
}

void vtkMedialBallCSVReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent); // FileName
}
