// SPDX-License-Identifier: BSD-3-Clause
// Polyhedra built in double precision for the 3D exactness tests: convex hulls of
// points in general position and prisms over planar polygons.
#ifndef MedialPolyhedronTestUtilities_h
#define MedialPolyhedronTestUtilities_h

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace medialtest
{
// Incremental convex hull (points in general position), outward-wound triangles.
inline vtkSmartPointer<vtkPolyData> ConvexHull(const std::vector<std::array<double, 3>>& x)
{
  using Face = std::array<int, 3>;
  auto orient = [&x](int a, int b, int c, int d) {
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = x[b][k] - x[a][k];
      v[k] = x[c][k] - x[a][k];
      w[k] = x[d][k] - x[a][k];
    }
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
  };
  // Outward faces see the fourth vertex on their negative side.
  std::vector<Face> faces;
  for (Face f : { Face{ 0, 1, 2 }, Face{ 0, 1, 3 }, Face{ 0, 2, 3 }, Face{ 1, 2, 3 } })
  {
    const int other = 6 - f[0] - f[1] - f[2];
    if (orient(f[0], f[1], f[2], other) > 0)
    {
      std::swap(f[1], f[2]);
    }
    faces.push_back(f);
  }
  for (int p = 4; p < static_cast<int>(x.size()); ++p)
  {
    std::vector<char> visible(faces.size());
    bool any = false;
    for (size_t f = 0; f < faces.size(); ++f)
    {
      visible[f] = orient(faces[f][0], faces[f][1], faces[f][2], p) > 1e-12;
      any = any || visible[f];
    }
    if (!any)
    {
      continue;
    }
    // Horizon: directed edges of visible faces whose reverse is not on a visible face.
    std::map<std::pair<int, int>, int> edges;
    for (size_t f = 0; f < faces.size(); ++f)
    {
      if (visible[f])
      {
        for (int e = 0; e < 3; ++e)
        {
          edges[{ faces[f][e], faces[f][(e + 1) % 3] }] = 1;
        }
      }
    }
    std::vector<Face> next;
    for (size_t f = 0; f < faces.size(); ++f)
    {
      if (!visible[f])
      {
        next.push_back(faces[f]);
      }
    }
    for (const auto& e : edges)
    {
      if (!edges.count({ e.first.second, e.first.first }))
      {
        next.push_back({ e.first.first, e.first.second, p });
      }
    }
    faces.swap(next);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : x)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const Face& f : faces)
  {
    const vtkIdType ids[3] = { f[0], f[1], f[2] };
    cells->InsertNextCell(3, ids);
  }
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}

/// The prism of height h over a simple polygon in the z = 0 plane (counter-clockwise
/// seen from +z): two polygon caps and one quad per side, double-precision points.
inline vtkSmartPointer<vtkPolyData> Prism(const std::vector<std::array<double, 2>>& polygon, double h)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType n = static_cast<vtkIdType>(polygon.size());
  for (double z : { 0.0, h })
  {
    for (const auto& p : polygon)
    {
      points->InsertNextPoint(p[0], p[1], z);
    }
  }
  vtkNew<vtkCellArray> cells;
  std::vector<vtkIdType> bottom, top;
  for (vtkIdType i = 0; i < n; ++i)
  {
    bottom.push_back(n - 1 - i); // clockwise from +z: outward is -z
    top.push_back(n + i);
    const vtkIdType j = (i + 1) % n;
    const vtkIdType side[4] = { i, j, n + j, n + i };
    cells->InsertNextCell(4, side);
  }
  cells->InsertNextCell(n, bottom.data());
  cells->InsertNextCell(n, top.data());
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}

/// A polyhedron with axis-aligned polygon faces, each given by its corners and its
/// outward axis (0, 1, 2) and sign; the corners are reversed where their (Newell)
/// normal points the other way, so every face is counter-clockwise seen from outside.
struct AxisFace
{
  std::vector<std::array<double, 3>> Corners;
  int Axis;
  double Sign;
};
inline vtkSmartPointer<vtkPolyData> AxisAlignedPolyhedron(const std::vector<AxisFace>& faces)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (AxisFace face : faces)
  {
    auto& corners = face.Corners;
    double normal = 0.0;
    const int u = (face.Axis + 1) % 3, v = (face.Axis + 2) % 3;
    for (size_t i = 0; i < corners.size(); ++i)
    {
      const auto& p = corners[i];
      const auto& q = corners[(i + 1) % corners.size()];
      normal += (p[u] - q[u]) * (p[v] + q[v]);
    }
    if (normal * face.Sign < 0.0)
    {
      std::reverse(corners.begin(), corners.end());
    }
    std::vector<vtkIdType> ids;
    for (const auto& p : corners)
    {
      ids.push_back(points->InsertNextPoint(p.data()));
    }
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}

/// The box [0, A] x [0, B] x [0, C] without the corner box [a, A] x [b, B] x [c, C]:
/// three reflex edges meeting at the reflex vertex (a, b, c).
inline vtkSmartPointer<vtkPolyData> NotchedBox(double A, double B, double C, double a, double b, double c)
{
  return AxisAlignedPolyhedron({
    { { { 0, 0, 0 }, { 0, B, 0 }, { 0, B, C }, { 0, 0, C } }, 0, -1 },
    { { { 0, 0, 0 }, { A, 0, 0 }, { A, 0, C }, { 0, 0, C } }, 1, -1 },
    { { { 0, 0, 0 }, { A, 0, 0 }, { A, B, 0 }, { 0, B, 0 } }, 2, -1 },
    { { { A, 0, 0 }, { A, B, 0 }, { A, B, c }, { A, b, c }, { A, b, C }, { A, 0, C } }, 0, 1 },
    { { { 0, B, 0 }, { A, B, 0 }, { A, B, c }, { a, B, c }, { a, B, C }, { 0, B, C } }, 1, 1 },
    { { { 0, 0, C }, { A, 0, C }, { A, b, C }, { a, b, C }, { a, B, C }, { 0, B, C } }, 2, 1 },
    { { { a, b, c }, { a, B, c }, { a, B, C }, { a, b, C } }, 0, 1 },
    { { { a, b, c }, { A, b, c }, { A, b, C }, { a, b, C } }, 1, 1 },
    { { { a, b, c }, { A, b, c }, { A, B, c }, { a, B, c } }, 2, 1 },
  });
}

/// The box [0, X] x [0, Y] x [0, Z] with a channel along x cut into its top,
/// [y1, y2] x [z1, Z], and one along y cut into its bottom, [x1, x2] x [0, z2]
/// (z2 < z1): four reflex edges, two along x and two along y, skew to each other.
inline vtkSmartPointer<vtkPolyData> CrossedGrooves(
  double X, double Y, double Z, double y1, double y2, double z1, double x1, double x2, double z2)
{
  return AxisAlignedPolyhedron({
    // Top strips, the top channel's floor and walls.
    { { { 0, 0, Z }, { X, 0, Z }, { X, y1, Z }, { 0, y1, Z } }, 2, 1 },
    { { { 0, y2, Z }, { X, y2, Z }, { X, Y, Z }, { 0, Y, Z } }, 2, 1 },
    { { { 0, y1, z1 }, { X, y1, z1 }, { X, y2, z1 }, { 0, y2, z1 } }, 2, 1 },
    { { { 0, y1, z1 }, { X, y1, z1 }, { X, y1, Z }, { 0, y1, Z } }, 1, 1 },
    { { { 0, y2, z1 }, { X, y2, z1 }, { X, y2, Z }, { 0, y2, Z } }, 1, -1 },
    // Bottom strips, the bottom channel's ceiling and walls.
    { { { 0, 0, 0 }, { x1, 0, 0 }, { x1, Y, 0 }, { 0, Y, 0 } }, 2, -1 },
    { { { x2, 0, 0 }, { X, 0, 0 }, { X, Y, 0 }, { x2, Y, 0 } }, 2, -1 },
    { { { x1, 0, z2 }, { x2, 0, z2 }, { x2, Y, z2 }, { x1, Y, z2 } }, 2, -1 },
    { { { x1, 0, 0 }, { x1, Y, 0 }, { x1, Y, z2 }, { x1, 0, z2 } }, 0, 1 },
    { { { x2, 0, 0 }, { x2, Y, 0 }, { x2, Y, z2 }, { x2, 0, z2 } }, 0, -1 },
    // Sides: U-shaped around each channel's ends.
    { { { 0, 0, 0 }, { 0, Y, 0 }, { 0, Y, Z }, { 0, y2, Z }, { 0, y2, z1 }, { 0, y1, z1 }, { 0, y1, Z }, { 0, 0, Z } },
      0, -1 },
    { { { X, 0, 0 }, { X, Y, 0 }, { X, Y, Z }, { X, y2, Z }, { X, y2, z1 }, { X, y1, z1 }, { X, y1, Z }, { X, 0, Z } },
      0, 1 },
    { { { 0, 0, 0 }, { x1, 0, 0 }, { x1, 0, z2 }, { x2, 0, z2 }, { x2, 0, 0 }, { X, 0, 0 }, { X, 0, Z }, { 0, 0, Z } },
      1, -1 },
    { { { 0, Y, 0 }, { x1, Y, 0 }, { x1, Y, z2 }, { x2, Y, z2 }, { x2, Y, 0 }, { X, Y, 0 }, { X, Y, Z }, { 0, Y, Z } },
      1, 1 },
  });
}
}

#endif
