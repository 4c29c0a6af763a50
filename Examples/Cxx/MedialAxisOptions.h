// SPDX-License-Identifier: BSD-3-Clause
// medial-axis: the command line's options and the rules every flag follows.
//  - `--flag value` and `--flag=value` alike; a flag that takes no value refuses one.
//  - Whole numbers take the suffixes k, M and G (10k = 10,000, 1M = 1,000,000) and
//    exponents (1e6); every number is checked against its range.
//  - Every output path is checked before any work: its extension must be one the
//    output's writer table (vtkMedialFileWriter) has, and its folder writable.
//  - A run that writes nothing (no output flag, no --stats) is refused before any work.
//  - The hidden --help-table prints the flag table (name, short name, kind, range,
//    default; tab-separated) for the check of docs/cli.md (scripts/check-cli-page.py).
#ifndef MedialAxisOptions_h
#define MedialAxisOptions_h

#include <set>
#include <string>

namespace medialaxis
{
struct Options
{
  std::string Input;
  long long Samples = 10000;
  int Method = 0;
  int Strategy = 0;
  double Coverage = 0.0;
  unsigned long long Seed = 1;
  int Threads = 0;
  double Tolerance = 1e-6;
  double MinAngle = 45.0;
  double MaxProtrusion = 1e-4;
  std::string Balls;       // --balls: read balls instead of sampling
  std::string Output;      // -o: the balls
  std::string Render;      // --render: the picture
  std::string Reconstruct; // --reconstruct: the union of balls
  std::string Junctions;   // --junctions: the 2D medial graph
  std::string Thickness;   // --thickness: the surface with its wall thickness
  std::string MedialMesh;  // --medial-mesh: the 3D medial mesh
  std::string Html;        // --html: the self-contained web page
  std::string CommandLine; // the arguments, as the page shows them
  bool Denoise = false;          // --denoise, --denoise-*: the surface smoothed first
  int DenoiseIterations = 0;     // --denoise-iterations (0: vtkMedialDenoiseFilter's default)
  double DenoisePassBand = -1.0; // --denoise-passband (negative: the filter's default)
  bool Prune = false;            // --prune, --prune-threshold: the graph or medial mesh pruned
  double PruneThreshold = -1.0;  // negative: the measure's default
  long long Simplify = 0;        // --simplify K: the medial mesh reduced to K balls
  int SimplifyMethod = -1;       // --simplify-method: vtkMedialSimplifyFilter's Method (-1: not given)
  double SimplifyTolerance = -1.0; // --simplify-tolerance: its ErrorTolerance (negative: not given)
  double ThicknessBelow = 0.0;
  int Repair = 0;               // --repair: vtkMedialRepairFilter's mode (0 auto, 1 none, 2 wrap)
  double WeldTolerance = -1.0;  // --weld-tolerance (negative: the filter's default)
  double MaximumHoleSize = -1.0; // --max-hole-size
  double WrapAlpha = -1.0;      // --wrap-alpha
  double WrapOffset = -1.0;     // --wrap-offset
  int Resolution = 128;
  bool Stats = false;
  bool Quiet = false;
  int View = 0; // vtkMedialScene::VIEW_AUTO
  int Size[2] = { 0, 0 };
  double Zoom = 1.0;
  std::set<std::string> Given; // long names of the flags on the command line
};

/// Parses the command line; prints help or the version and exits 0 when asked;
/// fails (message, exit 1) on any mistake.
Options Parse(int argc, char* argv[]);

/// Fails unless the options ask for something to write, and the output paths can
/// be written; before any work.
void CheckOutputs(const Options& options);

/// "medial-axis: error: REASON" on stderr and exit 1.
[[noreturn]] void Fail(const std::string& reason);

/// The extension of `path` in lower case with its dot.
std::string Extension(const std::string& path);
}

#endif
