// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialOFFReader
 * @brief Reads a polygon surface in the Object File Format (OFF), text form.
 *
 * Format (Geomview), one record per line:
 * @code
 * OFF               header keyword; the counts may follow on the same line
 * nv nf ne          counts; ne (edges) is ignored and may be omitted
 * x y z [...]       nv vertex records
 * n i0 ... i(n-1) [colour]   nf face records, 0-based indices, n >= 3
 * @endcode
 * Accepted variants: `OFF`, `COFF` (vertex colour), `NOFF` (vertex normal) and
 * `CNOFF`. Their extra vertex columns, and any further numeric columns on a
 * vertex or face line (alpha, texture coordinates, face colour), must be numbers
 * and are ignored. A file without the keyword, starting with the counts, is
 * read as plain OFF. Blank lines and `#` comments are skipped. Other variants
 * (4OFF, nOFF, STOFF, `OFF BINARY`, ...) are reported as unsupported. Records
 * must not span lines (every common writer puts one per line).
 *
 * Output: vtkPolyData with double-precision points and one polygon cell per
 * face (triangles, quads and larger polygons as they are; nothing is
 * triangulated).
 *
 * Bad input (missing or empty file, truncated file, counts that disagree with
 * the records, non-numeric tokens, NaN or infinite coordinates, index out of
 * range, faces with fewer than three vertices) gives one error naming the file
 * and line, and an empty output. Header counts are not trusted for allocation.
 *
 * @sa vtkMedialMeshReader
 */
#ifndef vtkMedialOFFReader_h
#define vtkMedialOFFReader_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkAbstractPolyDataReader.h"

class VTKMEDIALAXISREADERS_EXPORT vtkMedialOFFReader : public vtkAbstractPolyDataReader
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialOFFReader* New();
  vtkTypeMacro(vtkMedialOFFReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// 1 when the file opens and starts with a valid OFF header (keyword and counts); 0 otherwise.
  static int CanReadFile(const char* fileName);

protected:
  vtkMedialOFFReader() = default;
  ~vtkMedialOFFReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMedialOFFReader(const vtkMedialOFFReader&) = delete;
  void operator=(const vtkMedialOFFReader&) = delete;
};

#endif
