// SPDX-License-Identifier: BSD-3-Clause
// Pieces (as ParaView and pvbatch ask for them, one per MPI rank): the R pieces of a
// RANDOM run, put together, are the one-piece balls bit for bit, for R = 2, 3 and 7,
// in 3D (3001 samples, and 140,001, whose hint chains are longer) and 2D. The
// iterative strategies and a coverage stop are sequential: piece 0 of R is the
// one-piece run and the other pieces are empty.
#include "MedialPieceTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"

#include <array>
#include <cstdlib>
#include <cstring>

using namespace medialtest;

namespace
{
using Row = std::array<double, 12>;

// One row per ball: centre, Radius, SurfacePoint, ContactPoint, SeparationAngle, SourceCellId.
void AppendRows(vtkPolyData* balls, std::vector<Row>& rows)
{
  for (vtkIdType i = 0; i < balls->GetNumberOfPoints(); ++i)
  {
    Row row;
    balls->GetPoint(i, row.data());
    row[3] = Value(balls, "Radius", i);
    for (int c = 0; c < 3; ++c)
    {
      row[4 + c] = Value(balls, "SurfacePoint", i, c);
      row[7 + c] = Value(balls, "ContactPoint", i, c);
    }
    row[10] = Value(balls, "SeparationAngle", i);
    row[11] = Value(balls, "SourceCellId", i);
    rows.push_back(row);
  }
}

// Balls of pieces 0..pieces-1, sorted; `sizes` gets each piece's ball count.
std::vector<Row> PieceRows(vtkMedialAxisSampler* sampler, int pieces, std::vector<vtkIdType>& sizes)
{
  std::vector<Row> rows;
  sizes.clear();
  for (int p = 0; p < pieces; ++p)
  {
    sampler->UpdatePiece(p, pieces, 0);
    sizes.push_back(sampler->GetOutput()->GetNumberOfPoints());
    AppendRows(sampler->GetOutput(), rows);
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

long long DifferentRows(const std::vector<Row>& a, const std::vector<Row>& b)
{
  if (a.size() != b.size())
  {
    return -1;
  }
  long long differ = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    differ += std::memcmp(a[i].data(), b[i].data(), sizeof(Row)) != 0;
  }
  return differ;
}

// Split runs: every piece count gives the one-piece set of balls, split about evenly.
int CheckSplit(vtkMedialAxisSampler* sampler, const char* what, vtkIdType minimum)
{
  std::vector<vtkIdType> sizes;
  const std::vector<Row> whole = PieceRows(sampler, 1, sizes);
  MEDIAL_CHECK(static_cast<vtkIdType>(whole.size()) >= minimum, "%s: only %zu balls", what, whole.size());
  for (int pieces : { 2, 3, 7 })
  {
    const std::vector<Row> parts = PieceRows(sampler, pieces, sizes);
    const long long differ = DifferentRows(whole, parts);
    std::printf("%s: %d pieces, %zu balls, rows differing from one piece: %lld, smallest piece %lld\n",
      what, pieces, parts.size(), differ, static_cast<long long>(*std::min_element(sizes.begin(), sizes.end())));
    MEDIAL_CHECK(differ == 0, "%s: %d pieces differ from one piece in %lld rows", what, pieces, differ);
    MEDIAL_CHECK(*std::min_element(sizes.begin(), sizes.end()) * pieces >= minimum / 2,
      "%s: the work is not split (%d pieces)", what, pieces);
  }
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerPieces(int, char*[])
{
  vtkNew<vtkMedialShapeSource> jack;
  jack->SetResolution(10);
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputConnection(jack->GetOutputPort());
  sampler->SetNumberOfSamples(3001); // not a multiple of the pieces or of the hint chains
  sampler->SetNumberOfThreads(2);
  if (CheckSplit(sampler, "3D one-pass", 3000) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  // Large runs use longer hint chains (128 samples at this count): the pieces still cut
  // the leaf order at whole chains.
  sampler->SetNumberOfSamples(140001);
  if (CheckSplit(sampler, "3D one-pass, long chains", 140000) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  sampler->SetMethodToBisection();
  sampler->SetNumberOfSamples(500);
  if (CheckSplit(sampler, "3D bisection", 500) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  vtkNew<vtkMedialShapeSource> frame;
  frame->SetShapeToSquareFrame();
  vtkNew<vtkMedialAxisSampler> planar;
  planar->SetInputConnection(frame->GetOutputPort());
  planar->SetNumberOfSamples(997);
  if (CheckSplit(planar, "2D", 997) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }

  sampler->SetMethodToOnePass();
  sampler->SetNumberOfSamples(1500);
  sampler->SetSamplingStrategyToFaceDistance();
  auto bitExact = [](vtkPolyData* a, vtkPolyData* b) { return BitDifferences(a, b) == 0; };
  if (CheckFirstPieceOnly(sampler, "face-distance", bitExact) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  sampler->SetSamplingStrategyToRandom();
  sampler->SetCoverageTolerance(0.05);
  if (CheckFirstPieceOnly(sampler, "random with a coverage stop", bitExact) != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
