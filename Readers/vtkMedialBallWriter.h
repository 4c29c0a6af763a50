// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallWriter
 * @brief Base of the writers of medial balls (.ma, .ply, .csv): checks and
 * gathers the balls, then lets the subclass write its format.
 *
 * Input: vtkPolyData whose points are ball centres, with a one-component
 * point-data array `Radius`; lines are edges (a polyline gives its segments),
 * polygons and strips are triangulated into faces, vertex cells are not written
 * (every point is written anyway).
 *
 * Before the file is touched, WriteData() checks that every coordinate and radius
 * is finite, that no radius is negative and that every cell refers to an existing
 * point; otherwise it reports an error naming the file and the problem, writes
 * nothing, and Write() returns 0 with GetErrorCode() set. Lines of one point and
 * polygons of fewer than three points are skipped with a warning. A file that
 * cannot be written completely (disk full) is removed.
 *
 * @sa vtkMedialMeshWriter vtkMedialBallPLYWriter vtkMedialBallCSVWriter vtkMedialFileWriter
 */
#ifndef vtkMedialBallWriter_h
#define vtkMedialBallWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkWriter.h"

#include <iosfwd> // for std::ostream

class vtkPolyData;
namespace medialballs
{
struct BallRecords;
}

class VTKMEDIALAXISREADERS_EXPORT vtkMedialBallWriter : public vtkWriter
{
public:
  ///@{
  /// Standard VTK methods: the type queries of vtkTypeMacro (SafeDownCast, IsA,
  /// NewInstance) and PrintSelf() (the settings). No New(): the class is abstract.
  vtkTypeMacro(vtkMedialBallWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  /// The input polydata.
  vtkPolyData* GetInput();

protected:
  vtkMedialBallWriter();
  ~vtkMedialBallWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  /// Writes the checked records in the subclass's format.
  virtual void WriteRecords(std::ostream& file, const medialballs::BallRecords& records) = 0;
  /// What the file holds, for messages ("medial mesh", "PLY balls", ...).
  virtual const char* GetDescription() const = 0;

  char* FileName = nullptr;

private:
  vtkMedialBallWriter(const vtkMedialBallWriter&) = delete;
  void operator=(const vtkMedialBallWriter&) = delete;
};

#endif
