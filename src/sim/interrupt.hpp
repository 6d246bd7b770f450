#pragma once
// SIGINT/SIGTERM during a run: the step loop stops at the end of the current step and the log is
// marked "failed: interrupted" instead of being left as if still running.
#include <stdexcept>

namespace mssph {

class RunInterrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

void install_interrupt_handlers();
bool interrupt_requested();

}  // namespace mssph
