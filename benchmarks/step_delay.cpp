#include "step_delay.hpp"

#include "util/errors.hpp"

#include <cerrno>
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

std::size_t extra_step_interval() {
  const char* text = std::getenv(kExtraStepVariable);
  if (text == nullptr || *text == '\0') return 0;
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(text, &end, 10);
  if (*end != '\0' || *text == '-' || errno == ERANGE || n == 0) {
    throw InputError(std::string(kExtraStepVariable) + "=" + text + ": expected a positive whole number of steps");
  }
  return static_cast<std::size_t>(n);
}

void busy_wait(double seconds) {
  if (seconds <= 0.0) return;
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
  }
}

}  // namespace mssph::bench
