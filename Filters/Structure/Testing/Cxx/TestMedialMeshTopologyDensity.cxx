// SPDX-License-Identifier: BSD-3-Clause
// The medial mesh has the solid's topology at every density and seed: on generated
// valid solids of known topology (a ball, a torus, a genus-2 solid and a hollow ball,
// coarsely and finely tessellated), sampled at several densities with three seeds
// each, the mesh counted from its cells is one component with the solid's Euler
// characteristic (1 - genus; 2 for the hollow ball), the filter reports the same and
// warns of nothing.
//
// The coarse shapes are the hard ones: their medial axes are made of flat sheets lying
// in the bisector planes of the faces at convex edges, so the mesh's simplices are
// coplanar with surface edges and double-precision crossing tests there were noise
// (the coarse torus had Euler characteristic -6 to -1 instead of 0 at every density
// and seed before the tests became exact). MEDIAL_TOPOLOGY_SAMPLES (a comma-separated
// list) replaces the densities, e.g. 50000,100000,200000 for a long run.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialMeshFilter.h"
#include "vtkMedialShapeSource.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int TestMedialMeshTopologyDensity(int, char*[])
{
  struct Case
  {
    const char* Name;
    int Shape;
    int Genus;
    int Resolution;
    int Euler; // of the solid: 1 - genus, or 2 for a ball with one cavity
  };
  const Case cases[] = { { "coarse ball", vtkMedialShapeSource::SPHERE, 0, 1, 1 },
    { "coarse torus", vtkMedialShapeSource::TORUS, 1, 2, 0 },
    { "coarse torus 3", vtkMedialShapeSource::TORUS, 1, 3, 0 },
    { "torus", vtkMedialShapeSource::TORUS, 1, 16, 0 },
    { "coarse genus 2", vtkMedialShapeSource::RINGS, 2, 4, -1 },
    { "coarse hollow ball", vtkMedialShapeSource::HOLLOW_SPHERE, 0, 2, 2 } };
  std::vector<vtkIdType> densities = { 5000, 20000 };
  if (const char* list = std::getenv("MEDIAL_TOPOLOGY_SAMPLES"))
  {
    densities.clear();
    for (const char* p = list; *p;)
    {
      char* end = nullptr;
      densities.push_back(std::strtoll(p, &end, 10));
      p = *end == ',' ? end + 1 : end + std::strlen(end);
    }
  }
  const long long seeds[] = { 1, 7, 42 };
  int failures = 0;
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> solid = medialtest::MakeSolid(c.Shape, c.Genus, c.Resolution);
    for (vtkIdType samples : densities)
    {
      for (long long seed : seeds)
      {
        vtkNew<vtkMedialAxisSampler> sampler;
        sampler->SetInputData(solid);
        sampler->SetNumberOfSamples(samples);
        sampler->SetRandomSeed(seed);
        sampler->SetNumberOfThreads(2);
        vtkNew<vtkMedialMeshFilter> filter;
        medialtest::EventLog log;
        log.Watch(filter);
        filter->SetInputData(solid);
        filter->SetBallsConnection(sampler->GetOutputPort());
        filter->SetNumberOfThreads(2);
        filter->Update();
        const medialtest::MeshTopology t = medialtest::CountTopology(filter->GetOutput());
        const bool right = filter->GetHasSolidTopology() && filter->GetSolidEulerCharacteristic() == c.Euler &&
          t.Euler() == c.Euler && t.Components == 1 && filter->GetEulerCharacteristic() == t.Euler() &&
          filter->GetNumberOfComponents() == 1 && log.Errors == 0 && log.Warnings == 0;
        std::printf("%-20s %7lld samples, seed %2lld: chi %3lld (solid %d), %lld component(s)%s\n", c.Name,
          static_cast<long long>(samples), seed, static_cast<long long>(t.Euler()), c.Euler,
          static_cast<long long>(t.Components), right ? "" : "  <-- WRONG");
        if (!right)
        {
          std::printf("  filter: chi %lld, %lld component(s), solid chi %lld; %s\n",
            static_cast<long long>(filter->GetEulerCharacteristic()),
            static_cast<long long>(filter->GetNumberOfComponents()),
            static_cast<long long>(filter->GetSolidEulerCharacteristic()), log.Text.c_str());
          ++failures;
        }
      }
    }
  }
  MEDIAL_CHECK(failures == 0, "%d run(s) without the solid's topology", failures);
  return EXIT_SUCCESS;
}
