// SPDX-License-Identifier: BSD-3-Clause
// Disks whose centres lie in one plane (a tilted plane, then z = 0) give the
// boundary curves of the union of disks: closed polylines in that plane, every
// vertex within one voxel of the exact boundary (circle arcs not covered by other
// disks), and every point of the exact boundary within one voxel of the curves.
#include "MedialBallUnionTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMedialBallUnion.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
struct Disk
{
  double X, Y, R;
};

// Exact distance from (x, y) to the boundary of the union of disks.
double DistanceToUnionBoundary(const std::vector<Disk>& disks, double x, double y)
{
  auto covered = [&](double px, double py, size_t skipA, size_t skipB) {
    for (size_t k = 0; k < disks.size(); ++k)
    {
      if (k != skipA && k != skipB && std::hypot(px - disks[k].X, py - disks[k].Y) < disks[k].R - 1e-12)
      {
        return true;
      }
    }
    return false;
  };
  double best = HUGE_VAL;
  for (size_t i = 0; i < disks.size(); ++i)
  {
    const Disk& d = disks[i];
    const double len = std::hypot(x - d.X, y - d.Y);
    const double px = d.X + d.R * (x - d.X) / len, py = d.Y + d.R * (y - d.Y) / len;
    if (!covered(px, py, i, i))
    {
      best = std::min(best, std::fabs(len - d.R));
      continue;
    }
    // Otherwise the nearest boundary point on this circle is an arc end: a crossing.
    for (size_t j = 0; j < disks.size(); ++j)
    {
      const Disk& e = disks[j];
      const double dist = std::hypot(e.X - d.X, e.Y - d.Y);
      if (j == i || dist >= d.R + e.R || dist <= std::fabs(d.R - e.R))
      {
        continue;
      }
      const double along = (dist * dist + d.R * d.R - e.R * e.R) / (2 * dist);
      const double half = std::sqrt(d.R * d.R - along * along);
      const double ux = (e.X - d.X) / dist, uy = (e.Y - d.Y) / dist;
      for (double s : { -1.0, 1.0 })
      {
        const double cx = d.X + along * ux - s * half * uy, cy = d.Y + along * uy + s * half * ux;
        if (!covered(cx, cy, i, j))
        {
          best = std::min(best, std::hypot(x - cx, y - cy));
        }
      }
    }
  }
  return best;
}

int CheckPlane(const double origin[3], const double u[3], const double v[3], const char* name)
{
  // Three overlapping disks (no hole between them) and one on its own: two closed curves.
  const std::vector<Disk> disks = { { 0.0, 0.0, 1.0 }, { 1.5, 0.0, 0.8 }, { 0.7, 1.0, 0.7 },
    { 3.5, 0.0, 0.4 } };
  auto toWorld = [&](double x, double y, double w[3]) {
    for (int k = 0; k < 3; ++k)
    {
      w[k] = origin[k] + x * u[k] + y * v[k];
    }
  };
  std::vector<BallSpec> balls;
  for (const Disk& d : disks)
  {
    double w[3];
    toWorld(d.X, d.Y, w);
    balls.push_back({ w[0], w[1], w[2], d.R });
  }
  vtkNew<vtkMedialBallUnion> ballUnion;
  ballUnion->SetInputData(MakeBalls(balls));
  ballUnion->SetSampleDimensions(160, 90, 7);
  ballUnion->Update();
  vtkPolyData* curves = ballUnion->GetOutput();
  const double h = ballUnion->GetVoxelSize();
  double normal[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };

  double worstOffPlane = 0.0, worstVertex = 0.0;
  for (vtkIdType i = 0; i < curves->GetNumberOfPoints(); ++i)
  {
    double p[3], d[3];
    curves->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      d[k] = p[k] - origin[k];
    }
    const double x = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
    const double y = d[0] * v[0] + d[1] * v[1] + d[2] * v[2];
    worstOffPlane = std::max(worstOffPlane, std::fabs(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]));
    worstVertex = std::max(worstVertex, DistanceToUnionBoundary(disks, x, y));
  }
  // Closed polylines: the first point id is repeated at the end.
  // Marching squares may split a sub-voxel loop off a concave crease (its fixed
  // saddle case); such specks are allowed, but only two curves may be larger.
  int closed = 0, large = 0;
  vtkCellArray* lines = curves->GetLines();
  for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    lines->GetCellAtId(c, npts, ids);
    closed += (npts > 3 && ids[0] == ids[npts - 1]) ? 1 : 0;
    double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double p[3];
      curves->GetPoint(ids[k], p);
      for (int j = 0; j < 3; ++j)
      {
        lo[j] = std::min(lo[j], p[j]);
        hi[j] = std::max(hi[j], p[j]);
      }
    }
    large += std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) > h ? 1 : 0;
  }
  // Exact boundary samples to the curves.
  double worstBoundary = 0.0;
  int boundarySamples = 0;
  for (size_t i = 0; i < disks.size(); ++i)
  {
    for (int s = 0; s < 360; ++s)
    {
      const double angle = 2.0 * 3.14159265358979323846 * s / 360.0;
      const double x = disks[i].X + disks[i].R * std::cos(angle), y = disks[i].Y + disks[i].R * std::sin(angle);
      if (DistanceToUnionBoundary(disks, x, y) > 1e-9)
      {
        continue; // inside another disk
      }
      ++boundarySamples;
      double w[3];
      toWorld(x, y, w);
      double nearest = HUGE_VAL;
      for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
      {
        vtkIdType npts;
        const vtkIdType* ids;
        lines->GetCellAtId(c, npts, ids);
        for (vtkIdType k = 0; k + 1 < npts; ++k)
        {
          double a[3], b[3];
          curves->GetPoint(ids[k], a);
          curves->GetPoint(ids[k + 1], b);
          nearest = std::min(nearest, PointSegmentDistance(w, a, b));
        }
      }
      worstBoundary = std::max(worstBoundary, nearest);
    }
  }
  std::printf("%s: dimension %d, voxel %.4g, %lld points, %lld polylines (%d closed, %d larger than a voxel), off plane %.2g, "
              "vertex to boundary %.3g voxels, boundary to curves %.3g voxels (%d samples)\n",
    name, ballUnion->GetOutputDimension(), h, static_cast<long long>(curves->GetNumberOfPoints()),
    static_cast<long long>(lines->GetNumberOfCells()), closed, large, worstOffPlane, worstVertex / h,
    worstBoundary / h, boundarySamples);
  MEDIAL_CHECK(ballUnion->GetOutputDimension() == 2, "%s: dimension %d", name, ballUnion->GetOutputDimension());
  MEDIAL_CHECK(curves->GetNumberOfPolys() == 0 && large == 2, "%s: expected two curves, got %d", name, large);
  MEDIAL_CHECK(closed == lines->GetNumberOfCells(), "%s: %d of %lld curves closed", name, closed,
    static_cast<long long>(lines->GetNumberOfCells()));
  MEDIAL_CHECK(worstOffPlane <= 1e-9, "%s: a vertex is %g off the plane", name, worstOffPlane);
  MEDIAL_CHECK(worstVertex <= h, "%s: a vertex is %.3g voxels off the boundary", name, worstVertex / h);
  MEDIAL_CHECK(worstBoundary <= h, "%s: the boundary is %.3g voxels from the curves", name, worstBoundary / h);
  MEDIAL_CHECK(boundarySamples > 500, "%s: too few boundary samples", name);

  // The field image is one slice along the plane, 160 x 90 as asked.
  int dims[3];
  ballUnion->GetFieldOutput()->GetDimensions(dims);
  // Its direction matrix holds the plane's in-plane axes and normal as columns.
  vtkMatrix3x3* direction = ballUnion->GetFieldOutput()->GetDirectionMatrix();
  double worstDirection = 0.0;
  for (int col = 0; col < 3; ++col)
  {
    double dot = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      dot += direction->GetElement(k, col) * normal[k];
    }
    worstDirection = std::max(worstDirection, std::fabs(std::fabs(dot) - (col == 2 ? 1.0 : 0.0)));
  }
  MEDIAL_CHECK(dims[0] == 160 && dims[1] == 90 && dims[2] == 1, "%s: image %d %d %d", name, dims[0], dims[1], dims[2]);
  MEDIAL_CHECK(worstDirection < 1e-9, "%s: image direction differs from the plane by %g", name, worstDirection);
  return EXIT_SUCCESS;
}
}

int TestMedialBallUnion2D(int, char*[])
{
  const double tiltedOrigin[3] = { 0.3, -0.2, 0.7 };
  const double tiltedU[3] = { 1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0 };
  const double tiltedV[3] = { 2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0 };
  const double flatOrigin[3] = { 0.0, 0.0, 0.0 };
  const double x[3] = { 1.0, 0.0, 0.0 }, y[3] = { 0.0, 1.0, 0.0 };
  if (CheckPlane(flatOrigin, x, y, "z = 0") != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return CheckPlane(tiltedOrigin, tiltedU, tiltedV, "tilted plane");
}
