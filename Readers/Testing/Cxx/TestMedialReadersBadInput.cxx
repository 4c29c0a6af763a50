// SPDX-License-Identifier: BSD-3-Clause
// Every malformed .ma or OFF file gives one error that names the line, and an
// empty output; nothing crashes or allocates what the header merely claims.
// The writer refuses input it cannot write faithfully and leaves no file.
#include "ReaderTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMedialMeshReader.h"
#include "vtkMedialMeshWriter.h"
#include "vtkMedialOFFReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <sys/stat.h>

#include <optional>
#include <string>
#include <vector>

using namespace readertest;

namespace
{
enum Format
{
  MA,
  OFF
};

struct Case
{
  const char* Name;
  Format Kind;
  std::optional<std::string> Content; // none: the file does not exist
  int Line;            // expected line number in the message; 0: none
  const char* Expected; // substring of the message
};

const char* const TwoVertices = "v 0 0 0 1\nv 1 0 0 0.5\n";

// clang-format off
const std::vector<Case>& Cases()
{
  static const std::vector<Case> cases = {
    { "ma missing file", MA, std::nullopt, 0, "cannot open" },
    { "ma empty file", MA, "", 1, "file is empty" },
    { "ma blank lines only", MA, "\n  \n# comment\n", 4, "file is empty" },
    { "ma header of two counts", MA, "2 1\nv 0 0 0 1\n", 1, "expected the header" },
    { "ma non-numeric header", MA, "two 0 0\n", 1, "is not a non-negative integer" },
    { "ma negative count", MA, "-2 0 0\n", 1, "is not a non-negative integer" },
    { "ma count beyond 64 bits", MA, "99999999999999999999 0 0\n", 1, "is not a non-negative integer" },
    { "ma truncated vertices", MA, "3 0 0\nv 0 0 0 1\nv 1 0 0 1\n", 4, "ends before 'v' record 3 of 3" },
    { "ma truncated faces", MA, "2 1 1\nv 0 0 0 1\nv 1 0 0 1\ne 0 1\n", 5, "ends before 'f' record 1 of 1" },
    { "ma fewer vertices than counted", MA, "3 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1\n", 4, "expected 'v' record 3 of 3, found 'e'" },
    { "ma more vertices than counted", MA, "1 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1\n", 3, "expected 'e' record 1 of 1, found 'v'" },
    { "ma record after the last", MA, "2 0 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1\n", 4, "unexpected record 'e'" },
    { "ma edge index out of range", MA, "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 2\n", 4, "index '2' is not an integer in [0, 2)" },
    { "ma negative face index", MA, "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 -1 2\n", 5, "index '-1'" },
    { "ma fractional index", MA, "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0 1.5\n", 4, "index '1.5'" },
    { "ma face of four indices", MA, "3 0 1\nv 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 0 1 2 0\n", 5, "needs 3 vertex indices, found 4" },
    { "ma edge of one index", MA, "2 1 0\nv 0 0 0 1\nv 1 0 0 1\ne 0\n", 4, "needs 2 vertex indices, found 1" },
    { "ma vertex without radius", MA, "1 0 0\nv 0 0 0\n", 2, "needs 'v x y z r'" },
    { "ma non-numeric coordinate", MA, "1 0 0\nv 0 abc 0 1\n", 2, "'abc' is not a number" },
    { "ma number with junk", MA, "1 0 0\nv 0 1.0x 0 1\n", 2, "'1.0x' is not a number" },
    { "ma NaN coordinate", MA, "1 0 0\nv nan 0 0 1\n", 2, "NaN or infinite" },
    { "ma infinite radius", MA, "1 0 0\nv 0 0 0 inf\n", 2, "NaN or infinite" },
    { "ma overflowing coordinate", MA, "1 0 0\nv 1e999 0 0 1\n", 2, "out of the range of double" },
    { "ma negative radius", MA, "2 0 0\nv 0 0 0 1\nv 1 0 0 -0.5\n", 3, "negative radius" },
    { "ma huge vertex count", MA, "1000000000000 0 0\nv 0 0 0 1\n", 3, "ends before 'v' record 2 of 1000000000000" },
    { "ma huge face count", MA, "2 0 1000000000000\nv 0 0 0 1\nv 1 0 0 1\n", 4, "ends before 'f' record 1 of 1000000000000" },
    { "ma binary junk", MA, std::string("\x7f" "ELF\x01\x02\0\0 1 2", 12), 1, "is not a non-negative integer" },

    { "off missing file", OFF, std::nullopt, 0, "cannot open" },
    { "off empty file", OFF, "", 1, "file is empty" },
    { "off comments only", OFF, "# nothing\n\n", 3, "file is empty" },
    { "off not an OFF file", OFF, "ply\nformat ascii 1.0\n", 1, "not an OFF file" },
    { "off variant 4OFF", OFF, "4OFF\n1 0 0\n0 0 0 1\n", 1, "unsupported OFF variant '4OFF'" },
    { "off variant nOFF", OFF, "nOFF\n2\n1 0 0\n0 0\n", 1, "unsupported OFF variant 'nOFF'" },
    { "off variant STOFF", OFF, "STOFF\n1 0 0\n0 0 0 0 0\n", 1, "unsupported OFF variant 'STOFF'" },
    { "off binary", OFF, "OFF BINARY\n", 1, "unsupported OFF variant 'OFF BINARY'" },
    { "off no counts", OFF, "OFF\n# counts missing\n", 3, "ends before the counts" },
    { "off counts are words", OFF, "OFF\nthree one zero\n", 2, "expected the counts" },
    { "off one count", OFF, "OFF 3\n", 1, "found 1 value(s)" },
    { "off truncated vertices", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n", 5, "ends before vertex 3 of 3" },
    { "off truncated faces", OFF, "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 7, "ends before face 2 of 2" },
    { "off more faces than counted", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n", 7, "unexpected data '3'" },
    { "off face index out of range", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6, "index '3' is not an integer in [0, 3)" },
    { "off face longer than its line", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", 6, "face of 4 vertices has only 3" },
    { "off face of two vertices", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 6, "at least 3" },
    { "off huge face size", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000000 0 1 2\n", 6, "has only 3" },
    { "off bad face colour", OFF, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", 6, "'red' is not a number" },
    { "off short vertex", OFF, "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4, "needs 3 values, found 2" },
    { "off NOFF without normals", OFF, "NOFF\n1 0 0\n0 0 0\n", 3, "needs 6 values" },
    { "off COFF without colour", OFF, "COFF\n1 0 0\n0 0 0\n", 3, "needs 6 values" },
    { "off non-numeric coordinate", OFF, "OFF\n1 0 0\n0 zero 0\n", 3, "'zero' is not a number" },
    { "off NaN coordinate", OFF, "OFF\n1 0 0\n0 0 NaN\n", 3, "NaN or infinite" },
    { "off infinite coordinate", OFF, "OFF\n1 0 0\n-inf 0 0\n", 3, "NaN or infinite" },
    { "off huge counts", OFF, "OFF\n1000000000000 1000000000000 0\n0 0 0\n", 4, "ends before vertex 2 of 1000000000000" },
  };
  return cases;
}
// clang-format on

vtkSmartPointer<vtkPolyDataAlgorithm> MakeReader(Format kind, const std::string& path)
{
  if (kind == MA)
  {
    auto reader = vtkSmartPointer<vtkMedialMeshReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  auto reader = vtkSmartPointer<vtkMedialOFFReader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

// The reader's own words, without VTK's "ERROR: In file, line" prefix.
std::string Shown(const std::string& message)
{
  const size_t at = message.find("Cannot");
  return at == std::string::npos ? std::string("(no message)") : message.substr(at);
}

bool Exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

int CheckReaders(const TempDir& dir)
{
  int index = 0;
  for (const Case& c : Cases())
  {
    const std::string name = "case" + std::to_string(index++) + (c.Kind == MA ? ".ma" : ".off");
    const std::string path = c.Content ? dir.Write(name, *c.Content) : dir.File(name);
    auto reader = MakeReader(c.Kind, path);
    EventLog log;
    log.Watch(reader);
    const int ok = reader->GetExecutive()->Update();
    const std::string message = log.LineWith("Cannot read");
    std::printf("%-32s %s\n", c.Name, Shown(message).c_str());
    MEDIAL_CHECK(!ok && log.Errors >= 1, "%s: no error reported", c.Name);
    const std::string where =
      c.Line > 0 ? "', line " + std::to_string(c.Line) + ": " : std::string("': ");
    MEDIAL_CHECK(message.find(where) != std::string::npos, "%s: message lacks \"%s\"", c.Name,
      where.c_str());
    MEDIAL_CHECK(message.find(c.Expected) != std::string::npos, "%s: message lacks \"%s\"",
      c.Name, c.Expected);
    vtkPolyData* out = reader->GetOutput();
    MEDIAL_CHECK(out->GetNumberOfPoints() == 0 && out->GetNumberOfCells() == 0,
      "%s: output not empty", c.Name);
  }
  return EXIT_SUCCESS;
}

// A directory is not read as an empty file.
int CheckDirectory(const TempDir& dir)
{
  for (Format kind : { MA, OFF })
  {
    auto reader = MakeReader(kind, dir.Path);
    EventLog log;
    log.Watch(reader);
    reader->Update();
    const std::string message = log.LineWith("Cannot read");
    std::printf("%-32s %s\n", "directory", Shown(message).c_str());
    MEDIAL_CHECK(log.Errors >= 1 && message.find("is a directory") != std::string::npos,
      "directory: %s", message.c_str());
    MEDIAL_CHECK(reader->GetOutput()->GetNumberOfPoints() == 0, "directory: output not empty");
  }
  return EXIT_SUCCESS;
}

// A failed read after a good one must not leave the good data in the output.
int CheckOutputClearedAfterFailure(const TempDir& dir)
{
  const std::string good = dir.Write("good.ma", std::string("2 1 0\n") + TwoVertices + "e 0 1\n");
  const std::string bad = dir.Write("bad.ma", "2 1 0\nv 0 0 0 1\n");
  vtkNew<vtkMedialMeshReader> reader;
  EventLog log;
  log.Watch(reader);
  reader->SetFileName(good.c_str());
  reader->Update();
  MEDIAL_CHECK(log.Errors == 0 && reader->GetOutput()->GetNumberOfPoints() == 2, "good file");
  reader->SetFileName(bad.c_str());
  reader->Update();
  MEDIAL_CHECK(log.Errors >= 1, "bad file after good: no error");
  MEDIAL_CHECK(reader->GetOutput()->GetNumberOfPoints() == 0 &&
      reader->GetOutput()->GetNumberOfCells() == 0 &&
      !reader->GetOutput()->GetPointData()->GetArray("Radius"),
    "bad file after good: output not empty");
  return EXIT_SUCCESS;
}

int CheckWriterRefuses(const TempDir& dir)
{
  auto polydata = [](double radius, bool withRadius) {
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    pd->SetPoints(points);
    vtkNew<vtkCellArray> lines;
    const vtkIdType segment[2] = { 0, 1 };
    lines->InsertNextCell(2, segment);
    pd->SetLines(lines);
    if (withRadius)
    {
      vtkNew<vtkDoubleArray> r;
      r->SetName("Radius");
      r->InsertNextValue(1.0);
      r->InsertNextValue(radius);
      pd->GetPointData()->AddArray(r);
    }
    return pd;
  };
  struct WriterCase
  {
    const char* Name;
    vtkSmartPointer<vtkPolyData> Input;
    const char* Expected;
  };
  auto badIndex = polydata(1.0, true);
  const vtkIdType outside[2] = { 1, 2 };
  badIndex->GetLines()->InsertNextCell(2, outside);
  auto twoComponents = polydata(1.0, false);
  vtkNew<vtkDoubleArray> vectorRadius;
  vectorRadius->SetName("Radius");
  vectorRadius->SetNumberOfComponents(2);
  vectorRadius->SetNumberOfTuples(2);
  vectorRadius->Fill(1.0);
  twoComponents->GetPointData()->AddArray(vectorRadius);
  const std::vector<WriterCase> cases = {
    { "writer without Radius", polydata(1.0, false), "no point-data array 'Radius'" },
    { "writer negative radius", polydata(-1.0, true), "negative radius" },
    { "writer NaN radius", polydata(std::nan(""), true), "NaN or infinite" },
    { "writer point id out of range", badIndex, "outside [0, 2)" },
    { "writer two-component Radius", twoComponents, "2 components" },
  };
  int index = 0;
  for (const WriterCase& c : cases)
  {
    const std::string path = dir.File("written" + std::to_string(index++) + ".ma");
    vtkNew<vtkMedialMeshWriter> writer;
    EventLog log;
    log.Watch(writer);
    writer->SetInputData(c.Input);
    writer->SetFileName(path.c_str());
    const int ok = writer->Write();
    const std::string message = log.LineWith("Cannot write");
    std::printf("%-32s %s\n", c.Name, Shown(message).c_str());
    MEDIAL_CHECK(!ok && log.Errors >= 1, "%s: no error reported", c.Name);
    MEDIAL_CHECK(message.find(c.Expected) != std::string::npos, "%s: message lacks \"%s\"",
      c.Name, c.Expected);
    MEDIAL_CHECK(!Exists(path), "%s: a file was written", c.Name);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialReadersBadInput(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "cannot create a temporary folder");
  for (auto check : { CheckReaders, CheckDirectory, CheckOutputClearedAfterFailure, CheckWriterRefuses })
  {
    if (check(dir) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
