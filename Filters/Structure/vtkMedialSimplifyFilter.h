// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSimplifyFilter
 * @brief Simplifies a medial mesh to a given number of balls, keeping its topology.
 *
 * Algorithm: Q-MAT (Li et al. 2015, vtkMedialQuadricSimplification): every ball
 * starts with the spherical quadric error of the tangent planes of its slabs and cones;
 * edges are collapsed, cheapest first, each into the ball that minimises the summed
 * quadric; a collapse that would change the topology (the link condition) waits until
 * its neighbourhood changes. Collapses keep the homotopy type, so the components and
 * the Euler characteristic of the input are those of the output.
 *
 * Input: a medial mesh (vtkPolyData with triangles and/or lines and a point-data radius,
 * input array 0, default Radius), e.g. vtkMedialMeshFilter's output or a .ma file.
 * Output: a medial mesh with exactly NumberOfBalls points (fewer when the input has
 * fewer; more, with a warning, when no allowed collapse is left, which needs at least
 * one ball per component and a few per cycle), in the layout of vtkMedialMeshFilter:
 * point data Radius and MedialPointType (from the mesh: 0 rim, 1 sheet, 2 seam,
 * 3 junction), vertex cells, curve and seam lines and triangles with cell data
 * MedialCellType; the input's field data (its topology figures still hold). It goes through the
 * medial mesh writer (.ma) and vtkMedialBallUnion's MEDIAL_MESH envelope.
 *
 * @sa vtkMedialMeshFilter vtkMedialPruneFilter vtkMedialBallUnion
 */
#ifndef vtkMedialSimplifyFilter_h
#define vtkMedialSimplifyFilter_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialSimplifyFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkMedialSimplifyFilter* New();
  vtkTypeMacro(vtkMedialSimplifyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The number of balls to keep (default 100).
  vtkSetClampMacro(NumberOfBalls, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(NumberOfBalls, vtkIdType);
  ///@}

  ///@{
  /// Figures from the last execution: collapses left that the link condition refused
  /// (0 when NumberOfBalls was reached), and the topology of input and output.
  vtkGetMacro(NumberOfBlockedCollapses, vtkIdType);
  vtkGetMacro(EulerCharacteristic, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  ///@}

protected:
  vtkMedialSimplifyFilter();
  ~vtkMedialSimplifyFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfBalls = 100;
  vtkIdType NumberOfBlockedCollapses = 0;
  vtkIdType EulerCharacteristic = 0;
  vtkIdType NumberOfComponents = 0;

private:
  vtkMedialSimplifyFilter(const vtkMedialSimplifyFilter&) = delete;
  void operator=(const vtkMedialSimplifyFilter&) = delete;
};

#endif
