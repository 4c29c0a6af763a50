// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialBallWriter.h"
#include "vtkMedialBallRecords.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkPolyData.h"

#include <string>

vtkMedialBallWriter::vtkMedialBallWriter() = default;

vtkMedialBallWriter::~vtkMedialBallWriter()
{
  this->SetFileName(nullptr);
}

vtkPolyData* vtkMedialBallWriter::GetInput()
{
  return vtkPolyData::SafeDownCast(this->Superclass::GetInput());
}

int vtkMedialBallWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkMedialBallWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  // Validate everything and gather the records before the file is touched.
  medialballs::BallRecords records;
  const std::string problem = medialballs::GatherBalls(this->GetInput(), records);
  if (!problem.empty())
  {
    vtkErrorMacro(
      "Cannot write " << this->GetDescription() << " '" << this->FileName << "': " << problem << "; nothing written.");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  if (records.Skipped > 0)
  {
    vtkWarningMacro("Skipped " << records.Skipped << " line(s) or polygon(s) with too few points.");
  }
  std::string why;
  const unsigned long code = medialballs::WriteWhole(
    this->FileName, [&](std::ostream& file) { this->WriteRecords(file, records); }, why);
  if (code != vtkErrorCode::NoError)
  {
    vtkErrorMacro(<< why);
    this->SetErrorCode(code);
  }
}

void vtkMedialBallWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
