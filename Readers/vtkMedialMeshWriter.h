// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshWriter
 * @brief Writes polydata with a `Radius` point array as a .ma medial mesh.
 *
 * Writes the format vtkMedialMeshReader reads: the header `nv ne nf`, one
 * `v x y z r` record per point, then `e i j` and `f i j k` records (edges from
 * lines, faces from triangulated polygons and strips; see vtkMedialBallWriter for
 * what is checked and skipped). Numbers are written with max_digits10 significant
 * digits, independent of the locale, so that reading the file back gives the same
 * doubles bit for bit.
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
  static vtkMedialMeshWriter* New();
  vtkTypeMacro(vtkMedialMeshWriter, vtkMedialBallWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
