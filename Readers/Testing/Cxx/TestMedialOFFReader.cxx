// SPDX-License-Identifier: BSD-3-Clause
// OFF files as tools write them: comments, blank lines, counts on the keyword's
// line, polygons of any size, COFF/NOFF/CNOFF vertex columns, face colours,
// CRLF, a byte order mark, no keyword. Every one must give exactly the expected
// points and faces.
#include "ReaderTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialOFFReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vector>

using namespace readertest;

namespace
{
struct Case
{
  const char* Name;
  std::string Content;
  std::vector<double> Coordinates; // x y z per point
  Cells Faces;
};

// A square pyramid with a pentagon-free base, and a house (pentagon) shape.
const std::vector<double> Pyramid = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1 };
const Cells PyramidFaces = { { 0, 3, 2, 1 }, { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } };
const std::vector<double> House = { 0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 3, 0, 0, 2, 0, 1.25, -0.5, 1e-3 };
const Cells HouseFaces = { { 0, 1, 2, 3, 4 }, { 0, 5, 1 } };

std::vector<Case> Cases()
{
  return {
    { "plain OFF with comments and blank lines",
      "OFF\n# a square pyramid\n\n5 5 8   # nv nf ne\n"
      "0 0 0\n1 0 0\n  1 1 0\n\n0 1 0\n0.5 0.5 1 # apex\n"
      "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n# between faces\n3 2 3 4\n3 3 0 4\n\n# end\n",
      Pyramid, PyramidFaces },
    { "counts on the keyword line, no ne",
      "OFF 5 5\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
      "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n",
      Pyramid, PyramidFaces },
    { "pentagon and triangle with face colours",
      "OFF\n6 2 0\n0 0 0\n2 0 0\n2 2 0\n1 3 0\n0 2 0\n1.25 -0.5 1e-3\n"
      "5 0 1 2 3 4 255 0 0\n3 0 5 1 0.1 0.2 0.3 1.0\n",
      House, HouseFaces },
    { "COFF with RGBA vertex colours",
      "COFF\n6 2 0\n0 0 0 255 0 0 255\n2 0 0 0 255 0 255\n2 2 0 0 0 255 255\n1 3 0 1 1 1 1\n"
      "0 2 0 0.5 0.5 0.5 1\n1.25 -0.5 1e-3 0 0 0 0\n5 0 1 2 3 4\n3 0 5 1\n",
      House, HouseFaces },
    { "NOFF with normals",
      "NOFF\n6 2 0\n0 0 0 0 0 1\n2 0 0 0 0 1\n2 2 0 0 0 1\n1 3 0 0 0 1\n0 2 0 0 0 1\n"
      "1.25 -0.5 1e-3 0 0 -1\n5 0 1 2 3 4\n3 0 5 1\n",
      House, HouseFaces },
    { "CNOFF with normals and colours",
      "CNOFF\n6 2 0\n0 0 0 0 0 1 1 0 0\n2 0 0 0 0 1 1 0 0\n2 2 0 0 0 1 1 0 0\n1 3 0 0 0 1 1 0 0\n"
      "0 2 0 0 0 1 1 0 0\n1.25 -0.5 1e-3 0 0 -1 1 0 0\n5 0 1 2 3 4\n3 0 5 1\n",
      House, HouseFaces },
    { "CRLF line endings",
      "OFF\r\n6 2 0\r\n0 0 0\r\n2 0 0\r\n2 2 0\r\n1 3 0\r\n0 2 0\r\n1.25 -0.5 1e-3\r\n"
      "5 0 1 2 3 4\r\n3 0 5 1\r\n",
      House, HouseFaces },
    { "UTF-8 byte order mark",
      "\xEF\xBB\xBFOFF\n6 2 0\n0 0 0\n2 0 0\n2 2 0\n1 3 0\n0 2 0\n1.25 -0.5 1e-3\n5 0 1 2 3 4\n3 0 5 1\n",
      House, HouseFaces },
    { "no keyword, tabs",
      "6\t2\t0\n0\t0\t0\n2 0 0\n2 2 0\n1 3 0\n0 2 0\n1.25\t-0.5\t1e-3\n5 0 1 2 3 4\n3\t0 5 1",
      House, HouseFaces },
    { "vertices only",
      "OFF\n2 0 0\n1 2 3\n-4 -5 -6\n", { 1, 2, 3, -4, -5, -6 }, {} },
    { "empty mesh", "OFF\n0 0 0\n", {}, {} },
  };
}
}

int TestMedialOFFReader(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "cannot create a temporary folder");
  int index = 0;
  for (const Case& c : Cases())
  {
    const std::string path = dir.Write("case" + std::to_string(index++) + ".off", c.Content);
    vtkNew<vtkMedialOFFReader> reader;
    EventLog log;
    log.Watch(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* out = reader->GetOutput();
    std::printf("%-42s %lld points, %lld polygons\n", c.Name, (long long)out->GetNumberOfPoints(),
      (long long)out->GetNumberOfPolys());
    MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", c.Name, log.Text.c_str());
    MEDIAL_CHECK(vtkMedialOFFReader::CanReadFile(path.c_str()) == 1, "%s: CanReadFile says no", c.Name);
    const vtkIdType n = static_cast<vtkIdType>(c.Coordinates.size() / 3);
    MEDIAL_CHECK(out->GetNumberOfPoints() == n, "%s: %lld points, expected %lld", c.Name,
      (long long)out->GetNumberOfPoints(), (long long)n);
    MEDIAL_CHECK(n == 0 || out->GetPoints()->GetDataType() == VTK_DOUBLE, "%s: points not double",
      c.Name);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      for (int k = 0; k < 3; ++k)
      {
        MEDIAL_CHECK(p[k] == c.Coordinates[3 * i + k], "%s: point %lld component %d is %g, expected %g",
          c.Name, (long long)i, k, p[k], c.Coordinates[3 * i + k]);
      }
    }
    MEDIAL_CHECK(CellsOf(out->GetPolys()) == c.Faces, "%s: faces differ", c.Name);
    MEDIAL_CHECK(out->GetNumberOfCells() == static_cast<vtkIdType>(c.Faces.size()),
      "%s: cells other than polygons", c.Name);
  }
  return EXIT_SUCCESS;
}
