// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialShapeSource.h"
#include "vtkMedialArrayNames.h"

#include "vtkCellArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkMedialShapeSource);

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct MeshBuilder
{
  std::vector<std::array<double, 3>> Points;
  std::vector<std::array<vtkIdType, 3>> Triangles;

  vtkIdType Add(double x, double y, double z)
  {
    this->Points.push_back({ x, y, z });
    return static_cast<vtkIdType>(this->Points.size() - 1);
  }
  void Tri(vtkIdType a, vtkIdType b, vtkIdType c) { this->Triangles.push_back({ a, b, c }); }

  void Emit(vtkPolyData* out) const
  {
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    pts->SetNumberOfPoints(static_cast<vtkIdType>(this->Points.size()));
    for (size_t i = 0; i < this->Points.size(); ++i)
    {
      pts->SetPoint(static_cast<vtkIdType>(i), this->Points[i].data());
    }
    vtkNew<vtkCellArray> polys;
    polys->AllocateExact(static_cast<vtkIdType>(this->Triangles.size()), 3 * this->Triangles.size());
    for (const auto& t : this->Triangles)
    {
      polys->InsertNextCell(3, t.data());
    }
    out->SetPoints(pts);
    out->SetPolys(polys);
  }
};

void MakeSphere(MeshBuilder& m, double radius, int levels)
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  const double ico[12][3] = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },
    { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 },
    { -g, 0, 1 } };
  const int faces[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  auto addUnit = [&m](double x, double y, double z) {
    const double l = std::sqrt(x * x + y * y + z * z);
    return m.Add(x / l, y / l, z / l);
  };
  for (const auto& p : ico)
  {
    addUnit(p[0], p[1], p[2]);
  }
  for (const auto& f : faces)
  {
    m.Tri(f[0], f[1], f[2]);
  }
  for (int level = 0; level < levels; ++level)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto mid = [&](vtkIdType a, vtkIdType b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoints.find(key);
      if (it != midpoints.end())
      {
        return it->second;
      }
      const auto pa = m.Points[a], pb = m.Points[b];
      const vtkIdType id = addUnit(pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]);
      midpoints.emplace(key, id);
      return id;
    };
    std::vector<std::array<vtkIdType, 3>> next;
    next.reserve(4 * m.Triangles.size());
    for (const auto& t : m.Triangles)
    {
      const vtkIdType ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      next.push_back({ t[0], ab, ca });
      next.push_back({ t[1], bc, ab });
      next.push_back({ t[2], ca, bc });
      next.push_back({ ab, bc, ca });
    }
    m.Triangles.swap(next);
  }
  for (auto& p : m.Points)
  {
    for (double& c : p)
    {
      c *= radius;
    }
  }
}

// Two concentric geodesic spheres; the inner one's triangles face into the cavity.
void MakeHollowSphere(MeshBuilder& m, double outer, double inner, int levels)
{
  MakeSphere(m, outer, levels);
  MeshBuilder cavity;
  MakeSphere(cavity, inner, levels);
  const vtkIdType offset = static_cast<vtkIdType>(m.Points.size());
  for (const auto& p : cavity.Points)
  {
    m.Add(p[0], p[1], p[2]);
  }
  for (const auto& t : cavity.Triangles)
  {
    m.Tri(offset + t[0], offset + t[2], offset + t[1]);
  }
}

// A ring of radius `ring` in the z = 0 plane swept by a circle of radius `tube`.
void MakeTorus(MeshBuilder& m, double ring, double tube, int resolution)
{
  const int around = 4 * resolution;
  const int across = std::max(6, static_cast<int>(std::lround(around * tube / ring)));
  for (int i = 0; i < around; ++i)
  {
    const double u = 2.0 * Pi * i / around;
    for (int j = 0; j < across; ++j)
    {
      const double v = 2.0 * Pi * j / across;
      const double w = ring + tube * std::cos(v);
      m.Add(w * std::cos(u), w * std::sin(u), tube * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % around) * across + j % across); };
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < across; ++j)
    {
      m.Tri(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.Tri(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
}

void MakeBox(MeshBuilder& m, const double lengths[3], int n)
{
  // Shared grid points: index by integer lattice coordinates on the box surface.
  std::map<std::array<int, 3>, vtkIdType> ids;
  auto point = [&](int i, int j, int k) {
    const std::array<int, 3> key = { i, j, k };
    auto it = ids.find(key);
    if (it != ids.end())
    {
      return it->second;
    }
    const vtkIdType id = m.Add(lengths[0] * (static_cast<double>(i) / n - 0.5),
      lengths[1] * (static_cast<double>(j) / n - 0.5), lengths[2] * (static_cast<double>(k) / n - 0.5));
    ids.emplace(key, id);
    return id;
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side)
    {
      for (int a = 0; a < n; ++a)
      {
        for (int b = 0; b < n; ++b)
        {
          vtkIdType q[4];
          const int corners[4][2] = { { a, b }, { a + 1, b }, { a + 1, b + 1 }, { a, b + 1 } };
          for (int c = 0; c < 4; ++c)
          {
            int ijk[3];
            ijk[axis] = side * n;
            ijk[u] = corners[c][0];
            ijk[v] = corners[c][1];
            q[c] = point(ijk[0], ijk[1], ijk[2]);
          }
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
          if (side == 1)
          {
            m.Tri(q[0], q[1], q[2]);
            m.Tri(q[0], q[2], q[3]);
          }
          else
          {
            m.Tri(q[0], q[2], q[1]);
            m.Tri(q[0], q[3], q[2]);
          }
        }
      }
    }
  }
}

void MakeCapsule(MeshBuilder& m, double radius, double length, int resolution)
{
  const int around = 4 * resolution;
  const int capRings = resolution; // rings per hemisphere, excluding the pole
  const int bodyRings = std::max(1, static_cast<int>(std::ceil(length / (2 * Pi * radius / around))));
  // Profile from the south pole to the north pole: (distance from axis, z).
  std::vector<std::pair<double, double>> profile;
  for (int i = 1; i <= capRings; ++i)
  {
    const double a = -0.5 * Pi + 0.5 * Pi * i / capRings;
    profile.emplace_back(radius * std::cos(a), -0.5 * length + radius * std::sin(a));
  }
  for (int i = 1; i <= bodyRings; ++i)
  {
    profile.emplace_back(radius, -0.5 * length + length * i / bodyRings);
  }
  for (int i = 1; i < capRings; ++i)
  {
    const double a = 0.5 * Pi * i / capRings;
    profile.emplace_back(radius * std::cos(a), 0.5 * length + radius * std::sin(a));
  }
  const vtkIdType south = m.Add(0, 0, -0.5 * length - radius);
  std::vector<vtkIdType> firstOfRing;
  for (const auto& pr : profile)
  {
    firstOfRing.push_back(static_cast<vtkIdType>(m.Points.size()));
    for (int k = 0; k < around; ++k)
    {
      const double phi = 2 * Pi * k / around;
      m.Add(pr.first * std::cos(phi), pr.first * std::sin(phi), pr.second);
    }
  }
  const vtkIdType north = m.Add(0, 0, 0.5 * length + radius);
  for (int k = 0; k < around; ++k)
  {
    const int k1 = (k + 1) % around;
    m.Tri(south, firstOfRing.front() + k1, firstOfRing.front() + k);
    m.Tri(north, firstOfRing.back() + k, firstOfRing.back() + k1);
  }
  for (size_t r = 0; r + 1 < firstOfRing.size(); ++r)
  {
    for (int k = 0; k < around; ++k)
    {
      const int k1 = (k + 1) % around;
      const vtkIdType a = firstOfRing[r] + k, b = firstOfRing[r] + k1;
      const vtkIdType c = firstOfRing[r + 1] + k1, d = firstOfRing[r + 1] + k;
      m.Tri(a, b, c);
      m.Tri(a, c, d);
    }
  }
}

// Signed distance to a capsule (segment a-b, radius r).
double CapsuleDistance(const double p[3], const double a[3], const double b[3], double r)
{
  double ab[3], ap[3];
  for (int i = 0; i < 3; ++i)
  {
    ab[i] = b[i] - a[i];
    ap[i] = p[i] - a[i];
  }
  const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const double t = std::min(1.0, std::max(0.0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2));
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double d = ap[i] - t * ab[i];
    d2 += d * d;
  }
  return std::sqrt(d2) - r;
}

double SmoothMin(double a, double b, double k)
{
  const double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

double JackDistance(const double p[3])
{
  static const double origin[3] = { 0, 0, 0 };
  static const double armX[2][3] = { { -1.6, 0, 0 }, { 1.6, 0, 0 } };
  static const double armY[2][3] = { { 0, -0.2, 0 }, { 0, 1.2, 0 } };
  static const double armZ[2][3] = { { 0, 0, -0.9 }, { 0, 0, 0.9 } };
  double d = CapsuleDistance(p, origin, origin, 0.55);
  d = SmoothMin(d, CapsuleDistance(p, armX[0], armX[1], 0.3), 0.2);
  d = SmoothMin(d, CapsuleDistance(p, armY[0], armY[1], 0.2), 0.2);
  d = SmoothMin(d, CapsuleDistance(p, armZ[0], armZ[1], 0.12), 0.15);
  return d;
}

// Planar loops in z = 0, one polygon cell each (the first is the outer boundary).
void EmitLoops(vtkPolyData* out, const std::vector<std::vector<std::array<double, 2>>>& loops)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  for (const auto& l : loops)
  {
    std::vector<vtkIdType> ids;
    for (const auto& p : l)
    {
      ids.push_back(pts->InsertNextPoint(p[0], p[1], 0.0));
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  out->SetPoints(pts);
  out->SetPolys(polys);
}

void MakePlanar(vtkPolyData* out, int shape, const double lengths[3], double radius, int resolution)
{
  std::vector<std::vector<std::array<double, 2>>> loops;
  switch (shape)
  {
    case vtkMedialShapeSource::L_SHAPE:
      loops.push_back({ { 0, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } });
      break;
    case vtkMedialShapeSource::RECTANGLE:
      loops.push_back({ { 0, 0 }, { lengths[0], 0 }, { lengths[0], lengths[1] }, { 0, lengths[1] } });
      break;
    case vtkMedialShapeSource::SQUARE_FRAME:
      loops.push_back({ { -2, -2 }, { 2, -2 }, { 2, 2 }, { -2, 2 } });
      loops.push_back({ { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } });
      break;
    case vtkMedialShapeSource::ELLIPSE:
    case vtkMedialShapeSource::TREFOIL:
    {
      std::vector<std::array<double, 2>> curve;
      const int n = 16 * resolution;
      for (int i = 0; i < n; ++i)
      {
        const double t = 2.0 * Pi * i / n;
        if (shape == vtkMedialShapeSource::ELLIPSE)
        {
          curve.push_back({ 0.5 * lengths[0] * std::cos(t), 0.5 * lengths[1] * std::sin(t) });
        }
        else
        {
          const double r = radius * (1.0 + 0.5 * std::cos(3.0 * t));
          curve.push_back({ r * std::cos(t), r * std::sin(t) });
        }
      }
      loops.push_back(curve);
      break;
    }
    default:
    {
      std::vector<std::array<double, 2>> star;
      const int spikes = std::max(3, resolution);
      for (int i = 0; i < 2 * spikes; ++i)
      {
        const double a = Pi * i / spikes;
        // A fixed irrational wobble breaks the star's symmetry.
        const double r = radius * (i % 2 == 0 ? 1.0 : 0.5) * (1.0 + 0.08 * std::sin(7.31 * i + 0.5));
        star.push_back({ r * std::cos(a), r * std::sin(a) });
      }
      loops.push_back(star);
    }
  }
  EmitLoops(out, loops);
}

// Genus rings of ring radius 1 and tube radius 0.35 in the z = 0 plane, centres 1.7
// apart along x, blended where neighbours overlap: a solid of that genus.
double RingsDistance(const double p[3], int genus)
{
  double d = HUGE_VAL;
  for (int i = 0; i < genus; ++i)
  {
    const double x = p[0] - 1.7 * (i - 0.5 * (genus - 1));
    const double ring = std::sqrt(x * x + p[1] * p[1]) - 1.0;
    const double tube = std::sqrt(ring * ring + p[2] * p[2]) - 0.35;
    d = i == 0 ? tube : SmoothMin(d, tube, 0.2);
  }
  return d;
}

// The zero level of a signed distance sampled on a grid of `cells` cells along the
// longest side of the box [lo, hi] (vtkFlyingEdges3D).
template <class Distance>
void ContourDistance(vtkPolyData* out, const double lo[3], const double hi[3], int cells, Distance distance)
{
  const double h = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) / cells;
  int dims[3];
  for (int i = 0; i < 3; ++i)
  {
    dims[i] = static_cast<int>(std::ceil((hi[i] - lo[i]) / h)) + 1;
  }
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(dims);
  grid->SetOrigin(lo[0], lo[1], lo[2]);
  grid->SetSpacing(h, h, h);
  vtkNew<vtkFloatArray> field;
  field->SetName(vtkMedialArrayNames::Distance);
  field->SetNumberOfTuples(static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2]);
  vtkIdType id = 0;
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i)
      {
        const double p[3] = { lo[0] + i * h, lo[1] + j * h, lo[2] + k * h };
        field->SetValue(id++, static_cast<float>(distance(p)));
      }
    }
  }
  grid->GetPointData()->SetScalars(field);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  // The distance is negative inside, and vtkFlyingEdges3D winds its triangles so that
  // they face the lower values: inward. Reversing each triangle's corners (the first and
  // last swapped, as the preparation's own flip does) makes the shapes face outward as
  // documented, and the filters see the same triangles as before.
  vtkNew<vtkReverseSense> outward;
  outward->SetInputConnection(contour->GetOutputPort());
  outward->ReverseCellsOn();
  outward->ReverseNormalsOff();
  outward->Update();
  out->ShallowCopy(outward->GetOutput());
}

void MakeJack(vtkPolyData* out, int resolution)
{
  const double lo[3] = { -2.0, -0.8, -1.1 }, hi[3] = { 2.0, 1.5, 1.1 };
  ContourDistance(out, lo, hi, 4 * resolution, JackDistance);
}

void MakeRings(vtkPolyData* out, int genus, int resolution)
{
  const double halfWidth = 0.85 * (genus - 1) + 1.5;
  const double lo[3] = { -halfWidth, -1.5, -0.5 }, hi[3] = { halfWidth, 1.5, 0.5 };
  ContourDistance(out, lo, hi, 4 * resolution, [genus](const double p[3]) { return RingsDistance(p, genus); });
}

// The torus's exact signed distance on a cube of `points` grid points per axis,
// 1.1 (ring + tube) on either side of the centre.
void MakeContouredTorus(vtkPolyData* out, double ring, double tube, int points)
{
  const double half = 1.1 * (ring + tube);
  const double lo[3] = { -half, -half, -half }, hi[3] = { half, half, half };
  ContourDistance(out, lo, hi, std::max(points, 2) - 1, [ring, tube](const double p[3]) {
    return std::hypot(std::hypot(p[0], p[1]) - ring, p[2]) - tube;
  });
}
}

vtkMedialShapeSource::vtkMedialShapeSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkMedialShapeSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  MeshBuilder m;
  switch (this->Shape)
  {
    case SPHERE:
      if (this->Resolution > 9)
      {
        vtkErrorMacro(<< "SPHERE resolution " << this->Resolution << " is above 9 (5M triangles).");
        return 0;
      }
      MakeSphere(m, this->Radius, this->Resolution);
      break;
    case BOX:
      MakeBox(m, this->BoxLengths, this->Resolution);
      break;
    case CAPSULE:
      MakeCapsule(m, this->Radius, this->Length, this->Resolution);
      break;
    case TORUS:
      if (!(this->TubeRadius < this->Radius))
      {
        vtkErrorMacro(<< "TORUS tube radius " << this->TubeRadius << " is not below the ring radius "
                      << this->Radius << ".");
        return 0;
      }
      MakeTorus(m, this->Radius, this->TubeRadius, this->Resolution);
      break;
    case CONTOURED_TORUS:
      if (!(this->TubeRadius < this->Radius))
      {
        vtkErrorMacro(<< "CONTOURED_TORUS tube radius " << this->TubeRadius << " is not below the ring radius "
                      << this->Radius << ".");
        return 0;
      }
      MakeContouredTorus(output, this->Radius, this->TubeRadius, this->Resolution);
      return 1;
    case HOLLOW_SPHERE:
      if (this->Resolution > 8 || !(this->InnerRadius < this->Radius))
      {
        vtkErrorMacro(<< "HOLLOW_SPHERE needs a resolution of at most 8 and an inner radius below "
                         "the outer one (got "
                      << this->Resolution << ", " << this->InnerRadius << " and " << this->Radius << ").");
        return 0;
      }
      MakeHollowSphere(m, this->Radius, this->InnerRadius, this->Resolution);
      break;
    case L_SHAPE:
    case RECTANGLE:
    case SQUARE_FRAME:
    case STAR:
    case ELLIPSE:
    case TREFOIL:
      MakePlanar(output, this->Shape, this->BoxLengths, this->Radius, this->Resolution);
      return 1;
    case RINGS:
      MakeRings(output, this->Genus, this->Resolution);
      return 1;
    default:
      MakeJack(output, this->Resolution);
      return 1;
  }
  m.Emit(output);
  return 1;
}

void vtkMedialShapeSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shape: " << this->Shape << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Length: " << this->Length << "\n";
  os << indent << "TubeRadius: " << this->TubeRadius << "\n";
  os << indent << "InnerRadius: " << this->InnerRadius << "\n";
  os << indent << "Genus: " << this->Genus << "\n";
  os << indent << "BoxLengths: " << this->BoxLengths[0] << " " << this->BoxLengths[1] << " "
     << this->BoxLengths[2] << "\n";
}
