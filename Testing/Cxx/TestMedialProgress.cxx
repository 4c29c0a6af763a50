// SPDX-License-Identifier: BSD-3-Clause
// Every long stage of every filter reports VTK progress under its own name (the
// algorithm's progress text), so the command line and ParaView can show it. Each
// filter runs once on generated data with an observer that records (text, value)
// pairs. Checks, per filter: the expected stages appear in order; the long ones
// report progress inside the stage (at least three events); values never go back;
// the run ends at 1.
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialBallProtrusion.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialFileReader.h"
#include "vtkMedialFileWriter.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
struct Recorder
{
  std::vector<std::pair<std::string, double>> Events;
  vtkNew<vtkCallbackCommand> Command;
  explicit Recorder(vtkAlgorithm* algorithm)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
      const char* text = static_cast<vtkAlgorithm*>(caller)->GetProgressText();
      static_cast<Recorder*>(client)->Events.emplace_back(text ? text : "", *static_cast<double*>(data));
    });
    algorithm->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
};

struct Stage
{
  const char* Text;
  bool Long; // reports progress inside the stage
};

// The checks of the file comment; prints the stages seen.
int Check(const char* filter, const Recorder& r, const std::vector<Stage>& stages)
{
  std::printf("%s:", filter);
  std::string last = "\x01";
  for (const auto& e : r.Events)
  {
    if (e.first != last)
    {
      std::printf(" [%s] %.3f", e.first.c_str(), e.second);
      last = e.first;
    }
  }
  std::printf(" ... %.3f (%zu events)\n", r.Events.empty() ? -1.0 : r.Events.back().second, r.Events.size());
  MEDIAL_CHECK(!r.Events.empty() && r.Events.back().second == 1.0, "%s: the run does not end at 1", filter);
  for (size_t i = 1; i < r.Events.size(); ++i)
  {
    MEDIAL_CHECK(r.Events[i].second >= r.Events[i - 1].second - 1e-12, "%s: progress goes back at '%s' (%g < %g)",
      filter, r.Events[i].first.c_str(), r.Events[i].second, r.Events[i - 1].second);
  }
  size_t at = 0;
  for (const Stage& stage : stages)
  {
    while (at < r.Events.size() && r.Events[at].first != stage.Text)
    {
      ++at;
    }
    MEDIAL_CHECK(at < r.Events.size(), "%s: no progress from the stage '%s' (or out of order)", filter, stage.Text);
    int count = 0;
    for (; at < r.Events.size() && r.Events[at].first == stage.Text; ++at)
    {
      ++count;
    }
    MEDIAL_CHECK(!stage.Long || count >= 3, "%s: the long stage '%s' reports %d events", filter, stage.Text, count);
  }
  return EXIT_SUCCESS;
}

int ReadingAndSampling(const std::string& folder)
{
  // A 20480-triangle sphere as OFF: 30k lines, so the reader reports along the way.
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(5);
  sphere->Update();
  vtkPolyData* mesh = sphere->GetOutput();
  const std::string off = folder + "/sphere.off";
  {
    std::ofstream file(off);
    file << "OFF\n" << mesh->GetNumberOfPoints() << " " << mesh->GetNumberOfPolys() << " 0\n";
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      const double* p = mesh->GetPoint(i);
      file << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    vtkIdType n;
    const vtkIdType* ids;
    for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(n, ids);)
    {
      file << "3 " << ids[0] << " " << ids[1] << " " << ids[2] << "\n";
    }
  }
  vtkNew<vtkMedialFileReader> reader;
  reader->SetFileName(off.c_str());
  Recorder reading(reader);
  reader->Update();
  if (Check("vtkMedialFileReader (OFF)", reading, { { "Reading the surface", true } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(reader->GetOutputPort());
  sampler->SetNumberOfSamples(20000);
  sampler->SetNumberOfThreads(2);
  Recorder sampling(sampler);
  sampler->Update();
  if (Check("vtkMedialAxisSampler", sampling,
        { { "Preparing the surface", false }, { "Building the surface queries", false },
          { "Drawing the samples", false }, { "Sampling", true } }) !=
    EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialAxisSampler> strategy;
  strategy->SetInputConnection(reader->GetOutputPort());
  strategy->SetNumberOfSamples(3000);
  strategy->SetSamplingStrategy(vtkMedialAxisSampler::FACE_DISTANCE);
  Recorder iterative(strategy);
  strategy->Update();
  if (Check("vtkMedialAxisSampler (face-distance)", iterative,
        { { "Preparing the surface", false }, { "Building the surface queries", false },
          { "Sampling (face-distance strategy)", true } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  // Balls written and read back: .ma and PLY report as they read.
  for (const char* name : { "/balls.ma", "/balls.ply" })
  {
    vtkNew<vtkMedialFileWriter> writer;
    writer->SetInputConnection(sampler->GetOutputPort());
    writer->SetContentToBalls();
    writer->SetFileName((folder + name).c_str());
    MEDIAL_CHECK(writer->Write() == 1, "cannot write %s", name);
    vtkNew<vtkMedialFileReader> balls;
    balls->SetContentToBalls();
    balls->SetFileName((folder + name).c_str());
    Recorder ballReading(balls);
    balls->Update();
    if (Check(name + 1, ballReading, { { "Reading the balls", true } }) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }

  // Reconstruction and its measures.
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(64, 64, 64);
  Recorder union_(ballUnion);
  ballUnion->Update();
  if (Check("vtkMedialBallUnion", union_,
        { { "Gathering the balls", false }, { "Filling the distance field", true },
          { "Contouring the surface", false } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialReconstructionError> error;
  error->SetOriginalConnection(reader->GetOutputPort());
  error->SetReconstructionConnection(ballUnion->GetOutputPort());
  Recorder measuring(error);
  error->Update();
  if (Check("vtkMedialReconstructionError", measuring,
        { { "Building the distance queries", false }, { "Measuring from the vertices", false },
          { "Measuring from area samples", true } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialBallProtrusion> protrusion;
  protrusion->SetInputConnection(0, reader->GetOutputPort());
  protrusion->SetInputConnection(1, sampler->GetOutputPort());
  Recorder protruding(protrusion);
  protrusion->Update();
  if (Check("vtkMedialBallProtrusion", protruding,
        { { "Building the distance queries", false }, { "Measuring the balls", false } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialBallClassifier> classifier;
  classifier->SetInputConnection(sampler->GetOutputPort());
  classifier->SetSurfaceConnection(reader->GetOutputPort());
  Recorder classifying(classifier);
  classifier->Update();
  if (Check("vtkMedialBallClassifier", classifying,
        { { "Preparing the surface and its governors", false }, { "Classifying the balls", true },
          { "Solving seams and junctions", false } }) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputConnection(reader->GetOutputPort());
  thickness->SetThinThreshold(0.1); // cell thickness too
  Recorder measuringThickness(thickness);
  thickness->Update();
  if (Check("vtkMedialThickness", measuringThickness,
        { { "Preparing the surface", false }, { "Building the surface queries", false },
          { "Measuring the thickness at the vertices", true }, { "Measuring the thickness at the cells", true } }) !=
    EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialMeshFilter> medialMesh; // samples itself: the sampler's progress is a stage
  medialMesh->SetInputConnection(reader->GetOutputPort());
  medialMesh->GetSampler()->SetNumberOfSamples(3000);
  Recorder meshing(medialMesh);
  medialMesh->Update();
  return Check("vtkMedialMeshFilter", meshing,
    { { "Preparing the surface", false }, { "Sampling", true }, { "Classifying the balls", true },
      { "Inscribing the balls", false }, { "Building the regular triangulation", false },
      { "Building the medial mesh", false }, { "Writing the mesh", false } });
}

int Planar()
{
  vtkNew<vtkMedialShapeSource> star;
  star->SetShapeToStar();
  star->SetResolution(9);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(star->GetOutputPort());
  sampler->SetNumberOfSamples(20000);
  Recorder sampling(sampler);
  sampler->Update();
  if (Check("vtkMedialAxisSampler (2D)", sampling, { { "Preparing the polygon", false }, { "Sampling", true } }) !=
    EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkMedialJunctionFilter> junctions;
  junctions->SetInputConnection(star->GetOutputPort());
  junctions->SetSamplesPerUnitLength(20000); // more boundary samples than one block
  Recorder graph(junctions);
  junctions->Update();
  return Check("vtkMedialJunctionFilter", graph,
    { { "Preparing the polygon", false }, { "Solving the boundary disks", true }, { "Finding the junctions", true },
      { "Connecting the graph", false } });
}
}

int main()
{
  std::string pattern = (std::filesystem::temp_directory_path() / "medial-progress-XXXXXX").string();
  MEDIAL_CHECK(mkdtemp(pattern.data()), "cannot create a temporary folder");
  const int result = ReadingAndSampling(pattern) == EXIT_SUCCESS ? Planar() : EXIT_FAILURE;
  std::error_code ignored;
  std::filesystem::remove_all(pattern, ignored);
  return result;
}
