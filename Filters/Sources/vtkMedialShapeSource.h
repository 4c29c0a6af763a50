// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialShapeSource
 * @brief Closed triangle meshes generated in code, for demos and for tests whose
 * medial axis is known.
 *
 * Shapes (all closed, manifold, outward-oriented, centred at the origin):
 *  - JACK (default, the demo): a ball with three round arms of different radii
 *    and lengths, blended smoothly. Its medial axis branches and has several
 *    radii. Built by sampling the blended signed distance on a grid of
 *    4 * Resolution cells along its longest side and contouring it with
 *    vtkFlyingEdges3D.
 *  - SPHERE: a geodesic sphere of radius Radius: an icosahedron whose faces are
 *    split Resolution times (20 * 4^Resolution triangles), projected on the sphere.
 *  - BOX: an axis-aligned box with side lengths BoxLengths, each face split into
 *    Resolution x Resolution squares of two triangles.
 *  - CAPSULE: a cylinder of radius Radius and length Length along z with
 *    hemispherical caps, 4 * Resolution segments around.
 *  - TORUS: a ring of radius Radius in the z = 0 plane swept by a circle of radius
 *    TubeRadius, 4 * Resolution segments around the ring (and as many around the tube
 *    as keep the quads about square, at least 6). Its wall thickness is 2 TubeRadius.
 *  - HOLLOW_SPHERE: a geodesic sphere of radius Radius with a concentric spherical
 *    cavity of radius InnerRadius (both split Resolution times, as SPHERE); the
 *    cavity's triangles face into it. Its wall thickness is Radius - InnerRadius.
 *  - RINGS: Genus rings (ring radius 1, tube radius 0.35) side by side along x in the
 *    z = 0 plane, 1.7 apart, blended where they overlap: a solid of genus Genus, for
 *    topology tests. Contoured like JACK.
 *
 * Planar shapes in the z = 0 plane, as polygon cells (for vtkMedialJunctionFilter
 * and the 2D mode of vtkMedialAxisSampler; Resolution is ignored unless stated):
 *  - L_SHAPE: an L with unit-wide arms of length 2, corner at the origin; its
 *    reflex vertex (1, 1) gives a parabolic arc and a junction of radius 2 - sqrt 2.
 *  - RECTANGLE: BoxLengths[0] x BoxLengths[1], corner at the origin.
 *  - SQUARE_FRAME: the square [-2, 2]^2 with the hole [-1, 1]^2.
 *  - STAR: Resolution spikes of outer radius Radius and inner radius Radius / 2,
 *    radii wobbled deterministically so the graph has no symmetric degeneracies
 *    (2 * Resolution vertices).
 *  - ELLIPSE: semi-axes BoxLengths[0] / 2 and BoxLengths[1] / 2 (default 1.5 x 1),
 *    16 * Resolution vertices at equal parameter steps: a finely polygonised smooth
 *    curve whose medial axis is one segment (between the centres of curvature of its
 *    two ends), for pruning.
 *  - TREFOIL: a rounded 3-armed star, r(t) = Radius (1 + cos(3 t) / 2), 16 * Resolution
 *    vertices: three round lobes with concave waists; its smooth medial axis is three
 *    branches meeting at the centre.
 *
 * Output: vtkPolyData of triangles (polygons for the planar shapes), double-precision points.
 */
#ifndef vtkMedialShapeSource_h
#define vtkMedialShapeSource_h

#include "vtkMedialAxisSourcesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISSOURCES_EXPORT vtkMedialShapeSource : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialShapeSource* New();
  vtkTypeMacro(vtkMedialShapeSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// The shapes (Shape; each is described in the class comment).
  enum Shapes
  {
    JACK = 0,          ///< the demo: a ball with three arms (3D)
    SPHERE = 1,        ///< a geodesic sphere (3D)
    BOX = 2,           ///< an axis-aligned box (3D)
    CAPSULE = 3,       ///< a cylinder with hemispherical caps (3D)
    L_SHAPE = 4,       ///< an L with unit-wide arms (2D)
    RECTANGLE = 5,     ///< a rectangle (2D)
    SQUARE_FRAME = 6,  ///< a square with a square hole (2D)
    STAR = 7,          ///< a star with wobbled spikes (2D)
    TORUS = 8,         ///< a torus (3D)
    HOLLOW_SPHERE = 9, ///< a sphere with a concentric cavity (3D)
    RINGS = 10,        ///< Genus rings blended side by side (3D)
    ELLIPSE = 11,      ///< a finely polygonised ellipse (2D)
    TREFOIL = 12       ///< a rounded 3-armed star (2D)
  };

  ///@{
  /// Which shape to generate (default JACK).
  vtkSetClampMacro(Shape, int, JACK, TREFOIL);
  vtkGetMacro(Shape, int);
  void SetShapeToJack() { this->SetShape(JACK); }
  void SetShapeToSphere() { this->SetShape(SPHERE); }
  void SetShapeToBox() { this->SetShape(BOX); }
  void SetShapeToCapsule() { this->SetShape(CAPSULE); }
  void SetShapeToLShape() { this->SetShape(L_SHAPE); }
  void SetShapeToRectangle() { this->SetShape(RECTANGLE); }
  void SetShapeToSquareFrame() { this->SetShape(SQUARE_FRAME); }
  void SetShapeToStar() { this->SetShape(STAR); }
  void SetShapeToTorus() { this->SetShape(TORUS); }
  void SetShapeToHollowSphere() { this->SetShape(HOLLOW_SPHERE); }
  void SetShapeToRings() { this->SetShape(RINGS); }
  void SetShapeToEllipse() { this->SetShape(ELLIPSE); }
  void SetShapeToTrefoil() { this->SetShape(TREFOIL); }
  /// True for the planar (2D) shapes.
  static bool IsPlanar(int shape)
  {
    return (shape >= L_SHAPE && shape <= STAR) || shape == ELLIPSE || shape == TREFOIL;
  }
  ///@}

  ///@{
  /// Tessellation level; its meaning depends on the shape (default 16). See the class comment.
  vtkSetClampMacro(Resolution, int, 1, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// Radius of SPHERE and CAPSULE (default 1).
  vtkSetClampMacro(Radius, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /// Length of the CAPSULE's cylinder (default 2).
  vtkSetClampMacro(Length, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Length, double);
  ///@}

  ///@{
  /// Tube radius of the TORUS (default 0.3); below Radius.
  vtkSetClampMacro(TubeRadius, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(TubeRadius, double);
  ///@}

  ///@{
  /// Cavity radius of the HOLLOW_SPHERE (default 0.7); below Radius.
  vtkSetClampMacro(InnerRadius, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(InnerRadius, double);
  ///@}

  ///@{
  /// Number of rings of RINGS, its genus (default 1).
  vtkSetClampMacro(Genus, int, 1, 64);
  vtkGetMacro(Genus, int);
  ///@}

  ///@{
  /// Side lengths of the BOX (default 3, 2, 1).
  vtkSetVector3Macro(BoxLengths, double);
  vtkGetVector3Macro(BoxLengths, double);
  ///@}

protected:
  vtkMedialShapeSource();
  ~vtkMedialShapeSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Shape = JACK;
  int Resolution = 16;
  double Radius = 1.0;
  double Length = 2.0;
  double TubeRadius = 0.3;
  double InnerRadius = 0.7;
  int Genus = 1;
  double BoxLengths[3] = { 3.0, 2.0, 1.0 };

private:
  vtkMedialShapeSource(const vtkMedialShapeSource&) = delete;
  void operator=(const vtkMedialShapeSource&) = delete;
};

#endif
