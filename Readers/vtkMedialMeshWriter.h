// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshWriter
 * @brief Writes polydata with a `Radius` point array as a .ma medial mesh.
 *
 * Writes the clean form that Q-MAT (and vtkMedialMeshReader) reads: the header
 * `nv ne nf`, one `v x y z r` record per point, then `e i j` and `f i j k` records,
 * 0-based, no comment lines. Edges come from lines (a polyline of n points gives its
 * n - 1 segments), faces from triangles, triangulated polygons and split strips (see
 * vtkMedialBallWriter for what is checked and skipped). The edge list holds every
 * edge once: the line segments in order, then each triangle side not written yet
 * (sides a-b, b-c, c-a), so that it contains every side of every face as Q-MAT
 * expects; edges of one point (i i) are skipped. Numbers are written with
 * max_digits10 significant digits, independent of the locale, so that reading the
 * file back gives the same doubles bit for bit.
 *
 * Input: vtkPolyData with a one-component point-data array named `Radius`.
 * Missing or multi-component `Radius`, a negative, NaN or infinite radius or
 * coordinate, or a cell referring to a missing point is an error and no file is
 * written. Write() returns 0 and GetErrorCode() is set on failure.
 *
 * @sa vtkMedialMeshReader vtkMedialBallWriter
 */
#ifndef vtkMedialMeshWriter_h
#define vtkMedialMeshWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkMedialBallWriter.h"

class VTKMEDIALAXISREADERS_EXPORT vtkMedialMeshWriter : public vtkMedialBallWriter
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialMeshWriter* New();
  vtkTypeMacro(vtkMedialMeshWriter, vtkMedialBallWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

protected:
  vtkMedialMeshWriter() = default;
  ~vtkMedialMeshWriter() override = default;

  void WriteRecords(std::ostream& file, const medialballs::BallRecords& records) override;
  const char* GetDescription() const override { return "medial mesh"; }

private:
  vtkMedialMeshWriter(const vtkMedialMeshWriter&) = delete;
  void operator=(const vtkMedialMeshWriter&) = delete;
};

#endif
