// SPDX-License-Identifier: BSD-3-Clause
// An independent oracle for the 3D medial structure of polyhedra: brute-force
// distances to every triangle, the faces as planes, reflex edges as segments, and
// the junction vertices of the exact medial axis from every 4-subset of them.
#ifndef MedialStructureTestUtilities_h
#define MedialStructureTestUtilities_h

#include "MedialTestUtilities.h"

#include "vtkMedialAxisSampler.h"
#include "vtkMedialBallClassifier.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace medialtest
{
using Vec3 = std::array<double, 3>;

inline double Dot3(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Closest point on triangle (a, b, c) by projection and edge clamping; returns the distance.
inline double TriangleDistance(const double p[3], const double* a, const double* b, const double* c, double q[3])
{
  double ab[3], ac[3], n[3], ap[3];
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = p[k] - a[k];
  }
  n[0] = ab[1] * ac[2] - ab[2] * ac[1];
  n[1] = ab[2] * ac[0] - ab[0] * ac[2];
  n[2] = ab[0] * ac[1] - ab[1] * ac[0];
  const double n2 = Dot3(n, n);
  // Inside test of the projection with barycentric signs.
  const double t = Dot3(ap, n) / n2;
  double f[3];
  for (int k = 0; k < 3; ++k)
  {
    f[k] = p[k] - t * n[k];
  }
  const double* v[3] = { a, b, c };
  bool inside = true;
  for (int e = 0; e < 3 && inside; ++e)
  {
    double u[3], w[3], x[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = v[(e + 1) % 3][k] - v[e][k];
      w[k] = f[k] - v[e][k];
    }
    x[0] = u[1] * w[2] - u[2] * w[1];
    x[1] = u[2] * w[0] - u[0] * w[2];
    x[2] = u[0] * w[1] - u[1] * w[0];
    inside = Dot3(x, n) >= 0.0;
  }
  if (inside)
  {
    std::copy(f, f + 3, q);
    return std::fabs(t) * std::sqrt(n2);
  }
  double best = HUGE_VAL;
  for (int e = 0; e < 3; ++e)
  {
    const double* s = v[e];
    const double* w = v[(e + 1) % 3];
    double d[3], sp[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = w[k] - s[k];
      sp[k] = p[k] - s[k];
    }
    const double u = std::min(1.0, std::max(0.0, Dot3(sp, d) / Dot3(d, d)));
    double y[3];
    for (int k = 0; k < 3; ++k)
    {
      y[k] = s[k] + u * d[k];
    }
    const double dist = std::sqrt((p[0] - y[0]) * (p[0] - y[0]) + (p[1] - y[1]) * (p[1] - y[1]) + (p[2] - y[2]) * (p[2] - y[2]));
    if (dist < best)
    {
      best = dist;
      std::copy(y, y + 3, q);
    }
  }
  return best;
}

/// A polyhedron as faces (planes with their triangles) and reflex edges (segments).
class PolyhedronOracle
{
public:
  struct Ball
  {
    Vec3 Centre;
    double Radius;
    int Governors;
  };

  /// `shape`: outward-oriented closed polyhedron; `reflexEdges`: pairs of end points
  /// (a reflex vertex is a pair of equal points).
  PolyhedronOracle(vtkPolyData* shape, const std::vector<std::array<Vec3, 2>>& reflexEdges)
    : Segments(reflexEdges)
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(shape);
    triangles->Update();
    vtkPolyData* t = triangles->GetOutput();
    this->Diagonal = t->GetLength();
    for (vtkIdType c = 0; c < t->GetNumberOfCells(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* pts;
      t->GetCellPoints(c, npts, pts);
      std::array<double, 9> tri;
      for (int j = 0; j < 3; ++j)
      {
        t->GetPoint(pts[j], &tri[3 * j]);
      }
      double u[3], v[3], n[3];
      for (int k = 0; k < 3; ++k)
      {
        u[k] = tri[3 + k] - tri[k];
        v[k] = tri[6 + k] - tri[k];
      }
      n[0] = -(u[1] * v[2] - u[2] * v[1]);
      n[1] = -(u[2] * v[0] - u[0] * v[2]);
      n[2] = -(u[0] * v[1] - u[1] * v[0]);
      const double len = std::sqrt(Dot3(n, n));
      for (double& x : n)
      {
        x /= len;
      }
      const double d = Dot3(n, tri.data());
      const int id = static_cast<int>(this->Triangles.size());
      this->Triangles.push_back(tri);
      bool placed = false;
      for (Face& f : this->Faces)
      {
        if (std::fabs(f.N[0] - n[0]) + std::fabs(f.N[1] - n[1]) + std::fabs(f.N[2] - n[2]) < 1e-12 &&
          std::fabs(f.D - d) < 1e-12 * this->Diagonal)
        {
          f.Triangles.push_back(id);
          placed = true;
          break;
        }
      }
      if (!placed)
      {
        this->Faces.push_back({ { n[0], n[1], n[2] }, d, { id } });
      }
    }
  }

  double GetDiagonal() const { return this->Diagonal; }
  size_t GetNumberOfFaces() const { return this->Faces.size(); }

  /// Distance from x to the surface.
  double SurfaceDistance(const Vec3& x) const
  {
    double best = HUGE_VAL, q[3];
    for (const auto& t : this->Triangles)
    {
      best = std::min(best, TriangleDistance(x.data(), &t[0], &t[3], &t[6], q));
    }
    return best;
  }

  /// Distinct contacts of the ball (x, r): the faces' closest points at distance r
  /// within eps, those closer than 1e-6 of the diagonal to each other counted once
  /// (a reflex edge or vertex is the closest point of all the faces around it).
  int Governors(const Vec3& x, double r, double eps) const
  {
    std::vector<Vec3> contacts;
    for (const Face& f : this->Faces)
    {
      double best = HUGE_VAL, q[3];
      Vec3 bq;
      for (int t : f.Triangles)
      {
        const auto& tri = this->Triangles[t];
        const double d = TriangleDistance(x.data(), &tri[0], &tri[3], &tri[6], q);
        if (d < best)
        {
          best = d;
          std::copy(q, q + 3, bq.data());
        }
      }
      if (std::fabs(best - r) > eps)
      {
        continue;
      }
      bool known = false;
      for (const Vec3& c : contacts)
      {
        known = known || std::sqrt((c[0] - bq[0]) * (c[0] - bq[0]) + (c[1] - bq[1]) * (c[1] - bq[1]) +
                           (c[2] - bq[2]) * (c[2] - bq[2])) <= 1e-6 * this->Diagonal;
      }
      if (!known)
      {
        contacts.push_back(bq);
      }
    }
    return static_cast<int>(contacts.size());
  }

  /// The junction vertices: empty balls tangent to 4 features, touching 4 or more,
  /// from every 4-subset of faces and at most two reflex edges or vertices, merged within `merge`.
  std::vector<Ball> Junctions(double eps, double merge) const
  {
    const int nf = static_cast<int>(this->Faces.size());
    const int total = nf + static_cast<int>(this->Segments.size());
    std::vector<Ball> out;
    int f[4];
    for (f[0] = 0; f[0] < total; ++f[0])
      for (f[1] = f[0] + 1; f[1] < total; ++f[1])
        for (f[2] = f[1] + 1; f[2] < total; ++f[2])
          for (f[3] = f[2] + 1; f[3] < total; ++f[3])
          {
            if (f[1] >= nf)
            {
              continue; // at most two reflex edges or vertices per subset
            }
            // A face whose plane holds a reflex edge (or vertex) touches a ball only where
            // the edge does: with the edge it is one contact (and a double root).
            bool adjacent = false;
            for (int i = 0; i < 2; ++i)
            {
              for (int j = 2; j < 4 && f[j] >= nf; ++j)
              {
                const Face& face = this->Faces[f[i]];
                const auto& ends = this->Segments[f[j] - nf];
                adjacent = adjacent || (std::fabs(Dot3(face.N, ends[0].data()) - face.D) <= eps &&
                                         std::fabs(Dot3(face.N, ends[1].data()) - face.D) <= eps);
              }
            }
            if (adjacent || (f[2] < nf && f[3] >= nf && this->HoldsSegment(f[2], f[3] - nf, eps)))
            {
              continue;
            }
            for (const auto& X : f[2] >= nf ? this->SolveTwoQuadrics(f, nf) : this->Solve(f, nf))
            {
              const Vec3 c{ X[0], X[1], X[2] };
              if (!(X[3] > eps) || this->SurfaceDistance(c) < X[3] - eps || this->Governors(c, X[3], eps) < 4)
              {
                continue;
              }
              bool known = false;
              for (const Ball& b : out)
              {
                known = known ||
                  std::sqrt((b.Centre[0] - c[0]) * (b.Centre[0] - c[0]) + (b.Centre[1] - c[1]) * (b.Centre[1] - c[1]) +
                    (b.Centre[2] - c[2]) * (b.Centre[2] - c[2])) <= merge;
              }
              if (!known)
              {
                out.push_back({ c, X[3], this->Governors(c, X[3], eps) });
              }
            }
          }
    return out;
  }

private:
  struct Face
  {
    double N[3]; // inward
    double D;    // N.x = D on the face
    std::vector<int> Triangles;
  };

  bool HoldsSegment(int face, int segment, double eps) const
  {
    const Face& f = this->Faces[face];
    const auto& ends = this->Segments[segment];
    return std::fabs(Dot3(f.N, ends[0].data()) - f.D) <= eps && std::fabs(Dot3(f.N, ends[1].data()) - f.D) <= eps;
  }

  // |x - p|^2 - ((x - p).u)^2 - r^2 of segment s's line (u = 0 for a vertex), and its gradient.
  double Quadric(int s, const double X[4], double g[4]) const
  {
    const auto& ends = this->Segments[s];
    double u[3] = { ends[1][0] - ends[0][0], ends[1][1] - ends[0][1], ends[1][2] - ends[0][2] };
    const double ul = std::sqrt(Dot3(u, u));
    double w[3];
    for (int k = 0; k < 3; ++k)
    {
      u[k] = ul > 0.0 ? u[k] / ul : 0.0;
      w[k] = X[k] - ends[0][k];
    }
    const double along = Dot3(w, u);
    for (int k = 0; k < 3; ++k)
    {
      g[k] = 2.0 * (w[k] - along * u[k]);
    }
    g[3] = -2.0 * X[3];
    return Dot3(w, w) - along * along - X[3] * X[3];
  }

  // Two faces and two reflex edges (or vertices): the faces leave a plane of (x, r),
  // X0 + s D1 + t D2; Newton's method on the two quadrics from a 16 x 16 grid of
  // starts over it (brute force), roots merged.
  std::vector<std::array<double, 4>> SolveTwoQuadrics(const int f[4], int nf) const
  {
    double rows[2][4], b[2];
    for (int i = 0; i < 2; ++i)
    {
      const Face& face = this->Faces[f[i]];
      rows[i][0] = face.N[0];
      rows[i][1] = face.N[1];
      rows[i][2] = face.N[2];
      rows[i][3] = -1.0;
      b[i] = face.D;
    }
    // Minimum-norm X0 = R^T (R R^T)^-1 b and an orthonormal basis D1, D2 of the null space.
    auto dot4 = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2] + x[3] * y[3]; };
    const double g00 = dot4(rows[0], rows[0]), g01 = dot4(rows[0], rows[1]), g11 = dot4(rows[1], rows[1]);
    const double det = g00 * g11 - g01 * g01;
    if (!(std::fabs(det) > 1e-12))
    {
      return {};
    }
    const double l0 = (g11 * b[0] - g01 * b[1]) / det, l1 = (g00 * b[1] - g01 * b[0]) / det;
    double X0[4], D[2][4];
    for (int k = 0; k < 4; ++k)
    {
      X0[k] = l0 * rows[0][k] + l1 * rows[1][k];
    }
    // Orthonormal rows q0, q1, then unit vectors with the rows and earlier picks projected out.
    double q[4][4];
    for (int i = 0; i < 2; ++i)
    {
      std::copy(rows[i], rows[i] + 4, q[i]);
      for (int j = 0; j < i; ++j)
      {
        const double p = dot4(q[i], q[j]);
        for (int k = 0; k < 4; ++k)
        {
          q[i][k] -= p * q[j][k];
        }
      }
      const double n = std::sqrt(dot4(q[i], q[i]));
      for (double& x : q[i])
      {
        x /= n;
      }
    }
    int found = 2;
    for (int e = 0; e < 4 && found < 4; ++e)
    {
      double v[4] = { 0, 0, 0, 0 };
      v[e] = 1.0;
      for (int j = 0; j < found; ++j)
      {
        const double p = dot4(v, q[j]);
        for (int k = 0; k < 4; ++k)
        {
          v[k] -= p * q[j][k];
        }
      }
      const double n = std::sqrt(dot4(v, v));
      if (n > 0.3)
      {
        for (int k = 0; k < 4; ++k)
        {
          q[found][k] = v[k] / n;
        }
        ++found;
      }
    }
    if (found < 4)
    {
      return {};
    }
    double basis[2][4];
    std::copy(q[2], q[2] + 4, basis[0]);
    std::copy(q[3], q[3] + 4, basis[1]);
    std::copy(basis[0], basis[0] + 4, D[0]);
    std::copy(basis[1], basis[1] + 4, D[1]);
    std::vector<std::array<double, 4>> roots;
    const double span = this->Diagonal;
    for (int gi = 0; gi < 16; ++gi)
    {
      for (int gj = 0; gj < 16; ++gj)
      {
        double st[2] = { span * (-1.0 + 2.0 * (gi + 0.5) / 16), span * (-1.0 + 2.0 * (gj + 0.5) / 16) };
        double X[4], F[2] = { 1, 1 };
        for (int it = 0; it < 60; ++it)
        {
          for (int k = 0; k < 4; ++k)
          {
            X[k] = X0[k] + st[0] * D[0][k] + st[1] * D[1][k];
          }
          double g0[4], g1[4];
          F[0] = this->Quadric(f[2] - nf, X, g0);
          F[1] = this->Quadric(f[3] - nf, X, g1);
          const double J[2][2] = { { dot4(g0, D[0]), dot4(g0, D[1]) }, { dot4(g1, D[0]), dot4(g1, D[1]) } };
          const double dj = J[0][0] * J[1][1] - J[0][1] * J[1][0];
          if (!(std::fabs(dj) > 1e-300))
          {
            break;
          }
          st[0] -= (J[1][1] * F[0] - J[0][1] * F[1]) / dj;
          st[1] -= (J[0][0] * F[1] - J[1][0] * F[0]) / dj;
        }
        if (std::fabs(F[0]) + std::fabs(F[1]) > 1e-20 * this->Diagonal * this->Diagonal || !(X[3] > 0.0))
        {
          continue;
        }
        bool known = false;
        for (const auto& r : roots)
        {
          known = known || std::fabs(r[0] - X[0]) + std::fabs(r[1] - X[1]) + std::fabs(r[2] - X[2]) + std::fabs(r[3] - X[3]) <
              1e-10 * this->Diagonal;
        }
        if (!known)
        {
          roots.push_back({ X[0], X[1], X[2], X[3] });
        }
      }
    }
    return roots;
  }

  // Balls tangent to features f[0..3] (faces < nf, then at most one reflex edge's line or vertex).
  std::vector<std::array<double, 4>> Solve(const int f[4], int nf) const
  {
    // Rows n.x - r = d of the faces.
    double A[4][5];
    int m = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (f[i] < nf)
      {
        const Face& face = this->Faces[f[i]];
        A[m][0] = face.N[0];
        A[m][1] = face.N[1];
        A[m][2] = face.N[2];
        A[m][3] = -1.0;
        A[m][4] = face.D;
        ++m;
      }
    }
    if (m == 4)
    {
      std::array<double, 4> X;
      if (!Gauss(A, 4, X.data()))
      {
        return {};
      }
      return { X };
    }
    // Three faces: X = X0 + t D, D the 4D cross product of the three rows; then the
    // line's |x - p|^2 - ((x - p).u)^2 = r^2 is a quadratic in t.
    double D[4];
    for (int col = 0; col < 4; ++col)
    {
      double M[3][3];
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0, c = 0; j < 4; ++j)
        {
          if (j != col)
          {
            M[i][c++] = A[i][j];
          }
        }
      }
      const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
        M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
      D[col] = (col % 2 == 0 ? 1.0 : -1.0) * det;
    }
    int k = 0;
    for (int i = 1; i < 4; ++i)
    {
      k = std::fabs(D[i]) > std::fabs(D[k]) ? i : k;
    }
    if (!(std::fabs(D[k]) > 1e-12))
    {
      return {};
    }
    // Particular solution with X_k = 0.
    double B[4][5];
    for (int i = 0; i < 3; ++i)
    {
      std::copy(A[i], A[i] + 5, B[i]);
    }
    for (int j = 0; j < 5; ++j)
    {
      B[3][j] = j == k ? 1.0 : 0.0;
    }
    double X0[4];
    if (!Gauss(B, 4, X0))
    {
      return {};
    }
    const auto& s = this->Segments[f[3] - nf];
    double u[3] = { s[1][0] - s[0][0], s[1][1] - s[0][1], s[1][2] - s[0][2] };
    const double ul = std::sqrt(Dot3(u, u));
    for (double& x : u)
    {
      x = ul > 0.0 ? x / ul : 0.0; // a reflex vertex: |x - p| = r
    }
    // w(t) = X0x - p + t Dx; |w|^2 - (w.u)^2 - (X0r + t Dr)^2 = 0.
    double w0[3], wd[3];
    for (int i = 0; i < 3; ++i)
    {
      w0[i] = X0[i] - s[0][i];
      wd[i] = D[i];
    }
    const double a = Dot3(wd, wd) - Dot3(wd, u) * Dot3(wd, u) - D[3] * D[3];
    const double b = 2.0 * (Dot3(w0, wd) - Dot3(w0, u) * Dot3(wd, u) - X0[3] * D[3]);
    const double c = Dot3(w0, w0) - Dot3(w0, u) * Dot3(w0, u) - X0[3] * X0[3];
    std::vector<double> roots;
    if (std::fabs(a) < 1e-14 * (std::fabs(b) + std::fabs(c)))
    {
      roots.push_back(-c / b);
    }
    else
    {
      const double disc = b * b - 4 * a * c;
      if (disc >= 0)
      {
        roots.push_back((-b + std::sqrt(disc)) / (2 * a));
        roots.push_back((-b - std::sqrt(disc)) / (2 * a));
      }
    }
    std::vector<std::array<double, 4>> out;
    for (double t : roots)
    {
      out.push_back({ X0[0] + t * D[0], X0[1] + t * D[1], X0[2] + t * D[2], X0[3] + t * D[3] });
    }
    return out;
  }

  // Gaussian elimination with partial pivoting on an n x (n + 1) system.
  static bool Gauss(double A[4][5], int n, double* x)
  {
    for (int c = 0; c < n; ++c)
    {
      int p = c;
      for (int i = c + 1; i < n; ++i)
      {
        p = std::fabs(A[i][c]) > std::fabs(A[p][c]) ? i : p;
      }
      if (std::fabs(A[p][c]) < 1e-12)
      {
        return false;
      }
      std::swap(A[p], A[c]);
      for (int i = 0; i < n; ++i)
      {
        if (i != c)
        {
          const double r = A[i][c] / A[c][c];
          for (int j = c; j <= n; ++j)
          {
            A[i][j] -= r * A[c][j];
          }
        }
      }
    }
    for (int i = 0; i < n; ++i)
    {
      x[i] = A[i][n] / A[i][i];
    }
    return true;
  }

  std::vector<std::array<double, 9>> Triangles;
  std::vector<Face> Faces;
  std::vector<std::array<Vec3, 2>> Segments;
  double Diagonal = 1.0;
};

/// Balls of `shape` at theta = 0 (one-pass), classified with exact points at theta = 0.
inline vtkSmartPointer<vtkMedialBallClassifier> ClassifyAtThetaZero(vtkPolyData* shape, vtkIdType samples, int seed)
{
  vtkNew<vtkMedialAxisSampler> sampler;
  sampler->SetInputData(shape);
  sampler->SetNumberOfSamples(samples);
  sampler->SetMinimumSeparationAngle(0.0);
  sampler->SetRandomSeed(seed);
  auto classifier = vtkSmartPointer<vtkMedialBallClassifier>::New();
  classifier->SetInputConnection(sampler->GetOutputPort());
  classifier->SetSurfaceData(shape);
  classifier->SetMinimumSeparationAngle(0.0);
  classifier->Update();
  return classifier;
}
}

#endif
