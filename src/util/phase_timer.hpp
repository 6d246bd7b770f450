#pragma once
// Times one phase of a host backend's step on the steady clock: the seconds are written to the
// given slot when the timer goes out of scope.
#include <chrono>
#include <utility>

namespace mssph {

class PhaseTimer {
 public:
  explicit PhaseTimer(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ~PhaseTimer() { seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_;
};

// Runs `work` and writes its wall-clock seconds to `seconds`: one line per phase in a step.
template <class Work>
void timed(double& seconds, Work&& work) {
  PhaseTimer timer(seconds);
  std::forward<Work>(work)();
}

}  // namespace mssph
