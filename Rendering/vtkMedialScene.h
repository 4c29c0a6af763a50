// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialScene
 * @brief The pictures of medialaxis results, built and rendered offscreen: one scene
 * builder for the command line, the image tests and Python.
 *
 * What is drawn depends on what is given:
 *  - 3D (no Graph): the Surface as a light grey translucent shell (SurfaceOpacity),
 *    the Medial balls' centres (and any link lines or medial-mesh faces) coloured by
 *    their `Radius` array from blue (thin) to red (thick), the centres drawn as
 *    spheres of PointSize pixels, with a scalar bar (ScalarBarVisibility). Medial may
 *    be a medial mesh (vtkMedialMeshFilter's output), and with ColorBy POINT_TYPE it
 *    is coloured by `MedialPointType`: rim blue, sheet grey, seam orange, junction
 *    red, with their names in the legend. With SurfaceScalars (e.g. "Thickness" from
 *    vtkMedialThickness), the Surface is drawn opaque and coloured by that point array
 *    instead, with its scale, and the Medial balls are left out. Given a
 *    Reconstruction, the picture gets a second view on the right of the first: the
 *    reconstruction, shaded in copper, seen through the
 *    same camera.
 *  - 2D (a Graph, vtkMedialJunctionFilter's output): the Surface's outline in black
 *    (the edges of one polygon cell only: a triangulated region shows its boundary,
 *    not its triangles), the graph's arcs by `ArcType` (blue linear, orange parabolic), the
 *    maximal disks of the six largest junctions (grey circles), junctions (red) and
 *    end points (green).
 *
 * Camera (parallel projection). The view direction comes from ViewDirection:
 *  - VIEW_AUTO (default): from the principal axes of everything drawn (the
 *    eigenvectors of the points' scatter matrix, taken as the world axes when each
 *    lies within 20 degrees of one): the axis of largest extent runs across the
 *    picture, the second upwards (its largest component positive), and the camera
 *    looks along the third (from the side where its largest component is
 *    positive). A planar input is seen straight along its normal.
 *  - VIEW_PLUS_X ... VIEW_MINUS_Z: the camera looks along that world axis (as
 *    ParaView's "set view direction" buttons); of the two other world axes the one
 *    with the larger extent runs across, the other points up.
 *  - VIEW_ISO: the camera looks along -(1, 1, 1), with the automatic view's upward
 *    world axis pointing up.
 *  - SetView(): the given position, focal point and view up.
 * Whatever the direction, the view is then framed: the projected extent of
 * everything drawn fills the view but for Margin (a fraction of the view's width and
 * height on each side), and then zoomed by Zoom (1: framed; 2: twice as large,
 * cropping).
 *
 * The scalar bar gets a strip of its own, 120 pixels wide, on the right of the
 * picture, so it never covers the model.
 *
 * Render() builds the scene in the scene's offscreen render window of WindowSize pixels
 * (0, 0: 900 x 640 in 3D, 900 x 700 in 2D, and twice as wide with a reconstruction)
 * on a white background, renders it and returns the window. WritePNG() renders and
 * saves the picture; the PNG writer's errors are reported as this object's.
 * Rendering needs an X display with Debian's VTK (xvfb-run), not with a VTK built for
 * OSMesa or EGL (scripts/vtk-osmesa.sh): NeedsDisplay() says which.
 *
 * @sa vtkMedialAxisSampler vtkMedialJunctionFilter vtkMedialBallUnion
 */
#ifndef vtkMedialScene_h
#define vtkMedialScene_h

#include "vtkMedialAxisRenderingModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <string> // for std::string

class vtkPolyData;
class vtkRenderWindow;
class vtkPolyDataMapper;
class vtkRenderer;

class VTKMEDIALAXISRENDERING_EXPORT vtkMedialScene : public vtkObject
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialScene* New();
  vtkTypeMacro(vtkMedialScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The input shape: a surface (3D) or planar loops (2D).
  virtual void SetSurface(vtkPolyData*);
  vtkGetObjectMacro(Surface, vtkPolyData);
  ///@}

  ///@{
  /// Medial balls (vtkMedialAxisSampler's output): points, and lines for links, with `Radius`.
  virtual void SetMedial(vtkPolyData*);
  vtkGetObjectMacro(Medial, vtkPolyData);
  ///@}

  ///@{
  /// The 2D medial graph (vtkMedialJunctionFilter's output); when set, the 2D scene is drawn.
  virtual void SetGraph(vtkPolyData*);
  vtkGetObjectMacro(Graph, vtkPolyData);
  ///@}

  ///@{
  /// A reconstruction (vtkMedialBallUnion's output 0), drawn in a second view (3D scene).
  virtual void SetReconstruction(vtkPolyData*);
  vtkGetObjectMacro(Reconstruction, vtkPolyData);
  ///@}

  ///@{
  /// Opacity of the 3D surface (default 0.2; 1 draws it opaque).
  vtkSetClampMacro(SurfaceOpacity, double, 0.0, 1.0);
  vtkGetMacro(SurfaceOpacity, double);
  ///@}

  ///@{
  /// A point array of the Surface to colour it by, opaque, with its scale (default
  /// empty: the translucent grey shell). E.g. vtkMedialArrayNames::Thickness.
  vtkSetStdStringFromCharMacro(SurfaceScalars);
  vtkGetCharFromStdStringMacro(SurfaceScalars);
  ///@}

  ///@{
  /// Diameter of the medial points in pixels (default 4) and width of link lines (default 1).
  vtkSetClampMacro(PointSize, double, 0.0, 100.0);
  vtkGetMacro(PointSize, double);
  vtkSetClampMacro(LineWidth, double, 0.0, 100.0);
  vtkGetMacro(LineWidth, double);
  ///@}

  ///@{
  /// Whether the 3D scene shows the radius scale (default on).
  vtkSetMacro(ScalarBarVisibility, bool);
  vtkGetMacro(ScalarBarVisibility, bool);
  vtkBooleanMacro(ScalarBarVisibility, bool);
  ///@}

  /// What colours the medial points in 3D (ColorBy).
  enum ColorModes
  {
    RADIUS = 0,    ///< the Radius array, with a colour bar
    POINT_TYPE = 1 ///< the 3D MedialPointType codes (rim, sheet, seam, junction)
  };

  ///@{
  /// What colours the Medial data in 3D: its `Radius` (default) or its 3D
  /// `MedialPointType` codes.
  vtkSetClampMacro(ColorBy, int, RADIUS, POINT_TYPE);
  vtkGetMacro(ColorBy, int);
  void SetColorByToRadius() { this->SetColorBy(RADIUS); }
  void SetColorByToPointType() { this->SetColorBy(POINT_TYPE); }
  ///@}

  ///@{
  /// Size of the whole picture in pixels; 0, 0 (default) takes the scene's own.
  vtkSetVector2Macro(WindowSize, int);
  vtkGetVector2Macro(WindowSize, int);
  ///@}

  ///@{
  /// Zoom after framing (default 1: everything drawn fits, with the margin).
  vtkSetClampMacro(Zoom, double, 0.01, 1000.0);
  vtkGetMacro(Zoom, double);
  ///@}

  ///@{
  /// Empty border around the framed model, as a fraction of the view's width and
  /// height on each side (default 0.05).
  vtkSetClampMacro(Margin, double, 0.0, 0.45);
  vtkGetMacro(Margin, double);
  ///@}

  /// The camera's direction (see the class comment).
  enum ViewDirections
  {
    VIEW_AUTO = 0, ///< from the principal axes: the longest extent across, the second up
    VIEW_PLUS_X,   ///< looking along +x
    VIEW_MINUS_X,  ///< looking along -x
    VIEW_PLUS_Y,   ///< looking along +y
    VIEW_MINUS_Y,  ///< looking along -y
    VIEW_PLUS_Z,   ///< looking along +z
    VIEW_MINUS_Z,  ///< looking along -z
    VIEW_ISO       ///< looking along -(1, 1, 1)
  };

  ///@{
  /// The view direction (default VIEW_AUTO). Setting it drops a SetView() view.
  virtual void SetViewDirection(int direction);
  vtkGetMacro(ViewDirection, int);
  ///@}

  /// The name of a view direction: "auto", "+x", "-x", "+y", "-y", "+z", "-z", "iso".
  static const char* GetViewDirectionName(int direction);
  /// The view direction of a name (see GetViewDirectionName), or -1.
  static int GetViewDirectionFromName(const char* name);

  /// Looks from `position` at `focalPoint` with `viewUp` instead of the scene's view.
  void SetView(const double position[3], const double focalPoint[3], const double viewUp[3]);
  /// Back to the scene's own view (ViewDirection).
  void ResetView() { this->CustomView = false; }

  /// Builds the scene in this object's offscreen window (created by the first
  /// Render() and emptied by each one), renders it and returns the window. nullptr,
  /// with an error, without anything to draw.
  vtkRenderWindow* Render();

  /// Renders and writes the picture as a PNG file. 1 on success, 0 on failure (error).
  int WritePNG(const char* fileName);

  /// The camera's frame the scene would use for what is set (see the class comment):
  /// `right` across the picture, `up`, and `toward` the camera; unit vectors. The web
  /// page (vtkMedialHTMLWriter) opens with this view.
  void GetViewAxes(double right[3], double up[3], double toward[3]) const { this->ViewAxes(right, up, toward); }

  /// The window of the last Render(), or nullptr.
  vtkRenderWindow* GetRenderWindow();

  /// True when this VTK renders through X, so that even offscreen rendering needs an X
  /// display (Debian's VTK); false for a VTK built for OSMesa or EGL.
  static bool NeedsDisplay();

protected:
  vtkMedialScene();
  ~vtkMedialScene() override;

  vtkPolyData* Surface = nullptr;
  vtkPolyData* Medial = nullptr;
  vtkPolyData* Graph = nullptr;
  vtkPolyData* Reconstruction = nullptr;
  double SurfaceOpacity = 0.2;
  std::string SurfaceScalars;
  double PointSize = 4.0;
  double LineWidth = 1.0;
  bool ScalarBarVisibility = true;
  int ColorBy = RADIUS;
  int WindowSize[2] = { 0, 0 };
  double Zoom = 1.0;
  double Margin = 0.05;
  int ViewDirection = VIEW_AUTO;
  bool CustomView = false;
  double ViewPosition[3] = { 0, 0, 1 };
  double ViewFocalPoint[3] = { 0, 0, 0 };
  double ViewUp[3] = { 0, 1, 0 };

private:
  vtkMedialScene(const vtkMedialScene&) = delete;
  void operator=(const vtkMedialScene&) = delete;

  vtkSmartPointer<vtkRenderer> AddBalls(vtkRenderer* renderer);
  vtkSmartPointer<vtkRenderer> ColourBy(vtkPolyDataMapper* mapper, vtkPolyData* data, const char* name);
  void AddGraph(vtkRenderer* renderer, const double normal[3]);
  vtkSmartPointer<vtkRenderer> AddReconstructionView(vtkRenderer* left);
  void ViewAxes(double right[3], double up[3], double toward[3]) const;
  void Frame(vtkRenderer* renderer, double aspect);

  vtkSmartPointer<vtkRenderWindow> Window;
  int LegendPixels = 120; // width of the scale's strip, set by ColourBy
};

#endif
