// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkMedialDisjointSets
 * @brief Internal: union-find over the ids 0..n-1 (path halving; a set's root is its
 * smallest id, so the result does not depend on the order of the joins).
 *
 * Used for the connected components of the medial mesh, of its complex while it is
 * built, and of a surface's triangles.
 */
#ifndef vtkMedialDisjointSets_h
#define vtkMedialDisjointSets_h

#include "vtkType.h"

#include <algorithm>
#include <numeric>
#include <vector>

class vtkMedialDisjointSets
{
public:
  explicit vtkMedialDisjointSets(vtkIdType n)
    : Parent(static_cast<size_t>(n))
  {
    std::iota(this->Parent.begin(), this->Parent.end(), vtkIdType(0));
  }

  /// The root of x's set.
  vtkIdType Find(vtkIdType x)
  {
    while (this->Parent[x] != x)
    {
      x = this->Parent[x] = this->Parent[this->Parent[x]];
    }
    return x;
  }

  /// Joins the sets of a and b; false when they were one already.
  bool Join(vtkIdType a, vtkIdType b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a == b)
    {
      return false;
    }
    this->Parent[std::max(a, b)] = std::min(a, b);
    return true;
  }

private:
  std::vector<vtkIdType> Parent;
};

#endif
