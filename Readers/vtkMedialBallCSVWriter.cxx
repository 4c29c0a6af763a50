// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallCSVWriter.h"
#include "vtkMedialBallRecords.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <ostream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMedialBallCSVWriter);

namespace
{
// Column names of one array: NAME, NAME_x/_y/_z, or NAME_0, NAME_1, ...
void AppendColumnNames(std::string& header, vtkDataArray* array)
{
  const std::string name = array->GetName();
  const int n = array->GetNumberOfComponents();
  for (int c = 0; c < n; ++c)
  {
    header += ',';
    header += name;
    if (n == 3)
    {
      header += std::string("_") + "xyz"[c];
    }
    else if (n > 1)
    {
      header += "_" + std::to_string(c);
    }
  }
}
}

void vtkMedialBallCSVWriter::WriteRecords(std::ostream& file, const medialballs::BallRecords& records)
{
  using medialballs::AppendNumber;
  vtkPolyData* input = records.Input;
  // Every other named numeric point array, in the order the point data holds them.
  std::vector<vtkDataArray*> extra;
  std::string text = "x,y,z,radius";
  vtkPointData* pd = input->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array != records.Radius && array->GetName() && *array->GetName())
    {
      extra.push_back(array);
      AppendColumnNames(text, array);
    }
  }
  text += '\n';
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    for (double value : { p[0], p[1], p[2], records.Radius->GetComponent(i, 0) })
    {
      AppendNumber(text, value);
      text += ',';
    }
    for (vtkDataArray* array : extra)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        AppendNumber(text, array->GetComponent(i, c));
        text += ',';
      }
    }
    text.back() = '\n';
    if (text.size() > (1 << 20))
    {
      file.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void vtkMedialBallCSVWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
