// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialThickness on bad input: errors for what has no surface, a warning and NaN
// where an open surface lets the ray escape, NaN for a point no cell uses, and the
// same output whatever the thread count.
#include "MedialThicknessTestUtilities.h"

#include "vtkMedialRepairFilter.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"

#include <cstdlib>
#include <cstring>

using namespace medialtest;

namespace
{
vtkSmartPointer<vtkPolyData> Run(vtkPolyData* input, EventLog& log, int threads = 0)
{
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputData(input);
  thickness->SetNumberOfThreads(threads);
  thickness->SetRepairMode(vtkMedialRepairFilter::NONE); // the input as it is
  log.Watch(thickness);
  thickness->Update();
  return thickness->GetOutput();
}
}

int TestMedialThicknessBadInput(int, char*[])
{
  {
    vtkNew<vtkPolyData> empty;
    EventLog log;
    Run(empty, log);
    MEDIAL_CHECK(log.Errors > 0 && !log.LineWith("no points or no cells").empty(), "empty: %s", log.Text.c_str());
  }
  {
    vtkNew<vtkPolyData> lines;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    points->InsertNextPoint(0, 1, 1);
    vtkNew<vtkCellArray> cells;
    const vtkIdType line[3] = { 0, 1, 2 };
    cells->InsertNextCell(3, line);
    lines->SetPoints(points);
    lines->SetLines(cells);
    EventLog log;
    Run(lines, log);
    MEDIAL_CHECK(log.Errors > 0 && !log.LineWith("a surface is required").empty(), "lines: %s", log.Text.c_str());
  }
  {
    // A sphere without its polar cap, and an extra point that no cell uses.
    auto sphere = MakeShape(vtkMedialShapeSource::SPHERE, 4);
    vtkNew<vtkCellArray> kept;
    for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      sphere->GetCellPoints(c, n, ids);
      double z = 0;
      for (vtkIdType k = 0; k < n; ++k)
      {
        z += sphere->GetPoint(ids[k])[2] / n;
      }
      if (z < 0.8)
      {
        kept->InsertNextCell(n, ids);
      }
    }
    vtkNew<vtkPolyData> open;
    vtkNew<vtkPoints> points;
    points->DeepCopy(sphere->GetPoints());
    const vtkIdType lonely = points->InsertNextPoint(0, 0, 0);
    open->SetPoints(points);
    open->SetPolys(kept);
    EventLog log;
    auto out = Run(open, log);
    const std::string warning = log.LineWith("Input surface is open");
    std::printf("warning: %s\n", warning.c_str());
    MEDIAL_CHECK(log.Errors == 0 && !warning.empty(), "open: %s", log.Text.c_str());
    vtkDataArray* t = out->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    MEDIAL_CHECK(std::isnan(t->GetComponent(lonely, 0)), "the unused point has a value");
    vtkIdType nan = 0;
    for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
    {
      nan += std::isnan(t->GetComponent(i, 0)) ? 1 : 0;
    }
    MEDIAL_CHECK(nan > 1 && nan < t->GetNumberOfTuples() / 2, "%lld NaN values", static_cast<long long>(nan));
  }
  {
    // One thread or two: the same bytes.
    auto jack = MakeShape(vtkMedialShapeSource::JACK, 10);
    EventLog a, b;
    auto one = Run(jack, a, 1);
    auto two = Run(jack, b, 2);
    for (const char* name : { vtkMedialArrayNames::Thickness, vtkMedialArrayNames::MedialCentre, vtkMedialArrayNames::RayThickness })
    {
      vtkDataArray* u = one->GetPointData()->GetArray(name);
      vtkDataArray* v = two->GetPointData()->GetArray(name);
      for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
      {
        for (int c = 0; c < u->GetNumberOfComponents(); ++c)
        {
          const double x = u->GetComponent(i, c), y = v->GetComponent(i, c);
          MEDIAL_CHECK(std::memcmp(&x, &y, sizeof(double)) == 0, "%s differs at %lld", name, static_cast<long long>(i));
        }
      }
    }
  }
  return EXIT_SUCCESS;
}
