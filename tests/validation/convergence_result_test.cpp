// convergence_result (validation/framework/convergence.hpp) on made-up series: the order check,
// and the check that replaces it where each value is a mean with a standard error (the finest
// error may exceed the coarsest by at most twice their combined standard error).
#include "framework/convergence.hpp"
#include "framework/fits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mssph::validation {
namespace {

const std::vector<double> kSpacing{0.04, 0.02, 0.01};
const std::vector<double> kExpected{100.0, 100.0, 100.0};

Status second_check(const std::vector<double>& measured, const std::vector<double>& standard_error = {}) {
  const CaseResult r = convergence_result("q", kSpacing, kExpected, measured, 0.05, "cpu", standard_error);
  EXPECT_EQ(r.checks.size(), 2u);
  return r.checks.at(1).status;
}

TEST(ConvergenceResult, TheOrderCheckFailsAnErrorThatGrowsWithRefinement) {
  EXPECT_EQ(second_check({104.0, 102.0, 101.0}), Status::pass);  // p = 1
  EXPECT_EQ(second_check({101.0, 102.0, 104.0}), Status::fail);  // p = -1
}

// Errors 1 % and 3 % at the coarsest and finest spacings: 2 % apart. With standard errors of 1 %
// each the bound is 2 sqrt(2) % = 2.83 %: the growth is within the noise. With 0.5 % each it is
// 1.41 %: beyond it.
TEST(ConvergenceResult, WithStandardErrorsTheFinestMayExceedTheCoarsestOnlyWithinTheNoise) {
  const std::vector<double> growing{101.0, 102.0, 103.0};
  EXPECT_EQ(second_check(growing, {1.0, 1.0, 1.0}), Status::pass);
  EXPECT_EQ(second_check(growing, {0.5, 0.5, 0.5}), Status::fail);
  EXPECT_EQ(second_check({103.0, 102.0, 101.0}, {0.1, 0.1, 0.1}), Status::pass);
}

TEST(MeanAndStandardError, OfFourSamples) {
  const auto [mean, error] = mean_and_standard_error({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(mean, 2.5);
  EXPECT_NEAR(error, std::sqrt(5.0 / 3.0) / 2.0, 1e-15);  // sample variance 5/3, over sqrt(4)
}

}  // namespace
}  // namespace mssph::validation
