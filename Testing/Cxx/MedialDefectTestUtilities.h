// SPDX-License-Identifier: BSD-3-Clause
// Generated defective surfaces whose solid is known, for the repair's tests and its
// benchmark (medial-repair-bench): each comes with the true solid's depth function,
// its largest inscribed ball, its Euler characteristic and how far the mesh may
// deviate from it. Every defect is built from vtkMedialShapeSource's shapes or in code,
// deterministically (mt19937_64 with fixed seeds).
#ifndef MedialDefectTestUtilities_h
#define MedialDefectTestUtilities_h

#include "MedialShapeTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkMedialShapeSource.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace medialtest
{
/// A surface's points and polygons as bytes: what the repair's repeat and weld tests compare
/// between runs.
inline std::vector<unsigned char> SurfaceBytes(vtkPolyData* pd)
{
  std::vector<unsigned char> bytes;
  auto add = [&bytes](const void* data, size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), p, p + size);
  };
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    add(x, sizeof(x));
  }
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto cells = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(n, ids);
    add(&n, sizeof(n));
    add(ids, static_cast<size_t>(n) * sizeof(vtkIdType));
  }
  return bytes;
}

struct Defect
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Surface;
  /// Distance from x to the true solid's boundary: positive inside, negative outside.
  std::function<double(const double x[3])> Depth;
  double Tolerance = 0.0;   // how far the mesh may deviate from the true solid
  double LargestBall = 0.0; // the true solid's largest inscribed radius
  int Euler = 0;            // the true solid's Euler characteristic
  bool Clean = false;       // already a valid solid: the repair must leave it untouched
};

namespace defects
{
using Point = std::array<double, 3>;

inline double Norm(const double x[3])
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

inline vtkSmartPointer<vtkPolyData> Shape(int shape, int resolution, const std::function<void(vtkMedialShapeSource*)>& set = {})
{
  return MakeShape(shape, resolution, set);
}

/// A polydata of the given points and triangles.
inline vtkSmartPointer<vtkPolyData> Mesh(const std::vector<Point>& points, const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (const Point& x : points)
  {
    p->InsertNextPoint(x.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : triangles)
  {
    cells->InsertNextCell(3, t.data());
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(p);
  out->SetPolys(cells);
  return out;
}

inline std::vector<Point> Points(vtkPolyData* pd)
{
  std::vector<Point> x(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pd->GetPoint(i, x[i].data());
  }
  return x;
}

inline std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* pd)
{
  std::vector<std::array<vtkIdType, 3>> t;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      t.push_back({ ids[0], ids[1], ids[2] });
    }
  }
  return t;
}

inline vtkSmartPointer<vtkPolyData> Translated(vtkPolyData* pd, double dx, double dy, double dz)
{
  std::vector<Point> x = Points(pd);
  for (Point& p : x)
  {
    p[0] += dx;
    p[1] += dy;
    p[2] += dz;
  }
  return Mesh(x, Triangles(pd));
}

inline vtkSmartPointer<vtkPolyData> Append(vtkPolyData* a, vtkPolyData* b)
{
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(a);
  append->AddInputData(b);
  append->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(append->GetOutput());
  return out;
}

// Depth in the box [lo, hi] (exact for a box: the distance to the nearest face inside,
// minus the distance to the box outside).
inline double BoxDepth(const double x[3], const double lo[3], const double hi[3])
{
  double inside = HUGE_VAL, outside2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    inside = std::min({ inside, x[k] - lo[k], hi[k] - x[k] });
    const double out = std::max({ lo[k] - x[k], x[k] - hi[k], 0.0 });
    outside2 += out * out;
  }
  return outside2 > 0.0 ? -std::sqrt(outside2) : inside;
}

// The largest chord deviation of a geodesic sphere of radius 1 with `resolution`
// splits: its longest edge's sagitta, with margin.
inline double GeodesicSagitta(int resolution)
{
  const double edge = 1.1071487 / (1 << resolution); // the icosahedron's edge angle, split
  return 2.0 * (1.0 - std::cos(0.5 * edge * 1.3));
}

/// A closed tube of radius `a` along the figure eight (2 sin t, sin 2t, 0): one closed
/// shell (a torus) that crosses itself where the curve does, at the origin at right
/// angles. Its solid is the union of the balls along the curve, the tubular neighbourhood
/// of a figure eight: genus 2, Euler characteristic -1, largest ball a.
inline Defect CrossingShell()
{
  const double a = 0.3;
  const int n = 240, m = 24;
  auto curve = [](double t, double c[3], double tangent[3]) {
    c[0] = 2.0 * std::sin(t);
    c[1] = std::sin(2.0 * t);
    c[2] = 0.0;
    tangent[0] = 2.0 * std::cos(t);
    tangent[1] = 2.0 * std::cos(2.0 * t);
    tangent[2] = 0.0;
    const double l = Norm(tangent);
    for (int k = 0; k < 3; ++k)
    {
      tangent[k] /= l;
    }
  };
  std::vector<Point> x;
  std::vector<std::array<vtkIdType, 3>> tris;
  for (int i = 0; i < n; ++i)
  {
    double c[3], t[3];
    curve(2.0 * M_PI * i / n, c, t);
    const double side[3] = { -t[1], t[0], 0.0 };
    for (int j = 0; j < m; ++j)
    {
      const double phi = 2.0 * M_PI * j / m;
      x.push_back({ c[0] + a * (std::cos(phi) * side[0]), c[1] + a * (std::cos(phi) * side[1]), a * std::sin(phi) });
    }
  }
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const vtkIdType p00 = i * m + j, p01 = i * m + (j + 1) % m, p10 = ((i + 1) % n) * m + j,
                      p11 = ((i + 1) % n) * m + (j + 1) % m;
      tris.push_back({ p00, p10, p11 });
      tris.push_back({ p00, p11, p01 });
    }
  }
  // Depth: a minus the distance to the curve, the curve sampled finely and refined by
  // ternary search steps around the nearest sample.
  auto depth = [a](const double y[3]) {
    const int samples = 4096;
    double best = HUGE_VAL;
    auto distance = [&](double t) {
      const double c[3] = { 2.0 * std::sin(t), std::sin(2.0 * t), 0.0 };
      const double d[3] = { y[0] - c[0], y[1] - c[1], y[2] - c[2] };
      return Norm(d);
    };
    int bestI = 0;
    for (int i = 0; i < samples; ++i)
    {
      const double d = distance(2.0 * M_PI * i / samples);
      if (d < best)
      {
        best = d;
        bestI = i;
      }
    }
    double lo = 2.0 * M_PI * (bestI - 1) / samples, hi = 2.0 * M_PI * (bestI + 1) / samples;
    for (int k = 0; k < 40; ++k)
    {
      const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
      if (distance(m1) < distance(m2))
      {
        hi = m2;
      }
      else
      {
        lo = m1;
      }
    }
    best = std::min(best, distance(0.5 * (lo + hi)));
    return a - best;
  };
  // The tube's polygons cut inside the circle of radius a by 1 - cos(pi / m) of it,
  // and along the curve by its chords.
  return { "crossing shell", Mesh(x, tris), depth, 0.01, a, -1, false };
}

/// Two closed unit spheres (geodesic, 5120 triangles each) whose centres are 1.2 apart,
/// in one surface: an un-booleaned union. Solid: the union (Euler characteristic 1,
/// largest ball 1.0, at either centre).
inline Defect OverlappingSpheres()
{
  auto sphere = Shape(vtkMedialShapeSource::SPHERE, 4);
  auto both = Append(sphere, Translated(sphere, 1.2, 0.0, 0.0));
  auto depth = [](const double x[3]) {
    // The union's boundary is each sphere outside the other: the nearest point of a
    // sphere's part outside the other is its radial projection when that lies outside
    // the other ball, else on the circle where they meet (x = 0.6, radius 0.8).
    const double centres[2][3] = { { 0, 0, 0 }, { 1.2, 0, 0 } };
    double inside = -HUGE_VAL, boundary = HUGE_VAL;
    for (int s = 0; s < 2; ++s)
    {
      const double* c = centres[s];
      const double* o = centres[1 - s];
      double d[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
      const double r = Norm(d);
      inside = std::max(inside, 1.0 - r);
      double q[3] = { c[0] + 1, c[1], c[2] };
      if (r > 0.0)
      {
        for (int k = 0; k < 3; ++k)
        {
          q[k] = c[k] + d[k] / r;
        }
      }
      const double qo[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] };
      if (Norm(qo) >= 1.0)
      {
        boundary = std::min(boundary, std::fabs(1.0 - r));
      }
      else
      {
        const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2]);
        const double dx = x[0] - 0.6, dr = rho - 0.8;
        boundary = std::min(boundary, std::sqrt(dx * dx + dr * dr));
      }
    }
    return inside > 0.0 ? boundary : inside;
  };
  return { "overlapping spheres", both, depth, GeodesicSagitta(4), 1.0, 1, false };
}

/// A unit sphere (geodesic, 5120 triangles) with three small holes (the triangles within
/// 0.15 rad of three directions removed). Solid: the ball.
inline Defect SphereWithHoles()
{
  auto sphere = Shape(vtkMedialShapeSource::SPHERE, 4);
  const std::vector<Point> x = Points(sphere);
  std::vector<std::array<vtkIdType, 3>> kept;
  const double holes[3][3] = { { 0, 0, 1 }, { 0.8, 0.6, 0 }, { -0.6, 0, -0.8 } };
  for (const auto& t : Triangles(sphere))
  {
    double c[3] = { 0, 0, 0 };
    for (vtkIdType v : t)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[k] += x[v][k] / 3.0;
      }
    }
    const double r = Norm(c);
    bool hole = false;
    for (const auto& h : holes)
    {
      hole = hole || (c[0] * h[0] + c[1] * h[1] + c[2] * h[2]) / r > std::cos(0.15);
    }
    if (!hole)
    {
      kept.push_back(t);
    }
  }
  auto depth = [](const double y[3]) { return 1.0 - Norm(y); };
  return { "sphere with holes", Mesh(x, kept), depth, GeodesicSagitta(4) + 0.02, 1.0, 1, false };
}

/// A box (1 x 0.8 x 0.6, faces split 6 x 6) saved as a triangle soup: every triangle
/// has its own three corners, each coordinate moved by up to 1e-7. Solid: the box.
inline Defect JitteredSoup()
{
  auto box = Shape(vtkMedialShapeSource::BOX, 6, [](vtkMedialShapeSource* s) { s->SetBoxLengths(1.0, 0.8, 0.6); });
  const std::vector<Point> x = Points(box);
  std::vector<Point> soup;
  std::vector<std::array<vtkIdType, 3>> tris;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> jitter(-1e-7, 1e-7);
  for (const auto& t : Triangles(box))
  {
    std::array<vtkIdType, 3> own;
    for (int i = 0; i < 3; ++i)
    {
      Point p = x[t[i]];
      for (double& c : p)
      {
        c += jitter(random);
      }
      own[i] = static_cast<vtkIdType>(soup.size());
      soup.push_back(p);
    }
    tris.push_back(own);
  }
  auto depth = [](const double y[3]) {
    const double lo[3] = { -0.5, -0.4, -0.3 }, hi[3] = { 0.5, 0.4, 0.3 };
    return BoxDepth(y, lo, hi);
  };
  return { "jittered soup", Mesh(soup, tris), depth, 1e-6, 0.3, 1, false };
}

/// A box (1 x 0.8 x 0.6, 12 facets a side) with rectangular windows cut in three faces
/// (0.5 x 0.3 in the x faces, 0.6 x 0.3 in the +y face: 0.37 to 0.52 of the diagonal,
/// larger than MaximumHoleSize). Nothing else is closed, so the repair fills them too
/// (flat, in their faces) rather than wrapping a thin solid around the sheet: the box.
/// Solid: the box (Euler characteristic 1, largest ball 0.3).
inline Defect BoxWithWindows()
{
  auto box = Shape(vtkMedialShapeSource::BOX, 12, [](vtkMedialShapeSource* s) { s->SetBoxLengths(1.0, 0.8, 0.6); });
  const std::vector<Point> x = Points(box);
  std::vector<std::array<vtkIdType, 3>> kept;
  for (const auto& t : Triangles(box))
  {
    double c[3] = { 0, 0, 0 };
    for (vtkIdType v : t)
    {
      for (int k = 0; k < 3; ++k)
      {
        c[k] += x[v][k] / 3.0;
      }
    }
    const bool xWindow = std::fabs(std::fabs(c[0]) - 0.5) < 1e-9 && std::fabs(c[1]) < 0.25 && std::fabs(c[2]) < 0.15;
    const bool yWindow = std::fabs(c[1] - 0.4) < 1e-9 && std::fabs(c[0]) < 0.3 && std::fabs(c[2]) < 0.15;
    if (!xWindow && !yWindow)
    {
      kept.push_back(t);
    }
  }
  auto depth = [](const double y[3]) {
    const double lo[3] = { -0.5, -0.4, -0.3 }, hi[3] = { 0.5, 0.4, 0.3 };
    return BoxDepth(y, lo, hi);
  };
  return { "box with windows", Mesh(x, kept), depth, 1e-6, 0.3, 1, false };
}

/// A torus (ring radius 1, tube 0.3) with a fifth of its triangles turned over (chosen at
/// random). Solid: the solid torus (Euler characteristic 0, largest ball 0.3).
inline Defect FlippedTorus()
{
  auto torus = Shape(vtkMedialShapeSource::TORUS, 12);
  std::vector<std::array<vtkIdType, 3>> tris = Triangles(torus);
  std::mt19937_64 random(11);
  std::uniform_int_distribution<int> fifth(0, 4);
  for (auto& t : tris)
  {
    if (fifth(random) == 0)
    {
      std::swap(t[1], t[2]);
    }
  }
  auto depth = [](const double y[3]) {
    const double rho = std::sqrt(y[0] * y[0] + y[1] * y[1]);
    return 0.3 - std::sqrt((rho - 1.0) * (rho - 1.0) + y[2] * y[2]);
  };
  return { "flipped torus", Mesh(Points(torus), tris), depth, 0.01, 0.3, 0, false };
}

/// A unit sphere with a stray open disk (radius 0.5, tilted, off centre) inside it.
/// Solid: the ball.
inline Defect SphereWithSheet()
{
  auto sphere = Shape(vtkMedialShapeSource::SPHERE, 4);
  std::vector<Point> x;
  std::vector<std::array<vtkIdType, 3>> tris;
  const int rings = 8, around = 32;
  const double radius = 0.5, tilt = 0.3, z0 = 0.2;
  auto at = [&](double r, double phi) {
    const double u = r * std::cos(phi), v = r * std::sin(phi);
    return Point{ u, v * std::cos(tilt), z0 + v * std::sin(tilt) };
  };
  x.push_back(at(0, 0));
  for (int i = 1; i <= rings; ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      x.push_back(at(radius * i / rings, 2.0 * M_PI * j / around));
    }
  }
  auto id = [&](int i, int j) { return i == 0 ? vtkIdType(0) : vtkIdType(1 + (i - 1) * around + (j % around)); };
  for (int j = 0; j < around; ++j)
  {
    tris.push_back({ 0, id(1, j), id(1, j + 1) });
  }
  for (int i = 1; i < rings; ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      tris.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      tris.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  auto depth = [](const double y[3]) { return 1.0 - Norm(y); };
  return { "sphere with a sheet", Append(sphere, Mesh(x, tris)), depth, GeodesicSagitta(4), 1.0, 1, false };
}

/// A hollow sphere (radii 1 and 0.6) with a ball of radius 0.25 inside its cavity: a
/// valid solid of two bodies (Euler characteristic 2 + 1 = 3; largest ball 0.25). It
/// must stay as it is.
inline Defect SolidInCavity()
{
  auto hollow = Shape(vtkMedialShapeSource::HOLLOW_SPHERE, 4, [](vtkMedialShapeSource* s) { s->SetInnerRadius(0.6); });
  auto ball = Shape(vtkMedialShapeSource::SPHERE, 3, [](vtkMedialShapeSource* s) { s->SetRadius(0.25); });
  auto depth = [](const double y[3]) {
    const double r = Norm(y);
    return std::max(std::min(1.0 - r, r - 0.6), 0.25 - r);
  };
  return { "solid in a cavity", Append(hollow, ball), depth, GeodesicSagitta(4), 0.25, 3, true };
}

/// Two unit cubes, [0, 1]^3 and the one whose lowest corner is `b`, in one point list:
/// the points they share become the same points.
inline vtkSmartPointer<vtkPolyData> TwoCubes(double bx, double by, double bz)
{
  auto cube = Shape(vtkMedialShapeSource::BOX, 2, [](vtkMedialShapeSource* s) { s->SetBoxLengths(1, 1, 1); });
  auto a = Translated(cube, 0.5, 0.5, 0.5);
  auto b = Translated(cube, bx + 0.5, by + 0.5, bz + 0.5);
  std::vector<Point> x = Points(a);
  std::vector<std::array<vtkIdType, 3>> tris = Triangles(a);
  const std::vector<Point> xb = Points(b);
  std::vector<vtkIdType> map(xb.size());
  for (size_t i = 0; i < xb.size(); ++i)
  {
    auto found = std::find(x.begin(), x.end(), xb[i]);
    map[i] = static_cast<vtkIdType>(found - x.begin());
    if (found == x.end())
    {
      x.push_back(xb[i]);
    }
  }
  for (auto t : Triangles(b))
  {
    tris.push_back({ map[t[0]], map[t[1]], map[t[2]] });
  }
  return Mesh(x, tris);
}

/// Two unit cubes that share one edge (x = y = 1, 0 <= z <= 1), welded there: a
/// non-manifold edge with four triangles. Solid: the two cubes (their interiors are
/// apart: two bodies, Euler characteristic 2, largest ball 0.5).
inline Defect CubesSharingAnEdge()
{
  auto depth = [](const double y[3]) {
    const double loA[3] = { 0, 0, 0 }, hiA[3] = { 1, 1, 1 }, loB[3] = { 1, 1, 0 }, hiB[3] = { 2, 2, 1 };
    return std::max(BoxDepth(y, loA, hiA), BoxDepth(y, loB, hiB));
  };
  return { "cubes sharing an edge", TwoCubes(1, 1, 0), depth, 1e-9, 0.5, 2, false };
}

/// Two unit cubes that share one corner (1, 1, 1), welded there: a pinched vertex (its
/// triangles are two fans that share only it) between two shells that touch there.
/// Solid: the two cubes (two bodies, Euler characteristic 2, largest ball 0.5).
inline Defect CubesSharingAVertex()
{
  auto depth = [](const double y[3]) {
    const double loA[3] = { 0, 0, 0 }, hiA[3] = { 1, 1, 1 }, loB[3] = { 1, 1, 1 }, hiB[3] = { 2, 2, 2 };
    return std::max(BoxDepth(y, loA, hiA), BoxDepth(y, loB, hiB));
  };
  return { "cubes sharing a vertex", TwoCubes(1, 1, 1), depth, 1e-9, 0.5, 2, false };
}

/// A horn torus: ring radius 0.5, tube radius 0.5, so that the tube touches the axis at
/// the origin, where all its inner triangles meet in one point: a pinched vertex (two
/// fans, the upper and the lower, that share only it) within one shell, which is
/// otherwise closed, manifold and free of intersections. Solid: the horn torus (its
/// inside an open solid torus: Euler characteristic 0; largest ball 0.5).
inline Defect HornTorus(int around = 48, int tube = 24)
{
  const double ring = 0.5, radius = 0.5;
  std::vector<Point> x;
  x.push_back({ 0, 0, 0 }); // the pinch, at tube angle pi
  const int half = tube / 2;
  auto id = [&](int i, int j) {
    j = ((j % tube) + tube) % tube;
    return j == half ? vtkIdType(0) : vtkIdType(1 + (i % around) * (tube - 1) + (j < half ? j : j - 1));
  };
  for (int i = 0; i < around; ++i)
  {
    const double u = 2.0 * M_PI * i / around;
    for (int j = 0; j < tube; ++j)
    {
      if (j == half)
      {
        continue;
      }
      const double v = 2.0 * M_PI * j / tube, rho = ring + radius * std::cos(v);
      x.push_back({ rho * std::cos(u), rho * std::sin(u), radius * std::sin(v) });
    }
  }
  std::vector<std::array<vtkIdType, 3>> tris;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      const vtkIdType a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (a != b)
      {
        tris.push_back({ a, b, c });
      }
      if (c != d)
      {
        tris.push_back({ a, c, d });
      }
    }
  }
  auto depth = [ring, radius](const double y[3]) {
    const double rho = std::sqrt(y[0] * y[0] + y[1] * y[1]);
    return radius - std::sqrt((rho - ring) * (rho - ring) + y[2] * y[2]);
  };
  return { "horn torus", Mesh(x, tris), depth, 0.01, radius, 0, false };
}
}

/// The generated defects, in the order.
inline std::vector<Defect> GeneratedDefects()
{
  return { defects::CrossingShell(), defects::OverlappingSpheres(), defects::SphereWithHoles(),
    defects::JitteredSoup(), defects::FlippedTorus(), defects::SphereWithSheet(), defects::SolidInCavity(),
    defects::CubesSharingAnEdge(), defects::BoxWithWindows(), defects::CubesSharingAVertex() };
}
}

#endif
