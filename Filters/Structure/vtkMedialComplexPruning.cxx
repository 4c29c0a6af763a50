// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedialComplexPruning.h"
#include "vtkMedialPruneFilter.h"

#include "vtkMedialDisjointSets.h"
#include "vtkMedialEnvelope.h"
#include "vtkMedialSimplicialComplex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace
{
constexpr double Degrees = 180.0 / 3.14159265358979323846;
constexpr double Infinity = std::numeric_limits<double>::infinity();

double Distance(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Separation angle (degrees) from the slope of the radius: |grad R| = cos(theta / 2).
double AngleFromSlope(double slope)
{
  return 2.0 * std::acos(std::min(1.0, std::abs(slope))) * Degrees;
}
}

vtkIdType vtkMedialComplexPruning::OtherEnd(vtkIdType edge, vtkIdType v) const
{
  const auto& e = this->Complex->Edges[edge];
  return e[0] == v ? e[1] : e[0];
}

vtkIdType vtkMedialComplexPruning::Opposite(vtkIdType triangle, vtkIdType edge) const
{
  const auto& t = this->Complex->Triangles[triangle];
  const auto& e = this->Complex->Edges[edge];
  for (vtkIdType v : t)
  {
    if (v != e[0] && v != e[1])
    {
      return v;
    }
  }
  return t[0];
}

bool vtkMedialComplexPruning::CollapseAll(
  const KeyFunction& key, const CollapseFunction& done, const std::function<bool()>& aborted)
{
  const vtkMedialSimplicialComplex& c = *this->Complex;
  const size_t nv = c.Radii.size(), ne = c.Edges.size(), nt = c.Triangles.size();
  std::vector<int> edgeCount(ne), vertexCount(nv);
  for (size_t e = 0; e < ne; ++e)
  {
    edgeCount[e] = static_cast<int>(c.EdgeTriangles[e].size());
  }
  for (size_t v = 0; v < nv; ++v)
  {
    vertexCount[v] = static_cast<int>(c.VertexEdges[v].size());
  }
  std::vector<char> triangleAlive(nt, 1), edgeAlive(ne, 1);
  std::priority_queue<Collapse, std::vector<Collapse>, std::greater<Collapse>> heap;
  auto push = [&](int kind, vtkIdType simplex, vtkIdType face) {
    heap.push({ key(kind, simplex, face), kind, simplex, face });
  };
  // A ball on exactly one edge, of no triangle: that edge collapses into the other end.
  auto offerVertex = [&](vtkIdType v) {
    if (vertexCount[v] != 1)
    {
      return;
    }
    for (vtkIdType e : c.VertexEdges[v])
    {
      if (edgeAlive[e] && edgeCount[e] == 0)
      {
        push(EDGE, e, v);
      }
    }
  };
  // An edge of one triangle frees that triangle; an edge of none may have a free end.
  auto offerEdge = [&](vtkIdType e) {
    if (!edgeAlive[e])
    {
      return;
    }
    if (edgeCount[e] == 1)
    {
      for (vtkIdType t : c.EdgeTriangles[e])
      {
        if (triangleAlive[t])
        {
          push(TRIANGLE, t, e);
        }
      }
    }
    else if (edgeCount[e] == 0)
    {
      offerVertex(c.Edges[e][0]);
      offerVertex(c.Edges[e][1]);
    }
  };
  for (size_t e = 0; e < ne; ++e)
  {
    offerEdge(static_cast<vtkIdType>(e));
  }
  vtkIdType made = 0;
  while (!heap.empty())
  {
    Collapse next = heap.top();
    heap.pop();
    const bool valid = next.Kind == TRIANGLE
      ? triangleAlive[next.Simplex] && edgeAlive[next.Face] && edgeCount[next.Face] == 1
      : edgeAlive[next.Simplex] && edgeCount[next.Simplex] == 0 && vertexCount[next.Face] == 1;
    if (!valid)
    {
      continue;
    }
    const double now = key(next.Kind, next.Simplex, next.Face);
    if (now > next.Key)
    {
      next.Key = now; // its key grew since it was queued: wait for its turn
      heap.push(next);
      continue;
    }
    if ((++made & 1023) == 0 && aborted && aborted())
    {
      return false;
    }
    if (next.Kind == TRIANGLE)
    {
      triangleAlive[next.Simplex] = 0;
      edgeAlive[next.Face] = 0;
      for (vtkIdType e : c.TriangleEdges[next.Simplex])
      {
        --edgeCount[e];
      }
      for (vtkIdType v : c.Edges[next.Face])
      {
        --vertexCount[v];
      }
      done(next);
      for (vtkIdType e : c.TriangleEdges[next.Simplex])
      {
        offerEdge(e);
      }
      for (vtkIdType v : c.Edges[next.Face])
      {
        offerVertex(v);
      }
    }
    else
    {
      edgeAlive[next.Simplex] = 0;
      vertexCount[next.Face] = 0;
      const vtkIdType other = this->OtherEnd(next.Simplex, next.Face);
      --vertexCount[other];
      done(next);
      offerVertex(other);
    }
  }
  return true;
}

void vtkMedialComplexPruning::ComputeBurn(const std::function<bool()>& aborted)
{
  const vtkMedialSimplicialComplex& c = *this->Complex;
  auto& burn = this->Burn;
  burn.assign(c.Radii.size(), Infinity);
  // The free faces burn from their balls' radii.
  for (size_t e = 0; e < c.Edges.size(); ++e)
  {
    const bool freeEdge = c.EdgeTriangles[e].size() == 1;
    for (vtkIdType v : c.Edges[e])
    {
      if (freeEdge || (c.EdgeTriangles[e].empty() && c.VertexEdges[v].size() == 1))
      {
        burn[v] = c.Radii[v];
      }
    }
  }
  auto key = [&](int kind, vtkIdType simplex, vtkIdType face) {
    if (kind == EDGE)
    {
      const vtkIdType w = this->OtherEnd(simplex, face);
      return burn[face] + Distance(c.Point(face), c.Point(w));
    }
    const vtkIdType a = c.Edges[face][0], b = c.Edges[face][1], o = this->Opposite(simplex, face);
    const double across =
      std::min(burn[a] + Distance(c.Point(a), c.Point(o)), burn[b] + Distance(c.Point(b), c.Point(o)));
    return std::max(std::max(burn[a], burn[b]), across);
  };
  auto done = [&](const Collapse& k) {
    const vtkIdType reached = k.Kind == EDGE ? this->OtherEnd(k.Simplex, k.Face) : this->Opposite(k.Simplex, k.Face);
    burn[reached] = std::min(burn[reached], k.Key);
  };
  this->CollapseAll(key, done, aborted);
}

void vtkMedialComplexPruning::ComputeMeasures(int measure, double diagonal)
{
  const vtkMedialSimplicialComplex& c = *this->Complex;
  const size_t nv = c.Radii.size();
  const double top = vtkMedialPruneFilter::GetMeasureUpperBound(measure);
  this->VertexSignificance.assign(nv, top);
  for (size_t v = 0; v < nv; ++v)
  {
    const double b = this->Burn[v], r = c.Radii[v];
    double value = top;
    if (measure == vtkMedialPruneFilter::EROSION_THICKNESS && std::isfinite(b))
    {
      value = std::min(top, std::max(0.0, b - r) / diagonal);
    }
    else if (measure == vtkMedialPruneFilter::TUBULARITY && std::isfinite(b))
    {
      value = b > 0.0 ? std::max(0.0, b - r) / b : 0.0;
    }
    else if (measure == vtkMedialPruneFilter::SCALE_AXIS)
    {
      // The smallest scale at which a neighbour's scaled ball covers this one.
      double s = Infinity;
      for (vtkIdType e : c.VertexEdges[v])
      {
        const vtkIdType q = this->OtherEnd(e, static_cast<vtkIdType>(v));
        if (c.Radii[q] > r)
        {
          s = std::min(s, Distance(c.Point(v), c.Point(q)) / (c.Radii[q] - r));
        }
      }
      value = std::isfinite(s) ? std::max(0.0, 1.0 - 1.0 / s) : top;
    }
    this->VertexSignificance[v] = value;
  }
  // Separation angles from the slope of the radius over each triangle and curve edge.
  this->EdgeAngle.resize(c.Edges.size());
  for (size_t e = 0; e < c.Edges.size(); ++e)
  {
    const vtkIdType a = c.Edges[e][0], b = c.Edges[e][1];
    const double length = Distance(c.Point(a), c.Point(b));
    this->EdgeAngle[e] = length > 0.0 ? AngleFromSlope((c.Radii[b] - c.Radii[a]) / length) : 180.0;
  }
  this->TriangleAngle.resize(c.Triangles.size());
  for (size_t t = 0; t < c.Triangles.size(); ++t)
  {
    // Over a triangle grad R = -W, W being the in-plane part of the slab's tangent normals.
    const auto& tri = c.Triangles[t];
    const double* centres[3] = { c.Point(tri[0]), c.Point(tri[1]), c.Point(tri[2]) };
    const double radii[3] = { c.Radii[tri[0]], c.Radii[tri[1]], c.Radii[tri[2]] };
    vtkMedialEnvelope::TangentPlanes planes;
    const bool solved = vtkMedialEnvelope::SlabTangentPlanes(centres, radii, planes);
    const double n2 = vtkMedialEnvelope::Dot3(planes.N, planes.N);
    const double scale = vtkMedialEnvelope::Dot3(planes.E1, planes.E1) * vtkMedialEnvelope::Dot3(planes.E2, planes.E2);
    double angle = 180.0;
    if (solved || n2 > 1e-24 * scale)
    {
      angle = AngleFromSlope(std::sqrt(vtkMedialEnvelope::Dot3(planes.W, planes.W)));
    }
    else
    {
      for (vtkIdType e : c.TriangleEdges[t])
      {
        angle = std::min(angle, this->EdgeAngle[e]); // collinear: the steepest side
      }
    }
    this->TriangleAngle[t] = angle;
  }
}

bool vtkMedialComplexPruning::Run(
  const vtkMedialSimplicialComplex& complex, int measure, double diagonal, const std::function<bool()>& aborted)
{
  this->Complex = &complex;
  this->Measure = measure;
  this->Diagonal = diagonal > 0.0 ? diagonal : 1.0;
  const double top = vtkMedialPruneFilter::GetMeasureUpperBound(measure);
  this->VertexLevels.assign(complex.Radii.size(), top);
  this->EdgeLevels.assign(complex.Edges.size(), top);
  this->TriangleLevels.assign(complex.Triangles.size(), top);
  this->RemovalLevels.clear();
  this->ComputeBurn(aborted);
  if (aborted && aborted())
  {
    return false;
  }
  this->ComputeMeasures(measure, this->Diagonal);

  const bool byAngle = measure == vtkMedialPruneFilter::SEPARATION_ANGLE || measure == vtkMedialPruneFilter::LAMBDA;
  auto angleValue = [&](double angle, double radius) {
    return measure == vtkMedialPruneFilter::SEPARATION_ANGLE
      ? angle
      : std::min(top, radius * std::sin(angle / Degrees / 2.0) / this->Diagonal);
  };
  auto key = [&](int kind, vtkIdType simplex, vtkIdType face) {
    if (kind == EDGE)
    {
      const vtkIdType w = this->OtherEnd(simplex, face);
      return byAngle ? angleValue(this->EdgeAngle[simplex], std::max(complex.Radii[face], complex.Radii[w]))
                     : std::max(this->VertexSignificance[face], this->VertexSignificance[w]);
    }
    const auto& t = complex.Triangles[simplex];
    if (byAngle)
    {
      return angleValue(
        this->TriangleAngle[simplex], std::max({ complex.Radii[t[0]], complex.Radii[t[1]], complex.Radii[t[2]] }));
    }
    return std::max(
      { this->VertexSignificance[t[0]], this->VertexSignificance[t[1]], this->VertexSignificance[t[2]] });
  };
  double level = 0.0;
  auto done = [&](const Collapse& k) {
    level = std::max(level, k.Key);
    this->RemovalLevels.push_back(level);
    if (k.Kind == TRIANGLE)
    {
      this->TriangleLevels[k.Simplex] = this->EdgeLevels[k.Face] = level;
    }
    else
    {
      this->EdgeLevels[k.Simplex] = this->VertexLevels[k.Face] = level;
    }
  };
  return this->CollapseAll(key, done, aborted);
}

vtkIdType vtkMedialComplexPruning::CountRemovedBelow(double threshold) const
{
  return static_cast<vtkIdType>(
    std::lower_bound(this->RemovalLevels.begin(), this->RemovalLevels.end(), threshold) -
    this->RemovalLevels.begin());
}

vtkIdType vtkMedialComplexPruning::CountRemovedPieces(double threshold) const
{
  const vtkMedialSimplicialComplex& c = *this->Complex;
  const vtkIdType nt = static_cast<vtkIdType>(c.Triangles.size());
  const vtkIdType ne = static_cast<vtkIdType>(c.Edges.size());
  // Simplices: triangles 0..nt-1, then edges.
  vtkMedialDisjointSets sets(nt + ne);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    for (vtkIdType e : c.TriangleEdges[t])
    {
      if (this->TriangleLevels[t] < threshold && this->EdgeLevels[e] < threshold)
      {
        sets.Join(t, nt + e);
      }
    }
  }
  for (vtkIdType v = 0; v < c.GetNumberOfVertices(); ++v)
  {
    vtkIdType first = -1;
    for (vtkIdType e : c.VertexEdges[v])
    {
      if (this->VertexLevels[v] < threshold && this->EdgeLevels[e] < threshold)
      {
        first = first < 0 ? nt + e : (sets.Join(first, nt + e), first);
      }
    }
  }
  vtkIdType pieces = 0;
  for (vtkIdType s = 0; s < nt + ne; ++s)
  {
    const bool removed = s < nt ? this->TriangleLevels[s] < threshold : this->EdgeLevels[s - nt] < threshold;
    pieces += removed && sets.Find(s) == s ? 1 : 0;
  }
  return pieces;
}
