// convergence_result (validation/framework/convergence.hpp) on made-up series: the order check
// (observed_order_check); self_convergence_result, whose second check asks that the values
// settle; and grid_convergence (fits.hpp), the apparent order and Richardson limit it reports.
#include "framework/convergence.hpp"
#include "framework/fits.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace mssph::validation {
namespace {

const std::vector<double> kSpacing{0.04, 0.02, 0.01};
const std::vector<double> kExpected{100.0, 100.0, 100.0};

Status second_check(const std::vector<double>& measured) {
  const CaseResult r = convergence_result("q", kSpacing, kExpected, measured, 0.05, "cpu");
  EXPECT_EQ(r.checks.size(), 2u);
  return r.checks.at(1).status;
}

TEST(ConvergenceResult, TheOrderCheckFailsAnErrorThatGrowsWithRefinement) {
  EXPECT_EQ(second_check({104.0, 102.0, 101.0}), Status::pass);  // p = 1
  EXPECT_EQ(second_check({101.0, 102.0, 104.0}), Status::fail);  // p = -1
}

// The bound rotating_sphere asks of its torque's error: with h halved, the error at most 2^-1/2 of
// the coarser one (order 1/2). An error that shrinks more slowly fails.
TEST(ObservedOrderCheck, FailsAnErrorThatShrinksMoreSlowlyThanAsked) {
  EXPECT_EQ(observed_order_check("q", {0.02, 0.01}, {0.2, 0.1}, 0.5).status, Status::pass);   // p = 1
  EXPECT_EQ(observed_order_check("q", {0.02, 0.01}, {0.2, 0.16}, 0.5).status, Status::fail);  // p = 0.32
}

// shear_decay's order check reads grid_convergence's order, NaN where the values do not converge
// monotonically: a range check fails it.
TEST(RangeCheck, FailsAnOrderThatIsNotDefined) {
  const GridConvergence g = grid_convergence({0.04, 0.02, 0.01}, {0.96, 0.99, 0.97});
  EXPECT_EQ(range_check("q", "-", 0.5, std::numeric_limits<double>::infinity(), g.order).status, Status::fail);
}

Status settling_check(const std::vector<double>& measured) {
  const CaseResult r = self_convergence_result("q", kSpacing, kExpected, measured, 0.10, "cpu");
  EXPECT_EQ(r.checks.size(), 2u);
  return r.checks.at(1).status;
}

// A limit 6 % off the expectation passes the first check at 10 % and the second when the changes
// shrink, whatever the error against the expectation does; changes that grow fail.
TEST(SelfConvergenceResult, TheValuesMustSettleAsTheSpacingShrinks) {
  EXPECT_EQ(settling_check({110.0, 96.0, 94.5}), Status::pass);  // changes 14, 1.5
  EXPECT_EQ(settling_check({94.0, 95.0, 97.0}), Status::fail);   // changes 1, 2
  EXPECT_EQ(settling_check({94.0, 94.0, 94.0}), Status::pass);   // settled
  EXPECT_EQ(settling_check({94.0, 94.0, 95.0}), Status::fail);   // moves only at the finest
}

TEST(SelfConvergenceResult, ReportsTheRichardsonLimit) {
  // Changes 8 and 2 over a refinement ratio of 2: order 2, limit 94 - 2 / 3.
  const CaseResult r = self_convergence_result("q", kSpacing, kExpected, {104.0, 96.0, 94.0}, 0.10, "cpu");
  EXPECT_NE(r.details.find("apparent order 2.000000"), std::string::npos) << r.details;
  EXPECT_NE(r.details.find("Richardson limit -0.066667"), std::string::npos) << r.details;
  EXPECT_EQ(r.checks.at(0).status, Status::pass);
}

TEST(SelfConvergenceResult, NeedsThreeSpacings) {
  EXPECT_THROW(self_convergence_result("q", {0.02, 0.01}, {1.0, 1.0}, {1.1, 1.05}, 0.1, "cpu"), std::invalid_argument);
}

// q = 1 + 50 h^2 at spacings whose ratios differ (1.25, then 1.2): order 2 and limit 1 come back.
TEST(GridConvergence, UnequalRatios) {
  const std::array<double, 3> h{0.01, 0.008, 0.04 / 6.0};
  const GridConvergence g =
      grid_convergence(h, {1.0 + 50.0 * h[0] * h[0], 1.0 + 50.0 * h[1] * h[1], 1.0 + 50.0 * h[2] * h[2]});
  ASSERT_TRUE(g.monotone);
  EXPECT_NEAR(g.order, 2.0, 1e-9);
  EXPECT_NEAR(g.limit, 1.0, 1e-12);
}

TEST(GridConvergence, NoLimitWhereTheValuesOscillateOrDoNotSettle) {
  EXPECT_FALSE(grid_convergence({0.04, 0.02, 0.01}, {1.1, 0.95, 1.02}).monotone);  // changes of both signs
  EXPECT_FALSE(grid_convergence({0.04, 0.02, 0.01}, {1.0, 1.01, 1.03}).monotone);  // the finer change larger
  EXPECT_FALSE(grid_convergence({0.04, 0.02, 0.01}, {1.0, 1.0, 1.0}).monotone);    // no change to fit
}

}  // namespace
}  // namespace mssph::validation
