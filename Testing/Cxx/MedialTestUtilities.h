// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the filter tests: array access, shared-mesh lookup (error capture
// and MEDIAL_CHECK come from Testing/Cxx/MedialTestSupport.h).
#ifndef MedialTestUtilities_h
#define MedialTestUtilities_h

#include "MedialTestSupport.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
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

/// A copy of `surface` with Gaussian noise of sigma = fraction * diagonal added to every
/// coordinate of every point (mt19937_64 with `seed`: the same noise on every platform
/// that has the same standard library).
inline vtkSmartPointer<vtkPolyData> WithGaussianNoise(vtkPolyData* surface, double fraction, unsigned seed)
{
  auto noisy = vtkSmartPointer<vtkPolyData>::New();
  noisy->DeepCopy(surface);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, fraction * surface->GetLength());
  for (vtkIdType i = 0; i < noisy->GetNumberOfPoints(); ++i)
  {
    double x[3];
    noisy->GetPoint(i, x);
    for (double& c : x)
    {
      c += gauss(random);
    }
    noisy->GetPoints()->SetPoint(i, x);
  }
  noisy->GetPoints()->Modified();
  return noisy;
}

/// A copy of `surface` turned by `degrees` about the axis (1, 2, 3): the tests' one generic
/// rotation, so that no face or edge of a generated shape lies along a coordinate axis.
inline vtkSmartPointer<vtkPolyData> Turned(vtkPolyData* surface, double degrees)
{
  vtkNew<vtkTransform> rotation;
  rotation->RotateWXYZ(degrees, 1.0, 2.0, 3.0);
  vtkNew<vtkTransformPolyDataFilter> turned;
  turned->SetInputData(surface);
  turned->SetTransform(rotation);
  turned->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  turned->Update();
  return turned->GetOutput();
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

/// Number of points that differ bit for bit; -1 when the point counts differ.
inline long long PointDifferences(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return -1;
  }
  long long diff = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double x[3], y[3];
    a->GetPoint(i, x);
    b->GetPoint(i, y);
    diff += std::memcmp(x, y, sizeof(x)) != 0;
  }
  return diff;
}

/// Number of values that differ bit for bit (points, point arrays, lines); -1 when
/// the shapes differ.
inline long long BitDifferences(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfLines() != b->GetNumberOfLines())
  {
    return -1;
  }
  long long diff = PointDifferences(a, b);
  for (const char* name : { "Radius", "SurfacePoint", "ContactPoint", "SeparationAngle", "SourceCellId" })
  {
    vtkDataArray* u = a->GetPointData()->GetArray(name);
    vtkDataArray* v = b->GetPointData()->GetArray(name);
    if (!u || !v)
    {
      return -1;
    }
    for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < u->GetNumberOfComponents(); ++c)
      {
        const double s = u->GetComponent(i, c), t = v->GetComponent(i, c);
        diff += std::memcmp(&s, &t, sizeof(double)) != 0;
      }
    }
  }
  vtkIdType na, nb;
  const vtkIdType *ia, *ib;
  vtkCellArray* la = a->GetLines();
  vtkCellArray* lb = b->GetLines();
  la->InitTraversal();
  lb->InitTraversal();
  while (la->GetNextCell(na, ia) && lb->GetNextCell(nb, ib))
  {
    diff += na != nb || ia[0] != ib[0] || ia[na - 1] != ib[nb - 1];
  }
  return diff;
}

/// Distance from p to the segment [a, b] (a point when a == b).
inline double PointSegmentDistance(const double p[3], const double a[3], const double b[3])
{
  double ab[3], ap[3];
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
  }
  const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  double t = len2 > 0 ? (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  double d2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = ap[k] - t * ab[k];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

/// A shared PLY mesh (e.g. "horse.ply"), or null with a "skipped" line when ../shared is absent.
inline vtkSmartPointer<vtkPolyData> ReadSharedPLY(const char* name)
{
  const std::string path = SharedMesh(name);
  if (path.empty())
  {
    std::printf("shared meshes absent: %s part skipped\n", name);
    return nullptr;
  }
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
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
