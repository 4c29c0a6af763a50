// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialRepairWeld.h"

#include "vtkMedialDisjointSets.h"
#include "vtkMedialPointCloud.h"

#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkStaticPointLocator.h"

#include <vector>

namespace vtkMedialRepairWeld
{
void Weld(vtkMedialSurfaceRepair::Soup& soup, double tolerance, Counts& counts)
{
  counts = Counts();
  const vtkIdType n = static_cast<vtkIdType>(soup.Points.size());
  if (n == 0)
  {
    return;
  }
  // The soup's coordinates, read in place.
  const auto locator = vtkMedialPointCloud::Locator(soup.Points[0].data(), n);

  // The pairs, bucket by bucket. A point farther than the tolerance from its bucket's
  // faces has all its neighbours in its bucket: it is compared with the bucket's later
  // points only. A point near a face (within twice the tolerance, with a margin for the
  // rounding of the bucket's bounds) is queried across buckets. Every pair within the
  // tolerance is thus found (once or twice); the order in which they are found does not
  // change the clusters.
  const double* bounds = locator->GetBounds();
  const double* h = locator->GetSpacing();
  int divisions[3];
  locator->GetDivisions(divisions);
  const double tolerance2 = tolerance * tolerance;
  double near[3];
  for (int k = 0; k < 3; ++k)
  {
    near[k] = 2.0 * tolerance + 1e-9 * h[k];
  }
  const vtkIdType buckets = static_cast<vtkIdType>(divisions[0]) * divisions[1] * divisions[2];
  // A set's root is its lowest point: a cluster's name does not depend on the order in
  // which its pairs are found.
  vtkMedialDisjointSets clusters(n);
  vtkNew<vtkIdList> inBucket, found;
  for (vtkIdType b = 0; b < buckets; ++b)
  {
    if (locator->GetNumberOfPointsInBucket(b) == 0)
    {
      continue;
    }
    locator->GetBucketIds(b, inBucket);
    const vtkIdType ijk[3] = { b % divisions[0], (b / divisions[0]) % divisions[1],
      b / (static_cast<vtkIdType>(divisions[0]) * divisions[1]) };
    const vtkIdType count = inBucket->GetNumberOfIds();
    for (vtkIdType a = 0; a < count; ++a)
    {
      const vtkIdType i = inBucket->GetId(a);
      const double* x = soup.Points[i].data();
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k)
      {
        const double lo = bounds[2 * k] + ijk[k] * h[k];
        inside = x[k] - lo > near[k] && lo + h[k] - x[k] > near[k];
      }
      if (inside)
      {
        for (vtkIdType c = a + 1; c < count; ++c)
        {
          const vtkIdType j = inBucket->GetId(c);
          if (vtkMath::Distance2BetweenPoints(x, soup.Points[j].data()) <= tolerance2)
          {
            clusters.Join(i, j);
          }
        }
      }
      else
      {
        locator->FindPointsWithinRadius(tolerance, x, found);
        for (vtkIdType c = 0; c < found->GetNumberOfIds(); ++c)
        {
          clusters.Join(i, found->GetId(c));
        }
      }
    }
  }

  // Each cluster's lowest point stands for it; the points are renumbered in order of
  // first use by the triangles that keep three clusters.
  std::vector<vtkIdType> id(static_cast<size_t>(n), -1);
  vtkMedialSurfaceRepair::Soup welded;
  welded.Triangles.reserve(soup.Triangles.size());
  for (const auto& t : soup.Triangles)
  {
    const vtkIdType a = clusters.Find(t[0]), b = clusters.Find(t[1]), c = clusters.Find(t[2]);
    if (a == b || b == c || a == c)
    {
      ++counts.DroppedTriangles;
      continue;
    }
    std::array<vtkIdType, 3> tri;
    const vtkIdType corners[3] = { a, b, c };
    for (int k = 0; k < 3; ++k)
    {
      vtkIdType& to = id[corners[k]];
      if (to < 0)
      {
        to = static_cast<vtkIdType>(welded.Points.size());
        welded.Points.push_back(soup.Points[corners[k]]);
      }
      tri[k] = to;
    }
    welded.Triangles.push_back(tri);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    counts.MergedPoints += clusters.Find(i) != i ? 1 : 0;
  }
  soup = std::move(welded);
}
}
