#include "bench/mann_whitney.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mssph::bench {
namespace {

struct Ranking {
  double rank_sum_x = 0.0;  // sum of the mid-ranks of the first sample
  double tie_term = 0.0;    // sum over tie groups of t^3 - t
  bool has_ties = false;
};

Ranking rank(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<std::pair<double, bool>> all;  // value, from x
  all.reserve(x.size() + y.size());
  for (double v : x) all.emplace_back(v, true);
  for (double v : y) all.emplace_back(v, false);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Ranking r;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j].first == all[i].first) ++j;
    const double t = static_cast<double>(j - i);
    const double mid_rank = 0.5 * static_cast<double>(i + 1 + j);  // mean of ranks i+1 .. j
    for (std::size_t k = i; k < j; ++k) {
      if (all[k].second) r.rank_sum_x += mid_rank;
    }
    if (t > 1.0) {
      r.has_ties = true;
      r.tie_term += t * t * t - t;
    }
    i = j;
  }
  return r;
}

// Number of arrangements of nx x-values and ny y-values with U = u, for u = 0 .. nx ny, by the
// recurrence c(u; m, n) = c(u - n; m - 1, n) + c(u; m, n - 1) (the largest value is an x, which
// exceeds all n y-values, or a y, which adds nothing to U).
std::vector<double> exact_counts(std::size_t nx, std::size_t ny) {
  // table[m][u] for the current n; built up over n.
  std::vector<std::vector<double>> prev(nx + 1), cur(nx + 1);
  for (std::size_t m = 0; m <= nx; ++m) prev[m] = {1.0};  // n = 0: U = 0 only
  for (std::size_t n = 1; n <= ny; ++n) {
    cur[0] = {1.0};
    for (std::size_t m = 1; m <= nx; ++m) {
      cur[m].assign(m * n + 1, 0.0);
      for (std::size_t u = 0; u < prev[m].size(); ++u) cur[m][u] += prev[m][u];
      for (std::size_t u = 0; u < cur[m - 1].size(); ++u) cur[m][u + n] += cur[m - 1][u];
    }
    std::swap(prev, cur);
  }
  return prev[nx];
}

double exact_two_sided_p(double u, std::size_t nx, std::size_t ny) {
  const std::vector<double> counts = exact_counts(nx, ny);
  const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
  const auto k = static_cast<std::size_t>(std::llround(u));
  const double lower = std::accumulate(counts.begin(), counts.begin() + static_cast<long>(k) + 1, 0.0);
  const double upper = std::accumulate(counts.begin() + static_cast<long>(k), counts.end(), 0.0);
  return std::min(1.0, 2.0 * std::min(lower, upper) / total);
}

}  // namespace

MannWhitneyResult mann_whitney_u(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.empty() || y.empty()) throw std::invalid_argument("Mann-Whitney U test: both samples need a value");
  const double nx = static_cast<double>(x.size());
  const double ny = static_cast<double>(y.size());
  const Ranking r = rank(x, y);
  MannWhitneyResult result;
  result.u = r.rank_sum_x - nx * (nx + 1.0) / 2.0;
  if (!r.has_ties && x.size() <= kExactLimit && y.size() <= kExactLimit) {
    result.exact = true;
    result.p_value = exact_two_sided_p(result.u, x.size(), y.size());
    return result;
  }
  // Normal approximation: E[U] = nx ny / 2, Var[U] = nx ny / 12 ((N + 1) - sum(t^3 - t) / (N (N - 1))).
  const double n = nx + ny;
  const double mean = nx * ny / 2.0;
  const double variance = nx * ny / 12.0 * ((n + 1.0) - r.tie_term / (n * (n - 1.0)));
  if (variance <= 0.0) {  // every value equal: no evidence of any difference
    result.p_value = 1.0;
    return result;
  }
  const double deviation = std::max(0.0, std::abs(result.u - mean) - 0.5);           // continuity correction
  result.p_value = std::min(1.0, std::erfc(deviation / std::sqrt(2.0 * variance)));  // 2 (1 - Phi(z))
  return result;
}

double smallest_p_value(std::size_t nx, std::size_t ny) {
  std::vector<double> x(nx), y(ny);
  std::iota(x.begin(), x.end(), 0.0);
  std::iota(y.begin(), y.end(), static_cast<double>(nx));
  return mann_whitney_u(x, y).p_value;
}

}  // namespace mssph::bench
