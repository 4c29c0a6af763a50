// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialArrayNames.h
 * @brief The names of every array the medialaxis filters read or write.
 *
 * These names are a stable contract: tests, scripts, the ParaView plugin and users'
 * pipelines look arrays up by them. Use the constants instead of string literals.
 *
 * Point data of medial balls (vtkMedialAxisSampler and the structure filters):
 *  - Radius (double): ball radius;
 *  - SurfacePoint (double x3): the surface sample P the ball is tangent at;
 *  - ContactPoint (double x3): the second touching point;
 *  - SeparationAngle (double, degrees): the angle P-centre-contact;
 *  - SourceCellId (vtkIdType): the input cell that P lies on;
 *  - GovernorCount (int): surface regions the ball touches (2D: edges and reflex
 *    vertices; 3D: faces, reflex edges and reflex vertices, regions less than theta
 *    apart counting as one; see vtkMedialBallClassifier);
 *  - MedialPointType (int):
 *    2D (vtkMedialJunctionFilter): 0 end, 1 regular, 2 junction;
 *    3D (vtkMedialBallClassifier): 0 rim (at most one governor, or a radius within the
 *    contact tolerance: a sheet's free boundary), 1 sheet (2 governors), 2 seam (3),
 *    3 junction (4 or more).
 *
 * Cell data of the 2D medial graph: ArcType (0 linear, 1 parabolic), PolygonId.
 * Cell data of the 3D medial mesh: MedialCellType (0 isolated ball, 1 curve edge,
 * 2 seam edge, 3 sheet triangle).
 * Cell data of the sampler's links: InitialLink.
 *
 * Point and cell data on a surface (thickness): Thickness, MedialRadius, MedialCentre,
 * RayThickness, TangentThickness; field data ThinAreaFraction, ThinRegionCount.
 *
 * Field data: RequestedSamples, DiscardedSamples, MeanIterations, CappedSamples,
 * EvaluatedSamples, SeedSamples, CoverageReached, MaxCoverageGap; the medial mesh's
 * EulerCharacteristic and Components, and the solid's SolidEulerCharacteristic and
 * SolidComponents.
 *
 * The distance field of a reconstruction (vtkMedialBallUnion output 1): Distance.
 *
 * Measures (vtkMedialReconstructionError, vtkMedialBallProtrusion): point data
 * SurfaceDistance (a vertex's distance to the other shape) and Protrusion (a ball's
 * radius minus its centre's distance to the surface); field data VertexMaxError,
 * VertexMeanError, AreaMaxError, AreaMeanError (two components: reconstruction to
 * original, original to reconstruction) and MaxProtrusion, relative to the diagonal.
 *
 * Pruning (vtkMedialPruneFilter): cell data Significance, the threshold of the chosen
 * measure from which pruning removes the cell.
 */
#ifndef vtkMedialArrayNames_h
#define vtkMedialArrayNames_h

/// The array names, one constant per array (the file comment says which filter writes each).
namespace vtkMedialArrayNames
{
/// Point data of balls (double): the ball radius.
constexpr const char* Radius = "Radius";
/// Point data of balls (double x3): the surface sample P the ball is tangent at.
constexpr const char* SurfacePoint = "SurfacePoint";
/// Point data of balls (double x3): the second touching point.
constexpr const char* ContactPoint = "ContactPoint";
/// Point data of balls (double): the angle P-centre-contact, in degrees.
constexpr const char* SeparationAngle = "SeparationAngle";
/// Point data of balls (vtkIdType): the input cell that P lies on.
constexpr const char* SourceCellId = "SourceCellId";
/// Point data of balls (int): the surface regions the ball touches.
constexpr const char* GovernorCount = "GovernorCount";
/// Point data (int): 2D 0 end, 1 regular, 2 junction; 3D 0 rim, 1 sheet, 2 seam, 3 junction.
constexpr const char* MedialPointType = "MedialPointType";

/// Cell data of the medial mesh (int): 0 ball, 1 curve edge, 2 seam edge, 3 sheet triangle.
constexpr const char* MedialCellType = "MedialCellType";

/// Cell data of the 2D medial graph (int): 0 linear, 1 parabolic.
constexpr const char* ArcType = "ArcType";
/// Cell data of the 2D medial graph: the input polygon the arc belongs to.
constexpr const char* PolygonId = "PolygonId";
/// Cell data of the sampler's links (closest-neighbor): the seed link a line refines.
constexpr const char* InitialLink = "InitialLink";

/// Point and cell data of a surface: the wall thickness (the inscribed ball's diameter).
constexpr const char* Thickness = "Thickness";
/// Point and cell data of a surface: the radius of the inscribed ball behind it.
constexpr const char* MedialRadius = "MedialRadius";
/// Point and cell data of a surface (double x3): that ball's centre.
constexpr const char* MedialCentre = "MedialCentre";
/// Point and cell data of a surface: the distance along the inward normal.
constexpr const char* RayThickness = "RayThickness";
/// Point and cell data of a surface: the diameter of the ball tangent along the normal alone.
constexpr const char* TangentThickness = "TangentThickness";
/// Field data of a surface: the share of the area thinner than the threshold.
constexpr const char* ThinAreaFraction = "ThinAreaFraction";
/// Field data of a surface: the number of regions thinner than the threshold.
constexpr const char* ThinRegionCount = "ThinRegionCount";

/// Field data of the sampler: the samples asked for.
constexpr const char* RequestedSamples = "RequestedSamples";
/// Field data of the sampler: the samples that gave no ball.
constexpr const char* DiscardedSamples = "DiscardedSamples";
/// Field data of the sampler: the mean iterations per ball.
constexpr const char* MeanIterations = "MeanIterations";
/// Field data of the sampler: the samples that reached the iteration cap.
constexpr const char* CappedSamples = "CappedSamples";
/// Field data of the sampler's iterative strategies: the samples evaluated.
constexpr const char* EvaluatedSamples = "EvaluatedSamples";
/// Field data of the sampler's iterative strategies: the seeds (the first points).
constexpr const char* SeedSamples = "SeedSamples";
/// Field data of the sampler (0 or 1): whether the coverage stop was reached.
constexpr const char* CoverageReached = "CoverageReached";
/// Field data of the sampler: the largest gap to the union of balls / diagonal.
constexpr const char* MaxCoverageGap = "MaxCoverageGap";
/// Field data of the medial mesh: its Euler characteristic.
constexpr const char* EulerCharacteristic = "EulerCharacteristic";
/// Field data of the medial mesh: its connected components.
constexpr const char* Components = "Components";
/// Field data of the medial mesh: the solid's Euler characteristic.
constexpr const char* SolidEulerCharacteristic = "SolidEulerCharacteristic";
/// Field data of the medial mesh: the solid's connected components.
constexpr const char* SolidComponents = "SolidComponents";

/// Point data of the reconstruction's image: the clamped distance-like field.
constexpr const char* Distance = "Distance";

/// Point data of a measured shape: a vertex's distance to the other shape.
constexpr const char* SurfaceDistance = "SurfaceDistance";
/// Point data of balls: the radius minus the centre's distance to the surface.
constexpr const char* Protrusion = "Protrusion";
/// Field data (2 components): the largest vertex distance / diagonal.
constexpr const char* VertexMaxError = "VertexMaxError";
/// Field data (2 components): the mean vertex distance / diagonal.
constexpr const char* VertexMeanError = "VertexMeanError";
/// Field data (2 components): the largest distance of area samples / diagonal.
constexpr const char* AreaMaxError = "AreaMaxError";
/// Field data (2 components): the mean distance of area samples / diagonal.
constexpr const char* AreaMeanError = "AreaMeanError";
/// Field data of balls: the largest protrusion / diagonal.
constexpr const char* MaxProtrusion = "MaxProtrusion";

/// Cell data of a pruned axis: the threshold from which pruning removes the cell.
constexpr const char* Significance = "Significance";

/// Field data (strings) of the repair's output, and of a filter's output when it repaired its
/// input (RepairMode): one line per step that ran. The Repair* arrays below are one value each.
constexpr const char* RepairReport = "RepairReport";
/// Field data: 1 when the input was a valid solid, passed through untouched.
constexpr const char* RepairInputValid = "RepairInputValid";
/// Field data: triangle pairs of the input that intersect (CGAL's exact predicates).
constexpr const char* RepairIntersectingPairs = "RepairIntersectingPairs";
/// Field data: points merged by the weld.
constexpr const char* RepairWeldedPoints = "RepairWeldedPoints";
/// Field data: invalid, degenerate and duplicate triangles dropped.
constexpr const char* RepairDroppedTriangles = "RepairDroppedTriangles";
/// Field data: points split off non-manifold edges and corners.
constexpr const char* RepairSplitPoints = "RepairSplitPoints";
/// Field data: pairs of border edges stitched.
constexpr const char* RepairStitchedEdges = "RepairStitchedEdges";
/// Field data: triangles turned over to agree with the rest of their shell.
constexpr const char* RepairRewoundTriangles = "RepairRewoundTriangles";
/// Field data: shells wound inward as a whole, turned over.
constexpr const char* RepairTurnedShells = "RepairTurnedShells";
/// Field data: holes filled (refined and faired).
constexpr const char* RepairFilledHoles = "RepairFilledHoles";
/// Field data: holes larger than MaximumHoleSize, left to the wrap.
constexpr const char* RepairUnfilledHoles = "RepairUnfilledHoles";
/// Field data: shells that crossed themselves, made to bound their solid.
constexpr const char* RepairResolvedShells = "RepairResolvedShells";
/// Field data: unions of overlapping shells made (one shell fewer each).
constexpr const char* RepairJoinedShells = "RepairJoinedShells";
/// Field data: pairs of shells that only touch, kept as separate bodies.
constexpr const char* RepairTouchingShells = "RepairTouchingShells";
/// Field data: open pieces removed from inside the solid.
constexpr const char* RepairRemovedSheets = "RepairRemovedSheets";
/// Field data: 1 when the output is the alpha wrap.
constexpr const char* RepairWrapped = "RepairWrapped";
/// Field data: the largest distance from the input to the output / diagonal.
constexpr const char* RepairMaximumDistance = "RepairMaximumDistance";
/// Field data: the share of the input's area buried inside the repaired solid.
constexpr const char* RepairBuriedArea = "RepairBuriedArea";
}

#endif
