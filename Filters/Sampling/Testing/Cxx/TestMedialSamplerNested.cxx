// SPDX-License-Identifier: BSD-3-Clause
// Solids as users have them: shells oriented by nesting, several bodies, touching ones.
//  - vtkMedialTriangleMesh: the nesting depth and parent of every shell, cavities and
//    bodies, for nested spheres and for nested axis-aligned boxes (rays along x meet
//    box edges: the parity test must notice and try elsewhere), with each shell wound
//    either way in the file; contacts for touching and intersecting shells only.
//  - the sampler on a hollow sphere wound outward throughout (what a naive export
//    writes): the balls fill the wall, radius (R1 - R2) / 2 on the middle sphere, none
//    discarded, the same bytes whatever the windings, and a note only when the cavity
//    was wound as a solid; a solid ball in the cavity of a hollow one, every shell
//    wound as it should be: balls in the wall and in the inner ball only, no message;
//    two bodies: no message.
//  - touching and intersecting bodies: a warning that names both shells and a place.
#include "MedialTestUtilities.h"

#include "vtkMedialRepairFilter.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialShapeSource.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkCellArray.h"
#include "vtkPoints.h"

#include <cstdlib>

using namespace medialtest;

namespace
{
struct Part
{
  int Shape;
  int Resolution;
  double Size; // sphere radius, cube side
  double Offset[3];
  bool Reversed;
};

// The parts as one mesh, in order.
vtkSmartPointer<vtkPolyData> Assemble(const std::vector<Part>& parts)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (const Part& part : parts)
  {
    vtkNew<vtkMedialShapeSource> source;
    source->SetShape(part.Shape);
    source->SetResolution(part.Resolution);
    source->SetRadius(part.Size);
    source->SetBoxLengths(part.Size, part.Size, part.Size);
    source->Update();
    vtkPolyData* pd = source->GetOutput();
    const vtkIdType first = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      const double* x = pd->GetPoint(i);
      points->InsertNextPoint(x[0] + part.Offset[0], x[1] + part.Offset[1], x[2] + part.Offset[2]);
    }
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      pd->GetCellPoints(c, n, ids);
      vtkIdType t[3] = { ids[0] + first, ids[1] + first, ids[2] + first };
      if (part.Reversed)
      {
        std::swap(t[0], t[2]);
      }
      cells->InsertNextCell(3, t);
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(cells);
  return out;
}

// Every shell's depth as expected, its volume's sign from it, and the counts.
int CheckNesting(const char* label, const std::vector<Part>& parts, const std::vector<int>& depths,
  const std::vector<int>& parents)
{
  vtkMedialTriangleMesh mesh;
  std::string error;
  MEDIAL_CHECK(mesh.Build(Assemble(parts), error), "%s: %s", label, error.c_str());
  MEDIAL_CHECK(mesh.Shells.size() == depths.size(), "%s: %zu shells", label, mesh.Shells.size());
  vtkIdType cavities = 0;
  for (size_t s = 0; s < depths.size(); ++s)
  {
    const vtkMedialTriangleMesh::Shell& shell = mesh.Shells[s];
    MEDIAL_CHECK(shell.Closed && shell.Depth == depths[s] && shell.Parent == parents[s],
      "%s: shell %zu closed %d depth %d parent %d", label, s, shell.Closed, shell.Depth, shell.Parent);
    MEDIAL_CHECK((shell.Volume > 0) == (depths[s] % 2 == 0), "%s: shell %zu volume %g", label, s, shell.Volume);
    cavities += depths[s] % 2;
  }
  MEDIAL_CHECK(mesh.Cavities == cavities && mesh.Bodies == static_cast<vtkIdType>(depths.size()) - cavities &&
      mesh.Contacts.empty(),
    "%s: %lld cavities, %lld bodies, %zu contacts", label, static_cast<long long>(mesh.Cavities),
    static_cast<long long>(mesh.Bodies), mesh.Contacts.size());
  std::printf("%s: depths and parents as expected, %lld cavities\n", label, static_cast<long long>(cavities));
  return EXIT_SUCCESS;
}

vtkSmartPointer<vtkPolyData> Sample(vtkPolyData* input, EventLog& log, vtkIdType samples = 2000)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  log.Watch(sampler);
  sampler->SetInputData(input);
  sampler->SetNumberOfSamples(samples);
  // The shells as they are: the nesting and the contact warnings are what is tested
  // (the repair would join the crossing shells).
  sampler->SetRepairMode(vtkMedialRepairFilter::NONE);
  sampler->Update();
  return sampler->GetOutput();
}

double Norm(const double x[3])
{
  return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

int CheckMeshes()
{
  const int ball = vtkMedialShapeSource::SPHERE, box = vtkMedialShapeSource::BOX;
  for (bool flip : { false, true })
  {
    // Windings in the file: all alike, or alternating.
    if (CheckNesting(flip ? "three spheres, alternate windings" : "three spheres, all outward",
          { { ball, 3, 1.0, { 0, 0, 0 }, false }, { ball, 3, 0.7, { 0, 0, 0 }, flip },
            { ball, 3, 0.4, { 0, 0, 0 }, false } },
          { 0, 1, 2 }, { -1, 0, 1 }) != EXIT_SUCCESS ||
      CheckNesting(flip ? "four boxes, two nests, reversed" : "four boxes, two nests",
        { { box, 4, 3.0, { 0, 0, 0 }, flip }, { box, 3, 2.0, { 0, 0, 0 }, flip }, { box, 2, 1.0, { 0, 0, 0 }, flip },
          { box, 2, 1.0, { 5, 0, 0 }, flip } },
        { 0, 1, 2, 0 }, { -1, 0, 1, -1 }) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  // Touching (face to face, no vertex in common) and intersecting shells: a contact,
  // and neither counts for the other's depth.
  const std::vector<std::vector<Part>> touching = { { { box, 2, 1.0, { 0, 0, 0 }, false }, { box, 3, 1.0, { 1, 0, 0 }, false } },
    { { ball, 3, 1.0, { 0, 0, 0 }, false }, { ball, 3, 1.0, { 1.5, 0, 0 }, false } },
    { { ball, 3, 1.0, { 0, 0, 0 }, false }, { ball, 3, 0.5, { 0.6, 0, 0 }, false } } };
  for (const auto& parts : touching)
  {
    vtkMedialTriangleMesh mesh;
    std::string error;
    MEDIAL_CHECK(mesh.Build(Assemble(parts), error), "%s", error.c_str());
    MEDIAL_CHECK(mesh.Contacts.size() == 1 && mesh.Contacts[0].A == 0 && mesh.Contacts[0].B == 1 &&
        mesh.Cavities == 0 && mesh.Shells[1].Depth == 0,
      "%zu contacts, %lld cavities", mesh.Contacts.size(), static_cast<long long>(mesh.Cavities));
    const std::vector<std::string> warnings = mesh.Warnings();
    MEDIAL_CHECK(warnings.size() == 1 &&
        warnings[0].find("Two shells touch or intersect: shell 0 (input cell 0) and shell 1 (input cell ") == 0 &&
        warnings[0].find(" near (") != std::string::npos,
      "warnings: %s", warnings.empty() ? "none" : warnings[0].c_str());
    // The place is on both shells, within their tolerance and a triangle's size.
    std::printf("%s\n", warnings[0].c_str());
  }
  return EXIT_SUCCESS;
}
}

int TestMedialSamplerNested(int, char*[])
{
  if (CheckMeshes() != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  const int ball = vtkMedialShapeSource::SPHERE;
  // A hollow sphere (1 and 0.7) as a naive export writes it, both shells outward, then
  // with the cavity facing inward as vtkMedialShapeSource writes it: the same bytes.
  EventLog naiveLog, sourceLog;
  auto naive = Sample(Assemble({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 0.7, { 0, 0, 0 }, false } }), naiveLog);
  auto oriented = Sample(Assemble({ { ball, 4, 1.0, { 0, 0, 0 }, true }, { ball, 4, 0.7, { 0, 0, 0 }, true } }), sourceLog);
  const std::string note = naiveLog.LineWith("Nested shells handled");
  std::printf("%s\n", note.c_str());
  MEDIAL_CHECK(naiveLog.Errors == 0 && naiveLog.Warnings == 1 &&
      note.find("2 shells make 1 solid body and 1 cavity") != std::string::npos,
    "messages: %s", naiveLog.Text.c_str());
  MEDIAL_CHECK(sourceLog.Errors == 0 && sourceLog.Warnings == 0,
    "a cavity that already faces into itself is no defect, yet: %s", sourceLog.Text.c_str());
  MEDIAL_CHECK(naive->GetNumberOfPoints() == 2000 && FieldValue(naive, "DiscardedSamples") == 0.0, "%lld balls",
    static_cast<long long>(naive->GetNumberOfPoints()));
  MEDIAL_CHECK(BitDifferences(naive, oriented) == 0, "the windings in the file changed the balls");
  double worstRadius = 0.0, worstCentre = 0.0;
  for (vtkIdType i = 0; i < naive->GetNumberOfPoints(); ++i)
  {
    double c[3];
    naive->GetPoint(i, c);
    worstRadius = std::max(worstRadius, std::fabs(Value(naive, "Radius", i) - 0.15));
    worstCentre = std::max(worstCentre, std::fabs(Norm(c) - 0.85));
  }
  std::printf("hollow sphere 1 / 0.7: radius off 0.15 by %.4f at most, centre off the 0.85 sphere by %.4f\n",
    worstRadius, worstCentre);
  MEDIAL_CHECK(worstRadius < 0.005 && worstCentre < 0.005, "radius %g centre %g", worstRadius, worstCentre);

  // A solid ball (0.4) in the cavity (0.7) of a hollow ball (1): each ball is in the
  // wall or in the inner ball, and both have some.
  EventLog nestedLog;
  auto nested = Sample(Assemble({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 0.7, { 0, 0, 0 }, true },
                         { ball, 4, 0.4, { 0, 0, 0 }, false } }),
    nestedLog);
  vtkIdType wall = 0, core = 0;
  for (vtkIdType i = 0; i < nested->GetNumberOfPoints(); ++i)
  {
    double c[3];
    nested->GetPoint(i, c);
    const double r = Value(nested, "Radius", i);
    const bool inWall = std::fabs(Norm(c) - 0.85) < 0.005 && std::fabs(r - 0.15) < 0.005;
    const bool inCore = Norm(c) + r <= 0.4 + 1e-6 && r > 0.3;
    MEDIAL_CHECK(inWall || inCore, "ball %lld: |c| %g r %g", static_cast<long long>(i), Norm(c), r);
    (inWall ? wall : core)++;
  }
  std::printf("solid in a cavity in a solid: %lld balls in the wall, %lld in the inner ball, %g discarded\n",
    static_cast<long long>(wall), static_cast<long long>(core), FieldValue(nested, "DiscardedSamples"));
  MEDIAL_CHECK(wall > 0 && core > 0 && FieldValue(nested, "DiscardedSamples") == 0.0 && nestedLog.Warnings == 0,
    "%lld in the wall, %lld in the core: %s", static_cast<long long>(wall), static_cast<long long>(core),
    nestedLog.Text.c_str());

  // Two disjoint bodies, the second wound inward: two solids, no message.
  EventLog twoLog;
  auto two = Sample(Assemble({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 0.5, { 3, 0, 0 }, true } }), twoLog);
  MEDIAL_CHECK(twoLog.Warnings == 0 && FieldValue(two, "DiscardedSamples") == 0.0, "%s", twoLog.Text.c_str());
  for (vtkIdType i = 0; i < two->GetNumberOfPoints(); ++i)
  {
    double c[3];
    two->GetPoint(i, c);
    const double r = Value(two, "Radius", i);
    const bool first = c[0] < 1.5;
    const double offset[3] = { c[0] - (first ? 0.0 : 3.0), c[1], c[2] };
    MEDIAL_CHECK(Norm(offset) + r <= (first ? 1.0 : 0.5) + 1e-3, "ball %lld leaves its body", static_cast<long long>(i));
  }

  // Intersecting bodies through the sampler: the contact warning, then the discarded count.
  EventLog crossLog;
  Sample(Assemble({ { ball, 4, 1.0, { 0, 0, 0 }, false }, { ball, 4, 1.0, { 1.5, 0, 0 }, false } }), crossLog);
  MEDIAL_CHECK(crossLog.LineWith("Two shells touch or intersect: shell 0 (input cell 0) and shell 1 (input cell 5120) near (") != "" &&
      crossLog.LineWith("samples were discarded: their inward ray met the surface from outside, where shells touch or intersect") != "",
    "%s", crossLog.Text.c_str());
  return EXIT_SUCCESS;
}
