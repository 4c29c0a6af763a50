// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialAxisSamplerInternals.h
 * @brief Internal: the passes of vtkMedialAxisSampler::RequestData, kept out of the
 * installed header because they name the internal engines (vtkMedialTriangleMesh,
 * vtkMedialSurfaceQuery, vtkMedialSampleRecord, vtkMedialBallParameters). Not installed.
 *
 * A nested class of the filter, so that it sets the filter's figures
 * (DiscardedSamples, ...) directly. 3D passes in vtkMedialAxisSampler.cxx, the 2D
 * mode in vtkMedialAxisSampler2D.cxx.
 */
#ifndef vtkMedialAxisSamplerInternals_h
#define vtkMedialAxisSamplerInternals_h

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallSolver.h"
#include "vtkMedialBuffer.h"
#include "vtkMedialSampleRecord.h"
#include "vtkMedialSurfaceNormals.h"

#include "vtkFieldData.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <new>
#include <vector>

class vtkMedialCoverage;
class vtkMedialPieces;
class vtkMedialStages;
struct vtkMedialIterativeResult;
struct vtkMedialIterativeSettings;
class vtkMedialSurfaceQuery;
class vtkMedialTriangleMesh;

class vtkMedialAxisSampler::vtkInternals
{
public:
  explicit vtkInternals(vtkMedialAxisSampler* self)
    : Self(self)
  {
  }

  /// The repair's report (field data) when PrepareSurface sampled a repaired surface.
  vtkSmartPointer<vtkFieldData> RepairReport;

  /// The 3D surface: mesh preparation (with its warnings) and the queries. False
  /// when RequestData must return `status` (0 on error, 1 when aborted).
  bool PrepareSurface(vtkPolyData* input, vtkMedialTriangleMesh& mesh, vtkMedialSurfaceQuery& query, int& status,
    vtkMedialStages& stages);
  /// RANDOM: this piece's share of the samples, drawn, sorted by BVH leaf, solved in
  /// blocks; with a coverage stop (RequestData runs it in piece 0 only) all of them.
  int SampleRandom(vtkMedialTriangleMesh& mesh, vtkMedialSurfaceQuery& query,
    const vtkMedialPieces& pieces, vtkPolyData* output, vtkMedialStages& stages);
  /// CLOSEST_NEIGHBOR and FACE_DISTANCE (vtkMedialIterativeSampling); RequestData runs
  /// them in piece 0 only.
  int SampleIterative(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, vtkPolyData* output);
  /// The 2D mode, for planar polygons or closed polylines (vtkMedialAxisSampler2D.cxx).
  int Sample2D(vtkPolyData* input, const vtkMedialPieces& pieces, vtkPolyData* output, vtkMedialStages& stages);

  /// Refuses up front what cannot fit in this machine's memory: `count` samples of
  /// about `bytesPerSample` each. `advice` ends the error message.
  bool CheckMemory(vtkIdType count, double bytesPerSample, const char* advice) const;
  /// Resizes every vector to `count` elements; false, with an error, when that fails.
  template <class... Vectors>
  bool Allocate(vtkIdType count, Vectors&... vectors) const
  {
    try
    {
      (vectors.resize(static_cast<size_t>(count)), ...);
    }
    catch (const std::bad_alloc&)
    {
      this->ReportAllocationFailure(count);
      return false;
    }
    return true;
  }
  /// Turns the valid records into output vertices, point data and field data, and
  /// sets DiscardedSamples, CappedSamples and MeanIterations. Shared by 2D and 3D.
  void WriteSamples(vtkPolyData* output, vtkIdType requested, const vtkMedialSampleRecord* records, vtkIdType count);

private:
  // Each sample's triangle, 32-bit (the tree holds fewer than 2^31 triangles): 4 MB
  // less at 1 M samples, beside the records at the run's peak.
  using SampleTriangles = std::vector<std::int32_t>;
  // Bisection / shrinking-ball settings in absolute units.
  vtkMedialBallParameters MakeBallParameters(double diagonal) const;
  // The samples a piece solves and their order (see SampleRandom): `index` gets the
  // piece's sample indices in increasing order, `order` positions in `index` in leaf
  // order, `triangles` the triangle each one picked; `index` is left empty when it would
  // be 0, 1, 2, ... (one piece, or a coverage stop). With a coverage stop, all
  // samples, ordered by leaf within blocks once drawn.
  void SelectSamples(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query,
    const vtkMedialPieces& pieces, bool coverage, int threads, std::vector<vtkIdType>& index,
    std::vector<vtkIdType>& order, SampleTriangles& triangles) const;
  // What the RANDOM strategy's sample points need of the mesh: the id order of the
  // corners of triangles[i] (each sample's pick, from SelectSamples) into idOrders[i]
  // (vtkMedialCornerIdOrder); SolveBlocks draws the points from the tree's corners.
  void DrawSamples(const vtkMedialTriangleMesh& mesh, int threads, const SampleTriangles& triangles,
    std::vector<std::uint8_t>& idOrders) const;
  // Order of items by BVH leaf of their triangle (within blocks of `block` items when a
  // coverage stop needs prefixes, else a global, stable counting sort).
  static void SortByLeaf(const vtkMedialSurfaceQuery& query, const SampleTriangles& triangles,
    vtkIdType block, std::vector<vtkIdType>& order);
  // Solves the samples in hint chains: with `coverage`, block by block, stopping after
  // the first block that reaches it; without, in one loop (`block` unused). Returns the
  // samples used (a prefix). Sample i is sample index[i] of the stream (i when `index`
  // is empty), its point drawn on triangles[i] (vtkMedialDrawSurfacePointOnCorners).
  vtkIdType SolveBlocks(const vtkMedialTriangleMesh& mesh, const vtkMedialSurfaceQuery& query, int threads,
    vtkIdType block, const std::vector<vtkIdType>& index, const SampleTriangles& triangles,
    const std::vector<std::uint8_t>& idOrders, const std::vector<vtkIdType>& order,
    vtkMedialBuffer<vtkMedialSampleRecord>& results, vtkMedialCoverage* coverage);
  // Warns about samples discarded on an open or folded surface, or where shells touch.
  void WarnDiscarded(const vtkMedialTriangleMesh& mesh, vtkIdType count) const;
  // Warns when FACE_DISTANCE gave up faces and stopped short of the budget and the coverage.
  void WarnStoppedEarly(const vtkMedialTriangleMesh& mesh, const vtkMedialIterativeSettings& settings,
    const vtkMedialIterativeResult& result) const;
  // Adds a one-value field-data array.
  static void AddField(vtkPolyData* output, const char* name, double value);
  // CoverageReached and MaxCoverageGap.
  void WriteCoverage(vtkPolyData* output) const;
  // CLOSEST_NEIGHBOR's links as line cells, with their InitialLink.
  static void WriteLinks(vtkPolyData* output, const std::vector<vtkMedialSampleRecord>& records,
    const std::vector<vtkIdType>& linkEnds, const std::vector<vtkIdType>& initialLink);
  void ReportAllocationFailure(vtkIdType count) const;

  vtkMedialAxisSampler* Self;
  // The smooth surface's normals, built by PrepareSurface when theta > 0.
  vtkMedialSurfaceNormals Normals;
};

#endif
