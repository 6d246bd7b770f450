#pragma once
// The two-sided Mann-Whitney U test (Wilcoxon rank-sum test): do two samples of timings come
// from the same distribution? Rank-based, so a few outliers from a noisy machine do not decide
// it, and no normality is assumed. The test Google Benchmark's tools/compare.py uses.
#include <cstddef>
#include <vector>

namespace mssph::bench {

struct MannWhitneyResult {
  double u = 0.0;        // U of the first sample: pairs (x, y) with x > y, ties counting 1/2
  double p_value = 1.0;  // two-sided
  bool exact = false;    // exact permutation distribution, else the normal approximation
};

// Exact distribution of U when neither sample has more than kExactLimit values and there are no
// ties; otherwise the normal approximation with tie correction and continuity correction
// (Conover, Practical Nonparametric Statistics, 3rd ed., section 5.1). Both samples need at
// least one value.
inline constexpr std::size_t kExactLimit = 20;
MannWhitneyResult mann_whitney_u(const std::vector<double>& x, const std::vector<double>& y);

// The smallest two-sided p-value the test can give for samples of these sizes (complete
// separation): when it is not below alpha, no difference can be significant.
double smallest_p_value(std::size_t nx, std::size_t ny);

}  // namespace mssph::bench
