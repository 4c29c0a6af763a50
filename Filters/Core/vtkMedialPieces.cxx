// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialPieces.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <vector>

vtkMedialPieces vtkMedialPieces::FromRequest(vtkInformation* outInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkMedialPieces pieces;
  if (outInfo && outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES()))
  {
    pieces.NumberOfPieces = std::max(1, outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()));
    pieces.Piece = outInfo->Has(SDDP::UPDATE_PIECE_NUMBER()) ? outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()) : 0;
  }
  // ParaView and pvbatch give piece r of R to rank r of R: then a gather reaches
  // every piece. Any other layout (serial streaming) is not distributed.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (pieces.NumberOfPieces > 1 && controller &&
    controller->GetNumberOfProcesses() == pieces.NumberOfPieces &&
    controller->GetLocalProcessId() == pieces.Piece)
  {
    pieces.Controller = controller;
  }
  return pieces;
}

vtkSmartPointer<vtkPolyData> vtkMedialPieces::GatherToFirst(
  vtkPointSet* input, vtkDataArray* values, const char* name, std::string& error) const
{
  // Each piece sends (x, y, z, value) tuples; a count of -1 flags a piece that has
  // points but no values, so that process 0 can report it instead of dropping them.
  const vtkIdType points = input ? input->GetNumberOfPoints() : 0;
  const bool usable = points == 0 ||
    (values && values->GetNumberOfComponents() == 1 && values->GetNumberOfTuples() == points);
  std::vector<double> local;
  if (usable)
  {
    local.reserve(static_cast<size_t>(4 * points));
    for (vtkIdType i = 0; i < points; ++i)
    {
      double p[3];
      input->GetPoint(i, p);
      local.insert(local.end(), { p[0], p[1], p[2], values->GetComponent(i, 0) });
    }
  }
  const int processes = this->Controller->GetNumberOfProcesses();
  const bool first = this->Controller->GetLocalProcessId() == 0;
  const vtkIdType sent = usable ? static_cast<vtkIdType>(local.size()) : -1;
  std::vector<vtkIdType> counts(first ? processes : 1, 0);
  this->Controller->Gather(&sent, counts.data(), 1, 0);

  std::vector<vtkIdType> lengths(processes, 0), offsets(processes, 0);
  vtkIdType total = 0;
  if (first)
  {
    for (int r = 0; r < processes; ++r)
    {
      if (counts[r] < 0 && error.empty())
      {
        error = "piece " + std::to_string(r) + " has points but no one-component point-data array '" +
          name + "'";
      }
      lengths[r] = std::max<vtkIdType>(0, counts[r]);
      offsets[r] = total;
      total += lengths[r];
    }
  }
  std::vector<double> all(static_cast<size_t>(std::max<vtkIdType>(total, 1)));
  this->Controller->GatherV(local.data(), all.data(), static_cast<vtkIdType>(local.size()),
    lengths.data(), offsets.data(), 0);
  if (!first)
  {
    return nullptr;
  }

  auto gathered = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> centres;
  centres->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> gatheredValues;
  gatheredValues->SetName(name);
  const vtkIdType n = total / 4;
  centres->SetNumberOfPoints(n);
  gatheredValues->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    centres->SetPoint(i, all[4 * i], all[4 * i + 1], all[4 * i + 2]);
    gatheredValues->SetValue(i, all[4 * i + 3]);
  }
  gathered->SetPoints(centres);
  gathered->GetPointData()->AddArray(gatheredValues);
  return gathered;
}
