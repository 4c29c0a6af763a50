// SPDX-License-Identifier: BSD-3-Clause
// The tree build makes the same tree whatever the thread count and however its passes
// are spread over the threads: on an ellipsoid of 542,400 triangles (enough for the first
// levels' partitions to run on every thread), the leaf order (each triangle's rank),
// the node count, and the tree's leaf-order copies of the vertices and planes are the
// same with 1 and 2 threads, and the leaf order is the one the serial two-ended
// exchange made before the top levels ran in parallel (its fingerprint, taken from
// that build, is written below: change it only for an intended change of the tree).
// The leaf-order copies hold the mesh's own coordinates bit for bit, kept as floats
// when every coordinate is one (float points, the sphere's own) and as doubles when not
// (the same ellipsoid in double precision).
#include "MedialTestUtilities.h"

#include "vtkMedialTriangleBVH.h"
#include "vtkMedialTriangleMesh.h"

#include "vtkNew.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <omp.h>

#include <cstdint>
#include <cstring>
#include <string>

using namespace medialtest;

namespace
{
// FNV-1a over bytes.
std::uint64_t Fingerprint(const void* data, size_t bytes, std::uint64_t hash = 0xcbf29ce484222325ull)
{
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i)
  {
    hash = (hash ^ p[i]) * 0x100000001b3ull;
  }
  return hash;
}

struct TreeFacts
{
  std::uint64_t LeafOrder = 0, Copies = 0;
  vtkIdType Nodes = 0;
  vtkIdType WrongCopies = -1; // triangles whose copy differs from the mesh's points
};

TreeFacts Facts(const vtkMedialTriangleMesh& mesh, int threads)
{
  omp_set_num_threads(threads);
  vtkMedialTriangleBVH tree;
  TreeFacts facts;
  if (!tree.Build(mesh))
  {
    return facts;
  }
  const auto& ranks = tree.GetLeafRanks();
  facts.LeafOrder = Fingerprint(ranks.data(), ranks.size() * sizeof(ranks[0]));
  facts.Copies = 0xcbf29ce484222325ull;
  facts.WrongCopies = 0;
  for (vtkIdType t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    double scratch[9];
    const double* corners = tree.GetTriangleVertices(t, scratch);
    facts.Copies = Fingerprint(corners, 9 * sizeof(double), facts.Copies);
    facts.Copies = Fingerprint(tree.GetPlane(t), 4 * sizeof(double), facts.Copies);
    for (int j = 0; j < 3; ++j)
    {
      facts.WrongCopies += std::memcmp(corners + 3 * j, mesh.GetPoint(mesh.GetTriangle(t)[j]), 3 * sizeof(double)) != 0;
    }
  }
  facts.Nodes = tree.GetNumberOfNodes();
  return facts;
}
}

int TestMedialTreeLayout(int, char*[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(800);
  sphere->SetPhiResolution(341);
  vtkNew<vtkTransform> stretch; // no symmetry: distinct centroids along every axis
  stretch->Scale(1.0, 0.55, 0.3);
  stretch->RotateZ(17.0);
  stretch->RotateX(29.0);
  vtkNew<vtkTransformPolyDataFilter> ellipsoid;
  ellipsoid->SetInputConnection(sphere->GetOutputPort());
  ellipsoid->SetTransform(stretch);
  ellipsoid->Update();
  vtkMedialTriangleMesh mesh;
  std::string error;
  MEDIAL_CHECK(ellipsoid->GetOutput()->GetPoints()->GetDataType() == VTK_FLOAT, "not float points");
  MEDIAL_CHECK(mesh.Build(ellipsoid->GetOutput(), error), "mesh: %s", error.c_str());
  MEDIAL_CHECK(mesh.GetNumberOfTriangles() > (1 << 19), "only %lld triangles",
    static_cast<long long>(mesh.GetNumberOfTriangles()));
  const TreeFacts one = Facts(mesh, 1), two = Facts(mesh, 2);
  MEDIAL_CHECK(one.Nodes > 0 && one.Nodes == two.Nodes, "node counts %lld and %lld",
    static_cast<long long>(one.Nodes), static_cast<long long>(two.Nodes));
  MEDIAL_CHECK(one.LeafOrder == two.LeafOrder, "the leaf order differs between 1 and 2 threads");
  MEDIAL_CHECK(one.WrongCopies == 0 && two.WrongCopies == 0, "float points: %lld and %lld copies differ from the mesh",
    static_cast<long long>(one.WrongCopies), static_cast<long long>(two.WrongCopies));
  MEDIAL_CHECK(one.Copies == two.Copies, "the leaf-order vertices or planes differ between 1 and 2 threads");
  const std::uint64_t serialLeafOrder = 0x47af348fc03df469ull; // the serial partitions' leaf order
  MEDIAL_CHECK(one.LeafOrder == serialLeafOrder,
    "leaf order fingerprint %016llx, expected %016llx (the serial two-ended exchange's)",
    static_cast<unsigned long long>(one.LeafOrder), static_cast<unsigned long long>(serialLeafOrder));

  // The same ellipsoid in double precision: coordinates that are not floats.
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  ellipsoid->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  ellipsoid->Update();
  MEDIAL_CHECK(mesh.Build(ellipsoid->GetOutput(), error), "double mesh: %s", error.c_str());
  const TreeFacts doubles = Facts(mesh, 2);
  MEDIAL_CHECK(doubles.WrongCopies == 0, "double points: %lld copies differ from the mesh",
    static_cast<long long>(doubles.WrongCopies));
  std::printf("leaf order %016llx; copies exact with float and double points\n",
    static_cast<unsigned long long>(one.LeafOrder));
  return EXIT_SUCCESS;
}
