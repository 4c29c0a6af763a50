// SPDX-License-Identifier: BSD-3-Clause
// medial-axis: medial axis transform of a closed triangle mesh or of planar
// polygons, from the command line.
//
// Reads a mesh or polygon (or generates a demo shape), runs vtkMedialAxisSampler
// (and, for 2D input, vtkMedialJunctionFilter), and writes the medial balls, the
// medial graph, a picture and a JSON line of figures. Only wiring lives here;
// every algorithm is in a filter, every picture in vtkMedialScene.

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialMeshWriter.h"
#include "vtkMedialPruneFilter.h"
#include "vtkMedialSimplifyFilter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSTLWriter.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"

#include <omp.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const char* Usage =
  "usage: medial-axis [INPUT] [-n N] [--method bisection|shrinking-ball|one-pass] [--seed S]\n"
  "                   [--strategy random|closest-neighbor|face-distance] [--coverage E]\n"
  "                   [--threads T] [--tolerance E] [--min-angle DEG] [-o OUT.vtp]\n"
  "                   [--render OUT.png] [--stats] [--reconstruct OUT.vtp|.stl|.ply]\n"
  "                   [--resolution N] [--junctions OUT.vtp] [--medial-mesh OUT.vtp|OUT.ma]\n"
  "                   [--max-protrusion E] [--thickness OUT.vtp] [--thickness-below T]\n"
  "  INPUT        closed surface: .vtp .vtk .ply .stl .obj .off; or planar polygons / closed\n"
  "               polylines (any plane, holes allowed) for the 2D medial axis;\n"
  "               or a demo: demo:jack (3D, the default with no INPUT), demo:l-shape,\n"
  "               demo:rectangle, demo:frame (square with a square hole), demo:star,\n"
  "               demo:ellipse, demo:trefoil (2D)\n"
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
  "  --max-protrusion E  largest depth, relative to the bounding-box diagonal, by which a\n"
  "               ball may cross the surface; deeper, it is shrunk about its centre until\n"
  "               inscribed (default 1e-4; 1 = never: the angle rule alone, whose balls\n"
  "               cross the surface by up to about 2% of the diagonal)\n"
  "  -o OUT.vtp   write the medial balls (points with Radius, SurfacePoint, ...)\n"
  "  --render OUT.png  render the surface and the medial points offscreen (needs X; use xvfb-run)\n"
  "  --stats      print one JSON line of figures on stdout; 3D input adds protrusion_max_rel,\n"
  "               how far the balls cross the surface (relative to the diagonal)\n"
  "  --reconstruct OUT  write the boundary of the union of the medial balls (.vtp .stl .ply);\n"
  "               with --stats adds reconstruction_seconds and, for a closed input,\n"
  "               hausdorff_max_rel and hausdorff_mean_rel (vertex to surface, the larger\n"
  "               of the two directions, relative to the bounding-box diagonal);\n"
  "               with --render the reconstruction is drawn beside the input\n"
  "  --resolution N  grid points per axis of the reconstruction (default 128)\n"
  "  --junctions OUT.vtp  2D input only: write the medial graph (junctions, end points,\n"
  "               linear and parabolic arcs; point data Radius, MedialPointType,\n"
  "               GovernorCount; cell data ArcType). --render then draws it too.\n"
  "  --prune      remove the insignificant branches, keeping the topology: of the 2D graph\n"
  "               (--junctions, --render) or of the medial mesh (--medial-mesh); the\n"
  "               default measure (tubularity) and threshold; --stats adds pruned_branches\n"
  "  --prune-threshold X  --prune with this threshold instead (tubularity, in [0, 1])\n"
  "  --simplify K  3D, with --medial-mesh: simplify the medial mesh to exactly K balls\n"
  "               (Q-MAT's quadric error, edge collapses, topology kept); --reconstruct then\n"
  "               rebuilds from its envelope; --stats adds kept_balls and simplify_seconds\n"
  "  --medial-mesh OUT  3D input only: write the medial mesh (the balls joined by edges and\n"
  "               triangles, with the solid's topology) as .vtp (point data Radius,\n"
  "               MedialPointType, ...; cell data MedialCellType) or .ma (Q-MAT's form);\n"
  "               with --stats adds medial_vertices, medial_edges (triangle sides\n"
  "               included), medial_faces, seams and junctions (vertices of those\n"
  "               MedialPointTypes), euler_characteristic, components and\n"
  "               medial_mesh_seconds; --render then draws it coloured by MedialPointType\n"
  "  --thickness OUT.vtp  3D input: write the surface with its wall thickness (point and cell\n"
  "               data Thickness, MedialRadius, MedialCentre, RayThickness); --render then\n"
  "               draws the surface coloured by thickness; --stats adds thickness_min,\n"
  "               thickness_p01 and thickness_median\n"
  "  --thickness-below T  3D input: report the share of the area and the number of regions\n"
  "               thinner than T (in the input's units), e.g. a printer's minimum wall\n";

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
  bool Prune = false;
  double PruneThreshold = -1.0;
  long long Simplify = 0;
  bool Stats = false;
  std::string Reconstruct;
  int Resolution = 128;
  double MaxProtrusion = 1e-4;
  std::string Thickness;
  double ThicknessBelow = 0.0;
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

// --method NAME.
int ParseMethod(const std::string& name)
{
  for (int m : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    if (name == vtkMedialAxisSampler::GetMethodName(m))
    {
      return m;
    }
  }
  Fail("unknown --method '" + name + "' (bisection, shrinking-ball, one-pass)");
}

// --strategy NAME.
int ParseStrategy(const std::string& name)
{
  for (int k = vtkMedialAxisSampler::RANDOM; k <= vtkMedialAxisSampler::FACE_DISTANCE; ++k)
  {
    if (name == vtkMedialAxisSampler::GetSamplingStrategyName(k))
    {
      return k;
    }
  }
  Fail("unknown --strategy '" + name + "' (random, closest-neighbor, face-distance)");
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
      o.Method = ParseMethod(need(i));
    }
    else if (a == "--strategy")
    {
      o.Strategy = ParseStrategy(need(i));
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
    else if (a == "--junctions")
    {
      o.Junctions = need(i);
    }
    else if (a == "--medial-mesh")
    {
      o.MedialMesh = need(i);
    }
    else if (a == "--prune")
    {
      o.Prune = true;
    }
    else if (a == "--prune-threshold")
    {
      o.Prune = true;
      o.PruneThreshold = number(i, 0, 1);
    }
    else if (a == "--simplify")
    {
      o.Simplify = static_cast<long long>(integer(i, 1, 1e9));
    }
    else if (a == "--resolution")
    {
      o.Resolution = static_cast<int>(integer(i, 8, 2048));
    }
    else if (a == "--max-protrusion")
    {
      o.MaxProtrusion = number(i, 0, 1);
    }
    else if (a == "--thickness")
    {
      o.Thickness = need(i);
    }
    else if (a == "--thickness-below")
    {
      o.ThicknessBelow = number(i, 0, 1e300);
      if (!(o.ThicknessBelow > 0.0))
      {
        Fail("--thickness-below expects a thickness above 0");
      }
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
  return vtkMedialFileReader::GetExtension(path.c_str());
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
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!sink.LastError.empty())
  {
    Fail("cannot read '" + path + "': " + sink.LastError);
  }
  vtkPolyData* data = reader->GetOutput();
  if (data->GetNumberOfPoints() == 0)
  {
    Fail("cannot read '" + path + "': no points (empty or not a " + Extension(path) + " file)");
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

// Updates `filter`, fails with the first error reported, and keeps a copy of output 0.
vtkSmartPointer<vtkPolyData> Run(vtkPolyDataAlgorithm* filter, MessageSink& sink)
{
  filter->Update();
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(filter->GetOutput());
  return result;
}

// Union of the medial balls (or, with `envelope`, the interpolated envelope of the medial
// mesh), written to `path` by its extension.
vtkSmartPointer<vtkPolyData> Reconstruct(vtkPolyData* medial, const Options& opt, MessageSink& sink, bool envelope)
{
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(medial);
  if (envelope)
  {
    ballUnion->SetPrimitives(vtkMedialBallUnion::MEDIAL_MESH);
  }
  ballUnion->SetSampleDimensions(opt.Resolution, opt.Resolution, opt.Resolution);
  ballUnion->SetNumberOfThreads(opt.Threads);
  return Run(ballUnion, sink);
}

// Writes binary VTK XML polydata; fails with the writer's reason.
void WriteVtp(vtkPolyData* data, const std::string& path, MessageSink& sink)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToBinary();
  if (!writer->Write() || !sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// The reconstruction, written by the extension of `path` (.stl, .ply or .vtp).
void WriteReconstruction(vtkPolyData* reconstruction, const std::string& path, MessageSink& sink)
{
  const std::string ext = Extension(path);
  if (ext != ".stl" && ext != ".ply")
  {
    WriteVtp(reconstruction, path, sink);
    return;
  }
  int written = 0;
  if (ext == ".stl")
  {
    vtkNew<vtkSTLWriter> w;
    w->SetInputData(reconstruction);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    written = w->Write();
  }
  else
  {
    vtkNew<vtkPLYWriter> w;
    w->SetInputData(reconstruction);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    written = w->Write();
  }
  if (!written || !sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// JSON members for --reconstruct; the error figures only for a closed input.
std::string ReconstructionStats(vtkPolyData* surface, vtkPolyData* reconstruction, double seconds,
  vtkMedialAxisSampler* sampler, const Options& opt, MessageSink& sink)
{
  if (!reconstruction)
  {
    return "";
  }
  std::ostringstream js;
  js.precision(6);
  js << ", \"reconstruction_seconds\": " << seconds << ", \"resolution\": " << opt.Resolution;
  if (sampler->GetBoundaryEdges() == 0 && reconstruction->GetNumberOfCells() > 0)
  {
    vtkNew<vtkMedialReconstructionError> error;
    error->SetOriginalData(surface);
    error->SetReconstructionData(reconstruction);
    error->SetNumberOfThreads(opt.Threads);
    error->Update();
    if (!sink.LastError.empty())
    {
      Fail(sink.LastError);
    }
    js << ", \"hausdorff_max_rel\": " << error->GetVertexHausdorff()
       << ", \"hausdorff_mean_rel\": " << error->GetVertexMeanHausdorff()
       << ", \"hausdorff_area_max_rel\": " << error->GetAreaHausdorff()
       << ", \"hausdorff_area_mean_rel\": " << error->GetAreaMeanHausdorff();
  }
  return js.str();
}

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
  else if (name == "demo:ellipse")
  {
    demo->SetShapeToEllipse(); // 256 vertices: a smooth curve, for --prune
  }
  else if (name == "demo:trefoil")
  {
    demo->SetShapeToTrefoil(); // a rounded 3-armed star, 256 vertices, for --prune
  }
  else
  {
    return false;
  }
  demo->Update();
  out = demo->GetOutput();
  return true;
}

vtkSmartPointer<vtkPolyData> RunJunctions(vtkPolyData* polygon, int threads, MessageSink& sink)
{
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(polygon);
  junctions->SetNumberOfThreads(threads);
  return Run(junctions, sink);
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

// Fails unless `path` is a writable .vtp name.
void CheckVtpPath(const std::string& path, const char* flag)
{
  if (Extension(path) != ".vtp")
  {
    Fail(std::string(flag) + " writes VTK XML polydata and needs a .vtp name, got '" + path + "'");
  }
  CheckWritable(path, flag);
}

// Fails before any work when an output cannot be written or rendered.
void CheckOutputs(const Options& opt)
{
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
    CheckVtpPath(opt.Output, "-o");
  }
  if (!opt.Reconstruct.empty())
  {
    CheckReconstructPath(opt.Reconstruct);
  }
  if (!opt.Junctions.empty())
  {
    CheckVtpPath(opt.Junctions, "--junctions");
  }
  if (!opt.MedialMesh.empty())
  {
    if (Extension(opt.MedialMesh) != ".vtp" && Extension(opt.MedialMesh) != ".ma")
    {
      Fail("--medial-mesh writes .vtp or .ma (Q-MAT's form), got '" + opt.MedialMesh + "'");
    }
    CheckWritable(opt.MedialMesh, "--medial-mesh");
  }
  if (!opt.Thickness.empty())
  {
    CheckVtpPath(opt.Thickness, "--thickness");
  }
}

// The input surface: a demo shape (none given: demo:jack) or a file.
vtkSmartPointer<vtkPolyData> LoadInput(const Options& opt, MessageSink& sink)
{
  vtkSmartPointer<vtkPolyData> surface;
  if (opt.Input.empty())
  {
    MakeDemo("demo:jack", surface);
  }
  else if (opt.Input.rfind("demo:", 0) == 0)
  {
    if (!MakeDemo(opt.Input, surface))
    {
      Fail("unknown demo '" + opt.Input + "' (demo:jack, demo:l-shape, demo:rectangle, demo:frame, demo:star, demo:ellipse, demo:trefoil)");
    }
  }
  else
  {
    surface = ReadSurface(opt.Input, sink);
  }
  return surface;
}

// Progress bar on stderr: only on a terminal, and only once a run has lasted a second.
struct Progress
{
  std::chrono::steady_clock::time_point Start;
  bool Shown = false;

  static void Show(vtkObject*, unsigned long, void* client, void* data)
  {
    auto* p = static_cast<Progress*>(client);
    const double fraction = *static_cast<double*>(data);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - p->Start).count();
    if (elapsed < 1.0 && !p->Shown)
    {
      return;
    }
    p->Shown = true;
    const int width = 40, filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%  %.1fs", std::string(filled, '#').c_str(),
      std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100 + 0.5), elapsed);
    std::fflush(stderr);
  }
};

// Ctrl-C while sampling: abort at the next block, then exit with 130 (OnInterrupt).
void AbortOnInterrupt(vtkObject* caller, unsigned long, void*, void* data)
{
  // The pipeline reports 0 before RequestData starts; blocks report more than 0.
  if (*static_cast<double*>(data) > 0.0)
  {
    AbortWatched = 1;
  }
  if (Interrupted)
  {
    static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
  }
}

// Runs the sampler on `surface` with the command line's settings; `seconds` is its wall time.
vtkSmartPointer<vtkMedialAxisSampler> Sample(vtkPolyData* surface, const Options& opt, MessageSink& sink, double& seconds)
{
  auto sampler = vtkSmartPointer<vtkMedialAxisSampler>::New();
  sampler->SetInputData(surface);
  sampler->SetNumberOfSamples(static_cast<vtkIdType>(opt.Samples));
  sampler->SetMethod(opt.Method);
  sampler->SetSamplingStrategy(opt.Strategy);
  sampler->SetCoverageTolerance(opt.Coverage);
  sampler->SetRandomSeed(opt.Seed);
  sampler->SetNumberOfThreads(opt.Threads);
  sampler->SetTolerance(opt.Tolerance);
  sampler->SetMinimumSeparationAngle(opt.MinAngle);
  sampler->SetMaximumProtrusion(opt.MaxProtrusion);

  const auto start = std::chrono::steady_clock::now();
  Progress progress{ start };
  vtkNew<vtkCallbackCommand> progressCommand;
  if (isatty(STDERR_FILENO))
  {
    progressCommand->SetClientData(&progress);
    progressCommand->SetCallback(&Progress::Show);
    sampler->AddObserver(vtkCommand::ProgressEvent, progressCommand);
  }
  vtkNew<vtkCallbackCommand> interruptCommand;
  interruptCommand->SetCallback(&AbortOnInterrupt);
  sampler->AddObserver(vtkCommand::ProgressEvent, interruptCommand);

  sampler->Update();
  AbortWatched = 0;
  if (Interrupted)
  {
    std::cerr << (progress.Shown ? "\n" : "") << "medial-axis: interrupted\n";
    std::exit(130);
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress.Shown)
  {
    std::fprintf(stderr, "\n");
  }
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  sampler->RemoveAllObservers(); // the progress state lives on this stack
  return sampler;
}

// --prune: the graph or medial mesh pruned with the default measure (or --prune-threshold).
vtkSmartPointer<vtkPolyData> RunPrune(vtkPolyData* axis, const Options& opt, MessageSink& sink, long long& pruned)
{
  vtkNew<vtkMedialPruneFilter> prune;
  prune->SetInputData(axis);
  prune->SetThreshold(opt.PruneThreshold);
  vtkSmartPointer<vtkPolyData> result = Run(prune, sink);
  pruned = prune->GetNumberOfPrunedBranches();
  return result;
}

// Figures of --prune and --simplify for --stats.
struct Reduction
{
  long long PrunedBranches = -1;
  double SimplifySeconds = -1.0;
};

// --medial-mesh: the medial mesh of the sampled balls (given on port 1, so the sampling
// is not repeated), pruned (--prune) and simplified (--simplify K), written as .vtp or .ma.
vtkSmartPointer<vtkPolyData> RunMedialMesh(vtkPolyData* surface, vtkPolyData* balls, const Options& opt,
  MessageSink& sink, Reduction& reduction)
{
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(surface);
  filter->SetBallsData(balls);
  filter->SetNumberOfThreads(opt.Threads);
  filter->GetClassifier()->SetMinimumSeparationAngle(opt.MinAngle); // the balls' theta
  vtkSmartPointer<vtkPolyData> mesh = Run(filter, sink);
  if (opt.Prune)
  {
    long long pruned = 0;
    mesh = RunPrune(mesh, opt, sink, pruned);
    reduction.PrunedBranches = pruned;
  }
  if (opt.Simplify > 0)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkNew<vtkMedialSimplifyFilter> simplify;
    simplify->SetInputData(mesh);
    simplify->SetNumberOfBalls(opt.Simplify);
    mesh = Run(simplify, sink);
    reduction.SimplifySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (Extension(opt.MedialMesh) == ".ma")
  {
    vtkNew<vtkMedialMeshWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(opt.MedialMesh.c_str());
    if (!writer->Write() || !sink.LastError.empty())
    {
      Fail("cannot write '" + opt.MedialMesh + "': " + sink.LastError);
    }
  }
  else
  {
    WriteVtp(mesh, opt.MedialMesh, sink);
  }
  return mesh;
}

// JSON members of the medial mesh: sizes, point types, topology and time.
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
    perType[std::min(3, std::max(0, static_cast<int>(types->GetTuple1(i))))]++;
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
     << ", \"medial_faces\": " << faces << ", \"seams\": " << perType[2] << ", \"junctions\": " << perType[3]
     << ", \"euler_characteristic\": " << euler
     << ", \"components\": " << field(vtkMedialArrayNames::Components) << ", \"medial_mesh_seconds\": " << seconds;
  return js.str();
}

// --render: the 2D graph scene for planar input, the surface coloured by thickness
// with --thickness, else the 3D scene (with the reconstruction beside it when there is
// one, and the medial mesh coloured by point type instead of the balls when there is one).
void RenderPicture(vtkPolyData* surface, vtkPolyData* medial, vtkPolyData* graph, vtkPolyData* reconstruction,
  vtkPolyData* medialMesh, vtkPolyData* thickness, const std::string& path, MessageSink& sink)
{
  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(surface);
  if (graph)
  {
    scene->SetGraph(graph);
  }
  else if (thickness)
  {
    scene->SetSurface(thickness);
    scene->SetSurfaceScalars(vtkMedialArrayNames::Thickness);
  }
  else
  {
    scene->SetMedial(medialMesh ? medialMesh : medial);
    scene->SetColorBy(medialMesh ? vtkMedialScene::POINT_TYPE : vtkMedialScene::RADIUS);
    scene->SetReconstruction(reconstruction);
  }
  if (!scene->WritePNG(path.c_str()) || !sink.LastError.empty())
  {
    Fail("cannot write '" + path + "': " + sink.LastError);
  }
}

// JSON members of the sampler's run (the line's opening brace included).
std::string SamplerStats(
  const Options& opt, vtkMedialAxisSampler* sampler, vtkPolyData* medial, bool planar, double seconds)
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
  js << ", \"seconds\": " << seconds;
  return js.str();
}

// vtkMedialThickness with the sampler's angle and protrusion settings.
vtkSmartPointer<vtkPolyData> MeasureThickness(vtkPolyData* surface, const Options& opt, MessageSink& sink)
{
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputData(surface);
  thickness->SetMinimumSeparationAngle(opt.MinAngle);
  thickness->SetMaximumProtrusion(opt.MaxProtrusion);
  thickness->SetThinThreshold(opt.ThicknessBelow);
  thickness->SetNumberOfThreads(opt.Threads);
  return Run(thickness, sink);
}

// JSON members for --thickness and --thickness-below (or, without --stats, a line for
// --thickness-below): percentiles of the point Thickness (NaN left out), the thin share
// of the area and its regions.
std::string ThicknessReport(vtkPolyData* thickness, const Options& opt)
{
  std::vector<double> values;
  vtkDataArray* t = thickness->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
  for (vtkIdType i = 0; t && i < t->GetNumberOfTuples(); ++i)
  {
    if (!std::isnan(t->GetComponent(i, 0)))
    {
      values.push_back(t->GetComponent(i, 0));
    }
  }
  std::sort(values.begin(), values.end());
  auto quantile = [&](double q) {
    return values.empty() ? std::nan("") : values[static_cast<size_t>(q * (values.size() - 1))];
  };
  auto field = [&](const char* name) {
    vtkDataArray* a = thickness->GetFieldData()->GetArray(name);
    return a ? a->GetComponent(0, 0) : 0.0;
  };
  const double share = field(vtkMedialArrayNames::ThinAreaFraction);
  const double regions = field(vtkMedialArrayNames::ThinRegionCount);
  std::ostringstream out;
  out.precision(6);
  if (!opt.Stats)
  {
    out << "thinner than " << opt.ThicknessBelow << ": " << 100.0 * share << "% of the area, in " << regions
        << (regions == 1 ? " region" : " regions");
    return out.str();
  }
  out << ", \"thickness_min\": " << quantile(0.0) << ", \"thickness_p01\": " << quantile(0.01)
      << ", \"thickness_median\": " << quantile(0.5);
  if (opt.ThicknessBelow > 0.0)
  {
    out << ", \"thickness_below\": " << opt.ThicknessBelow << ", \"thin_area_fraction\": " << share
        << ", \"thin_regions\": " << regions;
  }
  return out.str();
}

// JSON members of the balls' protrusion through the surface (vtkMedialBallProtrusion).
std::string ProtrusionStats(vtkPolyData* surface, vtkPolyData* medial, const Options& opt, MessageSink& sink)
{
  vtkNew<vtkMedialBallProtrusion> protrusion;
  protrusion->SetSurfaceData(surface);
  protrusion->SetBallsData(medial);
  protrusion->SetNumberOfThreads(opt.Threads);
  protrusion->Update();
  if (!sink.LastError.empty())
  {
    Fail(sink.LastError);
  }
  std::ostringstream js;
  js.precision(6);
  js << ", \"max_protrusion\": " << opt.MaxProtrusion << ", \"protrusion_max_rel\": " << protrusion->GetMaxProtrusion();
  return js.str();
}

// JSON members of the 2D medial graph.
// JSON members of --prune and --simplify.
std::string ReductionStats(const Reduction& reduction, vtkPolyData* medialMesh)
{
  std::ostringstream js;
  if (reduction.PrunedBranches >= 0)
  {
    js << ", \"pruned_branches\": " << reduction.PrunedBranches;
  }
  if (medialMesh && (reduction.PrunedBranches >= 0 || reduction.SimplifySeconds >= 0.0))
  {
    js << ", \"kept_balls\": " << (medialMesh ? medialMesh->GetNumberOfPoints() : 0);
  }
  if (reduction.SimplifySeconds >= 0.0)
  {
    js << ", \"simplify_seconds\": " << reduction.SimplifySeconds;
  }
  return js.str();
}

std::string GraphStats(vtkPolyData* graph)
{
  vtkIdType junctions = 0, ends = 0;
  vtkDataArray* types = graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  for (vtkIdType i = 0; i < graph->GetNumberOfPoints(); ++i)
  {
    const int t = static_cast<int>(types->GetTuple1(i));
    junctions += t == vtkMedialJunctionFilter::JUNCTION_POINT ? 1 : 0;
    ends += t == vtkMedialJunctionFilter::END_POINT ? 1 : 0;
  }
  std::ostringstream js;
  js << ", \"junctions\": " << junctions << ", \"end_points\": " << ends << ", \"arcs\": " << graph->GetNumberOfLines();
  return js.str();
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
  CheckOutputs(opt);

  vtkSmartPointer<vtkPolyData> surface = LoadInput(opt, sink);
  const bool planar = vtkMedialAxisSampler::IsPlanarInput(surface);
  if (!opt.MedialMesh.empty() && planar)
  {
    Fail("--medial-mesh needs a closed surface; '" + opt.Input + "' is planar (see --junctions)");
  }
  if (opt.Simplify > 0 && (planar || opt.MedialMesh.empty()))
  {
    Fail("--simplify K simplifies the medial mesh of a closed surface: give --medial-mesh OUT.ma|.vtp");
  }
  if (!opt.Junctions.empty() && !planar)
  {
    Fail("--junctions needs planar polygons or closed polylines; '" + opt.Input + "' is not planar");
  }
  const bool wantThickness = !opt.Thickness.empty() || opt.ThicknessBelow > 0.0;
  if (wantThickness && planar)
  {
    Fail("--thickness and --thickness-below need a 3D surface; '" + opt.Input + "' is planar");
  }
  vtkSmartPointer<vtkPolyData> graph;
  if (planar && (!opt.Junctions.empty() || !opt.Render.empty() || opt.Stats))
  {
    graph = RunJunctions(surface, opt.Threads, sink);
  }
  Reduction reduction;
  if (graph && opt.Prune)
  {
    long long pruned = 0;
    graph = RunPrune(graph, opt, sink, pruned);
    reduction.PrunedBranches = pruned;
  }
  if (!opt.Junctions.empty())
  {
    WriteVtp(graph, opt.Junctions, sink);
  }

  double seconds = 0.0;
  vtkSmartPointer<vtkMedialAxisSampler> sampler = Sample(surface, opt, sink, seconds);
  vtkPolyData* medial = sampler->GetOutput();
  if (!opt.Output.empty())
  {
    WriteVtp(medial, opt.Output, sink);
  }
  vtkSmartPointer<vtkPolyData> medialMesh;
  double medialMeshSeconds = 0.0;
  if (!opt.MedialMesh.empty())
  {
    const auto start = std::chrono::steady_clock::now();
    medialMesh = RunMedialMesh(surface, medial, opt, sink, reduction);
    medialMeshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  vtkSmartPointer<vtkPolyData> reconstruction;
  double reconstructionSeconds = 0.0;
  if (!opt.Reconstruct.empty())
  {
    const auto start = std::chrono::steady_clock::now();
    // A pruned or simplified medial mesh is rebuilt from its envelope; else the balls' union.
    const bool envelope = medialMesh && (opt.Prune || opt.Simplify > 0);
    reconstruction = Reconstruct(envelope ? medialMesh.Get() : medial, opt, sink, envelope);
    reconstructionSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    WriteReconstruction(reconstruction, opt.Reconstruct, sink);
  }
  vtkSmartPointer<vtkPolyData> thickness;
  if (wantThickness)
  {
    thickness = MeasureThickness(surface, opt, sink);
    if (!opt.Thickness.empty())
    {
      WriteVtp(thickness, opt.Thickness, sink);
    }
    if (opt.ThicknessBelow > 0.0 && !opt.Stats)
    {
      std::cout << ThicknessReport(thickness, opt) << std::endl;
    }
  }
  if (!opt.Render.empty())
  {
    RenderPicture(
      surface, medial, planar ? graph.Get() : nullptr, reconstruction, medialMesh, thickness, opt.Render, sink);
  }
  if (opt.Stats)
  {
    std::cout << SamplerStats(opt, sampler, medial, planar, seconds)
              << (planar ? std::string() : ProtrusionStats(surface, medial, opt, sink))
              << ReconstructionStats(surface, reconstruction, reconstructionSeconds, sampler, opt, sink)
              << MedialMeshStats(medialMesh, medialMeshSeconds) << (graph ? GraphStats(graph) : std::string())
              << (thickness ? ThicknessReport(thickness, opt) : std::string()) << ReductionStats(reduction, medialMesh)
              << "}" << std::endl;
  }
  return 0;
}
