// SPDX-License-Identifier: BSD-3-Clause
// A densely sampled box (3 x 2 x 1, 20000 medial balls) reconstructs within a
// stated bound: every vertex within 1% of the diagonal of the box surface and
// every point of the box surface within 1.5% of the reconstruction (the convex
// edges and corners are rounded: balls shrink towards them), means under 0.3%.
#include "MedialBallUnionTestUtilities.h"

#include "vtkGenericCell.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallUnion.h"
#include "vtkMedialShapeSource.h"
#include "vtkStaticCellLocator.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialBallUnionBox(int, char*[])
{
  const double L[3] = { 3.0, 2.0, 1.0 };
  vtkNew<vtkMedialShapeSource> box;
  box->SetShapeToBox();
  box->SetBoxLengths(L[0], L[1], L[2]);
  box->SetResolution(8);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(box->GetOutputPort());
  sampler->SetNumberOfSamples(20000);
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputConnection(sampler->GetOutputPort());
  ballUnion->SetSampleDimensions(128, 96, 64);
  ballUnion->Update();
  vtkPolyData* surface = ballUnion->GetOutput();
  box->Update();
  double bounds[6];
  box->GetOutput()->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diagonal = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);

  // Reconstruction -> box: exact distance to the box boundary.
  double worstOut = 0.0, meanOut = 0.0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], outside = 0.0;
    surface->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      q[k] = std::fabs(p[k] - centre[k]) - 0.5 * L[k];
      outside += std::max(q[k], 0.0) * std::max(q[k], 0.0);
    }
    const double inside = std::min(std::max({ q[0], q[1], q[2] }), 0.0);
    const double d = std::sqrt(outside) + std::fabs(inside);
    worstOut = std::max(worstOut, d);
    meanOut += d;
  }
  meanOut /= std::max<vtkIdType>(1, surface->GetNumberOfPoints());

  // Box -> reconstruction: a regular grid of points on the six faces.
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double worstIn = 0.0, meanIn = 0.0;
  long samples = 0;
  const int perUnit = 40;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const int na = static_cast<int>(L[a] * perUnit), nb = static_cast<int>(L[b] * perUnit);
    for (int side = -1; side <= 1; side += 2)
    {
      for (int i = 0; i <= na; ++i)
      {
        for (int j = 0; j <= nb; ++j)
        {
          double p[3], closest[3], d2;
          p[axis] = centre[axis] + side * 0.5 * L[axis];
          p[a] = centre[a] + (i / static_cast<double>(na) - 0.5) * L[a];
          p[b] = centre[b] + (j / static_cast<double>(nb) - 0.5) * L[b];
          vtkIdType cellId;
          int subId;
          locator->FindClosestPoint(p, closest, cell, cellId, subId, d2);
          worstIn = std::max(worstIn, std::sqrt(d2));
          meanIn += std::sqrt(d2);
          ++samples;
        }
      }
    }
  }
  meanIn /= samples;
  std::printf("box, 20000 balls, voxel %.3g of the diagonal: reconstruction->box max %.3g%% mean "
              "%.3g%%, box->reconstruction max %.3g%% mean %.3g%% (of the diagonal)\n",
    ballUnion->GetVoxelSize() / diagonal, 100 * worstOut / diagonal, 100 * meanOut / diagonal,
    100 * worstIn / diagonal, 100 * meanIn / diagonal);
  MEDIAL_CHECK(OpenEdges(surface) == 0, "surface is not closed");
  MEDIAL_CHECK(worstOut <= 0.01 * diagonal, "reconstruction->box %.3g%%", 100 * worstOut / diagonal);
  MEDIAL_CHECK(worstIn <= 0.015 * diagonal, "box->reconstruction %.3g%%", 100 * worstIn / diagonal);
  MEDIAL_CHECK(meanOut <= 0.003 * diagonal && meanIn <= 0.003 * diagonal, "means %.3g%% %.3g%%",
    100 * meanOut / diagonal, 100 * meanIn / diagonal);
  return EXIT_SUCCESS;
}
