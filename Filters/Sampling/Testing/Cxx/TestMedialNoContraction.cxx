// SPDX-License-Identifier: BSD-3-Clause
// The build must not fuse a * b + c into a fused multiply-add (one rounding instead
// of two): cmake/medialaxisCompileSettings.cmake passes -ffp-contract=off. With fusing,
// the watertight ray test's edge function of a shared edge, c.x b.y - c.y b.x, is no
// longer the exact negative of the neighbour's, b.x c.y - b.y c.x, so a ray through
// the edge can slip between the two triangles. Built with -march=native and fusing
// allowed, four tests failed, among them TestMedialSurfaceImport ("ray slips through
// the surface") and TestMedialTriangleDistanceBound.
//
// EdgeFunction is compiled for FMA (x86-64: a target attribute, used only when the CPU
// has FMA; aarch64 always has it), so if the flag is dropped the compiler fuses it and
// the antisymmetry below fails on 100,000 random edges. Skipped where no FMA is
// available (nothing could be fused there).
#include <cmath>
#include <cstdio>
#include <random>

namespace
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define MEDIAL_FMA_TARGET __attribute__((target("fma"), noinline))
bool HasFusedMultiplyAdd()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("fma");
}
#elif defined(__aarch64__)
#define MEDIAL_FMA_TARGET __attribute__((noinline))
bool HasFusedMultiplyAdd()
{
  return true;
}
#else
#define MEDIAL_FMA_TARGET
bool HasFusedMultiplyAdd()
{
  return false;
}
#endif

// The 2D edge function of the watertight ray test, in the form the ray code uses.
MEDIAL_FMA_TARGET double EdgeFunction(const double b[2], const double c[2])
{
  return c[0] * b[1] - c[1] * b[0];
}
}

int TestMedialNoContraction(int, char*[])
{
  if (!HasFusedMultiplyAdd())
  {
    std::printf("no fused multiply-add on this CPU: nothing to check\n");
    return MEDIALAXIS_SKIP_RETURN_CODE;
  }
  std::mt19937_64 random(20261203);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int asymmetric = 0;
  for (int trial = 0; trial < 100000; ++trial)
  {
    const double b[2] = { unit(random), unit(random) };
    const double c[2] = { unit(random), unit(random) };
    if (EdgeFunction(b, c) != -EdgeFunction(c, b))
    {
      ++asymmetric;
    }
  }
  // A plain product difference of equal terms is zero; fused, it is the rounding error
  // of one product (2^-60 for x = 1 + 2^-30).
  volatile double x = 1.0 + std::ldexp(1.0, -30);
  const double same[2] = { x, x };
  const double zero = EdgeFunction(same, same);
  std::printf("edges whose two orientations are not exact negatives: %d of 100000; x*x - x*x = %g\n",
    asymmetric, zero);
  if (asymmetric != 0 || zero != 0.0)
  {
    std::printf("FAILED: the compiler fused multiply-adds; build with -ffp-contract=off\n");
    return 1;
  }
  return 0;
}
