// SPDX-License-Identifier: BSD-3-Clause
// Helpers for the 2D tests: polygons as vtkPolyData, and junctions read back from a medial graph.
#ifndef MedialPolygonTestUtilities_h
#define MedialPolygonTestUtilities_h

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <vector>

namespace medialtest
{
using Loop2 = std::vector<std::array<double, 2>>;

/// Loops as polygon cells (asLines: closed polylines, first point repeated) in the z = 0 plane.
inline vtkSmartPointer<vtkPolyData> MakePolygon(const std::vector<Loop2>& loops, bool asLines = false)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (const auto& l : loops)
  {
    std::vector<vtkIdType> ids;
    for (const auto& p : l)
    {
      ids.push_back(pts->InsertNextPoint(p[0], p[1], 0.0));
    }
    if (asLines)
    {
      ids.push_back(ids.front());
    }
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  pd->SetPoints(pts);
  if (asLines)
  {
    pd->SetLines(cells);
  }
  else
  {
    pd->SetPolys(cells);
  }
  return pd;
}

/// One polyline cell per piece of 3D points.
inline vtkSmartPointer<vtkPolyData> MakePolylines(const std::vector<std::vector<std::array<double, 3>>>& pieces)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const auto& piece : pieces)
  {
    std::vector<vtkIdType> ids;
    for (const auto& p : piece)
    {
      ids.push_back(points->InsertNextPoint(p.data()));
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  pd->SetPoints(points);
  pd->SetLines(lines);
  return pd;
}

inline Loop2 Rectangle(double x0, double y0, double x1, double y1)
{
  return { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } };
}

inline Loop2 RegularPolygon(int n, double radius, double phase = 0.0)
{
  Loop2 l;
  for (int i = 0; i < n; ++i)
  {
    const double a = phase + 2.0 * 3.14159265358979323846 * i / n;
    l.push_back({ radius * std::cos(a), radius * std::sin(a) });
  }
  return l;
}

struct MedialNode
{
  double X[3];
  double Radius;
  int Governors;
};

/// Points of a junction-filter output with the given MedialPointType.
inline std::vector<MedialNode> NodesOfType(vtkPolyData* graph, int type)
{
  std::vector<MedialNode> out;
  vtkDataArray* t = graph->GetPointData()->GetArray("MedialPointType");
  vtkDataArray* r = graph->GetPointData()->GetArray("Radius");
  vtkDataArray* g = graph->GetPointData()->GetArray("GovernorCount");
  for (vtkIdType i = 0; t && i < graph->GetNumberOfPoints(); ++i)
  {
    if (static_cast<int>(t->GetTuple1(i)) == type)
    {
      MedialNode n;
      graph->GetPoint(i, n.X);
      n.Radius = r->GetTuple1(i);
      n.Governors = static_cast<int>(g->GetTuple1(i));
      out.push_back(n);
    }
  }
  return out;
}

/// Largest distance from any expected point to its nearest node; +inf if nodes is empty.
inline double MatchError(const std::vector<MedialNode>& nodes, const std::vector<std::array<double, 3>>& expected)
{
  double worst = 0.0;
  for (const auto& e : expected)
  {
    double best = HUGE_VAL;
    for (const auto& n : nodes)
    {
      best = std::min(best, std::sqrt((n.X[0] - e[0]) * (n.X[0] - e[0]) + (n.X[1] - e[1]) * (n.X[1] - e[1]) +
                              (n.X[2] - e[2]) * (n.X[2] - e[2])));
    }
    worst = std::max(worst, best);
  }
  return worst;
}
}

#endif
