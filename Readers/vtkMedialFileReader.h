// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialFileReader
 * @brief Reads any file the medialaxis tools accept, choosing the reader by the
 * file name's extension. The one place where extensions map to readers.
 *
 * The extension (matched without regard to case) and the Content decide:
 *
 * | Content | extension | reader |
 * |---|---|---|
 * | SURFACE | .vtp | vtkXMLPolyDataReader |
 * | SURFACE | .vtk | vtkDataSetReader (any legacy dataset; its outer surface is extracted with vtkDataSetSurfaceFilter) |
 * | SURFACE | .ply | vtkPLYReader (the common binary layout, float vertices and faces alone, is read directly with the same output: vtkMedialPLYSurface.h) |
 * | SURFACE | .stl | vtkSTLReader |
 * | SURFACE | .obj | vtkOBJReader |
 * | SURFACE | .off | vtkMedialOFFReader |
 * | BALLS | .ma | vtkMedialMeshReader (centres, `Radius`, edges and faces) |
 * | BALLS | .ply | vtkMedialBallPLYReader (vertices with a `radius` property, edges, faces) |
 * | BALLS | .vtp | vtkXMLPolyDataReader (e.g. the sampler's output saved by `medial-axis -o`) |
 * | BALLS | .vtk | vtkPolyDataReader |
 * | BALLS | .csv | vtkMedialBallCSVReader (columns x, y, z, radius) |
 *
 * As a reader (SetFileName, Update) it runs the chosen reader and passes its output
 * on. The chosen reader's errors and warnings are reported again as this reader's
 * own, with the same text, so an observer on this reader (or the output window)
 * sees them, and the update fails after an error. A file name without a reader for
 * the Content is an error that lists the extensions there are readers for. The
 * chosen reader's progress is reported as this reader's, with the progress text
 * "Reading the surface" or "Reading the balls". Every format vtkMedialFileWriter
 * writes for a Content is read back for the same Content.
 *
 * The static methods serve callers that want the stock reader itself (to set its
 * own options), a usage line, or a check before any work: NewReader(),
 * GetExtensions(), CanReadExtension(), GetExtension(). A new format is one row of
 * the table in vtkMedialFileReader.cxx.
 *
 * Output: vtkPolyData.
 *
 * @sa vtkMedialOFFReader vtkMedialMeshReader vtkMedialBallPLYReader vtkMedialFileWriter
 */
#ifndef vtkMedialFileReader_h
#define vtkMedialFileReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkMedialAxisReadersModule.h" // for export macro
#include "vtkWrappingHints.h"           // for VTK_NEWINSTANCE

#include <string> // for std::string

class vtkAlgorithm;

class VTKMEDIALAXISREADERS_EXPORT vtkMedialFileReader : public vtkAbstractPolyDataReader
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialFileReader* New();
  vtkTypeMacro(vtkMedialFileReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// What the file holds, which decides the reader for an extension.
  enum Contents
  {
    SURFACE = 0, ///< a closed surface or planar loops: the sampler's input
    BALLS = 1    ///< medial balls: points with a `Radius` array
  };

  ///@{
  /// What to read (default SURFACE).
  vtkSetClampMacro(Content, int, SURFACE, BALLS);
  vtkGetMacro(Content, int);
  void SetContentToSurface() { this->SetContent(SURFACE); }
  void SetContentToBalls() { this->SetContent(BALLS); }
  ///@}

  /**
   * A new reader for `fileName` (a new reference, its file name set), chosen by the
   * extension for `content`; nullptr when there is none. For .vtk it is the
   * vtkDataSetReader alone, whose output may be another dataset type than
   * vtkPolyData (this class extracts the surface).
   */
  VTK_NEWINSTANCE
  static vtkAlgorithm* NewReader(const char* fileName, int content = SURFACE);

  /// The extensions read for `content`, e.g. ".vtp .vtk .ply .stl .obj .off".
  static std::string GetExtensions(int content = SURFACE);

  /// 1 when `fileName`'s extension has a reader for `content` (the file is not opened).
  static int CanReadExtension(const char* fileName, int content = SURFACE);

  /// The extension of `fileName` in lower case with its dot ("" when it has none).
  static std::string GetExtension(const char* fileName);

  /// True when the last update read the file directly (a PLY surface of the common
  /// binary layout) rather than through the table's reader; the output is the same.
  vtkGetMacro(ReadDirectly, bool);

protected:
  vtkMedialFileReader() = default;
  ~vtkMedialFileReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Content = SURFACE;
  bool ReadDirectly = false;

private:
  vtkMedialFileReader(const vtkMedialFileReader&) = delete;
  void operator=(const vtkMedialFileReader&) = delete;
};

#endif
