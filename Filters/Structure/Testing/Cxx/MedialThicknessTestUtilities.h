// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the thickness tests: run the filter, summarise an array over chosen points.
#ifndef MedialThicknessTestUtilities_h
#define MedialThicknessTestUtilities_h

#include "MedialShapeTestUtilities.h"
#include "MedialTestUtilities.h"

#include "vtkCellData.h"
#include "vtkMedialArrayNames.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialThickness.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <functional>

namespace medialtest
{
/// Minimum, median and maximum of a point (or cell) array over the ids that `keep` accepts.
struct Summary
{
  double Min = HUGE_VAL, Median = std::nan(""), Max = -HUGE_VAL;
  vtkIdType Count = 0;
};
inline Summary Summarise(vtkDataArray* values, const std::function<bool(vtkIdType)>& keep)
{
  Summary s;
  std::vector<double> kept;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    if (keep(i))
    {
      const double v = values->GetComponent(i, 0);
      kept.push_back(v);
      s.Min = std::min(s.Min, v);
      s.Max = std::max(s.Max, v);
    }
  }
  s.Count = static_cast<vtkIdType>(kept.size());
  s.Median = Median(kept);
  return s;
}

/// Prints one row of the closed-form table: expected, then min / median / max.
inline void PrintRow(const char* what, double expected, const Summary& s)
{
  std::printf("| %s | %.6g | %.6g | %.6g | %.6g | %lld |\n", what, expected, s.Min, s.Median, s.Max,
    static_cast<long long>(s.Count));
}

/// `surface` turned about all three axes (30, 20 and 10 degrees), so that no face or
/// crease lies along an axis and the thickness is found from rounded coordinates.
inline vtkSmartPointer<vtkPolyData> Turned(vtkPolyData* surface)
{
  vtkNew<vtkTransform> turn;
  turn->RotateX(30.0);
  turn->RotateY(20.0);
  turn->RotateZ(10.0);
  vtkNew<vtkTransformPolyDataFilter> filter;
  filter->SetInputData(surface);
  filter->SetTransform(turn);
  filter->Update();
  return filter->GetOutput();
}

/// True when every value is within `relative` of `expected` (NaN fails).
inline bool Within(const Summary& s, double expected, double relative)
{
  return s.Count > 0 && std::fabs(s.Min - expected) <= relative * expected &&
    std::fabs(s.Max - expected) <= relative * expected;
}
}

#endif
