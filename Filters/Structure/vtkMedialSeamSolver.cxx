// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialSeamSolver.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialGroupByKey.h"
#include "vtkMedialNearestPoints.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialThreads.h"
#include "vtkMedialTriangleMesh.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

namespace
{
namespace G = vtkMedialGeometry;
using BallVector = vtkMedialSeamSolver::BallVector;

// Pivots below this (rows normalised, coordinates scaled to the diagonal) are rank loss.
constexpr double PivotFloor = 1e-11;
// A dependent row whose right-hand side is further from zero than this is inconsistent.
constexpr double InconsistentRow = 1e-9;

struct Row
{
  double A[4];
  double B; // A.X = B
};

// Q(X) = x^T H x - r^2 + G.X + C, X = (x, r).
struct Quadric
{
  double H[3][3];
  double G[4];
  double C;
  int Kind;           // POINT or LINE
  double Direction[3]; // LINE: the direction the quadric was built with
};

double Evaluate(const Quadric& q, const double X[4])
{
  double v = -X[3] * X[3] + q.C;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      v += X[i] * q.H[i][j] * X[j];
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    v += q.G[i] * X[i];
  }
  return v;
}

void Gradient(const Quadric& q, const double X[4], double g[4])
{
  for (int i = 0; i < 3; ++i)
  {
    g[i] = q.G[i];
    for (int j = 0; j < 3; ++j)
    {
      g[i] += 2.0 * q.H[i][j] * X[j];
    }
  }
  g[3] = q.G[3] - 2.0 * X[3];
}

// |x - p|^2 - ((x - p).u)^2 - r^2 (u = 0: the point p).
Quadric MakeQuadric(int kind, const double p[3], const double u[3])
{
  Quadric q;
  q.Kind = kind;
  const double pu = G::Dot(p, u);
  for (int i = 0; i < 3; ++i)
  {
    q.Direction[i] = u[i];
    for (int j = 0; j < 3; ++j)
    {
      q.H[i][j] = (i == j ? 1.0 : 0.0) - u[i] * u[j];
    }
    q.G[i] = -2.0 * (p[i] - pu * u[i]);
  }
  q.G[3] = 0.0;
  q.C = G::Dot(p, p) - pu * pu;
  return q;
}

// The affine solution set X0 + N s of linear rows, N orthonormal (Dim columns).
struct LinearSpace
{
  double X0[4] = { 0, 0, 0, 0 };
  double N[4][4] = {}; // N[k] is the k-th basis vector
  int Dim = 4;

  // Gauss-Jordan with full pivoting. False when the rows are inconsistent.
  bool Reduce(const std::vector<Row>& rows)
  {
    thread_local std::vector<std::array<double, 5>> m; // per-thread scratch: no allocation per call
    m.clear();
    for (const Row& row : rows)
    {
      const double len = std::sqrt(row.A[0] * row.A[0] + row.A[1] * row.A[1] + row.A[2] * row.A[2] + row.A[3] * row.A[3]);
      if (!(len > 1e-300))
      {
        if (std::fabs(row.B) > InconsistentRow)
        {
          return false;
        }
        continue;
      }
      m.push_back({ row.A[0] / len, row.A[1] / len, row.A[2] / len, row.A[3] / len, row.B / len });
    }
    int pivotColumn[4];
    bool used[4] = { false, false, false, false };
    int rank = 0;
    const int rowsCount = static_cast<int>(m.size());
    while (rank < std::min(rowsCount, 4))
    {
      int bi = -1, bj = -1;
      double best = PivotFloor;
      for (int i = rank; i < rowsCount; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          if (!used[j] && std::fabs(m[i][j]) > best)
          {
            best = std::fabs(m[i][j]);
            bi = i;
            bj = j;
          }
        }
      }
      if (bi < 0)
      {
        break;
      }
      std::swap(m[bi], m[rank]);
      used[bj] = true;
      pivotColumn[rank] = bj;
      const double inv = 1.0 / m[rank][bj];
      for (double& v : m[rank])
      {
        v *= inv;
      }
      for (int i = 0; i < rowsCount; ++i)
      {
        if (i != rank && m[i][bj] != 0.0)
        {
          const double f = m[i][bj];
          for (int j = 0; j < 5; ++j)
          {
            m[i][j] -= f * m[rank][j];
          }
        }
      }
      ++rank;
    }
    for (int i = rank; i < rowsCount; ++i)
    {
      if (std::fabs(m[i][4]) > InconsistentRow)
      {
        return false;
      }
    }
    std::fill(this->X0, this->X0 + 4, 0.0);
    for (int i = 0; i < rank; ++i)
    {
      this->X0[pivotColumn[i]] = m[i][4];
    }
    this->Dim = 0;
    for (int f = 0; f < 4; ++f)
    {
      if (used[f])
      {
        continue;
      }
      double* v = this->N[this->Dim];
      std::fill(v, v + 4, 0.0);
      v[f] = 1.0;
      for (int i = 0; i < rank; ++i)
      {
        v[pivotColumn[i]] = -m[i][f];
      }
      // Gram-Schmidt against the earlier basis vectors.
      for (int k = 0; k < this->Dim; ++k)
      {
        const double d = v[0] * this->N[k][0] + v[1] * this->N[k][1] + v[2] * this->N[k][2] + v[3] * this->N[k][3];
        for (int j = 0; j < 4; ++j)
        {
          v[j] -= d * this->N[k][j];
        }
      }
      const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
      for (int j = 0; j < 4; ++j)
      {
        v[j] /= len;
      }
      ++this->Dim;
    }
    return true;
  }

  void At(const double* s, double X[4]) const
  {
    for (int j = 0; j < 4; ++j)
    {
      X[j] = this->X0[j];
      for (int k = 0; k < this->Dim; ++k)
      {
        X[j] += s[k] * this->N[k][j];
      }
    }
  }
};

// Solves the d x d system J x = b in place (partial pivoting). False when singular.
bool SolveSmall(double J[4][4], double b[4], int d)
{
  for (int c = 0; c < d; ++c)
  {
    int p = c;
    for (int i = c + 1; i < d; ++i)
    {
      p = std::fabs(J[i][c]) > std::fabs(J[p][c]) ? i : p;
    }
    if (!(std::fabs(J[p][c]) > 1e-300))
    {
      return false;
    }
    std::swap(J[p], J[c]);
    std::swap(b[p], b[c]);
    for (int i = c + 1; i < d; ++i)
    {
      const double f = J[i][c] / J[c][c];
      for (int j = c; j < d; ++j)
      {
        J[i][j] -= f * J[c][j];
      }
      b[i] -= f * b[c];
    }
  }
  for (int c = d - 1; c >= 0; --c)
  {
    for (int j = c + 1; j < d; ++j)
    {
      b[c] -= J[c][j] * b[j];
    }
    b[c] /= J[c][c];
  }
  return true;
}

// Roots of a s^2 + b s + c = 0, stable form; near-double roots are kept.
int QuadraticRoots(double a, double b, double c, double roots[2])
{
  const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c);
  if (!(scale > 0.0))
  {
    return 0;
  }
  if (std::fabs(a) <= 1e-14 * scale)
  {
    if (b == 0.0)
    {
      return 0;
    }
    roots[0] = -c / b;
    return 1;
  }
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0)
  {
    if (disc < -1e-12 * (b * b + std::fabs(4.0 * a * c)))
    {
      return 0;
    }
    disc = 0.0;
  }
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0)
  {
    roots[0] = 0.0;
    return 1;
  }
  roots[0] = q / a;
  roots[1] = c / q;
  return 2;
}

// Damped steps after which Newton's method gives up when no halving of the step
// lowered a residual still above the acceptance level (see Newton).
constexpr int MaximumStalls = 3;

// Newton's method on the first `space.Dim` quadrics over X0 + N s, from X. Converged
// when the squared residual is at most 1e-24. Near a root the Newton step is a descent
// direction, so a step that no halving (down to 2^-29) makes lower the residual means
// the iteration is stuck away from a root: after MaximumStalls such steps above the
// acceptance level it gives up (measured: a call that converged never had more than
// one; the calls that do not converge had spent most of the solver's time going on
// for all 60 iterations).
bool Newton(const LinearSpace& space, const std::vector<Quadric>& quadrics, double X[4])
{
  const int d = space.Dim;
  double s[4] = { 0, 0, 0, 0 };
  for (int k = 0; k < d; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      s[k] += (X[j] - space.X0[j]) * space.N[k][j];
    }
  }
  auto residual = [&](const double* at, double F[4]) {
    double Y[4];
    space.At(at, Y);
    double norm = 0.0;
    for (int i = 0; i < d; ++i)
    {
      F[i] = Evaluate(quadrics[i], Y);
      norm += F[i] * F[i];
    }
    return norm;
  };
  double F[4];
  double norm = residual(s, F);
  int stalls = 0;
  for (int iteration = 0; iteration < 60 && norm > 1e-32; ++iteration)
  {
    double Y[4], J[4][4], step[4];
    space.At(s, Y);
    for (int i = 0; i < d; ++i)
    {
      double g[4];
      Gradient(quadrics[i], Y, g);
      for (int k = 0; k < d; ++k)
      {
        J[i][k] = g[0] * space.N[k][0] + g[1] * space.N[k][1] + g[2] * space.N[k][2] + g[3] * space.N[k][3];
      }
      step[i] = -F[i];
    }
    if (!SolveSmall(J, step, d))
    {
      return false;
    }
    // Damped: halve the step until the residual falls (or the step is tiny).
    double t = 1.0, trial[4], Ftrial[4], trialNorm = 0.0;
    bool lowered = false;
    for (int halving = 0; halving < 30 && !lowered; ++halving, t *= 0.5)
    {
      for (int k = 0; k < d; ++k)
      {
        trial[k] = s[k] + t * step[k];
      }
      trialNorm = residual(trial, Ftrial);
      lowered = trialNorm < norm;
    }
    if (!lowered && norm > 1e-24 && ++stalls >= MaximumStalls)
    {
      return false;
    }
    double moved = 0.0;
    for (int k = 0; k < d; ++k)
    {
      moved = std::max(moved, std::fabs(trial[k] - s[k]));
      s[k] = trial[k];
      F[k] = Ftrial[k];
    }
    norm = trialNorm;
    if (moved < 1e-16)
    {
      break;
    }
  }
  space.At(s, X);
  return norm <= 1e-24;
}

// Merges points closer than a tolerance; a junction absorbs seam points.
class PointMerger
{
public:
  explicit PointMerger(double tolerance)
    : Tolerance(tolerance)
  {
  }
  vtkIdType Add(const vtkMedialSeamSolver::ExactPoint& p, std::vector<vtkMedialSeamSolver::ExactPoint>& points)
  {
    long long key[3];
    for (int k = 0; k < 3; ++k)
    {
      key[k] = static_cast<long long>(std::floor(p.Centre[k] / this->Tolerance));
    }
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        for (long long dz = -1; dz <= 1; ++dz)
        {
          const auto it = this->Cells.find(Hash(key[0] + dx, key[1] + dy, key[2] + dz));
          if (it == this->Cells.end())
          {
            continue;
          }
          for (vtkIdType id : it->second)
          {
            auto& q = points[id];
            if (G::Distance2(q.Centre, p.Centre) <= this->Tolerance * this->Tolerance)
            {
              q.Type = std::max(q.Type, p.Type);
              q.GovernorCount = std::max(q.GovernorCount, p.GovernorCount);
              std::vector<int> merged;
              std::set_union(q.Features.begin(), q.Features.end(), p.Features.begin(), p.Features.end(),
                std::back_inserter(merged));
              q.Features.swap(merged);
              return id;
            }
          }
        }
      }
    }
    const vtkIdType id = static_cast<vtkIdType>(points.size());
    points.push_back(p);
    this->Cells[Hash(key[0], key[1], key[2])].push_back(id);
    return id;
  }

private:
  static long long Hash(long long x, long long y, long long z)
  {
    return (x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL);
  }
  double Tolerance;
  std::unordered_map<long long, std::vector<vtkIdType>> Cells;
};

bool Includes(const std::vector<int>& big, const std::vector<int>& small)
{
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

// Calls visit(subset) for every k-subset of `set` (k = 3 or 4), in lexicographic order.
template <class Visit>
void Subsets(const std::vector<int>& set, int k, Visit visit)
{
  const int n = static_cast<int>(set.size());
  int idx[4];
  for (idx[0] = 0; idx[0] < n; ++idx[0])
  {
    for (idx[1] = idx[0] + 1; idx[1] < n; ++idx[1])
    {
      for (idx[2] = idx[1] + 1; idx[2] < n; ++idx[2])
      {
        if (k == 3)
        {
          visit(std::array<int, 4>{ set[idx[0]], set[idx[1]], set[idx[2]], -1 });
          continue;
        }
        for (idx[3] = idx[2] + 1; idx[3] < n; ++idx[3])
        {
          visit(std::array<int, 4>{ set[idx[0]], set[idx[1]], set[idx[2]], set[idx[3]] });
        }
      }
    }
  }
}

// Unions of more governors than this are not split into candidates.
constexpr size_t MaximumUnion = 6;
// Seeds kept per junction candidate.
constexpr size_t MaximumSeeds = 4;
}

vtkMedialSeamSolver::vtkMedialSeamSolver(const vtkMedialGovernors& governors)
  : Governors(governors)
{
  const double* b = governors.GetMesh().Bounds;
  for (int k = 0; k < 3; ++k)
  {
    this->Origin[k] = 0.5 * (b[2 * k] + b[2 * k + 1]);
  }
  this->Scale = governors.GetDiagonal() > 0.0 ? governors.GetDiagonal() : 1.0;
}

namespace
{
// The equations of `n` features in scaled coordinates: planes as rows, points and
// lines as quadrics; quadrics with the quadratic part of an earlier one (points;
// parallel lines) become the linear row of their difference.
void BuildEquations(const vtkMedialGovernors& governors, const int* features, int n,
  const double origin[3], double scale, std::vector<Row>& rows, std::vector<Quadric>& quadrics)
{
  for (int i = 0; i < n; ++i)
  {
    const auto& f = governors.GetFeature(features[i]);
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (f.Point[k] - origin[k]) / scale;
    }
    if (f.Kind == vtkMedialGovernors::PLANE)
    {
      rows.push_back({ { f.Direction[0], f.Direction[1], f.Direction[2], -1.0 }, G::Dot(f.Direction, p) });
      continue;
    }
    const double zero[3] = { 0, 0, 0 };
    const double* u = f.Kind == vtkMedialGovernors::LINE ? f.Direction : zero;
    const Quadric* same = nullptr;
    for (const Quadric& q : quadrics)
    {
      double x[3];
      G::Cross(q.Direction, u, x);
      if (q.Kind == f.Kind && G::Dot(x, x) <= 1e-18)
      {
        same = &q;
        break;
      }
    }
    const Quadric q = MakeQuadric(f.Kind, p, same ? same->Direction : u);
    if (!same)
    {
      quadrics.push_back(q);
      continue;
    }
    Row row;
    for (int k = 0; k < 4; ++k)
    {
      row.A[k] = q.G[k] - same->G[k];
    }
    row.B = same->C - q.C;
    rows.push_back(row);
  }
}
}

void vtkMedialSeamSolver::TangentBalls(const int* features, int n, const double* constraint,
  const std::vector<BallVector>& seeds, std::vector<BallVector>& out) const
{
  // Per-thread scratch (the solver runs millions of these small systems): no allocation per call.
  thread_local std::vector<Row> rows;
  thread_local std::vector<Quadric> quadrics;
  thread_local std::vector<std::array<double, 4>> scaled;
  rows.clear();
  quadrics.clear();
  scaled.clear();
  BuildEquations(this->Governors, features, n, this->Origin, this->Scale, rows, quadrics);
  if (constraint)
  {
    // w.(x, r) = k in world units; in scaled units w'.X' = (k - w.origin) / scale with w' = w.
    Row row;
    std::copy(constraint, constraint + 4, row.A);
    row.B = (constraint[4] - (constraint[0] * this->Origin[0] + constraint[1] * this->Origin[1] +
                               constraint[2] * this->Origin[2])) / this->Scale;
    rows.push_back(row);
  }
  LinearSpace space;
  if (!space.Reduce(rows) || space.Dim > static_cast<int>(quadrics.size()))
  {
    return; // inconsistent, or a family of solutions (degenerate set)
  }
  if (space.Dim == 0)
  {
    scaled.push_back({ space.X0[0], space.X0[1], space.X0[2], space.X0[3] });
  }
  else if (space.Dim == 1)
  {
    const Quadric& q = quadrics[0];
    const double* v = space.N[0];
    double g0[4];
    Gradient(q, space.X0, g0);
    double a = -v[3] * v[3];
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        a += v[i] * q.H[i][j] * v[j];
      }
    }
    const double b = g0[0] * v[0] + g0[1] * v[1] + g0[2] * v[2] + g0[3] * v[3];
    double roots[2];
    const int count = QuadraticRoots(a, b, Evaluate(q, space.X0), roots);
    for (int i = 0; i < count; ++i)
    {
      std::array<double, 4> X;
      space.At(&roots[i], X.data());
      scaled.push_back(X);
    }
  }
  else
  {
    for (const BallVector& seed : seeds)
    {
      std::array<double, 4> X;
      for (int k = 0; k < 3; ++k)
      {
        X[k] = (seed[k] - this->Origin[k]) / this->Scale;
      }
      X[3] = seed[3] / this->Scale;
      if (Newton(space, quadrics, X.data()))
      {
        scaled.push_back(X);
      }
    }
  }
  for (const auto& X : scaled)
  {
    if (!(X[3] > 0.0) || !std::isfinite(X[0] + X[1] + X[2] + X[3]))
    {
      continue;
    }
    BallVector ball;
    for (int k = 0; k < 3; ++k)
    {
      ball[k] = this->Origin[k] + this->Scale * X[k];
    }
    ball[3] = this->Scale * X[3];
    const bool known = std::any_of(out.begin(), out.end(), [&](const BallVector& b) {
      return std::fabs(b[0] - ball[0]) + std::fabs(b[1] - ball[1]) + std::fabs(b[2] - ball[2]) +
        std::fabs(b[3] - ball[3]) <= 1e-13 * this->Scale;
    });
    if (!known)
    {
      out.push_back(ball);
    }
  }
}

bool vtkMedialSeamSolver::SeamTangent(const int features[3], const BallVector& reference, double t[4]) const
{
  double X[4];
  for (int k = 0; k < 3; ++k)
  {
    X[k] = (reference[k] - this->Origin[k]) / this->Scale;
  }
  X[3] = reference[3] / this->Scale;
  // The tangency gradients at the reference; the seam runs along their null vector.
  thread_local std::vector<Row> rows; // per-thread scratch
  rows.clear();
  for (int i = 0; i < 3; ++i)
  {
    const auto& f = this->Governors.GetFeature(features[i]);
    Row row;
    row.B = 0.0;
    if (f.Kind == vtkMedialGovernors::PLANE)
    {
      std::copy(f.Direction, f.Direction + 3, row.A);
      row.A[3] = -1.0;
    }
    else
    {
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = (f.Point[k] - this->Origin[k]) / this->Scale;
      }
      const double zero[3] = { 0, 0, 0 };
      Gradient(MakeQuadric(f.Kind, p, f.Kind == vtkMedialGovernors::LINE ? f.Direction : zero), X, row.A);
    }
    rows.push_back(row);
  }
  LinearSpace space;
  if (!space.Reduce(rows) || space.Dim != 1)
  {
    return false;
  }
  // A direction in scaled units is the same direction in world units.
  std::copy(space.N[0], space.N[0] + 4, t);
  return true;
}

bool vtkMedialSeamSolver::SeamConstraint(
  const int features[3], const BallVector& reference, double constraint[5]) const
{
  if (!this->SeamTangent(features, reference, constraint))
  {
    return false;
  }
  constraint[4] = constraint[0] * reference[0] + constraint[1] * reference[1] + constraint[2] * reference[2] +
    constraint[3] * reference[3];
  return true;
}

bool vtkMedialSeamSolver::Verify(const BallVector& ball, const int* features, int n, ExactPoint& point) const
{
  const double tolerance = this->VerifyTolerance * this->Governors.GetDiagonal();
  const double r = ball[3];
  // The ball empty (the contains-ball query) and its governors, in one walk.
  vtkMedialGovernors::BallGovernors touched;
  if (!(r > tolerance) ||
    !this->Governors.ClassifyIfEmpty(ball.data(), r, tolerance, this->Governors.GetMinimumSeparationAngle(), touched))
  {
    return false;
  }
  for (int i = 0; i < n; ++i)
  {
    if (!std::binary_search(touched.ContactFeatures.begin(), touched.ContactFeatures.end(), features[i]))
    {
      return false;
    }
  }
  if (touched.Count() < 3)
  {
    return false; // a transition inside a sheet, or governors merged by theta
  }
  std::copy(ball.begin(), ball.begin() + 3, point.Centre);
  point.Radius = r;
  point.GovernorCount = touched.Count();
  point.Type = touched.Count() >= 4 ? vtkMedialGovernors::JUNCTION : vtkMedialGovernors::SEAM;
  point.Features = touched.ContactFeatures;
  return true;
}

void vtkMedialSeamSolver::SolveCandidates(std::vector<Candidate>& candidates, int threads,
  const std::function<bool()>& aborted, bool& stopped) const
{
  const vtkIdType count = static_cast<vtkIdType>(candidates.size());
  const vtkIdType block = 4096;
  for (vtkIdType begin = 0; begin < count && !stopped; begin += block)
  {
    const vtkIdType end = std::min(count, begin + block);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16)
    for (vtkIdType i = begin; i < end; ++i)
    {
      Candidate& c = candidates[i];
      if (c.Solved)
      {
        continue;
      }
      c.Solved = true;
      std::vector<BallVector> solutions;
      double constraint[5];
      if (c.N == 3)
      {
        if (!this->SeamConstraint(c.Features.data(), c.Seeds[0], constraint))
        {
          continue;
        }
      }
      this->TangentBalls(c.Features.data(), c.N, c.N == 3 ? constraint : nullptr, c.Seeds, solutions);
      for (const BallVector& s : solutions)
      {
        ExactPoint p;
        const double moved = std::sqrt(G::Distance2(s.data(), c.Seeds[0].data()));
        if (moved <= c.Reach && this->Verify(s, c.Features.data(), c.N, p))
        {
          if (c.N == 4 || p.GovernorCount < 4)
          {
            c.Found.push_back(p);
            continue;
          }
          // A seam point touching a fourth governor lies within the tolerance of a
          // junction: the quadruple gives that exactly.
          for (int d : p.Features)
          {
            if (d != c.Features[0] && d != c.Features[1] && d != c.Features[2])
            {
              std::array<int, 4> q{ { c.Features[0], c.Features[1], c.Features[2], d } };
              std::sort(q.begin(), q.end());
              c.Nearby.emplace_back(q, s);
            }
          }
        }
      }
    }
    stopped = aborted && aborted();
  }
}

bool vtkMedialSeamSolver::HasIncidentPair(const std::array<int, 4>& f, int n) const
{
  for (int i = 0; i < n; ++i)
  {
    for (int j = i + 1; j < n; ++j)
    {
      if (this->Governors.AreIncident(f[i], f[j]))
      {
        return true;
      }
    }
  }
  return false;
}

void vtkMedialSeamSolver::AddTriple(Candidates& candidates, const std::array<int, 4>& f,
  const BallVector& reference, double reach, vtkIdType pair) const
{
  if (this->HasIncidentPair(f, 3))
  {
    return;
  }
  Candidate c;
  c.Features = f;
  c.N = 3;
  c.Seeds.push_back(reference);
  c.Reach = reach;
  if (pair >= 0)
  {
    c.Pairs.push_back(pair);
  }
  candidates.Triples.push_back(std::move(c));
}

void vtkMedialSeamSolver::AddQuadruple(
  Candidates& candidates, const std::array<int, 4>& f, const BallVector& seed, vtkIdType pair) const
{
  if (this->HasIncidentPair(f, 4))
  {
    return;
  }
  Candidate& c = candidates.Quadruples[f];
  c.Features = f;
  c.N = 4;
  if (!c.Solved && c.Seeds.size() < MaximumSeeds)
  {
    c.Seeds.push_back(seed);
  }
  if (pair >= 0 && c.Pairs.size() < MaximumSeeds)
  {
    c.Pairs.push_back(pair);
  }
}

void vtkMedialSeamSolver::Propose(
  const std::vector<Ball>& balls, const std::vector<Pair>& pairs, Candidates& candidates) const
{
  auto vectorOf = [](const Ball& b) { return BallVector{ b.Centre[0], b.Centre[1], b.Centre[2], b.Radius }; };
  for (size_t p = 0; p < pairs.size(); ++p)
  {
    const Ball& a = balls[pairs[p][0]];
    const Ball& b = balls[pairs[p][1]];
    const auto& A = a.Governors.Features;
    const auto& B = b.Governors.Features;
    if (!a.Governors.AllSimple() || !b.Governors.AllSimple() || Includes(A, B) || Includes(B, A))
    {
      continue;
    }
    std::vector<int> u;
    std::set_union(A.begin(), A.end(), B.begin(), B.end(), std::back_inserter(u));
    const BallVector va = vectorOf(a), vb = vectorOf(b);
    BallVector mid;
    double gap2 = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      mid[k] = 0.5 * (va[k] + vb[k]);
      gap2 += (va[k] - vb[k]) * (va[k] - vb[k]);
    }
    const vtkIdType pair = static_cast<vtkIdType>(p);
    if (u.size() == 3)
    {
      this->AddTriple(candidates, { { u[0], u[1], u[2], -1 } }, mid, 2.0 * std::sqrt(gap2), pair);
    }
    else if (u.size() <= MaximumUnion)
    {
      Subsets(u, 4, [&](const std::array<int, 4>& f) { this->AddQuadruple(candidates, f, mid, pair); });
    }
  }
  for (const Ball& b : balls)
  {
    const auto& g = b.Governors.Features;
    if (g.size() < 3 || g.size() > MaximumUnion || !b.Governors.AllSimple())
    {
      continue;
    }
    Subsets(g, 3, [&](const std::array<int, 4>& f) { this->AddTriple(candidates, f, vectorOf(b), b.Radius, -1); });
    Subsets(g, 4, [&](const std::array<int, 4>& f) { this->AddQuadruple(candidates, f, vectorOf(b), -1); });
  }
}

void vtkMedialSeamSolver::ProposeFromSeams(Candidates& candidates) const
{
  // Two accepted seams that share two governors meet at the junction of all four.
  std::map<std::array<int, 2>, std::vector<std::pair<int, BallVector>>> byPair;
  for (const Candidate& c : candidates.Triples)
  {
    for (const ExactPoint& p : c.Found)
    {
      const BallVector seed{ p.Centre[0], p.Centre[1], p.Centre[2], p.Radius };
      const auto& f = c.Features;
      byPair[{ { f[0], f[1] } }].emplace_back(f[2], seed);
      byPair[{ { f[0], f[2] } }].emplace_back(f[1], seed);
      byPair[{ { f[1], f[2] } }].emplace_back(f[0], seed);
    }
  }
  using Third = std::pair<int, BallVector>;
  for (auto& entry : byPair)
  {
    auto& thirds = entry.second;
    // One seed per distinct third governor is enough.
    std::stable_sort(
      thirds.begin(), thirds.end(), [](const Third& x, const Third& y) { return x.first < y.first; });
    thirds.erase(std::unique(thirds.begin(), thirds.end(),
                   [](const Third& x, const Third& y) { return x.first == y.first; }),
      thirds.end());
    for (size_t i = 0; i < thirds.size(); ++i)
    {
      for (size_t j = i + 1; j < thirds.size(); ++j)
      {
        std::array<int, 4> f{ { entry.first[0], entry.first[1], thirds[i].first, thirds[j].first } };
        std::sort(f.begin(), f.end());
        this->AddQuadruple(candidates, f, thirds[i].second, -1);
        this->AddQuadruple(candidates, f, thirds[j].second, -1);
      }
    }
  }
  // Seam points that touched a fourth governor: its junction.
  for (const Candidate& c : candidates.Triples)
  {
    for (const Tagged& q : c.Nearby)
    {
      this->AddQuadruple(candidates, q.first, q.second, -1);
    }
  }
}

void vtkMedialSeamSolver::MergePoints(const std::vector<Ball>& balls, const std::vector<Pair>& pairs,
  const std::vector<Candidate>& quadruples, const std::vector<Candidate>& triples, Result& result) const
{
  // Junctions first, in candidate order; each pair gets the point it found nearest
  // to its midpoint.
  PointMerger merger(this->MergeTolerance * this->Governors.GetDiagonal());
  std::vector<double> pairDistance(pairs.size(), HUGE_VAL);
  for (const std::vector<Candidate>* list : { &quadruples, &triples })
  {
    for (const Candidate& c : *list)
    {
      for (const ExactPoint& p : c.Found)
      {
        ++result.Verified;
        const vtkIdType id = merger.Add(p, result.Points);
        for (vtkIdType pair : c.Pairs)
        {
          const Ball& a = balls[pairs[pair][0]];
          const Ball& b = balls[pairs[pair][1]];
          const double m[3] = { 0.5 * (a.Centre[0] + b.Centre[0]), 0.5 * (a.Centre[1] + b.Centre[1]),
            0.5 * (a.Centre[2] + b.Centre[2]) };
          const double d = G::Distance2(m, p.Centre);
          if (d < pairDistance[pair])
          {
            pairDistance[pair] = d;
            result.PairPoint[pair] = id;
          }
        }
      }
    }
  }
}

bool vtkMedialSeamSolver::Solve(const std::vector<Ball>& balls, const std::vector<Pair>& pairs,
  int threads, const std::function<bool()>& aborted, Result& result) const
{
  result = Result();
  result.PairPoint.assign(pairs.size(), -1);
  threads = vtkMedialThreadCount(threads);

  // 1. Seam candidates (triples) and junction candidates (quadruples) from pairs and balls.
  Candidates candidates;
  this->Propose(balls, pairs, candidates);

  // 2. Seam points, and the junctions where two seams found meet.
  bool stopped = aborted && aborted();
  this->SolveCandidates(candidates.Triples, threads, aborted, stopped);
  if (stopped)
  {
    return false;
  }
  this->ProposeFromSeams(candidates);

  // 3. Junction vertices, then every seam traced from its seam points and junctions
  //    to its ends, where more junctions are solved.
  std::vector<Candidate> first;
  for (auto& entry : candidates.Quadruples)
  {
    first.push_back(entry.second);
  }
  this->SolveCandidates(first, threads, aborted, stopped);
  for (Candidate& c : first)
  {
    candidates.Quadruples[c.Features] = std::move(c);
  }
  if (stopped || !this->TraceAll(candidates, threads, aborted, result))
  {
    return false;
  }
  std::vector<Candidate> quadruples;
  quadruples.reserve(candidates.Quadruples.size());
  for (auto& entry : candidates.Quadruples)
  {
    quadruples.push_back(std::move(entry.second));
  }
  result.SeamCandidates = static_cast<vtkIdType>(candidates.Triples.size());
  result.JunctionCandidates = static_cast<vtkIdType>(quadruples.size());

  // 4. Merged points.
  this->MergePoints(balls, pairs, quadruples, candidates.Triples, result);
  return true;
}

std::vector<vtkMedialSeamSolver::Pair> vtkMedialSeamSolver::NearestPairs(
  const double* centres, vtkIdType n, int k, int threads)
{
  std::vector<Pair> pairs;
  if (n < 2 || k < 1)
  {
    return pairs;
  }
  vtkMedialNearestPoints nearest;
  nearest.Build(centres, n);
  // Each centre finds itself among its k + 1 nearest (unless more than k + 1 centres
  // share its place and have smaller ids): k + 1 slots per centre, self and unused -1.
  const int wanted = static_cast<int>(std::min<vtkIdType>(k + 1, n));
  std::vector<vtkIdType> found(static_cast<size_t>(n) * wanted, -1);
#pragma omp parallel num_threads(std::max(1, threads))
  {
    std::vector<double> dist2(static_cast<size_t>(wanted));
#pragma omp for schedule(static)
    for (vtkIdType i = 0; i < n; ++i)
    {
      vtkIdType* ids = found.data() + i * wanted;
      const int count = nearest.Find(centres + 3 * i, wanted, ids, dist2.data());
      for (int j = 0; j < count; ++j)
      {
        ids[j] = ids[j] == i ? -1 : ids[j];
      }
    }
  }
  // Each pair once, in order: grouped by the smaller id (unused slots under key n), then
  // each group's larger ids sorted and unique; the list a sort of all the pairs gives, in
  // a fraction of its comparisons (the groups hold about 2k ids).
  const vtkIdType slots = n * wanted;
  auto smaller = [&](vtkIdType s) { return found[s] < 0 ? n : std::min(s / wanted, found[s]); };
  std::vector<vtkIdType> larger(static_cast<size_t>(slots));
  const auto offsets = vtkMedialGroupByKey(
    slots, n + 1, smaller, [&](vtkIdType s, vtkIdType at) { larger[at] = std::max(s / wanted, found[s]); },
    std::max(1, threads));
  pairs.reserve(larger.size());
  for (vtkIdType a = 0; a < n; ++a)
  {
    const auto begin = larger.begin() + offsets[a], end = larger.begin() + offsets[a + 1];
    std::sort(begin, end);
    for (auto b = begin; b != end; ++b)
    {
      if (b == begin || *b != *(b - 1))
      {
        pairs.push_back({ a, *b });
      }
    }
  }
  return pairs;
}
