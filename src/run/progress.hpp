#pragma once
// Progress of a long run on stderr: one line every few seconds once the run has lasted a few
// seconds (steps, simulated time, rate, ETA). Silent when quiet.
#include <chrono>
#include <cstddef>

namespace mssph {

class ProgressReporter {
 public:
  // `first_step`: the steps already done when this process started (a restarted run's).
  ProgressReporter(std::size_t total_steps, double dt, bool quiet, std::size_t first_step = 0);
  void update(std::size_t steps_done);

 private:
  using Clock = std::chrono::steady_clock;
  std::size_t total_steps_;
  std::size_t first_step_;
  double dt_;
  bool quiet_;
  Clock::time_point start_;
  Clock::time_point last_print_;
};

}  // namespace mssph
