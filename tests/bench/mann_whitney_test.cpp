// The Mann-Whitney U test against values computed by hand and against published ones.
#include "bench/mann_whitney.hpp"

#include <gtest/gtest.h>

namespace mssph::bench {
namespace {

TEST(MannWhitney, CompleteSeparationOfThreeAgainstThree) {
  // U = 0; of the C(6, 3) = 20 equally likely arrangements, one gives U = 0 and one U = 9:
  // two-sided p = 2 / 20. So 3 repetitions a side can never reach p < 0.05.
  const MannWhitneyResult r = mann_whitney_u({1, 2, 3}, {4, 5, 6});
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_TRUE(r.exact);
  EXPECT_NEAR(r.p_value, 0.1, 1e-12);
  EXPECT_NEAR(smallest_p_value(3, 3), 0.1, 1e-12);
  EXPECT_NEAR(smallest_p_value(4, 4), 2.0 / 70.0, 1e-12);  // C(8, 4) = 70
}

TEST(MannWhitney, FiveAgainstFiveMatchesTheCriticalValueTable) {
  // Tables of the Mann-Whitney test (e.g. Siegel and Castellan, Nonparametric Statistics, table J)
  // give 2 as the critical U for n1 = n2 = 5 at two-sided alpha 0.05. By hand: the number of the
  // C(10, 5) = 252 arrangements with U = 0, 1, 2, 3 is 1, 1, 2, 3 (partitions of U into at most
  // 5 parts of at most 5), so P(U <= 2) = 4/252 and P(U <= 3) = 7/252.
  const std::vector<double> y{5, 6, 7, 8, 9};
  const MannWhitneyResult u2 = mann_whitney_u({1, 2, 3, 4, 6.5}, y);  // 6.5 beats 5 and 6
  EXPECT_DOUBLE_EQ(u2.u, 2.0);
  EXPECT_NEAR(u2.p_value, 8.0 / 252.0, 1e-12);
  EXPECT_LT(u2.p_value, 0.05);
  const MannWhitneyResult u3 = mann_whitney_u({1, 2, 3, 4, 7.5}, y);
  EXPECT_DOUBLE_EQ(u3.u, 3.0);
  EXPECT_NEAR(u3.p_value, 14.0 / 252.0, 1e-12);
  EXPECT_GT(u3.p_value, 0.05);
}

TEST(MannWhitney, UnequalSizesExactAsPublished) {
  // SciPy's documentation of scipy.stats.mannwhitneyu (ages of 5 male and 4 female subjects):
  // U1 = 17, exact two-sided p = 0.1111 = 2 * 7/126.
  const MannWhitneyResult r = mann_whitney_u({19, 22, 16, 29, 24}, {20, 11, 17, 12});
  EXPECT_DOUBLE_EQ(r.u, 17.0);
  EXPECT_TRUE(r.exact);
  EXPECT_NEAR(r.p_value, 2.0 * 7.0 / 126.0, 1e-12);
}

TEST(MannWhitney, TiesUseTheNormalApproximationWithTieCorrection) {
  // x = {1, 2, 2, 3}, y = {2, 3, 4, 5}. Mid-ranks: 1 -> 1; the three 2s -> 3; the two 3s -> 5.5;
  // 4 -> 7; 5 -> 8. R_x = 1 + 3 + 3 + 5.5 = 12.5, U = R_x - 4*5/2 = 2.5. E[U] = 8; ties
  // t = 3 and 2 give sum(t^3 - t) = 30, so Var[U] = 16/12 (9 - 30/56) = 11.2857.
  // p = erfc((|2.5 - 8| - 0.5) / sqrt(2 * 11.2857)) = 0.136658 (scipy.stats.mannwhitneyu agrees).
  const MannWhitneyResult r = mann_whitney_u({1, 2, 2, 3}, {2, 3, 4, 5});
  EXPECT_DOUBLE_EQ(r.u, 2.5);
  EXPECT_FALSE(r.exact);
  EXPECT_NEAR(r.p_value, 0.1366582477, 1e-9);
}

TEST(MannWhitney, LargeSamplesUseTheNormalApproximation) {
  // 25 against 25, completely separated: U = 0, E[U] = 312.5, Var[U] = 625 * 51 / 12;
  // p = erfc(312 / sqrt(2 Var)) = 1.4157e-9.
  std::vector<double> x, y;
  for (int i = 0; i < 25; ++i) {
    x.push_back(i);
    y.push_back(25 + i);
  }
  const MannWhitneyResult r = mann_whitney_u(x, y);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_FALSE(r.exact);
  EXPECT_NEAR(r.p_value / 1.4156562248e-9, 1.0, 1e-8);
}

TEST(MannWhitney, SymmetricInItsSamples) {
  const std::vector<double> x{3.1, 2.7, 4.4, 5.0, 3.9, 2.2};
  const std::vector<double> y{4.1, 5.2, 6.3, 3.0, 5.8};
  const MannWhitneyResult xy = mann_whitney_u(x, y);
  const MannWhitneyResult yx = mann_whitney_u(y, x);
  EXPECT_DOUBLE_EQ(xy.u + yx.u, 30.0);  // U_x + U_y = nx ny
  EXPECT_NEAR(xy.p_value, yx.p_value, 1e-12);
}

TEST(MannWhitney, IdenticalSamplesGiveNoEvidence) {
  EXPECT_DOUBLE_EQ(mann_whitney_u({1, 1, 1}, {1, 1, 1}).p_value, 1.0);
  EXPECT_THROW(mann_whitney_u({}, {1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace mssph::bench
