// SPDX-License-Identifier: BSD-3-Clause
// The local check of a repaired patch (vtkMedialRepairPatch::Certify) against the whole
// check (vtkMedialSolidCheck with CGAL's exact pairs) of the stitched shell. A closed slab
// over [0,1] x [0,1], top at 0.2, bottom at 0 in the middle and sagging to -0.3 at the
// corners, every face a grid; the patch is a square of the top face, and
// its "repair" keeps the patch's border and pushes its inner points down by a depth:
//  - 0.1: a dent inside the slab, a valid solid: both checks say valid, and the local
//    distance and inside tests agree with the whole surface's queries;
//  - 0.2: the dent's middle point lands on the bottom face's middle point (touching the
//    rest far from the patch, in rings): not valid locally (the whole check merges the
//    two points and sees a shared corner: it does not look for pinched points);
//  - 0.3: the dent goes through the bottom face (and stays in the slab's bounds): not valid;
//  - 0.1 with the dent's triangles turned over: not oriented, not valid;
//  - a "repair" that drops a triangle of the patch: open, not valid.
// The local check must never say valid where the whole check does not, must find the
// dent through the bottom (an intersection with the rest far from the patch), and say valid
// for the clean dent (else the repair falls back to the whole check: slower, not wrong).
#include "vtkMedialRepairFilter.h"
#include "vtkMedialRepairPatch.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace
{
using Soup = vtkMedialSurfaceRepair::Soup;

// The slab's surface, n x n squares on the top and bottom faces, n x m on the sides, each
// split into two triangles, facing out.
Soup Slab(int n, int m, double height)
{
  Soup soup;
  std::map<std::array<long, 3>, vtkIdType> ids; // grid coordinates (in 1/n and 1/m) -> point
  auto point = [&](long i, long j, long k) {
    const std::array<long, 3> key{ i, j, k };
    const auto at = ids.find(key);
    if (at != ids.end())
    {
      return at->second;
    }
    const vtkIdType id = static_cast<vtkIdType>(soup.Points.size());
    // The bottom sags towards the edges (its centre is highest, at 0): a dent through
    // it stays inside the slab's bounds.
    const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
    const double bottom = -0.6 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5));
    soup.Points.push_back({ x, y, bottom + (height - bottom) * k / m });
    ids.emplace(key, id);
    return id;
  };
  // A quad a b c d (counter-clockwise seen from outside) as two triangles.
  auto quad = [&](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d) {
    soup.Triangles.push_back({ a, b, c });
    soup.Triangles.push_back({ a, c, d });
  };
  for (long i = 0; i < n; ++i)
  {
    for (long j = 0; j < n; ++j)
    {
      quad(point(i, j, m), point(i + 1, j, m), point(i + 1, j + 1, m), point(i, j + 1, m)); // top, +z
      quad(point(i, j, 0), point(i, j + 1, 0), point(i + 1, j + 1, 0), point(i + 1, j, 0)); // bottom, -z
    }
  }
  for (long i = 0; i < n; ++i)
  {
    for (long k = 0; k < m; ++k)
    {
      quad(point(i, 0, k), point(i + 1, 0, k), point(i + 1, 0, k + 1), point(i, 0, k + 1)); // y = 0, -y
      quad(point(i + 1, n, k), point(i, n, k), point(i, n, k + 1), point(i + 1, n, k + 1)); // y = 1, +y
      quad(point(0, i + 1, k), point(0, i, k), point(0, i, k + 1), point(0, i + 1, k + 1)); // x = 0, -x
      quad(point(n, i, k), point(n, i + 1, k), point(n, i + 1, k + 1), point(n, i, k + 1)); // x = 1, +x
    }
  }
  return soup;
}

// Whether the whole check of `soup` finds a valid solid with no triangle rewound.
bool WholeValid(const Soup& soup)
{
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  if (!mesh.Build(vtkMedialSurfaceRepair::ToPolyData(soup), error) || !query.Build(&mesh, error))
  {
    return false;
  }
  vtkMedialSolidCheck check;
  check.Run(mesh, query, 1, true);
  check.Decide(mesh, vtkMedialRepairFilter::ExactPairTest);
  bool rewound = false;
  for (const auto& shell : mesh.Shells)
  {
    rewound = rewound || shell.Rewound > 0;
  }
  return check.IsValidSolid() && mesh.Shells.size() == 1 && !rewound;
}

struct Case
{
  const char* Name;
  double Depth;
  bool Turn;
  bool Drop;
  bool Valid;     // the local check's expected answer (valid implies the whole check's)
  int WholeValid; // the whole check's expected answer (-1: either)
};
}

int TestMedialRepairPatch(int, char*[])
{
  const int n = 16, m = 4;
  const double height = 0.2;
  const Soup shell = Slab(n, m, height);
  if (!WholeValid(shell))
  {
    std::printf("FAIL: the slab itself is not a valid solid\n");
    return 1;
  }
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  if (!mesh.Build(vtkMedialSurfaceRepair::ToPolyData(shell), error) || !query.Build(&mesh, error))
  {
    std::printf("FAIL: %s\n", error.c_str());
    return 1;
  }
  // The patch: the top face's triangles over [4/16, 12/16]^2.
  const double lo = 4.0 / n, hi = 12.0 / n, top = height;
  std::vector<char> in(shell.Triangles.size(), 0);
  for (size_t t = 0; t < shell.Triangles.size(); ++t)
  {
    bool inside = true;
    for (vtkIdType v : shell.Triangles[t])
    {
      const auto& x = shell.Points[v];
      inside = inside && x[2] == top && x[0] >= lo && x[0] <= hi && x[1] >= lo && x[1] <= hi;
    }
    in[t] = inside ? 1 : 0;
  }
  const Case cases[] = {
    { "a dent inside the slab", 0.1, false, false, true, 1 },
    { "a dent onto the bottom face's points", 0.2, false, false, false, -1 },
    { "a dent through the bottom face", 0.3, false, false, false, 0 },
    { "a dent turned over", 0.1, true, false, false, 0 },
    { "a dent with a triangle dropped", 0.1, false, true, false, 0 },
  };
  int failures = 0;
  for (const Case& c : cases)
  {
    // P, and the stitched shell (S - P in order, then P').
    Soup before, stitched;
    std::vector<vtkIdType> beforeId(shell.Points.size(), -1);
    stitched.Points = shell.Points;
    for (size_t t = 0; t < shell.Triangles.size(); ++t)
    {
      if (!in[t])
      {
        stitched.Triangles.push_back(shell.Triangles[t]);
        continue;
      }
      std::array<vtkIdType, 3> tri;
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = shell.Triangles[t][k];
        if (beforeId[v] < 0)
        {
          beforeId[v] = static_cast<vtkIdType>(before.Points.size());
          before.Points.push_back(shell.Points[v]);
        }
        tri[k] = beforeId[v];
      }
      before.Triangles.push_back(tri);
    }
    // P': the inner points moved down (new points), the border kept.
    std::vector<vtkIdType> moved(shell.Points.size(), -1);
    bool dropped = false;
    for (size_t t = 0; t < shell.Triangles.size(); ++t)
    {
      if (!in[t])
      {
        continue;
      }
      if (c.Drop && !dropped)
      {
        dropped = true;
        continue;
      }
      std::array<vtkIdType, 3> tri;
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = shell.Triangles[t][k];
        const auto& x = shell.Points[v];
        const bool border = x[0] == lo || x[0] == hi || x[1] == lo || x[1] == hi;
        if (border)
        {
          tri[k] = v;
          continue;
        }
        if (moved[v] < 0)
        {
          moved[v] = static_cast<vtkIdType>(stitched.Points.size());
          stitched.Points.push_back({ x[0], x[1], x[2] - c.Depth });
        }
        tri[k] = moved[v];
      }
      if (c.Turn)
      {
        std::swap(tri[1], tri[2]);
      }
      stitched.Triangles.push_back(tri);
    }
    const bool whole = WholeValid(stitched);
    vtkMedialRepairPatch patch;
    std::string why;
    const bool local = patch.Certify(shell, query, in, before, stitched, why);
    std::printf("%s: whole check %s, local check %s%s%s\n", c.Name, whole ? "valid" : "not valid",
      local ? "valid" : "not valid", local ? "" : ": ", local ? "" : why.c_str());
    if (local != c.Valid || (local && !whole) || (c.WholeValid >= 0 && whole != (c.WholeValid == 1)))
    {
      std::printf("FAIL: expected %s\n", c.Valid ? "valid" : "not valid");
      ++failures;
    }
    if (!local || !whole)
    {
      continue;
    }
    // The local queries against the whole surface's, at points near and far.
    vtkMedialTriangleMesh stitchedMesh;
    vtkMedialSurfaceQuery stitchedQuery;
    stitchedMesh.Build(vtkMedialSurfaceRepair::ToPolyData(stitched), error);
    stitchedQuery.Build(&stitchedMesh, error);
    int disagree = 0;
    for (int i = 0; i <= 10; ++i)
    {
      for (int k = 0; k <= 10; ++k)
      {
        const double x[3] = { 0.05 + 0.09 * i, 0.5, -0.05 + 0.03 * k };
        vtkMedialSurfaceQuery::ClosestHit hit;
        const double d = stitchedQuery.ClosestPoint(x, 4.0, hit) ? hit.Distance : 4.0;
        if (std::fabs(d - patch.Distance(x, 4.0)) > 1e-15 || stitchedQuery.IsInside(x) != patch.IsInside(x))
        {
          ++disagree;
        }
      }
    }
    if (disagree > 0)
    {
      std::printf("FAIL: the local distance or inside test differs from the whole surface's at %d points\n", disagree);
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
