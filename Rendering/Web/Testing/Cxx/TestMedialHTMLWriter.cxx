// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialHTMLWriter without a browser: the page's data read back from the HTML text
// (base64, zlib, VTK's vtk.js export) equals the input; above MaximumNumberOfBalls
// every k-th ball is kept and the manifest says so; a triangulated planar region is
// exported as its outline; the viewer's script cannot close its <script> element;
// bad input gives an error and no page. Without a viewer in this build (no npm) Write()
// fails with the reason, and the test is skipped.
#include "MedialTestSupport.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialHTMLWriter.h"
#include "vtkMedialJunctionFilter.h"
#include "vtkMedialShapeSource.h"

#include "vtkBase64Utilities.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkZLibDataCompressor.h"

#include <cmath>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

namespace
{
size_t Count(const std::string& text, const std::string& needle)
{
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
  {
    ++n;
  }
  return n;
}

// The text of the page's resource `url`, or "".
std::string Resource(const std::string& page, const std::string& url)
{
  const std::string open = "data-url=\"" + url + "\">";
  const size_t at = page.find(open);
  if (at == std::string::npos)
  {
    return "";
  }
  const size_t begin = at + open.size();
  return page.substr(begin, page.find("</script>", begin) - begin);
}

// The values of array `name` of dataset `dataset` ("balls", ...), decoded as the page's
// viewer decodes them: the dataset's index gives the array's id, its resource is
// base64 of zlib of the raw little-endian values.
template <class T>
std::vector<T> ArrayOf(const std::string& page, const std::string& dataset, const std::string& name)
{
  const std::string index = Resource(page, dataset + ".json");
  const std::regex entry("\"name\": \"" + name + "\"[^}]*\"id\": \"([^\"]+)\"");
  std::smatch match;
  if (!std::regex_search(index, match, entry))
  {
    return {};
  }
  const std::string text = Resource(page, "data/" + match[1].str() + ".gz");
  std::vector<unsigned char> packed(text.size());
  const size_t n = vtkBase64Utilities::DecodeSafely(
    reinterpret_cast<const unsigned char*>(text.data()), text.size(), packed.data(), packed.size());
  const std::regex size("\"name\": \"" + name + "\"[^}]*\}[^}]*\"size\": ([0-9]+)");
  if (!std::regex_search(index, match, size))
  {
    return {};
  }
  std::vector<T> values(std::stoul(match[1].str()));
  vtkNew<vtkZLibDataCompressor> zlib;
  const size_t bytes = zlib->Uncompress(
    packed.data(), n, reinterpret_cast<unsigned char*>(values.data()), values.size() * sizeof(T));
  return bytes == values.size() * sizeof(T) ? values : std::vector<T>();
}
}

int TestMedialHTMLWriter(int, char*[])
{
  std::string errors;
  vtkNew<vtkCallbackCommand> collect;
  collect->SetClientData(&errors);
  collect->SetCallback([](vtkObject*, unsigned long, void* client, void* text) {
    *static_cast<std::string*>(client) += std::string(static_cast<const char*>(text)) + "\n";
  });

  vtkNew<vtkMedialShapeSource> jack;
  jack->Update();
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(5000);
  sampler->SetNumberOfThreads(2);
  sampler->Update();
  vtkPolyData* balls = sampler->GetOutput();

  vtkNew<vtkMedialHTMLWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, collect);
  writer->SetSurface(jack->GetOutput());
  writer->SetBalls(balls);
  writer->WriteToOutputStringOn();
  if (!vtkMedialHTMLWriter::HasViewer())
  {
    MEDIAL_CHECK(writer->Write() == 0, "a page was written without a viewer");
    MEDIAL_CHECK(errors.find("no web viewer") != std::string::npos && std::strlen(vtkMedialHTMLWriter::GetViewerStatus()) > 0,
      "no reason given: '%s'", errors.c_str());
    std::printf("skipped: this build has no web viewer: %s\n", vtkMedialHTMLWriter::GetViewerStatus());
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }

  // 5000 balls, at most 1000 shown: every 5th, read back bit for bit as float32.
  writer->SetMaximumNumberOfBalls(1000);
  MEDIAL_CHECK(writer->Write() == 1, "Write failed: %s", errors.c_str());
  const std::string page = writer->GetOutputString();
  std::printf("page: %lld bytes (viewer %lld, data %lld), %lld of %lld balls, vtk.js %s\n",
    static_cast<long long>(writer->GetNumberOfBytes()), static_cast<long long>(writer->GetNumberOfViewerBytes()),
    static_cast<long long>(writer->GetNumberOfDataBytes()), static_cast<long long>(writer->GetNumberOfDisplayedBalls()),
    static_cast<long long>(writer->GetNumberOfBalls()), vtkMedialHTMLWriter::GetViewerVersion());
  MEDIAL_CHECK(writer->GetNumberOfBytes() == static_cast<vtkIdType>(page.size()), "size %lld", static_cast<long long>(page.size()));
  MEDIAL_CHECK(writer->GetNumberOfDisplayedBalls() == 1000 && writer->GetNumberOfBalls() == 5000, "%lld shown",
    static_cast<long long>(writer->GetNumberOfDisplayedBalls()));
  MEDIAL_CHECK(page.find("\"total\": 5000, \"stride\": 5, \"maximum\": 1000") != std::string::npos, "no decimation in the manifest");
  MEDIAL_CHECK(page.rfind("<!DOCTYPE html>", 0) == 0, "not an HTML page");
  // Every <script> is closed once: the viewer's text cannot end its element early.
  MEDIAL_CHECK(Count(page, "<script") == Count(page, "</script>"), "%zu <script, %zu </script>", Count(page, "<script"),
    Count(page, "</script>"));
  MEDIAL_CHECK(page.find("http://") == std::string::npos || page.find("src=\"http") == std::string::npos,
    "the page loads something from the network");
  const std::vector<float> xyz = ArrayOf<float>(page, "balls", "points");
  const std::vector<float> radius = ArrayOf<float>(page, "balls", "Radius");
  MEDIAL_CHECK(xyz.size() == 3000 && radius.size() == 1000, "%zu coordinates, %zu radii read back", xyz.size(), radius.size());
  for (vtkIdType k = 0; k < 1000; ++k)
  {
    double p[3];
    balls->GetPoint(5 * k, p);
    const float r = static_cast<float>(balls->GetPointData()->GetArray("Radius")->GetTuple1(5 * k));
    MEDIAL_CHECK(xyz[3 * k] == static_cast<float>(p[0]) && xyz[3 * k + 1] == static_cast<float>(p[1]) &&
        xyz[3 * k + 2] == static_cast<float>(p[2]) && radius[k] == r,
      "ball %lld read back differs", static_cast<long long>(k));
  }
  const std::vector<int> triangles = ArrayOf<int>(page, "surface", "polys");
  MEDIAL_CHECK(triangles.size() == static_cast<size_t>(4 * jack->GetOutput()->GetNumberOfPolys()) && triangles[0] == 3,
    "%zu cell values for %lld triangles", triangles.size(), static_cast<long long>(jack->GetOutput()->GetNumberOfPolys()));

  // A triangulated square region (8 triangles on a 3 x 3 grid of points) goes out as its
  // 8 boundary edges, with the 2D graph.
  vtkNew<vtkPoints> grid;
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      grid->InsertNextPoint(i, j, 0);
    }
  }
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      const vtkIdType a = 3 * j + i;
      const vtkIdType t1[3] = { a, a + 1, a + 4 }, t2[3] = { a, a + 4, a + 3 };
      cells->InsertNextCell(3, t1);
      cells->InsertNextCell(3, t2);
    }
  }
  vtkNew<vtkPolyData> region;
  region->SetPoints(grid);
  region->SetPolys(cells);
  vtkNew<vtkMedialJunctionFilter> graph;
  graph->SetInputData(region);
  graph->Update();
  vtkNew<vtkMedialHTMLWriter> planar;
  planar->AddObserver(vtkCommand::ErrorEvent, collect);
  planar->SetSurface(region);
  planar->SetGraph(graph->GetOutput());
  planar->WriteToOutputStringOn();
  MEDIAL_CHECK(planar->Write() == 1, "planar Write failed: %s", errors.c_str());
  const std::string page2d = planar->GetOutputString();
  MEDIAL_CHECK(page2d.find("\"planar\": true") != std::string::npos, "not planar");
  MEDIAL_CHECK(std::regex_search(page2d, std::regex("\"surface\": \\{\"url\": \"surface.json\", \"points\": [0-9]+, \"cells\": 8, \"outline\": true")),
    "the outline is not the 8 boundary edges");
  MEDIAL_CHECK(std::regex_search(page2d, std::regex("\"graph\": \\{\"url\": \"graph.json\", \"points\": [1-9]")), "no graph");

  // Bad input: an error, no page.
  errors.clear();
  vtkNew<vtkMedialHTMLWriter> empty;
  empty->AddObserver(vtkCommand::ErrorEvent, collect);
  empty->WriteToOutputStringOn();
  MEDIAL_CHECK(empty->Write() == 0 && errors.find("Nothing to show") != std::string::npos, "empty: '%s'", errors.c_str());
  errors.clear();
  vtkNew<vtkPolyData> bare;
  bare->SetPoints(grid);
  empty->SetBalls(bare);
  MEDIAL_CHECK(empty->Write() == 0 && errors.find("'Radius'") != std::string::npos, "no radius: '%s'", errors.c_str());
  errors.clear();
  writer->WriteToOutputStringOff();
  writer->SetFileName("/nonexistent-folder/page.html");
  MEDIAL_CHECK(writer->Write() == 0 && errors.find("Cannot open '/nonexistent-folder/page.html'") != std::string::npos,
    "unwritable: '%s'", errors.c_str());
  return EXIT_SUCCESS;
}
