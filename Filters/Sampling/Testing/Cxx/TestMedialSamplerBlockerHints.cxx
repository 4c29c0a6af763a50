// SPDX-License-Identifier: BSD-3-Clause
// The one-pass search's hints (a nearby ball's contact triangle and blockers) change
// its speed, never its ball. Each sample's ball is searched cold (no hints), then
// again with the hints of other samples: the next sample's (as the sampler hints),
// and those of the samples with the smallest and the largest balls, whose blockers
// lie far from this ball's answer (above it or below it). Every hinted ball must be
// the cold one within 1e-9 of the diagonal (in practice the 1e-12 slack). On the
// jack (thin arms on a thick hub: neighbouring radii differ by far more than any
// guessed factor) and a torus, at theta = 45 (the angle rule, under which emptiness
// is not monotone in the radius, so a search started below the bound at a
// neighbour's radius can miss the answer) and at theta = 0. The test also checks
// that many hints come from balls far smaller than the answer.
#include "MedialTestUtilities.h"

#include "vtkMedialBallSolver.h"
#include "vtkMedialGeometry.h"
#include "vtkMedialRandom.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialSurfaceQuery.h"
#include "vtkMedialTriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using namespace medialtest;

namespace
{
using Chain = vtkMedialTriangleBVH::BlockerChain;

int Check(vtkPolyData* surface, const char* label, double theta)
{
  vtkMedialTriangleMesh mesh;
  vtkMedialSurfaceQuery query;
  std::string error;
  MEDIAL_CHECK(mesh.Build(surface, error) && query.Build(&mesh, error), "%s: %s", label, error.c_str());
  const vtkMedialBallParameters param =
    vtkMedialMakeBallParameters(vtkMedialBallParameters::ONE_PASS, 1e-6, theta, 1e-4, 100, mesh.Diagonal);
  constexpr vtkIdType samples = 600;
  std::vector<vtkIdType> triangles(samples);
  std::vector<double> points(3 * samples);
  std::vector<vtkMedialSampleRecord> cold(samples);
  std::vector<Chain> chains(samples);
  vtkIdType smallest = 0, largest = 0;
  for (vtkIdType i = 0; i < samples; ++i)
  {
    vtkMedialDrawSurfacePoint(mesh, 3, i, triangles[i], &points[3 * i]);
    vtkMedialSolveBall(query, mesh, param, triangles[i], &points[3 * i], cold[i], -1, &chains[i]);
    MEDIAL_CHECK(cold[i].Valid, "%s: sample %lld has no ball", label, static_cast<long long>(i));
    smallest = cold[i].Radius < cold[smallest].Radius ? i : smallest;
    largest = cold[i].Radius > cold[largest].Radius ? i : largest;
  }
  double worst = 0.0;
  vtkIdType below = 0, hinted = 0;
  for (vtkIdType i = 0; i < samples; ++i)
  {
    for (vtkIdType j : { (i + 1) % samples, smallest, largest })
    {
      Chain blockers = chains[j];
      vtkMedialSampleRecord ball;
      vtkMedialSolveBall(query, mesh, param, triangles[i], &points[3 * i], ball, cold[j].ContactTriangle, &blockers);
      const double dc = std::sqrt(vtkMedialGeometry::Distance2(ball.Centre, cold[i].Centre));
      worst = std::max({ worst, std::fabs(ball.Radius - cold[i].Radius) / mesh.Diagonal, dc / mesh.Diagonal });
      below += 1.05 * cold[j].Radius < cold[i].Radius;
      ++hinted;
    }
  }
  std::printf("%s, theta %g: %lld hinted searches (%lld hinted by a ball over 5%% smaller); "
              "worst change of radius or centre %.2e of the diagonal\n",
    label, theta, static_cast<long long>(hinted), static_cast<long long>(below), worst);
  MEDIAL_CHECK(worst <= 1e-9, "%s theta %g: a hint changed a ball by %g of the diagonal", label, theta, worst);
  MEDIAL_CHECK(below >= samples / 2, "%s: too few hints from smaller balls (%lld)", label, static_cast<long long>(below));
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerBlockerHints(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->Update();
  vtkNew<vtkMedialShapeSource> torus;
  torus->SetShapeToTorus();
  torus->Update();
  for (double theta : { 45.0, 0.0 })
  {
    if (Check(jack->GetOutput(), "jack", theta) != EXIT_SUCCESS ||
      Check(torus->GetOutput(), "torus", theta) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
