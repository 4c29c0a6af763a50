// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the filter tests: array access, shared-mesh lookup (error capture
// and MEDIAL_CHECK come from Testing/Cxx/MedialTestSupport.h).
#ifndef MedialTestUtilities_h
#define MedialTestUtilities_h

#include "MedialTestSupport.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace medialtest
{
inline double Value(vtkPolyData* pd, const char* name, vtkIdType i, int c = 0)
{
  return pd->GetPointData()->GetArray(name)->GetComponent(i, c);
}

inline double FieldValue(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetComponent(0, 0) : std::nan("");
}

inline double Diagonal(vtkPolyData* pd)
{
  return pd->GetLength();
}

/// Full path of a shared mesh, or empty when ../shared is absent.
inline std::string SharedMesh(const char* name)
{
  const std::string path = std::string(MEDIALAXIS_SHARED_MESH_DIR) + "/" + name;
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? path : std::string();
}

inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return std::nan("");
  }
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}

#endif
