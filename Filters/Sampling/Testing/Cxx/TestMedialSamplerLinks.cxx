// SPDX-License-Identifier: BSD-3-Clause
// ClosestNeighbor links, checked by brute force on the output:
//  - the seeds are the first SeedSamples points; the line cells come grouped by
//    InitialLink, each group a path from one seed P to another seed Q;
//  - replaying the initial links in order: Q had no link yet, the balls of P and Q
//    do not overlap, and no other seed without a link that does not overlap P is
//    closer to P; a chain continues from the previous Q, and a new chain starts only
//    when the previous Q had no candidate left, at the first seed without a link;
//  - the split points each lie on exactly two lines of the same group, and with the
//    budget not used up, every final link joins overlapping balls;
//  - the closing rounds' samples come last, on no line.
#include "MedialStrategyTestUtilities.h"

#include "vtkIdTypeArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <cstdlib>
#include <map>

using namespace medialtest;

namespace
{
struct Ball
{
  double C[3];
  double R;
};
double Dist(const Ball& a, const Ball& b)
{
  return std::sqrt((a.C[0] - b.C[0]) * (a.C[0] - b.C[0]) + (a.C[1] - b.C[1]) * (a.C[1] - b.C[1]) +
    (a.C[2] - b.C[2]) * (a.C[2] - b.C[2]));
}
bool Overlap(const Ball& a, const Ball& b)
{
  return Dist(a, b) <= a.R + b.R;
}
}

int TestMedialSamplerLinks(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(20000);
  sampler->SetSeedFraction(0.05); // 1000 seeds; the links run out before the budget
  sampler->SetSamplingStrategyToClosestNeighbor();
  sampler->Update();
  vtkPolyData* out = sampler->GetOutput();
  const vtkIdType n = out->GetNumberOfPoints();
  const vtkIdType seeds = static_cast<vtkIdType>(FieldValue(out, "SeedSamples"));
  std::printf("%lld points, %lld seeds, %lld lines, %lld evaluated\n", static_cast<long long>(n),
    static_cast<long long>(seeds), static_cast<long long>(out->GetNumberOfLines()),
    static_cast<long long>(sampler->GetEvaluatedSamples()));
  MEDIAL_CHECK(seeds > 100 && seeds < n, "seeds %lld of %lld points", static_cast<long long>(seeds),
    static_cast<long long>(n));
  MEDIAL_CHECK(out->GetNumberOfLines() > seeds / 2, "only %lld lines", static_cast<long long>(out->GetNumberOfLines()));
  MEDIAL_CHECK(sampler->GetEvaluatedSamples() < 20000, "the budget ran out: the split stop is not tested");
  std::vector<Ball> balls(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    out->GetPoint(i, balls[i].C);
    balls[i].R = Value(out, "Radius", i);
  }

  // Paths per initial link.
  vtkIdTypeArray* initial = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("InitialLink"));
  MEDIAL_CHECK(initial && initial->GetNumberOfTuples() == out->GetNumberOfCells(), "no InitialLink cell array");
  const vtkIdType verts = out->GetNumberOfVerts();
  std::vector<std::pair<vtkIdType, vtkIdType>> links; // (P, Q) per initial link, in order
  std::vector<int> uses(static_cast<size_t>(n), 0);
  std::vector<vtkIdType> group(static_cast<size_t>(n), -1);
  vtkIdType npts;
  const vtkIdType* ids;
  vtkIdType line = 0, previousEnd = -1, overlapping = 0;
  vtkCellArray* lines = out->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(npts, ids); ++line)
  {
    MEDIAL_CHECK(npts == 2, "line %lld has %lld points", static_cast<long long>(line), static_cast<long long>(npts));
    const vtkIdType link = initial->GetValue(verts + line);
    if (link == static_cast<vtkIdType>(links.size()))
    {
      MEDIAL_CHECK(ids[0] < seeds, "initial link %lld starts at a non-seed", static_cast<long long>(link));
      links.emplace_back(ids[0], -1);
    }
    else
    {
      MEDIAL_CHECK(link == static_cast<vtkIdType>(links.size()) - 1 && ids[0] == previousEnd,
        "line %lld does not continue the path of link %lld", static_cast<long long>(line),
        static_cast<long long>(link));
    }
    links.back().second = ids[1];
    previousEnd = ids[1];
    for (int k = 0; k < 2; ++k)
    {
      if (ids[k] >= seeds)
      {
        ++uses[ids[k]];
        MEDIAL_CHECK(group[ids[k]] < 0 || group[ids[k]] == link, "split point in two links");
        group[ids[k]] = link;
      }
    }
    overlapping += Overlap(balls[ids[0]], balls[ids[1]]) ? 1 : 0;
  }
  // The closing rounds' samples (face-distance, after the links ran out) come last, on
  // no line, a sixteenth of the samples before them at most.
  vtkIdType closing = n;
  while (closing > seeds && uses[closing - 1] == 0)
  {
    --closing;
  }
  MEDIAL_CHECK(n > closing && n - closing <= closing / 16, "%lld closing samples after %lld",
    static_cast<long long>(n - closing), static_cast<long long>(closing));
  for (vtkIdType i = seeds; i < closing; ++i)
  {
    MEDIAL_CHECK(uses[i] == 2, "split point %lld is on %d lines", static_cast<long long>(i), uses[i]);
  }
  std::printf("%zu initial links; %lld of %lld final links join overlapping balls\n", links.size(),
    static_cast<long long>(overlapping), static_cast<long long>(line));
  MEDIAL_CHECK(overlapping == line, "%lld final links join balls that do not overlap",
    static_cast<long long>(line - overlapping));

  // Replay of step 1 on the seeds.
  std::vector<char> linked(static_cast<size_t>(seeds), 0), done(static_cast<size_t>(seeds), 0);
  auto candidate = [&](vtkIdType p) {
    vtkIdType best = -1;
    for (vtkIdType q = 0; q < seeds; ++q)
    {
      if (q != p && !linked[q] && !Overlap(balls[p], balls[q]) && (best < 0 || Dist(balls[p], balls[q]) < Dist(balls[p], balls[best])))
      {
        best = q;
      }
    }
    return best;
  };
  vtkIdType current = -1;
  for (size_t k = 0; k < links.size(); ++k)
  {
    const vtkIdType p = links[k].first, q = links[k].second;
    MEDIAL_CHECK(q < seeds && q != p, "link %zu does not end at another seed", k);
    if (p != current)
    {
      MEDIAL_CHECK(current < 0 || candidate(current) < 0, "chain ended at %lld with a candidate left",
        static_cast<long long>(current));
      if (current >= 0)
      {
        done[current] = 1;
      }
      vtkIdType first = 0;
      while (first < seeds && (linked[first] || done[first]))
      {
        ++first;
      }
      // Seeds skipped as chain starts had no candidate at all.
      while (first < p)
      {
        MEDIAL_CHECK(candidate(first) < 0, "seed %lld was skipped as a chain start", static_cast<long long>(first));
        done[first] = 1;
        while (first < seeds && (linked[first] || done[first]))
        {
          ++first;
        }
      }
      MEDIAL_CHECK(first == p, "link %zu starts at %lld, expected %lld", k, static_cast<long long>(p),
        static_cast<long long>(first));
    }
    done[p] = 1;
    MEDIAL_CHECK(!linked[q], "link %zu ends at seed %lld, which already had a link", k, static_cast<long long>(q));
    MEDIAL_CHECK(!Overlap(balls[p], balls[q]), "link %zu joins overlapping balls", k);
    const vtkIdType best = candidate(p);
    MEDIAL_CHECK(Dist(balls[p], balls[q]) <= Dist(balls[p], balls[best]), "link %zu: seed %lld is closer than %lld", k,
      static_cast<long long>(best), static_cast<long long>(q));
    linked[p] = linked[q] = 1;
    current = q;
  }
  MEDIAL_CHECK(current < 0 || candidate(current) < 0, "the last chain ended with a candidate left");
  return EXIT_SUCCESS;
}
