// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallCSVWriter
 * @brief Writes medial balls as a CSV table, one ball per row.
 *
 * The first line names the columns: `x,y,z,radius`, then one column per component
 * of every other numeric point-data array (a one-component array by its name, a
 * three-component one as NAME_x, NAME_y, NAME_z, others as NAME_0, NAME_1, ...).
 * Numbers have max_digits10 significant digits and a '.' decimal point whatever
 * the locale. Cells (links, faces) are not written: a table holds balls only.
 * vtkMedialBallCSVReader reads the x, y, z and radius columns back.
 *
 * @sa vtkMedialBallCSVReader vtkMedialBallWriter vtkMedialFileWriter
 */
#ifndef vtkMedialBallCSVWriter_h
#define vtkMedialBallCSVWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkMedialBallWriter.h"

class VTKMEDIALAXISREADERS_EXPORT vtkMedialBallCSVWriter : public vtkMedialBallWriter
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallCSVWriter* New();
  vtkTypeMacro(vtkMedialBallCSVWriter, vtkMedialBallWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

protected:
  vtkMedialBallCSVWriter() = default;
  ~vtkMedialBallCSVWriter() override = default;

  void WriteRecords(std::ostream& file, const medialballs::BallRecords& records) override;
  const char* GetDescription() const override { return "CSV balls"; }

private:
  vtkMedialBallCSVWriter(const vtkMedialBallCSVWriter&) = delete;
  void operator=(const vtkMedialBallCSVWriter&) = delete;
};

#endif
