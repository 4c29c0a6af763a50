// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialRepairFilter.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialPieces.h"
#include "vtkMedialPipeline.h"
#include "vtkMedialPlane.h"
#include "vtkMedialProgress.h"
#include "vtkMedialRepairPatch.h"
#include "vtkMedialRepairWeld.h"
#include "vtkMedialSolidCheck.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialSurfaceRepair.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <sstream>
#include <unordered_map>

vtkStandardNewMacro(vtkMedialRepairFilter);

namespace
{
using Soup = vtkMedialSurfaceRepair::Soup;
using Pairs = std::vector<std::pair<vtkIdType, vtkIdType>>;

// Rounds of union and self-crossing resolution before the wrap takes what is left.
constexpr int ShellRounds = 4;
// Input deeper than this inside the repaired solid (relative to the diagonal) is buried
// (an overlap joined, a sheet removed), not moved.
constexpr double BuriedDepth = 1e-3;
// A shell resolved from its self-intersections may move its surface by this much
// (relative to the diagonal) where it is not buried: CGAL's local removal smooths (the
// fold of horse.ply, subdivided twice, is smoothed out by moving 1.7e-3 of it; filled
// as a hole in horse.ply itself, 7.6e-4).
constexpr double MovedTolerance = 2e-3;
// Shells with more triangles than this are not autorefined as a whole when their
// crossings are local (few pairs): a minute and gigabytes on a million triangles.
constexpr vtkIdType LargeShell = 200000;
// The local self-intersection removal runs on a patch this many rings wider than its
// region: CGAL widens a region it cannot mend by up to 6 rings, and by its box.
constexpr int PatchMargin = 12;

using vtkMedialSurfaceRepair::ToPolyData;

// The triangles of `mesh` (oriented as it oriented them) for which keep(triangle) is
// true, over their points only.
template <class Keep>
Soup SoupOf(const vtkMedialTriangleMesh& mesh, Keep keep)
{
  Soup soup;
  std::vector<vtkIdType> id(mesh.GetNumberOfPoints(), -1);
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!keep(t))
    {
      continue;
    }
    std::array<vtkIdType, 3> tri;
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType v = mesh.GetTriangle(t)[k];
      if (id[v] < 0)
      {
        id[v] = static_cast<vtkIdType>(soup.Points.size());
        const double* x = mesh.GetPoint(v);
        soup.Points.push_back({ x[0], x[1], x[2] });
      }
      tri[k] = id[v];
    }
    soup.Triangles.push_back(tri);
  }
  return soup;
}

Soup SoupOf(const vtkMedialTriangleMesh& mesh)
{
  return SoupOf(mesh, [](vtkIdType) { return true; });
}

void Append(Soup& to, const Soup& from)
{
  const vtkIdType offset = static_cast<vtkIdType>(to.Points.size());
  to.Points.insert(to.Points.end(), from.Points.begin(), from.Points.end());
  for (const auto& t : from.Triangles)
  {
    to.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
}

// The input's polygons and strips as triangles, on its own points.
Soup Triangulated(vtkPolyData* input)
{
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(input->GetPoints());
  surface->SetPolys(input->GetPolys());
  surface->SetStrips(input->GetStrips());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(surface);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* out = triangles->GetOutput();
  Soup soup;
  soup.Points.resize(out->GetNumberOfPoints());
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    out->GetPoint(i, soup.Points[i].data());
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = out->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      soup.Triangles.push_back({ ids[0], ids[1], ids[2] });
    }
  }
  return soup;
}

// The input's points, and points every `spacing` along its lines: what the wrap of a
// surface-less input wraps.
Soup PointsAndLines(vtkPolyData* input, double spacing)
{
  Soup soup;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> x;
    input->GetPoint(i, x.data());
    soup.Points.push_back(x);
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* lines = input->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      double a[3], b[3];
      input->GetPoint(ids[k], a);
      input->GetPoint(ids[k + 1], b);
      const double length = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      const int steps = static_cast<int>(std::min(1e6, std::ceil(length / spacing)));
      for (int s = 1; s < steps; ++s)
      {
        const double f = static_cast<double>(s) / steps;
        soup.Points.push_back({ a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]) });
      }
    }
  }
  return soup;
}

// The triangles of `soup` within `rings` rings of `seeds` (a ring: the triangles that
// share a point with the ones before).
std::vector<char> Grow(const Soup& soup, const std::vector<vtkIdType>& seeds, int rings)
{
  const size_t np = soup.Points.size(), nt = soup.Triangles.size();
  std::vector<vtkIdType> start(np + 1, 0);
  for (const auto& t : soup.Triangles)
  {
    ++start[t[0] + 1];
    ++start[t[1] + 1];
    ++start[t[2] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<vtkIdType> around(static_cast<size_t>(start.back()));
  std::vector<vtkIdType> next(start.begin(), start.end() - 1);
  for (size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      around[next[soup.Triangles[t][k]]++] = static_cast<vtkIdType>(t);
    }
  }
  std::vector<char> in(nt, 0);
  std::vector<vtkIdType> front;
  for (vtkIdType t : seeds)
  {
    if (t >= 0 && static_cast<size_t>(t) < nt && !in[t])
    {
      in[t] = 1;
      front.push_back(t);
    }
  }
  std::vector<char> seen(np, 0);
  for (int ring = 0; ring < rings && !front.empty(); ++ring)
  {
    std::vector<vtkIdType> grown;
    for (vtkIdType t : front)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = soup.Triangles[t][k];
        if (seen[v])
        {
          continue;
        }
        seen[v] = 1;
        for (vtkIdType i = start[v]; i < start[v + 1]; ++i)
        {
          if (!in[around[i]])
          {
            in[around[i]] = 1;
            grown.push_back(around[i]);
          }
        }
      }
    }
    front.swap(grown);
  }
  return in;
}

// The directed edges of `soup` whose edge no other triangle of it uses: its border.
std::vector<std::pair<vtkIdType, vtkIdType>> Border(const Soup& soup)
{
  std::vector<std::array<vtkIdType, 3>> edges; // lower point, higher point, the triangle's direction
  edges.reserve(3 * soup.Triangles.size());
  for (const auto& t : soup.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = t[k], b = t[(k + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), a < b ? 1 : 0 });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<vtkIdType, vtkIdType>> border;
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1])
    {
      ++j;
    }
    if (j == i + 1)
    {
      const auto& e = edges[i];
      border.emplace_back(e[2] ? e[0] : e[1], e[2] ? e[1] : e[0]);
    }
    i = j;
  }
  return border;
}

// Puts `after` in the place of the triangles of `soup` marked `in` (whose extraction
// was `before`, with `soupPoint`), stitched along the patch's border: `after` must have
// kept that border, the same points (bit for bit) joined by the same directed edges.
// The points no triangle uses any more are dropped. False, with `soup` unchanged, when
// the border moved.
bool Stitch(Soup& soup, const std::vector<char>& in, const std::vector<vtkIdType>& soupPoint, const Soup& before,
  const Soup& after)
{
  using Edges = std::vector<std::pair<vtkIdType, vtkIdType>>;
  Edges border = Border(before);
  std::map<std::array<double, 3>, vtkIdType> onBorder; // coordinates -> id in `soup`
  for (auto& e : border)
  {
    e = { soupPoint[e.first], soupPoint[e.second] };
    onBorder.emplace(soup.Points[e.first], e.first);
    onBorder.emplace(soup.Points[e.second], e.second);
  }
  // `after`'s points: those on the border keep their ids, the others are new.
  std::vector<vtkIdType> id(after.Points.size(), -1);
  vtkIdType next = static_cast<vtkIdType>(soup.Points.size());
  for (size_t i = 0; i < after.Points.size(); ++i)
  {
    const auto at = onBorder.find(after.Points[i]);
    id[i] = at != onBorder.end() ? at->second : next++;
  }
  Edges border2 = Border(after);
  for (auto& e : border2)
  {
    e = { id[e.first], id[e.second] };
  }
  std::sort(border.begin(), border.end());
  std::sort(border2.begin(), border2.end());
  if (border != border2)
  {
    return false;
  }
  Soup stitched;
  std::vector<vtkIdType> newId(static_cast<size_t>(next), -1);
  // The points in order: the soup's first (those still used), then `after`'s new ones.
  std::vector<std::array<double, 3>> all(static_cast<size_t>(next));
  std::copy(soup.Points.begin(), soup.Points.end(), all.begin());
  for (size_t i = 0; i < after.Points.size(); ++i)
  {
    all[id[i]] = after.Points[i];
  }
  std::vector<char> used(all.size(), 0);
  for (size_t t = 0; t < soup.Triangles.size(); ++t)
  {
    if (!in[t])
    {
      used[soup.Triangles[t][0]] = used[soup.Triangles[t][1]] = used[soup.Triangles[t][2]] = 1;
    }
  }
  for (const auto& t : after.Triangles)
  {
    used[id[t[0]]] = used[id[t[1]]] = used[id[t[2]]] = 1;
  }
  for (size_t v = 0; v < all.size(); ++v)
  {
    if (used[v])
    {
      newId[v] = static_cast<vtkIdType>(stitched.Points.size());
      stitched.Points.push_back(all[v]);
    }
  }
  for (size_t t = 0; t < soup.Triangles.size(); ++t)
  {
    if (!in[t])
    {
      const auto& x = soup.Triangles[t];
      stitched.Triangles.push_back({ newId[x[0]], newId[x[1]], newId[x[2]] });
    }
  }
  for (const auto& t : after.Triangles)
  {
    stitched.Triangles.push_back({ newId[id[t[0]]], newId[id[t[1]]], newId[id[t[2]]] });
  }
  soup = std::move(stitched);
  return true;
}

// The soup's pieces (triangles connected through shared edges, by point ids) that have
// no border edge.
vtkIdType ClosedPieces(const Soup& soup)
{
  const size_t nt = soup.Triangles.size();
  std::vector<size_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](size_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  std::vector<std::array<vtkIdType, 3>> edges; // lower point, higher point, triangle
  edges.reserve(3 * nt);
  for (size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = soup.Triangles[t][k], b = soup.Triangles[t][(k + 1) % 3];
      edges.push_back({ std::min(a, b), std::max(a, b), static_cast<vtkIdType>(t) });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<char> open(nt, 0);
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i + 1;
    while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1])
    {
      parent[find(static_cast<size_t>(edges[j][2]))] = find(static_cast<size_t>(edges[i][2]));
      ++j;
    }
    if (j == i + 1)
    {
      open[edges[i][2]] = 1;
    }
    i = j;
  }
  std::vector<char> openPiece(nt, 0);
  for (size_t t = 0; t < nt; ++t)
  {
    openPiece[find(t)] |= open[t];
  }
  vtkIdType closed = 0;
  for (size_t t = 0; t < nt; ++t)
  {
    closed += find(t) == t && !openPiece[t] ? 1 : 0;
  }
  return closed;
}

vtkIdType UsedPoints(const Soup& soup)
{
  std::vector<char> used(soup.Points.size(), 0);
  for (const auto& t : soup.Triangles)
  {
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  return static_cast<vtkIdType>(std::count(used.begin(), used.end(), 1));
}

// Pairs of `mesh`'s triangles that intersect by CGAL's exact predicates, from the
// candidates of the double-precision search.
Pairs ExactPairs(const vtkMedialTriangleMesh& mesh, const Pairs& candidates)
{
  vtkMedialSolidCheck check;
  check.Pairs = candidates;
  check.Decide(mesh, vtkMedialSurfaceRepair::IntersectingPairs);
  return check.Intersecting;
}

// CPU seconds of the process, every thread.
double CpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string Plural(vtkIdType n, const char* one, const char* many)
{
  std::ostringstream os;
  os << n << " " << (n == 1 ? one : many);
  return os.str();
}
}

// The steps of one update (see the class comment), and the state they share.
class vtkMedialRepairFilter::vtkInternals
{
public:
  vtkInternals(vtkMedialRepairFilter* self)
    : Self(self)
    , Threads(vtkMedialThreadCount(self->NumberOfThreads))
  {
  }

  /// Fills `output`; false with GetError() when the input cannot be repaired.
  bool Run(vtkPolyData* input, vtkPolyData* output);
  const std::string& GetError() const { return this->Error; }

private:
  // A mesh, its queries and (once asked) its exact self-intersection pairs, with the
  // soup they were built on. The steps share the last one while the soup does not
  // change (PrepareSoup): a mesh and a tree cost as much as a step on a clean shell.
  struct Prepared
  {
    Soup Source;
    vtkMedialTriangleMesh OwnMesh;
    vtkMedialSurfaceQuery OwnQuery;
    const vtkMedialTriangleMesh* Mesh = &OwnMesh; // or the input's, borrowed
    const vtkMedialSurfaceQuery* Query = &OwnQuery;
    Pairs Candidates;     // from the double-precision search, when it ran
    bool HasCandidates = false;
    Pairs Exact;          // by CGAL's predicates
    bool HasExact = false;
  };
  using PreparedPtr = std::shared_ptr<Prepared>;
  // The preparation of `soup` (the last one when it was built on the same soup), with
  // its exact pairs when `pairs`; null (with the error) when it cannot be built.
  PreparedPtr PrepareSoup(const Soup& soup, bool pairs);
  void FindExactPairs(Prepared& prepared);
  bool NoVolume(const std::string& why);
  bool ShellsValid(const Soup& soup, vtkIdType& touching);
  bool Overlap(const vtkMedialTriangleMesh& mesh, int a, int b);
  double Moved(const Soup& before, const Soup& after);
  // Triangles this small are degenerate to the preparation (vtkMedialTriangleMesh
  // counts those under 1e-14 of the squared diagonal): Clean removes them, with margin.
  double TinyArea() const { return 1e-12 * this->Diagonal * this->Diagonal; }
  bool Shells(Soup& work, bool& wrap);
  bool RemoveInPatch(Soup& shell, const std::vector<vtkIdType>& near, int rings, std::string& error,
    std::vector<char>& in, Soup& before);
  double MovedInPatch(const vtkMedialRepairPatch& patch);
  template <typename Distance, typename Inside>
  double LargestMove(const Soup& before, const std::vector<vtkIdType>& moved, Distance distance, Inside inside);
  void MeasurePatch(const vtkMedialTriangleMesh& input, const vtkMedialRepairPatch& patch);
  void SetMeasured(const vtkMedialTriangleMesh& input, double largest, const std::vector<unsigned char>& buriedTriangle);
  bool RemoveSheets(Soup& work, bool& wrap);
  void Measure(const vtkMedialTriangleMesh& input, vtkPolyData* output, const vtkMedialSurfaceQuery* outputQuery);
  void Line(const std::string& text) { this->Self->Report.push_back(text); }
  // Ends the current stage's timer and starts one for `next`; reports the progress the
  // steps before `next` stand for and polls the caller's abort. False (error "aborted")
  // when aborted: the step is not started.
  bool Stage(const char* next)
  {
    this->EndStage(next);
    if (!next)
    {
      return true;
    }
    // The share of the work done before each step (the union, self-intersection and
    // wrap steps, "shells" and "wrap", take most of a repair's time).
    struct Step
    {
      const char* Name;
      const char* Text;
      double Done;
    };
    static const Step steps[] = { { "check", "Checking the surface", 0.0 }, { "weld", "Welding", 0.1 },
      { "clean", "Cleaning and orienting", 0.15 }, { "holes", "Filling holes", 0.25 },
      { "shells", "Joining and resolving shells", 0.35 }, { "sheets", "Removing inner sheets", 0.7 },
      { "orient", "Checking the result", 0.75 }, { "wrap", "Wrapping", 0.8 },
      { "pinch", "Splitting pinched vertices", 0.9 }, { "measure", "Measuring the change", 0.92 } };
    for (const Step& step : steps)
    {
      if (std::strcmp(step.Name, next) == 0)
      {
        this->Self->SetProgressText(step.Text);
        this->Self->UpdateProgress(step.Done);
      }
    }
    if (this->Self->GetAbortExecute())
    {
      this->Fail("aborted");
      return false;
    }
    return true;
  }
  void EndStage(const char* next)
  {
    const auto now = std::chrono::steady_clock::now();
    const double cpu = CpuSeconds();
    if (!this->StageName.empty())
    {
      this->Self->StageTimes.emplace_back(this->StageName, std::chrono::duration<double>(now - this->StageStart).count());
      this->Self->StageCpuTimes.push_back(cpu - this->StageCpuStart);
    }
    this->StageName = next ? next : "";
    this->StageStart = now;
    this->StageCpuStart = cpu;
  }
  void Fail(const std::string& text) { this->Error = text; }

  vtkMedialRepairFilter* Self;
  int Threads;
  double Diagonal = 0.0;
  bool NoSolid = false; // nothing closed was left: the wrap is a thin solid around a sheet
  bool OpenPieces = true; // the shells step saw an open piece (the sheets step has work)
  bool FilledShut = false; // holes larger than MaximumHoleSize were filled to close a piece
  PreparedPtr Last;       // the last preparation, shared by the steps
  bool WorkIsInput = false; // the shells step starts from the input's own mesh
  // The one shell, resolved by a local removal whose result was checked locally: the
  // final check and the measure are local too (see vtkMedialRepairPatch).
  std::unique_ptr<vtkMedialRepairPatch> Patch;
  std::string Error;
  std::string StageName;
  std::chrono::steady_clock::time_point StageStart;
  double StageCpuStart = 0.0;
};

void vtkMedialRepairFilter::vtkInternals::FindExactPairs(Prepared& prepared)
{
  if (prepared.HasExact)
  {
    return;
  }
  if (!prepared.HasCandidates)
  {
    prepared.Query->FindIntersectingPairs(this->Threads, prepared.Candidates);
    prepared.HasCandidates = true;
  }
  prepared.Exact = ExactPairs(*prepared.Mesh, prepared.Candidates);
  prepared.HasExact = true;
}

vtkMedialRepairFilter::vtkInternals::PreparedPtr vtkMedialRepairFilter::vtkInternals::PrepareSoup(
  const Soup& soup, bool pairs)
{
  if (!this->Last || this->Last->Source.Triangles != soup.Triangles || this->Last->Source.Points != soup.Points)
  {
    auto prepared = std::make_shared<Prepared>();
    prepared->Source = soup;
    vtkSmartPointer<vtkPolyData> surface = ToPolyData(soup);
    std::string error;
    if (!prepared->OwnMesh.Build(surface, error) || !prepared->OwnQuery.Build(&prepared->OwnMesh, error))
    {
      this->Fail(error);
      return nullptr;
    }
    this->Last = prepared;
  }
  if (pairs)
  {
    this->FindExactPairs(*this->Last);
  }
  return this->Last;
}

bool vtkMedialRepairFilter::vtkInternals::NoVolume(const std::string& why)
{
  this->Fail(why + ": it bounds no volume; RepairMode WRAP (--repair wrap) makes a thin solid around it");
  return false;
}

// Whether shells a and b of `mesh` have a volume in common: a triangle of one crosses
// the other (touching, even along a face, does not count).
bool vtkMedialRepairFilter::vtkInternals::Overlap(const vtkMedialTriangleMesh& mesh, int a, int b)
{
  const Soup shellB = SoupOf(mesh, [&](vtkIdType t) { return mesh.ShellOfTriangle[t] == b; });
  vtkSmartPointer<vtkPolyData> surfaceB = ToPolyData(shellB);
  vtkMedialTriangleMesh meshB;
  vtkMedialSurfaceQuery queryB;
  std::string error;
  if (!meshB.Build(surfaceB, error) || !queryB.Build(&meshB, error))
  {
    return true;
  }
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (mesh.ShellOfTriangle[t] != a)
    {
      continue;
    }
    const vtkIdType* v = mesh.GetTriangle(t);
    if (queryB.TriangleCrossesSurface(mesh.GetPoint(v[0]), mesh.GetPoint(v[1]), mesh.GetPoint(v[2])))
    {
      return true;
    }
  }
  return false;
}

// The largest distance from the points `moved` of `before` to a surface (`distance(x,
// bound)`, `bound` when nothing is nearer), over the points not buried in its solid
// (`inside(x)` beyond BuriedDepth): Moved() and MovedInPatch() with their own queries.
template <typename Distance, typename Inside>
double vtkMedialRepairFilter::vtkInternals::LargestMove(
  const Soup& before, const std::vector<vtkIdType>& moved, Distance distance, Inside inside)
{
  const double bound = 2.0 * this->Diagonal, buried = BuriedDepth * this->Diagonal;
  const vtkIdType n = static_cast<vtkIdType>(moved.size());
  double largest = 0.0;
#pragma omp parallel for schedule(static) num_threads(this->Threads) reduction(max : largest)
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double* x = before.Points[moved[i]].data();
    const double d = distance(x, bound);
    if (!(d > buried && inside(x)))
    {
      largest = std::max(largest, d);
    }
  }
  return largest;
}

// The largest distance from a point of `before` to the surface `after`, over the points
// that are not buried in its solid (deeper than BuriedDepth).
double vtkMedialRepairFilter::vtkInternals::Moved(const Soup& before, const Soup& after)
{
  PreparedPtr p = this->PrepareSoup(after, false);
  if (!p)
  {
    this->Error.clear();
    return HUGE_VAL;
  }
  const vtkMedialSurfaceQuery& query = *p->Query;
  // A point of `before` that is still a point of `after` has not moved: only the
  // others are measured (a local step keeps most of the shell's points).
  std::vector<std::array<double, 3>> kept(after.Points);
  std::sort(kept.begin(), kept.end());
  std::vector<vtkIdType> moved;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(before.Points.size()); ++i)
  {
    if (!std::binary_search(kept.begin(), kept.end(), before.Points[i]))
    {
      moved.push_back(i);
    }
  }
  return this->LargestMove(before, moved,
    [&](const double* x, double bound) {
      vtkMedialSurfaceQuery::ClosestHit hit;
      return query.ClosestPoint(x, bound, hit) ? hit.Distance : bound;
    },
    [&](const double* x) { return query.IsInside(x); });
}

// Moved() for a shell whose patch vtkMedialRepairPatch certified: the points of the patch
// that the result dropped are the only ones that moved.
double vtkMedialRepairFilter::vtkInternals::MovedInPatch(const vtkMedialRepairPatch& patch)
{
  const Soup& before = patch.GetBefore();
  std::vector<vtkIdType> moved;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(before.Points.size()); ++i)
  {
    if (!patch.KeptPoint(before.Points[i].data()))
    {
      moved.push_back(i);
    }
  }
  return this->LargestMove(before, moved, [&](const double* x, double bound) { return patch.Distance(x, bound); },
    [&](const double* x) { return patch.IsInside(x); });
}

// A valid solid: every shell closed, manifold (as the preparation sees it),
// consistently oriented, free of exact self-intersections and degenerate triangles,
// and no two shells with a volume in common (touching ones are counted).
bool vtkMedialRepairFilter::vtkInternals::ShellsValid(const Soup& soup, vtkIdType& touching)
{
  touching = 0;
  PreparedPtr p = soup.Triangles.empty() ? nullptr : this->PrepareSoup(soup, true);
  if (!p)
  {
    return false;
  }
  const vtkMedialTriangleMesh& m = *p->Mesh;
  if (m.BoundaryEdges > 0 || m.DegenerateTriangles > 0 || m.DuplicateTriangles > 0 || m.NonOrientableComponents > 0)
  {
    return false;
  }
  std::set<std::pair<int, int>> contacts;
  for (const auto& pair : p->Exact)
  {
    const int a = m.ShellOfTriangle[pair.first], b = m.ShellOfTriangle[pair.second];
    if (a == b)
    {
      return false;
    }
    contacts.insert({ std::min(a, b), std::max(a, b) });
  }
  for (const auto& c : m.Contacts)
  {
    contacts.insert({ c.A, c.B });
  }
  for (const auto& c : contacts)
  {
    if (this->Overlap(m, c.first, c.second) || this->Overlap(m, c.second, c.first))
    {
      return false;
    }
  }
  // A non-manifold edge is accepted only between shells that touch.
  if (m.NonManifoldEdges > 0 && contacts.empty())
  {
    return false;
  }
  touching = static_cast<vtkIdType>(contacts.size());
  return true;
}

// CGAL's local self-intersection removal on the triangles `near` of a closed shell and
// `rings` rings around them, run on a patch cut out of the shell (those triangles and
// PatchMargin rings more, for CGAL's own widening) and stitched back along the patch's
// border, which must not move: CGAL's work then costs as much on a million triangles as
// on a thousand (the halfedge mesh of the whole shell took longer than the removal).
bool vtkMedialRepairFilter::vtkInternals::RemoveInPatch(Soup& shell, const std::vector<vtkIdType>& near, int rings,
  std::string& error, std::vector<char>& in, Soup& before)
{
  in = Grow(shell, near, rings + PatchMargin);
  std::vector<vtkIdType> shellPoint;
  before = vtkMedialRepairPatch::Extract(shell, in, shellPoint);
  // `near` in the patch's numbering (it keeps the shell's triangle order).
  std::vector<vtkIdType> patchTriangle(shell.Triangles.size(), -1);
  vtkIdType next = 0;
  for (size_t t = 0; t < in.size(); ++t)
  {
    patchTriangle[t] = in[t] ? next++ : -1;
  }
  std::vector<vtkIdType> nearPatch;
  for (vtkIdType t : near)
  {
    nearPatch.push_back(patchTriangle[t]);
  }
  Soup after = before;
  if (!vtkMedialSurfaceRepair::RemoveSelfIntersections(after, nearPatch, rings, error))
  {
    return false;
  }
  if (!Stitch(shell, in, shellPoint, before, after))
  {
    error = "CGAL's local self-intersection removal reached the border of its patch";
    return false;
  }
  return true;
}

// Steps 4 and 5: closed shells that overlap are joined, shells that cross themselves
// are resolved, in rounds until neither applies. `wrap` is set when one cannot be done.
bool vtkMedialRepairFilter::vtkInternals::Shells(Soup& work, bool& wrap)
{
  vtkMedialRepairFilter* self = this->Self;
  std::set<std::pair<int, int>> touching; // by round: reset each round
  for (int round = 0; round < ShellRounds; ++round)
  {
    // Held here: the steps below prepare other soups.
    const PreparedPtr p = this->PrepareSoup(work, true);
    if (!p)
    {
      return false;
    }
    const vtkMedialTriangleMesh& m = *p->Mesh;
    const int shells = static_cast<int>(m.Shells.size());
    if (round == 0)
    {
      // The steps here make closed shells only: without an open piece now, the
      // sheets step has nothing to do.
      this->OpenPieces = std::any_of(m.Shells.begin(), m.Shells.end(), [](const auto& s) { return !s.Closed; });
    }
    std::vector<vtkIdType> selfPairs(shells, 0);
    std::set<std::pair<int, int>> contacts;
    for (const auto& pair : p->Exact)
    {
      const int a = m.ShellOfTriangle[pair.first], b = m.ShellOfTriangle[pair.second];
      if (a == b)
      {
        ++selfPairs[a];
      }
      else
      {
        contacts.insert({ std::min(a, b), std::max(a, b) });
      }
    }
    for (const auto& c : m.Contacts)
    {
      contacts.insert({ c.A, c.B });
    }
    if (round == 0)
    {
      self->IntersectingPairs = static_cast<vtkIdType>(p->Exact.size());
    }
    // A closed solid shell (not a cavity) free of self-intersections can be joined.
    auto joinable = [&](int s) { return m.Shells[s].Closed && m.Shells[s].Depth % 2 == 0 && selfPairs[s] == 0; };
    std::vector<Soup> pieces(shells);
    std::vector<char> done(shells, 0);
    for (int s = 0; s < shells; ++s)
    {
      pieces[s] = SoupOf(m, [&](vtkIdType t) { return m.ShellOfTriangle[t] == s; });
    }
    bool changed = false;
    // Step 4: unions, each shell in at most one union per round.
    touching.clear();
    for (const auto& c : contacts)
    {
      if (done[c.first] || done[c.second])
      {
        continue;
      }
      if (!joinable(c.first) || !joinable(c.second))
      {
        if (selfPairs[c.first] == 0 && selfPairs[c.second] == 0)
        {
          wrap = true; // a cavity or an open piece in contact: nothing exact applies
        }
        continue;
      }
      Soup joined;
      std::string error;
      if (vtkMedialSurfaceRepair::Union(pieces[c.first], pieces[c.second], joined, error))
      {
        vtkMedialSurfaceRepair::CleanCounts counts;
        if (vtkMedialSurfaceRepair::Clean(joined, counts, error, this->TinyArea()))
        {
          pieces[c.first] = joined;
          pieces[c.second] = Soup();
          done[c.first] = done[c.second] = 1;
          ++self->JoinedShells; // one shell fewer per union
          changed = true;
          continue;
        }
      }
      // No union: shells that only touch stay separate bodies; overlapping ones go to the wrap.
      if (this->Overlap(m, c.first, c.second) || this->Overlap(m, c.second, c.first))
      {
        wrap = true;
      }
      else
      {
        touching.insert(c);
      }
    }
    // Step 5: shells that cross themselves.
    for (int s = 0; s < shells; ++s)
    {
      if (selfPairs[s] == 0 || done[s])
      {
        continue;
      }
      if (!m.Shells[s].Closed)
      {
        wrap = true;
        continue;
      }
      // Autorefinement first (exact: the solid's own boundary when the shell crosses
      // itself through the solid), then CGAL's local removal (for folds: a patch that
      // turns over on itself has no solid inside it, and the autorefinement may keep the
      // wrong side of it). A result is taken only if it is a valid solid and keeps the
      // input's surface: no input point farther than MovedTolerance from it, except the
      // points buried inside it.
      Soup shell;
      std::string error;
      bool resolved = false;
      auto tidy = [&](Soup& soup) {
        vtkMedialSurfaceRepair::CleanCounts counts;
        vtkIdType unused = 0;
        return vtkMedialSurfaceRepair::Clean(soup, counts, error, this->TinyArea()) && counts.BorderEdges == 0 &&
          this->ShellsValid(soup, unused);
      };
      // The local removal returns a halfedge mesh (manifold, oriented): its soup is
      // cleaned (a pass over the whole shell) only when it is not a valid solid as it is.
      auto tidyLocal = [&](Soup& soup) {
        vtkIdType unused = 0;
        return this->ShellsValid(soup, unused) || tidy(soup);
      };
      // The shell's triangles in the pairs (pieces[s] keeps the mesh's triangle order).
      std::vector<vtkIdType> near;
      {
        std::vector<vtkIdType> local(m.GetNumberOfTriangles(), -1);
        vtkIdType next = 0;
        for (vtkIdType t = 0; t < m.GetNumberOfTriangles(); ++t)
        {
          local[t] = m.ShellOfTriangle[t] == s ? next++ : -1;
        }
        for (const auto& pair : p->Exact)
        {
          if (m.ShellOfTriangle[pair.first] == s && m.ShellOfTriangle[pair.second] == s)
          {
            near.push_back(local[pair.first]);
            near.push_back(local[pair.second]);
          }
        }
      }
      // A few pairs in a large shell are local folds: the local removal first there,
      // on a region grown until it succeeds (a fold of a finely subdivided shell spans
      // many rings). The whole-shell autorefinement costs a minute on a million
      // triangles: a large shell with few pairs goes to the wrap instead.
      const vtkIdType triangles = static_cast<vtkIdType>(pieces[s].Triangles.size());
      const bool local = 100 * selfPairs[s] < triangles;
      const bool whole = !local || triangles <= LargeShell;
      std::vector<int> attempts; // rings of a local attempt, or 0 for the whole shell
      if (!local)
      {
        attempts.push_back(0);
      }
      for (int rings : { 3, 12, 48 })
      {
        attempts.push_back(rings);
      }
      if (local && whole)
      {
        attempts.push_back(0);
      }
      for (size_t attempt = 0; attempt < attempts.size() && !resolved; ++attempt)
      {
        shell = pieces[s];
        if (attempts[attempt] == 0)
        {
          // The rounding of the exact result can leave slivers and a few crossings
          // along the intersection curves: the local removal takes those.
          const std::vector<vtkIdType> everywhere;
          resolved = vtkMedialSurfaceRepair::Autorefine(shell, error) &&
            (tidy(shell) || (vtkMedialSurfaceRepair::RemoveSelfIntersections(shell, everywhere, 0, error) && tidy(shell)));
        }
        else
        {
          std::vector<char> in;
          Soup before;
          resolved = this->RemoveInPatch(shell, near, attempts[attempt], error, in, before);
          // The one shell of the first round: checked and measured locally when
          // vtkMedialRepairPatch can certify it, else as a whole.
          if (resolved && round == 0 && shells == 1)
          {
            auto patch = std::make_unique<vtkMedialRepairPatch>();
            std::string why;
            if (patch->Certify(pieces[s], *p->Query, in, before, shell, why))
            {
              resolved = this->MovedInPatch(*patch) <= MovedTolerance * this->Diagonal;
              if (resolved)
              {
                this->Patch = std::move(patch);
              }
              continue;
            }
          }
          resolved = resolved && tidyLocal(shell);
        }
        resolved = resolved && this->Moved(pieces[s], shell) <= MovedTolerance * this->Diagonal;
      }
      if (resolved)
      {
        pieces[s] = shell;
        done[s] = 1;
        ++self->ResolvedShells;
        changed = true;
      }
      else
      {
        wrap = true;
      }
    }
    if (!changed)
    {
      break;
    }
    work = Soup();
    for (const Soup& piece : pieces)
    {
      Append(work, piece);
    }
    if (this->Patch)
    {
      break; // one valid shell: another round would find nothing to do
    }
  }
  self->TouchingShells = static_cast<vtkIdType>(touching.size());
  return true;
}

// Step 6: open pieces inside the closed shells' solid go; open pieces elsewhere leave
// the wrap to close them. False (with the reason) when nothing closed is left.
bool vtkMedialRepairFilter::vtkInternals::RemoveSheets(Soup& work, bool& wrap)
{
  if (!this->OpenPieces)
  {
    return true;
  }
  const PreparedPtr p = this->PrepareSoup(work, false);
  if (!p)
  {
    return false;
  }
  const vtkMedialTriangleMesh& m = *p->Mesh;
  std::vector<char> closed(m.Shells.size());
  bool anyClosed = false, anyOpen = false;
  for (size_t s = 0; s < m.Shells.size(); ++s)
  {
    closed[s] = m.Shells[s].Closed;
    anyClosed = anyClosed || closed[s];
    anyOpen = anyOpen || !closed[s];
  }
  if (!anyOpen)
  {
    return true;
  }
  if (!anyClosed)
  {
    // Nothing closed: a flat surface bounds no volume whatever is done to it (an error,
    // or with WRAP a thin solid); a curved one is a solid with holes too large to fill,
    // which the wrap closes.
    double centroid[3], values[3], axes[3][3];
    const vtkIdType np = m.GetNumberOfPoints();
    auto point = [&](vtkIdType i, double x[3]) { std::copy_n(m.GetPoint(i), 3, x); };
    vtkMedialPlane::FitPoints(np, point, centroid, values, axes);
    const double normal[3] = { axes[0][2], axes[1][2], axes[2][2] };
    const bool flat = vtkMedialPlane::MaxDistance(np, point, centroid, normal) <= 1e-6 * this->Diagonal;
    if (flat && this->Self->Mode != WRAP)
    {
      std::ostringstream os;
      os << "the surface is flat (" << Plural(static_cast<vtkIdType>(m.Shells.size()), "open piece", "open pieces")
         << " in one plane)";
      return this->NoVolume(os.str());
    }
    // (After the larger holes were filled shut, some piece is closed by its own
    // points: what is left is wrapped with it, not a thin solid.)
    this->NoSolid = !this->FilledShut;
    wrap = true;
    return true;
  }
  // The solid of the closed shells.
  const Soup solidSoup = SoupOf(m, [&](vtkIdType t) { return closed[m.ShellOfTriangle[t]] != 0; });
  const PreparedPtr s = this->PrepareSoup(solidSoup, false);
  if (!s)
  {
    return false;
  }
  const double tolerance = 1e-9 * this->Diagonal;
  std::vector<char> remove(m.Shells.size(), 0);
  std::vector<char> seen(m.GetNumberOfPoints(), 0);
  std::vector<char> outside(m.Shells.size(), 0);
  for (vtkIdType t = 0; t < m.GetNumberOfTriangles(); ++t)
  {
    const int shell = m.ShellOfTriangle[t];
    if (closed[shell] || outside[shell])
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType v = m.GetTriangle(t)[k];
      if (seen[v])
      {
        continue;
      }
      seen[v] = 1;
      vtkMedialSurfaceQuery::ClosestHit hit;
      const bool onSurface = s->Query->ClosestPoint(m.GetPoint(v), tolerance, hit);
      if (!onSurface && !s->Query->IsInside(m.GetPoint(v)))
      {
        outside[shell] = 1;
        break;
      }
    }
  }
  Soup kept;
  vtkIdType removed = 0;
  for (size_t shell = 0; shell < m.Shells.size(); ++shell)
  {
    if (!closed[shell] && !outside[shell])
    {
      remove[shell] = 1;
      ++removed;
    }
    wrap = wrap || (!closed[shell] && outside[shell]);
  }
  if (removed > 0)
  {
    work = SoupOf(m, [&](vtkIdType t) { return !remove[m.ShellOfTriangle[t]]; });
    this->Self->RemovedSheets = removed;
  }
  return true;
}

// The distance from the input (points and triangle centroids) to the output, and the
// share of the input's area buried inside the output's solid.
void vtkMedialRepairFilter::vtkInternals::Measure(
  const vtkMedialTriangleMesh& input, vtkPolyData* output, const vtkMedialSurfaceQuery* outputQuery)
{
  vtkMedialRepairFilter* self = this->Self;
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery built;
  std::string error;
  if (!outputQuery && (!mesh.Build(output, error) || !built.Build(&mesh, error)))
  {
    return;
  }
  const vtkMedialSurfaceQuery& query = outputQuery ? *outputQuery : built;
  const vtkMedialTriangleMesh& out = outputQuery ? *outputQuery->GetMesh() : mesh;
  const double outputDiagonal = out.Diagonal;
  // Input the output kept as it was (its points, its triangles) is at distance 0 and
  // not buried: only the rest is measured (most of the input after a local step).
  using Coordinates = std::array<double, 3>;
  struct Hash
  {
    size_t operator()(const Coordinates& c) const
    {
      const std::hash<double> h;
      return h(c[0]) ^ (h(c[1]) * 0x9e3779b97f4a7c15ull) ^ (h(c[2]) * 0xc2b2ae3d27d4eb4full);
    }
  };
  std::unordered_map<Coordinates, vtkIdType, Hash> outPoints(2 * static_cast<size_t>(out.GetNumberOfPoints()));
  for (vtkIdType i = 0; i < out.GetNumberOfPoints(); ++i)
  {
    const double* x = out.GetPoint(i);
    outPoints.emplace(Coordinates{ x[0], x[1], x[2] }, i);
  }
  auto outPoint = [&](const double* x) -> vtkIdType {
    const auto at = outPoints.find(Coordinates{ x[0], x[1], x[2] });
    return at != outPoints.end() ? at->second : -1;
  };
  auto sorted = [](vtkIdType a, vtkIdType b, vtkIdType c) {
    std::array<vtkIdType, 3> t{ a, b, c };
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<std::array<vtkIdType, 3>> outTriangles(out.GetNumberOfTriangles());
  for (vtkIdType t = 0; t < out.GetNumberOfTriangles(); ++t)
  {
    const vtkIdType* v = out.GetTriangle(t);
    outTriangles[t] = sorted(v[0], v[1], v[2]);
  }
  std::sort(outTriangles.begin(), outTriangles.end());
  const vtkIdType nt = input.GetNumberOfTriangles();
  std::vector<vtkIdType> used;
  {
    std::vector<char> seen(input.GetNumberOfPoints(), 0);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType v = input.GetTriangle(t)[k];
        if (!seen[v])
        {
          seen[v] = 1;
          used.push_back(v);
        }
      }
    }
  }
  const vtkIdType np = static_cast<vtkIdType>(used.size());
  const double bound = 2.0 * std::max(this->Diagonal, outputDiagonal);
  const double buried = BuriedDepth * this->Diagonal;
  const bool wrapped = self->Wrapped;
  // Samples: the triangles' centroids (weighted by area for the buried share), then
  // the points.
  // The areas are summed afterwards in triangle order, so that the share is the same bits
  // on any number of threads (a parallel + reduction is not); the maximum is exact anyway.
  double largest = 0.0;
  std::vector<unsigned char> buriedTriangle(nt, 0);
#pragma omp parallel for schedule(static) num_threads(this->Threads) reduction(max : largest)
  for (vtkIdType i = 0; i < nt + np; ++i)
  {
    double x[3];
    bool kept = false;
    if (i < nt)
    {
      const vtkIdType* v = input.GetTriangle(i);
      for (int k = 0; k < 3; ++k)
      {
        x[k] = (input.GetPoint(v[0])[k] + input.GetPoint(v[1])[k] + input.GetPoint(v[2])[k]) / 3.0;
      }
      const vtkIdType a = outPoint(input.GetPoint(v[0])), b = outPoint(input.GetPoint(v[1])),
                      c = outPoint(input.GetPoint(v[2]));
      kept = a >= 0 && b >= 0 && c >= 0 && std::binary_search(outTriangles.begin(), outTriangles.end(), sorted(a, b, c));
    }
    else
    {
      std::copy_n(input.GetPoint(used[i - nt]), 3, x);
      kept = outPoint(x) >= 0;
    }
    if (kept)
    {
      continue;
    }
    vtkMedialSurfaceQuery::ClosestHit hit;
    const double distance = query.ClosestPoint(x, bound, hit) ? hit.Distance : bound;
    const bool inside = !wrapped && distance > buried && query.IsInside(x);
    if (!inside)
    {
      largest = std::max(largest, distance);
    }
    else if (i < nt)
    {
      buriedTriangle[i] = 1;
    }
  }
  this->SetMeasured(input, largest, buriedTriangle);
}

// The report's figures from a measure: the largest distance relative to the diagonal,
// and the buried share of the input's area, summed in triangle order (the same bits on
// any thread count).
void vtkMedialRepairFilter::vtkInternals::SetMeasured(
  const vtkMedialTriangleMesh& input, double largest, const std::vector<unsigned char>& buriedTriangle)
{
  double buriedArea = 0.0, area = 0.0;
  for (vtkIdType t = 0; t < input.GetNumberOfTriangles(); ++t)
  {
    area += input.Areas[t];
    if (buriedTriangle[t])
    {
      buriedArea += input.Areas[t];
    }
  }
  this->Self->MaximumDistance = largest / this->Diagonal;
  this->Self->BuriedArea = area > 0.0 ? buriedArea / area : 0.0;
}

// Measure() when the output is the input with one patch replaced (vtkMedialRepairPatch):
// the input outside the patch is kept, at distance 0 and not buried, so only the
// patch's triangles and points are measured.
void vtkMedialRepairFilter::vtkInternals::MeasurePatch(const vtkMedialTriangleMesh& input, const vtkMedialRepairPatch& patch)
{
  const vtkIdType nt = input.GetNumberOfTriangles();
  std::vector<vtkIdType> samples; // triangles of the patch, then -1 - i for point i of the patch
  for (vtkIdType t = 0; t < nt; ++t)
  {
    if (patch.InPatch(t))
    {
      samples.push_back(t);
    }
  }
  const Soup& before = patch.GetBefore();
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(before.Points.size()); ++i)
  {
    samples.push_back(-1 - i);
  }
  const double bound = 2.0 * this->Diagonal, buried = BuriedDepth * this->Diagonal;
  const vtkIdType n = static_cast<vtkIdType>(samples.size());
  double largest = 0.0;
  std::vector<unsigned char> buriedTriangle(nt, 0);
#pragma omp parallel for schedule(static) num_threads(this->Threads) reduction(max : largest)
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType sample = samples[i];
    double x[3];
    bool kept = false;
    if (sample >= 0)
    {
      const vtkIdType* v = input.GetTriangle(sample);
      for (int k = 0; k < 3; ++k)
      {
        x[k] = (input.GetPoint(v[0])[k] + input.GetPoint(v[1])[k] + input.GetPoint(v[2])[k]) / 3.0;
      }
      kept = patch.KeptTriangle(input.GetPoint(v[0]), input.GetPoint(v[1]), input.GetPoint(v[2]));
    }
    else
    {
      std::copy_n(before.Points[-1 - sample].data(), 3, x);
      kept = patch.KeptPoint(x);
    }
    if (kept)
    {
      continue;
    }
    const double distance = patch.Distance(x, bound);
    if (!(distance > buried && patch.IsInside(x)))
    {
      largest = std::max(largest, distance);
    }
    else if (sample >= 0)
    {
      buriedTriangle[sample] = 1;
    }
  }
  this->SetMeasured(input, largest, buriedTriangle);
}

bool vtkMedialRepairFilter::vtkInternals::Run(vtkPolyData* input, vtkPolyData* output)
{
  vtkMedialRepairFilter* self = this->Self;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    this->Fail("the input has no points");
    return false;
  }
  this->Diagonal = input->GetLength();
  const bool wrapNow = self->Mode == WRAP;
  const double alpha = self->WrapAlpha * this->Diagonal, offset = self->WrapOffset * this->Diagonal;
  Soup wrapped;
  auto wrapSoup = [&](const Soup& soup) {
    std::string error;
    if (!vtkMedialSurfaceRepair::Wrap(soup, alpha, offset, wrapped, error))
    {
      this->Fail("the alpha wrap failed: " + error);
      return false;
    }
    self->Wrapped = true;
    return true;
  };

  // No polygons: nothing but the wrap can make a solid.
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    const std::string why = "the input has no polygons or triangle strips (only lines or points)";
    if (!wrapNow)
    {
      return this->NoVolume(why);
    }
    if (!wrapSoup(PointsAndLines(input, 0.25 * alpha)))
    {
      return false;
    }
    this->Line("wrap: " + why + ", so it bounds no volume: the alpha wrap is a thin solid around it (" +
      Plural(static_cast<vtkIdType>(wrapped.Triangles.size()), "triangle", "triangles") + ")");
    output->ShallowCopy(ToPolyData(wrapped));
    self->Changed = true;
    return true;
  }

  // 0. The check, as every filter's preparation makes it.
  if (!this->Stage("check"))
  {
    return false;
  }
  // The input's mesh, tree and check: the caller's when it made them on this input
  // (SetCheckedInput: a filter's preparation), else built here.
  const PreparedPtr original = std::make_shared<Prepared>();
  vtkMedialSolidCheck ownCheck;
  const vtkMedialSolidCheck* checked = &ownCheck;
  std::string error;
  if (self->CheckedMesh && self->CheckedQuery && self->CheckedResult && !wrapNow)
  {
    original->Mesh = self->CheckedMesh;
    original->Query = self->CheckedQuery;
    checked = self->CheckedResult;
  }
  else
  {
    if (!original->OwnMesh.Build(input, error, [self]() { return self->GetAbortExecute() != 0; }))
    {
      if (error.find("no non-degenerate") == std::string::npos)
      {
        this->Fail(error);
        return false;
      }
      return this->NoVolume(error);
    }
    if (!original->OwnQuery.Build(&original->OwnMesh, error))
    {
      this->Fail(error);
      return false;
    }
    if (!wrapNow)
    {
      ownCheck.Run(original->OwnMesh, original->OwnQuery, this->Threads);
    }
  }
  const vtkMedialSolidCheck& check = *checked;
  const vtkMedialTriangleMesh& m0 = *original->Mesh;
  // Asked by a filter's preparation, which orients every shell as it prepares and
  // merges a split pinch's copies back into one point: a surface that differs from the
  // prepared input only there is, to it, the input, which it has already prepared.
  const bool forPreparation = checked == self->CheckedResult;
  if (!wrapNow && (check.IsValid() || check.OnlyPairs()))
  {
    original->Candidates = check.Pairs; // the pair search ran
    original->HasCandidates = true;
  }
  // The input's winding against the outward one the preparation found (the filters
  // need not care, they orient as they prepare; this filter's output must be oriented):
  // triangles against the rest of their shell, and shells wound inward as a whole.
  vtkIdType rewound = 0, turned = 0;
  for (const auto& shell : m0.Shells)
  {
    rewound += std::min(shell.Rewound, shell.Triangles - shell.Rewound);
    turned += 2 * shell.Rewound > shell.Triangles ? 1 : 0;
  }
  if (!wrapNow)
  {
    bool valid = check.IsValid();
    if (check.OnlyPairs())
    {
      this->FindExactPairs(*original);
      self->IntersectingPairs = static_cast<vtkIdType>(original->Exact.size());
      valid = original->Exact.empty();
    }
    // A pinched vertex is no defect to the preparation (the same solid, the same
    // balls), but this filter's output is to be manifold at its vertices too.
    const bool pinched = check.PinchedVertices > 0;
    if (valid && rewound == 0 && turned == 0 && !pinched)
    {
      self->InputWasValid = true;
      output->ShallowCopy(input);
      this->Stage(nullptr);
      return true;
    }
    if (valid && forPreparation)
    {
      output->ShallowCopy(input); // Changed stays false: the preparation keeps its mesh
      this->Stage(nullptr);
      return true;
    }
    if (self->Mode == NONE)
    {
      std::vector<std::string> problems = valid ? std::vector<std::string>() : check.Problems();
      if (pinched)
      {
        problems.push_back(check.PinchedClause());
      }
      if (rewound > 0)
      {
        problems.push_back(Plural(rewound, "triangle", "triangles") + " wound against the rest of their shell");
      }
      if (turned > 0)
      {
        problems.push_back(Plural(turned, "shell", "shells") + " wound inward as a whole");
      }
      for (const std::string& problem : problems)
      {
        this->Line("check: " + problem + " (not repaired: Mode NONE)");
      }
      output->ShallowCopy(input);
      return true;
    }
  }
  Soup triangulated = Triangulated(input);
  if (wrapNow)
  {
    if (!this->Stage("wrap"))
    {
      return false;
    }
    if (!wrapSoup(triangulated))
    {
      return false;
    }
    std::ostringstream os;
    os << "wrap: the alpha wrap of the input (alpha " << self->WrapAlpha << ", offset " << self->WrapOffset
       << " of the diagonal), as asked: " << Plural(static_cast<vtkIdType>(wrapped.Triangles.size()), "triangle", "triangles");
    this->Line(os.str());
    vtkSmartPointer<vtkPolyData> out = ToPolyData(wrapped);
    output->ShallowCopy(out);
    self->Changed = true;
    if (!this->Stage("measure"))
    {
      return false;
    }
    this->Measure(m0, output, nullptr);
    this->Stage(nullptr);
    return true;
  }

  // 1. Weld (an open surface only: a closed one has nothing to weld), from the prepared
  // mesh, whose equal points are already one point: points within the tolerance are
  // merged transitively, by union-find over the pairs a locator finds, so the clusters
  // depend on the coordinates alone, not on threads or order (vtkMedialRepairWeld.h).
  if (!this->Stage("weld"))
  {
    return false;
  }
  Soup work = SoupOf(m0);
  const vtkIdType inputTriangles = static_cast<vtkIdType>(triangulated.Triangles.size());
  bool welded = false;
  if (m0.BoundaryEdges > 0 && self->WeldTolerance > 0.0)
  {
    // In place: with nothing merged the welded soup is the same soup (its points are
    // already in order of first use, and the mesh has no collapsed triangles).
    vtkMedialRepairWeld::Counts counts;
    vtkMedialRepairWeld::Weld(work, self->WeldTolerance * this->Diagonal, counts);
    self->WeldedPoints = counts.MergedPoints;
    welded = self->WeldedPoints > 0;
    if (welded)
    {
      std::ostringstream os;
      os << "weld: " << Plural(self->WeldedPoints, "point", "points") << " merged within " << self->WeldTolerance
         << " of the diagonal";
      // A weld of coincident corners (a soup, jitter far below the tolerance) collapses
      // no triangle; one that collapses many merges real neighbours: the tolerance
      // reaches the mesh's short edges, and its transitive clusters grow over regions.
      if (counts.DroppedTriangles > 0.01 * static_cast<double>(inputTriangles))
      {
        os << "; warning: it collapsed " << Plural(counts.DroppedTriangles, "triangle", "triangles") << " ("
           << 100.0 * static_cast<double>(counts.DroppedTriangles) / static_cast<double>(inputTriangles)
           << "% of the input's): the tolerance reaches the mesh's short edges, lower it (WeldTolerance, --weld-tolerance)";
      }
      this->Line(os.str());
    }
  }
  self->DroppedTriangles += inputTriangles - static_cast<vtkIdType>(work.Triangles.size());
  // The preparation's winding is the input's only where it did not have to weld or
  // clean; there the soup's orientation is found again (step 2, and at the end).
  self->RewoundTriangles = welded ? 0 : rewound;
  self->TurnedShells = welded ? 0 : turned;

  // 2. Clean, orient, stitch.
  const bool clean = welded || m0.NonManifoldEdges > 0 || m0.NonOrientableComponents > 0 ||
    m0.DegenerateTriangles > 0 || m0.DuplicateTriangles > 0 || m0.BoundaryEdges > 0;
  vtkIdType borderEdges = m0.BoundaryEdges;
  if (!this->Stage("clean"))
  {
    return false;
  }
  if (clean)
  {
    vtkMedialSurfaceRepair::CleanCounts counts;
    if (!vtkMedialSurfaceRepair::Clean(work, counts, error, this->TinyArea()))
    {
      this->Fail(error);
      return false;
    }
    self->DroppedTriangles += counts.DroppedTriangles + counts.DegenerateFaces;
    self->SplitPoints = counts.SplitPoints;
    self->StitchedEdges = counts.StitchedEdges;
    borderEdges = counts.BorderEdges;
  }
  if (self->DroppedTriangles > 0)
  {
    this->Line("drop: " + Plural(self->DroppedTriangles, "degenerate or duplicate triangle", "degenerate or duplicate triangles") + " removed");
  }
  if (self->SplitPoints > 0)
  {
    this->Line("orient: " + Plural(self->SplitPoints, "point", "points") + " split where more than two triangles met or windings disagreed");
  }
  if (self->StitchedEdges > 0)
  {
    this->Line("stitch: " + Plural(self->StitchedEdges, "pair", "pairs") + " of border edges stitched");
  }
  if (self->RewoundTriangles > 0)
  {
    this->Line("orient: " + Plural(self->RewoundTriangles, "triangle", "triangles") + " turned over to agree with the rest of their shell");
  }
  if (self->TurnedShells > 0)
  {
    this->Line("orient: " + Plural(self->TurnedShells, "shell", "shells") + " wound inward turned over to face out of the solid");
  }

  // 3. Holes.
  if (!this->Stage("holes"))
  {
    return false;
  }
  if (borderEdges > 0)
  {
    std::vector<vtkMedialSurfaceRepair::Hole> holes;
    if (!vtkMedialSurfaceRepair::FillHoles(work, self->MaximumHoleSize * this->Diagonal, holes, error))
    {
      this->Fail(error);
      return false;
    }
    vtkIdType faired = 0;
    double largest = 0.0, largestLeft = 0.0;
    for (const auto& hole : holes)
    {
      self->FilledHoles += hole.Filled ? 1 : 0;
      faired += hole.Filled && hole.Faired ? 1 : 0;
      // A sheet's rim (its hole would be as large as the piece) is no hole.
      const bool rim = !(hole.Area < 0.5 * hole.PieceArea);
      self->UnfilledHoles += !hole.Filled && !rim ? 1 : 0;
      largest = hole.Filled ? std::max(largest, hole.Size) : largest;
      largestLeft = !hole.Filled && !rim ? std::max(largestLeft, hole.Size) : largestLeft;
    }
    if (self->FilledHoles > 0)
    {
      std::ostringstream os;
      os << "holes: " << Plural(self->FilledHoles, "hole", "holes") << " filled (" << faired
         << " faired), the largest " << largest / this->Diagonal << " of the diagonal";
      this->Line(os.str());
    }
    // Holes too large to fill and nothing closed: the wrap would make a thin solid around
    // the surface, not the solid it means. The larger holes are filled too when that
    // closes a piece (a sheet's rim is still no hole, so a sheet stays open).
    if (self->UnfilledHoles > 0 && self->Mode == AUTO)
    {
      const PreparedPtr p = this->PrepareSoup(work, false);
      if (!p)
      {
        return false;
      }
      const auto& shells = p->Mesh->Shells;
      if (std::none_of(shells.begin(), shells.end(), [](const auto& shell) { return shell.Closed; }))
      {
        Soup filled = work;
        std::vector<vtkMedialSurfaceRepair::Hole> large;
        // Kept when some piece is closed now: the later steps then treat the rest
        // (stray sheets inside the solid removed; open pieces outside wrapped with it).
        const vtkIdType closed =
          vtkMedialSurfaceRepair::FillHoles(filled, HUGE_VAL, large, error) ? ClosedPieces(filled) : 0;
        if (closed > 0)
        {
          vtkIdType filledLarge = 0;
          for (const auto& hole : large)
          {
            filledLarge += hole.Filled ? 1 : 0;
          }
          std::ostringstream os;
          os << "holes: " << Plural(filledLarge, "hole", "holes") << " larger than MaximumHoleSize "
             << self->MaximumHoleSize << " of the diagonal filled too (the largest " << largestLeft / this->Diagonal
             << "): nothing closed was left, and filled they close "
             << Plural(closed, "piece", "pieces");
          this->Line(os.str());
          self->FilledHoles += filledLarge;
          this->FilledShut = true;
          self->UnfilledHoles = 0;
          work = std::move(filled);
        }
        error.clear();
      }
    }
    if (self->UnfilledHoles > 0)
    {
      std::ostringstream os;
      os << "holes: " << Plural(self->UnfilledHoles, "hole", "holes") << " larger than MaximumHoleSize "
         << self->MaximumHoleSize << " of the diagonal (the largest " << largestLeft / this->Diagonal
         << "): left to the wrap";
      this->Line(os.str());
    }
  }

  // 4, 5. Unions and self-crossing shells, 6. stray sheets.
  if (!clean && borderEdges == 0)
  {
    // Nothing was welded, cleaned or filled: the soup is the input's mesh, whose
    // preparation (and pairs) the next steps reuse. What they read of it (shells,
    // contacts, pairs) is what a preparation of the soup would find.
    original->Source = work;
    this->Last = original;
    this->WorkIsInput = true;
  }
  bool wrap = false;
  if (!this->Stage("shells"))
  {
    return false;
  }
  if (!this->Shells(work, wrap))
  {
    return false;
  }
  if (!this->Stage("sheets"))
  {
    return false;
  }
  if (!this->RemoveSheets(work, wrap))
  {
    return false;
  }
  if (self->JoinedShells > 0)
  {
    this->Line("union: " + Plural(self->JoinedShells, "union", "unions") + " of overlapping shells (exact corefinement): " +
      Plural(self->JoinedShells, "shell", "shells") + " fewer");
  }
  if (self->ResolvedShells > 0)
  {
    this->Line("self-intersections: " + Plural(self->ResolvedShells, "shell", "shells") + " crossing itself made to bound its solid (" +
      Plural(self->IntersectingPairs, "intersecting triangle pair", "intersecting triangle pairs") + " in the input)");
  }
  if (self->TouchingShells > 0)
  {
    this->Line("touch: " + Plural(self->TouchingShells, "pair", "pairs") + " of shells touch without a volume in common: kept as separate bodies");
  }
  if (self->RemovedSheets > 0)
  {
    this->Line("sheets: " + Plural(self->RemovedSheets, "open piece", "open pieces") + " inside the solid removed");
  }

  // The final check, and the orientation to bound a volume.
  if (!this->Stage("orient"))
  {
    return false;
  }
  PreparedPtr result;
  if (!wrap && !this->Patch)
  {
    vtkIdType touching = 0;
    wrap = !this->ShellsValid(work, touching);
    if (wrap && this->Error.empty())
    {
      this->Line("check: the repaired surface is still not a valid solid");
    }
    this->Error.clear();
    if (!wrap)
    {
      // The steps' own orientation (CGAL's soup orientation picks one per piece) is
      // settled here, not a change to the input, not reported: the preparation
      // orients every shell to bound a volume (cavities inward, as CGAL's
      // orient_to_bound_a_volume), so its triangles are the output.
      result = this->Last;
      const auto& shells = result->Mesh->Shells;
      if (std::any_of(shells.begin(), shells.end(), [](const auto& s) { return s.Rewound > 0; }))
      {
        work = SoupOf(*result->Mesh);
        result->Source = work;
      }
    }
  }
  // Nothing changed but what the preparation does anyway (touching shells kept apart,
  // a pinch it would merge back): the preparation keeps the mesh it has.
  // (the triangle count first: a soup of the whole mesh is not built where a step
  // changed it, as on a large surface whose crossings were removed)
  if (!wrap && forPreparation && static_cast<vtkIdType>(work.Triangles.size()) == m0.GetNumberOfTriangles())
  {
    const Soup prepared = SoupOf(m0);
    if (work.Points == prepared.Points && work.Triangles == prepared.Triangles)
    {
      output->ShallowCopy(input);
      this->Stage(nullptr);
      return true;
    }
  }
  // 7. The wrap.
  if (!this->Stage("wrap"))
  {
    return false;
  }
  if (wrap)
  {
    if (!wrapSoup(work.Triangles.empty() ? triangulated : work))
    {
      return false;
    }
    std::ostringstream os;
    // Why nothing closed was left: holes too large to fill, or open pieces (sheets,
    // polygons in several planes) that had no hole to fill.
    os << "wrap: "
       << (!this->NoSolid ? "what the exact steps could not make a solid is wrapped"
             : self->UnfilledHoles > 0
             ? "nothing closed was left (holes too large to fill): the wrap is a thin solid around the surface"
             : "nothing closed was left (open pieces that bound no volume): the wrap is a thin solid around the surface")
       << " (alpha " << self->WrapAlpha << ", offset " << self->WrapOffset << " of the diagonal): "
       << Plural(static_cast<vtkIdType>(wrapped.Triangles.size()), "triangle", "triangles");
    this->Line(os.str());
    work = wrapped;
  }
  // 8. Pinches: a point where the solid touches itself (its triangles form two or more
  // fans) gets a copy per fan, at the same place, so that the output is manifold at
  // its vertices too (a printer's slicer asks for that). The wrap's output has none,
  // and the Euler characteristic rules them out for free on most surfaces.
  if (!this->Stage("pinch"))
  {
    return false;
  }
  if (!wrap)
  {
    const vtkMedialTriangleMesh& last = result ? *result->Mesh : m0;
    if (last.PinchedVertexBound() > 0)
    {
      const vtkIdType split = vtkMedialSurfaceRepair::SplitPinchedPoints(work);
      if (split > 0)
      {
        self->SplitPoints += split;
        this->Line("pinch: " + Plural(split, "point", "points") +
          " added where the surface touches itself at a vertex (a copy per extra fan of triangles, at the same place)");
      }
    }
  }
  vtkSmartPointer<vtkPolyData> out = ToPolyData(work);
  output->ShallowCopy(out);
  self->Changed = true;
  if (!this->Stage("measure"))
  {
    return false;
  }
  if (!wrap && this->Patch && this->WorkIsInput)
  {
    this->MeasurePatch(m0, *this->Patch);
  }
  else
  {
    this->Measure(m0, output, wrap || !result ? nullptr : result->Query);
  }
  this->Stage(nullptr);
  return true;
}

//------------------------------------------------------------------------------
vtkMedialRepairFilter::vtkMedialRepairFilter() = default;

std::vector<char> vtkMedialRepairFilter::ExactPairTest(
  const std::vector<std::array<double, 18>>& corners, const std::vector<std::array<vtkIdType, 6>>& ids)
{
  return vtkMedialSurfaceRepair::IntersectingPairs(corners, ids);
}

const char* vtkMedialRepairFilter::GetModeName(int mode)
{
  switch (mode)
  {
    case AUTO:
      return "auto";
    case NONE:
      return "none";
    case WRAP:
      return "wrap";
    default:
      return "unknown";
  }
}

int vtkMedialRepairFilter::GetModeFromName(const char* name)
{
  for (int mode = AUTO; mode <= WRAP; ++mode)
  {
    if (name && std::string(name) == GetModeName(mode))
    {
      return mode;
    }
  }
  return -1;
}

const char* vtkMedialRepairFilter::GetTimedStageName(int i)
{
  return i >= 0 && i < static_cast<int>(this->StageTimes.size()) ? this->StageTimes[i].first.c_str() : nullptr;
}

double vtkMedialRepairFilter::GetTimedStageSeconds(int i)
{
  return i >= 0 && i < static_cast<int>(this->StageTimes.size()) ? this->StageTimes[i].second : 0.0;
}

double vtkMedialRepairFilter::GetTimedStageCpuSeconds(int i)
{
  return i >= 0 && i < static_cast<int>(this->StageCpuTimes.size()) ? this->StageCpuTimes[i] : 0.0;
}

const char* vtkMedialRepairFilter::GetReportLine(int i)
{
  return i >= 0 && i < static_cast<int>(this->Report.size()) ? this->Report[i].c_str() : nullptr;
}

int vtkMedialRepairFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkMedialRequestWholeInput(inputVector);
  return 1;
}

int vtkMedialRepairFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  const auto start = std::chrono::steady_clock::now();
  this->InputWasValid = this->Changed = this->Wrapped = false;
  this->IntersectingPairs = this->WeldedPoints = this->DroppedTriangles = this->SplitPoints = 0;
  this->StitchedEdges = this->RewoundTriangles = this->TurnedShells = this->FilledHoles = 0;
  this->UnfilledHoles = this->ResolvedShells = this->JoinedShells = this->TouchingShells = 0;
  this->RemovedSheets = 0;
  this->MaximumDistance = this->BuriedArea = this->Seconds = 0.0;
  this->Report.clear();
  this->StageTimes.clear();
  this->StageCpuTimes.clear();
  if (!vtkMedialPieces::FromRequest(outputVector->GetInformationObject(0)).IsFirst())
  {
    return 1; // piece 0 repairs the whole surface; the other pieces stay empty
  }
  vtkInternals internals(this);
  const bool done = internals.Run(input, output);
  if (!done && this->GetAbortExecute())
  {
    output->Initialize(); // aborted: an empty output, as VTK's filters leave it
    return 1;
  }
  if (!done)
  {
    vtkErrorMacro(<< "Cannot repair the surface: " << internals.GetError() << ".");
    return 0;
  }
  this->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->UpdateProgress(1.0);

  // The report as field data.
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkStringArray> lines;
  lines->SetName(vtkMedialArrayNames::RepairReport);
  for (const std::string& line : this->Report)
  {
    lines->InsertNextValue(line);
  }
  fd->AddArray(lines);
  auto addCount = [fd](const char* name, vtkIdType value) {
    vtkNew<vtkIdTypeArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  auto addValue = [fd](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fd->AddArray(a);
  };
  addCount(vtkMedialArrayNames::RepairInputValid, this->InputWasValid ? 1 : 0);
  addCount(vtkMedialArrayNames::RepairIntersectingPairs, this->IntersectingPairs);
  addCount(vtkMedialArrayNames::RepairWeldedPoints, this->WeldedPoints);
  addCount(vtkMedialArrayNames::RepairDroppedTriangles, this->DroppedTriangles);
  addCount(vtkMedialArrayNames::RepairSplitPoints, this->SplitPoints);
  addCount(vtkMedialArrayNames::RepairStitchedEdges, this->StitchedEdges);
  addCount(vtkMedialArrayNames::RepairRewoundTriangles, this->RewoundTriangles);
  addCount(vtkMedialArrayNames::RepairTurnedShells, this->TurnedShells);
  addCount(vtkMedialArrayNames::RepairFilledHoles, this->FilledHoles);
  addCount(vtkMedialArrayNames::RepairUnfilledHoles, this->UnfilledHoles);
  addCount(vtkMedialArrayNames::RepairResolvedShells, this->ResolvedShells);
  addCount(vtkMedialArrayNames::RepairJoinedShells, this->JoinedShells);
  addCount(vtkMedialArrayNames::RepairTouchingShells, this->TouchingShells);
  addCount(vtkMedialArrayNames::RepairRemovedSheets, this->RemovedSheets);
  addCount(vtkMedialArrayNames::RepairWrapped, this->Wrapped ? 1 : 0);
  addValue(vtkMedialArrayNames::RepairMaximumDistance, this->MaximumDistance);
  addValue(vtkMedialArrayNames::RepairBuriedArea, this->BuriedArea);
  if (this->ReportSteps)
  {
    for (const std::string& line : this->Report)
    {
      vtkWarningMacro(<< "Repair: " << line << ".");
    }
  }
  return 1;
}

void vtkMedialRepairFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << GetModeName(this->Mode) << "\n";
  os << indent << "WeldTolerance: " << this->WeldTolerance << "\n";
  os << indent << "MaximumHoleSize: " << this->MaximumHoleSize << "\n";
  os << indent << "WrapAlpha: " << this->WrapAlpha << "\n";
  os << indent << "WrapOffset: " << this->WrapOffset << "\n";
  os << indent << "ReportSteps: " << this->ReportSteps << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "InputWasValid: " << this->InputWasValid << "\n";
  os << indent << "Changed: " << this->Changed << "\n";
  os << indent << "Wrapped: " << this->Wrapped << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
}
