// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshWriter.h"
#include "vtkMedialBallRecords.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <ostream>
#include <string>

vtkStandardNewMacro(vtkMedialMeshWriter);

// The .ma text: a header line, then one line per vertex, edge and face, written in
// chunks so that the whole file need not fit in memory twice.
void vtkMedialMeshWriter::WriteRecords(std::ostream& file, const medialballs::BallRecords& records)
{
  using medialballs::AppendNumber;
  vtkPolyData* input = records.Input;
  const vtkIdType nv = input->GetNumberOfPoints();
  std::string text;
  AppendNumber(text, nv);
  text += ' ';
  AppendNumber(text, static_cast<vtkIdType>(records.Edges.size()));
  text += ' ';
  AppendNumber(text, static_cast<vtkIdType>(records.Faces.size()));
  text += '\n';
  auto flush = [&]() {
    if (text.size() > (1 << 20))
    {
      file.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  };
  for (vtkIdType i = 0; i < nv; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    text += 'v';
    for (double value : { p[0], p[1], p[2], records.Radius->GetComponent(i, 0) })
    {
      text += ' ';
      AppendNumber(text, value);
    }
    text += '\n';
    flush();
  }
  // A record line: the tag, then the ids.
  auto appendIds = [&](char tag, const vtkIdType* ids, int count) {
    text += tag;
    for (int k = 0; k < count; ++k)
    {
      text += ' ';
      AppendNumber(text, ids[k]);
    }
    text += '\n';
    flush();
  };
  for (const auto& e : records.Edges)
  {
    appendIds('e', e.data(), 2);
  }
  for (const auto& f : records.Faces)
  {
    appendIds('f', f.data(), 3);
  }
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void vtkMedialMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
