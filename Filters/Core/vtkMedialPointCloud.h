// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialPointCloud
 * @brief Internal: a built vtkStaticPointLocator over coordinates the caller owns.
 *
 * The coordinates (x0 y0 z0 x1 ...) are wrapped in a vtkDoubleArray that reads them in
 * place (no copy, never freed by VTK), so they must outlive the locator. Used where an
 * engine keeps its points in a std::vector (the repair's weld, the
 * coverage selection's pairs) and wants VTK's bucket locator over them.
 */
#ifndef vtkMedialPointCloud_h
#define vtkMedialPointCloud_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkStaticPointLocator;

namespace vtkMedialPointCloud
{
/// A locator over `count` points at `xyz`, built (BuildLocator has run).
vtkSmartPointer<vtkStaticPointLocator> Locator(const double* xyz, vtkIdType count);
}

#endif
