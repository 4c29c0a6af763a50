// SPDX-License-Identifier: BSD-3-Clause
// The surface preparation's own fast paths against what they replace:
//  - vtkMedialTriangleMesh reads triangles straight from the cell array and merges
//    coincident points itself: on a shuffled triangle soup (with -0 coordinates,
//    unused points, a collapsed and a duplicate triangle), and on the same soup with
//    quads and a strip (the vtkTriangleFilter path), the points, the triangles' vertex
//    sets, the source cell ids and the counts equal those of VTK's pipeline
//    (vtkIdFilter, vtkTriangleFilter, vtkStaticCleanPolyData at tolerance 0);
//  - rays through the tree are watertight: from inside a closed octahedron (whose
//    rays from the centre meet vertices and edges exactly) and sphere, rays aimed
//    exactly at every vertex and edge midpoint hit a triangle at that point, and
//    count one crossing (vtkMedialSurfaceQuery::CountCrossings);
//  - the query needs none of the mesh's arrays after Build (the random sampler frees
//    them before it solves the balls): after vtkMedialTriangleMesh::ReleaseGeometry the
//    same rays hit the same triangles at the same distances, and the same segments
//    cross the surface, bit for bit.
#include "MedialTestUtilities.h"

#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellData.h"
#include "vtkIdFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkPlatonicSolidSource.h"
#include "vtkStaticCleanPolyData.h"
#include "vtkTriangleFilter.h"

#include <array>
#include <random>
#include <set>
#include <vector>

using namespace medialtest;

namespace
{
// A closed sphere as a soup: every triangle has its own three points, the triangles
// are shuffled, zeros are written as -0 in one copy out of two, and some unused
// points, a collapsed triangle and a duplicate triangle are added. With `polygons`,
// a quad and a strip over fresh points are appended (one strip triangle repeats one
// of the quad's).
vtkSmartPointer<vtkPolyData> Soup(bool polygons)
{
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(2);
  sphere->Update();
  vtkPolyData* closed = sphere->GetOutput();
  std::vector<std::array<vtkIdType, 3>> triangles;
  vtkIdType npts;
  const vtkIdType* pts;
  vtkCellArray* polys = closed->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
  {
    triangles.push_back({ pts[0], pts[1], pts[2] });
  }
  std::mt19937 random(5);
  std::shuffle(triangles.begin(), triangles.end(), random);
  triangles.push_back(triangles[3]); // a duplicate
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  int copy = 0;
  auto addPoint = [&](const double x[3]) {
    double y[3];
    for (int k = 0; k < 3; ++k)
    {
      y[k] = x[k] == 0.0 && (copy++ % 2) ? -0.0 : x[k];
    }
    return points->InsertNextPoint(y);
  };
  for (const auto& t : triangles)
  {
    vtkIdType ids[3];
    for (int j = 0; j < 3; ++j)
    {
      double x[3];
      closed->GetPoint(t[j], x);
      ids[j] = addPoint(x);
    }
    cells->InsertNextCell(3, ids);
    const double unused[3] = { 7.0, 7.0, static_cast<double>(points->GetNumberOfPoints()) };
    if (cells->GetNumberOfCells() % 50 == 0)
    {
      points->InsertNextPoint(unused);
    }
  }
  {
    // Collapsed: two of its points coincide.
    double a[3], b[3];
    closed->GetPoint(0, a);
    closed->GetPoint(1, b);
    const vtkIdType ids[3] = { addPoint(a), addPoint(b), addPoint(a) };
    cells->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> soup;
  soup->SetPoints(points);
  soup->SetPolys(cells);
  if (polygons)
  {
    // A quad and a strip, apart from the sphere.
    const double quad[4][3] = { { 3, 0, 0 }, { 4, 0, 0 }, { 4, 1, 0 }, { 3, 1, 0 } };
    vtkIdType q[4];
    for (int j = 0; j < 4; ++j)
    {
      q[j] = addPoint(quad[j]);
    }
    cells->InsertNextCell(4, q);
    vtkNew<vtkCellArray> strips;
    const vtkIdType s[5] = { q[0], q[1], q[3], q[2], addPoint(quad[0]) };
    strips->InsertNextCell(5, s);
    soup->SetStrips(strips);
  }
  return soup;
}

// The old import, VTK's filters, against the mesh's own.
int CheckImport(const char* label, vtkPolyData* soup)
{
  vtkNew<vtkIdFilter> ids;
  ids->SetInputData(soup);
  ids->PointIdsOff();
  ids->CellIdsOn();
  ids->SetCellIdsArrayName("ids");
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
  vtkPolyData* reference = merge->GetOutput();
  auto* sourceIds = vtkIdTypeArray::SafeDownCast(reference->GetCellData()->GetArray("ids"));
  // Sorted vertices and source cell of each triangle the mesh keeps: not collapsed,
  // and the first with its vertices.
  std::vector<std::array<vtkIdType, 4>> expected;
  std::set<std::array<vtkIdType, 3>> seen;
  vtkIdType collapsed = 0, duplicates = 0, npts;
  const vtkIdType* pts;
  vtkIdType c = 0;
  vtkCellArray* polys = reference->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts); ++c)
  {
    // VTK's merge may leave a collapsed triangle with 2 ids or with a repeated one.
    std::array<vtkIdType, 4> key = { pts[0], pts[1], npts > 2 ? pts[2] : pts[1], sourceIds->GetValue(c) };
    std::sort(key.begin(), key.begin() + 3);
    if (npts != 3 || key[0] == key[1] || key[1] == key[2])
    {
      ++collapsed;
    }
    else if (!seen.insert({ key[0], key[1], key[2] }).second)
    {
      ++duplicates;
    }
    else
    {
      expected.push_back(key);
    }
  }

  vtkMedialTriangleMesh mesh;
  std::string error;
  MEDIAL_CHECK(mesh.Build(soup, error), "%s: %s", label, error.c_str());
  MEDIAL_CHECK(mesh.GetNumberOfPoints() == reference->GetNumberOfPoints(), "%s: %lld points, VTK %lld", label,
    static_cast<long long>(mesh.GetNumberOfPoints()), static_cast<long long>(reference->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh.GetNumberOfPoints(); ++i)
  {
    double x[3];
    reference->GetPoint(i, x);
    MEDIAL_CHECK(std::equal(x, x + 3, mesh.GetPoint(i)), "%s: point %lld differs", label, static_cast<long long>(i));
  }
  MEDIAL_CHECK(collapsed == 1 && mesh.DegenerateTriangles == collapsed && mesh.DuplicateTriangles == duplicates &&
      duplicates >= 1,
    "%s: %lld degenerate, %lld duplicate; VTK %lld collapsed, %lld duplicate", label,
    static_cast<long long>(mesh.DegenerateTriangles), static_cast<long long>(mesh.DuplicateTriangles),
    static_cast<long long>(collapsed), static_cast<long long>(duplicates));
  // The mesh turns triangles over: compare vertex sets.
  std::vector<std::array<vtkIdType, 4>> found;
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    std::array<vtkIdType, 4> key = { v[0], v[1], v[2], mesh.SourceCellIds[t] };
    std::sort(key.begin(), key.begin() + 3);
    found.push_back(key);
  }
  std::sort(expected.begin(), expected.end());
  std::sort(found.begin(), found.end());
  MEDIAL_CHECK(found == expected, "%s: %zu triangles, VTK %zu, or a triangle or its source cell differs",
    label, found.size(), expected.size());
  std::printf("%s: %lld points and %zu triangles as VTK's pipeline gives\n", label,
    static_cast<long long>(mesh.GetNumberOfPoints()), found.size());
  return EXIT_SUCCESS;
}

int CheckWatertightRays(const char* label, vtkPolyData* closed)
{
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  MEDIAL_CHECK(mesh.Build(closed, error) && query.Build(&mesh, error), "%s", error.c_str());
  const double centre[3] = { 0.5 * (mesh.Bounds[0] + mesh.Bounds[1]), 0.5 * (mesh.Bounds[2] + mesh.Bounds[3]),
    0.5 * (mesh.Bounds[4] + mesh.Bounds[5]) };
  long long rays = 0;
  struct Answer
  {
    vtkMedialSurfaceQuery::RayHit Hit;
    bool Crosses;
  };
  std::vector<std::array<double, 3>> targets;
  std::vector<Answer> answers;
  auto aim = [&](const double target[3]) {
    targets.push_back({ target[0], target[1], target[2] });
    double d[3], length = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d[k] = target[k] - centre[k];
      length += d[k] * d[k];
    }
    length = std::sqrt(length);
    for (double& x : d)
    {
      x /= length;
    }
    vtkMedialSurfaceQuery::RayHit hit;
    MEDIAL_CHECK(query.Intersect(centre, d, 0.0, HUGE_VAL, -1, hit), "ray %lld slips through the surface", rays);
    MEDIAL_CHECK(std::fabs(hit.Distance - length) <= 1e-9 * mesh.Diagonal, "ray %lld: hit at %g, aimed at %g", rays,
      hit.Distance, length);
    MEDIAL_CHECK(query.CountCrossings(centre, d, HUGE_VAL) == 1, "ray %lld: %d crossings", rays,
      query.CountCrossings(centre, d, HUGE_VAL));
    ++rays;
    return EXIT_SUCCESS;
  };
  // A ray's hit and whether the segment from the centre to twice the target crosses.
  auto answer = [&](const std::array<double, 3>& target) {
    double d[3], beyond[3], length = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d[k] = target[k] - centre[k];
      beyond[k] = centre[k] + 2.0 * d[k];
      length += d[k] * d[k];
    }
    for (double& x : d)
    {
      x /= std::sqrt(length);
    }
    Answer a{};
    query.Intersect(centre, d, 0.0, HUGE_VAL, -1, a.Hit);
    a.Crosses = query.SegmentCrossesSurface(centre, beyond);
    return a;
  };
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = mesh.GetTriangle(t);
    for (int j = 0; j < 3; ++j)
    {
      const double* a = mesh.GetPoint(v[j]);
      const double* b = mesh.GetPoint(v[(j + 1) % 3]);
      const double middle[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
      if (aim(a) != EXIT_SUCCESS || aim(middle) != EXIT_SUCCESS)
      {
        return EXIT_FAILURE;
      }
    }
    // Through the centroid: the segment to twice as far crosses the face's interior.
    double centroid[3] = { 0, 0, 0 };
    for (int j = 0; j < 3; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        centroid[k] += mesh.GetPoint(v[j])[k] / 3.0;
      }
    }
    if (aim(centroid) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  size_t crossing = 0;
  for (const auto& target : targets)
  {
    answers.push_back(answer(target));
    crossing += answers.back().Crosses ? 1 : 0;
  }
  MEDIAL_CHECK(crossing >= static_cast<size_t>(mesh.GetNumberOfTriangles()),
    "%zu segments cross the surface, fewer than the %lld through triangle centroids", crossing,
    static_cast<long long>(mesh.GetNumberOfTriangles()));
  mesh.ReleaseGeometry();
  for (size_t i = 0; i < targets.size(); ++i)
  {
    const Answer a = answer(targets[i]);
    MEDIAL_CHECK(a.Hit.Triangle == answers[i].Hit.Triangle && a.Hit.Distance == answers[i].Hit.Distance &&
        a.Crosses == answers[i].Crosses,
      "ray %zu after ReleaseGeometry: triangle %lld at %.17g (crosses %d), before %lld at %.17g (crosses %d)", i,
      static_cast<long long>(a.Hit.Triangle), a.Hit.Distance, a.Crosses,
      static_cast<long long>(answers[i].Hit.Triangle), answers[i].Hit.Distance, answers[i].Crosses);
  }
  std::printf("%s: %lld rays through vertices, edge midpoints and centroids, each hits once at its target, the same after "
              "the mesh's arrays are released\n",
    label, rays);
  return EXIT_SUCCESS;
}
}

int TestMedialSurfaceImport(int, char*[])
{
  if (CheckImport("triangle soup", Soup(false)) != EXIT_SUCCESS ||
    CheckImport("soup with a quad and a strip", Soup(true)) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // The octahedron's rays from its centre pass exactly through vertices and edges.
  vtkNew<vtkPlatonicSolidSource> octahedron;
  octahedron->SetSolidTypeToOctahedron();
  octahedron->Update();
  vtkNew<vtkMedialShapeSource> sphere;
  sphere->SetShapeToSphere();
  sphere->SetResolution(3);
  sphere->Update();
  if (CheckWatertightRays("octahedron", octahedron->GetOutput()) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return CheckWatertightRays("sphere", sphere->GetOutput());
}
