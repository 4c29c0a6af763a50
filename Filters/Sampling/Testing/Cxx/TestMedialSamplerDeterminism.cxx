// SPDX-License-Identifier: BSD-3-Clause
// The same seed gives bit-identical output with 1 and 2 threads, and a mesh with
// every triangle's winding reversed (all normals flipped), or with every other
// triangle reversed (mixed orientation), gives the same output. Also with 140,001
// samples, whose hint chains are longer (128 samples).
#include "MedialTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkReverseSense.h"

#include <cstdlib>

using namespace medialtest;

int TestMedialSamplerDeterminism(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(12);
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputConnection(jack->GetOutputPort());
  reverse->ReverseCellsOn();
  reverse->ReverseNormalsOn();

  // Mixed orientation: every other triangle's winding reversed.
  jack->Update();
  vtkNew<vtkPolyData> mixed;
  mixed->SetPoints(jack->GetOutput()->GetPoints());
  vtkNew<vtkCellArray> mixedCells;
  for (vtkIdType c = 0; c < jack->GetOutput()->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* pts;
    jack->GetOutput()->GetCellPoints(c, n, pts);
    const vtkIdType reversed[3] = { pts[2], pts[1], pts[0] };
    mixedCells->InsertNextCell(3, c % 2 ? reversed : pts);
  }
  mixed->SetPolys(mixedCells);

  for (int method : { vtkMedialAxisSampler::BISECTION, vtkMedialAxisSampler::SHRINKING_BALL, vtkMedialAxisSampler::ONE_PASS })
  {
    vtkNew<vtkMedialAxisSampler> one, two, flipped, mixedSampler;
    mixedSampler->SetNumberOfSamples(4000);
    mixedSampler->SetRandomSeed(99);
    mixedSampler->SetMethod(method);
    mixedSampler->SetInputData(mixed);
    mixedSampler->Update();
    for (vtkMedialAxisSampler* s : { one.Get(), two.Get(), flipped.Get() })
    {
      s->SetNumberOfSamples(4000);
      s->SetRandomSeed(99);
      s->SetMethod(method);
      s->SetInputConnection(jack->GetOutputPort());
    }
    one->SetNumberOfThreads(1);
    two->SetNumberOfThreads(2);
    flipped->SetNumberOfThreads(2);
    flipped->SetInputConnection(reverse->GetOutputPort());
    one->Update();
    two->Update();
    flipped->Update();
    const char* m = vtkMedialAxisSampler::GetMethodName(method);
    MEDIAL_CHECK(one->GetOutput()->GetNumberOfPoints() > 3900, "%s: only %lld points", m,
      static_cast<long long>(one->GetOutput()->GetNumberOfPoints()));
    const long long threads = BitDifferences(one->GetOutput(), two->GetOutput());
    const long long flips = BitDifferences(one->GetOutput(), flipped->GetOutput());
    std::printf("%s: values differing 1 vs 2 threads: %lld; original vs flipped: %lld\n", m, threads, flips);
    MEDIAL_CHECK(threads == 0, "%s: thread count changed %lld values", m, threads);
    MEDIAL_CHECK(flips == 0, "%s: flipping the winding changed %lld values", m, flips);
    const long long mixes = BitDifferences(one->GetOutput(), mixedSampler->GetOutput());
    std::printf("%s: original vs mixed orientation: %lld\n", m, mixes);
    MEDIAL_CHECK(mixes == 0, "%s: mixed orientation changed %lld values", m, mixes);

    // A different seed must give a different sample set (the seed is honoured).
    one->SetRandomSeed(100);
    one->Update();
    MEDIAL_CHECK(BitDifferences(one->GetOutput(), two->GetOutput()) != 0, "%s: seed ignored", m);
  }

  vtkNew<vtkMedialAxisSampler> one, two;
  for (vtkMedialAxisSampler* s : { one.Get(), two.Get() })
  {
    s->SetNumberOfSamples(140001);
    s->SetInputConnection(jack->GetOutputPort());
  }
  one->SetNumberOfThreads(1);
  two->SetNumberOfThreads(2);
  one->Update();
  two->Update();
  const long long threads = BitDifferences(one->GetOutput(), two->GetOutput());
  std::printf("one-pass, 140001 samples: values differing 1 vs 2 threads: %lld\n", threads);
  MEDIAL_CHECK(one->GetOutput()->GetNumberOfPoints() > 139000, "long chains: only %lld points",
    static_cast<long long>(one->GetOutput()->GetNumberOfPoints()));
  MEDIAL_CHECK(threads == 0, "long chains: thread count changed %lld values", threads);
  return EXIT_SUCCESS;
}
