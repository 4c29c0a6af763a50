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
 *
 * Output: vtkPolyData of triangles, double-precision points.
 */
#ifndef vtkMedialShapeSource_h
#define vtkMedialShapeSource_h

#include "vtkMedialAxisFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISFILTERS_EXPORT vtkMedialShapeSource : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialShapeSource* New();
  vtkTypeMacro(vtkMedialShapeSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Shapes
  {
    JACK = 0,
    SPHERE = 1,
    BOX = 2,
    CAPSULE = 3
  };

  ///@{
  /// Which shape to generate (default JACK).
  vtkSetClampMacro(Shape, int, JACK, CAPSULE);
  vtkGetMacro(Shape, int);
  void SetShapeToJack() { this->SetShape(JACK); }
  void SetShapeToSphere() { this->SetShape(SPHERE); }
  void SetShapeToBox() { this->SetShape(BOX); }
  void SetShapeToCapsule() { this->SetShape(CAPSULE); }
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
  double BoxLengths[3] = { 3.0, 2.0, 1.0 };

private:
  vtkMedialShapeSource(const vtkMedialShapeSource&) = delete;
  void operator=(const vtkMedialShapeSource&) = delete;
};

#endif
