// SPDX-License-Identifier: BSD-3-Clause
#include "MedialAxisOptions.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialFileWriter.h"
#include "vtkMedialHTMLWriter.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialScene.h"
#include "vtkMedialSimplifyFilter.h"

#include "vtkVersion.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#ifndef MEDIALAXIS_VERSION
#define MEDIALAXIS_VERSION "unknown"
#endif

namespace medialaxis
{
namespace
{
const char* Usage =
  "usage: medial-axis [INPUT] [options]           (--flag value and --flag=value alike)\n"
  "  INPUT             closed surface (.vtp .vtk .ply .stl .obj .off) or planar polygons /\n"
  "                    closed polylines (any plane; holes, several outer boundaries, islands)\n"
  "                    for the 2D medial axis; or a demo: demo:jack (3D, the default with no\n"
  "                    INPUT and no --balls), demo:l-shape, demo:rectangle, demo:frame, demo:star,\n"
  "                    demo:ellipse, demo:trefoil\n"
  "Sampling:\n"
  "  -n, --samples N   surface samples (default 10000; 10k, 1M accepted)\n"
  "  --method M        one-pass (default, fastest), bisection (the report's) or shrinking-ball\n"
  "  --strategy S      where the samples go (3D): random (default), closest-neighbor\n"
  "                    (Poisson-disk seeds linked to their closest non-overlapping neighbour,\n"
  "                    links split until the balls overlap, then face-distance rounds for a\n"
  "                    sixteenth more samples; -o then holds the links as lines) or\n"
  "                    face-distance (Poisson-disk seeds, then round by round the faces\n"
  "                    farthest from the union of balls)\n"
  "  --coverage E      stop once every face's vertices and centroid are within E (relative to\n"
  "                    the diagonal) of the union of balls, or at -n samples (default 0: off);\n"
  "                    -n is then only a cap (a larger one that is not reached changes nothing)\n"
  "  --seed S          random seed (default 1); output is identical for any thread count\n"
  "  --threads T       OpenMP threads, 0 = all cores (default 0)\n"
  "  --tolerance E     bisection tolerance relative to the diagonal (default 1e-6)\n"
  "  --min-angle DEG   minimum separation angle theta (default 45; 0 = exact medial axis of\n"
  "                    the polyhedron)\n"
  "  --max-protrusion E  largest depth, relative to the diagonal, by which a ball may cross\n"
  "                    the surface; deeper, it is shrunk about its centre until inscribed\n"
  "                    (default 1e-4; 1 = never: the angle rule alone, whose balls cross the\n"
  "                    surface by up to about 2% of the diagonal)\n"
  "  --balls IN        read medial balls instead of sampling: .ma (Q-MAT, MATFP, Coverage\n"
  "                    Axis, ours), .ply with a per-vertex radius, .vtp, .vtk, .csv; INPUT is\n"
  "                    then optional (the surface to draw and to measure against)\n"
  "Repair (3D input; docs/repair.md):\n"
  "  --repair M        auto (default): a surface that is not a valid solid (open, non-\n"
  "                    manifold, self-intersecting, overlapping shells, stray sheets,\n"
  "                    an unwelded soup) is repaired before anything else sees it, one\n"
  "                    warning per step; a valid solid is used as it is (the same bytes\n"
  "                    out as with none). none: used as it is, with warnings. wrap: the\n"
  "                    alpha wrap of the input (any soup: a closed, manifold solid,\n"
  "                    offset outwards by --wrap-offset). --stats adds repair_* members\n"
  "                    when the surface was repaired\n"
  "  --weld-tolerance E  points closer than E (relative to the diagonal) are welded\n"
  "                    when the surface is open (default 1e-6)\n"
  "  --max-hole-size E holes up to E across (relative to the diagonal) are filled,\n"
  "                    larger ones wrapped (default 0.25)\n"
  "  --wrap-alpha E    the alpha wrap's alpha (no feature narrower than it is\n"
  "                    followed), relative to the diagonal (default 0.02)\n"
  "  --wrap-offset E   the alpha wrap's distance from the input, relative to the\n"
  "                    diagonal (default 0.001)\n"
  "Outputs (checked before any work; the extension chooses the format):\n"
  "  -o, --output OUT  the medial balls: .vtp .vtk .ply (radius property) .ma .csv\n"
  "  --reconstruct OUT the surface of the union of the balls: .vtp .vtk .stl .ply .obj;\n"
  "                    with --stats adds reconstruction_seconds and, against a closed input,\n"
  "                    hausdorff_max_rel, hausdorff_mean_rel (vertices) and\n"
  "                    hausdorff_area_max_rel, hausdorff_area_mean_rel (area samples),\n"
  "                    relative to the diagonal; with --render drawn beside the input\n"
  "  --resolution N    grid points per axis of the reconstruction (default 128)\n"
  "  --junctions OUT   2D input: the medial graph (junctions, end points, linear and\n"
  "                    parabolic arcs; Radius, MedialPointType, GovernorCount; cell data\n"
  "                    ArcType, PolygonId): .vtp .vtk .ply .ma .csv; --render then draws it\n"
  "  --medial-mesh OUT 3D input: the medial mesh (the balls joined by edges and triangles;\n"
  "                    point data Radius, MedialPointType, GovernorCount; cell data\n"
  "                    MedialCellType): .vtp .vtk .ply .ma (Q-MAT's form) .csv; --stats adds\n"
  "                    medial_vertices, medial_edges, medial_faces, seams, junctions,\n"
  "                    euler_characteristic, components and medial_mesh_seconds; --render\n"
  "                    then draws it coloured by MedialPointType\n"
  "  --denoise         3D input with noise (scans): smooth the surface before anything else\n"
  "                    (vtkMedialDenoiseFilter: a windowed sinc low-pass, 20 iterations,\n"
  "                    pass band 0.03); every later step sees the smoothed surface (with\n"
  "                    --stats, the reconstruction error too), and --prune's default scale\n"
  "                    becomes 1.3. Rounds sharp edges: not for clean CAD meshes. --stats\n"
  "                    adds denoise_max_move (largest vertex move / diagonal), denoise_seconds\n"
  "  --denoise-iterations N, --denoise-passband X  --denoise with N iterations (1 to 1000,\n"
  "                    default 20) or pass band X (0.001 to 2, default 0.03; lower\n"
  "                    smooths more)\n"
  "  --prune           2D: remove the insignificant branches of the graph (--junctions,\n"
  "                    --render), keeping the topology (tubularity at 0.05). 3D: the scale\n"
  "                    axis transform: balls that another ball covers once all are scaled\n"
  "                    by 1.5 (1.3 with --denoise) go before they are written, measured or\n"
  "                    meshed, then the medial mesh's branches by the same measure;\n"
  "                    --stats adds pruned_branches (mesh or graph), pruned_balls (3D) and\n"
  "                    kept_balls\n"
  "  --prune-threshold X  --prune with this threshold in [0, 1]: 2D tubularity; 3D the\n"
  "                    scale axis significance 1 - 1/s (default 1/3, s = 1.5; with --denoise\n"
  "                    0.2308, s = 1.3)\n"
  "  --simplify K      with --medial-mesh: the medial mesh simplified to exactly K balls\n"
  "                    (Q-MAT's quadric error with planes that hold creases, edge collapses,\n"
  "                    topology kept); --reconstruct then rebuilds its envelope; --stats\n"
  "                    adds kept_balls, simplify_seconds\n"
  "  --simplify-method M  quadric (default: Q-MAT's edge collapses) or coverage (the K\n"
  "                    balls that cover the surface best, Coverage Axis, joined by collapses)\n"
  "  --simplify-tolerance X  quadric: collapses that would leave a surface vertex farther\n"
  "                    than X (relative to the diagonal) from the envelope go last, least\n"
  "                    distance first (default 0.0075; 0: Q-MAT's order alone)\n"
  "  --thickness OUT   3D input: the surface with its wall thickness (point and cell data\n"
  "                    Thickness, MedialRadius, MedialCentre, TangentThickness,\n"
  "                    RayThickness): .vtp .vtk;\n"
  "                    --render then draws the surface coloured by thickness; --stats adds\n"
  "                    thickness_min, thickness_p01 and thickness_median\n"
  "  --thickness-below T  3D input: the share of the area and the number of regions thinner\n"
  "                    than T (in the input's units), e.g. a printer's minimum wall; a line\n"
  "                    on stdout, or members of the --stats line\n"
  "  --render OUT.png  a picture, offscreen (needs X: run under xvfb-run)\n"
  "  --html OUT.html   one self-contained web page of everything this run made (the\n"
  "                    surface, balls, medial mesh or 2D graph, thickness, reconstruction),\n"
  "                    to turn around, filter and pick in any current browser, offline\n"
  "                    (vtk.js, bundled at build time; more than 100k balls are thinned);\n"
  "                    --stats adds html_bytes, html_balls_shown\n"
  "  --view V          --render's and --html's view: auto (default: the longest extent\n"
  "                    across, the second up), +x -x +y\n"
  "                    -y +z -z (look along that axis), iso\n"
  "  --size WxH        picture size in pixels (default 900x640, 900x700 in 2D, twice as wide\n"
  "                    with --reconstruct)\n"
  "  --zoom Z          zoom after framing the whole model (default 1)\n"
  "  --stats           one JSON line of figures on stdout; 3D input adds protrusion_max_rel,\n"
  "                    how far the balls cross the surface (relative to the diagonal)\n"
  "Messages:\n"
  "  --quiet           no progress (warnings and errors are still printed)\n"
  "  --version         the program's version\n"
  "  -h, --help        this text\n"
  "Progress goes to stderr: a bar per stage on a terminal, one line per finished stage\n"
  "otherwise. A run without an output and without --stats is refused.\n";

[[noreturn]] void Exit(const std::string& text)
{
  std::cout << text;
  std::exit(0);
}

bool ParseNumber(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
}

// A whole number with an optional suffix k, M or G (and exponents: 1e6).
bool ParseCount(std::string text, double& value)
{
  double scale = 1.0;
  if (!text.empty())
  {
    switch (text.back())
    {
      case 'k':
      case 'K':
        scale = 1e3;
        break;
      case 'M':
        scale = 1e6;
        break;
      case 'G':
        scale = 1e9;
        break;
      default:
        break;
    }
    if (scale > 1.0)
    {
      text.pop_back();
    }
  }
  if (!ParseNumber(text, value))
  {
    return false;
  }
  value = std::round(value * scale * 1e6) / 1e6; // 1.5k is 1500 exactly
  return value == std::floor(value);
}

std::string Range(double lo, double hi)
{
  std::ostringstream os;
  os << "[" << lo << ", " << hi << "]";
  return os.str();
}

// What a flag takes and what it does with it. docs/cli.md has one row per flag, in this
// order, with the same range and default (the docs-cli-flags test compares them through
// --help-table).
struct Flag
{
  const char* Long;
  const char* Short; // or nullptr
  enum Kinds
  {
    SWITCH,
    TEXT,
    COUNT,
    NUMBER
  } Kind;
  double Lo, Hi; // COUNT and NUMBER: the accepted range (Hi 1e300: no upper bound)
  std::function<void(Options&, const std::string& text, double value)> Apply;
  const char* Default = nullptr; // the default as --help and docs/cli.md spell it, if one
};

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

int ParseSimplifyMethod(const std::string& name)
{
  for (int m = vtkMedialSimplifyFilter::QUADRIC; m <= vtkMedialSimplifyFilter::COVERAGE; ++m)
  {
    if (name == vtkMedialSimplifyFilter::GetMethodName(m))
    {
      return m;
    }
  }
  Fail("unknown --simplify-method '" + name + "' (quadric, coverage)");
}

int ParseRepair(const std::string& name)
{
  const int mode = vtkMedialRepairFilter::GetModeFromName(name.c_str());
  if (mode < 0)
  {
    Fail("unknown --repair '" + name + "' (auto, none, wrap)");
  }
  return mode;
}

int ParseView(const std::string& name)
{
  const int view = vtkMedialScene::GetViewDirectionFromName(name.c_str());
  if (view < 0)
  {
    Fail("unknown --view '" + name + "' (auto, +x, -x, +y, -y, +z, -z, iso)");
  }
  return view;
}

void ParseSize(const std::string& text, int size[2])
{
  const size_t x = text.find_first_of("xX");
  double w = 0, h = 0;
  if (x == std::string::npos || !ParseCount(text.substr(0, x), w) || !ParseCount(text.substr(x + 1), h) ||
    w < 16 || h < 16 || w > 16384 || h > 16384)
  {
    Fail("--size expects WIDTHxHEIGHT in pixels, each in [16, 16384], got '" + text + "'");
  }
  size[0] = static_cast<int>(w);
  size[1] = static_cast<int>(h);
}

const std::vector<Flag>& Flags()
{
  using F = Flag;
  static const std::vector<Flag> flags = {
    { "samples", "n", F::COUNT, 1, 1e15, [](Options& o, auto&, double v) { o.Samples = static_cast<long long>(v); }, "10000" },
    { "method", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Method = ParseMethod(t); }, "one-pass" },
    { "strategy", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Strategy = ParseStrategy(t); }, "random" },
    { "coverage", nullptr, F::NUMBER, 0, 1, [](Options& o, auto&, double v) { o.Coverage = v; }, "0" },
    { "seed", nullptr, F::COUNT, 0, 9.0e15, [](Options& o, auto&, double v) { o.Seed = static_cast<unsigned long long>(v); }, "1" },
    { "threads", nullptr, F::COUNT, 0, 4096, [](Options& o, auto&, double v) { o.Threads = static_cast<int>(v); }, "0" },
    { "tolerance", nullptr, F::NUMBER, 1e-15, 0.1, [](Options& o, auto&, double v) { o.Tolerance = v; }, "1e-6" },
    { "min-angle", nullptr, F::NUMBER, 0, 179, [](Options& o, auto&, double v) { o.MinAngle = v; }, "45" },
    { "max-protrusion", nullptr, F::NUMBER, 0, 1, [](Options& o, auto&, double v) { o.MaxProtrusion = v; }, "1e-4" },
    { "balls", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Balls = t; } },
    { "repair", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Repair = ParseRepair(t); }, "auto" },
    { "weld-tolerance", nullptr, F::NUMBER, 0, 0.001, [](Options& o, auto&, double v) { o.WeldTolerance = v; }, "1e-6" },
    { "max-hole-size", nullptr, F::NUMBER, 0, 2, [](Options& o, auto&, double v) { o.MaximumHoleSize = v; }, "0.25" },
    { "wrap-alpha", nullptr, F::NUMBER, 1e-4, 1, [](Options& o, auto&, double v) { o.WrapAlpha = v; }, "0.02" },
    { "wrap-offset", nullptr, F::NUMBER, 1e-6, 0.1, [](Options& o, auto&, double v) { o.WrapOffset = v; }, "0.001" },
    { "output", "o", F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Output = t; } },
    { "reconstruct", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Reconstruct = t; } },
    { "resolution", nullptr, F::COUNT, 8, 2048, [](Options& o, auto&, double v) { o.Resolution = static_cast<int>(v); }, "128" },
    { "junctions", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Junctions = t; } },
    { "medial-mesh", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.MedialMesh = t; } },
    { "denoise", nullptr, F::SWITCH, 0, 0, [](Options& o, auto&, double) { o.Denoise = true; } },
    { "denoise-iterations", nullptr, F::COUNT, 1, 1000,
      [](Options& o, auto&, double v) {
        o.Denoise = true;
        o.DenoiseIterations = static_cast<int>(v);
      }, "20" },
    { "denoise-passband", nullptr, F::NUMBER, 0.001, 2,
      [](Options& o, auto&, double v) {
        o.Denoise = true;
        o.DenoisePassBand = v;
      }, "0.03" },
    { "prune", nullptr, F::SWITCH, 0, 0, [](Options& o, auto&, double) { o.Prune = true; } },
    { "prune-threshold", nullptr, F::NUMBER, 0, 1,
      [](Options& o, auto&, double v) {
        o.Prune = true;
        o.PruneThreshold = v;
      } },
    { "simplify", nullptr, F::COUNT, 1, 1e9, [](Options& o, auto&, double v) { o.Simplify = static_cast<long long>(v); } },
    { "simplify-method", nullptr, F::TEXT, 0, 0,
      [](Options& o, auto& t, double) { o.SimplifyMethod = ParseSimplifyMethod(t); }, "quadric" },
    { "simplify-tolerance", nullptr, F::NUMBER, 0, 1, [](Options& o, auto&, double v) { o.SimplifyTolerance = v; }, "0.0075" },
    { "thickness", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Thickness = t; } },
    { "thickness-below", nullptr, F::NUMBER, 0, 1e300,
      [](Options& o, auto&, double v) {
        if (!(v > 0.0))
        {
          Fail("--thickness-below expects a thickness above 0");
        }
        o.ThicknessBelow = v;
      } },
    { "render", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Render = t; } },
    { "html", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.Html = t; } },
    { "view", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { o.View = ParseView(t); }, "auto" },
    { "size", nullptr, F::TEXT, 0, 0, [](Options& o, auto& t, double) { ParseSize(t, o.Size); }, "900x640" },
    { "zoom", nullptr, F::NUMBER, 0.01, 100, [](Options& o, auto&, double v) { o.Zoom = v; }, "1" },
    { "stats", nullptr, F::SWITCH, 0, 0, [](Options& o, auto&, double) { o.Stats = true; } },
    { "quiet", nullptr, F::SWITCH, 0, 0, [](Options& o, auto&, double) { o.Quiet = true; } },
    { "help", "h", F::SWITCH, 0, 0, [](Options&, auto&, double) { Exit(Usage); } },
    { "version", nullptr, F::SWITCH, 0, 0,
      [](Options&, auto&, double) {
        Exit(std::string("medial-axis ") + MEDIALAXIS_VERSION + " (VTK " + vtkVersion::GetVTKVersion() + ")\n");
      } },
  };
  return flags;
}

// The flag table as tab-separated lines (long name, short name, kind, range, default), for
// the hidden --help-table that scripts/check-cli-page.py reads.
std::string FlagTable()
{
  static const char* const kinds[] = { "switch", "text", "count", "number" };
  std::ostringstream os;
  os.precision(17);
  for (const Flag& f : Flags())
  {
    os << f.Long << '\t' << (f.Short ? f.Short : "") << '\t' << kinds[f.Kind] << '\t' << f.Lo << '\t' << f.Hi
       << '\t' << (f.Default ? f.Default : "") << '\n';
  }
  return os.str();
}

// The flag spelled `name` (--long or -short), or nullptr.
const Flag* FindFlag(const std::string& name)
{
  for (const Flag& f : Flags())
  {
    if (name == std::string("--") + f.Long || (f.Short && name == std::string("-") + f.Short))
    {
      return &f;
    }
  }
  return nullptr;
}

// Checks and applies one flag's value.
void Apply(const Flag& flag, const std::string& spelled, const std::string& text, Options& o)
{
  double value = 0.0;
  if (flag.Kind == Flag::COUNT || flag.Kind == Flag::NUMBER)
  {
    const bool ok = flag.Kind == Flag::COUNT ? ParseCount(text, value) : ParseNumber(text, value);
    if (!ok || value < flag.Lo || value > flag.Hi)
    {
      Fail(spelled + " expects " + (flag.Kind == Flag::COUNT ? "a whole number (10k, 1M accepted)" : "a number") +
        " in " + Range(flag.Lo, flag.Hi) + ", got '" + text + "'");
    }
  }
  else if (flag.Kind == Flag::TEXT && text.empty())
  {
    Fail(spelled + " needs a value (see --help)");
  }
  flag.Apply(o, text, value);
  o.Given.insert(flag.Long);
}
}

[[noreturn]] void Fail(const std::string& reason)
{
  if (isatty(STDERR_FILENO))
  {
    std::cerr << "\r\033[K"; // over a progress bar, if one is drawn
  }
  std::cerr << "medial-axis: error: " << reason << "\n";
  std::exit(1);
}

std::string Extension(const std::string& path)
{
  return vtkMedialFileReader::GetExtension(path.c_str());
}

Options Parse(int argc, char* argv[])
{
  Options o;
  o.Method = vtkMedialAxisSampler::ONE_PASS;
  o.Strategy = vtkMedialAxisSampler::RANDOM;
  o.View = vtkMedialScene::VIEW_AUTO;
  // Hidden, not in the table: the table itself, for the docs' check.
  if (argc == 2 && std::string(argv[1]) == "--help-table")
  {
    Exit(FlagTable());
  }
  o.CommandLine = "medial-axis";
  for (int i = 1; i < argc; ++i)
  {
    o.CommandLine += std::string(" ") + argv[i];
  }
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg.size() < 2 || arg[0] != '-')
    {
      if (!o.Input.empty())
      {
        Fail("more than one input file given ('" + o.Input + "' and '" + arg + "')");
      }
      o.Input = arg;
      continue;
    }
    // --name=value, and -n=value for the short names.
    const size_t equals = arg.rfind("--", 0) == 0 ? arg.find('=') : (arg.size() > 2 && arg[2] == '=' ? 2 : std::string::npos);
    const std::string name = arg.substr(0, equals);
    const Flag* flag = FindFlag(name);
    if (!flag)
    {
      Fail("unknown option '" + name + "' (see --help)");
    }
    if (flag->Kind == Flag::SWITCH)
    {
      if (equals != std::string::npos)
      {
        Fail(name + " takes no value, got '" + arg + "'");
      }
      Apply(*flag, name, "", o);
      continue;
    }
    if (equals == std::string::npos && i + 1 >= argc)
    {
      Fail(name + " needs a value (see --help)");
    }
    Apply(*flag, name, equals != std::string::npos ? arg.substr(equals + 1) : argv[++i], o);
  }
  return o;
}

namespace
{
// Fails unless `path` can be created as a file.
void CheckWritable(const std::string& path, const std::string& flag)
{
  struct stat st;
  if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
  {
    Fail(flag + " path '" + path + "' is a directory");
  }
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (access(dir.c_str(), W_OK) != 0)
  {
    Fail(flag + " path '" + path + "' is not writable (folder '" + dir + "')");
  }
}

// Fails unless the writer table writes `content` to `path`'s extension, and the path is writable.
void CheckWriter(const std::string& path, const std::string& flag, int content)
{
  if (!vtkMedialFileWriter::CanWriteExtension(path.c_str(), content))
  {
    Fail(flag + " writes " + vtkMedialFileWriter::GetExtensions(content) + ", got '" + path + "'");
  }
  CheckWritable(path, flag);
}
}

void CheckOutputs(const Options& o)
{
  if (o.Output.empty() && o.Render.empty() && o.Reconstruct.empty() && o.Junctions.empty() && o.Thickness.empty() &&
    o.MedialMesh.empty() && o.Html.empty() && o.ThicknessBelow <= 0.0 && !o.Stats)
  {
    Fail("nothing to write: give -o OUT, --reconstruct OUT, --junctions OUT, --medial-mesh OUT, --thickness OUT, "
         "--thickness-below T, --render OUT.png, --html OUT.html or --stats (see --help)");
  }
  if (!o.Balls.empty())
  {
    for (const char* sampling : { "samples", "method", "strategy", "coverage", "seed", "tolerance", "min-angle", "max-protrusion" })
    {
      if (o.Given.count(sampling))
      {
        Fail(std::string("--") + sampling + " is for sampling, and --balls reads the balls instead");
      }
    }
    if (!vtkMedialFileReader::CanReadExtension(o.Balls.c_str(), vtkMedialFileReader::BALLS))
    {
      Fail("--balls reads " + vtkMedialFileReader::GetExtensions(vtkMedialFileReader::BALLS) + ", got '" + o.Balls +
        "'");
    }
  }
  if (o.Repair == vtkMedialRepairFilter::NONE)
  {
    for (const char* setting : { "weld-tolerance", "max-hole-size", "wrap-alpha", "wrap-offset" })
    {
      if (o.Given.count(setting))
      {
        Fail(std::string("--") + setting + " sets the repair, and --repair none turns it off");
      }
    }
  }
  if (!o.Render.empty())
  {
    const char* display = std::getenv("DISPLAY");
    if (vtkMedialScene::NeedsDisplay() && (!display || !*display))
    {
      Fail("--render needs an X display and none is set (DISPLAY is empty); run under "
           "xvfb-run, e.g. 'xvfb-run -a medial-axis ... --render out.png'");
    }
    if (Extension(o.Render) != ".png")
    {
      Fail("--render writes a PNG picture and needs a .png name, got '" + o.Render + "'");
    }
    CheckWritable(o.Render, "--render");
  }
  if (!o.Html.empty())
  {
    const std::string ext = Extension(o.Html);
    if (ext != ".html" && ext != ".htm")
    {
      Fail("--html writes a web page and needs a .html name, got '" + o.Html + "'");
    }
    if (!vtkMedialHTMLWriter::HasViewer())
    {
      Fail(std::string("--html: this build has no web viewer: ") + vtkMedialHTMLWriter::GetViewerStatus());
    }
    CheckWritable(o.Html, "--html");
  }
  if (!o.Output.empty())
  {
    CheckWriter(o.Output, "-o", vtkMedialFileWriter::BALLS);
  }
  if (!o.Reconstruct.empty())
  {
    CheckWriter(o.Reconstruct, "--reconstruct", vtkMedialFileWriter::SURFACE);
  }
  if (!o.Junctions.empty())
  {
    CheckWriter(o.Junctions, "--junctions", vtkMedialFileWriter::BALLS);
  }
  if (!o.MedialMesh.empty())
  {
    CheckWriter(o.MedialMesh, "--medial-mesh", vtkMedialFileWriter::BALLS);
  }
  if (o.Simplify > 0 && o.MedialMesh.empty())
  {
    Fail("--simplify K simplifies the medial mesh of a closed surface: give --medial-mesh OUT.ma|.vtp");
  }
  if (o.SimplifyMethod >= 0 && o.Simplify <= 0)
  {
    Fail("--simplify-method chooses how --simplify K simplifies: give --simplify K");
  }
  if (o.SimplifyTolerance >= 0.0 && o.Simplify <= 0)
  {
    Fail("--simplify-tolerance guards how --simplify K simplifies: give --simplify K");
  }
  if (o.SimplifyTolerance >= 0.0 && o.SimplifyMethod == vtkMedialSimplifyFilter::COVERAGE)
  {
    Fail("--simplify-tolerance guards the quadric method's collapses, not --simplify-method coverage");
  }
  if (!o.Thickness.empty())
  {
    // Only the VTK formats keep the point and cell arrays, the whole point of the file.
    const std::string ext = Extension(o.Thickness);
    if (ext != ".vtp" && ext != ".vtk")
    {
      Fail("--thickness writes the surface with its Thickness arrays: .vtp .vtk, got '" + o.Thickness + "'");
    }
    CheckWriter(o.Thickness, "--thickness", vtkMedialFileWriter::SURFACE);
  }
}
}
