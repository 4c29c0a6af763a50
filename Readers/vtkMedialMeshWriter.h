// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshWriter
 * @brief Writes polydata with a `Radius` point array as a .ma medial mesh.
 *
 * Writes the clean form that Q-MAT (and vtkMedialMeshReader) reads: the header
 * `nv ne nf`, one `v x y z r` record per point, then `e i j` and `f i j k` records,
 * 0-based, no comment lines.
 *  - Lines become edges; a polyline of n points gives its n - 1 segments.
 *  - Triangles become faces; triangle strips are split into their triangles
 *    and polygons are triangulated (ear cutting, with a fan when that fails).
 *  - The edge list holds every edge once: the line segments in order, then each
 *    triangle side not written yet (sides a-b, b-c, c-a), so that it contains every
 *    side of every face as Q-MAT expects. Edges of one point (i i) are skipped.
 *  - Vertex cells are not written (every point is written anyway). Lines of one
 *    point and polygons of fewer than three points are skipped with a warning.
 * Numbers are written with max_digits10 significant digits, independent of the
 * locale, so that reading the file back gives the same doubles bit for bit.
 *
 * Input: vtkPolyData with a one-component point-data array named `Radius`.
 * Missing or multi-component `Radius`, a negative, NaN or infinite radius or
 * coordinate, or a cell referring to a missing point is an error and no file is
 * written. Write() returns 0 and GetErrorCode() is set on failure.
 *
 * @sa vtkMedialMeshReader
 */
#ifndef vtkMedialMeshWriter_h
#define vtkMedialMeshWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkWriter.h"

class vtkPolyData;

class VTKMEDIALAXISREADERS_EXPORT vtkMedialMeshWriter : public vtkWriter
{
public:
  static vtkMedialMeshWriter* New();
  vtkTypeMacro(vtkMedialMeshWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .ma file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// The input polydata.
  vtkPolyData* GetInput();

protected:
  vtkMedialMeshWriter();
  ~vtkMedialMeshWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;

private:
  vtkMedialMeshWriter(const vtkMedialMeshWriter&) = delete;
  void operator=(const vtkMedialMeshWriter&) = delete;
};

#endif
