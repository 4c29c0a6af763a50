// SPDX-License-Identifier: BSD-3-Clause
// medial-axis: medial axis transform of a closed triangle mesh or of planar
// polygons, from the command line.
//
// Reads a mesh or polygon (or generates a demo shape), runs vtkMedialAxisSampler
// (and, for 2D input, vtkMedialJunctionFilter), and writes the medial balls, the
// medial graph, a picture and a JSON line of figures. Only wiring lives here;
// every algorithm is in a filter.

#include "vtkMedialArrayNames.h"
#include "MedialReconstructionError.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialMeshWriter.h"
#include "vtkMedialShapeSource.h"
#include "vtkOFFReader.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDataSetReader.h"
#include "vtkFieldData.h"
#include "vtkDataArray.h"
#include "vtkLogger.h"
#include "vtkCellData.h"
#include "vtkGlyph3D.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkCellArray.h"
#include "vtkRegularPolygonSource.h"
#include "vtkSphereSource.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPolyDataNormals.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <omp.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

namespace
{
const char* Usage =
  "usage: medial-axis [INPUT] [-n N] [--method bisection|shrinking-ball|one-pass] [--seed S]\n"
  "                   [--strategy random|closest-neighbor|face-distance] [--coverage E]\n"
  "                   [--threads T] [--tolerance E] [--min-angle DEG] [-o OUT.vtp]\n"
  "                   [--render OUT.png] [--stats] [--reconstruct OUT.vtp|.stl|.ply]\n"
  "                   [--resolution N] [--junctions OUT.vtp] [--medial-mesh OUT.vtp|OUT.ma]\n"
  "  INPUT        closed surface: .vtp .vtk .ply .stl .obj .off; or planar polygons / closed\n"
  "               polylines (any plane, holes allowed) for the 2D medial axis;\n"
  "               or a demo: demo:jack (3D, the default with no INPUT), demo:l-shape,\n"
  "               demo:rectangle, demo:frame (square with a square hole), demo:star (2D)\n"
  "  -n N         number of surface samples (default 10000)\n"
  "  --method M   one-pass (default, fastest), bisection (the report's) or shrinking-ball\n"
  "  --strategy S where the samples go (3D): random (default), closest-neighbor (Poisson-disk\n"
  "               seeds linked to their closest non-overlapping neighbour, links split until\n"
  "               the balls overlap; -o then holds the links as lines) or face-distance\n"
  "               (Poisson-disk seeds, then always the face farthest from the union of balls)\n"
  "  --coverage E stop once every face's vertices and centroid are within E (relative to the\n"
  "               bounding-box diagonal) of the union of balls, or at -n samples (default 0: off)\n"
  "  --seed S     random seed (default 1); output is identical for any thread count\n"
  "  --threads T  OpenMP threads, 0 = all cores (default 0)\n"
  "  --tolerance E  bisection tolerance relative to the bounding-box diagonal (default 1e-6)\n"
  "  --min-angle DEG  minimum separation angle theta in degrees (default 45; 0 = exact\n"
  "               medial axis of the polyhedron)\n"
  "  -o OUT.vtp   write the medial balls (points with Radius, SurfacePoint, ...)\n"
  "  --render OUT.png  render the surface and the medial points offscreen (needs X; use xvfb-run)\n"
  "  --stats      print one JSON line of figures on stdout\n"
  "  --reconstruct OUT  write the boundary of the union of the medial balls (.vtp .stl .ply);\n"
  "               with --stats adds reconstruction_seconds and, for a closed input,\n"
  "               hausdorff_max_rel and hausdorff_mean_rel (vertex to surface, the larger\n"
  "               of the two directions, relative to the bounding-box diagonal);\n"
  "               with --render the reconstruction is drawn beside the input\n"
  "  --resolution N  grid points per axis of the reconstruction (default 128)\n"
  "  --junctions OUT.vtp  2D input only: write the medial graph (junctions, end points,\n"
  "               linear and parabolic arcs; point data Radius, MedialPointType,\n"
  "               GovernorCount; cell data ArcType). --render then draws it too.\n"
  "  --medial-mesh OUT  3D input only: write the medial mesh (the balls joined by edges and\n"
  "               triangles, with the solid's topology) as .vtp (point data Radius,\n"
  "               MedialPointType, ...; cell data MedialCellType) or .ma (Q-MAT's form);\n"
  "               with --stats adds medial_vertices, medial_edges (triangle sides\n"
  "               included), medial_faces, seams and junctions (vertices of those\n"
  "               MedialPointTypes), euler_characteristic, components and\n"
  "               medial_mesh_seconds; --render then draws it coloured by MedialPointType\n";

struct Options
{
  std::string Input;
  long long Samples = 10000;
  int Method = vtkMedialAxisSampler::ONE_PASS;
  int Strategy = vtkMedialAxisSampler::RANDOM;
  double Coverage = 0.0;
  unsigned long long Seed = 1;
  int Threads = 0;
  double Tolerance = 1e-6;
  double MinAngle = 45.0;
  std::string Output;
  std::string Render;
  std::string Junctions;
  std::string MedialMesh;
  bool Stats = false;
  std::string Reconstruct;
  int Resolution = 128;
};

volatile std::sig_atomic_t Interrupted = 0;
// Set while the sampler runs its blocks and checks for an abort after each one.
volatile std::sig_atomic_t AbortWatched = 0;

// Ctrl-C: inside the sampler's blocks, ask it to abort (the progress observer does);
// anywhere else (reading, preparation, writing) nothing would notice, so leave at once.
void OnInterrupt(int)
{
  Interrupted = 1;
  if (!AbortWatched)
  {
    const char message[] = "medial-axis: interrupted\n";
    [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, message, sizeof(message) - 1);
    _exit(130);
  }
}

[[noreturn]] void Fail(const std::string& reason)
{
  std::cerr << "medial-axis: error: " << reason << "\n";
  std::exit(1);
}

// Receives every VTK error and warning (readers' internal helpers included) and
// turns them into one-line messages: warnings are printed, the first error is
// kept as the reason for failing.
class MessageSink : public vtkOutputWindow
{
public:
  static MessageSink* New();
  vtkTypeMacro(MessageSink, vtkOutputWindow);

  std::string LastError;

  void DisplayErrorText(const char* raw) override
  {
    const std::string text = OneLine(raw);
    // The executive's "returned failure" follows the real reason; use it only alone.
    const bool pipelineNote = text.find("returned failure for request") != std::string::npos;
    if (this->LastError.empty() || this->ReasonIsFallback)
    {
      if (!pipelineNote)
      {
        this->LastError = text;
        this->ReasonIsFallback = false;
      }
      else if (this->LastError.empty())
      {
        this->LastError = this->LastWarning.empty() ? text.substr(0, text.find(" for request")) : this->LastWarning;
        this->ReasonIsFallback = true;
      }
    }
  }
  void DisplayWarningText(const char* raw) override
  {
    this->LastWarning = OneLine(raw);
    std::cerr << "medial-axis: warning: " << this->LastWarning << "\n";
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayText(const char* text) override { std::cerr << text; }
  void DisplayDebugText(const char*) override {}

private:
  std::string LastWarning;
  bool ReasonIsFallback = false;

  // VTK writes "ERROR: In file, line N\nClass (0x...): message"; keep the message.
  static std::string OneLine(const char* raw)
  {
    std::string text = raw ? raw : "";
    const size_t colon = text.find("): ");
    if (colon != std::string::npos)
    {
      text = text.substr(colon + 3);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
  }
};
vtkStandardNewMacro(MessageSink);

bool ParseNumber(const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && std::isfinite(value);
}

Options Parse(int argc, char* argv[])
{
  Options o;
  auto need = [&](int& i) -> const char* {
    if (i + 1 >= argc)
    {
      Fail(std::string(argv[i]) + " needs a value (see --help)");
    }
    return argv[++i];
  };
  auto number = [&](int& i, double lo, double hi) {
    const std::string flag = argv[i];
    const char* text = need(i);
    double v;
    if (!ParseNumber(text, v) || v < lo || v > hi)
    {
      std::ostringstream os;
      os << flag << " expects a number in [" << lo << ", " << hi << "], got '" << text << "'";
      Fail(os.str());
    }
    return v;
  };
  auto integer = [&](int& i, double lo, double hi) {
    const std::string flag = argv[i];
    const double v = number(i, lo, hi);
    if (v != std::floor(v))
    {
      Fail(flag + " expects a whole number");
    }
    return v;
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (a == "-n")
    {
      o.Samples = static_cast<long long>(integer(i, 1, 1e15));
    }
    else if (a == "--method")
    {
      const std::string m = need(i);
      if (m == "bisection")
      {
        o.Method = vtkMedialAxisSampler::BISECTION;
      }
      else if (m == "shrinking-ball")
      {
        o.Method = vtkMedialAxisSampler::SHRINKING_BALL;
      }
      else if (m == "one-pass")
      {
        o.Method = vtkMedialAxisSampler::ONE_PASS;
      }
      else
      {
        Fail("unknown --method '" + m + "' (bisection, shrinking-ball, one-pass)");
      }
    }
    else if (a == "--strategy")
    {
      const std::string m = need(i);
      if (m == "random")
      {
        o.Strategy = vtkMedialAxisSampler::RANDOM;
      }
      else if (m == "closest-neighbor")
      {
        o.Strategy = vtkMedialAxisSampler::CLOSEST_NEIGHBOR;
      }
      else if (m == "face-distance")
      {
        o.Strategy = vtkMedialAxisSampler::FACE_DISTANCE;
      }
      else
      {
        Fail("unknown --strategy '" + m + "' (random, closest-neighbor, face-distance)");
      }
    }
    else if (a == "--coverage")
    {
      o.Coverage = number(i, 0, 1);
    }
    else if (a == "--seed")
    {
      o.Seed = static_cast<unsigned long long>(integer(i, 0, 9.0e15));
    }
    else if (a == "--threads")
    {
      o.Threads = static_cast<int>(integer(i, 0, 4096));
    }
    else if (a == "--tolerance")
    {
      o.Tolerance = number(i, 1e-15, 0.1);
    }
    else if (a == "--min-angle")
    {
      o.MinAngle = number(i, 0, 179);
    }
    else if (a == "-o")
    {
      o.Output = need(i);
    }
    else if (a == "--render")
    {
      o.Render = need(i);
    }
    else if (a == "--stats")
    {
      o.Stats = true;
    }
    else if (a == "--reconstruct")
    {
      o.Reconstruct = need(i);
    }
    else if (a == "--resolution")
    {
      o.Resolution = static_cast<int>(integer(i, 8, 2048));
    }
    else if (a == "--junctions")
    {
      o.Junctions = need(i);
    }
    else if (a == "--medial-mesh")
    {
      o.MedialMesh = need(i);
    }
    else if (!a.empty() && a[0] == '-')
    {
      Fail("unknown option '" + a + "' (see --help)");
    }
    else if (o.Input.empty())
    {
      o.Input = a;
    }
    else
    {
      Fail("more than one input file given");
    }
  }
  return o;
}

std::string Extension(const std::string& path)
{
  const size_t dot = path.find_last_of('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// Fails unless `path` can be created as a file.
void CheckWritable(const std::string& path, const char* what)
{
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    Fail(std::string(what) + " path '" + path + "' is a directory");
  }
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (access(dir.c_str(), W_OK) != 0)
  {
    Fail(std::string(what) + " path '" + path + "' is not writable (folder '" + dir + "')");
  }
}

template <class Reader>
vtkSmartPointer<vtkAlgorithm> FileReader(const std::string& path)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

vtkSmartPointer<vtkPolyData> ReadSurface(const std::string& path, MessageSink& sink)
{
  struct stat st;
  if (stat(path.c_str(), &st) != 0)
  {
    Fail("cannot open input '" + path + "': " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode))
  {
    Fail("input '" + path + "' is a directory");
  }
  if (st.st_size == 0)
  {
    Fail("input '" + path + "' is empty");
  }
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkAlgorithm> reader, legacy;
  if (ext == ".vtp")
  {
    reader = FileReader<vtkXMLPolyDataReader>(path);
  }
  else if (ext == ".vtk")
  {
    // Any legacy dataset; its surface is extracted.
    legacy = FileReader<vtkDataSetReader>(path); // kept alive: the connection does not own it
    auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    surface->SetInputConnection(legacy->GetOutputPort());
    reader = surface;
  }
  else if (ext == ".ply")
  {
    reader = FileReader<vtkPLYReader>(path);
  }
  else if (ext == ".stl")
  {
    reader = FileReader<vtkSTLReader>(path);
  }
  else if (ext == ".obj")
  {
    reader = FileReader<vtkOBJReader>(path);
  }
  else if (ext == ".off")
  {
    reader = FileReader<vtkOFFReader>(path);
  }
  else
  {
    Fail("unsupported input extension '" + ext + "' (.vtp .vtk .ply .stl .obj .off)");
  }
  reader->Update();
  if (!sink.LastError.empty())
  {
    Fail("cannot read '" + path + "': " + sink.LastError);
  }
  vtkPolyData* data = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!data || data->GetNumberOfPoints() == 0)
  {
    Fail("cannot read '" + path + "': no points (empty or not a " + ext + " file)");
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(data);
  return copy;
}

// Checks the --reconstruct path before any work, like -o.
void CheckReconstructPath(const std::string& path)
{
  const std::string ext = Extension(path);
  if (ext != ".vtp" && ext != ".stl" && ext != ".ply")
  {
    Fail("--reconstruct writes .vtp, .stl or .ply, got '" + path + "'");
  }
  CheckWritable(path, "--reconstruct");
}

// Union of the medial balls, written to `path` by its extension.
vtkSmartPointer<vtkPolyData> Reconstruct(vtkPolyData* medial, const Options& opt, MessageSink& sink)
{
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(medial);
  ballUnion->SetSampleDimensions(opt.Resolution, opt.Resolution, opt.Resolution);
  ballUnion->SetNumberOfThreads(opt.Threads);
  ballUnion->Update();
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(ballUnion->GetOutput());
  return result;
}

void WriteReconstruction(vtkPolyData* reconstruction, const std::string& path, MessageSink& sink)
{
  const std::string ext = Extension(path);
  int written = 0;
  if (ext == ".stl")
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(reconstruction);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    written = w->Write();
  }
  else if (ext == ".ply")
  {
    vtkNew<vtkPLYWriter> w;
    w->SetInputData(reconstruction);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    written = w->Write();
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(reconstruction);
    w->SetFileName(path.c_str());
    w->SetDataModeToBinary();
    written = w->Write();
  }
  if (!written || !sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// Splits the window: the input and medial points on the left, the reconstruction on
// the right with the same camera.
void AddReconstructionView(vtkRenderWindow* window, vtkRenderer* left, vtkPolyData* reconstruction)
{
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(reconstruction);
  normals->SplittingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.90, 0.62, 0.40);
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(1, 1, 1);
  right->AddActor(actor);
  right->SetActiveCamera(left->GetActiveCamera());
  window->AddRenderer(right);
  int* size = window->GetSize();
  window->SetSize(2 * size[0], size[1]);
}

// Saves what the window shows as a PNG; fails with the writer's reason.
void WritePng(vtkRenderWindow* window, const std::string& path, MessageSink& sink)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(path.c_str());
  png->Write();
  if (!sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// --medial-mesh: the medial mesh of the sampled balls (vtkMedialMeshFilter).
vtkSmartPointer<vtkPolyData> RunMedialMesh(
  vtkPolyData* surface, vtkPolyData* balls, int threads, MessageSink& sink)
{
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(surface);
  filter->SetBallsData(balls);
  filter->SetNumberOfThreads(threads);
  filter->Update();
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(filter->GetOutput());
  return mesh;
}

void CheckMedialMeshPath(const std::string& path)
{
  const std::string ext = Extension(path);
  if (ext != ".vtp" && ext != ".ma")
  {
    Fail("--medial-mesh writes .vtp or .ma (Q-MAT's form), got '" + path + "'");
  }
  CheckWritable(path, "--medial-mesh");
}

void WriteMedialMesh(vtkPolyData* mesh, const std::string& path, MessageSink& sink)
{
  int written = 0;
  if (Extension(path) == ".ma")
  {
    vtkNew<vtkMedialMeshWriter> w;
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    written = w->Write();
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(mesh);
    w->SetFileName(path.c_str());
    w->SetDataModeToBinary();
    written = w->Write();
  }
  if (!written || !sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// JSON members for --medial-mesh: sizes, point types, topology and time.
std::string MedialMeshStats(vtkPolyData* mesh, double seconds)
{
  if (!mesh)
  {
    return "";
  }
  vtkIdType perType[4] = { 0, 0, 0, 0 };
  vtkDataArray* types = mesh->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    const int t = static_cast<int>(types->GetTuple1(i));
    perType[std::min(3, std::max(0, t))]++;
  }
  auto field = [mesh](const char* name) -> long long {
    vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
    return a ? static_cast<long long>(a->GetTuple1(0)) : 0;
  };
  const long long vertices = mesh->GetNumberOfPoints(), faces = mesh->GetNumberOfPolys();
  const long long euler = field(vtkMedialArrayNames::EulerCharacteristic);
  std::ostringstream js;
  js.precision(6);
  js << ", \"medial_vertices\": " << vertices << ", \"medial_edges\": " << vertices + faces - euler
     << ", \"medial_faces\": " << faces << ", \"seams\": " << perType[2]
     << ", \"junctions\": " << perType[3] << ", \"euler_characteristic\": " << euler
     << ", \"components\": " << field(vtkMedialArrayNames::Components)
     << ", \"medial_mesh_seconds\": " << seconds;
  return js.str();
}

// The medial mesh coloured by MedialPointType (rim, sheet, seam, junction) through a
// four-entry table, and its legend.
void ColourByPointType(vtkPolyDataMapper* mapper, vtkLookupTable* lut, vtkScalarBarActor* bar)
{
  const double colours[4][3] = { { 0.20, 0.45, 0.85 }, { 0.75, 0.75, 0.72 }, { 0.95, 0.55, 0.10 },
    { 0.85, 0.10, 0.10 } };
  const char* names[4] = { "rim", "sheet", "seam", "junction" };
  lut->SetNumberOfTableValues(4);
  lut->SetTableRange(0, 3);
  for (int t = 0; t < 4; ++t)
  {
    lut->SetTableValue(t, colours[t][0], colours[t][1], colours[t][2]);
    lut->SetAnnotation(t, names[t]);
  }
  lut->IndexedLookupOn();
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(vtkMedialArrayNames::MedialPointType);
  mapper->SetScalarRange(0, 3);
  mapper->ScalarVisibilityOn();
  bar->SetLookupTable(lut);
  bar->SetTitle(vtkMedialArrayNames::MedialPointType);
}

void Render(vtkPolyData* surface, vtkPolyData* medial, const std::string& path, MessageSink& sink,
  vtkPolyData* reconstruction = nullptr, vtkPolyData* medialMesh = nullptr)
{
  vtkNew<vtkPolyDataMapper> surfaceMapper;
  surfaceMapper->SetInputData(surface);
  surfaceMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> surfaceActor;
  surfaceActor->SetMapper(surfaceMapper);
  surfaceActor->GetProperty()->SetColor(0.80, 0.82, 0.86);
  surfaceActor->GetProperty()->SetOpacity(0.22);

  double range[2] = { 0.0, 1.0 };
  if (auto* r = medial->GetPointData()->GetArray(vtkMedialArrayNames::Radius))
  {
    if (r->GetNumberOfTuples() > 0)
    {
      r->GetRange(range);
    }
  }
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0); // blue (thin) to red (thick)
  lut->SetTableRange(range);
  lut->Build();
  vtkNew<vtkPolyDataMapper> medialMapper;
  medialMapper->SetInputData(medial);
  medialMapper->SetLookupTable(lut);
  medialMapper->SetScalarModeToUsePointFieldData();
  medialMapper->SelectColorArray(vtkMedialArrayNames::Radius);
  medialMapper->SetScalarRange(range);
  medialMapper->ScalarVisibilityOn();
  vtkNew<vtkActor> medialActor;
  medialActor->SetMapper(medialMapper);
  medialActor->GetProperty()->SetPointSize(4);
  medialActor->GetProperty()->RenderPointsAsSpheresOn();

  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle(vtkMedialArrayNames::Radius);
  vtkNew<vtkLookupTable> typeColours;
  if (medialMesh)
  {
    medialMapper->SetInputData(medialMesh);
    ColourByPointType(medialMapper, typeColours, bar);
    medialActor->GetProperty()->SetLineWidth(1.5);
  }
  bar->SetNumberOfLabels(5);
  bar->SetWidth(0.09);
  bar->SetHeight(0.6);
  bar->SetPosition(0.89, 0.2);
  bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor(surfaceActor);
  renderer->AddActor(medialActor);
  renderer->AddActor2D(bar);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.6);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(900, 640);
  window->AddRenderer(renderer);
  if (reconstruction)
  {
    AddReconstructionView(window, renderer, reconstruction);
  }
  window->Render();
  WritePng(window, path, sink);
}

// JSON members for --reconstruct; the Hausdorff figures only for a closed input.
std::string ReconstructionStats(vtkPolyData* surface, vtkPolyData* reconstruction, double seconds,
  vtkMedialAxisSampler* sampler, const Options& opt)
{
  if (!reconstruction)
  {
    return "";
  }
  std::ostringstream js;
  js.precision(6);
  js << ", \"reconstruction_seconds\": " << seconds << ", \"resolution\": " << opt.Resolution;
  if (sampler->GetBoundaryEdges() == 0)
  {
    const int threads = opt.Threads > 0 ? opt.Threads : omp_get_num_procs();
    const medialbench::ReconstructionError e =
      medialbench::MeasureReconstruction(surface, reconstruction, threads);
    js << ", \"hausdorff_max_rel\": " << e.MaxRel() << ", \"hausdorff_mean_rel\": " << e.MeanRel();
  }
  return js.str();
}

// ---- 2D input: demo shapes, planarity, the medial graph and its picture ----

// demo:NAME inputs; returns false for an unknown name.
bool MakeDemo(const std::string& name, vtkSmartPointer<vtkPolyData>& out)
{
  vtkNew<vtkMedialShapeSource> demo;
  if (name == "demo:jack")
  {
    demo->SetShapeToJack();
  }
  else if (name == "demo:l-shape")
  {
    demo->SetShapeToLShape();
  }
  else if (name == "demo:rectangle")
  {
    demo->SetShapeToRectangle();
  }
  else if (name == "demo:frame")
  {
    demo->SetShapeToSquareFrame();
  }
  else if (name == "demo:star")
  {
    demo->SetShapeToStar();
    demo->SetResolution(9);
  }
  else
  {
    return false;
  }
  demo->Update();
  out = demo->GetOutput();
  return true;
}

// Plane of the points (centroid and the normal of least variance); the returned
// value is the largest distance of a point from it, relative to the diagonal.
double FitPlane(vtkPolyData* pd, double centre[3], double normal[3])
{
  const vtkIdType n = pd->GetNumberOfPoints();
  centre[0] = centre[1] = centre[2] = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += p[k] / n;
    }
  }
  if (!std::isfinite(centre[0] + centre[1] + centre[2]))
  {
    return HUGE_VAL; // NaN or infinite coordinates: not a plane (the sampler says why)
  }
  double cov[3][3] = {}, row0[3], row1[3], row2[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        cov[a][b] += (p[a] - centre[a]) * (p[b] - centre[b]);
      }
    }
  }
  double* rows[3] = { row0, row1, row2 };
  double* in[3] = { cov[0], cov[1], cov[2] };
  double values[3], vecs[3][3];
  double* v[3] = { vecs[0], vecs[1], vecs[2] };
  for (int a = 0; a < 3; ++a)
  {
    std::copy(cov[a], cov[a] + 3, rows[a]);
  }
  vtkMath::Jacobi(in, values, v);
  // Eigenvalues come sorted in decreasing order; vectors are the columns.
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = vecs[k][2];
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    worst = std::max(worst,
      std::abs((p[0] - centre[0]) * normal[0] + (p[1] - centre[1]) * normal[1] + (p[2] - centre[2]) * normal[2]));
  }
  const double diag = pd->GetLength();
  return diag > 0 ? worst / diag : 0.0;
}

// 2D input: planar loops as polygons or polylines (a closed surface is never planar).
bool IsPlanarInput(vtkPolyData* pd)
{
  if (pd->GetNumberOfStrips() > 0 || (pd->GetNumberOfPolys() == 0 && pd->GetNumberOfLines() == 0))
  {
    return false;
  }
  double c[3], n[3];
  return pd->GetNumberOfPoints() >= 3 && FitPlane(pd, c, n) <= 1e-6;
}

vtkSmartPointer<vtkPolyData> RunJunctions(vtkPolyData* polygon, int threads, MessageSink& sink)
{
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(polygon);
  junctions->SetNumberOfThreads(threads);
  junctions->Update();
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  auto graph = vtkSmartPointer<vtkPolyData>::New();
  graph->ShallowCopy(junctions->GetOutput());
  return graph;
}

// Points of the graph with one MedialPointType, as spheres.
vtkSmartPointer<vtkActor> NodeActor(vtkPolyData* graph, int type, double size, const double rgb[3])
{
  vtkNew<vtkPoints> pts;
  auto* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  for (vtkIdType i = 0; types && i < graph->GetNumberOfPoints(); ++i)
  {
    if (static_cast<int>(types->GetTuple1(i)) == type)
    {
      pts->InsertNextPoint(graph->GetPoint(i));
    }
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(size);
  ball->SetThetaResolution(16);
  ball->SetPhiResolution(12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(cloud);
  glyphs->SetSourceConnection(ball->GetOutputPort());
  glyphs->ScalingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

// Picture of a 2D medial axis: the polygon (black), the graph's arcs (blue linear,
// orange parabolic), junctions (red), end points (green) and the maximal disks of
// the largest junctions (grey circles).
void Render2D(vtkPolyData* polygon, vtkPolyData* graph, const std::string& path, MessageSink& sink)
{
  double centre[3], normal[3];
  FitPlane(polygon, centre, normal);
  const double diag = polygon->GetLength();
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);

  vtkNew<vtkPolyData> outline;
  outline->SetPoints(polygon->GetPoints());
  vtkNew<vtkCellArray> edges;
  for (vtkCellArray* cells : { polygon->GetPolys(), polygon->GetLines() })
  {
    vtkIdType npts;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
    {
      std::vector<vtkIdType> loop(ids, ids + npts);
      if (cells == polygon->GetPolys())
      {
        loop.push_back(ids[0]);
      }
      edges->InsertNextCell(static_cast<vtkIdType>(loop.size()), loop.data());
    }
  }
  outline->SetLines(edges);
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputData(outline);
  outlineMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> outlineActor;
  outlineActor->SetMapper(outlineMapper);
  outlineActor->GetProperty()->SetColor(0.1, 0.1, 0.1);
  outlineActor->GetProperty()->SetLineWidth(3);
  renderer->AddActor(outlineActor);

  // Arcs coloured by ArcType through a two-entry table.
  vtkNew<vtkLookupTable> arcColours;
  arcColours->SetNumberOfTableValues(2);
  arcColours->SetTableValue(0, 0.15, 0.35, 0.85);
  arcColours->SetTableValue(1, 0.95, 0.55, 0.1);
  arcColours->SetTableRange(0, 1);
  arcColours->Build();
  vtkNew<vtkPolyDataMapper> arcMapper;
  arcMapper->SetInputData(graph);
  arcMapper->SetScalarModeToUseCellFieldData();
  arcMapper->SelectColorArray(vtkMedialArrayNames::ArcType);
  arcMapper->SetLookupTable(arcColours);
  arcMapper->SetScalarRange(0, 1);
  arcMapper->ScalarVisibilityOn();
  vtkNew<vtkActor> arcActor;
  arcActor->SetMapper(arcMapper);
  arcActor->GetProperty()->SetLineWidth(3);
  renderer->AddActor(arcActor);

  // Maximal disks of the (up to) six largest junctions.
  std::vector<std::pair<double, vtkIdType>> junctions;
  auto* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  auto* radius = graph->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  for (vtkIdType i = 0; types && i < graph->GetNumberOfPoints(); ++i)
  {
    if (static_cast<int>(types->GetTuple1(i)) == vtkMedialJunctionFilter::JUNCTION_POINT)
    {
      junctions.emplace_back(-radius->GetTuple1(i), i);
    }
  }
  std::sort(junctions.begin(), junctions.end());
  for (size_t k = 0; k < junctions.size() && k < 6; ++k)
  {
    vtkNew<vtkRegularPolygonSource> circle;
    circle->SetNumberOfSides(96);
    circle->GeneratePolygonOff();
    circle->SetRadius(-junctions[k].first);
    circle->SetCenter(graph->GetPoint(junctions[k].second));
    circle->SetNormal(normal);
    vtkNew<vtkPolyDataMapper> m;
    m->SetInputConnection(circle->GetOutputPort());
    vtkNew<vtkActor> a;
    a->SetMapper(m);
    a->GetProperty()->SetColor(0.55, 0.55, 0.6);
    a->GetProperty()->SetLineWidth(1.5);
    renderer->AddActor(a);
  }
  const double red[3] = { 0.85, 0.1, 0.1 }, green[3] = { 0.1, 0.65, 0.2 };
  renderer->AddActor(NodeActor(graph, vtkMedialJunctionFilter::JUNCTION_POINT, 0.012 * diag, red));
  renderer->AddActor(NodeActor(graph, vtkMedialJunctionFilter::END_POINT, 0.009 * diag, green));

  // Look straight at the plane.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + normal[0], centre[1] + normal[1], centre[2] + normal[2]);
  double up[3] = { 0, 1, 0 };
  if (std::abs(vtkMath::Dot(up, normal)) > 0.9)
  {
    up[0] = 1;
    up[1] = 0;
  }
  camera->SetViewUp(up);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(900, 700);
  window->AddRenderer(renderer);
  window->Render();
  WritePng(window, path, sink);
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", c);
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}
}

int main(int argc, char* argv[])
{
  const Options opt = Parse(argc, argv);
  std::signal(SIGINT, OnInterrupt);
  vtkNew<MessageSink> sinkWindow;
  vtkOutputWindow::SetInstance(sinkWindow);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the sink prints instead
  MessageSink& sink = *sinkWindow;

  if (!opt.Render.empty())
  {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
      Fail("--render needs an X display and none is set (DISPLAY is empty); run under "
           "xvfb-run, e.g. 'xvfb-run -a medial-axis ... --render out.png'");
    }
    CheckWritable(opt.Render, "--render");
  }
  if (!opt.Output.empty())
  {
    if (Extension(opt.Output) != ".vtp")
    {
      Fail("-o writes VTK XML polydata and needs a .vtp name, got '" + opt.Output + "'");
    }
    CheckWritable(opt.Output, "-o");
  }
  if (!opt.Reconstruct.empty())
  {
    CheckReconstructPath(opt.Reconstruct);
  }

  if (!opt.MedialMesh.empty())
  {
    CheckMedialMeshPath(opt.MedialMesh);
  }
  if (!opt.Junctions.empty())
  {
    if (Extension(opt.Junctions) != ".vtp")
    {
      Fail("--junctions writes VTK XML polydata and needs a .vtp name, got '" + opt.Junctions + "'");
    }
    CheckWritable(opt.Junctions, "--junctions");
  }

  vtkSmartPointer<vtkPolyData> surface;
  if (opt.Input.empty())
  {
    MakeDemo("demo:jack", surface);
  }
  else if (opt.Input.rfind("demo:", 0) == 0)
  {
    if (!MakeDemo(opt.Input, surface))
    {
      Fail("unknown demo '" + opt.Input + "' (demo:jack, demo:l-shape, demo:rectangle, demo:frame, demo:star)");
    }
  }
  else
  {
    surface = ReadSurface(opt.Input, sink);
  }
  const bool planar = IsPlanarInput(surface);
  if (!opt.MedialMesh.empty() && planar)
  {
    Fail("--medial-mesh needs a closed surface; '" + opt.Input + "' is planar (see --junctions)");
  }
  if (!opt.Junctions.empty() && !planar)
  {
    Fail("--junctions needs planar polygons or closed polylines; '" + opt.Input + "' is not planar");
  }
  vtkSmartPointer<vtkPolyData> graph;
  if (planar && (!opt.Junctions.empty() || !opt.Render.empty() || opt.Stats))
  {
    graph = RunJunctions(surface, opt.Threads, sink);
  }
  if (!opt.Junctions.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(graph);
    writer->SetFileName(opt.Junctions.c_str());
    writer->SetDataModeToBinary();
    if (!writer->Write() || !sink.LastError.empty())
    {
      Fail("cannot write '" + opt.Junctions + "': " + sink.LastError);
    }
  }

  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(static_cast<vtkIdType>(opt.Samples));
  sampler->SetMethod(opt.Method);
  sampler->SetSamplingStrategy(opt.Strategy);
  sampler->SetCoverageTolerance(opt.Coverage);
  sampler->SetRandomSeed(opt.Seed);
  sampler->SetNumberOfThreads(opt.Threads);
  sampler->SetTolerance(opt.Tolerance);
  sampler->SetMinimumSeparationAngle(opt.MinAngle);

  // Progress bar: only on a terminal, and only once a run has lasted a second.
  const auto start = std::chrono::steady_clock::now();
  struct Progress
  {
    std::chrono::steady_clock::time_point Start;
    bool Shown = false;
  } progress{ start };
  vtkNew<vtkCallbackCommand> progressCommand;
  if (isatty(STDERR_FILENO))
  {
    progressCommand->SetClientData(&progress);
    progressCommand->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
      auto* p = static_cast<Progress*>(client);
      const double fraction = *static_cast<double*>(data);
      const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - p->Start).count();
      if (elapsed < 1.0 && !p->Shown)
      {
        return;
      }
      p->Shown = true;
      const int width = 40, filled = static_cast<int>(fraction * width + 0.5);
      std::fprintf(stderr, "\r[%s%s] %3d%%  %.1fs", std::string(filled, '#').c_str(),
        std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100 + 0.5), elapsed);
      std::fflush(stderr);
    });
    sampler->AddObserver(vtkCommand::ProgressEvent, progressCommand);
  }

  // Ctrl-C while sampling: abort at the next block, then exit with 130 (OnInterrupt).
  vtkNew<vtkCallbackCommand> interruptCommand;
  interruptCommand->SetCallback([](vtkObject* caller, unsigned long, void*, void* data) {
    // The pipeline reports 0 before RequestData starts; blocks report more than 0.
    if (*static_cast<double*>(data) > 0.0)
    {
      AbortWatched = 1;
    }
    if (Interrupted)
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  sampler->AddObserver(vtkCommand::ProgressEvent, interruptCommand);

  sampler->Update();
  AbortWatched = 0;
  if (Interrupted)
  {
    std::cerr << (progress.Shown ? "\n" : "") << "medial-axis: interrupted\n";
    return 130;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress.Shown)
  {
    std::fprintf(stderr, "\n");
  }
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  vtkPolyData* medial = sampler->GetOutput();

  if (!opt.Output.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(medial);
    writer->SetFileName(opt.Output.c_str());
    writer->SetDataModeToBinary();
    if (!writer->Write() || !sink.LastError.empty())
    {
      Fail("cannot write '" + opt.Output + "': " + sink.LastError);
    }
  }
  vtkSmartPointer<vtkPolyData> medialMesh;
  double medialMeshSeconds = 0.0;
  if (!opt.MedialMesh.empty())
  {
    const auto meshStart = std::chrono::steady_clock::now();
    medialMesh = RunMedialMesh(surface, medial, opt.Threads, sink);
    medialMeshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - meshStart).count();
    WriteMedialMesh(medialMesh, opt.MedialMesh, sink);
  }
  vtkSmartPointer<vtkPolyData> reconstruction;
  double reconstructionSeconds = 0.0;
  if (!opt.Reconstruct.empty())
  {
    const auto reconstructStart = std::chrono::steady_clock::now();
    reconstruction = Reconstruct(medial, opt, sink);
    reconstructionSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - reconstructStart).count();
    WriteReconstruction(reconstruction, opt.Reconstruct, sink);
  }
  if (!opt.Render.empty())
  {
    if (planar)
    {
      Render2D(surface, graph, opt.Render, sink);
    }
    else
    {
      Render(surface, medial, opt.Render, sink, reconstruction, medialMesh);
    }
  }
  if (opt.Stats)
  {
    const int threads = opt.Threads > 0 ? opt.Threads : omp_get_num_procs();
    std::ostringstream js;
    js.precision(6);
    js << "{\"input\": " << JsonString(opt.Input.empty() ? "demo:jack" : opt.Input)
       << ", \"triangles\": " << sampler->GetNumberOfTriangles() << ", \"samples\": " << opt.Samples
       << ", \"medial_points\": " << medial->GetNumberOfPoints()
       << ", \"discarded\": " << sampler->GetDiscardedSamples() << ", \"method\": "
       << JsonString(vtkMedialAxisSampler::GetMethodName(opt.Method)) << ", \"threads\": " << threads
       << ", \"min_angle\": " << opt.MinAngle << ", \"tolerance\": " << opt.Tolerance
       << ", \"iterations_mean\": " << sampler->GetMeanIterations()
       << ", \"capped\": " << sampler->GetCappedSamples()
       << ", \"strategy\": "
       << JsonString(vtkMedialAxisSampler::GetSamplingStrategyName(planar ? vtkMedialAxisSampler::RANDOM : opt.Strategy));
    if (!planar && (opt.Strategy != vtkMedialAxisSampler::RANDOM || opt.Coverage > 0.0))
    {
      js << ", \"evaluated\": " << sampler->GetEvaluatedSamples() << ", \"seeds\": " << sampler->GetSeedSamples()
         << ", \"links\": " << medial->GetNumberOfLines() << ", \"coverage\": " << opt.Coverage
         << ", \"coverage_reached\": " << (sampler->GetCoverageReached() ? "true" : "false")
         << ", \"max_coverage_gap\": " << sampler->GetMaxCoverageGap();
    }
    js << ", \"seconds\": " << seconds
       << ReconstructionStats(surface, reconstruction, reconstructionSeconds, sampler, opt)
       << MedialMeshStats(medialMesh, medialMeshSeconds);
    if (graph)
    {
      vtkIdType junctions = 0, ends = 0;
      auto* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
      for (vtkIdType i = 0; i < graph->GetNumberOfPoints(); ++i)
      {
        const int t = static_cast<int>(types->GetTuple1(i));
        junctions += t == vtkMedialJunctionFilter::JUNCTION_POINT ? 1 : 0;
        ends += t == vtkMedialJunctionFilter::END_POINT ? 1 : 0;
      }
      js << ", \"junctions\": " << junctions << ", \"end_points\": " << ends
         << ", \"arcs\": " << graph->GetNumberOfLines();
    }
    js << "}";
    std::cout << js.str() << std::endl;
  }
  return 0;
}
