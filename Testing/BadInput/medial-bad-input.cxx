// SPDX-License-Identifier: BSD-3-Clause
// medial-bad-input: the filter side of the bad-input table (Testing/BadInput/cases.tsv).
//
//   medial-bad-input generate DIR
//       writes every input file the table names into DIR (run by ctest before the rows)
//   medial-bad-input run FILE [-n N] [--repair auto|none|wrap] [--junctions] [--write OUT.vtp]
//                         [--same-as REF [--scale S]] [--cli-output OUT.vtp]
//       runs the pipeline the command-line program would run, filter by filter: the
//       reader for FILE's extension (vtkMedialFileReader), vtkMedialAxisSampler (and, with --junctions,
//       vtkMedialJunctionFilter), optionally vtkXMLPolyDataWriter. Prints one summary
//       line per filter and every error or warning it logged, and exits 0 when every
//       update succeeded, 1 when one failed. --same-as checks that the radii, divided by
//       S and relative to the diagonal, equal those of REF's run (within 1e-6);
//       --cli-output checks the command-line program's .vtp against REF's run the same way.
#include "vtkMedialArrayNames.h"
#include "MedialShapeTestUtilities.h"
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMath.h"
#include "vtkMedialShapeSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

using medialtest::EventLog;

namespace
{
// Messages that reach no observer (readers' internal helpers) are printed as "vtk: ...".
class PrintingOutputWindow : public vtkOutputWindow
{
public:
  static PrintingOutputWindow* New();
  vtkTypeMacro(PrintingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override { Print(text); }
  void DisplayErrorText(const char* text) override { Print(text); }
  void DisplayWarningText(const char* text) override { Print(text); }
  void DisplayGenericWarningText(const char* text) override { Print(text); }
  void DisplayDebugText(const char*) override {}

private:
  static void Print(const char* text)
  {
    std::string line = text ? text : "";
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::printf("vtk: %s\n", line.c_str());
  }
};
vtkStandardNewMacro(PrintingOutputWindow);

// ---------------------------------------------------------------- inputs

using Polys = std::vector<std::vector<vtkIdType>>;

vtkSmartPointer<vtkPolyData> Make(const std::vector<std::array<double, 3>>& pts, const Polys& polys,
  const Polys& lines = {})
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : pts)
  {
    points->InsertNextPoint(p.data());
  }
  pd->SetPoints(points);
  vtkNew<vtkCellArray> cells, lineCells;
  for (const auto& c : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  for (const auto& c : lines)
  {
    lineCells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  if (!polys.empty())
  {
    pd->SetPolys(cells);
  }
  if (!lines.empty())
  {
    pd->SetLines(lineCells);
  }
  return pd;
}

// The triangles of `pd`, each passed through `edit` (which may drop it by returning false).
vtkSmartPointer<vtkPolyData> EditTriangles(
  vtkPolyData* pd, const std::function<bool(vtkIdType, std::vector<vtkIdType>&)>& edit)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(pd->GetPoints());
  vtkNew<vtkCellArray> cells;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    pd->GetCellPoints(c, n, ids);
    std::vector<vtkIdType> tri(ids, ids + n);
    if (edit(c, tri))
    {
      cells->InsertNextCell(static_cast<vtkIdType>(tri.size()), tri.data());
    }
  }
  out->SetPolys(cells);
  return out;
}

// Every point mapped to x * scale + offset * scale (double precision).
vtkSmartPointer<vtkPolyData> Scaled(vtkPolyData* pd, double scale)
{
  const double offset[3] = { 3, -2, 1 }; // off the origin too
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    points->InsertNextPoint(
      (x[0] + offset[0]) * scale, (x[1] + offset[1]) * scale, (x[2] + offset[2]) * scale);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(pd->GetPolys());
  return out;
}

// A closed, consistently wound box whose top-centre vertex is pulled down through
// the bottom: a folded-over, self-intersecting spike.
vtkSmartPointer<vtkPolyData> FoldedBox()
{
  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->SetResolution(8);
  box->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(box->GetOutput());
  double bounds[6];
  out->GetBounds(bounds);
  const double top[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), bounds[5] };
  vtkIdType nearest = 0;
  double best = HUGE_VAL;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double d = vtkMath::Distance2BetweenPoints(x, top);
    if (d < best)
    {
      best = d;
      nearest = i;
    }
  }
  out->GetPoints()->SetPoint(nearest, top[0], top[1], bounds[4] - 0.5 * (bounds[5] - bounds[4]));
  return out;
}

// Several generated shapes in one mesh: each moved by Offset, its triangles reversed
// when asked (a naive export winds every shell outward; nesting must sort it out).
struct Body
{
  int Shape;
  int Resolution;
  double Size;       // radius of a sphere, side of a cube
  double Offset[3];
  bool Reversed;
};
vtkSmartPointer<vtkPolyData> Bodies(const std::vector<Body>& bodies)
{
  std::vector<std::array<double, 3>> pts;
  Polys tris;
  for (const Body& body : bodies)
  {
    vtkNew<vtkMedialShapeSource> source;
    source->SetShape(body.Shape);
    source->SetResolution(body.Resolution);
    source->SetRadius(body.Size);
    source->SetBoxLengths(body.Size, body.Size, body.Size);
    source->Update();
    vtkPolyData* b = source->GetOutput();
    const vtkIdType first = static_cast<vtkIdType>(pts.size());
    for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
    {
      double x[3];
      b->GetPoint(i, x);
      pts.push_back({ x[0] + body.Offset[0], x[1] + body.Offset[1], x[2] + body.Offset[2] });
    }
    for (vtkIdType c = 0; c < b->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      b->GetCellPoints(c, n, ids);
      std::vector<vtkIdType> t;
      for (vtkIdType k = 0; k < n; ++k)
      {
        t.push_back(ids[k] + first);
      }
      if (body.Reversed)
      {
        std::reverse(t.begin(), t.end());
      }
      tris.push_back(t);
    }
  }
  return Make(pts, tris);
}

// Two unit boxes touching along one edge: 4 triangles meet there.
vtkSmartPointer<vtkPolyData> BoxesSharingAnEdge()
{
  const int box = vtkMedialShapeSource::BOX;
  return Bodies({ { box, 1, 1.0, { 0, 0, 0 }, false }, { box, 1, 1.0, { 1, 1, 0 }, false } });
}

bool WriteText(const std::string& path, const std::string& text)
{
  std::ofstream f(path, std::ios::binary);
  f << text;
  return static_cast<bool>(f);
}

bool WriteVtp(const std::string& path, vtkPolyData* pd)
{
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(pd);
  w->SetFileName(path.c_str());
  w->SetDataModeToBinary();
  return w->Write() == 1;
}

const char* const TetraOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string TetraPly(const char* thirdVertex)
{
  return std::string("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                     "end_header\n0 0 0\n1 0 0\n") +
    thirdVertex + "\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

int Generate(const std::string& dir)
{
  std::error_code failed;
  std::filesystem::create_directories(dir + "/a-directory.vtp", failed);
  bool ok = !failed;
  ok &= WriteText(dir + "/empty.ply", "");
  ok &= WriteText(dir + "/off-named.ply", TetraOff);
  ok &= WriteText(dir + "/ply-named.stl", TetraPly("0 1 0"));
  ok &= WriteText(dir + "/legacy-named.vtp",
    "# vtk DataFile Version 3.0\ntetra\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
    "0 0 0 1 0 0 0 1 0 0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ok &= WriteVtp(dir + "/points-only.vtp", Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, {}));
  // An open polyline along four edges of a tetrahedron: not planar, no surface.
  ok &= WriteText(dir + "/lines-3d.vtk",
    "# vtk DataFile Version 3.0\nlines in 3D\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
    "0 0 0 1 0 0 0 1 0 0 0 1\nLINES 1 5\n4 0 1 2 3\n");
  ok &= WriteText(dir + "/triangle.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n4 0 0\n0 3 0\n3 0 1 2\n");
  ok &= WriteText(dir + "/nan.ply", TetraPly("0 nan 0"));
  ok &= WriteText(dir + "/inf.ply", TetraPly("0 inf 0"));

  const auto sphere = medialtest::MakeShape(vtkMedialShapeSource::SPHERE, 4);
  // A sphere with its polar cap (centroid z > 0.8) cut away.
  ok &= WriteVtp(dir + "/open-sphere.vtp", EditTriangles(sphere, [&](vtkIdType, std::vector<vtkIdType>& t) {
    double z = 0;
    for (vtkIdType id : t)
    {
      z += sphere->GetPoint(id)[2] / 3.0;
    }
    return z <= 0.8;
  }));
  ok &= WriteVtp(dir + "/non-manifold.vtp", BoxesSharingAnEdge());
  ok &= WriteVtp(dir + "/folded.vtp", FoldedBox());
  {
    // Solids as users have them: shells as a naive export writes them (all outward).
    const int ball = vtkMedialShapeSource::SPHERE, box = vtkMedialShapeSource::BOX;
    ok &= WriteVtp(dir + "/hollow-sphere.vtp",
      Bodies({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 0.7, { 0, 0, 0 }, false } }));
    ok &= WriteVtp(dir + "/solid-in-cavity.vtp", Bodies({ { ball, 4, 1.0, { 0, 0, 0 }, true },
      { ball, 4, 0.7, { 0, 0, 0 }, false }, { ball, 4, 0.4, { 0, 0, 0 }, true } }));
    ok &= WriteVtp(dir + "/two-bodies.vtp",
      Bodies({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 0.5, { 3, 0, 0 }, true } }));
    // Face to face, with different tessellations: no vertex in common.
    ok &= WriteVtp(dir + "/touching-boxes.vtp",
      Bodies({ { box, 2, 1.0, { 0, 0, 0 }, false }, { box, 3, 1.0, { 1, 0, 0 }, false } }));
    ok &= WriteVtp(dir + "/intersecting-spheres.vtp",
      Bodies({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 1.0, { 1.5, 0, 0 }, false } }));
  }
  {
    // Every triangle twice.
    auto doubled = EditTriangles(sphere, [](vtkIdType, std::vector<vtkIdType>&) { return true; });
    for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      sphere->GetCellPoints(c, n, ids);
      doubled->GetPolys()->InsertNextCell(n, ids);
    }
    ok &= WriteVtp(dir + "/duplicate-triangles.vtp", doubled);
    // A repeated-vertex sliver, a collinear triangle, a point-triangle in a good mesh.
    auto degenerate = EditTriangles(sphere, [](vtkIdType, std::vector<vtkIdType>&) { return true; });
    const vtkIdType sliver[3] = { 0, 0, 1 }, point[3] = { 2, 2, 2 };
    degenerate->GetPolys()->InsertNextCell(3, sliver);
    degenerate->GetPolys()->InsertNextCell(3, point);
    vtkIdType a = degenerate->GetPoints()->InsertNextPoint(0, 0, 0);
    degenerate->GetPoints()->InsertNextPoint(0.1, 0, 0);
    degenerate->GetPoints()->InsertNextPoint(0.2, 0, 0);
    const vtkIdType collinear[3] = { a, a + 1, a + 2 };
    degenerate->GetPolys()->InsertNextCell(3, collinear);
    ok &= WriteVtp(dir + "/degenerate-triangles.vtp", degenerate);
  }

  const auto jack = medialtest::MakeShape(vtkMedialShapeSource::JACK, 12);
  ok &= WriteVtp(dir + "/jack.vtp", jack);
  ok &= WriteVtp(dir + "/jack-1e12.vtp", Scaled(jack, 1e12));
  ok &= WriteVtp(dir + "/jack-1e-12.vtp", Scaled(jack, 1e-12));
  ok &= WriteVtp(dir + "/jack-flipped.vtp", EditTriangles(jack, [](vtkIdType, std::vector<vtkIdType>& t) {
    std::reverse(t.begin(), t.end());
    return true;
  }));
  ok &= WriteVtp(dir + "/jack-mixed.vtp", EditTriangles(jack, [](vtkIdType c, std::vector<vtkIdType>& t) {
    if (c % 2)
    {
      std::reverse(t.begin(), t.end());
    }
    return true;
  }));

  // 2D: a bow tie (its edges cross), and two square loops in parallel planes.
  ok &= WriteVtp(dir + "/bow-tie.vtp", Make({ { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2, 3 } }));
  ok &= WriteVtp(dir + "/two-planes.vtp",
    Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
      {}, { { 0, 1, 2, 3, 0 }, { 4, 5, 6, 7, 4 } }));
  ok &= WriteVtp(dir + "/two-planes-polygons.vtp",
    Make({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } },
      { { 0, 1, 2, 3 }, { 4, 5, 6, 7 } }));
  std::printf("generated the bad-input files in %s: %s\n", dir.c_str(), ok ? "ok" : "FAILED");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

// ---------------------------------------------------------------- runs

void PrintLog(const char* who, const EventLog& log)
{
  std::string text = log.Text;
  size_t at = 0;
  while (at < text.size())
  {
    size_t end = text.find('\n', at);
    end = end == std::string::npos ? text.size() : end;
    const std::string line = text.substr(at, end - at);
    // Keep the message after "Class (0x...): "; drop VTK's "ERROR: In file, line N" head
    // and the indented dump of a failed request.
    if (!line.empty() && line[0] != ' ' && line.rfind("ERROR: In ", 0) != 0 &&
      line.rfind("Warning: In ", 0) != 0)
    {
      const size_t colon = line.find("): ");
      std::printf("%s: %s\n", who, colon == std::string::npos ? line.c_str() : line.substr(colon + 3).c_str());
    }
    at = end + 1;
  }
}

struct SamplerRun
{
  vtkSmartPointer<vtkPolyData> Output;
  double Diagonal = 0.0;
};

// The sampler on a file, as run from the command line (seed 1, default settings).
bool RunSampler(const std::string& path, vtkIdType samples, int repair, SamplerRun& run, bool print)
{
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  EventLog log;
  log.Watch(reader);
  vtkNew<vtkMedialAxisSampler> sampler;
  log.Watch(sampler);
  sampler->SetInputConnection(reader->GetOutputPort());
  sampler->SetNumberOfSamples(samples);
  sampler->SetRepairMode(repair);
  const bool ok = sampler->GetExecutive()->Update() == 1;
  run.Output = sampler->GetOutput();
  if (auto* surface = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0)))
  {
    run.Diagonal = surface->GetLength();
  }
  if (print)
  {
    vtkDataArray* discarded = run.Output->GetFieldData()->GetArray(vtkMedialArrayNames::DiscardedSamples);
    std::printf("sampler: update %s, %d error(s), %d warning(s), %lld points, %g discarded\n",
      ok ? "ok" : "failed", log.Errors, log.Warnings, static_cast<long long>(run.Output->GetNumberOfPoints()),
      discarded ? discarded->GetComponent(0, 0) : 0.0);
    PrintLog("sampler log", log);
  }
  return ok;
}

// Largest |r_b / scale - r_a| relative to a's diagonal, or -1 when the counts differ.
double RadiusDifference(const SamplerRun& a, vtkPolyData* b, double scale)
{
  vtkDataArray* ra = a.Output->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  vtkDataArray* rb = b->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  if (!ra || !rb || ra->GetNumberOfTuples() != rb->GetNumberOfTuples())
  {
    return -1.0;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < ra->GetNumberOfTuples(); ++i)
  {
    worst = std::max(worst, std::fabs(rb->GetTuple1(i) / scale - ra->GetTuple1(i)) / a.Diagonal);
  }
  return worst;
}

bool ReportSame(const char* what, const SamplerRun& reference, vtkPolyData* other, double scale)
{
  const double worst = RadiusDifference(reference, other, scale);
  const bool same = worst >= 0.0 && worst <= 1e-6;
  std::printf("%s: radii / %g against the reference: max difference %.3g of the diagonal (%s)\n", what,
    scale, worst, same ? "same" : "DIFFERENT");
  return same;
}

int Run(int argc, char* argv[])
{
  const std::string path = argv[2];
  vtkIdType samples = 1000;
  int repair = vtkMedialRepairFilter::AUTO;
  bool junctions = false;
  std::string write, sameAs, cliOutput;
  double scale = 1.0;
  for (int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "-n" && hasValue)
    {
      samples = static_cast<vtkIdType>(std::strtod(argv[++i], nullptr));
    }
    else if (a == "--junctions")
    {
      junctions = true;
    }
    else if (a == "--repair" && hasValue)
    {
      repair = vtkMedialRepairFilter::GetModeFromName(argv[++i]);
      if (repair < 0)
      {
        std::printf("medial-bad-input: unknown --repair '%s'\n", argv[i]);
        return 2;
      }
    }
    else if (a == "--write" && hasValue)
    {
      write = argv[++i];
    }
    else if (a == "--same-as" && hasValue)
    {
      sameAs = argv[++i];
    }
    else if (a == "--scale" && hasValue)
    {
      scale = std::strtod(argv[++i], nullptr);
    }
    else if (a == "--cli-output" && hasValue)
    {
      cliOutput = argv[++i];
    }
    else
    {
      std::printf("medial-bad-input: unknown or incomplete option '%s'\n", a.c_str());
      return 2;
    }
  }

  bool ok = true;
  SamplerRun run;
  ok &= RunSampler(path, samples, repair, run, true);

  if (junctions)
  {
    vtkNew<vtkMedialFileReader> reader;
    reader->SetFileName(path.c_str());
    EventLog log;
    vtkNew<vtkMedialJunctionFilter> filter;
    log.Watch(filter);
    filter->SetInputConnection(reader->GetOutputPort());
    const bool good = filter->GetExecutive()->Update() == 1;
    std::printf("junctions: update %s, %d error(s), %d warning(s), %lld points, %lld arcs\n",
      good ? "ok" : "failed", log.Errors, log.Warnings,
      static_cast<long long>(filter->GetOutput()->GetNumberOfPoints()),
      static_cast<long long>(filter->GetOutput()->GetNumberOfLines()));
    PrintLog("junctions log", log);
    ok &= good;
  }

  if (!write.empty())
  {
    EventLog log;
    vtkNew<vtkXMLPolyDataWriter> writer;
    log.Watch(writer);
    writer->SetInputData(run.Output);
    writer->SetFileName(write.c_str());
    const bool good = writer->Write() == 1 && log.Errors == 0;
    std::printf("writer: write %s, %d error(s)\n", good ? "ok" : "failed", log.Errors);
    PrintLog("writer log", log);
    ok &= good;
  }

  if (!sameAs.empty())
  {
    SamplerRun reference;
    if (!RunSampler(sameAs, samples, repair, reference, false))
    {
      std::printf("reference run on '%s' failed\n", sameAs.c_str());
      return 1;
    }
    ok &= ReportSame("filter", reference, run.Output, scale);
    if (!cliOutput.empty())
    {
      vtkNew<vtkXMLPolyDataReader> cliReader;
      cliReader->SetFileName(cliOutput.c_str());
      cliReader->Update();
      ok &= ReportSame("command line", reference, cliReader->GetOutput(), scale);
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
}

int main(int argc, char* argv[])
{
  vtkNew<PrintingOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the window prints instead
  if (argc == 3 && std::string(argv[1]) == "generate")
  {
    return Generate(argv[2]);
  }
  if (argc >= 3 && std::string(argv[1]) == "run")
  {
    return Run(argc, argv);
  }
  std::printf("usage: medial-bad-input generate DIR | run FILE [-n N] [--repair MODE] [--junctions] [--write OUT.vtp]\n"
              "       [--same-as REF [--scale S]] [--cli-output OUT.vtp]\n");
  return 2;
}
