// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialUniformGrid
 * @brief Internal: the one uniform grid of the engines, binning items (points,
 * ball centres, polygon edges) by cell for box, ring and sphere queries.
 *
 * In the spirit of vtkStaticPointLocator: cells of a fixed size per axis from an
 * origin, numbered x fastest, then y, then z; a 2D grid has one layer (dims[2] = 1).
 * Coordinates are clamped, so a point outside the grid belongs to the nearest
 * boundary cell: the boundary cells reach to infinity, and every query treats
 * them so.
 *
 * Contents:
 *  - static (Build): a counting sort into compressed rows. An item may lie in
 *    several cells (an edge crossing them); each cell lists its items in
 *    increasing id (SortCells reorders them).
 *  - dynamic (Insert): items added one by one while the grid is queried; a cell
 *    lists these newest first.
 *
 * Queries visit cells in a fixed order (z, then y, then x; rings as described at
 * ForEachCellInShell), so callers whose ties or early exits depend on the visit
 * order get the same answer every run. Queries are const and thread-safe.
 */
#ifndef vtkMedialUniformGrid_h
#define vtkMedialUniformGrid_h

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

class vtkMedialUniformGrid
{
public:
  /// Default cap of the cubic grids: 2^22 cells.
  static constexpr double MaximumCubicCells = 4194304.0;

  /// `dims` cells of size cellSize[axis] per axis, from `origin`.
  void Initialize(const double origin[3], const double cellSize[3], const int dims[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Origin[k] = origin[k];
      this->CellSize[k] = cellSize[k];
      this->Dims[k] = std::max(1, dims[k]);
    }
    this->Clear();
  }

  /// Cubic cells of side `size` from the low corner of `bounds`, floor(extent / size) + 1 per axis.
  void InitializeCubic(const double bounds[6], double size)
  {
    double origin[3], cellSize[3];
    int dims[3];
    for (int k = 0; k < 3; ++k)
    {
      origin[k] = bounds[2 * k];
      cellSize[k] = size;
      dims[k] = std::max(1, static_cast<int>((bounds[2 * k + 1] - bounds[2 * k]) / size) + 1);
    }
    this->Initialize(origin, cellSize, dims);
  }

  /// The smallest side, from `size` up by factors of 1.25, whose cubic grid over
  /// `bounds` has at most `maximumCells` cells.
  static double CubicCellSize(const double bounds[6], double size, double maximumCells = MaximumCubicCells)
  {
    for (;;)
    {
      double cells = 1.0;
      for (int k = 0; k < 3; ++k)
      {
        cells *= std::floor((bounds[2 * k + 1] - bounds[2 * k]) / size) + 1.0;
      }
      if (cells <= maximumCells || !(size > 0.0))
      {
        return size;
      }
      size *= 1.25;
    }
  }

  int GetDimension(int axis) const { return this->Dims[axis]; }
  int GetMaximumDimension() const { return std::max(this->Dims[0], std::max(this->Dims[1], this->Dims[2])); }
  double GetCellSize(int axis) const { return this->CellSize[axis]; }
  double GetOrigin(int axis) const { return this->Origin[axis]; }
  vtkIdType GetNumberOfCells() const
  {
    return static_cast<vtkIdType>(this->Dims[0]) * this->Dims[1] * this->Dims[2];
  }

  /// Cell coordinate of x along `axis`, clamped to [0, dims - 1].
  int Coordinate(double x, int axis) const
  {
    const double t = (x - this->Origin[axis]) / this->CellSize[axis];
    if (!(t > 0.0))
    {
      return 0;
    }
    return std::min(this->Dims[axis] - 1, static_cast<int>(std::min(t, 1e9)));
  }
  void CellCoordinates(const double x[3], int ijk[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      ijk[k] = this->Coordinate(x[k], k);
    }
  }
  vtkIdType CellId(int i, int j, int k) const
  {
    return (static_cast<vtkIdType>(k) * this->Dims[1] + j) * this->Dims[0] + i;
  }
  vtkIdType CellOf(const double x[3]) const
  {
    return this->CellId(this->Coordinate(x[0], 0), this->Coordinate(x[1], 1), this->Coordinate(x[2], 2));
  }
  /// Low side of cell slab i along `axis`.
  double CellLow(int axis, int i) const { return this->Origin[axis] + i * this->CellSize[axis]; }
  /// The box of cells that covers [x - reach, x + reach] (clamped).
  void CellBox(const double x[3], double reach, int lo[3], int hi[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = this->Coordinate(x[k] - reach, k);
      hi[k] = this->Coordinate(x[k] + reach, k);
    }
  }

  ///@{
  /// Static contents. cellsOf(item, add) calls add(cell) once for each cell the item
  /// lies in (not at all to leave it out); items are 0 .. count - 1.
  template <class CellsOf>
  void Build(vtkIdType count, CellsOf&& cellsOf)
  {
    this->Clear();
    const vtkIdType cells = this->GetNumberOfCells();
    std::vector<std::pair<vtkIdType, vtkIdType>> entries; // (cell, item), items in order
    entries.reserve(static_cast<size_t>(count));
    for (vtkIdType item = 0; item < count; ++item)
    {
      cellsOf(item, [&](vtkIdType cell) { entries.emplace_back(cell, item); });
    }
    this->Start.assign(static_cast<size_t>(cells) + 1, 0);
    for (const auto& e : entries)
    {
      ++this->Start[e.first + 1];
    }
    for (vtkIdType c = 0; c < cells; ++c)
    {
      this->Start[c + 1] += this->Start[c];
    }
    this->Items.resize(entries.size());
    std::vector<vtkIdType> fill(this->Start.begin(), this->Start.end() - 1);
    for (const auto& e : entries) // stable: a cell keeps increasing ids
    {
      this->Items[fill[e.first]++] = e.second;
    }
  }
  /// Points: item i at xyz[3 i], left out where `use` is given and 0.
  void BuildPoints(const std::vector<double>& xyz, const std::vector<char>& use)
  {
    this->Build(static_cast<vtkIdType>(xyz.size() / 3), [&](vtkIdType i, auto&& add) {
      if (use.empty() || use[i])
      {
        add(this->CellOf(&xyz[3 * i]));
      }
    });
  }
  /// Reorders every cell's items by `less` (static contents).
  template <class Less>
  void SortCells(Less&& less)
  {
    for (size_t c = 0; c + 1 < this->Start.size(); ++c)
    {
      std::sort(this->Items.begin() + this->Start[c], this->Items.begin() + this->Start[c + 1], less);
    }
  }
  /// The static items of a cell, as [first, last).
  const vtkIdType* CellBegin(vtkIdType cell) const { return this->Items.data() + this->Start[cell]; }
  const vtkIdType* CellEnd(vtkIdType cell) const { return this->Items.data() + this->Start[cell + 1]; }
  ///@}

  /// Dynamic contents: adds `item` (any id >= 0) to `cell`.
  void Insert(vtkIdType item, vtkIdType cell)
  {
    if (this->Head.empty())
    {
      this->Head.assign(static_cast<size_t>(this->GetNumberOfCells()), -1);
    }
    if (item >= static_cast<vtkIdType>(this->Next.size()))
    {
      this->Next.resize(static_cast<size_t>(item) + 1, -1);
    }
    this->Next[item] = this->Head[cell];
    this->Head[cell] = item;
  }

  bool IsCellEmpty(vtkIdType cell) const
  {
    return (this->Start.empty() || this->Start[cell] == this->Start[cell + 1]) &&
      (this->Head.empty() || this->Head[cell] < 0);
  }

  /// f(item) for the items of one cell: the static ones in order, then the dynamic ones.
  template <class F>
  void ForEachItemInCell(vtkIdType cell, F&& f) const
  {
    if (!this->Start.empty())
    {
      for (vtkIdType s = this->Start[cell]; s < this->Start[cell + 1]; ++s)
      {
        f(this->Items[s]);
      }
    }
    if (!this->Head.empty())
    {
      for (vtkIdType item = this->Head[cell]; item >= 0; item = this->Next[item])
      {
        f(item);
      }
    }
  }

  /// f(ijk, cell) for the cells of the box [lo, hi] of cell coordinates, clipped to
  /// the grid; z, then y, then x.
  template <class F>
  void ForEachCellInBox(const int lo[3], const int hi[3], F&& f) const
  {
    this->VisitBox(lo, hi, [&](const int* ijk, vtkIdType cell) {
      f(ijk, cell);
      return true;
    });
  }

  /// f(item) for the items of the cells of a box (see ForEachCellInBox).
  template <class F>
  void ForEachItemInBox(const int lo[3], const int hi[3], F&& f) const
  {
    this->ForEachCellInBox(lo, hi, [&](const int*, vtkIdType cell) { this->ForEachItemInCell(cell, f); });
  }

  /// True when pred(item) holds for an item of the box's cells; stops after the
  /// first cell that has one.
  template <class Pred>
  bool AnyItemInBox(const int lo[3], const int hi[3], Pred&& pred) const
  {
    bool found = false;
    this->VisitBox(lo, hi, [&](const int*, vtkIdType cell) {
      this->ForEachItemInCell(cell, [&](vtkIdType item) { found = found || pred(item); });
      return !found;
    });
    return found;
  }

  /// f(item) for the items of every cell that comes within `radius` of c (the
  /// boundary cells reaching to infinity).
  template <class F>
  void ForEachItemNear(const double c[3], double radius, F&& f) const
  {
    const double r2 = radius * radius;
    const int lo = this->Coordinate(c[0] - radius, 0), hi = this->Coordinate(c[0] + radius, 0);
    this->ForEachRowNear(c, radius, [&](int y, int z, int x0, int x1, double d2) {
      // One more cell each side (within the box): the test below alone decides,
      // whatever the rounding of the run.
      for (int x = std::max(lo, x0 - 1); x <= std::min(hi, x1 + 1); ++x)
      {
        const double dx = this->SlabDistance(c[0], x, 0);
        if (d2 + dx * dx <= r2)
        {
          this->ForEachItemInCell(this->CellId(x, y, z), f);
        }
      }
    });
  }

  /// f(y, z, x0, x1, d2) for each row of cells (fixed y and z) that comes within
  /// `radius` of c, d2 being the row's squared distance to c and [x0, x1] the run of
  /// its cells that may hold a point within `radius` (every point whose x lies in
  /// [c - radius, c + radius]); z, then y. The static items of a run are
  /// contiguous: from ItemOffset(CellId(x0, y, z)) to ItemOffset(CellId(x1, y, z) + 1).
  template <class F>
  void ForEachRowNear(const double c[3], double radius, F&& f) const
  {
    int lo[3], hi[3];
    this->CellBox(c, radius, lo, hi);
    const double r2 = radius * radius;
    for (int z = lo[2]; z <= hi[2]; ++z)
    {
      const double dz = this->SlabDistance(c[2], z, 2);
      for (int y = lo[1]; y <= hi[1]; ++y)
      {
        const double dy = this->SlabDistance(c[1], y, 1);
        const double d2 = dz * dz + dy * dy;
        if (d2 > r2)
        {
          continue;
        }
        const double dx = std::sqrt(r2 - d2);
        f(y, z, this->Coordinate(c[0] - dx, 0), this->Coordinate(c[0] + dx, 0), d2);
      }
    }
  }

  /// Distance along `axis` from x to cell slab i (0 inside; the boundary slabs reach to infinity).
  double SlabDistance(double x, int i, int axis) const
  {
    const double a = this->CellLow(axis, i);
    const double b = a + this->CellSize[axis];
    if (x < a && i > 0)
    {
      return a - x;
    }
    if (x > b && i < this->Dims[axis] - 1)
    {
      return x - b;
    }
    return 0.0;
  }

  /// Position of the cell's first static item in the item order (cell = the number of
  /// cells gives the item count): the items are stored cell after cell.
  vtkIdType ItemOffset(vtkIdType cell) const { return this->Start[cell]; }

  /// f(ijk, cell) for the cells at Chebyshev distance `ring` from cell `centre`,
  /// clipped to the grid. Order: layer by layer in z; a layer on the shell's faces
  /// (z = centre +- ring) whole, y then x; any other layer by its square's outline:
  /// for each x the rows y = centre - ring and centre + ring, then for each y in
  /// between the columns x = centre - ring and centre + ring.
  template <class F>
  void ForEachCellInShell(const int centre[3], int ring, F&& f) const
  {
    const int i0 = centre[0] - ring, i1 = centre[0] + ring;
    const int j0 = centre[1] - ring, j1 = centre[1] + ring;
    const int k0 = centre[2] - ring, k1 = centre[2] + ring;
    int ijk[3];
    auto visit = [&](int i, int j) {
      ijk[0] = i;
      ijk[1] = j;
      f(static_cast<const int*>(ijk), this->CellId(i, j, ijk[2]));
    };
    for (ijk[2] = std::max(0, k0); ijk[2] <= std::min(this->Dims[2] - 1, k1); ++ijk[2])
    {
      if (ijk[2] == k0 || ijk[2] == k1)
      {
        for (int j = std::max(0, j0); j <= std::min(this->Dims[1] - 1, j1); ++j)
        {
          for (int i = std::max(0, i0); i <= std::min(this->Dims[0] - 1, i1); ++i)
          {
            visit(i, j);
          }
        }
        continue;
      }
      for (int i = std::max(0, i0); i <= std::min(this->Dims[0] - 1, i1); ++i)
      {
        if (j0 >= 0)
        {
          visit(i, j0);
        }
        if (j1 < this->Dims[1] && j1 != j0)
        {
          visit(i, j1);
        }
      }
      for (int j = std::max(0, j0 + 1); j <= std::min(this->Dims[1] - 1, j1 - 1); ++j)
      {
        if (i0 >= 0)
        {
          visit(i0, j);
        }
        if (i1 < this->Dims[0] && i1 != i0)
        {
          visit(i1, j);
        }
      }
    }
  }

  /// Per cell, the Chebyshev distance in cells to the nearest cell holding an item
  /// (0 for those; -1 everywhere when the grid is empty). Ring searches start there.
  std::vector<int> DistanceToItems() const
  {
    const vtkIdType cells = this->GetNumberOfCells();
    std::vector<int> distance(static_cast<size_t>(cells), -1);
    std::vector<vtkIdType> front;
    for (vtkIdType c = 0; c < cells; ++c)
    {
      if (!this->IsCellEmpty(c))
      {
        distance[c] = 0;
        front.push_back(c);
      }
    }
    for (size_t head = 0; head < front.size(); ++head)
    {
      const vtkIdType c = front[head];
      const int centre[3] = { static_cast<int>(c % this->Dims[0]),
        static_cast<int>((c / this->Dims[0]) % this->Dims[1]),
        static_cast<int>(c / (static_cast<vtkIdType>(this->Dims[0]) * this->Dims[1])) };
      this->ForEachCellInShell(centre, 1, [&](const int*, vtkIdType n) {
        if (distance[n] < 0)
        {
          distance[n] = distance[c] + 1;
          front.push_back(n);
        }
      });
    }
    return distance;
  }

private:
  // f(ijk, cell) over the clipped box, z, then y, then x, until f returns false.
  template <class F>
  void VisitBox(const int lo[3], const int hi[3], F&& f) const
  {
    int ijk[3];
    for (ijk[2] = std::max(0, lo[2]); ijk[2] <= std::min(this->Dims[2] - 1, hi[2]); ++ijk[2])
    {
      for (ijk[1] = std::max(0, lo[1]); ijk[1] <= std::min(this->Dims[1] - 1, hi[1]); ++ijk[1])
      {
        for (ijk[0] = std::max(0, lo[0]); ijk[0] <= std::min(this->Dims[0] - 1, hi[0]); ++ijk[0])
        {
          if (!f(static_cast<const int*>(ijk), this->CellId(ijk[0], ijk[1], ijk[2])))
          {
            return;
          }
        }
      }
    }
  }

  void Clear()
  {
    this->Start.clear();
    this->Items.clear();
    this->Head.clear();
    this->Next.clear();
  }

  double Origin[3] = { 0, 0, 0 };
  double CellSize[3] = { 1, 1, 1 };
  int Dims[3] = { 1, 1, 1 };
  std::vector<vtkIdType> Start, Items; // static: compressed rows
  std::vector<vtkIdType> Head, Next;   // dynamic: linked lists
};

#endif
