#include "step_delay.hpp"

#include "util/errors.hpp"

#include <chrono>
#include <cstdlib>
#include <string>

namespace mssph::bench {

double step_delay_seconds() {
  const char* text = std::getenv(kStepDelayVariable);
  if (text == nullptr || *text == '\0') return 0.0;
  char* end = nullptr;
  const double microseconds = std::strtod(text, &end);
  if (*end != '\0' || !(microseconds >= 0.0)) {
    throw InputError(std::string(kStepDelayVariable) + "=" + text + ": expected a non-negative number of microseconds");
  }
  return microseconds * 1e-6;
}

void busy_wait(double seconds) {
  if (seconds <= 0.0) return;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
  }
}

}  // namespace mssph::bench
