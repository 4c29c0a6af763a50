// SPDX-License-Identifier: BSD-3-Clause
// vtkMedialMeshFilter lends the classifier the surface it has prepared (so the surface
// is prepared once): the classification it gets (governor counts, point types, the
// exact seam and junction balls) must be bit for bit that of a classifier that
// prepares the surface itself, and the loan must end with the run: the filter's
// classifier, used alone afterwards on another surface, classifies that surface.
#include "MedialMeshTestUtilities.h"

#include "vtkMedialArrayNames.h"
#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkMedialMeshFilter.h"

#include "vtkPointData.h"

#include <cstring>

namespace
{
// The same number of values, bit for bit (as doubles).
bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  if (!a || !b || a->GetNumberOfTuples() != b->GetNumberOfTuples() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < a->GetNumberOfComponents(); ++k)
    {
      const double x = a->GetComponent(i, k), y = b->GetComponent(i, k);
      if (std::memcmp(&x, &y, sizeof(x)) != 0)
      {
        return false;
      }
    }
  }
  return true;
}

// Both classifications: the balls' arrays and the exact points, bit for bit.
bool SameClassification(vtkMedialBallClassifier* a, vtkMedialBallClassifier* b)
{
  vtkPolyData* balls[2] = { a->GetOutput(0), b->GetOutput(0) };
  vtkPolyData* exact[2] = { a->GetOutput(1), b->GetOutput(1) };
  for (const char* name : { vtkMedialArrayNames::GovernorCount, vtkMedialArrayNames::MedialPointType })
  {
    if (!SameArray(balls[0]->GetPointData()->GetArray(name), balls[1]->GetPointData()->GetArray(name)) ||
      !SameArray(exact[0]->GetPointData()->GetArray(name), exact[1]->GetPointData()->GetArray(name)))
    {
      return false;
    }
  }
  return exact[0]->GetNumberOfPoints() == exact[1]->GetNumberOfPoints() &&
    (exact[0]->GetNumberOfPoints() == 0 ||
      SameArray(exact[0]->GetPoints()->GetData(), exact[1]->GetPoints()->GetData())) &&
    SameArray(exact[0]->GetPointData()->GetArray(vtkMedialArrayNames::Radius),
      exact[1]->GetPointData()->GetArray(vtkMedialArrayNames::Radius));
}

vtkSmartPointer<vtkPolyData> Sample(vtkPolyData* solid)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(solid);
  sampler->SetNumberOfSamples(2000);
  sampler->SetNumberOfThreads(2);
  sampler->Update();
  return sampler->GetOutput();
}

// A classifier with the filter's classifier's settings, preparing the surface itself.
vtkSmartPointer<vtkMedialBallClassifier> Alone(
  vtkMedialBallClassifier* like, vtkPolyData* balls, vtkPolyData* surface)
{
  auto classifier = vtkSmartPointer<vtkMedialBallClassifier>::New();
  classifier->SetMinimumSeparationAngle(like->GetMinimumSeparationAngle());
  classifier->SetTolerance(like->GetTolerance());
  classifier->SetNumberOfThreads(2);
  classifier->SetInputData(balls);
  classifier->SetSurfaceData(surface);
  classifier->Update();
  return classifier;
}
}

int TestMedialMeshPreparedSurface(int, char*[])
{
  // A box: planes and edges, so seams and junctions are solved. (The blended jack gave
  // seam balls only while the sampler's balls followed the facets' tilted normals.)
  vtkSmartPointer<vtkPolyData> box = medialtest::MakeSolid(vtkMedialShapeSource::BOX, 1, 8);
  vtkSmartPointer<vtkPolyData> balls = Sample(box);
  vtkNew<vtkMedialMeshFilter> filter;
  filter->SetInputData(box);
  filter->SetBallsData(balls);
  filter->SetNumberOfThreads(2);
  filter->Update();
  vtkMedialBallClassifier* lent = filter->GetClassifier();
  MEDIAL_CHECK(filter->GetOutput()->GetNumberOfPolys() > 0, "the box has no medial mesh");
  MEDIAL_CHECK(lent->GetNumberOfSeamPoints() + lent->GetNumberOfJunctionVertices() > 0,
    "the box's classification solved no exact point: nothing to compare");

  auto alone = Alone(lent, balls, box);
  std::printf("box: %lld seam points, %lld junction vertices (lent surface) vs %lld, %lld (prepared alone)\n",
    static_cast<long long>(lent->GetNumberOfSeamPoints()), static_cast<long long>(lent->GetNumberOfJunctionVertices()),
    static_cast<long long>(alone->GetNumberOfSeamPoints()), static_cast<long long>(alone->GetNumberOfJunctionVertices()));
  MEDIAL_CHECK(SameClassification(lent, alone), "the filter's classification differs from a classifier's alone");

  // The loan ends with the run: the same classifier, alone on another box, reads it.
  vtkNew<vtkMedialShapeSource> other;
  other->SetShapeToBox();
  other->SetBoxLengths(2.0, 1.2, 0.8);
  other->SetResolution(6);
  other->Update();
  vtkSmartPointer<vtkPolyData> otherBox = other->GetOutput();
  vtkSmartPointer<vtkPolyData> otherBalls = Sample(otherBox);
  lent->SetInputData(otherBalls);
  lent->SetSurfaceData(otherBox);
  lent->Update();
  auto otherAlone = Alone(lent, otherBalls, otherBox);
  MEDIAL_CHECK(lent->GetOutput(1)->GetNumberOfPoints() > 0, "the other box's classification solved no exact point");
  MEDIAL_CHECK(SameClassification(lent, otherAlone), "the filter's classifier, used alone afterwards, still reads the "
                                                     "surface it was lent");
  return EXIT_SUCCESS;
}
