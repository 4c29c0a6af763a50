// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialBallUnion
 * @brief Reconstructs a shape from medial balls: the boundary of the union of balls (3D)
 * or disks (2D), and the sampled distance-like field of the union.
 *
 * The union of balls B(c_i, r_i) is the zero sublevel set of
 *     f(x) = min_i (|x - c_i| - r_i),
 * which is negative inside the union, zero on its boundary and positive outside
 * (outside it is the exact Euclidean distance to the union).
 *
 * Algorithm:
 *  1. Validation: every point needs a finite, non-negative radius, taken from
 *     input array 0 (SetInputArrayToProcess; by default the point-data array
 *     `Radius`, not the active scalars). A missing array, cell data or an array of
 *     more than one component is an error.
 *  2. Dimension: with DIMENSION_AUTOMATIC the balls are treated as disks when the
 *     centres span exactly a plane (three or more centres, not collinear, all
 *     within 1e-9 of the diagonal of that plane); any plane, not only z = 0.
 *     One or two balls, or collinear centres, are 3D.
 *  3. Grid: the bounding box of the union (centres +- radii) plus Padding (relative
 *     to the union's bounding-box diagonal, at least two voxels on every side so
 *     that the surface is closed) is sampled either with SampleDimensions points
 *     per axis or with an isotropic Spacing relative to that diagonal. With
 *     ModelBounds set, the grid covers that box instead (no padding), so that
 *     reconstructions of different balls share one grid. In 2D the grid lies in the
 *     balls' plane, in a frame (origin, u, v) fitted to it (u along the world axis
 *     most perpendicular to the plane's normal, projected; a z = const plane keeps x
 *     and y).
 *  4. Field: the centres are binned into a grid of 16^d-voxel superblocks, each bin
 *     remembering its largest radius. For a superblock the bins that can reach it
 *     give the candidate balls. Over a box of grid points a ball has the bounds
 *     lower = min_box |x - c| - r and upper = max_box |x - c| - r; with U the
 *     smallest upper bound, a ball whose lower bound is >= B (the band half-width)
 *     or > U can never give the clamped field in the box, and is dropped. A box
 *     with no candidate left is filled with +B, one with U <= -B (deep inside)
 *     with -B; otherwise it is halved along each axis and its children are pruned
 *     from its list, down to 4^d voxels or 6 candidates. There every voxel takes
 *     the exact minimum over the list, visited in increasing lower bound so that it
 *     can stop early (squared distances are compared first; the square root is
 *     taken for improvements only). Superblocks are processed in z-slabs, in
 *     parallel with OpenMP; every voxel is computed independently, in a fixed
 *     order, so the image is identical for any thread count.
 *  5. Surface: vtkFlyingEdges3D (3D) or vtkFlyingEdges2D with its segments chained (2D) at
 *     value 0. The 3D surface is oriented outward; 2D curves are closed polylines
 *     (first point id repeated at the end) mapped back into the balls' plane.
 *
 * The field image (output 1) holds clamp(f, -B, B) with B = BandWidth voxel sizes
 * (the largest spacing): it is exactly f (double precision) wherever |f| < B, and
 * exactly -B or +B where f <= -B or f >= B. Contour it at values in (-B, B) only.
 * In 2D the image is a single slice; its origin and spacing are in the plane's
 * frame and its DirectionMatrix holds (u, v, normal) as columns, which most VTK
 * 9.1 filters ignore: output 0 is already placed in the balls' plane.
 *
 * Pipeline information: RequestInformation publishes output 1's WHOLE_EXTENT,
 * ORIGIN and SPACING when they do not depend on the balls, i.e. with ModelBounds
 * set and Dimension DIMENSION_3D, and its WHOLE_EXTENT alone with
 * USE_SAMPLE_DIMENSIONS and a fixed Dimension (2D: one slice). Otherwise (the
 * default DIMENSION_AUTOMATIC decides from the centres) they are set in RequestData.
 *
 * Input: any vtkPointSet with a point-data radius array (`Radius` by default).
 * Output 0: vtkPolyData, closed triangle surface (3D) or closed polylines (2D).
 * Output 1: vtkImageData, the clamped field as point scalars named `Distance`.
 *
 * Accuracy: the reconstructed boundary is within about one voxel of the exact
 * union boundary (flying edges interpolates linearly between exact samples).
 * Sharp creases of the union (where spheres meet) are cut by up to a voxel. In 2D,
 * marching squares' fixed saddle case can split a sub-voxel closed loop off a concave
 * crease; it lies within a voxel of the true boundary. The union is exact for the
 * balls it is given: balls that cross the original surface (a sampler with a
 * MinimumSeparationAngle above 0 allows it) make the reconstruction cross it too.
 *
 * Pieces (see vtkMedialPieces.h): every ball can reach every part of the surface.
 * With one MPI process per piece (ParaView, pvbatch) each process keeps its piece of
 * the balls (the sampler's share), process 0 gathers them all and builds the whole
 * union, and the other pieces are empty; the field is a minimum over the balls, so
 * the result does not depend on the number of processes. Without MPI every piece
 * requests the whole input and piece 0 computes.
 *
 * @sa vtkMedialAxisSampler vtkFlyingEdges3D vtkSignedDistance
 */
#ifndef vtkMedialBallUnion_h
#define vtkMedialBallUnion_h

#include "vtkMedialAxisReconstructionModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class vtkImageData;

class VTKMEDIALAXISRECONSTRUCTION_EXPORT vtkMedialBallUnion : public vtkPolyDataAlgorithm
{
public:
  ///@{
  /// Standard VTK methods: New() (an instance with the defaults below), the type
  /// queries of vtkTypeMacro (SafeDownCast, IsA, NewInstance) and PrintSelf() (the
  /// settings, and the figures of the last run where there are some).
  static vtkMedialBallUnion* New();
  vtkTypeMacro(vtkMedialBallUnion, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;
  ///@}

  /// How the grid is sized (ResolutionMode).
  enum ResolutionModes
  {
    USE_SAMPLE_DIMENSIONS = 0, ///< SampleDimensions points per axis
    USE_SPACING = 1            ///< an isotropic Spacing relative to the diagonal
  };
  /// What the shape is made of (Primitives).
  enum PrimitiveTypes
  {
    BALLS = 0,      ///< the union of the balls at the input's points
    MEDIAL_MESH = 1 ///< the envelope of a medial mesh: balls, cones and slabs
  };
  /// Balls or disks (Dimension).
  enum Dimensions
  {
    DIMENSION_AUTOMATIC = 0, ///< disks when the centres span exactly a plane, else balls
    DIMENSION_2D = 2,        ///< disks in the centres' plane
    DIMENSION_3D = 3         ///< balls
  };

  ///@{
  /// How the grid is sized (default USE_SAMPLE_DIMENSIONS).
  vtkSetClampMacro(ResolutionMode, int, USE_SAMPLE_DIMENSIONS, USE_SPACING);
  vtkGetMacro(ResolutionMode, int);
  void SetResolutionModeToSampleDimensions() { this->SetResolutionMode(USE_SAMPLE_DIMENSIONS); }
  void SetResolutionModeToSpacing() { this->SetResolutionMode(USE_SPACING); }
  ///@}

  ///@{
  /// Grid points per axis, padding included (default 128^3), used with
  /// USE_SAMPLE_DIMENSIONS. Each is clamped to at least 8 when set: the padding takes
  /// two voxels on every side, which leaves a smaller grid no room for the union. In
  /// 2D the first two are used along the plane's axes u and v.
  virtual void SetSampleDimensions(int i, int j, int k);
  virtual void SetSampleDimensions(const int dims[3]);
  vtkGetVector3Macro(SampleDimensions, int);
  ///@}

  ///@{
  /// The box the grid covers (xmin, xmax, ymin, ymax, zmin, zmax; default unset, all
  /// 0: the union's padded box). It is used when min <= max on every axis and it has
  /// an extent; the grid then spans it exactly (USE_SAMPLE_DIMENSIONS) or is centred
  /// on it (USE_SPACING, the spacing relative to the box's diagonal), without
  /// padding, so that two reconstructions can share a grid voxel for voxel. In 2D the
  /// grid spans the box's projection onto the balls' plane. Balls reaching beyond it
  /// are cut (with a warning: the surface is open there).
  vtkSetVector6Macro(ModelBounds, double);
  vtkGetVector6Macro(ModelBounds, double);
  bool HasModelBounds() const;
  ///@}

  ///@{
  /// Isotropic voxel size relative to the union's bounding-box diagonal, used with
  /// USE_SPACING (default 1/128).
  vtkSetClampMacro(Spacing, double, 1e-5, 0.5);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /// Margin around the union relative to its diagonal (default 0.02); never less than
  /// two voxels.
  vtkSetClampMacro(Padding, double, 0.0, 1.0);
  vtkGetMacro(Padding, double);
  ///@}

  ///@{
  /// Half-width B of the exact band of the field image, in voxel sizes (default 3, at
  /// least 2: flying edges only looks at neighbouring samples).
  vtkSetClampMacro(BandWidth, double, 2.0, 1000.0);
  vtkGetMacro(BandWidth, double);
  ///@}

  ///@{
  /// What the shape is made of (default BALLS):
  ///  - BALLS: the union of the balls at the input's points (cells are ignored);
  ///  - MEDIAL_MESH: the envelope of a medial mesh (vtkPolyData, e.g. from
  ///    vtkMedialMeshFilter or a .ma file): the balls interpolated along its lines
  ///    (cones between two spheres) and triangles (slabs between three; polygons are
  ///    fanned, strips split), and the balls of points in no cell. The field is
  ///    f(x) = min over primitives of min over interpolation weights l of
  ///    |x - c(l)| - r(l), in closed form (vtkMedialEnvelope.h), pruned like the balls
  ///    through each primitive's bounding ball and one of its vertex balls, then by its
  ///    value at a box's centre (it is 1-Lipschitz). An edge or triangle that reaches
  ///    less than 1% of a voxel beyond its vertex balls (a closed-form bound) is left
  ///    out: the reconstructed shape moves by at most that much, and a dense medial
  ///    mesh keeps only its few long or sparse pieces (on horse.ply about one edge in
  ///    seven at 128^3), which keeps the envelope close to the balls' speed.
  vtkSetClampMacro(Primitives, int, BALLS, MEDIAL_MESH);
  vtkGetMacro(Primitives, int);
  void SetPrimitivesToBalls() { this->SetPrimitives(BALLS); }
  void SetPrimitivesToMedialMesh() { this->SetPrimitives(MEDIAL_MESH); }
  ///@}

  ///@{
  /// Treat the balls as 3D balls, 2D disks, or decide from the centres (default).
  vtkSetClampMacro(Dimension, int, DIMENSION_AUTOMATIC, DIMENSION_3D);
  vtkGetMacro(Dimension, int);
  ///@}

  ///@{
  /// Largest number of grid points allowed (default 2^30); larger grids are an error.
  vtkSetClampMacro(MaximumNumberOfVoxels, vtkIdType, 64, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfVoxels, vtkIdType);
  ///@}

  ///@{
  /// OpenMP threads; 0 means all cores (default 0). The output does not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The sampled field (output 1).
  vtkImageData* GetFieldOutput();

  ///@{
  /// Figures from the last execution: the dimension used (2 or 3) and the voxel size.
  vtkGetMacro(OutputDimension, int);
  vtkGetMacro(VoxelSize, double);
  ///@}

protected:
  vtkMedialBallUnion();
  ~vtkMedialBallUnion() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The grid over [lo, hi] on the first `axes` axes: exactly (ModelBounds), or padded
  // (the union's box). Returns an error, or an empty string.
  std::string PlanGrid(const double lo[3], const double hi[3], int axes, bool exact, double origin[3],
    double spacing[3], int dims[3]) const;

  int ResolutionMode = USE_SAMPLE_DIMENSIONS;
  int SampleDimensions[3] = { 128, 128, 128 };
  double Spacing = 1.0 / 128.0;
  double Padding = 0.02;
  double ModelBounds[6] = { 0, 0, 0, 0, 0, 0 };
  double BandWidth = 3.0;
  int Dimension = DIMENSION_AUTOMATIC;
  int Primitives = BALLS;
  vtkIdType MaximumNumberOfVoxels = vtkIdType(1) << 30;
  int NumberOfThreads = 0;

  int OutputDimension = 0;
  double VoxelSize = 0.0;

private:
  vtkMedialBallUnion(const vtkMedialBallUnion&) = delete;
  void operator=(const vtkMedialBallUnion&) = delete;
};

#endif
