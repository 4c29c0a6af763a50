// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialNearestPoints (the seam solver's neighbour pairs) against brute force: for
// every query, the k nearest points must be the first k of all points sorted by
// (squared distance, id), in that order. Point sets: random in a box, random on a
// sheet (the medial centres' case, where the grid is sized from the occupancy), many
// duplicates (more copies of a place than k), an integer lattice (exact ties at every
// distance) and the same lattice scaled by 0.1 and shifted, collinear and coincident
// sets, and k larger than the number of points. Queries: the points themselves, and
// points around and outside the set. Then, where no distance ties at the k-th place,
// the set agrees with vtkStaticPointLocator::FindClosestNPoints (what the solver used
// before), on random points and on the duplicates.
#include "MedialTestUtilities.h"

#include "vtkMedialNearestPoints.h"
#include "vtkMedialPointCloud.h"

#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
double Distance2(const double* x, const double* q)
{
  return (x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]) + (x[2] - q[2]) * (x[2] - q[2]);
}

// The first k + 1 of all points by (squared distance, id), with their squared distances.
std::vector<std::pair<double, vtkIdType>> BruteForce(const std::vector<double>& xyz, const double* x, int k)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  std::vector<std::pair<double, vtkIdType>> all;
  for (vtkIdType i = 0; i < n; ++i)
  {
    all.emplace_back(Distance2(x, &xyz[3 * i]), i);
  }
  const auto end = all.begin() + std::min<vtkIdType>(k + 1, n);
  std::partial_sort(all.begin(), end, all.end());
  all.erase(end, all.end());
  return all;
}

// Every point as a query, and `extra` random queries over a box 1.5 times the set's.
int CheckSet(const char* label, const std::vector<double>& xyz, int k, int extra, unsigned seed, int& ties)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  vtkMedialNearestPoints nearest;
  nearest.Build(xyz.data(), n);
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], xyz[3 * i + a]);
      hi[a] = std::max(hi[a], xyz[3 * i + a]);
    }
  }
  std::mt19937_64 random(seed);
  std::vector<double> queries(xyz);
  for (int q = 0; q < extra; ++q)
  {
    for (int a = 0; a < 3; ++a)
    {
      const double half = 0.75 * (hi[a] - lo[a]) + 0.5;
      std::uniform_real_distribution<double> u(0.5 * (lo[a] + hi[a]) - half, 0.5 * (lo[a] + hi[a]) + half);
      queries.push_back(u(random));
    }
  }
  std::vector<vtkIdType> ids(static_cast<size_t>(k));
  std::vector<double> dist2(static_cast<size_t>(k));
  for (size_t q = 0; q < queries.size() / 3; ++q)
  {
    const double* x = &queries[3 * q];
    const auto expected = BruteForce(xyz, x, k);
    const int count = nearest.Find(x, k, ids.data(), dist2.data());
    MEDIAL_CHECK(count == static_cast<int>(std::min<vtkIdType>(k, n)), "%s: query %zu: %d points, expected %lld",
      label, q, count, static_cast<long long>(std::min<vtkIdType>(k, n)));
    for (int j = 0; j < count; ++j)
    {
      MEDIAL_CHECK(ids[j] == expected[j].second && dist2[j] == expected[j].first,
        "%s: query %zu: neighbour %d is %lld, expected %lld", label, q, j, static_cast<long long>(ids[j]),
        static_cast<long long>(expected[j].second));
    }
    if (count < n && expected[count].first == dist2[count - 1])
    {
      ++ties; // the k-th distance shared with a point left out: the id decided
    }
  }
  return EXIT_SUCCESS;
}

// The k nearest of each point as a set, from vtkStaticPointLocator and from vtkMedialNearestPoints.
int CheckAgainstLocator(const char* label, const std::vector<double>& xyz, int k)
{
  const vtkIdType n = static_cast<vtkIdType>(xyz.size() / 3);
  const auto locator = vtkMedialPointCloud::Locator(xyz.data(), n);
  vtkMedialNearestPoints nearest;
  nearest.Build(xyz.data(), n);
  vtkNew<vtkIdList> found;
  std::vector<vtkIdType> ids(static_cast<size_t>(k));
  std::vector<double> dist2(static_cast<size_t>(k));
  for (vtkIdType i = 0; i < n; ++i)
  {
    locator->FindClosestNPoints(k, &xyz[3 * i], found);
    std::set<vtkIdType> expected(found->begin(), found->end());
    const int count = nearest.Find(&xyz[3 * i], k, ids.data(), dist2.data());
    MEDIAL_CHECK(std::set<vtkIdType>(ids.begin(), ids.begin() + count) == expected,
      "%s: point %lld: not the locator's %d nearest", label, static_cast<long long>(i), k);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialNearestPoints(int, char*[])
{
  std::mt19937_64 random(37);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int ties = 0;

  std::vector<double> box;
  for (int i = 0; i < 3 * 2000; ++i)
  {
    box.push_back(unit(random));
  }
  MEDIAL_CHECK(CheckSet("random box", box, 13, 500, 1, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("random box, k = 1", box, 1, 200, 2, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("random box, k = 40", box, 40, 200, 3, ties) == EXIT_SUCCESS, "see above");

  // A wavy sheet: most of the box's cells empty.
  std::vector<double> sheet;
  for (int i = 0; i < 2000; ++i)
  {
    const double u = unit(random), v = unit(random);
    sheet.insert(sheet.end(), { 10.0 * u, 10.0 * v, 0.3 * std::sin(3.0 * u) * std::cos(2.0 * v) });
  }
  MEDIAL_CHECK(CheckSet("sheet", sheet, 13, 300, 4, ties) == EXIT_SUCCESS, "see above");

  // 200 places, each 1 to 20 times, the copies spread over the ids.
  std::vector<double> places, duplicates;
  for (int i = 0; i < 3 * 200; ++i)
  {
    places.push_back(unit(random));
  }
  std::vector<int> order;
  for (int p = 0; p < 200; ++p)
  {
    for (int c = 0; c < 1 + p % 20; ++c)
    {
      order.push_back(p);
    }
  }
  std::shuffle(order.begin(), order.end(), random);
  for (int p : order)
  {
    duplicates.insert(duplicates.end(), { places[3 * p], places[3 * p + 1], places[3 * p + 2] });
  }
  const int before = ties;
  MEDIAL_CHECK(CheckSet("duplicates", duplicates, 13, 200, 5, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(ties > before, "duplicates: no tie at the k-th distance, the tie rule is not tested");

  // An integer lattice: every distance shared by many points; and the same scaled by 0.1 and shifted.
  std::vector<double> lattice, scaled;
  for (int z = 0; z < 9; ++z)
  {
    for (int y = 0; y < 11; ++y)
    {
      for (int x = 0; x < 13; ++x)
      {
        lattice.insert(lattice.end(), { double(x), double(y), double(z) });
        scaled.insert(scaled.end(), { 0.1 * x + 0.3, 0.1 * y - 7.0, 0.1 * z });
      }
    }
  }
  const int latticeTies = ties;
  MEDIAL_CHECK(CheckSet("lattice", lattice, 13, 200, 6, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(ties > latticeTies + 500, "lattice: only %d ties at the k-th distance", ties - latticeTies);
  MEDIAL_CHECK(CheckSet("lattice, k = 7", lattice, 7, 0, 7, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("scaled lattice", scaled, 13, 200, 8, ties) == EXIT_SUCCESS, "see above");

  // Degenerate sets: on a line; all at one place; fewer points than k.
  std::vector<double> line, one, few;
  for (int i = 0; i < 500; ++i)
  {
    line.insert(line.end(), { 0.5 * unit(random), 1.0, 2.0 });
    one.insert(one.end(), { 1.0, 2.0, 3.0 });
  }
  for (int i = 0; i < 3 * 5; ++i)
  {
    few.push_back(unit(random));
  }
  MEDIAL_CHECK(CheckSet("line", line, 13, 100, 9, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("one place", one, 13, 100, 10, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("5 points, k = 13", few, 13, 100, 11, ties) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckSet("1 point", std::vector<double>{ 1.0, 2.0, 3.0 }, 13, 10, 12, ties) == EXIT_SUCCESS,
    "see above");

  // The locator the seam solver used before: the same sets.
  MEDIAL_CHECK(CheckAgainstLocator("random box", box, 13) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckAgainstLocator("sheet", sheet, 13) == EXIT_SUCCESS, "see above");
  MEDIAL_CHECK(CheckAgainstLocator("duplicates", duplicates, 13) == EXIT_SUCCESS, "see above");
  return EXIT_SUCCESS;
}
