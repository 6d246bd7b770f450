#include "step_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mssph {
namespace {

using Clock = std::chrono::steady_clock;

double run_batch(Backend& backend, std::size_t steps) {
  const Clock::time_point start = Clock::now();
  for (std::size_t k = 0; k < steps; ++k) backend.step();
  backend.synchronize();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

double StepTimes::min() const { return *std::min_element(per_step_seconds.begin(), per_step_seconds.end()); }
double StepTimes::max() const { return *std::max_element(per_step_seconds.begin(), per_step_seconds.end()); }
double StepTimes::median() const {
  std::vector<double> sorted = per_step_seconds;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

StepTimes time_steps(Backend& backend, const StepTimingOptions& options) {
  StepTimes times;
  if (options.warm_up_steps > 0) run_batch(backend, options.warm_up_steps);
  // One probe step sizes the batches; the warm-up has already paid for one-off costs.
  const double probe = std::max(run_batch(backend, 1), 1e-9);
  const auto steps_for = [probe](double seconds) { return static_cast<std::size_t>(std::ceil(seconds / probe)); };
  times.batch_steps = std::max<std::size_t>(1, steps_for(options.min_batch_seconds));
  const std::size_t batches = std::max(options.min_batches, steps_for(options.min_total_seconds) / times.batch_steps);
  const std::size_t affordable = std::max<std::size_t>(options.min_batches, options.max_steps / times.batch_steps);
  for (std::size_t b = 0; b < std::min(batches, affordable); ++b) {
    times.per_step_seconds.push_back(run_batch(backend, times.batch_steps) / static_cast<double>(times.batch_steps));
    times.steps += times.batch_steps;
  }
  // The phases from as many further steps, timed one by one, outside the step times above: timing
  // the phases costs a GPU step its events (Backend::set_phase_timing).
  times.phase_names = backend.phase_names();
  times.phase_seconds.assign(times.phase_names.size(), 0.0);
  backend.set_phase_timing(true);
  for (std::size_t b = 0; b < times.per_step_seconds.size(); ++b) {
    run_batch(backend, 1);
    const std::vector<double> last = backend.last_phase_seconds();
    for (std::size_t p = 0; p < last.size(); ++p) times.phase_seconds[p] += last[p];
  }
  backend.set_phase_timing(false);
  for (double& s : times.phase_seconds) s /= static_cast<double>(times.per_step_seconds.size());
  return times;
}

}  // namespace mssph
