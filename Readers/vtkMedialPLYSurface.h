// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialPLYSurface.h
 * @brief Internal: reads the common binary layout of a PLY surface in one pass, for
 * vtkMedialFileReader, which hands every other PLY file to vtkPLYReader.
 *
 * The layout: `format binary_little_endian 1.0`; comment and obj_info lines; an element
 * `vertex` whose properties are exactly float x, y, z, optionally followed by float nx,
 * ny, nz; then an element `face` with only the list `vertex_indices` (count uchar,
 * ushort, uint or int; indices int or uint), each face of 3 to 255 vertices indexing a
 * vertex. It is what vtkPLYWriter, MeshLab and most scanners write for a surface.
 *
 * The output is what vtkPLYReader makes of such a file, array for array (float points,
 * point normals `Normals`, the faces as polygons), with the polygons in 32-bit
 * storage, as vtkMedialFileReader keeps them. vtkPLYReader spends about 2,500
 * instructions a face on the 1.55M-triangle horse (its generic per-property reads and
 * a cell built per face); this spends a few tens: 0.4 s less on a 2-core machine
 * before any work starts. Not installed, not wrapped.
 */
#ifndef vtkMedialPLYSurface_h
#define vtkMedialPLYSurface_h

class vtkPolyData;

/// Reads `fileName` into `output` and returns true when the file has the layout above;
/// returns false, leaving `output` as it was, for any other file, unreadable and
/// malformed ones included (vtkPLYReader then reads it, or reports why it cannot).
bool vtkMedialReadPLYSurface(const char* fileName, vtkPolyData* output);

#endif
