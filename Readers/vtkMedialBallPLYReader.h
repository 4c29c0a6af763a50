// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallPLYReader
 * @brief Reads medial balls from a PLY file whose vertices have a `radius`
 * property (as CGAL- and MATTopo-style tools write them, and
 * vtkMedialBallPLYWriter).
 *
 * Accepts ASCII, binary little-endian and binary big-endian PLY 1.0 with any
 * elements and properties of any PLY scalar type (char/int8 ... double/float64)
 * or list type. Used:
 *  - element `vertex`: properties `x`, `y`, `z` and `radius` (or `r`), required;
 *  - element `edge`: properties `vertex1` and `vertex2`, one line cell each;
 *  - element `face`: list property `vertex_indices` (or `vertex_index`), one
 *    polygon cell each (any number of points, at least 3).
 * Every other element and property is read past and ignored.
 *
 * Output: vtkPolyData with double-precision points, the point-data array `Radius`
 * (double, active scalars), lines and polygons in file order (like
 * vtkMedialMeshReader).
 *
 * Bad input (not PLY, an unknown format or type, a missing vertex property, a
 * truncated body, a NaN or infinite value, a negative radius, an index out of
 * range, a face of fewer than three points) gives one error naming the file and
 * the element, and an empty output. Header counts are not trusted for allocation.
 * Progress is reported as the elements are read.
 *
 * @sa vtkMedialBallPLYWriter vtkMedialMeshReader vtkMedialFileReader
 */
#ifndef vtkMedialBallPLYReader_h
#define vtkMedialBallPLYReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisReadersModule.h" // for export macro

class VTKMEDIALAXISREADERS_EXPORT vtkMedialBallPLYReader : public vtkAbstractPolyDataReader
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallPLYReader* New();
  vtkTypeMacro(vtkMedialBallPLYReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// 1 when the file's PLY header parses and its vertices have x, y, z and a radius.
  static int CanReadFile(const char* fileName);

protected:
  vtkMedialBallPLYReader() = default;
  ~vtkMedialBallPLYReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMedialBallPLYReader(const vtkMedialBallPLYReader&) = delete;
  void operator=(const vtkMedialBallPLYReader&) = delete;
};

#endif
