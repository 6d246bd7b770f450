#pragma once
// Progress of a long run on stderr: one line every few seconds once the run has lasted a few
// seconds (steps, simulated time, rate, ETA). Silent when quiet.
#include <chrono>
#include <cstddef>

namespace mssph {

class ProgressReporter {
 public:
  ProgressReporter(std::size_t total_steps, double dt, bool quiet);
  void update(std::size_t steps_done);

 private:
  using Clock = std::chrono::steady_clock;
  std::size_t total_steps_;
  double dt_;
  bool quiet_;
  Clock::time_point start_;
  Clock::time_point last_print_;
};

}  // namespace mssph
