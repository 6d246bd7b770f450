#include "framework/convergence.hpp"

#include "framework/backends.hpp"
#include "framework/fits.hpp"

#include <cmath>
#include <limits>

namespace mssph::validation {

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
  result.checks.push_back(range_check("observed order p of the relative error", "-", 0.0,
                                      std::numeric_limits<double>::infinity(), observed_order(spacing, error)));
  for (Check& c : result.checks) c.backend = backend;
  Series series{"error", "particle spacing dx [m]", spacing, {{"relative error", error}}, true};
  result.series.push_back(series);
  return result;
}

CaseResult self_convergence_result(const std::string& quantity, const std::vector<double>& spacing,
                                   const std::vector<double>& expected, const std::vector<double>& measured,
                                   double finest_tolerance, const std::string& backend) {
  const std::size_t finest = spacing.size() - 1;
  CaseResult result;
  std::vector<double> error;
  result.details = "signed relative error of " + quantity + " by spacing:";
  for (std::size_t k = 0; k < spacing.size(); ++k) {
    error.push_back(measured[k] / expected[k] - 1.0);
    result.details += " dx = " + exact(spacing[k]).substr(0, 7) + " m: " + std::to_string(error.back()) + ";";
  }
  const double first_change = std::abs(measured[1] - measured[0]);
  const double last_change = std::abs(measured[finest] - measured[finest - 1]);
  const double change_ratio = first_change > 0.0  ? last_change / first_change
                              : last_change > 0.0 ? std::numeric_limits<double>::infinity()
                                                  : 0.0;
  // Apparent order over the mean refinement ratio r, and Richardson's limit q + (q - q_prev) / (r^p - 1).
  const double ratio = std::pow(spacing[0] / spacing[finest], 1.0 / static_cast<double>(finest));
  const double order = std::log(1.0 / change_ratio) / std::log(ratio) / static_cast<double>(finest - 1);
  const double limit = measured[finest] + (measured[finest] - measured[finest - 1]) / (std::pow(ratio, order) - 1.0);
  result.details += " changes " + std::to_string(first_change) + " (first), " + std::to_string(last_change) +
                    " (last); apparent order " + std::to_string(order) + "; Richardson limit " + std::to_string(limit) +
                    " (" + std::to_string(limit / expected[finest] - 1.0) + " from the expectation);";
  result.checks.push_back(relative_check(quantity + " at the finest dx = " + exact(spacing[finest]).substr(0, 7) + " m",
                                         "-", expected[finest], measured[finest], finest_tolerance));
  result.checks.push_back(
      bound_check("last change between spacings over the first (the values settle)", "-", change_ratio, 1.0));
  for (Check& c : result.checks) c.backend = backend;
  for (double& e : error) e = std::abs(e);
  Series series{"error", "particle spacing dx [m]", spacing, {{"relative error", error}}, true};
  result.series.push_back(series);
  return result;
}

}  // namespace mssph::validation
