// The float32 smoothing kernels (kernels/common/smoothing_kernels.hpp) against their float64 twins
// (src/model/smoothing_kernels.hpp), the W, grad W and lap W inside paper eq. 1-3 and 4-6. Method and
// tolerance: twin_support.hpp. Each kernel is compared relative to its peak value (at r = 0):
// near the support's edge both twins cancel h - r or h^2 - r^2, exactly in float32 for r near h.
#include "model/smoothing_kernels.hpp"
#include "common/smoothing_kernels.hpp"
#include "twin_support.hpp"

#include <limits>
#include <numbers>

namespace mssph::testing {
namespace {

// A support radius with an exact float32 value, so both twins use the same h.
double float_support(TwinDraws& draws) { return draws.uniform(0.005, 0.2); }

TEST(SmoothingKernelTwins, Poly6) {
  TwinDraws draws("SmoothingKernelTwins.Poly6");
  TwinComparison value("poly6 W(r^2)", 0.6);  // W > 1 % of its peak for r < 0.89 h: 0.8 of r in [0, 1.1 h)
  for (int k = 0; k < kDraws; ++k) {
    const double h = float_support(draws);
    const double r2 = draws.uniform(0.0, 1.21 * h * h);
    const Poly6Kernel expected(h);
    const kernels::SmoothingKernels got = kernels::SmoothingKernels::for_support(h);
    value.add(got.poly6(static_cast<float>(r2)), expected(r2), expected(0.0));
  }
}

TEST(SmoothingKernelTwins, Spiky) {
  TwinDraws draws("SmoothingKernelTwins.Spiky");
  TwinComparison value("spiky W(r)", 0.6);  // W > 1 % of its peak for r < 0.78 h: 0.7 of r in [0, 1.1 h)
  for (int k = 0; k < kDraws; ++k) {
    const double h = float_support(draws);
    const double r = draws.uniform(0.0, 1.1 * h);
    const SpikyKernel expected(h);
    value.add(kernels::SmoothingKernels::for_support(h).spiky(static_cast<float>(r)), expected(r), expected(0.0));
  }
}

TEST(SmoothingKernelTwins, SpikyGradient) {
  TwinDraws draws("SmoothingKernelTwins.SpikyGradient");
  TwinComparison gradient("spiky grad W(r_vec)", 0.6);
  for (int k = 0; k < kDraws; ++k) {
    const double h = float_support(draws);
    const Eigen::Vector3d r_vec = draws.vector(0.65 * h);  // |r_vec| up to 1.13 h
    const kernels::Vec3 r_float = to_float(r_vec);
    const double peak = 45.0 / (std::numbers::pi * std::pow(h, 4));  // |grad W| as r -> 0
    const kernels::SmoothingKernels kernel = kernels::SmoothingKernels::for_support(h);
    const Eigen::Vector3d got =
        to_double(kernel.spiky_gradient(r_float, kernel.pair_distance(kernels::squared_norm(r_float))));
    gradient.add(got, SpikyGradient(h)(r_vec), peak);
  }
}

// A pair's distance and its inverse from r^2 (PairDistance), against double; and coincident
// particles (r <= 1e-12 h), where the gradient has no direction: r = 0, 1 / r = 0, zero gradient.
// This is the host's arithmetic; the GPU's root (normal_rsqrt) is checked by the cuda agreement
// tests against the float64 reference (tests/backends), which run where a GPU is present. The
// threshold is at least the smallest normal float, so that root never takes a subnormal r^2.
TEST(SmoothingKernelTwins, PairDistance) {
  TwinDraws draws("SmoothingKernelTwins.PairDistance");
  TwinComparison distance("r from r^2", 0.9), inverse("1 / r from r^2", 0.9);
  for (int k = 0; k < kDraws; ++k) {
    const double h = float_support(draws);
    const float r2 = static_cast<float>(draws.uniform(1e-6 * h * h, 1.21 * h * h));
    const kernels::PairDistance d = kernels::SmoothingKernels::for_support(h).pair_distance(r2);
    distance.add(d.r, std::sqrt(double{r2}), std::sqrt(double{r2}));
    inverse.add(d.inverse, 1.0 / std::sqrt(double{r2}), 1.0 / std::sqrt(double{r2}));
  }
  const kernels::SmoothingKernels kernel = kernels::SmoothingKernels::for_support(0.02);
  for (const float r2 : {0.0f, 1e-30f}) {
    const kernels::PairDistance d = kernel.pair_distance(r2);
    EXPECT_EQ(d.r, 0.0f) << "r^2 = " << r2;
    EXPECT_EQ(d.inverse, 0.0f) << "r^2 = " << r2;
    const kernels::Vec3 gradient = kernel.spiky_gradient(kernels::Vec3{1e-15f, 0.0f, 0.0f}, d);
    EXPECT_EQ(gradient.x, 0.0f) << "r^2 = " << r2;
  }
  // A support so small that (1e-12 h)^2 is subnormal: a subnormal r^2 is still coincident.
  const kernels::SmoothingKernels tiny = kernels::SmoothingKernels::for_support(1e-9);
  EXPECT_EQ(tiny.coincident2, std::numeric_limits<float>::min());
  EXPECT_EQ(tiny.pair_distance(1e-39f).inverse, 0.0f);
}

TEST(SmoothingKernelTwins, ViscosityLaplacian) {
  TwinDraws draws("SmoothingKernelTwins.ViscosityLaplacian");
  TwinComparison laplacian("viscosity lap W(r)", 0.8);  // > 1 % of its peak for r < 0.99 h
  for (int k = 0; k < kDraws; ++k) {
    const double h = float_support(draws);
    const double r = draws.uniform(0.0, 1.1 * h);
    const ViscosityLaplacian expected(h);
    laplacian.add(kernels::SmoothingKernels::for_support(h).viscosity_laplacian(static_cast<float>(r)), expected(r),
                  expected(0.0));
  }
}

}  // namespace
}  // namespace mssph::testing
