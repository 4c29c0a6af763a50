// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialNearestPoints
 * @brief Internal: the k nearest of a fixed set of points, on a vtkMedialUniformGrid.
 *
 * Nearest means the smallest squared distance computed as vtkMath::Distance2BetweenPoints
 * does ((x0 - p0)^2 + (x1 - p1)^2 + (x2 - p2)^2, summed in that order), ties going to the
 * smaller id: the answer is the first k points of the list of all points sorted by
 * (squared distance, id), whatever the grid. A point that is itself among the points is
 * found at distance 0 like any other.
 *
 * vtkStaticPointLocator::FindClosestNPoints (VTK 9.1) gives the same set wherever the
 * k-th distance is not shared by a point left out: it keeps, of the points at the k-th
 * distance, those it meets first, bucket ring by bucket ring and by id within a bucket.
 * Points at the same place share a bucket, so it also agrees for duplicates (of the
 * query or of another point); it may differ only for distinct points at exactly the
 * same distance in different buckets.
 *
 * The search visits the grid's shells of cells around the query's cell outward
 * (ForEachCellInShell) and stops once k points are held and the next shell lies beyond
 * the k-th distance; cells beyond it in a shell are skipped. The cells are sized from
 * the points' occupancy (about PointsPerCell per non-empty cell), not from the bounding
 * box: medial centres lie on sheets, where a box-based size leaves most cells empty.
 * Queries are const and thread-safe.
 */
#ifndef vtkMedialNearestPoints_h
#define vtkMedialNearestPoints_h

#include "vtkMedialUniformGrid.h"

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

class vtkMedialNearestPoints
{
public:
  /// Target of the mean number of points per non-empty cell.
  static constexpr double PointsPerCell = 4.0;

  /// Bins `count` points at `xyz` (x0 y0 z0 x1 ...; read in place, they must outlive the queries).
  void Build(const double* xyz, vtkIdType count)
  {
    this->Points = xyz;
    this->Count = count;
    if (count <= 0)
    {
      return;
    }
    double bounds[6] = { xyz[0], xyz[0], xyz[1], xyz[1], xyz[2], xyz[2] };
    double largest = 0.0;
    for (vtkIdType i = 0; i < count; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        bounds[2 * k] = std::min(bounds[2 * k], xyz[3 * i + k]);
        bounds[2 * k + 1] = std::max(bounds[2 * k + 1], xyz[3 * i + k]);
        largest = std::max(largest, std::abs(xyz[3 * i + k]));
      }
    }
    double extent = 0.0, volume = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      extent = std::max(extent, bounds[2 * k + 1] - bounds[2 * k]);
    }
    if (!(extent > 0.0))
    {
      extent = 1.0; // all points at one place: one cell
    }
    for (int k = 0; k < 3; ++k)
    {
      volume *= std::max(bounds[2 * k + 1] - bounds[2 * k], 1e-3 * extent);
    }
    // A first size from the box (PointsPerCell per cell if the points filled it), then
    // corrected twice from the occupancy found, as if the points lay on sheets
    // (occupancy ~ size^2); the grid's cap bounds the cells.
    double size = std::cbrt(volume * PointsPerCell / static_cast<double>(count));
    std::vector<char> used;
    for (int round = 0; round < 3; ++round)
    {
      size = vtkMedialUniformGrid::CubicCellSize(bounds, size);
      this->Grid.InitializeCubic(bounds, size);
      if (round == 2)
      {
        break;
      }
      used.assign(static_cast<size_t>(this->Grid.GetNumberOfCells()), 0);
      vtkIdType occupied = 0;
      for (vtkIdType i = 0; i < count; ++i)
      {
        char& u = used[this->Grid.CellOf(xyz + 3 * i)];
        occupied += u == 0;
        u = 1;
      }
      const double mean = static_cast<double>(count) / static_cast<double>(occupied);
      if (mean > 0.5 * PointsPerCell && mean < 2.0 * PointsPerCell)
      {
        break;
      }
      size *= std::sqrt(PointsPerCell / mean);
    }
    this->Grid.Build(count, [&](vtkIdType i, auto&& add) { add(this->Grid.CellOf(xyz + 3 * i)); });
    // Cell membership and cell faces are both rounded: bounds are taken this much
    // closer, so that no point is left out by a rounding (a margin only adds visits).
    this->Margin = 1e-9 * size + 1e-14 * largest;
  }

  /**
   * The min(k, count) nearest points to x in (squared distance, id) order: their ids in
   * `ids` and squared distances in `dist2` (both with room for k). Returns their number.
   */
  int Find(const double x[3], int k, vtkIdType* ids, double* dist2) const
  {
    const int wanted = static_cast<int>(std::min<vtkIdType>(k, this->Count));
    if (wanted <= 0)
    {
      return 0;
    }
    int held = 0;
    int centre[3];
    this->Grid.CellCoordinates(x, centre);
    int lastRing = 0; // the shell that reaches the grid's far corner
    for (int a = 0; a < 3; ++a)
    {
      lastRing = std::max(lastRing, std::max(centre[a], this->Grid.GetDimension(a) - 1 - centre[a]));
    }
    for (int ring = 0; ring <= lastRing; ++ring)
    {
      this->Grid.ForEachCellInShell(centre, ring, [&](const int* ijk, vtkIdType cell) {
        if (held == wanted && this->CellDistance2(x, ijk) > dist2[held - 1])
        {
          return;
        }
        for (const vtkIdType* p = this->Grid.CellBegin(cell); p != this->Grid.CellEnd(cell); ++p)
        {
          const double* q = this->Points + 3 * *p;
          const double d = (x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]) +
            (x[2] - q[2]) * (x[2] - q[2]);
          if (held == wanted && !Before(d, *p, dist2[held - 1], ids[held - 1]))
          {
            continue;
          }
          int at = held < wanted ? held++ : held - 1;
          for (; at > 0 && Before(d, *p, dist2[at - 1], ids[at - 1]); --at)
          {
            dist2[at] = dist2[at - 1];
            ids[at] = ids[at - 1];
          }
          dist2[at] = d;
          ids[at] = *p;
        }
      });
      if (held == wanted)
      {
        const double reach = this->ShellReach(x, centre, ring) - this->Margin;
        if (reach > 0.0 && reach * reach > dist2[held - 1])
        {
          break;
        }
      }
    }
    return held;
  }

  vtkIdType GetNumberOfPoints() const { return this->Count; }

private:
  static bool Before(double d, vtkIdType id, double otherD, vtkIdType otherId)
  {
    return d < otherD || (d == otherD && id < otherId);
  }

  // A lower bound of the squared distance from x to the points of cell ijk.
  double CellDistance2(const double x[3], const int* ijk) const
  {
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double d = std::max(0.0, this->Grid.SlabDistance(x[a], ijk[a], a) - this->Margin);
      d2 += d * d;
    }
    return d2;
  }

  // The distance from x to the nearest point outside the shells 0 .. ring around centre
  // (infinite where they cover the grid's side: the boundary cells hold every point beyond).
  double ShellReach(const double x[3], const int centre[3], int ring) const
  {
    double reach = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
    {
      if (centre[a] - ring > 0)
      {
        reach = std::min(reach, x[a] - this->Grid.CellLow(a, centre[a] - ring));
      }
      if (centre[a] + ring < this->Grid.GetDimension(a) - 1)
      {
        reach = std::min(reach, this->Grid.CellLow(a, centre[a] + ring + 1) - x[a]);
      }
    }
    return reach;
  }

  vtkMedialUniformGrid Grid;
  const double* Points = nullptr;
  vtkIdType Count = 0;
  double Margin = 0.0;
};

#endif
