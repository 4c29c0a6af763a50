// SPDX-License-Identifier: BSD-3-Clause
// Internal to MedialAxis::Readers (not wrapped, not installed): a line reader that
// tokenizes text files and knows its line number, and checked number parsing.
// Numbers are parsed with std::from_chars: no exceptions, no locale dependence
// (strtod would read "1,5" under a German LC_NUMERIC), and the whole token must
// be consumed.
#ifndef vtkMedialTextParsing_h
#define vtkMedialTextParsing_h

#include "vtkObject.h"
#include "vtkSetGet.h"
#include "vtkType.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace medialreaders
{
/// Reads a text file line by line; strips '#' comments and splits on white space.
class TextLines
{
public:
  /// Opens the file and records its size in bytes. On failure returns false and
  /// sets `why`.
  bool Open(const std::string& path, std::string& why)
  {
    struct stat info;
    if (stat(path.c_str(), &info) != 0)
    {
      why = std::string("cannot open the file: ") + std::strerror(errno);
      return false;
    }
    if (S_ISDIR(info.st_mode))
    {
      why = "it is a directory, not a file";
      return false;
    }
    this->Stream.open(path, std::ios::in | std::ios::binary);
    if (!this->Stream)
    {
      why = "cannot open the file";
      return false;
    }
    // Regular files only: a pipe has no meaningful size, and then nothing is reserved.
    this->FileSize = S_ISREG(info.st_mode) ? static_cast<vtkTypeInt64>(info.st_size) : 0;
    return true;
  }

  /// Advances to the next line that has tokens (blank and comment-only lines are
  /// skipped). False at the end of the file.
  bool NextRecord()
  {
    while (!this->AtEnd && std::getline(this->Stream, this->Line))
    {
      ++this->LinesRead;
      if (this->Progress && this->FileSize > 0 && this->LinesRead % 16384 == 0)
      {
        this->Progress(std::min(1.0, static_cast<double>(this->Stream.tellg()) / static_cast<double>(this->FileSize)));
      }
      this->LineNumber = this->LinesRead;
      if (this->LinesRead == 1 && this->Line.compare(0, 3, "\xEF\xBB\xBF") == 0)
      {
        this->Line.erase(0, 3); // UTF-8 byte order mark, written by some Windows tools
      }
      this->Split();
      if (!this->Tokens.empty())
      {
        return true;
      }
    }
    // Past the last line: errors about a missing record name the line after it.
    this->AtEnd = true;
    this->Tokens.clear();
    this->LineNumber = this->LinesRead + 1;
    return false;
  }

  const std::vector<std::string_view>& GetTokens() const { return this->Tokens; }
  vtkIdType GetLineNumber() const { return this->LineNumber; }

  /// Called with the fraction of the file read, every 16384 lines.
  std::function<void(double)> Progress;

  /// An upper bound on how many records of at least `minimumBytes` bytes (newline
  /// included) the file can hold, and at most `count`. Used to cap reserve(), so
  /// that a header claiming 10^12 records allocates nothing it cannot fill.
  vtkIdType CapReserve(vtkIdType count, vtkIdType minimumBytes) const
  {
    return std::max<vtkIdType>(0, std::min<vtkIdType>(count, this->FileSize / minimumBytes));
  }

private:
  void Split()
  {
    this->Tokens.clear();
    std::string_view text(this->Line);
    const size_t hash = text.find('#');
    if (hash != std::string_view::npos)
    {
      text = text.substr(0, hash);
    }
    // Any ASCII white space separates tokens; '\r' covers CRLF files, '\0' binary junk.
    auto isSpace = [](char c) {
      return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' || c == '\0';
    };
    size_t i = 0;
    while (i < text.size())
    {
      while (i < text.size() && isSpace(text[i]))
      {
        ++i;
      }
      const size_t start = i;
      while (i < text.size() && !isSpace(text[i]))
      {
        ++i;
      }
      if (i > start)
      {
        this->Tokens.push_back(text.substr(start, i - start));
      }
    }
  }

  std::ifstream Stream;
  std::string Line;
  std::vector<std::string_view> Tokens;
  vtkIdType LinesRead = 0;
  vtkIdType LineNumber = 0;
  bool AtEnd = false;
  vtkTypeInt64 FileSize = 0;
};

/// Parses a whole token as a finite double. A leading '+' is accepted.
inline bool ParseFinite(std::string_view token, double& value)
{
  if (!token.empty() && token[0] == '+')
  {
    token.remove_prefix(1);
    if (!token.empty() && token[0] == '-')
    {
      return false; // "+-1"
    }
  }
  if (token.empty())
  {
    return false;
  }
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

/// Why ParseFinite rejected a token, for the error message.
inline std::string WhyNotFinite(std::string_view token)
{
  if (!token.empty() && token[0] == '+')
  {
    token.remove_prefix(1);
  }
  double value = 0.0;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ptr == end && result.ec == std::errc::result_out_of_range)
  {
    return "is out of the range of double";
  }
  if (result.ptr == end && result.ec == std::errc() && !std::isfinite(value))
  {
    return "is NaN or infinite";
  }
  return "is not a number";
}

/// Parses a whole token as an integer in [0, limit).
inline bool ParseIndex(std::string_view token, vtkIdType limit, vtkIdType& value)
{
  if (!token.empty() && token[0] == '+')
  {
    token.remove_prefix(1);
  }
  long long parsed = 0;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, parsed);
  if (token.empty() || result.ec != std::errc() || result.ptr != end || parsed < 0 ||
    parsed >= static_cast<long long>(limit))
  {
    return false;
  }
  value = static_cast<vtkIdType>(parsed);
  return true;
}

/// Base of the readers' parsers: the line reader, and the first error with its line.
class RecordParser
{
public:
  std::string Error;
  vtkIdType ErrorLine = 0; // 0: the error is not about a line

  /// Reports the fraction of the file read as the lines go by.
  void SetProgress(const std::function<void(double)>& progress) { this->Lines.Progress = progress; }

  /// "Cannot read WHAT 'FILE', line N: ERROR" (without ", line N" when ErrorLine is 0).
  std::string Describe(const char* what, const char* fileName) const
  {
    std::string text = std::string("Cannot read ") + what + " '" + fileName + "'";
    if (this->ErrorLine > 0)
    {
      text += ", line " + std::to_string(this->ErrorLine);
    }
    return text + ": " + this->Error;
  }

protected:
  /// Opens the file; false with the reason as the error.
  bool Open(const std::string& path)
  {
    std::string why;
    return this->Lines.Open(path, why) || this->Fail(0, why);
  }
  /// Records an error at the current line; always false.
  bool Fail(const std::string& message) { return this->Fail(this->Lines.GetLineNumber(), message); }
  bool Fail(vtkIdType line, const std::string& message)
  {
    this->ErrorLine = line;
    this->Error = message;
    return false;
  }

  TextLines Lines;
};

/// The parse step of a reader's RequestData: reads `fileName` with a new Parser into
/// `mesh`, reporting progress on `reader`. False, with the error reported on
/// `reader` ("No FileName set.", or the parser's "Cannot read WHAT 'FILE', line N:
/// ..."), when it cannot.
template <class Parser, class Mesh, class Reader>
bool ParseFile(Reader* reader, const char* fileName, const char* what, Mesh& mesh)
{
  if (!fileName || !*fileName)
  {
    vtkErrorWithObjectMacro(reader, "No FileName set.");
    return false;
  }
  Parser parser;
  parser.SetProgress([reader](double fraction) { reader->UpdateProgress(fraction); });
  if (!parser.Parse(fileName, mesh))
  {
    vtkErrorWithObjectMacro(reader, << parser.Describe(what, fileName));
    return false;
  }
  return true;
}

/// A reader's CanReadFile: 1 when the file opens and its header parses with a new Parser.
template <class Parser>
int CanReadHeader(const char* fileName)
{
  Parser parser;
  return fileName && parser.ParseHeader(fileName) ? 1 : 0;
}

/// Quotes a token for an error message, shortened so binary junk stays readable.
inline std::string Quote(std::string_view token)
{
  std::string text(token.substr(0, 40));
  for (char& c : text)
  {
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126)
    {
      c = '?';
    }
  }
  return "'" + text + (token.size() > 40 ? "...'" : "'");
}
}

#endif
