// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialHTMLWriter
 * @brief One self-contained HTML page of a medialaxis result, to turn around in any
 * current browser, offline, from a file or a web server.
 *
 * The page holds its data and its viewer: nothing is fetched. The viewer is vtk.js
 * (from the npm registry, pinned in Rendering/Web/viewer/package-lock.json), bundled
 * at build time and compiled into this library; HasViewer() says whether this build
 * has it (a build without npm has not, and Write() then fails with the reason).
 *
 * What is shown depends on what is given, as the run produced it:
 *  - Surface: the input, translucent (opacity slider, toggle). When it carries the
 *    point array `Thickness` (vtkMedialThickness's output), it can be coloured by
 *    thickness with a threshold slider that paints thinner regions red. A planar
 *    Surface is drawn by its outline (boundary edges: a triangulated region shows its
 *    boundary, not its triangles).
 *  - Balls: the centres as spheres coloured by `Radius` and sized by it (a size
 *    slider, from a fraction of the radius to the true ball), with a radius range
 *    filter. Above MaximumNumberOfBalls the page keeps every k-th ball (k the
 *    smallest step that fits) and says so.
 *  - MedialMesh: vtkMedialMeshFilter's output, faces and edges coloured by
 *    `MedialPointType` (rim, sheet, seam, junction), seam and junction vertices
 *    drawn on top, each a toggle.
 *  - Graph: vtkMedialJunctionFilter's output (2D): arcs by `ArcType`, junctions and
 *    end points, and the maximal disks of the junctions.
 *  - Reconstruction: vtkMedialBallUnion's surface, in a second view beside the
 *    input, through the same camera.
 * Clicking a ball, a medial vertex, a graph point or a surface point shows its
 * position, radius, type and thickness.
 *
 * Data: each dataset goes through VTK's own vtk.js export (vtkJSONDataSetWriter, into
 * memory), its arrays as float32 or small integers, zlib-compressed and base64-encoded
 * in the page; vtk.js's vtkHttpDataSetReader reads them back there (its "html" data
 * access helper). Only the arrays the page uses are kept.
 *
 * The page opens in the view vtkMedialScene would draw (ViewDirection). Write() writes
 * FileName (or the string GetOutputString() with WriteToOutputString); it returns 1 on
 * success, 0 with an error.
 *
 * @sa vtkMedialScene vtkMedialAxisSampler vtkMedialMeshFilter vtkMedialThickness
 */
#ifndef vtkMedialHTMLWriter_h
#define vtkMedialHTMLWriter_h

#include "vtkMedialAxisRenderingWebModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string

class vtkPolyData;

class VTKMEDIALAXISRENDERINGWEB_EXPORT vtkMedialHTMLWriter : public vtkObject
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialHTMLWriter* New();
  vtkTypeMacro(vtkMedialHTMLWriter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The input shape: a closed surface (3D, optionally with `Thickness`) or planar loops.
  virtual void SetSurface(vtkPolyData*);
  vtkGetObjectMacro(Surface, vtkPolyData);
  ///@}

  ///@{
  /// Medial balls: points with `Radius` (vtkMedialAxisSampler's output, or read balls).
  virtual void SetBalls(vtkPolyData*);
  vtkGetObjectMacro(Balls, vtkPolyData);
  ///@}

  ///@{
  /// The 3D medial mesh (vtkMedialMeshFilter's output), with `MedialPointType`.
  virtual void SetMedialMesh(vtkPolyData*);
  vtkGetObjectMacro(MedialMesh, vtkPolyData);
  ///@}

  ///@{
  /// The 2D medial graph (vtkMedialJunctionFilter's output).
  virtual void SetGraph(vtkPolyData*);
  vtkGetObjectMacro(Graph, vtkPolyData);
  ///@}

  ///@{
  /// A reconstruction (vtkMedialBallUnion's output 0), shown beside the input.
  virtual void SetReconstruction(vtkPolyData*);
  vtkGetObjectMacro(Reconstruction, vtkPolyData);
  ///@}

  ///@{
  /// The page's title (default "medialaxis").
  vtkSetStdStringFromCharMacro(Title);
  vtkGetCharFromStdStringMacro(Title);
  ///@}

  ///@{
  /// Free text shown under the title, e.g. the command line and its figures.
  vtkSetStdStringFromCharMacro(Details);
  vtkGetCharFromStdStringMacro(Details);
  ///@}

  ///@{
  /// The most balls the page shows (default 100000); above it every k-th ball is kept.
  vtkSetClampMacro(MaximumNumberOfBalls, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfBalls, vtkIdType);
  ///@}

  ///@{
  /// The opening view, one of vtkMedialScene's ViewDirections (default VIEW_AUTO).
  vtkSetClampMacro(ViewDirection, int, 0, 7);
  vtkGetMacro(ViewDirection, int);
  ///@}

  ///@{
  /// The file to write.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// Keep the page in memory (GetOutputString) instead of writing FileName.
  vtkSetMacro(WriteToOutputString, bool);
  vtkGetMacro(WriteToOutputString, bool);
  vtkBooleanMacro(WriteToOutputString, bool);
  ///@}

  /// The page of the last Write() with WriteToOutputString.
  std::string GetOutputString() const { return this->OutputString; }

  /// Builds the page and writes it. 1 on success, 0 on failure (error).
  int Write();

  ///@{
  /// Figures of the last Write(): the page's size in bytes, of which the viewer's
  /// script and the data (base64); the balls shown and given.
  vtkGetMacro(NumberOfBytes, vtkIdType);
  vtkGetMacro(NumberOfViewerBytes, vtkIdType);
  vtkGetMacro(NumberOfDataBytes, vtkIdType);
  vtkGetMacro(NumberOfDisplayedBalls, vtkIdType);
  vtkGetMacro(NumberOfBalls, vtkIdType);
  ///@}

  /// True when this build holds the page's viewer (vtk.js bundled by npm at build time).
  static bool HasViewer();
  /// Why the viewer is missing (empty when HasViewer()).
  static const char* GetViewerStatus();
  /// The pinned vtk.js version of the viewer (empty without one).
  static const char* GetViewerVersion();

protected:
  vtkMedialHTMLWriter();
  ~vtkMedialHTMLWriter() override;

  vtkPolyData* Surface = nullptr;
  vtkPolyData* Balls = nullptr;
  vtkPolyData* MedialMesh = nullptr;
  vtkPolyData* Graph = nullptr;
  vtkPolyData* Reconstruction = nullptr;
  std::string Title = "medialaxis";
  std::string Details;
  vtkIdType MaximumNumberOfBalls = 100000;
  int ViewDirection = 0;
  std::string FileName;
  bool WriteToOutputString = false;
  std::string OutputString;
  vtkIdType NumberOfBytes = 0;
  vtkIdType NumberOfViewerBytes = 0;
  vtkIdType NumberOfDataBytes = 0;
  vtkIdType NumberOfDisplayedBalls = 0;
  vtkIdType NumberOfBalls = 0;

private:
  vtkMedialHTMLWriter(const vtkMedialHTMLWriter&) = delete;
  void operator=(const vtkMedialHTMLWriter&) = delete;
};

#endif
