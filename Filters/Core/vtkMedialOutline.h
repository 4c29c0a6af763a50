// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialOutline.h
 * @brief Internal: the outline of a planar shape, as the pictures and the web page draw it.
 *
 * A planar shape comes as polygon cells (one per loop, holes as loops of their own),
 * as a triangulated region, or as closed polylines. Its outline is the edges used by
 * exactly one polygon cell (vtkFeatureEdges' boundary edges, after coincident points
 * are merged), so that a triangulated region shows its boundary and not every
 * triangle; the polylines are kept as they are. The output holds lines only, on
 * points of its own.
 */
#ifndef vtkMedialOutline_h
#define vtkMedialOutline_h

#include "vtkSmartPointer.h"

class vtkPolyData;

namespace vtkMedialOutline
{
/// The boundary edges of `shape`'s polygons and its polylines, as lines.
vtkSmartPointer<vtkPolyData> Boundary(vtkPolyData* shape);
}

#endif
