#pragma once
// Checks of command-line option values that CLI11's own validators leave open.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace mssph::cli {

// A positive, finite number: CLI11's PositiveNumber lets "nan" (no comparison fails) and "inf"
// through, which would make an interval that never elapses.
inline CLI::Validator positive_finite_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool whole = !text.empty() && end == text.c_str() + text.size();
        if (!whole || !std::isfinite(value) || !(value > 0.0)) return "expected a positive finite number, got " + text;
        return "";
      },
      "POSITIVE", "positive finite number");
}

}  // namespace mssph::cli
