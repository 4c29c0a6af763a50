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
 * RayThickness; field data ThinAreaFraction, ThinRegionCount.
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

namespace vtkMedialArrayNames
{
// Medial balls.
constexpr const char* Radius = "Radius";
constexpr const char* SurfacePoint = "SurfacePoint";
constexpr const char* ContactPoint = "ContactPoint";
constexpr const char* SeparationAngle = "SeparationAngle";
constexpr const char* SourceCellId = "SourceCellId";
constexpr const char* GovernorCount = "GovernorCount";
constexpr const char* MedialPointType = "MedialPointType";

// Cells of the 3D medial mesh (vtkMedialMeshFilter): 0 isolated ball, 1 curve edge,
// 2 seam edge, 3 sheet triangle.
constexpr const char* MedialCellType = "MedialCellType";

// Cells of the 2D medial graph and of the sampler's links.
constexpr const char* ArcType = "ArcType";
constexpr const char* PolygonId = "PolygonId";
constexpr const char* InitialLink = "InitialLink";

// Thickness on the input surface.
constexpr const char* Thickness = "Thickness";
constexpr const char* MedialRadius = "MedialRadius";
constexpr const char* MedialCentre = "MedialCentre";
constexpr const char* RayThickness = "RayThickness";
constexpr const char* ThinAreaFraction = "ThinAreaFraction";
constexpr const char* ThinRegionCount = "ThinRegionCount";

// Field data of the sampler.
constexpr const char* RequestedSamples = "RequestedSamples";
constexpr const char* DiscardedSamples = "DiscardedSamples";
constexpr const char* MeanIterations = "MeanIterations";
constexpr const char* CappedSamples = "CappedSamples";
constexpr const char* EvaluatedSamples = "EvaluatedSamples";
constexpr const char* SeedSamples = "SeedSamples";
constexpr const char* CoverageReached = "CoverageReached";
constexpr const char* MaxCoverageGap = "MaxCoverageGap";
// The medial mesh's topology, and the solid's when the surface is closed.
constexpr const char* EulerCharacteristic = "EulerCharacteristic";
constexpr const char* Components = "Components";
constexpr const char* SolidEulerCharacteristic = "SolidEulerCharacteristic";
constexpr const char* SolidComponents = "SolidComponents";

// The reconstruction's field image.
constexpr const char* Distance = "Distance";

// Measures of a reconstruction and of the balls.
constexpr const char* SurfaceDistance = "SurfaceDistance";
constexpr const char* Protrusion = "Protrusion";
constexpr const char* VertexMaxError = "VertexMaxError";
constexpr const char* VertexMeanError = "VertexMeanError";
constexpr const char* AreaMaxError = "AreaMaxError";
constexpr const char* AreaMeanError = "AreaMeanError";
constexpr const char* MaxProtrusion = "MaxProtrusion";

// Pruning (vtkMedialPruneFilter): the threshold from which a cell is removed.
constexpr const char* Significance = "Significance";

// The repair's report (vtkMedialRepairFilter), field data of its output and, when a
// filter repaired its input (RepairMode), of that filter's output: one line per step
// (a string array), then the counts and the distance.
constexpr const char* RepairReport = "RepairReport";
constexpr const char* RepairInputValid = "RepairInputValid";
constexpr const char* RepairIntersectingPairs = "RepairIntersectingPairs";
constexpr const char* RepairWeldedPoints = "RepairWeldedPoints";
constexpr const char* RepairDroppedTriangles = "RepairDroppedTriangles";
constexpr const char* RepairSplitPoints = "RepairSplitPoints";
constexpr const char* RepairStitchedEdges = "RepairStitchedEdges";
constexpr const char* RepairRewoundTriangles = "RepairRewoundTriangles";
constexpr const char* RepairTurnedShells = "RepairTurnedShells";
constexpr const char* RepairFilledHoles = "RepairFilledHoles";
constexpr const char* RepairUnfilledHoles = "RepairUnfilledHoles";
constexpr const char* RepairResolvedShells = "RepairResolvedShells";
constexpr const char* RepairJoinedShells = "RepairJoinedShells";
constexpr const char* RepairTouchingShells = "RepairTouchingShells";
constexpr const char* RepairRemovedSheets = "RepairRemovedSheets";
constexpr const char* RepairWrapped = "RepairWrapped";
constexpr const char* RepairMaximumDistance = "RepairMaximumDistance";
constexpr const char* RepairBuriedArea = "RepairBuriedArea";
}

#endif
