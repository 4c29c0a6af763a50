// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialFileReader: every extension the tools accept reaches its reader (the same
// tetrahedron in each surface format, an upper-case extension, a legacy unstructured
// grid whose surface is extracted, .ma balls); the format table's answers; an unknown
// extension and a broken file fail with one error on the reader itself; CanReadFile of
// the project's own readers.
#include "ReaderTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialMeshReader.h"
#include "vtkMedialOFFReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"

#include <string>
#include <vector>

using namespace readertest;

namespace
{
const char* const TetraPly = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                             "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* const TetraOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* const TetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* const TetraStl = "solid tetra\n"
                             "facet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
                             "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
                             "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
                             "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n"
                             "endsolid tetra\n";
// A legacy unstructured grid of one tetrahedron: its surface is four triangles.
const char* const TetraGrid = "# vtk DataFile Version 3.0\ntetra\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                              "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
const char* const Balls = "2 1 0\nv 0 0 0 1\nv 2 0 0 0.5\ne 0 1\n";

vtkIdType SurfaceTriangles(vtkPolyData* pd)
{
  vtkIdType triangles = 0;
  for (const auto& cell : CellsOf(pd->GetPolys()))
  {
    triangles += cell.size() == 3 ? 1 : 0;
  }
  return triangles;
}
}

int TestMedialFileReader(int, char*[])
{
  TempDir dir;
  MEDIAL_CHECK(dir.Valid(), "cannot create a temporary folder");

  // The format table.
  MEDIAL_CHECK(vtkMedialFileReader::GetExtensions(vtkMedialFileReader::SURFACE) == ".vtp .vtk .ply .stl .obj .off",
    "surface extensions: %s", vtkMedialFileReader::GetExtensions(vtkMedialFileReader::SURFACE).c_str());
  MEDIAL_CHECK(vtkMedialFileReader::GetExtensions(vtkMedialFileReader::BALLS) == ".ma .ply .vtp .vtk .csv", "ball extensions: %s",
    vtkMedialFileReader::GetExtensions(vtkMedialFileReader::BALLS).c_str());
  MEDIAL_CHECK(vtkMedialFileReader::GetExtension("/a.b/Mesh.PLY") == ".ply", "extension of Mesh.PLY");
  MEDIAL_CHECK(vtkMedialFileReader::GetExtension("/a.b/mesh").empty(), "a dot in a folder is no extension");
  MEDIAL_CHECK(vtkMedialFileReader::CanReadExtension("x.off") && !vtkMedialFileReader::CanReadExtension("x.ma") &&
      vtkMedialFileReader::CanReadExtension("x.ma", vtkMedialFileReader::BALLS) &&
      !vtkMedialFileReader::CanReadExtension("x.txt"),
    "CanReadExtension");
  const std::vector<std::pair<const char*, const char*>> readers = { { "a.vtp", "vtkXMLPolyDataReader" },
    { "a.vtk", "vtkDataSetReader" }, { "a.ply", "vtkPLYReader" }, { "a.stl", "vtkSTLReader" },
    { "a.obj", "vtkOBJReader" }, { "a.off", "vtkMedialOFFReader" } };
  for (const auto& [name, className] : readers)
  {
    vtkSmartPointer<vtkAlgorithm> reader;
    reader.TakeReference(vtkMedialFileReader::NewReader(name));
    MEDIAL_CHECK(reader && std::string(reader->GetClassName()) == className, "%s: reader %s, expected %s", name,
      reader ? reader->GetClassName() : "none", className);
  }
  MEDIAL_CHECK(!vtkMedialFileReader::NewReader("a.txt"), "a reader for .txt");

  // The same tetrahedron in every surface format.
  vtkNew<vtkPolyData> tetra;
  {
    Read ply;
    ReadFile(dir.Write("tetra.ply", TetraPly), vtkMedialFileReader::SURFACE, ply);
    MEDIAL_CHECK(ply.Ok, "tetra.ply: %s", ply.Log.Text.c_str());
    tetra->DeepCopy(ply.Output);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(tetra);
    writer->SetFileName(dir.File("tetra.vtp").c_str());
    MEDIAL_CHECK(writer->Write() == 1, "cannot write tetra.vtp");
  }
  const std::vector<std::string> surfaces = { dir.Write("tetra.PLY", TetraPly), dir.Write("tetra.off", TetraOff),
    dir.Write("tetra.obj", TetraObj), dir.Write("tetra.stl", TetraStl), dir.Write("tetra.vtk", TetraGrid),
    dir.File("tetra.vtp") };
  for (const std::string& path : surfaces)
  {
    Read r;
    ReadFile(path, vtkMedialFileReader::SURFACE, r);
    std::printf("%-60s %lld points, %lld triangles\n", path.c_str(), (long long)r.Output->GetNumberOfPoints(),
      (long long)SurfaceTriangles(r.Output));
    MEDIAL_CHECK(r.Ok && r.Log.Errors == 0 && r.Log.Warnings == 0, "%s: %s", path.c_str(), r.Log.Text.c_str());
    MEDIAL_CHECK(SurfaceTriangles(r.Output) == 4 && r.Output->GetNumberOfCells() == 4, "%s: %lld cells",
      path.c_str(), (long long)r.Output->GetNumberOfCells());
    double bounds[6];
    r.Output->GetBounds(bounds);
    MEDIAL_CHECK(bounds[0] == 0 && bounds[1] == 1 && bounds[2] == 0 && bounds[3] == 1 && bounds[4] == 0 &&
        bounds[5] == 1,
      "%s: not the unit tetrahedron", path.c_str());
  }

  // Balls from a .ma file; a .ma file is no surface.
  {
    Read r;
    ReadFile(dir.Write("balls.ma", Balls), vtkMedialFileReader::BALLS, r);
    vtkDataArray* radius = r.Output->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
    MEDIAL_CHECK(r.Ok && radius && radius->GetNumberOfTuples() == 2 && radius->GetTuple1(1) == 0.5 &&
        r.Output->GetNumberOfLines() == 1,
      "balls.ma: %s", r.Log.Text.c_str());
    Read surface;
    ReadFile(dir.File("balls.ma"), vtkMedialFileReader::SURFACE, surface);
    MEDIAL_CHECK(!surface.Ok && surface.Log.LineWith("unsupported input extension '.ma' (.vtp .vtk .ply .stl .obj .off)") != "",
      "balls.ma read as a surface: %s", surface.Log.Text.c_str());
  }

  // Errors: an unknown extension, and a broken file whose reader's error is reported by this reader.
  {
    Read r;
    ReadFile(dir.Write("notes.txt", "a mesh?\n"), vtkMedialFileReader::SURFACE, r);
    MEDIAL_CHECK(!r.Ok && r.Log.Errors >= 1 && r.Log.LineWith("unsupported input extension '.txt'") != "",
      "notes.txt: %s", r.Log.Text.c_str());
    MEDIAL_CHECK(r.Output->GetNumberOfPoints() == 0, "notes.txt: output not empty");
    Read broken;
    ReadFile(dir.Write("truncated.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n"), vtkMedialFileReader::SURFACE, broken);
    const std::string line = broken.Log.LineWith("Cannot read OFF file");
    std::printf("truncated.off: %s\n", line.c_str());
    MEDIAL_CHECK(!broken.Ok && line.find("vtkMedialFileReader") != std::string::npos &&
        line.find(", line 5: the file ends before vertex 3 of 8") != std::string::npos,
      "truncated.off: %s", broken.Log.Text.c_str());
    MEDIAL_CHECK(broken.Output->GetNumberOfPoints() == 0, "truncated.off: output not empty");
  }

  // CanReadFile of the project's readers looks at the header only.
  MEDIAL_CHECK(vtkMedialOFFReader::CanReadFile(dir.File("tetra.off").c_str()) == 1, "OFF CanReadFile");
  MEDIAL_CHECK(vtkMedialOFFReader::CanReadFile(dir.File("tetra.ply").c_str()) == 0, "OFF CanReadFile on PLY");
  MEDIAL_CHECK(vtkMedialOFFReader::CanReadFile(dir.File("missing.off").c_str()) == 0, "OFF CanReadFile, no file");
  MEDIAL_CHECK(vtkMedialMeshReader::CanReadFile(dir.File("balls.ma").c_str()) == 1, "MA CanReadFile");
  MEDIAL_CHECK(vtkMedialMeshReader::CanReadFile(dir.File("tetra.off").c_str()) == 0, "MA CanReadFile on OFF");
  return EXIT_SUCCESS;
}
