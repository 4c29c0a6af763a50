// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialFileWriter
 * @brief Writes polydata in the format the file name's extension says, choosing
 * the writer. The one place where extensions map to writers (the counterpart of
 * vtkMedialFileReader).
 *
 * The extension (matched without regard to case) and the Content decide:
 *
 * | Content | extension | writer |
 * |---|---|---|
 * | SURFACE | .vtp | vtkXMLPolyDataWriter (appended raw binary, uncompressed) |
 * | SURFACE | .vtk | vtkPolyDataWriter (binary legacy) |
 * | SURFACE | .stl | vtkSTLWriter (binary; triangles only) |
 * | SURFACE | .ply | vtkPLYWriter (binary) |
 * | SURFACE | .obj | vtkOBJWriter |
 * | BALLS | .vtp | vtkXMLPolyDataWriter (appended raw binary, uncompressed; every array: Radius, SurfacePoint, ...) |
 * | BALLS | .vtk | vtkPolyDataWriter |
 * | BALLS | .ply | vtkMedialBallPLYWriter (vertices with `radius`, edges, faces) |
 * | BALLS | .ma | vtkMedialMeshWriter (`v x y z r`, edges, faces) |
 * | BALLS | .csv | vtkMedialBallCSVWriter (one row per ball, every point array) |
 *
 * Lines (a planar reconstruction's curves) without polygons are refused for .stl
 * and the surface .ply, which hold triangles only.
 *
 * BALLS is any polydata whose points carry a `Radius` array: the sampler's balls,
 * a medial mesh, the 2D medial graph. Every ball format is read back by
 * vtkMedialFileReader with SetContentToBalls().
 *
 * As a writer (SetInputData or SetInputConnection, SetFileName, Write) it runs the
 * chosen writer on its input. The chosen writer's errors and warnings are reported
 * again as this writer's own; Write() returns 0 and GetErrorCode() is set on
 * failure. A file name without a writer for the Content is an error that lists
 * the extensions there are writers for, and nothing is written.
 *
 * The static methods serve callers that want the stock writer itself, a usage
 * line, or a check before any work: NewWriter(), GetExtensions(),
 * CanWriteExtension(). A new format is one row of the table in
 * vtkMedialFileWriter.cxx.
 *
 * @sa vtkMedialFileReader
 */
#ifndef vtkMedialFileWriter_h
#define vtkMedialFileWriter_h

#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkWrappingHints.h"           // for VTK_NEWINSTANCE
#include "vtkWriter.h"

#include <string> // for std::string

class vtkAlgorithm;
class vtkPolyData;

class VTKMEDIALAXISREADERS_EXPORT vtkMedialFileWriter : public vtkWriter
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialFileWriter* New();
  vtkTypeMacro(vtkMedialFileWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// What the data is, which decides the writer for an extension (as vtkMedialFileReader's).
  enum Contents
  {
    SURFACE = 0, ///< a surface or planar loops
    BALLS = 1    ///< points with a `Radius` array (and optionally edges and faces)
  };

  ///@{
  /// The file to write.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /// What to write (default SURFACE).
  vtkSetClampMacro(Content, int, SURFACE, BALLS);
  vtkGetMacro(Content, int);
  void SetContentToSurface() { this->SetContent(SURFACE); }
  void SetContentToBalls() { this->SetContent(BALLS); }
  ///@}

  /// The input polydata.
  vtkPolyData* GetInput();

  /**
   * A new writer for `fileName` (a new reference, its file name set and its binary
   * mode chosen), picked by the extension for `content`; nullptr when there is none.
   * It is a vtkWriter or, for .vtp, a vtkXMLWriter.
   */
  VTK_NEWINSTANCE
  static vtkAlgorithm* NewWriter(const char* fileName, int content = SURFACE);

  /// The extensions written for `content`, e.g. ".vtp .vtk .stl .ply .obj".
  static std::string GetExtensions(int content = SURFACE);

  /// 1 when `fileName`'s extension has a writer for `content`.
  static int CanWriteExtension(const char* fileName, int content = SURFACE);

protected:
  vtkMedialFileWriter() = default;
  ~vtkMedialFileWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;
  int Content = SURFACE;

private:
  vtkMedialFileWriter(const vtkMedialFileWriter&) = delete;
  void operator=(const vtkMedialFileWriter&) = delete;
};

#endif
