// A case whose expectation is wrong on purpose, so the tests can check that a wrong result is
// reported as FAIL and makes `mssph validate` exit 1: a flat punch's force grows linearly with
// the indentation, F = 2 a E* d (Johnson, Contact Mechanics, 1985, eq. 5.5 with the punch radius
// a), and Hertz's exponent 1.5 is checked against it through the Hertz case's own fit.
#include "framework/case_functions.hpp"
#include "physics/hertz/hertz.hpp"

namespace mssph::validation {

CaseResult run_wrong_expectation_case(const CaseContext&) {
  Indentation punch;
  const double stiffness = 2.0 * 0.02 * 1.0e5 / (1.0 - 0.3 * 0.3);  // 2 a E*, a = 2 cm [N/m]
  for (int k = 1; k <= 50; ++k) {
    punch.depth.push_back(5e-4 * k);
    punch.force.push_back(stiffness * punch.depth.back());
  }
  const HertzFit fit = fit_hertz(punch, 0.0, 1.0);
  CaseResult result;
  result.resolution = "analytic curve, 50 points";
  result.checks.push_back(absolute_check("exponent of F(d) (expected Hertz's, wrongly)", "-", 1.5, fit.exponent, 0.15));
  for (Check& c : result.checks) c.backend = "none";
  return result;
}

}  // namespace mssph::validation
