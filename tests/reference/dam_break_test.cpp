// The dam-break comparison (validation/physics/dam_break): the surge comparison on known lines,
// the collapse on the reference backend against Martin and Moyce 1952, failing when the water is
// made viscous, and, on the cpu backend, the column's height against the kernel support (decision
// 061).
#include "physics/dam_break/dam_break.hpp"
#include "framework/backends.hpp"
#include "physics/dam_break/experiments.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace mssph::testing {
namespace {

// A simulated front Z = 1 + s (T - T0), sampled finely, against the experiment's points on
// Z = 1 + 1.3 (T - 0.2).
validation::SurgeComparison compare_line(double speed, double start) {
  std::vector<double> T;
  std::vector<double> Z;
  for (double t = 0.0; t <= 4.0; t += 0.01) {
    T.push_back(t);
    Z.push_back(1.0 + speed * std::max(0.0, t - start));
  }
  std::vector<double> experiment_T;
  std::vector<double> experiment_Z;
  for (double t = 0.2; t <= 3.0; t += 0.25) {
    experiment_T.push_back(t);
    experiment_Z.push_back(1.0 + 1.3 * (t - 0.2));
  }
  return validation::compare_surge(T, Z, experiment_T, experiment_Z, 1.5, 3.5);
}

TEST(DamBreak, SurgeComparisonAlignsTheReleaseAndMeasuresTheSpeed) {
  const validation::SurgeComparison same = compare_line(1.3, 0.0);
  EXPECT_NEAR(same.speed, 1.3, 1e-9);
  EXPECT_NEAR(same.expected_speed, 1.3, 1e-9);
  EXPECT_NEAR(same.offset, 0.2, 1e-9);  // released 0.2 later in the experiment
  EXPECT_LT(same.largest_deviation, 1e-9);
  EXPECT_EQ(same.compared_points, 6u);  // Z from 1.65 to 3.275

  const validation::SurgeComparison slow = compare_line(1.0, 0.0);
  EXPECT_NEAR(slow.speed, 1.0, 1e-9);
  EXPECT_GT(slow.largest_deviation, 0.1);  // 2.865 where the experiment reaches 3.275: 12.5 %
}

struct Collapse {
  validation::SurgeComparison surge;
  double largest_height_deviation = 0.0;
};

// The case's checks at a = 10 dx (coarser than the case's, for the suite's time).
constexpr double kSpacing = validation::kDamBreakColumnWidth / 10.0;
Collapse collapse(const std::vector<std::string>& overrides, const std::string& backend = "reference") {
  const validation::DamBreakMeasurement m =
      validation::measure_dam_break(backend, validation::dam_break_scene(kSpacing, overrides), 0.002);
  const validation::NondimensionalCollapse c = validation::nondimensional(m);
  const validation::DamBreakExperiment& experiment = validation::martin_moyce_1952();
  return {validation::compare_surge(c, experiment), validation::largest_height_deviation(c, experiment)};
}

// Water (1 mPa s) collapses as in the experiment, within the case's 10 %; the same column as
// viscous as honey, 10 Pa s (the planted error), surges more slowly than the experiment.
TEST(DamBreak, WaterColumnCollapsesAsMartinAndMoyceMeasuredAndAViscousOneDoesNot) {
  const Collapse water = collapse({});
  EXPECT_NEAR(water.surge.speed, water.surge.expected_speed, 0.10 * water.surge.expected_speed);
  EXPECT_LT(water.surge.largest_deviation, 0.10);
  EXPECT_LT(water.largest_height_deviation, 0.10);

  const Collapse honey = collapse({"materials/water/viscosity=10"});
  EXPECT_LT(honey.surge.speed, 0.90 * honey.surge.expected_speed);
}

// Fewer neighbours hold the column up late in the collapse: at a = 10 dx on the cpu backend the
// height's largest deviation is 21.6 % at h = 1.5 dx and 3.2 % at h = 2.5 dx (9.3 % at the
// default 2 dx). The full case lets h / dx grow with the resolution for this (decision 061).
TEST(DamBreak, AWiderKernelSupportDrainsTheColumnAsMeasured) {
  const std::string narrow_h = "simulation/smoothing_length=" + validation::exact(1.5 * kSpacing);
  const std::string wide_h = "simulation/smoothing_length=" + validation::exact(2.5 * kSpacing);
  ASSERT_DOUBLE_EQ(validation::dam_break_scene(kSpacing, {wide_h}).simulation.smoothing_length, 2.5 * kSpacing);
  const Collapse narrow = collapse({narrow_h}, "cpu");
  const Collapse wide = collapse({wide_h}, "cpu");
  EXPECT_GT(narrow.largest_height_deviation - wide.largest_height_deviation, 0.10);
  EXPECT_LT(wide.largest_height_deviation, 0.10);  // the case's tolerance
}

}  // namespace
}  // namespace mssph::testing
