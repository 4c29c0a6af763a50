// SPDX-License-Identifier: BSD-3-Clause
// Thickness beside a convex crease that fades out (issue 39, fandisk's fin): a plate
// Lx x Ly x t whose top-front edge is sharp for y < Ly / 2 and rounded beyond it (a
// quarter circle of radius t / 2 in n facets, each less than the crease angle apart).
// The top, the rounding and the front are then one wall, joined around the crease's end,
// though a convex crease runs between them along the sharp half; a ball in that crease
// must still slide off it to the plate's thickness. Known answer: t at every vertex of
// the sharp crease, for n = 6, 12 and 24 facets, two densities along the edge, and the
// plate turned. Before the walls were asked near the ball (one wall with a crease
// inside it), the sharp crease read 0.675 t to 0.85 t.
// Prints the rows (expected, min, median, max over the crease's vertices).
#include "MedialThicknessTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Ledge
{
  vtkSmartPointer<vtkPolyData> Surface;
  std::vector<vtkIdType> Crease; // the sharp crease's vertices, ends excluded
};

// The plate, its profile in (x, z) swept along y: sharp for y <= Ly / 2 and rounded
// beyond; the step face at y = Ly / 2 is a fan from the sharp corner over the arc.
Ledge MakeLedge(double t, double lx, double ly, int arcFacets, int slices)
{
  const double rho = 0.5 * t, h = rho;
  using P2 = std::array<double, 2>;
  auto line = [&](P2 a, P2 b, std::vector<P2>& out) {
    const int k = std::max(1, static_cast<int>(std::lround(std::hypot(b[0] - a[0], b[1] - a[1]) / h)));
    for (int i = 0; i < k; ++i)
    {
      out.push_back({ a[0] + (b[0] - a[0]) * i / k, a[1] + (b[1] - a[1]) * i / k });
    }
  };
  std::vector<P2> base, top;
  line({ 0, 0 }, { lx, 0 }, base);
  line({ lx, 0 }, { lx, t - rho }, base);
  line({ lx - rho, t }, { 0, t }, top);
  line({ 0, t }, { 0, 0 }, top);
  std::vector<P2> sharp = base, round = base;
  sharp.push_back({ lx, t - rho });
  sharp.push_back({ lx, t });
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= arcFacets; ++i)
  {
    const double a = 0.5 * pi * i / arcFacets;
    round.push_back({ lx - rho + rho * std::cos(a), t - rho + rho * std::sin(a) });
  }
  sharp.insert(sharp.end(), top.begin(), top.end());
  round.insert(round.end(), top.begin() + 1, top.end()); // the arc ends at top[0]
  const size_t nb = base.size();

  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  auto ring = [&](const std::vector<P2>& profile, double y) {
    std::vector<vtkIdType> ids;
    for (const P2& p : profile)
    {
      ids.push_back(points->InsertNextPoint(p[0], y, p[1]));
    }
    return ids;
  };
  auto tri = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    const vtkIdType v[3] = { a, b, c };
    triangles->InsertNextCell(3, v);
  };
  auto loft = [&](const std::vector<vtkIdType>& r0, const std::vector<vtkIdType>& r1) {
    for (size_t i = 0; i < r0.size(); ++i)
    {
      const size_t j = (i + 1) % r0.size();
      tri(r0[i], r1[j], r0[j]);
      tri(r0[i], r1[i], r1[j]);
    }
  };
  auto cap = [&](const std::vector<vtkIdType>& r, bool flip) {
    double c[3] = { 0, 0, 0 };
    for (vtkIdType id : r)
    {
      double p[3];
      points->GetPoint(id, p);
      for (int k = 0; k < 3; ++k)
      {
        c[k] += p[k] / r.size();
      }
    }
    const vtkIdType centre = points->InsertNextPoint(c);
    for (size_t i = 0; i < r.size(); ++i)
    {
      const size_t j = (i + 1) % r.size();
      flip ? tri(centre, r[i], r[j]) : tri(centre, r[j], r[i]);
    }
  };
  Ledge ledge;
  std::vector<std::vector<vtkIdType>> rings;
  for (int s = 0; s <= slices; ++s)
  {
    rings.push_back(ring(sharp, 0.5 * ly * s / slices));
    if (s > 0 && s < slices)
    {
      ledge.Crease.push_back(rings.back()[nb + 1]);
    }
  }
  for (int s = 0; s < slices; ++s)
  {
    loft(rings[s], rings[s + 1]);
  }
  cap(rings.front(), true);
  const std::vector<vtkIdType>& mid = rings.back();
  // The rounded half's first ring shares the sharp ring's points but the corner's:
  // round[nb] is sharp[nb] (lx, t - rho), round[nb + arcFacets + k] is sharp[nb + 2 + k]
  // (the top, from the arc's end on); the arc's inner points are new.
  std::vector<vtkIdType> first(round.size());
  for (size_t i = 0; i <= nb; ++i)
  {
    first[i] = mid[i];
  }
  for (size_t k = 0; nb + arcFacets + k < round.size(); ++k)
  {
    first[nb + arcFacets + k] = mid[nb + 2 + k];
  }
  for (int i = 1; i < arcFacets; ++i)
  {
    first[nb + i] = points->InsertNextPoint(round[nb + i][0], 0.5 * ly, round[nb + i][1]);
  }
  std::vector<std::vector<vtkIdType>> rounded{ first };
  for (int s = 1; s <= slices; ++s)
  {
    rounded.push_back(ring(round, 0.5 * ly + 0.5 * ly * s / slices));
  }
  for (int s = 0; s < slices; ++s)
  {
    loft(rounded[s], rounded[s + 1]);
  }
  cap(rounded.back(), false);
  // The step face: the sharp corner and the arc.
  for (int i = 0; i < arcFacets; ++i)
  {
    tri(mid[nb + 1], first[nb + i], first[nb + i + 1]);
  }
  ledge.Surface = vtkSmartPointer<vtkPolyData>::New();
  ledge.Surface->SetPoints(points);
  ledge.Surface->SetPolys(triangles);
  return ledge;
}
}

int TestMedialThicknessFadingCrease(int, char*[])
{
  int failures = 0;
  const double t = 0.2;
  std::printf("| plate 1.2 x 1.6 x 0.2, half its top-front edge rounded | expected | min | median | max | "
              "vertices |\n|---|---|---|---|---|---|\n");
  for (int turned = 0; turned < 2; ++turned)
  {
    for (int facets : { 6, 12, 24 })
    {
      for (int slices : { 8, 16 })
      {
        Ledge ledge = MakeLedge(t, 1.2, 1.6, facets, slices);
        vtkSmartPointer<vtkPolyData> surface = ledge.Surface;
        if (turned)
        {
          surface = medialtest::Turned(surface);
        }
        vtkNew<vtkMedialThickness> thickness;
        thickness->SetInputData(surface);
        thickness->Update();
        vtkPolyData* out = thickness->GetOutput();
        const std::string name = "arc of " + std::to_string(facets) + " facets, " + std::to_string(slices) +
          " slices a half" + (turned ? ", turned" : "");
        if (out->GetNumberOfPoints() != surface->GetNumberOfPoints() || thickness->GetSurfaceRepaired())
        {
          std::printf("FAIL %s: the generated plate is not a clean solid\n", name.c_str());
          ++failures;
          continue;
        }
        std::vector<char> onCrease(out->GetNumberOfPoints(), 0);
        for (vtkIdType id : ledge.Crease)
        {
          onCrease[id] = 1;
        }
        const medialtest::Summary crease = medialtest::Summarise(
          out->GetPointData()->GetArray(vtkMedialArrayNames::Thickness), [&](vtkIdType i) { return onCrease[i] != 0; });
        medialtest::PrintRow((name + ": the sharp crease").c_str(), t, crease);
        if (!medialtest::Within(crease, t, 0.01))
        {
          std::printf("FAIL %s: the sharp crease reads %g to %g, not the plate's %g\n", name.c_str(), crease.Min,
            crease.Max, t);
          ++failures;
        }
      }
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
