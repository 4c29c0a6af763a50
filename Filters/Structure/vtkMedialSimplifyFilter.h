// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialSimplifyFilter
 * @brief Simplifies a medial mesh to a given number of balls, keeping its topology.
 *
 * Two methods (Method):
 *
 * QUADRIC (the default), Q-MAT (Li et al. 2015, vtkMedialQuadricSimplification): every ball
 * starts with the spherical quadric error of the tangent planes of its slabs and cones;
 * edges are collapsed, cheapest first, each into the ball that minimises the summed
 * quadric; a collapse that would change the Euler characteristic waits until its
 * neighbourhood changes. The components and the Euler characteristic of the input are
 * those of the output, but a collapse that fails the link condition may remove a
 * spurious cycle together with the cavity it bounds, so the homotopy type is not
 * strictly kept (under the link condition alone most of a real medial mesh cannot
 * collapse: see vtkMedialQuadricSimplification).
 *
 * With the surface on input port 1, QUADRIC's collapses are guarded (ErrorTolerance):
 * the surface's vertices (at most 20,000, every k-th beyond) are shared out to their
 * nearest balls, and a collapse that would leave one of its balls' vertices farther
 * than ErrorTolerance (and than they already were) from the envelope waits behind all
 * others; once only such collapses are left, the one that moves the surface least goes
 * first. The quadric alone lets corners and thin tips be pulled in by many cheap
 * collapses: fandisk at K = 100 went from 2.88% of the diagonal to 2.35% (measured
 * with vtkMedialReconstructionError on the MEDIAL_MESH envelope; see the K table in
 * docs/how-it-works/simplification.md).
 *
 * COVERAGE, the idea of Coverage Axis (Dou et al. 2022) and Coverage Axis++ (Wang et al.
 * 2024), vtkMedialCoverageSelection: the candidates are the medial mesh's balls, the
 * samples NumberOfSurfaceSamples points spread uniformly by area over the surface on
 * input port 1 (required for this method; stream RandomSeed). A ball covers a sample
 * that lies in it grown by Dilation (relative to the surface's diagonal). NumberOfBalls
 * balls are chosen greedily, each covering the most samples not yet covered; once all
 * coverable samples are covered the dilation is halved and the choice goes on. The
 * chosen balls keep their centres and radii; every other ball is collapsed into a
 * neighbour along the mesh's edges, cheapest first under the quadric error above and
 * under the same topology rules, so the chosen balls are joined by the mesh's own
 * edges and triangles (vtkMedialQuadricSimplification::RunKeeping). A ball not chosen
 * that no such collapse can remove is chosen in a new choice of the others (at most
 * six choices); after the sixth, chosen balls may go instead.
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
 * The coverage pairs are found in parallel (NumberOfThreads, 0 = all cores); the output
 * does not depend on the thread count.
 *
 * @sa vtkMedialMeshFilter vtkMedialPruneFilter vtkMedialBallUnion
 */
#ifndef vtkMedialSimplifyFilter_h
#define vtkMedialSimplifyFilter_h

#include "vtkMedialAxisStructureModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // for std::vector

class vtkMedialQuadricSimplification;
class vtkMedialRepairFilter;
class vtkMedialSimplicialComplex;
class vtkMedialTriangleMesh;

class VTKMEDIALAXISSTRUCTURE_EXPORT vtkMedialSimplifyFilter : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialSimplifyFilter* New();
  vtkTypeMacro(vtkMedialSimplifyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  ///@{
  /// The number of balls to keep (default 100).
  vtkSetClampMacro(NumberOfBalls, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(NumberOfBalls, vtkIdType);
  ///@}

  /// The simplification methods (Method).
  enum SimplificationMethod
  {
    QUADRIC = 0, ///< Q-MAT: edge collapses under the spherical quadric error
    COVERAGE = 1 ///< Coverage Axis: the balls that cover the surface, joined by collapses
  };

  ///@{
  /// The simplification method (default QUADRIC; see the class comment).
  vtkSetClampMacro(Method, int, QUADRIC, COVERAGE);
  vtkGetMacro(Method, int);
  void SetMethodToQuadric() { this->SetMethod(QUADRIC); }
  void SetMethodToCoverage() { this->SetMethod(COVERAGE); }
  static const char* GetMethodName(int method);
  ///@}

  ///@{
  /// QUADRIC: the weight of the planes that hold the sheets' rims where they are, against the
  /// slab planes (default 10; 0: Q-MAT's spherical quadric alone). They keep creases
  /// sharp: see vtkMedialQuadricSimplification.
  vtkSetClampMacro(RimWeight, double, 0.0, 1e6);
  vtkGetMacro(RimWeight, double);
  ///@}

  ///@{
  /// QUADRIC with a surface on input 1: the guard's tolerance, relative to the surface's
  /// diagonal (default 0.0075; 0: no guard). Collapses that would leave a surface vertex
  /// farther than this from the envelope go last, in the order of that distance (see
  /// the class comment).
  vtkSetClampMacro(ErrorTolerance, double, 0.0, 1.0);
  vtkGetMacro(ErrorTolerance, double);
  ///@}

  ///@{
  /// The surface whose samples the balls cover (input 1; COVERAGE only).
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSurfaceData(vtkDataObject* surface) { this->SetInputData(1, surface); }
  ///@}

  ///@{
  /// What is done with a surface on input 1 that is not a valid solid
  /// (vtkMedialRepairFilter's modes, as vtkMedialMeshFilter's RepairMode): AUTO (default)
  /// checks it and uses its repair (GetRepair) when it is not one; NONE neither checks
  /// nor repairs; WRAP uses its alpha wrap. Give it the surface the medial mesh was
  /// built in.
  vtkSetClampMacro(RepairMode, int, 0, 2);
  vtkGetMacro(RepairMode, int);
  virtual void SetRepair(vtkMedialRepairFilter*);
  vtkGetObjectMacro(Repair, vtkMedialRepairFilter);
  ///@}

  /// Includes the repair's modification time.
  vtkMTimeType GetMTime() override;

  ///@{
  /// COVERAGE: the start dilation of the balls, relative to the surface's diagonal
  /// (default 0.02), the number of surface samples (default 10000), their random stream
  /// (default 1), and the threads that find the coverage (0 = all cores, the default).
  vtkSetClampMacro(Dilation, double, 1e-6, 1.0);
  vtkGetMacro(Dilation, double);
  vtkSetClampMacro(NumberOfSurfaceSamples, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(NumberOfSurfaceSamples, vtkIdType);
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Figures from the last execution: collapses left that the link condition refused
  /// (0 when NumberOfBalls was reached), and the topology of input and output.
  vtkGetMacro(NumberOfBlockedCollapses, vtkIdType);
  vtkGetMacro(EulerCharacteristic, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  ///@}

  ///@{
  /// COVERAGE, after an execution: the dilation, relative to the surface's diagonal,
  /// within which the chosen balls cover every surface sample (a sample no input ball
  /// comes that near: as near as the nearest input ball), the one the bisection reached
  /// (at most Dilation; when K balls cannot cover at Dilation, Dilation itself and the
  /// cover is partial). 0 for QUADRIC.
  vtkGetMacro(CoveredDilation, double);
  ///@}

protected:
  vtkMedialSimplifyFilter();
  ~vtkMedialSimplifyFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfBalls = 100;
  int Method = QUADRIC;
  double RimWeight = 10.0;
  double ErrorTolerance = 0.0075;
  double Dilation = 0.02;
  vtkIdType NumberOfSurfaceSamples = 10000;
  int RandomSeed = 1;
  int NumberOfThreads = 0;
  int RepairMode = 0;
  vtkMedialRepairFilter* Repair = nullptr;
  vtkIdType NumberOfBlockedCollapses = 0;
  vtkIdType EulerCharacteristic = 0;
  vtkIdType NumberOfComponents = 0;
  double CoveredDilation = 0.0;

private:
  // COVERAGE: the kept flags of the complex's balls, the forced ones among them; false
  // on a bad surface or an abort.
  bool ChooseByCoverage(const vtkMedialSimplicialComplex& complex, const vtkMedialTriangleMesh& mesh, int threads,
    const std::vector<char>& forced, std::vector<char>& kept);
  // QUADRIC: the surface's vertices guard the collapses.
  void SetGuardPoints(const vtkMedialTriangleMesh& mesh, vtkMedialQuadricSimplification& simplification) const;

  vtkMedialSimplifyFilter(const vtkMedialSimplifyFilter&) = delete;
  void operator=(const vtkMedialSimplifyFilter&) = delete;
};

#endif
