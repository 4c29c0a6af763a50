// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallPLYWriter
 * @brief Writes medial balls as PLY: vertices with a `radius` property.
 *
 * The layout the CGAL- and MATTopo-style tools exchange, and that
 * vtkMedialBallPLYReader reads back:
 * @code
 * ply
 * format binary_little_endian 1.0      (or ascii 1.0)
 * element vertex N
 * property double x
 * property double y
 * property double z
 * property double radius
 * element edge M                       (only when there are edges)
 * property int vertex1
 * property int vertex2
 * element face F                       (only when there are faces)
 * property list uchar int vertex_indices
 * end_header
 * @endcode
 * Edges come from lines, faces from triangulated polygons and strips (see
 * vtkMedialBallWriter for the checks). Binary files are little endian whatever the
 * machine; ASCII numbers have max_digits10 digits, so both round-trip exactly.
 * More than 2^31 - 1 points cannot be indexed by `int` and are refused.
 *
 * @sa vtkMedialBallPLYReader vtkMedialBallWriter vtkMedialFileWriter
 */
#ifndef vtkMedialBallPLYWriter_h
#define vtkMedialBallPLYWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkMedialBallWriter.h"

class VTKMEDIALAXISREADERS_EXPORT vtkMedialBallPLYWriter : public vtkMedialBallWriter
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallPLYWriter* New();
  vtkTypeMacro(vtkMedialBallPLYWriter, vtkMedialBallWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// VTK_BINARY (default, little endian) or VTK_ASCII.
  vtkSetClampMacro(FileType, int, VTK_ASCII, VTK_BINARY);
  vtkGetMacro(FileType, int);
  void SetFileTypeToASCII() { this->SetFileType(VTK_ASCII); }
  void SetFileTypeToBinary() { this->SetFileType(VTK_BINARY); }
  ///@}

protected:
  vtkMedialBallPLYWriter() = default;
  ~vtkMedialBallPLYWriter() override = default;

  void WriteData() override;
  void WriteRecords(std::ostream& file, const medialballs::BallRecords& records) override;
  const char* GetDescription() const override { return "PLY balls"; }

  int FileType = VTK_BINARY;

private:
  vtkMedialBallPLYWriter(const vtkMedialBallPLYWriter&) = delete;
  void operator=(const vtkMedialBallPLYWriter&) = delete;
};

#endif
