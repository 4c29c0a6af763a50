// SPDX-License-Identifier: BSD-3-Clause
// medial-thickness-bench: wall thickness against closed forms and CGAL's shape diameter
// function, side by side.
//
//   medial-thickness-bench [--threads T] [--shared DIR] [--no-meshes] [--no-shapes]
//                          [--no-sdf] [--only NAME,NAME] [--write DIR]
//
// For the generated shapes whose wall thickness is known in closed form (sphere R = 1
// of 5k triangles: 2R; hollow sphere 1 / 0.6: its wall 0.4; box 1 x 0.62 x 0.37 turned
// by (30, 20, 10) degrees, 972 triangles: 0.37 at every vertex; torus (1, 0.27) and the
// same torus contoured from its distance field on a 120^3 grid: 2 x 0.27; capsule of
// radius 0.5: 1) and for every shared mesh, it prints the percentiles 1, 50 and 99 of
//  - Thickness, TangentThickness and RayThickness of vtkMedialThickness at the
//    vertices,
//  - CGAL's shape diameter function (CGAL::sdf_values of Surface_mesh_segmentation,
//    its defaults: a cone of 120 degrees, 25 rays; raw values, not normalised) at the
//    triangles of the same prepared surface,
// as value / true for the shapes and value / bounding-box diagonal for the meshes
// (which have no closed form), and the processor time of each (vtkMedialThickness
// with its preparation, one run of the filter for its three arrays; the SDF with the
// building of its surface mesh; both on the calling thread with --threads 1).
// --write DIR also writes each generated shape there as a .vtp (to run other builds or
// tools on the same surfaces), and for every input NAME the triangles the SDF saw with
// their raw SDF as the cell array ShapeDiameter, as NAME-sdf.vtp (to compare it cell by
// cell). Prints Markdown tables. Not a test: it checks nothing.
#include "vtkMedialArrayNames.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkXMLPolyDataWriter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// User + system processor seconds of the process (all threads).
double CpuSeconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Input
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Surface;
  double Truth = 0.0; // > 0: the closed-form thickness everywhere
};

vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution, double radius, double second = 0.0)
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShape(shape);
  source->SetResolution(resolution);
  source->SetRadius(radius);
  if (shape == vtkMedialShapeSource::TORUS || shape == vtkMedialShapeSource::CONTOURED_TORUS)
  {
    source->SetTubeRadius(second);
  }
  if (shape == vtkMedialShapeSource::HOLLOW_SPHERE)
  {
    source->SetInnerRadius(second);
  }
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkPolyData> TurnedBox()
{
  vtkNew<vtkMedialShapeSource> source;
  source->SetShapeToBox();
  source->SetBoxLengths(1.0, 0.62, 0.37);
  source->SetResolution(9);
  vtkNew<vtkTransform> turn;
  turn->RotateX(30.0);
  turn->RotateY(20.0);
  turn->RotateZ(10.0);
  vtkNew<vtkTransformPolyDataFilter> turned;
  turned->SetInputConnection(source->GetOutputPort());
  turned->SetTransform(turn);
  turned->Update();
  return turned->GetOutput();
}

std::vector<Input> Inputs(const std::string& shared, bool meshes, bool shapes)
{
  std::vector<Input> inputs;
  if (shapes)
  {
    inputs.push_back({ "sphere R = 1, 5k", Shape(vtkMedialShapeSource::SPHERE, 4, 1.0), 2.0 });
    inputs.push_back({ "hollow sphere 1 / 0.6", Shape(vtkMedialShapeSource::HOLLOW_SPHERE, 4, 1.0, 0.6), 0.4 });
    inputs.push_back({ "box 1 x 0.62 x 0.37 turned, 972", TurnedBox(), 0.37 });
    inputs.push_back({ "torus (1, 0.27)", Shape(vtkMedialShapeSource::TORUS, 48, 1.0, 0.27), 0.54 });
    inputs.push_back(
      { "contoured torus (1, 0.27), 120^3", Shape(vtkMedialShapeSource::CONTOURED_TORUS, 120, 1.0, 0.27), 0.54 });
    inputs.push_back({ "capsule r = 0.5", Shape(vtkMedialShapeSource::CAPSULE, 16, 0.5), 1.0 });
  }
  for (const char* name : { "horse.ply", "stanford-bunny.obj", "fandisk.obj", "spot.obj", "rocker-arm.obj" })
  {
    struct stat st;
    const std::string path = shared + "/" + name;
    if (meshes && stat(path.c_str(), &st) == 0)
    {
      vtkNew<vtkMedialFileReader> reader;
      reader->SetFileName(path.c_str());
      reader->Update();
      inputs.push_back({ name, reader->GetOutput(), 0.0 });
    }
  }
  return inputs;
}

// An input's name as a file name: every character but letters and digits a '-'.
std::string FileName(const std::string& name)
{
  std::string file;
  for (char c : name)
  {
    file += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  }
  return file;
}

// Percentiles 1, 50 and 99 of the finite values, each divided by `scale`.
std::string Percentiles(std::vector<double> values, double scale)
{
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
    values.end());
  if (values.empty())
  {
    return "| - | - | - ";
  }
  std::sort(values.begin(), values.end());
  auto at = [&](double q) { return values[static_cast<size_t>(q * (values.size() - 1) + 0.5)] / scale; };
  char text[96];
  std::snprintf(text, sizeof(text), "| %.4f | %.4f | %.4f ", at(0.01), at(0.5), at(0.99));
  return text;
}

std::vector<double> Values(vtkPolyData* surface, const char* name)
{
  std::vector<double> values;
  vtkDataArray* a = surface->GetPointData()->GetArray(name);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    values.push_back(a->GetComponent(i, 0));
  }
  return values;
}

// CGAL's raw SDF of every triangle of the prepared surface (outward, merged points),
// and the processor seconds it took (the surface mesh's build included). Empty when
// CGAL refuses the surface (a non-manifold one). With `cells`, those triangles with
// their SDF as the cell array ShapeDiameter.
std::vector<double> ShapeDiameter(vtkPolyData* surface, double& seconds, vtkPolyData* cells = nullptr)
{
  std::vector<double> values;
  vtkMedialTriangleMesh prepared;
  std::string error;
  if (!prepared.Build(surface, error))
  {
    return values;
  }
  const double start = CpuSeconds();
  SurfaceMesh mesh;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType i = 0; i < prepared.GetNumberOfPoints(); ++i)
  {
    const double* p = prepared.GetPoint(i);
    vertices.push_back(mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
    points->InsertNextPoint(p);
  }
  for (vtkIdType t = 0; t < prepared.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = prepared.GetTriangle(t);
    if (mesh.add_face(vertices[v[0]], vertices[v[1]], vertices[v[2]]) == SurfaceMesh::null_face())
    {
      continue; // non-manifold: CGAL's halfedge mesh cannot hold it; skipped
    }
    triangles->InsertNextCell(3, v); // in the order of mesh.faces()
  }
  auto sdf = mesh.add_property_map<SurfaceMesh::Face_index, double>("f:sdf").first;
  CGAL::sdf_values(mesh, sdf, 2.0 / 3.0 * CGAL_PI, 25, false);
  seconds = CpuSeconds() - start;
  for (auto f : mesh.faces())
  {
    values.push_back(sdf[f]);
  }
  if (cells)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName("ShapeDiameter");
    for (double v : values)
    {
      array->InsertNextValue(v);
    }
    cells->SetPoints(points);
    cells->SetPolys(triangles);
    cells->GetCellData()->AddArray(array);
  }
  return values;
}
}

int main(int argc, char* argv[])
{
  std::string shared = MEDIALAXIS_SHARED_MESH_DIR;
  int threads = 1;
  bool meshes = true, shapes = true, sdf = true;
  std::string only, write;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc)
    {
      threads = std::atoi(argv[++i]);
    }
    else if (a == "--shared" && i + 1 < argc)
    {
      shared = argv[++i];
    }
    else if (a == "--write" && i + 1 < argc)
    {
      write = argv[++i];
    }
    else if (a == "--only" && i + 1 < argc)
    {
      only = argv[++i];
    }
    else if (a == "--no-meshes" || a == "--no-shapes" || a == "--no-sdf")
    {
      (a == "--no-meshes" ? meshes : a == "--no-shapes" ? shapes : sdf) = false;
    }
    else
    {
      std::printf("usage: medial-thickness-bench [--threads T] [--shared DIR] [--no-meshes] [--no-shapes]\n"
                  "                              [--no-sdf] [--only NAME,NAME] [--write DIR]\n");
      return a == "--help" || a == "-h" ? 0 : 1;
    }
  }
  std::printf("| input | triangles | scale | Thickness p1 | p50 | p99 | TangentThickness p1 | p50 | p99 "
              "| RayThickness p1 | p50 | p99 | ours, s | CGAL SDF p1 | p50 | p99 | SDF, s |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Input& input : Inputs(shared, meshes, shapes))
  {
    if (!only.empty() && ("," + only + ",").find("," + input.Name + ",") == std::string::npos)
    {
      continue;
    }
    if (!write.empty() && input.Truth > 0.0)
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetFileName((write + "/" + FileName(input.Name) + ".vtp").c_str());
      writer->SetInputData(input.Surface);
      writer->Write();
    }
    const double scale = input.Truth > 0.0 ? input.Truth : input.Surface->GetLength();
    vtkNew<vtkMedialThickness> thickness;
    thickness->SetInputData(input.Surface);
    thickness->SetComputeCellThickness(false);
    thickness->SetNumberOfThreads(threads);
    const double start = CpuSeconds();
    thickness->Update();
    const double ours = CpuSeconds() - start;
    vtkPolyData* out = thickness->GetOutput();
    double sdfSeconds = 0.0;
    vtkNew<vtkPolyData> sdfCells;
    const std::vector<double> diameters =
      sdf ? ShapeDiameter(input.Surface, sdfSeconds, write.empty() ? nullptr : sdfCells.Get()) : std::vector<double>();
    if (!write.empty() && !diameters.empty())
    {
      vtkNew<vtkXMLPolyDataWriter> writer;
      writer->SetFileName((write + "/" + FileName(input.Name) + "-sdf.vtp").c_str());
      writer->SetInputData(sdfCells);
      writer->Write();
    }
    std::printf("| %s | %lld | %s ", input.Name.c_str(), static_cast<long long>(input.Surface->GetNumberOfCells()),
      input.Truth > 0.0 ? "true" : "diagonal");
    std::printf("%s", Percentiles(Values(out, vtkMedialArrayNames::Thickness), scale).c_str());
    std::printf("%s", Percentiles(Values(out, vtkMedialArrayNames::TangentThickness), scale).c_str());
    std::printf("%s", Percentiles(Values(out, vtkMedialArrayNames::RayThickness), scale).c_str());
    std::printf("| %.3f %s", ours, Percentiles(diameters, scale).c_str());
    std::printf("| %s |\n", sdf && !diameters.empty() ? std::to_string(sdfSeconds).substr(0, 6).c_str() : "-");
    std::fflush(stdout);
  }
  return EXIT_SUCCESS;
}
