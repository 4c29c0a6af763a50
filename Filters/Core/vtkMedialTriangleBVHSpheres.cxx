// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialTriangleBVH::MeasureWideSpheres: each wide node's inner sphere, the bound
// that lets the searches drop a curved patch that a ball comes close to everywhere
// (a ball centred in a finely tessellated sphere), see WideSphere.
#include "vtkMedialTriangleBVH.h"

#include "vtkMedialGeometry.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include <omp.h>

namespace
{
namespace G = vtkMedialGeometry;

// A subtree of at least FitMinimum triangles gets the sphere fitted to the corners of
// FitTriangles of them, spread over it; a smaller one takes its parent's centre.
constexpr std::int32_t FitMinimum = 64;
constexpr std::int32_t FitTriangles = 8;

// Sums over points y for Kasa's algebraic sphere fit (least squares of
// |y|^2 - 2 c.y - k), taken about a reference point for conditioning.
struct SphereMoments
{
  double Count = 0.0;
  double S[3] = { 0, 0, 0 };
  double SS[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double Q = 0.0;
  double QS[3] = { 0, 0, 0 };
  void Add(const double y[3])
  {
    const double q = G::Dot(y, y);
    this->Count += 1.0;
    this->Q += q;
    for (int i = 0; i < 3; ++i)
    {
      this->S[i] += y[i];
      this->QS[i] += q * y[i];
      for (int j = 0; j < 3; ++j)
      {
        this->SS[i][j] += y[i] * y[j];
      }
    }
  }
  // The fitted centre, solved about the points' mean m: (sum z z^T) (c - m) =
  // sum |z|^2 z / 2 with z = y - m. False for fewer than 4 points or a flat set.
  bool Centre(double c[3]) const
  {
    if (this->Count < 4.0)
    {
      return false;
    }
    const double n = this->Count;
    const double m[3] = { this->S[0] / n, this->S[1] / n, this->S[2] / n };
    const double mm = G::Dot(m, m);
    const double qz = this->Q - n * mm;
    double a[3][3], b[3];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a[i][j] = this->SS[i][j] - n * m[i] * m[j];
      }
      b[i] = 0.5 *
        (this->QS[i] - 2.0 * (this->SS[i][0] * m[0] + this->SS[i][1] * m[1] + this->SS[i][2] * m[2]) +
          n * mm * m[i] - m[i] * qz);
    }
    const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    const double scale = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    if (!(std::fabs(det) > 1e-13 * scale * scale * scale))
    {
      return false;
    }
    const double x = (b[0] * c00 + b[1] * (a[0][2] * a[2][1] - a[0][1] * a[2][2]) +
                       b[2] * (a[0][1] * a[1][2] - a[0][2] * a[1][1])) / det;
    const double y = (b[0] * c01 + b[1] * (a[0][0] * a[2][2] - a[0][2] * a[2][0]) +
                       b[2] * (a[0][2] * a[1][0] - a[0][0] * a[1][2])) / det;
    const double z = (b[0] * c02 + b[1] * (a[0][1] * a[2][0] - a[0][0] * a[2][1]) +
                       b[2] * (a[0][0] * a[1][1] - a[0][1] * a[1][0])) / det;
    c[0] = m[0] + x;
    c[1] = m[1] + y;
    c[2] = m[2] + z;
    return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
  }
};

// The float at or below v.
float FloatAtOrBelow(double v)
{
  float f = static_cast<float>(v);
  if (static_cast<double>(f) > v)
  {
    f = std::nextafter(f, -HUGE_VALF);
  }
  return f;
}
}

// Each wide node's subtree holds the leaf slots [first, last): a subtree's triangles are
// consecutive in leaf order and a child's wide node comes after its parent's, so one pass
// from the end finds every range. `parent` (optional) gets each wide node's parent, -1 at
// the root.
void vtkMedialTriangleBVH::WideSlotRanges(std::int32_t* first, std::int32_t* last, std::int32_t* parent) const
{
  const std::int64_t wides = static_cast<std::int64_t>(this->WideNodes.size());
  for (std::int64_t index = wides - 1; index >= 0; --index)
  {
    const WideNode& wide = this->WideNodes[index];
    std::int32_t lo = INT_MAX, hi = -1;
    for (int i = 0; i < 4; ++i)
    {
      const std::int32_t child = wide.Child[i];
      if (child < 0)
      {
        const LeafSlots leaf(child);
        lo = std::min(lo, leaf.Start);
        hi = std::max(hi, leaf.End);
      }
      else if (child > 0)
      {
        lo = std::min(lo, first[child]);
        hi = std::max(hi, last[child]);
        if (parent)
        {
          parent[child] = static_cast<std::int32_t>(index);
        }
      }
    }
    first[index] = lo;
    last[index] = hi;
  }
  if (parent && wides > 0)
  {
    parent[0] = -1;
  }
}

void vtkMedialTriangleBVH::MeasureWideSpheres()
{
  const std::int64_t wides = static_cast<std::int64_t>(this->WideNodes.size());
  this->WideSpheres.resize(static_cast<size_t>(wides));
  vtkMedialBuffer<std::int32_t> first(static_cast<size_t>(wides)), last(static_cast<size_t>(wides));
  vtkMedialBuffer<std::int32_t> parent(static_cast<size_t>(wides));
  this->WideSlotRanges(first.data(), last.data(), parent.data());
  // The centres of the subtrees of FitMinimum triangles or more, fitted in parallel
  // (reach2 +inf: fitted, -inf: none).
  vtkMedialBuffer<double> reach2(static_cast<size_t>(wides));
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t index = 0; index < wides; ++index)
  {
    WideSphere& sphere = this->WideSpheres[index];
    sphere.Centre[0] = sphere.Centre[1] = sphere.Centre[2] = 0.0f;
    sphere.Reach = -HUGE_VALF;
    reach2[index] = -HUGE_VAL;
    const std::int32_t count = last[index] - first[index];
    if (count < FitMinimum)
    {
      continue;
    }
    double scratch[9], reference[3];
    SphereMoments moments;
    for (std::int32_t j = 0; j < FitTriangles; ++j)
    {
      const std::int32_t slot =
        first[index] + static_cast<std::int32_t>(static_cast<std::int64_t>(j) * count / FitTriangles);
      const double* v = this->Corners(slot, scratch);
      for (int c = 0; c < 3; ++c)
      {
        if (j == 0 && c == 0)
        {
          G::Copy(v, reference);
        }
        double y[3];
        G::Sub(v + 3 * c, reference, y);
        moments.Add(y);
      }
    }
    double centre[3];
    if (moments.Centre(centre))
    {
      for (int k = 0; k < 3; ++k)
      {
        sphere.Centre[k] = static_cast<float>(centre[k] + (reference[k] - this->Origin[k]));
      }
      reach2[index] = std::isfinite(sphere.Centre[0] + sphere.Centre[1] + sphere.Centre[2]) ? HUGE_VAL : -HUGE_VAL;
    }
  }
  // A smaller subtree takes its parent's centre (parents first): on a curved patch it
  // fits as well, and the fit would cost more than the rest of this pass.
  for (std::int64_t index = 1; index < wides; ++index)
  {
    if (last[index] - first[index] < FitMinimum && parent[index] >= 0)
    {
      std::copy_n(this->WideSpheres[parent[index]].Centre, 3, this->WideSpheres[index].Centre);
      reach2[index] = reach2[parent[index]];
    }
  }
  // A lower bound of the distance from each centre to the triangles of the node's own
  // leaves (relative to Origin, as the searches measure the bound): the larger of the
  // distance to the triangle's plane less its corners' distance from that plane, and
  // the nearest corner's less a third of the longest edge's square
  // (vtkMedialGeometry::TriangleDistance2Below); both hold for slivers too.
#pragma omp parallel for schedule(dynamic, 256)
  for (std::int64_t index = 0; index < wides; ++index)
  {
    if (!(reach2[index] > 0.0))
    {
      continue;
    }
    const WideSphere& sphere = this->WideSpheres[index];
    const double centre[3] = { sphere.Centre[0], sphere.Centre[1], sphere.Centre[2] };
    const WideNode& wide = this->WideNodes[index];
    double nearest2 = HUGE_VAL, scratch[9];
    for (int i = 0; i < 4; ++i)
    {
      if (wide.Child[i] >= 0)
      {
        continue;
      }
      const LeafSlots leaf(wide.Child[i]);
      for (std::int32_t slot = leaf.Start; slot < leaf.End; ++slot)
      {
        const double* v = this->Corners(slot, scratch);
        const double* plane = this->LeafTriangles[slot].Plane;
        double corners[9], off = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          G::Sub(v + 3 * c, this->Origin, corners + 3 * c);
          off = std::max(off, std::fabs(G::Dot(plane, v + 3 * c) - plane[3]));
        }
        const double height = std::fabs(G::Dot(plane, centre) + (G::Dot(plane, this->Origin) - plane[3])) - off;
        const double below = G::TriangleDistance2Below(centre, corners, corners + 3, corners + 6);
        nearest2 = std::min(nearest2, std::max(height > 0.0 ? height * height : 0.0, below));
      }
    }
    reach2[index] = nearest2;
  }
  // The reach from the end (children first): the node's own leaves, and each inner
  // lane's subtree through its own sphere, the same bound as the searches use. Rounded
  // down past the rounding of the corners relative to Origin.
  const double pad = 4.0 * this->RoundingPad;
  for (std::int64_t index = wides - 1; index >= 0; --index)
  {
    double r2 = reach2[index];
    if (!(r2 >= 0.0))
    {
      continue; // no centre: Reach stays -inf
    }
    WideSphere& sphere = this->WideSpheres[index];
    const WideNode& wide = this->WideNodes[index];
    const double centre[3] = { sphere.Centre[0], sphere.Centre[1], sphere.Centre[2] };
    for (int i = 0; i < 4 && r2 > 0.0; ++i)
    {
      if (wide.Child[i] > 0)
      {
        r2 = std::min(r2, this->SphereDistance2Below(wide, i, wide.Child[i], centre));
      }
    }
    if (r2 > 0.0 && r2 < HUGE_VAL)
    {
      const double reach = std::sqrt(r2) * (1.0 - 1e-12) - pad;
      sphere.Reach = reach > 0.0 ? FloatAtOrBelow(reach) : -HUGE_VALF;
    }
  }
}

vtkIdType vtkMedialTriangleBVH::CountInnerSphereViolations() const
{
  const std::int64_t wides = static_cast<std::int64_t>(this->WideNodes.size());
  std::vector<std::int32_t> first(static_cast<size_t>(wides)), last(static_cast<size_t>(wides));
  this->WideSlotRanges(first.data(), last.data(), nullptr);
  vtkIdType violations = 0;
  for (std::int64_t index = 0; index < wides; ++index)
  {
    const WideSphere& sphere = this->WideSpheres[index];
    if (!(sphere.Reach > 0.0f))
    {
      continue;
    }
    const double centre[3] = { sphere.Centre[0], sphere.Centre[1], sphere.Centre[2] };
    double nearest2 = HUGE_VAL, scratch[9], corners[9], q[3];
    for (std::int32_t slot = first[index]; slot < last[index]; ++slot)
    {
      const double* v = this->Corners(slot, scratch);
      for (int c = 0; c < 9; ++c)
      {
        corners[c] = v[c] - this->Origin[c % 3];
      }
      nearest2 = std::min(nearest2, G::ClosestPointOnTriangle(centre, corners, corners + 3, corners + 6, q));
    }
    violations += std::sqrt(nearest2) < static_cast<double>(sphere.Reach);
  }
  return violations;
}
