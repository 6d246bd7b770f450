#pragma once
// Times a backend's simulation step alone (no logging, no I/O): a warm-up, then batches of steps
// each closed by one synchronize(), so a GPU's asynchronous launches are timed as they run in a
// simulation. Each batch gives one per-step time (batch time / batch size); their spread is what a
// figure or a benchmark reports.
#include "backend/backend.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace mssph {

struct StepTimingOptions {
  std::size_t warm_up_steps = 20;   // graph upload, caches, the first grid
  double min_batch_seconds = 2e-3;  // a batch long enough that the clock and the sync are negligible
  std::size_t min_batches = 10;     // enough per-step samples for a median and a spread
  double min_total_seconds = 0.5;   // timed steps in all, at least
  std::size_t max_steps = 100000;   // bound for tiny scenes
};

struct StepTimes {
  std::vector<double> per_step_seconds;  // one per batch [s]
  std::size_t steps = 0;                 // timed steps in all
  std::size_t batch_steps = 0;           // steps per batch
  std::vector<std::string> phase_names;  // the backend's phases
  std::vector<double> phase_seconds;     // mean time of each phase per step, over each batch's last step [s]

  double min() const;
  double median() const;
  double max() const;
};

StepTimes time_steps(Backend& backend, const StepTimingOptions& options = {});

}  // namespace mssph
