// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialTriangleMesh.h"

#include "vtkMedialGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCleanPolyData.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <sstream>

namespace
{
constexpr const char* SourceIdsName = "vtkMedialSourceCellId";

struct EdgeUse
{
  vtkIdType Lo, Hi; // sorted vertex ids
  vtkIdType Triangle;
  bool Forward; // the triangle walks Lo -> Hi
  bool operator<(const EdgeUse& o) const
  {
    return Lo != o.Lo ? Lo < o.Lo : (Hi != o.Hi ? Hi < o.Hi : Triangle < o.Triangle);
  }
};
}

// A triangle with the same three vertices as an earlier one (either orientation) would
// make each of its edges non-manifold and block every ray leaving it: keep the first.
void vtkMedialTriangleMesh::DropDuplicateTriangles()
{
  const size_t nt = this->SourceCellIds.size();
  std::vector<std::array<vtkIdType, 4>> keys(nt); // sorted vertices, then the triangle
  for (size_t t = 0; t < nt; ++t)
  {
    const vtkIdType* v = &this->Triangles[3 * t];
    keys[t] = { v[0], v[1], v[2], static_cast<vtkIdType>(t) };
    std::sort(keys[t].begin(), keys[t].begin() + 3);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> duplicate(nt, 0);
  for (size_t i = 1; i < nt; ++i)
  {
    if (std::equal(keys[i].begin(), keys[i].begin() + 3, keys[i - 1].begin()))
    {
      duplicate[keys[i][3]] = 1;
      ++this->DuplicateTriangles;
    }
  }
  if (this->DuplicateTriangles == 0)
  {
    return;
  }
  size_t kept = 0;
  for (size_t t = 0; t < nt; ++t)
  {
    if (!duplicate[t])
    {
      std::copy_n(&this->Triangles[3 * t], 3, &this->Triangles[3 * kept]);
      this->SourceCellIds[kept++] = this->SourceCellIds[t];
    }
  }
  this->Triangles.resize(3 * kept);
  this->SourceCellIds.resize(kept);
}

bool vtkMedialTriangleMesh::Build(
  vtkPolyData* input, std::string& error, const std::function<bool()>& aborted)
{
  auto stop = [&]() {
    if (aborted && aborted())
    {
      error = "aborted";
      return true;
    }
    return false;
  };
  *this = vtkMedialTriangleMesh();
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    error = "input has no points or no cells";
    return false;
  }
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      std::ostringstream os;
      os << "input point " << i << " has a NaN or infinite coordinate";
      error = os.str();
      return false;
    }
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    error = "input has no polygons or triangle strips (a surface is required)";
    return false;
  }

  // Shallow copy: the pipeline's input must not be modified.
  vtkNew<vtkPolyData> shallow;
  shallow->CopyStructure(input);
  vtkNew<vtkIdFilter> ids;
  ids->SetInputData(shallow);
  ids->PointIdsOff();
  ids->CellIdsOn();
  ids->FieldDataOff();
  ids->SetCellIdsArrayName(SourceIdsName);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputConnection(ids->GetOutputPort());
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  vtkNew<vtkStaticCleanPolyData> merge;
  merge->SetInputConnection(triangulate->GetOutputPort());
  merge->ToleranceIsAbsoluteOn();
  merge->SetAbsoluteTolerance(0.0);
  merge->ConvertPolysToLinesOff();
  merge->ConvertLinesToPointsOff();
  merge->ConvertStripsToPolysOff();
  merge->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  merge->Update();
  vtkPolyData* tri = merge->GetOutput();
  if (stop())
  {
    return false;
  }

  const vtkIdType np = tri->GetNumberOfPoints();
  this->Points.resize(3 * np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    tri->GetPoint(i, &this->Points[3 * i]);
  }
  tri->GetBounds(this->Bounds);
  this->Diagonal = std::sqrt((this->Bounds[1] - this->Bounds[0]) * (this->Bounds[1] - this->Bounds[0]) +
    (this->Bounds[3] - this->Bounds[2]) * (this->Bounds[3] - this->Bounds[2]) +
    (this->Bounds[5] - this->Bounds[4]) * (this->Bounds[5] - this->Bounds[4]));

  auto* sourceIds = vtkIdTypeArray::SafeDownCast(tri->GetCellData()->GetArray(SourceIdsName));
  vtkCellArray* polys = tri->GetPolys();
  const vtkIdType firstPoly = tri->GetNumberOfVerts() + tri->GetNumberOfLines();
  vtkIdType cellId = 0;
  vtkIdType npts;
  const vtkIdType* pts;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts); ++cellId)
  {
    if (npts != 3 || pts[0] == pts[1] || pts[1] == pts[2] || pts[0] == pts[2])
    {
      ++this->DegenerateTriangles; // collapsed by the point merge
      continue;
    }
    this->Triangles.insert(this->Triangles.end(), pts, pts + 3);
    this->SourceCellIds.push_back(sourceIds ? sourceIds->GetValue(firstPoly + cellId) : cellId);
  }
  this->DropDuplicateTriangles();
  const vtkIdType nt = static_cast<vtkIdType>(this->SourceCellIds.size());
  if (nt == 0)
  {
    error = "input has no non-degenerate triangles";
    return false;
  }

  {
    std::vector<char> used(this->Points.size() / 3, 0);
    for (vtkIdType id : this->Triangles)
    {
      this->UsedPoints += used[id] ? 0 : 1;
      used[id] = 1;
    }
  }

  // Edge uses, sorted so that the uses of one edge are adjacent.
  std::vector<EdgeUse> uses;
  uses.reserve(3 * nt);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType* v = &this->Triangles[3 * t];
    for (int e = 0; e < 3; ++e)
    {
      const vtkIdType a = v[e], b = v[(e + 1) % 3];
      uses.push_back({ std::min(a, b), std::max(a, b), t, a < b });
    }
  }
  if (stop())
  {
    return false;
  }
  std::sort(uses.begin(), uses.end());
  if (stop())
  {
    return false;
  }
  // Manifold adjacency: up to 3 neighbours per triangle, with "same direction" flags.
  std::vector<vtkIdType> neighbour(3 * nt, -1);
  std::vector<char> sameDirection(3 * nt, 0);
  std::vector<unsigned char> degree(nt, 0);
  for (size_t i = 0; i < uses.size();)
  {
    size_t j = i + 1;
    while (j < uses.size() && uses[j].Lo == uses[i].Lo && uses[j].Hi == uses[i].Hi)
    {
      ++j;
    }
    ++this->Edges;
    if (j - i == 1)
    {
      ++this->BoundaryEdges;
    }
    else if (j - i == 2)
    {
      const EdgeUse& a = uses[i];
      const EdgeUse& b = uses[i + 1];
      const bool same = a.Forward == b.Forward;
      if (degree[a.Triangle] < 3 && degree[b.Triangle] < 3)
      {
        neighbour[3 * a.Triangle + degree[a.Triangle]] = b.Triangle;
        sameDirection[3 * a.Triangle + degree[a.Triangle]++] = same;
        neighbour[3 * b.Triangle + degree[b.Triangle]] = a.Triangle;
        sameDirection[3 * b.Triangle + degree[b.Triangle]++] = same;
      }
    }
    else
    {
      ++this->NonManifoldEdges;
    }
    i = j;
  }

  // Breadth-first orientation per component.
  std::vector<int> component(nt, -1);
  std::vector<char> flip(nt, 0);
  std::vector<char> componentBad;
  std::vector<vtkIdType> queue;
  queue.reserve(nt);
  for (vtkIdType seed = 0; seed < nt; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    const int c = static_cast<int>(this->Components++);
    componentBad.push_back(0);
    component[seed] = c;
    queue.clear();
    queue.push_back(seed);
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const vtkIdType t = queue[q];
      for (int k = 0; k < degree[t]; ++k)
      {
        const vtkIdType u = neighbour[3 * t + k];
        const char want = flip[t] ^ sameDirection[3 * t + k];
        if (component[u] < 0)
        {
          component[u] = c;
          flip[u] = want;
          queue.push_back(u);
        }
        else if (flip[u] != want)
        {
          componentBad[c] = 1;
        }
      }
    }
  }
  for (char b : componentBad)
  {
    this->NonOrientableComponents += b;
  }
  auto applyFlip = [this](vtkIdType t) { std::swap(this->Triangles[3 * t], this->Triangles[3 * t + 2]); };
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (flip[t])
    {
      applyFlip(t);
    }
  }

  if (stop())
  {
    return false;
  }

  // Signed volume per component, about the box centre for accuracy.
  const double centre[3] = { 0.5 * (this->Bounds[0] + this->Bounds[1]),
    0.5 * (this->Bounds[2] + this->Bounds[3]), 0.5 * (this->Bounds[4] + this->Bounds[5]) };
  std::vector<double> volume(this->Components, 0.0);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    double a[3], b[3], c[3], bc[3];
    const vtkIdType* v = &this->Triangles[3 * t];
    vtkMedialGeometry::Sub(this->GetPoint(v[0]), centre, a);
    vtkMedialGeometry::Sub(this->GetPoint(v[1]), centre, b);
    vtkMedialGeometry::Sub(this->GetPoint(v[2]), centre, c);
    vtkMedialGeometry::Cross(b, c, bc);
    volume[component[t]] += vtkMedialGeometry::Dot(a, bc) / 6.0;
  }
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (volume[component[t]] < 0.0)
    {
      applyFlip(t);
    }
  }
  for (double v : volume)
  {
    this->FlippedComponents += v < 0.0 ? 1 : 0;
    this->Volume += std::fabs(v);
  }

  // Normals, areas, CDF. Zero-area triangles get zero weight and are never sampled.
  this->Normals.resize(3 * nt);
  this->Areas.resize(nt);
  this->AreaCdf.resize(nt);
  const double tinyArea = 1e-14 * this->Diagonal * this->Diagonal;
  double sum = 0.0;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    const vtkIdType* v = &this->Triangles[3 * t];
    double ab[3], ac[3], n[3];
    vtkMedialGeometry::Sub(this->GetPoint(v[1]), this->GetPoint(v[0]), ab);
    vtkMedialGeometry::Sub(this->GetPoint(v[2]), this->GetPoint(v[0]), ac);
    vtkMedialGeometry::Cross(ab, ac, n);
    const double len = std::sqrt(vtkMedialGeometry::Dot(n, n));
    double area = 0.5 * len;
    if (area <= tinyArea)
    {
      ++this->DegenerateTriangles;
      area = 0.0;
    }
    for (int i = 0; i < 3; ++i)
    {
      this->Normals[3 * t + i] = len > 0.0 ? n[i] / len : 0.0;
    }
    this->Areas[t] = area;
    sum += area;
    this->AreaCdf[t] = sum;
  }
  this->TotalArea = sum;
  if (!(sum > 0.0) || !(this->Diagonal > 0.0))
  {
    error = "input surface has no area";
    return false;
  }
  for (double& c : this->AreaCdf)
  {
    c /= sum;
  }
  this->AreaCdf.back() = 1.0;
  return true;
}

vtkIdType vtkMedialTriangleMesh::PickTriangleByArea(double u) const
{
  // First entry strictly greater than u: zero-area triangles repeat the previous
  // CDF value and so are never picked.
  auto it = std::upper_bound(this->AreaCdf.begin(), this->AreaCdf.end(), u);
  if (it == this->AreaCdf.end())
  {
    --it;
  }
  return static_cast<vtkIdType>(it - this->AreaCdf.begin());
}
