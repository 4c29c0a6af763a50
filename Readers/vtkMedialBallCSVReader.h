// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallCSVReader
 * @brief Reads medial balls from a CSV table with x, y, z and radius columns
 * (vtkMedialBallCSVWriter's output, or a spreadsheet's).
 *
 * The first line names the columns, separated by commas (or semicolons or tabs,
 * whichever the header line uses); the columns `x`, `y`, `z` and `radius` (or
 * `r`), matched without regard to case or surrounding spaces or quotes, are
 * required, in any order; other columns are ignored. Every further non-blank line
 * is one ball. Numbers use '.' as the decimal point.
 *
 * Output: vtkPolyData with double-precision points and the point-data array
 * `Radius` (double, active scalars); no cells (like the other ball readers'
 * points without edges).
 *
 * Bad input (a missing column, a row with too few fields, a field that is not a
 * number, a NaN or infinite value, a negative radius) gives one error naming the
 * file and line, and an empty output. Progress is reported as the file is read.
 *
 * @sa vtkMedialBallCSVWriter vtkMedialFileReader
 */
#ifndef vtkMedialBallCSVReader_h
#define vtkMedialBallCSVReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisReadersModule.h" // for export macro

class VTKMEDIALAXISREADERS_EXPORT vtkMedialBallCSVReader : public vtkAbstractPolyDataReader
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallCSVReader* New();
  vtkTypeMacro(vtkMedialBallCSVReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

protected:
  vtkMedialBallCSVReader() = default;
  ~vtkMedialBallCSVReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkMedialBallCSVReader(const vtkMedialBallCSVReader&) = delete;
  void operator=(const vtkMedialBallCSVReader&) = delete;
};

#endif
