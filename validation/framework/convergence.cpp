#include "framework/convergence.hpp"

#include "framework/backends.hpp"
#include "framework/fits.hpp"

#include <cmath>
#include <limits>

namespace mssph::validation {

CaseResult convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                              const std::vector<double>& expected, const std::vector<double>& measured,
                              double finest_tolerance, const std::string& backend,
                              const std::vector<double>& standard_error) {
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
  if (standard_error.empty()) {
    result.checks.push_back(range_check("observed order p of the relative error", "-", 0.0,
                                        std::numeric_limits<double>::infinity(), observed_order(spacing, error)));
  } else {
    const double order = observed_order(spacing, error);
    result.details += " observed order p = " + std::to_string(order) + " (reported, not checked);";
    const double combined =
        std::hypot(standard_error[finest] / std::abs(expected[finest]), standard_error[0] / std::abs(expected[0]));
    result.checks.push_back(bound_check("relative error at the finest dx minus at the coarsest (<= 2 standard errors)",
                                        "-", error[finest] - error[0], 2.0 * combined));
  }
  for (Check& c : result.checks) c.backend = backend;
  Series series{"error", "particle spacing dx [m]", spacing, {{"relative error", error}}, true};
  result.series.push_back(series);
  return result;
}

}  // namespace mssph::validation
