// SPDX-License-Identifier: BSD-3-Clause
// Writing a medial mesh and reading it back gives the same doubles bit for bit,
// the same edges and faces; polylines, strips and polygons are split as
// documented; the file is in Q-MAT's clean form (every triangle side an edge record,
// each edge once, 0-based, no comments); extra columns on 'v' lines, comments and
// CRLF are accepted.
#include "ReaderTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMedialMeshReader.h"
#include "vtkMedialMeshWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

using namespace readertest;

namespace
{
bool SameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

std::string Slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Data;
  int Errors = 0;
  std::string Text;
};

ReadResult Read(const std::string& path)
{
  vtkNew<vtkMedialMeshReader> reader;
  EventLog log;
  log.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  return { reader->GetOutput(), log.Errors, log.Text };
}

bool Write(vtkPolyData* pd, const std::string& path)
{
  vtkNew<vtkMedialMeshWriter> writer;
  EventLog log;
  log.Watch(writer);
  writer->SetInputData(pd);
  writer->SetFileName(path.c_str());
  return writer->Write() == 1 && log.Errors == 0;
}

vtkSmartPointer<vtkPolyData> MakeMedialMesh(
  const std::vector<std::array<double, 4>>& balls, vtkPoints* points)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  for (const auto& b : balls)
  {
    points->InsertNextPoint(b[0], b[1], b[2]);
    radius->InsertNextValue(b[3]);
  }
  pd->SetPoints(points);
  pd->GetPointData()->AddArray(radius);
  vtkNew<vtkCellArray> lines, polys, strips;
  pd->SetLines(lines);
  pd->SetPolys(polys);
  pd->SetStrips(strips);
  return pd;
}

void Add(vtkCellArray* cells, std::vector<vtkIdType> ids)
{
  cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
}

// Awkward values, a polyline, a strip and a triangle: exact round trip, and the
// documented splitting.
int CheckExactRoundTrip(const TempDir& dir)
{
  const double denormal = std::numeric_limits<double>::denorm_min();
  const std::vector<std::array<double, 4>> balls = {
    { 0.0, -0.0, 1.0, 0.0 },
    { 1.0 / 3.0, -2.0 / 7.0, 1e-300, 1.0 / 3.0 },
    { M_PI * 1e10, -0.1, denormal, 0.1 },
    { std::numeric_limits<double>::max(), -1e-5, 0.3, 1e-310 },
    { 0.1, 0.2, 0.30000000000000004, 123456.789 },
    { -std::numeric_limits<double>::max(), 7.0, std::nextafter(1.0, 2.0), 2.5 },
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto pd = MakeMedialMesh(balls, points);
  Add(pd->GetLines(), { 0, 1 });
  Add(pd->GetLines(), { 1, 2, 3 }); // polyline: two edges
  Add(pd->GetPolys(), { 0, 1, 2 });
  Add(pd->GetStrips(), { 2, 3, 4, 5 }); // strip: two triangles, alternating order

  const std::string first = dir.File("exact.ma");
  MEDIAL_CHECK(Write(pd, first), "writing exact.ma failed");
  const std::string text = Slurp(first);
  // 3 line segments, then the sides not written yet: 2-0; 3-4, 4-2; 3-5, 5-4.
  MEDIAL_CHECK(text.rfind("6 8 3\n", 0) == 0, "header is not '6 8 3': %s", text.c_str());
  const ReadResult back = Read(first);
  MEDIAL_CHECK(back.Errors == 0, "reading exact.ma: %s", back.Text.c_str());
  vtkPolyData* out = back.Data;
  MEDIAL_CHECK(out->GetNumberOfPoints() == 6, "%lld points", (long long)out->GetNumberOfPoints());
  vtkDataArray* radius = out->GetPointData()->GetArray("Radius");
  MEDIAL_CHECK(radius && radius->GetDataType() == VTK_DOUBLE, "no double Radius array");
  for (vtkIdType i = 0; i < 6; ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    for (int c = 0; c < 3; ++c)
    {
      MEDIAL_CHECK(SameBits(p[c], balls[i][c]), "point %lld component %d: %.17g != %.17g",
        (long long)i, c, p[c], balls[i][c]);
    }
    MEDIAL_CHECK(SameBits(radius->GetComponent(i, 0), balls[i][3]), "radius %lld: %.17g != %.17g",
      (long long)i, radius->GetComponent(i, 0), balls[i][3]);
  }
  MEDIAL_CHECK(CellsOf(out->GetLines()) ==
      Cells({ { 0, 1 }, { 1, 2 }, { 2, 3 }, { 2, 0 }, { 3, 4 }, { 4, 2 }, { 3, 5 }, { 5, 4 } }),
    "edges differ");
  MEDIAL_CHECK(CellsOf(out->GetPolys()) == Cells({ { 0, 1, 2 }, { 2, 3, 4 }, { 4, 3, 5 } }),
    "faces differ");
  MEDIAL_CHECK(out->GetNumberOfStrips() == 0 && out->GetNumberOfVerts() == 0, "extra cells");

  // Writing what was read gives the same file.
  const std::string second = dir.File("exact2.ma");
  MEDIAL_CHECK(Write(out, second), "writing exact2.ma failed");
  MEDIAL_CHECK(Slurp(second) == text, "second write differs from the first");
  return EXIT_SUCCESS;
}

// Random doubles over the whole exponent range, float points and float radii.
int CheckRandomValues(const TempDir& dir)
{
  std::mt19937_64 bits(12345);
  auto anyFinite = [&bits]() {
    for (;;)
    {
      const vtkTypeUInt64 word = bits();
      double value;
      std::memcpy(&value, &word, sizeof(value));
      if (std::isfinite(value))
      {
        return value;
      }
    }
  };
  std::vector<std::array<double, 4>> balls(2000);
  for (auto& b : balls)
  {
    b = { anyFinite(), anyFinite(), anyFinite(), std::fabs(anyFinite()) };
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto pd = MakeMedialMesh(balls, points);
  for (vtkIdType i = 0; i + 2 < 2000; i += 3)
  {
    Add(pd->GetPolys(), { i, i + 1, i + 2 });
    Add(pd->GetLines(), { i + 2, i });
  }
  const std::string path = dir.File("random.ma");
  MEDIAL_CHECK(Write(pd, path), "writing random.ma failed");
  const ReadResult back = Read(path);
  MEDIAL_CHECK(back.Errors == 0, "reading random.ma: %s", back.Text.c_str());
  vtkDataArray* radius = back.Data->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < 2000; ++i)
  {
    double p[3];
    back.Data->GetPoint(i, p);
    const bool same = SameBits(p[0], balls[i][0]) && SameBits(p[1], balls[i][1]) &&
      SameBits(p[2], balls[i][2]) && SameBits(radius->GetComponent(i, 0), balls[i][3]);
    MEDIAL_CHECK(same, "random ball %lld changed", (long long)i);
  }
  MEDIAL_CHECK(CellsOf(back.Data->GetPolys()) == CellsOf(pd->GetPolys()), "random faces differ");
  // The lines (each a side c-a), then the two other sides of each triangle.
  Cells expectedEdges = CellsOf(pd->GetLines());
  for (const auto& f : CellsOf(pd->GetPolys()))
  {
    expectedEdges.push_back({ f[0], f[1] });
    expectedEdges.push_back({ f[1], f[2] });
  }
  MEDIAL_CHECK(CellsOf(back.Data->GetLines()) == expectedEdges, "random edges differ");

  // Float storage: the written doubles are the floats, exactly.
  vtkNew<vtkPoints> floatPoints;
  floatPoints->SetDataTypeToFloat();
  floatPoints->InsertNextPoint(0.1, 1.0 / 3.0, 1e30);
  auto fp = vtkSmartPointer<vtkPolyData>::New();
  fp->SetPoints(floatPoints);
  vtkNew<vtkFloatArray> floatRadius;
  floatRadius->SetName("Radius");
  floatRadius->InsertNextValue(0.7f);
  fp->GetPointData()->AddArray(floatRadius);
  const std::string floatPath = dir.File("float.ma");
  MEDIAL_CHECK(Write(fp, floatPath), "writing float.ma failed");
  const ReadResult floats = Read(floatPath);
  double p[3];
  floats.Data->GetPoint(0, p);
  MEDIAL_CHECK(p[0] == double(0.1f) && p[1] == double(float(1.0 / 3.0)) && p[2] == double(1e30f) &&
      floats.Data->GetPointData()->GetArray("Radius")->GetComponent(0, 0) == double(0.7f),
    "float values changed");
  return EXIT_SUCCESS;
}

// Quad and pentagon faces become n - 2 triangles over the polygon's own vertices
// and covering its area; a one-point line is skipped with a warning.
int CheckPolygonSplitting(const TempDir& dir)
{
  const std::vector<std::array<double, 4>> balls = { { 0, 0, 0, 1 }, { 2, 0, 0, 1 },
    { 2, 2, 0, 1 }, { 0, 2, 0, 1 }, { 4, 0, 0, 1 }, { 5, 1, 0, 1 }, { 4.5, 2, 0, 1 },
    { 3.5, 2, 0, 1 }, { 3, 1, 0, 1 } };
  vtkNew<vtkPoints> points;
  auto pd = MakeMedialMesh(balls, points);
  Add(pd->GetPolys(), { 0, 1, 2, 3 });       // square, area 4
  Add(pd->GetPolys(), { 4, 5, 6, 7, 8 });    // convex pentagon, area 2.5
  Add(pd->GetLines(), { 3 });                // skipped
  vtkNew<vtkMedialMeshWriter> writer;
  EventLog log;
  log.Watch(writer);
  writer->SetInputData(pd);
  const std::string path = dir.File("polygons.ma");
  writer->SetFileName(path.c_str());
  MEDIAL_CHECK(writer->Write() == 1 && log.Errors == 0, "writing polygons.ma: %s", log.Text.c_str());
  MEDIAL_CHECK(log.Warnings == 1 && log.Text.find("Skipped 1") != std::string::npos,
    "no warning about the one-point line: %s", log.Text.c_str());
  const ReadResult back = Read(path);
  MEDIAL_CHECK(back.Errors == 0, "reading polygons.ma: %s", back.Text.c_str());
  const Cells faces = CellsOf(back.Data->GetPolys());
  MEDIAL_CHECK(faces.size() == 2 + 3, "%zu triangles, expected 5", faces.size());
  // The edges are the 5 + 7 distinct sides of the triangles; the one-point line is not one.
  MEDIAL_CHECK(back.Data->GetNumberOfLines() == 12, "%lld edges, expected 12",
    (long long)back.Data->GetNumberOfLines());
  const double expectedArea[2] = { 4.0, 2.5 };
  for (int polygon = 0; polygon < 2; ++polygon)
  {
    const size_t from = polygon == 0 ? 0 : 2, to = polygon == 0 ? 2 : 5;
    const vtkIdType lowest = polygon == 0 ? 0 : 4, highest = polygon == 0 ? 3 : 8;
    double area = 0.0;
    for (size_t t = from; t < to; ++t)
    {
      double a[3], b[3], c[3];
      for (vtkIdType id : faces[t])
      {
        MEDIAL_CHECK(id >= lowest && id <= highest, "triangle uses vertex %lld", (long long)id);
      }
      back.Data->GetPoint(faces[t][0], a);
      back.Data->GetPoint(faces[t][1], b);
      back.Data->GetPoint(faces[t][2], c);
      // Signed area: a consistently oriented split keeps the polygon's winding.
      area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
    }
    MEDIAL_CHECK(std::fabs(area - expectedArea[polygon]) < 1e-12, "polygon %d: area %g, expected %g",
      polygon, area, expectedArea[polygon]);
  }
  return EXIT_SUCCESS;
}

// The clean form Q-MAT reads, exactly: two triangles sharing a side, a dangling edge
// written twice, a vertex cell (not an edge): every side once, lines first.
int CheckQMatForm(const TempDir& dir)
{
  const std::vector<std::array<double, 4>> balls = { { 0, 0, 0, 1 }, { 1, 0, 0, 0.5 },
    { 0, 1, 0, 0.25 }, { 1, 1, 0, 2 }, { 2, 2, 0, 0 } };
  vtkNew<vtkPoints> points;
  auto pd = MakeMedialMesh(balls, points);
  Add(pd->GetLines(), { 3, 4 });
  Add(pd->GetLines(), { 4, 3 });
  Add(pd->GetPolys(), { 0, 1, 2 });
  Add(pd->GetPolys(), { 2, 1, 3 });
  vtkNew<vtkCellArray> verts;
  Add(verts, { 4 });
  pd->SetVerts(verts);
  const std::string path = dir.File("qmat.ma");
  MEDIAL_CHECK(Write(pd, path), "writing qmat.ma failed");
  const std::string expected = "5 6 2\n"
                               "v 0 0 0 1\n"
                               "v 1 0 0 0.5\n"
                               "v 0 1 0 0.25\n"
                               "v 1 1 0 2\n"
                               "v 2 2 0 0\n"
                               "e 3 4\n"
                               "e 0 1\n"
                               "e 1 2\n"
                               "e 2 0\n"
                               "e 1 3\n"
                               "e 3 2\n"
                               "f 0 1 2\n"
                               "f 2 1 3\n";
  const std::string text = Slurp(path);
  MEDIAL_CHECK(text == expected, "qmat.ma is\n%s", text.c_str());
  return EXIT_SUCCESS;
}

// Files from other tools: extra 'v' columns, comments, blank lines, CRLF, '+' signs.
int CheckForeignFile(const TempDir& dir)
{
  const std::string path = dir.Write("foreign.ma",
    "# written by some tool\r\n"
    "3 2 1\r\n"
    "\r\n"
    "v 0 0 0 1 0.25 7 extra\r\n"
    "v 1.5e0 -2 +3 0.5 9\r\n"
    "v 0 1 0 0 # zero radius is allowed\r\n"
    "e 0 1\r\n"
    "e 1 2\r\n"
    "f 0 1 2\r\n"
    "# trailing comment\r\n");
  const ReadResult back = Read(path);
  MEDIAL_CHECK(back.Errors == 0, "reading foreign.ma: %s", back.Text.c_str());
  vtkPolyData* out = back.Data;
  MEDIAL_CHECK(out->GetNumberOfPoints() == 3, "%lld points", (long long)out->GetNumberOfPoints());
  double p[3];
  out->GetPoint(1, p);
  MEDIAL_CHECK(p[0] == 1.5 && p[1] == -2.0 && p[2] == 3.0, "point 1 is %g %g %g", p[0], p[1], p[2]);
  vtkDataArray* radius = out->GetPointData()->GetArray("Radius");
  MEDIAL_CHECK(radius->GetComponent(0, 0) == 1.0 && radius->GetComponent(1, 0) == 0.5 &&
      radius->GetComponent(2, 0) == 0.0,
    "radii are not 1, 0.5, 0");
  MEDIAL_CHECK(CellsOf(out->GetLines()) == Cells({ { 0, 1 }, { 1, 2 } }), "edges differ");
  MEDIAL_CHECK(CellsOf(out->GetPolys()) == Cells({ { 0, 1, 2 } }), "faces differ");

  // An empty mesh is valid and round-trips.
  const ReadResult none = Read(dir.Write("none.ma", "0 0 0\n"));
  MEDIAL_CHECK(none.Errors == 0 && none.Data->GetNumberOfPoints() == 0, "empty mesh");
  return EXIT_SUCCESS;
}
}

int TestMedialMeshRoundTrip(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "cannot create a temporary folder");
  for (auto check :
    { CheckExactRoundTrip, CheckRandomValues, CheckPolygonSplitting, CheckQMatForm, CheckForeignFile })
  {
    if (check(dir) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
