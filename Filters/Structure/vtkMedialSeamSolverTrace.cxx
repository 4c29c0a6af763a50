// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialSeamSolver, part 2: following seams to their ends (see the class comment).
#include "vtkMedialSeamSolver.h"

#include "vtkMedialGeometry.h"
#include "vtkMedialSurfaceQuery.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace
{
using BallVector = vtkMedialSeamSolver::BallVector;

// Bounds on the work of tracing one seam: marching steps per direction and
// bisection steps (the seams traced in all are bounded by MaximumTracedSeams).
constexpr int MaximumSteps = 200;
constexpr int MaximumBisections = 64;
// Features touching a seam's last ball beyond which the end is degenerate: three are the
// seam's own, one more a junction or a transition; a few more occur at symmetric ends.
constexpr size_t MaximumTouched = 12;
// The bisection's list of nearby triangles (Ends): gathered once the bracket is below
// this share of the radius, when the list about a wider bracket would be long.
constexpr double NearbyShare = 1e-3;

double Distance4(const BallVector& a, const BallVector& b)
{
  double d2 = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    d2 += (a[k] - b[k]) * (a[k] - b[k]);
  }
  return std::sqrt(d2);
}

BallVector Along(const BallVector& x, double h, const double t[4])
{
  return { x[0] + h * t[0], x[1] + h * t[1], x[2] + h * t[2], x[3] + h * t[3] };
}
}

bool vtkMedialSeamSolver::OnSeam(
  const int features[3], const BallVector& guess, const double tangent[4], BallVector& out) const
{
  double constraint[5];
  std::copy(tangent, tangent + 4, constraint);
  constraint[4] = tangent[0] * guess[0] + tangent[1] * guess[1] + tangent[2] * guess[2] + tangent[3] * guess[3];
  thread_local std::vector<BallVector> solutions; // per-thread scratch
  solutions.clear();
  this->TangentBalls(features, 3, constraint, { guess }, solutions);
  double best = HUGE_VAL;
  for (const BallVector& s : solutions)
  {
    const double d = Distance4(s, guess);
    if (d < best)
    {
      best = d;
      out = s;
    }
  }
  return best < HUGE_VAL;
}

int vtkMedialSeamSolver::SeamState(const int features[3], const BallVector& X, double tolerance,
  std::vector<int>& touched, const vtkMedialTriangleBVH::Nearby* nearby) const
{
  if (!(X[3] > tolerance))
  {
    touched.clear();
    return LEFT;
  }
  // A feature is touched only when its primitive is tangent to the ball within the
  // tolerance (vtkMedialGovernors::TouchedFeatures): when one of the three is not, the
  // ball is off the seam whatever the surface queries would say (callers only ask
  // whether it is on the seam), so they are skipped.
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::fabs(this->Governors.DistanceToFeature(features[i], X.data()) - X[3]) <= tolerance))
    {
      touched.clear();
      return LEFT;
    }
  }
  // Empty (the contains-ball query) and the contacts in one walk, which stops at the
  // first point inside: cheap for the balls beyond a seam's end, which may hold much
  // of the surface.
  if (!this->Governors.TouchedFeatures(X.data(), X[3], tolerance, touched, true, nearby))
  {
    touched.clear();
    return BLOCKED;
  }
  for (int i = 0; i < 3; ++i)
  {
    if (!std::binary_search(touched.begin(), touched.end(), features[i]))
    {
      return LEFT;
    }
  }
  return ON_SEAM;
}

void vtkMedialSeamSolver::TraceSeam(const int features[3], const BallVector& start, TraceEnds& ends) const
{
  const double diagonal = this->Governors.GetDiagonal();
  const double tolerance = this->VerifyTolerance * diagonal;
  std::vector<int> touched;
  for (double direction : { 1.0, -1.0 })
  {
    double t[4];
    if (!this->SeamTangent(features, start, t))
    {
      return;
    }
    for (double& v : t)
    {
      v *= direction;
    }
    BallVector x = start;
    double h = std::max(0.25 * x[3], 1e-6 * diagonal);
    for (int step = 0; step < MaximumSteps && h > 1e-12 * diagonal; ++step)
    {
      const BallVector predicted = Along(x, h, t);
      BallVector y;
      if (!this->OnSeam(features, predicted, t, y) || Distance4(y, predicted) > 0.5 * h)
      {
        h *= 0.5; // the seam turns faster than the step: shorten it
        continue;
      }
      if (this->SeamState(features, y, tolerance, touched) != ON_SEAM)
      {
        this->Ends(features, x, y, t, ends);
        break;
      }
      double next[4];
      if (!this->SeamTangent(features, y, next))
      {
        break;
      }
      const double turn = next[0] * t[0] + next[1] * t[1] + next[2] * t[2] + next[3] * t[3];
      for (int k = 0; k < 4; ++k)
      {
        t[k] = turn < 0.0 ? -next[k] : next[k];
      }
      x = y;
      h = std::min(2.0 * h, diagonal);
    }
  }
}

void vtkMedialSeamSolver::Ends(const int features[3], const BallVector& last, const BallVector& beyond,
  const double tangent[4], TraceEnds& ends) const
{
  const double diagonal = this->Governors.GetDiagonal();
  const double tolerance = this->VerifyTolerance * diagonal;
  std::vector<int> touched;
  // The bisection's balls differ by less and less: once the bracket is small beside the
  // radius, their walks read a list of the triangles near it instead of the tree (the
  // same answers). Gathered then, the list is short (the contact patches within a thin
  // shell about the ball), and it covers the rest of the bisection (gathered again only
  // if a ball strays out of it).
  const vtkMedialSurfaceQuery& query = this->Governors.GetQuery();
  thread_local vtkMedialTriangleBVH::Nearby nearby; // per-thread scratch
  nearby.Distance = -1.0;
  BallVector lo = last, hi = beyond;
  for (int i = 0; i < MaximumBisections && Distance4(lo, hi) > 1e-10 * diagonal; ++i)
  {
    BallVector mid;
    for (int k = 0; k < 4; ++k)
    {
      mid[k] = 0.5 * (lo[k] + hi[k]);
    }
    BallVector z;
    if (!this->OnSeam(features, mid, tangent, z))
    {
      z = mid;
    }
    const double width = Distance4(lo, hi);
    if (width <= NearbyShare * z[3] && !query.Covers(nearby, z.data(), z[3] + tolerance))
    {
      query.GatherNearby(z.data(), z[3] + tolerance + 2.0 * width, nearby);
    }
    (this->SeamState(features, z, tolerance, touched, &nearby) == ON_SEAM ? lo : hi) = z;
  }
  if (!(lo[3] > tolerance))
  {
    return; // the rim: the radius goes to zero
  }
  // A bracket that did not close (the seam projections jumped about) says nothing of
  // what ends the seam; searching within its width would touch every feature near a
  // large ball (on smoothed noisy surfaces, tens of thousands per end, and gigabytes of
  // junction candidates).
  const double bracket = Distance4(lo, hi);
  if (bracket > tolerance)
  {
    return;
  }
  // What touches the last ball on the seam, within the bracket: the fourth governor
  // (a junction) or the edge or vertex a contact moves onto (a transition).
  this->Governors.TouchedFeatures(lo.data(), lo[3], tolerance + bracket, touched, false, &nearby);
  if (touched.size() > MaximumTouched)
  {
    return; // a degenerate end (many coplanar or cospherical features): no candidate is trusted
  }
  for (int d : touched)
  {
    if (d == features[0] || d == features[1] || d == features[2])
    {
      continue;
    }
    int incident = -1, count = 0;
    for (int i = 0; i < 3; ++i)
    {
      if (this->Governors.AreIncident(features[i], d))
      {
        incident = i;
        ++count;
      }
    }
    if (count == 0)
    {
      std::array<int, 4> q{ { features[0], features[1], features[2], d } };
      std::sort(q.begin(), q.end());
      ends.Quadruples.emplace_back(q, lo);
    }
    else if (count == 1)
    {
      std::array<int, 4> f{ { features[0], features[1], features[2], -1 } };
      f[incident] = d;
      std::sort(f.begin(), f.begin() + 3);
      ends.Triples.emplace_back(f, lo);
    }
  }
}

bool vtkMedialSeamSolver::TraceAll(
  Candidates& candidates, int threads, const std::function<bool()>& aborted, Result& result) const
{
  auto& quadruples = candidates.Quadruples;
  std::set<std::array<int, 4>> traced;
  std::vector<Tagged> pending;
  const size_t budget = static_cast<size_t>(std::max<vtkIdType>(0, this->MaximumTracedSeams));
  auto queue = [&](const std::array<int, 4>& f, const BallVector& at) {
    if (this->HasIncidentPair(f, 3) || traced.count(f))
    {
      return;
    }
    if (traced.size() >= budget)
    {
      result.TracingStopped = true;
      return;
    }
    traced.insert(f);
    pending.emplace_back(f, at);
  };
  // The seams of a junction: every triple of the features it touches.
  auto queueJunction = [&](const ExactPoint& p) {
    const auto& g = p.Features;
    const BallVector at{ p.Centre[0], p.Centre[1], p.Centre[2], p.Radius };
    for (size_t i = 0; i < g.size() && g.size() <= 8; ++i)
      for (size_t j = i + 1; j < g.size(); ++j)
        for (size_t k = j + 1; k < g.size(); ++k)
        {
          queue({ { g[i], g[j], g[k], -1 } }, at);
        }
  };
  for (const Candidate& c : candidates.Triples)
  {
    for (const ExactPoint& p : c.Found)
    {
      queue(c.Features, { p.Centre[0], p.Centre[1], p.Centre[2], p.Radius });
    }
  }
  for (const auto& entry : quadruples)
  {
    for (const ExactPoint& p : entry.second.Found)
    {
      queueJunction(p);
    }
  }
  while (!pending.empty())
  {
    const std::vector<Tagged> current = std::move(pending);
    pending.clear();
    std::vector<TraceEnds> ends(current.size());
    const vtkIdType n = static_cast<vtkIdType>(current.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (vtkIdType i = 0; i < n; ++i)
    {
      this->TraceSeam(current[i].first.data(), current[i].second, ends[i]);
    }
    if (aborted && aborted())
    {
      return false;
    }
    // Junction candidates met at the ends, solved now so their seams join the next wave.
    std::vector<std::array<int, 4>> fresh;
    for (const TraceEnds& e : ends)
    {
      for (const Tagged& q : e.Quadruples)
      {
        const bool known = quadruples.count(q.first) > 0;
        this->AddQuadruple(candidates, q.first, q.second, -1);
        if (!known && quadruples.count(q.first))
        {
          fresh.push_back(q.first);
        }
      }
    }
    std::vector<Candidate> solving;
    for (const auto& f : fresh)
    {
      solving.push_back(quadruples[f]);
    }
    bool stopped = false;
    this->SolveCandidates(solving, threads, aborted, stopped);
    if (stopped)
    {
      return false;
    }
    for (Candidate& c : solving)
    {
      for (const ExactPoint& p : c.Found)
      {
        queueJunction(p);
      }
      quadruples[c.Features] = std::move(c);
    }
    for (const TraceEnds& e : ends)
    {
      for (const Tagged& t : e.Triples)
      {
        queue(t.first, t.second);
      }
    }
  }
  result.TracedSeams = static_cast<vtkIdType>(traced.size());
  return true;
}
