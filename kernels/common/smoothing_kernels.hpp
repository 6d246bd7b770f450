#pragma once
// Float32 smoothing kernels of Mueller, Charypar and Gross 2003, support radius h (the same
// functions as src/model/smoothing_kernels.hpp, written for the GPU: constants precomputed, no
// branches beyond the support test and, for a pair's distance, the coincident one).
#include "vec_math.hpp"

#include <algorithm>
#include <limits>

namespace mssph::kernels {

// A pair's distance r = |x_i - x_j| and 1 / r from r^2. On the GPU both come from one reciprocal
// square root, the hardware approximation behind rsqrtf (within 2 ulp, CUDA C++ Programming
// Guide), so a pair term needs neither a square root nor a division: those are IEEE instruction
// sequences with a slow-path branch, and a warp runs a pair term whenever one of its 32 lanes
// meets a neighbour, at nearly every candidate. The host takes the IEEE square root and division.
// Coincident particles (r <= 1e-12 h, where the spiky gradient has no direction, or r^2 at most
// the smallest normal float) get r = 0 and 1 / r = 0; a NaN r^2 gives a NaN r on both. Every r^2
// past that test is a normal float or +inf, so the GPU's root (normal_rsqrt) needs no rescaling
// of subnormal arguments.
struct PairDistance {
  float r;        // [m]
  float inverse;  // 1 / r [1/m], 0 for coincident particles
};

struct SmoothingKernels {
  float h;
  float h2;
  float poly6_coefficient;        // 315 / (64 pi h^9)
  float spiky_value_coefficient;  // 15 / (pi h^6)
  float spiky_coefficient;        // -45 / (pi h^6)
  float laplacian_coefficient;    // 45 / (pi h^6)
  float coincident2;              // (1e-12 h)^2, at least the smallest normal float: below it a
                                  // pair counts as coincident (PairDistance)

  static SmoothingKernels for_support(double support) {
    const double pi = 3.14159265358979323846;
    const double h6 = support * support * support * support * support * support;
    return {static_cast<float>(support),
            static_cast<float>(support * support),
            static_cast<float>(315.0 / (64.0 * pi * h6 * support * support * support)),
            static_cast<float>(15.0 / (pi * h6)),
            static_cast<float>(-45.0 / (pi * h6)),
            static_cast<float>(45.0 / (pi * h6)),
            static_cast<float>(std::max(1e-24 * support * support, double{std::numeric_limits<float>::min()}))};
  }

  MSSPH_HD PairDistance pair_distance(float r2) const {
#if defined(__CUDA_ARCH__)
    const float inverse = r2 > coincident2 ? normal_rsqrt(r2) : 0.0f;
    return {r2 * inverse, inverse};
#else
    if (r2 <= coincident2) return {0.0f, 0.0f};
    const float r = std::sqrt(r2);
    return {r, 1.0f / r};
#endif
  }

  // poly6 W(r) from r^2 (moment matrices and rest volumes of deformable bodies).
  MSSPH_HD float poly6(float r2) const {
    if (r2 >= h2) return 0.0f;
    const float d = h2 - r2;
    return poly6_coefficient * d * d * d;
  }
  // Spiky kernel W(r) (number densities behind pressure, cpu_reference/density.hpp).
  MSSPH_HD float spiky(float r) const {
    if (r >= h) return 0.0f;
    const float d = h - r;
    return spiky_value_coefficient * d * d * d;
  }
  // Spiky gradient with respect to x_i, r_vec = x_i - x_j at distance d (pressure, elasticity); zero
  // for coincident particles, where d.inverse is 0.
  MSSPH_HD Vec3 spiky_gradient(Vec3 r_vec, PairDistance d) const {
    if (d.r >= h) return Vec3{0.0f, 0.0f, 0.0f};
    const float s = h - d.r;
    return (spiky_coefficient * s * s * d.inverse) * r_vec;
  }
  // Viscosity Laplacian (paper eq. 3).
  MSSPH_HD float viscosity_laplacian(float r) const { return r >= h ? 0.0f : laplacian_coefficient * (h - r); }
};

}  // namespace mssph::kernels
