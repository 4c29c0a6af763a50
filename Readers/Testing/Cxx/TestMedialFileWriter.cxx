// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialFileWriter and the ball formats: balls written in every ball format
// (.vtp .vtk .ply .ma .csv) through the writer table and read back through
// vtkMedialFileReader give the same centres and radii bit for bit (and the same
// edges and faces where the format holds them); ASCII PLY too; hand-written PLY
// balls in the other tools' layouts (float ASCII with extra properties and an
// `r` column, big-endian binary with mixed types) and a semicolon CSV; bad ball
// files and an unknown extension fail with one error and write nothing; every
// surface format round-trips a surface.
#include "ReaderTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialBallPLYReader.h"
#include "vtkMedialBallPLYWriter.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialFileWriter.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using namespace readertest;

namespace
{
// 5 balls with awkward coordinates, a SurfacePoint array, a polyline of 3 points
// (2 edges), an edge and a triangle.
vtkSmartPointer<vtkPolyData> MakeBalls()
{
  auto balls = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName(vtkMedialArrayNames::Radius);
  vtkNew<vtkDoubleArray> surface;
  surface->SetName(vtkMedialArrayNames::SurfacePoint);
  surface->SetNumberOfComponents(3);
  for (int i = 0; i < 5; ++i)
  {
    const double x[3] = { 0.1 * i + 1.0 / 3.0, -2.5e-7 * i, 1e6 + i / 7.0 };
    points->InsertNextPoint(x);
    radius->InsertNextValue(i == 0 ? 0.0 : 0.3 / (i + 1));
    surface->InsertNextTuple3(x[0], x[1] + 1.0, x[2]);
  }
  vtkNew<vtkCellArray> lines;
  const vtkIdType polyline[3] = { 0, 1, 2 }, edge[2] = { 3, 4 }, triangle[3] = { 1, 3, 4 };
  lines->InsertNextCell(3, polyline);
  lines->InsertNextCell(2, edge);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(3, triangle);
  balls->SetPoints(points);
  balls->SetLines(lines);
  balls->SetPolys(polys);
  balls->GetPointData()->AddArray(radius);
  balls->GetPointData()->AddArray(surface);
  return balls;
}

bool Write(vtkPolyData* data, const std::string& path, int content, EventLog& log)
{
  vtkNew<vtkMedialFileWriter> writer;
  log.Watch(writer);
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->SetContent(content);
  return writer->Write() == 1 && writer->GetErrorCode() == 0;
}

// Same centres and radii, bit for bit.
bool SameBalls(vtkPolyData* a, vtkPolyData* b)
{
  vtkDataArray* ra = a->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  vtkDataArray* rb = b->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  if (!ra || !rb || a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (std::memcmp(p, q, sizeof(p)) != 0 || ra->GetTuple1(i) != rb->GetTuple1(i))
    {
      return false;
    }
  }
  return true;
}

// Edges as the writers expand them: the polyline's segments, then the edge.
Cells ExpectedEdges()
{
  return { { 0, 1 }, { 1, 2 }, { 3, 4 } };
}

std::string BigEndian(double value)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, 8);
  std::string out;
  for (int k = 7; k >= 0; --k)
  {
    out += static_cast<char>((bits >> (8 * k)) & 0xff);
  }
  return out;
}

std::string BigEndian(float value)
{
  std::uint32_t bits;
  std::memcpy(&bits, &value, 4);
  std::string out;
  for (int k = 3; k >= 0; --k)
  {
    out += static_cast<char>((bits >> (8 * k)) & 0xff);
  }
  return out;
}

std::string BigEndian16(std::uint16_t value)
{
  return std::string(1, static_cast<char>(value >> 8)) + static_cast<char>(value & 0xff);
}

int RoundTrips(const TempDir& dir)
{
  vtkSmartPointer<vtkPolyData> balls = MakeBalls();
  for (const char* name : { "balls.vtp", "balls.vtk", "balls.ply", "balls.MA", "balls.csv" })
  {
    EventLog log;
    const std::string path = dir.File(name);
    MEDIAL_CHECK(Write(balls, path, vtkMedialFileWriter::BALLS, log), "%s: %s", name, log.Text.c_str());
    Read r;
    ReadFile(path, vtkMedialFileReader::BALLS, r);
    MEDIAL_CHECK(r.Ok && r.Log.Errors == 0, "%s read back: %s", name, r.Log.Text.c_str());
    MEDIAL_CHECK(SameBalls(balls, r.Output), "%s: the balls changed", name);
    const std::string ext = vtkMedialFileReader::GetExtension(name);
    if (ext == ".ply" || ext == ".ma")
    {
      // .ma is Q-MAT's clean form: every side of every face is an edge record too.
      const Cells edges = ext == ".ma" ? Cells({ { 0, 1 }, { 1, 2 }, { 3, 4 }, { 1, 3 }, { 4, 1 } }) : ExpectedEdges();
      MEDIAL_CHECK(CellsOf(r.Output->GetLines()) == edges, "%s: edges", name);
      MEDIAL_CHECK(CellsOf(r.Output->GetPolys()) == Cells({ { 1, 3, 4 } }), "%s: faces", name);
    }
    else if (ext != ".csv")
    {
      MEDIAL_CHECK(CellsOf(r.Output->GetLines()) == CellsOf(balls->GetLines()), "%s: lines", name);
      MEDIAL_CHECK(r.Output->GetPointData()->GetArray(vtkMedialArrayNames::SurfacePoint), "%s: SurfacePoint", name);
    }
  }
  // The CSV table's columns: x, y, z, radius, then every other point array.
  std::ifstream csv(dir.File("balls.csv"));
  std::string header;
  std::getline(csv, header);
  MEDIAL_CHECK(header == "x,y,z,radius,SurfacePoint_x,SurfacePoint_y,SurfacePoint_z", "CSV header '%s'",
    header.c_str());
  // ASCII PLY round-trips exactly too.
  vtkNew<vtkMedialBallPLYWriter> ascii;
  ascii->SetInputData(balls);
  ascii->SetFileName(dir.File("ascii.ply").c_str());
  ascii->SetFileTypeToASCII();
  MEDIAL_CHECK(ascii->Write() == 1, "ASCII PLY write");
  Read r;
  ReadFile(dir.File("ascii.ply"), vtkMedialFileReader::BALLS, r);
  MEDIAL_CHECK(r.Ok && SameBalls(balls, r.Output) && CellsOf(r.Output->GetLines()) == ExpectedEdges(),
    "ASCII PLY read back: %s", r.Log.Text.c_str());
  return EXIT_SUCCESS;
}

// PLY balls as other tools write them.
int ForeignFiles(const TempDir& dir)
{
  // ASCII, float coordinates, the radius named `r`, extra properties and elements
  // before and after, CRLF line ends, a quad face with a uint count.
  const std::string ascii = "ply\r\nformat ascii 1.0\r\ncomment from another tool\r\nelement camera 1\r\n"
                            "property float view\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
                            "property float z\r\nproperty uchar red\r\nproperty float r\r\n"
                            "property list uchar int neighbours\r\nelement face 1\r\n"
                            "property list uint int vertex_indices\r\nend_header\r\n"
                            "7.5\r\n0 0 0 255 0.5 2 1 2\r\n1 0 0 0 0.25 0\r\n0 2 0 9 1.5 1 0\r\n4 0 1 2 0\r\n";
  Read a;
  ReadFile(dir.Write("foreign.ply", ascii), vtkMedialFileReader::BALLS, a);
  vtkDataArray* radius = a.Output->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  MEDIAL_CHECK(a.Ok && radius && a.Output->GetNumberOfPoints() == 3 && radius->GetTuple1(2) == 1.5 &&
      a.Output->GetPoint(2)[1] == 2.0 && CellsOf(a.Output->GetPolys()) == Cells({ { 0, 1, 2, 0 } }),
    "foreign ASCII PLY: %s", a.Log.Text.c_str());
  MEDIAL_CHECK(vtkMedialBallPLYReader::CanReadFile(dir.File("foreign.ply").c_str()) == 1, "CanReadFile");

  // Big-endian binary: float x y z, double radius, a ushort flag; edges as ushort pairs.
  std::string be = "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                   "property float z\nproperty double radius\nproperty ushort flag\nelement edge 1\n"
                   "property ushort vertex1\nproperty ushort vertex2\nend_header\n";
  be += BigEndian(1.5f) + BigEndian(-2.0f) + BigEndian(0.25f) + BigEndian(0.1) + BigEndian16(7);
  be += BigEndian(3.0f) + BigEndian(4.0f) + BigEndian(5.0f) + BigEndian(2.0) + BigEndian16(8);
  be += BigEndian16(1) + BigEndian16(0);
  Read b;
  ReadFile(dir.Write("big.ply", be), vtkMedialFileReader::BALLS, b);
  radius = b.Output->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  MEDIAL_CHECK(b.Ok && radius && radius->GetTuple1(0) == 0.1 && b.Output->GetPoint(0)[1] == -2.0 &&
      b.Output->GetPoint(1)[2] == 5.0 && CellsOf(b.Output->GetLines()) == Cells({ { 1, 0 } }),
    "big-endian PLY: %s", b.Log.Text.c_str());

  // A spreadsheet's CSV: semicolons, other columns, another order, quotes.
  Read c;
  ReadFile(dir.Write("sheet.csv", "\"id\";\"Radius\";\"X\";\"Y\";\"Z\"\n1;0.5;1;2;3\n\n2;0.25;-1;-2;-3\n"),
    vtkMedialFileReader::BALLS, c);
  radius = c.Output->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  MEDIAL_CHECK(c.Ok && radius && c.Output->GetNumberOfPoints() == 2 && radius->GetTuple1(1) == 0.25 &&
      c.Output->GetPoint(1)[2] == -3.0,
    "spreadsheet CSV: %s", c.Log.Text.c_str());
  return EXIT_SUCCESS;
}

int BadFiles(const TempDir& dir)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                             "property double z\n";
  const struct
  {
    const char* Name;
    std::string Content;
    const char* Expected;
  } cases[] = {
    { "no-radius.ply", header + "end_header\n0 0 0\n1 1 1\n", "no scalar 'radius' property" },
    { "truncated.ply", header + "property double radius\nend_header\n0 0 0 1\n1 1\n", "vertex 1, property 'z': the file ends early" },
    { "negative.ply", header + "property double radius\nend_header\n0 0 0 1\n1 1 1 -2\n", "vertex 1 has a negative radius" },
    { "nan.ply", header + "property double radius\nend_header\n0 0 0 nan\n1 1 1 1\n", "vertex 0 has a NaN" },
    { "index.ply",
      header + "property double radius\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
               "0 0 0 1\n1 1 1 1\n3 0 1 2\n",
      "index 2 is not a vertex in [0, 2)" },
    { "text.ply", "solid x\n", "not a PLY file" },
    { "binary-truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty double x\n"
                              "property double y\nproperty double z\nproperty double radius\nend_header\n1234",
      "the file ends early" },
    { "no-column.csv", "x,y,z\n1,2,3\n", "no 'radius' column" },
    { "short-row.csv", "x,y,z,radius\n1,2,3,4\n1,2\n", "line 3: the row has 2 field(s)" },
    { "bad-number.csv", "x,y,z,radius\n1,2,3,abc\n", "field 'abc' is not a number" },
  };
  for (const auto& c : cases)
  {
    Read r;
    ReadFile(dir.Write(c.Name, c.Content), vtkMedialFileReader::BALLS, r);
    std::printf("%-22s %s\n", c.Name, r.Log.LineWith(c.Expected).c_str());
    MEDIAL_CHECK(!r.Ok && r.Log.LineWith(c.Expected) != "" && r.Output->GetNumberOfPoints() == 0,
      "%s: expected '%s', got: %s", c.Name, c.Expected, r.Log.LineWith("Cannot").c_str());
  }
  // Balls without a radius, a negative radius, an unknown extension: an error and no file.
  vtkNew<vtkPolyData> noRadius;
  noRadius->DeepCopy(MakeBalls());
  noRadius->GetPointData()->RemoveArray(vtkMedialArrayNames::Radius);
  vtkSmartPointer<vtkPolyData> good = MakeBalls();
  const struct
  {
    const char* Name;
    vtkPolyData* Data;
  } writes[] = { { "none.ma", noRadius }, { "none.ply", noRadius }, { "none.csv", noRadius },
    { "balls.txt", good }, { "balls", good } };
  for (const auto& w : writes)
  {
    EventLog log;
    const bool ok = Write(w.Data, dir.File(w.Name), vtkMedialFileWriter::BALLS, log);
    MEDIAL_CHECK(!ok && log.Errors >= 1 && !std::filesystem::exists(dir.File(w.Name)), "%s: written", w.Name);
  }
  EventLog unknown;
  Write(good, dir.File("balls.txt"), vtkMedialFileWriter::BALLS, unknown);
  MEDIAL_CHECK(unknown.LineWith("unsupported extension '.txt' for balls (.vtp .vtk .ply .ma .csv)") != "",
    "unknown extension: %s", unknown.Text.c_str());
  return EXIT_SUCCESS;
}

int Surfaces(const TempDir& dir)
{
  MEDIAL_CHECK(vtkMedialFileWriter::GetExtensions(vtkMedialFileWriter::SURFACE) == ".vtp .vtk .stl .ply .obj",
    "surface extensions %s", vtkMedialFileWriter::GetExtensions(vtkMedialFileWriter::SURFACE).c_str());
  MEDIAL_CHECK(vtkMedialFileWriter::CanWriteExtension("a.OBJ") && !vtkMedialFileWriter::CanWriteExtension("a.ma") &&
      vtkMedialFileWriter::CanWriteExtension("a.ma", vtkMedialFileWriter::BALLS),
    "CanWriteExtension");
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkPolyData* surface = sphere->GetOutput();
  double expected[6];
  surface->GetBounds(expected);
  for (const char* name : { "s.vtp", "s.vtk", "s.stl", "s.ply", "s.obj" })
  {
    EventLog log;
    MEDIAL_CHECK(Write(surface, dir.File(name), vtkMedialFileWriter::SURFACE, log), "%s: %s", name, log.Text.c_str());
    Read r;
    ReadFile(dir.File(name), vtkMedialFileReader::SURFACE, r);
    double bounds[6];
    r.Output->GetBounds(bounds);
    MEDIAL_CHECK(r.Ok && r.Output->GetNumberOfPolys() == surface->GetNumberOfPolys(), "%s: %lld polygons, %s", name,
      static_cast<long long>(r.Output->GetNumberOfPolys()), r.Log.Text.c_str());
    for (int k = 0; k < 6; ++k)
    {
      MEDIAL_CHECK(std::abs(bounds[k] - expected[k]) < 1e-6, "%s: bounds", name);
    }
  }
  // A .vtp holds VTK XML whatever writes it (the example that wrote STL bytes into one).
  std::ifstream vtp(dir.File("s.vtp"));
  std::string first;
  std::getline(vtp, first);
  MEDIAL_CHECK(first.find("<?xml") == 0 || first.find("<VTKFile") == 0, "s.vtp starts with '%s'", first.c_str());
  return EXIT_SUCCESS;
}
}

int TestMedialFileWriter(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "cannot create a temporary folder");
  MEDIAL_CHECK(vtkMedialFileWriter::GetExtensions(vtkMedialFileWriter::BALLS) == ".vtp .vtk .ply .ma .csv",
    "ball extensions %s", vtkMedialFileWriter::GetExtensions(vtkMedialFileWriter::BALLS).c_str());
  for (auto part : { &RoundTrips, &ForeignFiles, &BadFiles, &Surfaces })
  {
    if (part(dir) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
