// SPDX-License-Identifier: BSD-3-Clause
// Hollow parts and several bodies: a solid ball inside a spherical cavity inside a solid
// ball (shells of radius 1, 0.7 and 0.4: walls of 0.3 around the cavity, a core 0.8
// thick), whatever the winding of each shell in the file; then two disjoint bodies.
// With ThinThreshold 0.5, the thin cells are the two walls' shells: their area share is
// (1 + 0.7^2) / (1 + 0.7^2 + 0.4^2) and they form 2 regions.
#include "MedialThicknessTestUtilities.h"

#include "vtkAppendPolyData.h"
#include "vtkReverseSense.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
// A geodesic sphere of `radius` at `x` on the x axis, its triangles reversed if asked.
vtkSmartPointer<vtkPolyData> Ball(double radius, double x, bool reversed)
{
  auto sphere = MakeShape(vtkMedialShapeSource::SPHERE, 4, [&](vtkMedialShapeSource* s) { s->SetRadius(radius); });
  vtkNew<vtkTransform> move;
  move->Translate(x, 0, 0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(sphere);
  moved->SetTransform(move);
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputConnection(moved->GetOutputPort());
  vtkAlgorithm* last = reversed ? static_cast<vtkAlgorithm*>(reverse) : moved;
  last->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(vtkPolyData::SafeDownCast(last->GetOutputDataObject(0)));
  return out;
}

vtkSmartPointer<vtkPolyData> Append(const std::vector<vtkSmartPointer<vtkPolyData>>& parts)
{
  vtkNew<vtkAppendPolyData> append;
  for (const auto& p : parts)
  {
    append->AddInputData(p);
  }
  append->Update();
  return append->GetOutput();
}

double Norm(const double x[3])
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}
}

int TestMedialThicknessNested(int, char*[])
{
  const double radii[3] = { 1.0, 0.7, 0.4 };
  const double expected[3] = { 0.3, 0.3, 0.8 };
  // Windings of the three shells in the file: as generated (all outward), all reversed,
  // and the cavity the only one facing outward.
  const bool windings[3][3] = { { false, false, false }, { true, true, true }, { true, false, true } };
  std::vector<double> first;
  for (const auto& reversed : windings)
  {
    auto nested = Append({ Ball(radii[0], 0, reversed[0]), Ball(radii[1], 0, reversed[1]), Ball(radii[2], 0, reversed[2]) });
    vtkNew<vtkMedialThickness> thickness;
    thickness->SetInputData(nested);
    thickness->SetThinThreshold(0.5);
    EventLog log;
    log.Watch(thickness);
    thickness->Update();
    vtkPolyData* out = thickness->GetOutput();
    // A note only when the cavity's shell (radius 0.7) was wound as a solid.
    const bool cavityWoundAsSolid = !reversed[1];
    const std::string nestedNote = log.LineWith("Nested shells handled");
    std::printf("warning: %s\n", nestedNote.c_str());
    MEDIAL_CHECK(log.Errors == 0 &&
        (cavityWoundAsSolid ? log.Warnings == 1 &&
              nestedNote.find("3 shells make 2 solid bodies and 1 cavity") != std::string::npos &&
              nestedNote.find("shell 1 (input cell 5120) inside shell 0 (input cell 0)") != std::string::npos
                            : log.Warnings == 0),
      "messages: %s", log.Text.c_str());
    vtkDataArray* values = out->GetPointData()->GetArray(vtkMedialArrayNames::Thickness);
    std::printf("| shell | expected | min | median | max | points |\n|---|---|---|---|---|---|\n");
    for (int s = 0; s < 3; ++s)
    {
      const Summary shell = Summarise(values, [&](vtkIdType i) {
        double x[3];
        out->GetPoint(i, x);
        return std::fabs(Norm(x) - radii[s]) < 1e-9;
      });
      const std::string name = "sphere of radius " + std::to_string(radii[s]).substr(0, 3);
      PrintRow(name.c_str(), expected[s], shell);
      MEDIAL_CHECK(Within(shell, expected[s], 0.02) && shell.Count == out->GetNumberOfPoints() / 3,
        "shell %d: %g to %g over %lld points", s, shell.Min, shell.Max, static_cast<long long>(shell.Count));
    }
    const double share = (1.0 + 0.49) / (1.0 + 0.49 + 0.16);
    std::printf("thin (below 0.5): %.6f of the area (expected %.6f), %lld regions\n",
      thickness->GetThinAreaFraction(), share, static_cast<long long>(thickness->GetThinRegionCount()));
    MEDIAL_CHECK(std::fabs(thickness->GetThinAreaFraction() - share) < 1e-6 && thickness->GetThinRegionCount() == 2,
      "thin area %g, %lld regions", thickness->GetThinAreaFraction(), static_cast<long long>(thickness->GetThinRegionCount()));
    MEDIAL_CHECK(FieldValue(out, vtkMedialArrayNames::ThinRegionCount) == 2.0, "field data");
    // The same values whatever the winding in the file.
    std::vector<double> now;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      now.push_back(values->GetComponent(i, 0));
    }
    MEDIAL_CHECK(first.empty() || now == first, "the winding in the file changed the thickness");
    first = now;
  }

  // Two disjoint bodies are two solids: thickness 2 and 1, no message.
  auto two = Append({ Ball(1.0, 0, false), Ball(0.5, 3, true) });
  vtkNew<vtkMedialThickness> thickness;
  thickness->SetInputData(two);
  EventLog log;
  log.Watch(thickness);
  thickness->Update();
  MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "messages: %s", log.Text.c_str());
  vtkPolyData* out = thickness->GetOutput();
  for (int body = 0; body < 2; ++body)
  {
    const Summary s = Summarise(out->GetPointData()->GetArray(vtkMedialArrayNames::Thickness),
      [&](vtkIdType i) { return (out->GetPoint(i)[0] > 1.5) == (body == 1); });
    PrintRow(body ? "second body, radius 0.5" : "first body, radius 1", body ? 1.0 : 2.0, s);
    MEDIAL_CHECK(Within(s, body ? 1.0 : 2.0, 0.02), "body %d: %g to %g", body, s.Min, s.Max);
  }
  return EXIT_SUCCESS;
}
