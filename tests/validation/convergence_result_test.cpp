// convergence_result (validation/framework/convergence.hpp) on made-up series: the order check;
// and self_convergence_result, whose second check asks that the values settle.
#include "framework/convergence.hpp"

#include <gtest/gtest.h>

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
  EXPECT_NE(r.details.find("Richardson limit 93.333333"), std::string::npos) << r.details;
  EXPECT_EQ(r.checks.at(0).status, Status::pass);
}

}  // namespace
}  // namespace mssph::validation
