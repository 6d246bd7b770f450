#include "framework/convergence.hpp"

#include "framework/backends.hpp"
#include "framework/fits.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace mssph::validation {

Check observed_order_check(std::string quantity, const std::vector<double>& spacing, const std::vector<double>& error,
                           double smallest_order) {
  return range_check(std::move(quantity), "-", smallest_order, std::numeric_limits<double>::infinity(),
                     observed_order(spacing, error));
}

CaseResult convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                              const std::vector<double>& expected, const std::vector<double>& measured,
                              double finest_tolerance, const std::string& backend) {
  CaseResult result;
  std::vector<double> error;
  result.details = "relative error of " + quantity + " by spacing:";
  for (std::size_t k = 0; k < spacing.size(); ++k) {
    error.push_back(std::abs(measured[k] - expected[k]) / std::abs(expected[k]));
    result.details += " dx = " + exact(spacing[k]).substr(0, 7) + " m: " + std::to_string(error.back()) + ";";
  }
  const std::size_t finest = spacing.size() - 1;
  result.checks.push_back(relative_check(quantity + " at the finest dx = " + exact(spacing[finest]).substr(0, 7) + " m",
                                         "-", expected[finest], measured[finest], finest_tolerance));
  result.checks.push_back(observed_order_check("observed order p of the relative error", spacing, error, 0.0));
  for (Check& c : result.checks) c.backend = backend;
  Series series{"error", "particle spacing dx [m]", spacing, {{"relative error", error}}, true};
  result.series.push_back(series);
  return result;
}

CaseResult self_convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                                   const std::vector<double>& expected, const std::vector<double>& measured,
                                   double finest_tolerance, const std::string& backend) {
  if (spacing.size() < 3) throw std::invalid_argument("self_convergence_result: needs three spacings or more");
  const std::size_t finest = spacing.size() - 1;
  CaseResult result;
  std::vector<double> ratio;  // measured over expected: the expectation may move with the spacing
  std::vector<double> error;
  result.details = "signed relative error of " + quantity + " by spacing:";
  for (std::size_t k = 0; k < spacing.size(); ++k) {
    ratio.push_back(measured[k] / expected[k]);
    error.push_back(std::abs(ratio.back() - 1.0));
    result.details += " dx = " + exact(spacing[k]).substr(0, 7) + " m: " + std::to_string(ratio.back() - 1.0) + ";";
  }
  const double first_change = std::abs(ratio[1] - ratio[0]);
  const double last_change = std::abs(ratio[finest] - ratio[finest - 1]);
  const double change_ratio = first_change > 0.0  ? last_change / first_change
                              : last_change > 0.0 ? std::numeric_limits<double>::infinity()
                                                  : 0.0;
  result.details += " changes of measured / expected " + std::to_string(first_change) + " (first), " +
                    std::to_string(last_change) + " (last);";
  const GridConvergence g = grid_convergence({spacing[finest - 2], spacing[finest - 1], spacing[finest]},
                                             {ratio[finest - 2], ratio[finest - 1], ratio[finest]});
  result.details += g.monotone ? " apparent order " + std::to_string(g.order) + ", Richardson limit " +
                                     std::to_string(g.limit - 1.0) + " from the expectation;"
                               : " no Richardson limit: the finest three do not converge monotonically;";
  result.checks.push_back(relative_check(quantity + " at the finest dx = " + exact(spacing[finest]).substr(0, 7) + " m",
                                         "-", expected[finest], measured[finest], finest_tolerance));
  result.checks.push_back(
      bound_check("last change between spacings over the first (the values settle)", "-", change_ratio, 1.0));
  for (Check& c : result.checks) c.backend = backend;
  Series series{"error", "particle spacing dx [m]", spacing, {{"relative error", error}}, true};
  result.series.push_back(series);
  return result;
}

}  // namespace mssph::validation
