// SPDX-License-Identifier: BSD-3-Clause
// medial-axis: medial axis transform of a closed triangle mesh or of planar
// polygons, from the command line.
//
// Reads a mesh or polygons (or generates a demo shape), samples its medial balls
// with vtkMedialAxisSampler (or reads balls another tool wrote, --balls), and
// writes what is asked: the balls, the 2D medial graph (vtkMedialJunctionFilter),
// the union of balls (vtkMedialBallUnion), the 3D medial mesh (vtkMedialMeshFilter),
// the wall thickness (vtkMedialThickness),
// a picture (vtkMedialScene), a web page (vtkMedialHTMLWriter) and a JSON line of figures. Only wiring lives here: every algorithm is in a filter, every
// format in vtkMedialFileReader / vtkMedialFileWriter, every picture in
// vtkMedialScene. The flag rules are in MedialAxisOptions.h, what is said on
// stderr in MedialAxisConsole.h.
#include "MedialAxisRuntime.h"
#include "MedialAxisConsole.h"
#include "MedialAxisOptions.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialFileWriter.h"
#include "vtkMedialHTMLWriter.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialDenoiseFilter.h"
#include "vtkMedialJson.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialPruneFilter.h"
#include "vtkMedialScaleAxisFilter.h"
#include "vtkMedialSimplifyFilter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialRepairFilter.h"
#include "vtkMedialScene.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <omp.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using medialaxis::Console;
using medialaxis::Fail;
using medialaxis::Options;

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Updates a watched filter; fails with the first error it reported.
void Run(vtkAlgorithm* algorithm, Console& console, const std::string& context = "")
{
  console.ClearError();
  console.Watch(algorithm);
  algorithm->Update();
  console.ExitIfInterrupted();
  if (!console.GetError().empty())
  {
    Fail(context + console.GetError());
  }
}

vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* data)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(data);
  return copy;
}

// A file through vtkMedialFileReader, with the checks that give clear reasons.
vtkSmartPointer<vtkPolyData> ReadFile(const std::string& path, int content, Console& console)
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
  reader->SetContent(content);
  Run(reader, console, "cannot read '" + path + "': ");
  if (reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    Fail("cannot read '" + path + "': no points (empty or not a " + medialaxis::Extension(path) + " file)");
  }
  return Copy(reader->GetOutput());
}

// demo:NAME inputs; nullptr for an unknown name.
vtkSmartPointer<vtkPolyData> MakeDemo(const std::string& name)
{
  vtkNew<vtkMedialShapeSource> demo;
  if (name == "demo:l-shape")
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
  else if (name != "demo:jack")
  {
    return nullptr;
  }
  demo->Update();
  return Copy(demo->GetOutput());
}

// Writes `data` by the extension of `path` (checked before any work).
void Write(vtkPolyData* data, const std::string& path, int content, Console& console)
{
  console.Begin("Writing " + path);
  console.ClearError();
  vtkNew<vtkMedialFileWriter> writer;
  writer->SetInputData(data);
  writer->SetContent(content);
  writer->SetFileName(path.c_str());
  if (!writer->Write() || !console.GetError().empty())
  {
    Fail("cannot write '" + path + "': " + console.GetError());
  }
  console.End();
}

// One run of the program: the data as it is made, and the JSON line of --stats.
class Program
{
public:
  Program(const Options& options, Console& console)
    : Opt(options)
    , Out(console)
    , RepairMode(options.Repair)
  {
    this->Json.precision(6);
    this->RepairJson.precision(6);
  }

  void LoadInput();
  void Denoise();
  void MedialGraph();
  void SampleOrReadBalls();
  void Reconstruct();
  void MedialMesh();
  void Thickness();
  void Render();
  void WritePage();
  void PrintStats();

private:
  void Sample();
  void ReadBalls();
  void ReconstructionError();
  void Protrusion(bool sampled);
  void ThicknessReport();
  void MedialMeshReport(vtkMedialMeshFilter* filter, double seconds);
  vtkSmartPointer<vtkPolyData> Prune(vtkPolyData* axis);
  void PruneBalls();
  double ScaleAxisThreshold() const;
  void Simplify();
  void Rebuild(vtkPolyData* medial, bool envelope);
  void ConfigureRepair(vtkMedialRepairFilter* repair) const;
  void AfterRepair(bool repaired, vtkMedialRepairFilter* repair);
  void RepairSurface();

  const Options& Opt;
  Console& Out;
  std::ostringstream InputJson;  // the first member
  std::ostringstream RepairJson; // the repair's members, when the surface was repaired
  std::ostringstream Json;       // the members after them
  // What the next filter that prepares the 3D surface does with it: --repair for the
  // first one, then NONE (the surface has been checked, or repaired, once).
  int RepairMode;
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkPolyData> Balls;
  vtkSmartPointer<vtkPolyData> Graph;
  vtkSmartPointer<vtkPolyData> Reconstruction;
  vtkSmartPointer<vtkPolyData> WallThickness;
  vtkSmartPointer<vtkPolyData> Mesh; // --medial-mesh
  bool Planar = false;
  int Polygons = 0;
  bool Closed = true; // the sampler saw no boundary edges (or no sampler ran)
  double SampledProtrusion = -1.0; // the sampler's MaxProtrusion, when it measured it
};

// The surface: a file, a demo shape, the jack without INPUT (unless --balls).
void Program::LoadInput()
{
  const std::string& input = this->Opt.Input;
  if (input.empty() && !this->Opt.Balls.empty())
  {
    if (!this->Opt.Thickness.empty() || this->Opt.ThicknessBelow > 0.0)
    {
      Fail("--thickness and --thickness-below measure a surface: give INPUT with --balls");
    }
    if (!this->Opt.MedialMesh.empty())
    {
      Fail("--medial-mesh joins the balls inside a surface: give INPUT with --balls");
    }
    this->InputJson << "\"input\": null";
    return;
  }
  if (input.empty() || input.rfind("demo:", 0) == 0)
  {
    this->Surface = MakeDemo(input.empty() ? "demo:jack" : input);
    if (!this->Surface)
    {
      Fail("unknown demo '" + input + "' (demo:jack, demo:l-shape, demo:rectangle, demo:frame, demo:star, demo:ellipse, demo:trefoil)");
    }
  }
  else
  {
    this->Surface = ReadFile(input, vtkMedialFileReader::SURFACE, this->Out);
  }
  this->Planar = vtkMedialAxisSampler::IsPlanarInput(this->Surface);
  this->InputJson << "\"input\": " << vtkMedialJsonString(input.empty() ? "demo:jack" : input);
  if (this->Planar && (!this->Opt.Thickness.empty() || this->Opt.ThicknessBelow > 0.0))
  {
    Fail("--thickness and --thickness-below need a 3D surface; '" + input + "' is planar");
  }
  if (this->Planar && !this->Opt.MedialMesh.empty())
  {
    Fail("--medial-mesh needs a closed surface; '" + input + "' is planar (see --junctions)");
  }
}

// --denoise: the surface low-pass filtered (vtkMedialDenoiseFilter) before anything
// else sees it.
void Program::Denoise()
{
  const Options& o = this->Opt;
  if (!o.Denoise)
  {
    return;
  }
  if (!this->Surface)
  {
    Fail("--denoise smooths INPUT's surface: give INPUT");
  }
  if (this->Planar)
  {
    Fail("--denoise smooths a 3D surface; '" + o.Input + "' is planar");
  }
  vtkNew<vtkMedialDenoiseFilter> denoise;
  denoise->SetInputData(this->Surface);
  if (o.DenoiseIterations > 0)
  {
    denoise->SetNumberOfIterations(o.DenoiseIterations);
  }
  if (o.DenoisePassBand > 0.0)
  {
    denoise->SetPassBand(o.DenoisePassBand);
  }
  const Clock::time_point start = Clock::now();
  Run(denoise, this->Out);
  this->Json << ", \"denoise_iterations\": " << denoise->GetNumberOfIterations() << ", \"denoise_passband\": " << denoise->GetPassBand()
             << ", \"denoise_max_move\": " << denoise->GetMaximumDisplacement()
             << ", \"denoise_seconds\": " << SecondsSince(start);
  this->Surface = Copy(denoise->GetOutput());
}

// 2D input: the medial graph, when it is written, drawn or counted.
void Program::MedialGraph()
{
  if (!this->Opt.Junctions.empty() && !this->Planar)
  {
    Fail("--junctions needs planar polygons or closed polylines; '" +
      (this->Opt.Input.empty() ? std::string("(no INPUT)") : this->Opt.Input) + "' is not planar");
  }
  if (!this->Planar ||
    (this->Opt.Junctions.empty() && this->Opt.Render.empty() && this->Opt.Html.empty() && !this->Opt.Stats))
  {
    return;
  }
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputData(this->Surface);
  junctions->SetNumberOfThreads(this->Opt.Threads);
  Run(junctions, this->Out);
  this->Graph = Copy(junctions->GetOutput());
  this->Polygons = junctions->GetNumberOfPolygons();
  if (this->Opt.Prune)
  {
    this->Graph = this->Prune(this->Graph);
  }
  if (!this->Opt.Junctions.empty())
  {
    Write(this->Graph, this->Opt.Junctions, vtkMedialFileWriter::BALLS, this->Out);
  }
}

void Program::SampleOrReadBalls()
{
  const bool sampled = this->Opt.Balls.empty();
  if (sampled)
  {
    this->Sample();
  }
  else
  {
    this->RepairSurface();
    this->ReadBalls();
  }
  this->PruneBalls();
  if (this->Opt.Stats && this->Surface && !this->Planar)
  {
    this->Protrusion(sampled);
  }
  if (!this->Opt.Output.empty())
  {
    Write(this->Balls, this->Opt.Output, vtkMedialFileWriter::BALLS, this->Out);
  }
}

void Program::Sample()
{
  const Options& o = this->Opt;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(this->Surface);
  sampler->SetNumberOfSamples(static_cast<vtkIdType>(o.Samples));
  sampler->SetMethod(o.Method);
  sampler->SetSamplingStrategy(o.Strategy);
  sampler->SetCoverageTolerance(o.Coverage);
  sampler->SetRandomSeed(static_cast<vtkTypeInt64>(o.Seed)); // at most 9e15 (MedialAxisOptions)
  sampler->SetNumberOfThreads(o.Threads);
  sampler->SetTolerance(o.Tolerance);
  sampler->SetMinimumSeparationAngle(o.MinAngle);
  sampler->SetMaximumProtrusion(o.MaxProtrusion);
  sampler->SetRepairMode(this->Planar ? vtkMedialRepairFilter::NONE : this->RepairMode);
  this->ConfigureRepair(sampler->GetRepair());
  // --stats reports how far the balls cross the surface: the sampler measures it as it
  // goes (RANDOM strategy; --prune then keeps only some balls, which Protrusion measures).
  sampler->SetMeasureProtrusion(o.Stats && !o.Prune);
  const Clock::time_point start = Clock::now();
  Run(sampler, this->Out);
  const double seconds = SecondsSince(start);
  this->Balls = Copy(sampler->GetOutput());
  this->Closed = sampler->GetBoundaryEdges() == 0;
  if (!this->Planar)
  {
    this->AfterRepair(sampler->GetSurfaceRepaired(), sampler->GetRepair());
  }
  this->SampledProtrusion = sampler->GetMaxProtrusion();
  this->Balls->GetFieldData()->RemoveArray(vtkMedialArrayNames::MaxProtrusion); // -o is the same without --stats

  const int strategy = this->Planar ? vtkMedialAxisSampler::RANDOM : o.Strategy;
  auto& js = this->Json;
  js << ", \"triangles\": " << sampler->GetNumberOfTriangles() << ", \"samples\": " << o.Samples
     << ", \"medial_points\": " << this->Balls->GetNumberOfPoints()
     << ", \"discarded\": " << sampler->GetDiscardedSamples()
     << ", \"method\": " << vtkMedialJsonString(vtkMedialAxisSampler::GetMethodName(o.Method))
     << ", \"threads\": " << (o.Threads > 0 ? o.Threads : omp_get_num_procs()) << ", \"min_angle\": " << o.MinAngle
     << ", \"tolerance\": " << o.Tolerance << ", \"iterations_mean\": " << sampler->GetMeanIterations()
     << ", \"capped\": " << sampler->GetCappedSamples()
     << ", \"strategy\": " << vtkMedialJsonString(vtkMedialAxisSampler::GetSamplingStrategyName(strategy));
  if (!this->Planar && (o.Strategy != vtkMedialAxisSampler::RANDOM || o.Coverage > 0.0))
  {
    js << ", \"evaluated\": " << sampler->GetEvaluatedSamples() << ", \"seeds\": " << sampler->GetSeedSamples()
       << ", \"links\": " << this->Balls->GetNumberOfLines() << ", \"coverage\": " << o.Coverage
       << ", \"coverage_reached\": " << (sampler->GetCoverageReached() ? "true" : "false")
       << ", \"max_coverage_gap\": " << sampler->GetMaxCoverageGap();
  }
  js << ", \"seconds\": " << seconds;
}

// --balls: any tool's balls; they need a Radius.
void Program::ReadBalls()
{
  this->Balls = ReadFile(this->Opt.Balls, vtkMedialFileReader::BALLS, this->Out);
  vtkDataArray* radius = this->Balls->GetPointData()->GetArray(vtkMedialArrayNames::Radius);
  if (!radius || radius->GetNumberOfComponents() != 1)
  {
    Fail("--balls '" + this->Opt.Balls + "' has no one-component point array 'Radius'");
  }
  double range[2];
  radius->GetRange(range);
  this->Json << ", \"balls\": " << vtkMedialJsonString(this->Opt.Balls)
             << ", \"medial_points\": " << this->Balls->GetNumberOfPoints() << ", \"radius_min\": " << range[0]
             << ", \"radius_max\": " << range[1];
}

// How far the balls cross the 3D surface, and the limit the sampler was given: the
// sampler's own measure where it took one (every ball it made is written), else a pass
// of vtkMedialBallProtrusion over the balls (read with --balls, pruned, or from an
// iterative strategy). Both are the exact largest r - d(c).
void Program::Protrusion(bool sampled)
{
  double largest = this->SampledProtrusion;
  if (!sampled || largest < 0.0)
  {
    vtkNew<vtkMedialBallProtrusion> protrusion;
    protrusion->SetSurfaceData(this->Surface);
    protrusion->SetBallsData(this->Balls);
    protrusion->MaximumOnlyOn();
    protrusion->SetNumberOfThreads(this->Opt.Threads);
    Run(protrusion, this->Out);
    largest = protrusion->GetMaxProtrusion();
  }
  if (sampled)
  {
    this->Json << ", \"max_protrusion\": " << this->Opt.MaxProtrusion;
  }
  this->Json << ", \"protrusion_max_rel\": " << largest;
}

// --reconstruct: the union of the balls, and its error against a closed input; with
// --prune or --simplify on a medial mesh, MedialMesh rebuilds its envelope instead.
void Program::Reconstruct()
{
  if (this->Opt.Reconstruct.empty() ||
    (!this->Opt.MedialMesh.empty() && (this->Opt.Prune || this->Opt.Simplify > 0)))
  {
    return;
  }
  this->Rebuild(this->Balls, false);
}

// The union of `medial`'s balls or, with `envelope`, the interpolated envelope of the
// medial mesh (vtkMedialBallUnion MEDIAL_MESH).
void Program::Rebuild(vtkPolyData* medial, bool envelope)
{
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(medial);
  if (envelope)
  {
    ballUnion->SetPrimitives(vtkMedialBallUnion::MEDIAL_MESH);
  }
  ballUnion->SetSampleDimensions(this->Opt.Resolution, this->Opt.Resolution, this->Opt.Resolution);
  ballUnion->SetNumberOfThreads(this->Opt.Threads);
  const Clock::time_point start = Clock::now();
  Run(ballUnion, this->Out);
  this->Json << ", \"reconstruction_seconds\": " << SecondsSince(start) << ", \"resolution\": " << this->Opt.Resolution;
  this->Reconstruction = Copy(ballUnion->GetOutput());
  Write(this->Reconstruction, this->Opt.Reconstruct, vtkMedialFileWriter::SURFACE, this->Out);
  if (this->Opt.Stats && this->Surface && this->Closed && this->Reconstruction->GetNumberOfCells() > 0)
  {
    this->ReconstructionError();
  }
}

void Program::ReconstructionError()
{
  vtkNew<vtkMedialReconstructionError> error;
  error->SetOriginalData(this->Surface);
  error->SetReconstructionData(this->Reconstruction);
  error->SetNumberOfThreads(this->Opt.Threads);
  Run(error, this->Out);
  this->Json << ", \"hausdorff_max_rel\": " << error->GetVertexHausdorff()
             << ", \"hausdorff_mean_rel\": " << error->GetVertexMeanHausdorff()
             << ", \"hausdorff_area_max_rel\": " << error->GetAreaHausdorff()
             << ", \"hausdorff_area_mean_rel\": " << error->GetAreaMeanHausdorff();
}

// --medial-mesh: the medial mesh of the balls (given on port 1, so the sampling is not
// repeated), classified with the balls' angle.
void Program::MedialMesh()
{
  if (this->Opt.MedialMesh.empty())
  {
    return;
  }
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(this->Surface);
  filter->SetBallsData(this->Balls);
  filter->SetNumberOfThreads(this->Opt.Threads);
  filter->GetClassifier()->SetMinimumSeparationAngle(this->Opt.MinAngle);
  filter->SetRepairMode(this->RepairMode);
  this->ConfigureRepair(filter->GetRepair());
  const Clock::time_point start = Clock::now();
  Run(filter, this->Out);
  const double seconds = SecondsSince(start);
  this->AfterRepair(filter->GetSurfaceRepaired(), filter->GetRepair());
  this->Mesh = Copy(filter->GetOutput());
  this->MedialMeshReport(filter, seconds);
  if (this->Opt.Prune)
  {
    this->Mesh = this->Prune(this->Mesh);
  }
  this->Simplify();
  Write(this->Mesh, this->Opt.MedialMesh, vtkMedialFileWriter::BALLS, this->Out);
  if (!this->Opt.Reconstruct.empty() && (this->Opt.Prune || this->Opt.Simplify > 0))
  {
    this->Rebuild(this->Mesh, true);
  }
}

// The scale-axis significance 3D pruning keeps: --prune-threshold, or the default
// scale's 1 - 1/s. After --denoise the default scale is 1.3: the smoothing removed most
// of the noise the filter's 1.5 is for, and 1.3 keeps more of the shape (the noisy-horse
// table of docs/how-it-works/pruning.md: both noise levels within 1% and 2x only so).
double Program::ScaleAxisThreshold() const
{
  if (this->Opt.PruneThreshold >= 0.0)
  {
    return this->Opt.PruneThreshold;
  }
  vtkNew<vtkMedialScaleAxisFilter> defaults;
  const double scale = this->Opt.Denoise ? vtkMedialScaleAxisFilter::GetDenoisedScaleFactor() : defaults->GetScaleFactor();
  return 1.0 - 1.0 / scale;
}

// 3D --prune: the scale axis transform of the balls (vtkMedialScaleAxisFilter), before
// they are written, measured or meshed: balls covered at scale s = 1 / (1 - threshold)
// go. The noise's branches and the balls tangent to tilted facets are covered at a
// small scale (see the noisy-horse table of docs/how-it-works/pruning.md).
void Program::PruneBalls()
{
  if (!this->Opt.Prune || this->Planar)
  {
    return;
  }
  vtkNew<vtkMedialScaleAxisFilter> scaleAxis;
  scaleAxis->SetInputData(this->Balls);
  scaleAxis->SetScaleFactor(1.0 / std::max(1.0 - this->ScaleAxisThreshold(), 1e-9)); // clamped by the filter
  scaleAxis->SetNumberOfThreads(this->Opt.Threads);
  Run(scaleAxis, this->Out);
  this->Balls = Copy(scaleAxis->GetOutput());
  this->Json << ", \"pruned_balls\": " << scaleAxis->GetNumberOfRemovedBalls()
             << ", \"prune_scale\": " << scaleAxis->GetScaleFactor();
  if (this->Opt.MedialMesh.empty())
  {
    this->Json << ", \"kept_balls\": " << this->Balls->GetNumberOfPoints();
  }
}

// --prune: the 2D graph pruned with the default measure (tubularity) or --prune-threshold;
// the medial mesh (of balls PruneBalls kept) with the scale axis measure at the same threshold.
vtkSmartPointer<vtkPolyData> Program::Prune(vtkPolyData* axis)
{
  vtkNew<vtkMedialPruneFilter> prune;
  prune->SetInputData(axis);
  if (this->Planar)
  {
    prune->SetThreshold(this->Opt.PruneThreshold);
  }
  else
  {
    prune->SetMeasureToScaleAxis();
    prune->SetThreshold(this->ScaleAxisThreshold());
  }
  Run(prune, this->Out);
  this->Json << ", \"pruned_branches\": " << prune->GetNumberOfPrunedBranches();
  if (this->Opt.Simplify <= 0)
  {
    this->Json << ", \"kept_balls\": " << prune->GetOutput()->GetNumberOfPoints();
  }
  return Copy(prune->GetOutput());
}

// --simplify K: the medial mesh reduced to K balls.
void Program::Simplify()
{
  if (this->Opt.Simplify <= 0)
  {
    return;
  }
  vtkNew<vtkMedialSimplifyFilter> simplify;
  simplify->SetInputData(this->Mesh);
  simplify->SetNumberOfBalls(this->Opt.Simplify);
  simplify->SetMethod(std::max(0, this->Opt.SimplifyMethod));
  if (this->Opt.SimplifyTolerance >= 0.0)
  {
    simplify->SetErrorTolerance(this->Opt.SimplifyTolerance);
  }
  simplify->SetSurfaceData(this->Surface);
  simplify->SetRepairMode(this->RepairMode); // NONE by now: the medial mesh checked the surface
  this->ConfigureRepair(simplify->GetRepair());
  simplify->SetNumberOfThreads(this->Opt.Threads);
  const Clock::time_point start = Clock::now();
  Run(simplify, this->Out);
  this->Json << ", \"kept_balls\": " << simplify->GetOutput()->GetNumberOfPoints()
             << ", \"simplify_seconds\": " << SecondsSince(start);
  this->Mesh = Copy(simplify->GetOutput());
}

// JSON members of the medial mesh: sizes, point types, topology and time.
void Program::MedialMeshReport(vtkMedialMeshFilter* filter, double seconds)
{
  vtkIdType perType[4] = { 0, 0, 0, 0 };
  vtkDataArray* types = this->Mesh->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
  for (vtkIdType i = 0; types && i < types->GetNumberOfTuples(); ++i)
  {
    perType[std::min(3, std::max(0, static_cast<int>(types->GetTuple1(i))))]++;
  }
  this->Json << ", \"medial_vertices\": " << this->Mesh->GetNumberOfPoints()
             << ", \"medial_edges\": " << filter->GetNumberOfEdges()
             << ", \"medial_faces\": " << this->Mesh->GetNumberOfPolys() << ", \"seams\": " << perType[2]
             << ", \"junctions\": " << perType[3] << ", \"euler_characteristic\": " << filter->GetEulerCharacteristic()
             << ", \"components\": " << filter->GetNumberOfComponents() << ", \"medial_mesh_seconds\": " << seconds;
}

// --thickness, --thickness-below: the wall thickness of a 3D surface, with the
// sampler's angle and protrusion settings.
void Program::Thickness()
{
  if (this->Opt.Thickness.empty() && this->Opt.ThicknessBelow <= 0.0)
  {
    return;
  }
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputData(this->Surface);
  thickness->SetMinimumSeparationAngle(this->Opt.MinAngle);
  thickness->SetMaximumProtrusion(this->Opt.MaxProtrusion);
  thickness->SetThinThreshold(this->Opt.ThicknessBelow);
  thickness->SetNumberOfThreads(this->Opt.Threads);
  thickness->SetRepairMode(this->RepairMode);
  this->ConfigureRepair(thickness->GetRepair());
  Run(thickness, this->Out);
  this->AfterRepair(thickness->GetSurfaceRepaired(), thickness->GetRepair());
  this->WallThickness = Copy(thickness->GetOutput());
  if (!this->Opt.Thickness.empty())
  {
    Write(this->WallThickness, this->Opt.Thickness, vtkMedialFileWriter::SURFACE, this->Out);
  }
  this->ThicknessReport();
}

// Percentiles of the point Thickness (NaN left out) and the thin share of the area
// with its regions: JSON members with --stats, else a line for --thickness-below.
void Program::ThicknessReport()
{
  auto field = [&](const char* name) {
    vtkDataArray* a = this->WallThickness->GetFieldData()->GetArray(name);
    return a ? a->GetComponent(0, 0) : 0.0;
  };
  const double share = field(vtkMedialArrayNames::ThinAreaFraction);
  const double regions = field(vtkMedialArrayNames::ThinRegionCount);
  const double below = this->Opt.ThicknessBelow;
  if (!this->Opt.Stats)
  {
    if (below > 0.0)
    {
      std::cout << "thinner than " << below << ": " << 100.0 * share << "% of the area, in " << regions
                << (regions == 1 ? " region" : " regions") << std::endl;
    }
    return;
  }
  std::vector<double> values;
  vtkDataArray* t = this->WallThickness->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
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
  this->Json << ", \"thickness_min\": " << quantile(0.0) << ", \"thickness_p01\": " << quantile(0.01)
              << ", \"thickness_median\": " << quantile(0.5);
  if (below > 0.0)
  {
    this->Json << ", \"thickness_below\": " << below << ", \"thin_area_fraction\": " << share
                << ", \"thin_regions\": " << regions;
  }
}

// --render: the 2D graph scene for planar input, the surface coloured by thickness
// with --thickness, else the balls or the medial mesh coloured by point type (with the
// reconstruction beside them when there is one).
void Program::Render()
{
  if (this->Opt.Render.empty())
  {
    return;
  }
  this->Out.Begin("Rendering " + this->Opt.Render);
  this->Out.ClearError();
  vtkNew<vtkMedialScene> scene;
  scene->SetSurface(this->Surface);
  if (this->Graph)
  {
    scene->SetGraph(this->Graph);
  }
  else if (this->WallThickness)
  {
    scene->SetSurface(this->WallThickness);
    scene->SetSurfaceScalars(vtkMedialArrayNames::Thickness);
  }
  else
  {
    scene->SetMedial(this->Mesh ? this->Mesh : this->Balls);
    scene->SetColorBy(this->Mesh ? vtkMedialScene::POINT_TYPE : vtkMedialScene::RADIUS);
    scene->SetReconstruction(this->Reconstruction);
  }
  scene->SetViewDirection(this->Opt.View);
  scene->SetZoom(this->Opt.Zoom);
  scene->SetWindowSize(this->Opt.Size[0], this->Opt.Size[1]);
  if (!scene->WritePNG(this->Opt.Render.c_str()) || !this->Out.GetError().empty())
  {
    Fail("cannot write '" + this->Opt.Render + "': " + this->Out.GetError());
  }
  this->Out.End();
}

// The repair's settings from the command line (the filter's defaults otherwise).
void Program::ConfigureRepair(vtkMedialRepairFilter* repair) const
{
  const Options& o = this->Opt;
  if (o.WeldTolerance >= 0.0)
  {
    repair->SetWeldTolerance(o.WeldTolerance);
  }
  if (o.MaximumHoleSize >= 0.0)
  {
    repair->SetMaximumHoleSize(o.MaximumHoleSize);
  }
  if (o.WrapAlpha > 0.0)
  {
    repair->SetWrapAlpha(o.WrapAlpha);
  }
  if (o.WrapOffset > 0.0)
  {
    repair->SetWrapOffset(o.WrapOffset);
  }
}

// After the first filter that prepared the 3D surface: a repaired surface replaces the
// input for every later step (and measure), with its report in --stats; later filters
// need not check again.
void Program::AfterRepair(bool repaired, vtkMedialRepairFilter* repair)
{
  if (this->RepairMode == vtkMedialRepairFilter::NONE)
  {
    return;
  }
  this->RepairMode = vtkMedialRepairFilter::NONE;
  if (!repaired)
  {
    return;
  }
  this->Surface = Copy(repair->GetOutput());
  this->Closed = true;
  auto& js = this->RepairJson;
  js << ", \"repair\": " << vtkMedialJsonString(vtkMedialRepairFilter::GetModeName(this->Opt.Repair)) << ", \"repair_steps\": [";
  for (int i = 0; i < repair->GetNumberOfReportLines(); ++i)
  {
    js << (i ? ", " : "") << vtkMedialJsonString(repair->GetReportLine(i));
  }
  js << "], \"repair_intersecting_pairs\": " << repair->GetIntersectingPairs()
     << ", \"repair_welded_points\": " << repair->GetWeldedPoints()
     << ", \"repair_dropped_triangles\": " << repair->GetDroppedTriangles()
     << ", \"repair_split_points\": " << repair->GetSplitPoints()
     << ", \"repair_stitched_edges\": " << repair->GetStitchedEdges()
     << ", \"repair_rewound_triangles\": " << repair->GetRewoundTriangles()
     << ", \"repair_turned_shells\": " << repair->GetTurnedShells()
     << ", \"repair_filled_holes\": " << repair->GetFilledHoles()
     << ", \"repair_unfilled_holes\": " << repair->GetUnfilledHoles()
     << ", \"repair_unions\": " << repair->GetJoinedShells()
     << ", \"repair_resolved_shells\": " << repair->GetResolvedShells()
     << ", \"repair_touching_shells\": " << repair->GetTouchingShells()
     << ", \"repair_removed_sheets\": " << repair->GetRemovedSheets()
     << ", \"repair_wrapped\": " << (repair->GetWrapped() ? "true" : "false")
     << ", \"repair_max_distance_rel\": " << repair->GetMaximumDistance()
     << ", \"repair_buried_area\": " << repair->GetBuriedArea()
     << ", \"repair_triangles\": " << repair->GetOutput()->GetNumberOfPolys()
     << ", \"repair_seconds\": " << repair->GetSeconds();
}

// --balls with a 3D surface: the surface is checked (and repaired) here, before the
// balls are measured against it, since no sampler does it.
void Program::RepairSurface()
{
  if (!this->Surface || this->Planar || this->RepairMode == vtkMedialRepairFilter::NONE)
  {
    return;
  }
  vtkNew<vtkMedialRepairFilter> repair;
  repair->SetInputData(this->Surface);
  repair->SetMode(this->RepairMode);
  repair->SetNumberOfThreads(this->Opt.Threads);
  this->ConfigureRepair(repair);
  Run(repair, this->Out);
  this->AfterRepair(repair->GetChanged(), repair);
}

// --html: everything this run made, in one self-contained page (the surface with its
// thickness when measured).
void Program::WritePage()
{
  if (this->Opt.Html.empty())
  {
    return;
  }
  this->Out.Begin("Writing " + this->Opt.Html);
  this->Out.ClearError();
  vtkNew<vtkMedialHTMLWriter> page;
  page->SetSurface(this->WallThickness ? this->WallThickness : this->Surface);
  page->SetBalls(this->Balls);
  page->SetMedialMesh(this->Mesh);
  page->SetGraph(this->Graph);
  page->SetReconstruction(this->Reconstruction);
  const std::string& input = this->Opt.Input;
  page->SetTitle(input.empty() ? (this->Opt.Balls.empty() ? "demo:jack" : this->Opt.Balls.c_str()) : input.c_str());
  page->SetDetails(this->Opt.CommandLine.c_str());
  page->SetViewDirection(this->Opt.View);
  page->SetFileName(this->Opt.Html.c_str());
  if (!page->Write() || !this->Out.GetError().empty())
  {
    Fail("cannot write '" + this->Opt.Html + "': " + this->Out.GetError());
  }
  this->Json << ", \"html_bytes\": " << page->GetNumberOfBytes()
             << ", \"html_balls_shown\": " << page->GetNumberOfDisplayedBalls();
  this->Out.End();
}

void Program::PrintStats()
{
  if (!this->Opt.Stats)
  {
    return;
  }
  if (this->Graph)
  {
    vtkIdType junctions = 0, ends = 0;
    vtkDataArray* types = this->Graph->GetPointData()->GetArray(vtkMedialArrayNames::MedialPointType);
    for (vtkIdType i = 0; i < this->Graph->GetNumberOfPoints(); ++i)
    {
      const int t = static_cast<int>(types->GetTuple1(i));
      junctions += t == vtkMedialJunctionFilter::JUNCTION_POINT ? 1 : 0;
      ends += t == vtkMedialJunctionFilter::END_POINT ? 1 : 0;
    }
    this->Json << ", \"junctions\": " << junctions << ", \"end_points\": " << ends
               << ", \"arcs\": " << this->Graph->GetNumberOfLines() << ", \"polygons\": " << this->Polygons;
  }
  std::cout << "{" << this->InputJson.str() << this->RepairJson.str() << this->Json.str() << "}" << std::endl;
}
}

int main(int argc, char* argv[])
{
  medialaxis::RestartWithRuntimeSettings(argv);
  const Options options = medialaxis::Parse(argc, argv);
  medialaxis::CheckOutputs(options); // before any work
  Console console(options.Quiet);
  Program program(options, console);
  program.LoadInput();
  program.Denoise();
  program.MedialGraph();
  program.SampleOrReadBalls();
  program.Reconstruct();
  program.MedialMesh();
  program.Thickness();
  program.Render();
  program.WritePage();
  program.PrintStats();
  return 0;
}
