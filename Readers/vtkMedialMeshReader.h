// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialMeshReader
 * @brief Reads a medial mesh in the .ma text format (Q-MAT, MATFP, Coverage Axis).
 *
 * Format, one record per line, 0-based indices:
 * @code
 * nv ne nf          header: numbers of vertices, edges and faces
 * v x y z r         nv vertex records: medial ball centre and radius
 * e i j             ne edge records
 * f i j k           nf face (triangle) records
 * @endcode
 * Records appear in that order. Extra columns on `v` lines (some tools append
 * them) are ignored; `e` and `f` lines must have exactly their indices. Blank
 * lines and `#` comments are skipped.
 *
 * Output: vtkPolyData with double-precision points, a point-data array `Radius`
 * (double, also the active scalars), one line cell per edge and one triangle
 * per face, in file order.
 *
 * Bad input (missing or empty file, truncated file, counts that disagree with
 * the records, non-numeric tokens, NaN or infinite values, negative radius,
 * index out of range) gives one error naming the file and line, and an empty
 * output. Header counts are not trusted for allocation: storage grows with the
 * records actually read.
 *
 * @sa vtkMedialMeshWriter vtkMedialOFFReader vtkMedialFileReader
 */
#ifndef vtkMedialMeshReader_h
#define vtkMedialMeshReader_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkAbstractPolyDataReader.h"

class VTKMEDIALAXISREADERS_EXPORT vtkMedialMeshReader : public vtkAbstractPolyDataReader
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialMeshReader* New();
  vtkTypeMacro(vtkMedialMeshReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// 1 when the file opens and starts with a valid header 'nv ne nf'; 0 otherwise.
  static int CanReadFile(const char* fileName);

protected:
  vtkMedialMeshReader() = default;
  ~vtkMedialMeshReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMedialMeshReader(const vtkMedialMeshReader&) = delete;
  void operator=(const vtkMedialMeshReader&) = delete;
};

#endif
