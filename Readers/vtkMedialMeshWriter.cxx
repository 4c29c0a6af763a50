// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialMeshWriter.h"
#include "vtkMedialBallRecords.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <unordered_set>

vtkStandardNewMacro(vtkMedialMeshWriter);

namespace
{
// Q-MAT's form: the edges made unique, then every triangle side not among them yet
// (sides a-b, b-c, c-a), in order; edges of one point are dropped.
medialballs::EdgeList EdgesWithTriangleSides(const medialballs::BallRecords& records)
{
  const auto points = static_cast<std::uint64_t>(records.Input->GetNumberOfPoints());
  std::unordered_set<std::uint64_t> seen;
  medialballs::EdgeList unique;
  auto add = [&](vtkIdType a, vtkIdType b) {
    const auto key = static_cast<std::uint64_t>(std::min(a, b)) * points + static_cast<std::uint64_t>(std::max(a, b));
    if (a != b && seen.insert(key).second)
    {
      unique.push_back({ a, b });
    }
  };
  for (const auto& e : records.Edges)
  {
    add(e[0], e[1]);
  }
  for (const auto& f : records.Faces)
  {
    add(f[0], f[1]);
    add(f[1], f[2]);
    add(f[2], f[0]);
  }
  return unique;
}
}

// The .ma text: a header line, then one line per vertex, edge and face, written in
// chunks so that the whole file need not fit in memory twice.
void vtkMedialMeshWriter::WriteRecords(std::ostream& file, const medialballs::BallRecords& records)
{
  using medialballs::AppendNumber;
  vtkPolyData* input = records.Input;
  const medialballs::EdgeList edges = EdgesWithTriangleSides(records);
  const vtkIdType nv = input->GetNumberOfPoints();
  std::string text;
  AppendNumber(text, nv);
  text += ' ';
  AppendNumber(text, static_cast<vtkIdType>(edges.size()));
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
  for (const auto& e : edges)
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
