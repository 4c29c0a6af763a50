// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialViewerBundle.h
 * @brief Internal: the web page's viewer script, compiled into the library.
 *
 * CMake generates the definitions (vtkMedialViewerBundle.cxx in the build tree,
 * viewer/BuildViewer.cmake): the vtk.js bundle that `npm ci` and esbuild made from
 * viewer/package-lock.json and viewer/src, or, when that could not be done (no npm
 * at configure time, MEDIALAXIS_WEB_VIEWER off, npm ci failed), an empty script and
 * the reason.
 */
#ifndef vtkMedialViewerBundle_h
#define vtkMedialViewerBundle_h

#include <cstddef>

namespace vtkMedialViewerBundle
{
/// The minified viewer script (Size bytes; empty without a viewer).
extern const char* const Text;
extern const std::size_t Size;
/// Why there is no viewer, or "" when there is one.
extern const char* const Status;
/// The bundled vtk.js version, or "".
extern const char* const VtkJsVersion;
}

#endif
