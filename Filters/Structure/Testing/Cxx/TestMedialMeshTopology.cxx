// SPDX-License-Identifier: BSD-3-Clause
// The medial mesh is one component with the solid's Euler characteristic (1 - genus;
// 2 for the hollow sphere, whose cavity makes it a thick sphere) on generated solids of
// genus 0, 1, 2 and 3 and a hollow one at the sampler's default settings,
// counted from the output cells; and the filter's own figures agree.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialMeshFilter.h"

#include <cstdio>

int TestMedialMeshTopology(int, char*[])
{
  struct Case
  {
    const char* Name;
    int Shape;
    int Genus;
    int Euler;
    int Resolution;
  };
  const Case cases[] = { { "jack", vtkMedialShapeSource::JACK, 0, 1, 16 },
    { "capsule", vtkMedialShapeSource::CAPSULE, 0, 1, 16 }, { "box", vtkMedialShapeSource::BOX, 0, 1, 16 },
    { "torus", vtkMedialShapeSource::TORUS, 1, 0, 16 },
    { "hollow sphere", vtkMedialShapeSource::HOLLOW_SPHERE, 0, 2, 4 },
    { "ring", vtkMedialShapeSource::RINGS, 1, 0, 16 }, { "two rings", vtkMedialShapeSource::RINGS, 2, -1, 16 },
    { "three rings", vtkMedialShapeSource::RINGS, 3, -2, 16 } };
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(c.Shape, c.Genus, c.Resolution);
    vtkNew<vtkMedialMeshFilter> filter;
    medialtest::EventLog log;
    log.Watch(filter);
    filter->SetInputData(solid);
    filter->Update();
    vtkPolyData* mesh = filter->GetOutput();
    const medialtest::MeshTopology t = medialtest::CountTopology(mesh);
    std::printf("%-12s genus %d: V %lld E %lld F %lld chi %lld components %lld (filter chi %lld, "
                "solid chi %lld)\n",
      c.Name, c.Genus, static_cast<long long>(t.Vertices), static_cast<long long>(t.Edges),
      static_cast<long long>(t.Faces), static_cast<long long>(t.Euler()),
      static_cast<long long>(t.Components), static_cast<long long>(filter->GetEulerCharacteristic()),
      static_cast<long long>(filter->GetSolidEulerCharacteristic()));
    MEDIAL_CHECK(log.Errors == 0 && log.Warnings == 0, "%s: %s", c.Name, log.Text.c_str());
    MEDIAL_CHECK(filter->GetHasSolidTopology() && filter->GetSolidEulerCharacteristic() == c.Euler &&
        filter->GetSolidComponents() == 1,
      "%s: the generated solid is not the expected one", c.Name);
    MEDIAL_CHECK(t.Components == 1, "%s: %lld components", c.Name, static_cast<long long>(t.Components));
    MEDIAL_CHECK(t.Euler() == c.Euler, "%s: Euler characteristic %lld, expected %d", c.Name,
      static_cast<long long>(t.Euler()), c.Euler);
    MEDIAL_CHECK(filter->GetEulerCharacteristic() == t.Euler() && filter->GetNumberOfComponents() == 1 &&
        filter->GetNumberOfEdges() == t.Edges && t.Vertices == mesh->GetNumberOfPoints(),
      "%s: the filter's figures disagree with its cells", c.Name);
    MEDIAL_CHECK(filter->GetRemainingTetrahedra() == 0, "%s: %lld tetrahedra left", c.Name,
      static_cast<long long>(filter->GetRemainingTetrahedra()));
  }
  return EXIT_SUCCESS;
}
