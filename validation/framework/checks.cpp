#include "validation_case.hpp"

#include <cmath>
#include <sstream>

namespace mssph::validation {
namespace {

std::string number(double x) {
  std::ostringstream text;
  text.precision(4);
  text << x;
  return text.str();
}

// A NaN measurement (a blown-up run) fails every check.
Status judged(double error, double tolerance) {
  return std::isfinite(error) && error <= tolerance ? Status::pass : Status::fail;
}

Check made(std::string quantity, std::string unit, double expected, std::string expected_text, double measured,
           std::string error_kind, double tolerance) {
  Check c;
  c.quantity = std::move(quantity);
  c.unit = std::move(unit);
  c.expected = expected;
  c.expected_text = std::move(expected_text);
  c.measured = measured;
  c.error_kind = std::move(error_kind);
  c.tolerance = tolerance;
  return c;
}

}  // namespace

const char* status_name(Status status) {
  switch (status) {
    case Status::pass:
      return "PASS";
    case Status::fail:
      return "FAIL";
    case Status::skipped:
      return "SKIPPED";
  }
  return "?";
}

Check relative_check(std::string quantity, std::string unit, double expected, double measured, double tolerance) {
  Check c = made(std::move(quantity), std::move(unit), expected, number(expected), measured, "relative", tolerance);
  c.error = std::abs(measured - expected) / std::abs(expected);
  c.status = judged(c.error, tolerance);
  return c;
}

Check absolute_check(std::string quantity, std::string unit, double expected, double measured, double tolerance) {
  Check c = made(std::move(quantity), std::move(unit), expected, number(expected), measured, "absolute", tolerance);
  c.error = std::abs(measured - expected);
  c.status = judged(c.error, tolerance);
  return c;
}

Check bound_check(std::string quantity, std::string unit, double measured, double bound) {
  Check c = made(std::move(quantity), std::move(unit), 0.0, "<= " + number(bound), measured, "bound", bound);
  c.error = measured;
  c.status = judged(measured, bound);
  return c;
}

Check range_check(std::string quantity, std::string unit, double lower, double upper, double measured) {
  Check c = made(std::move(quantity), std::move(unit), 0.5 * (lower + upper),
                 number(lower).insert(0, 1, '[') + ", " + number(upper) + ']', measured, "range", 0.0);
  c.error = measured < lower ? lower - measured : (measured > upper ? measured - upper : 0.0);
  if (!std::isfinite(measured)) c.error = measured;
  c.status = judged(c.error, 0.0);
  return c;
}

Check skipped_check(std::string quantity, std::string reason) {
  Check c;
  c.quantity = std::move(quantity);
  // (std::string(1, '-') rather than "-": GCC 12 warns falsely on short literal assignments, PR 105329.)
  c.expected_text = std::string(1, '-');
  c.error_kind = std::string(1, '-');
  c.status = Status::skipped;
  c.note = std::move(reason);
  return c;
}

std::optional<CaseResult> skipped_without_physics_backend(const CaseContext& context, std::string quantity) {
  if (context.physics_backend_skip.empty()) return std::nullopt;
  CaseResult skipped;
  skipped.checks.push_back(skipped_check(std::move(quantity), context.physics_backend_skip));
  return skipped;
}

}  // namespace mssph::validation
