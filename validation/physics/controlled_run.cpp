#include "controlled_run.hpp"

#include <algorithm>

namespace mssph::validation {

ControlledRun run_controlled(Backend& backend, std::size_t body, std::size_t steps,
                             const std::function<Wrench(const BodyState&)>& control,
                             const std::function<double(const BodyState&)>& quantity,
                             const std::function<double(const BodyState&)>& deviation) {
  ControlledRun run;
  const std::size_t sample_every = std::max<std::size_t>(1, steps / 100);
  const std::size_t window_start = steps - 2 * steps / 5;
  const std::size_t earlier_start = steps - 3 * steps / 5;
  double window_sum = 0.0, earlier_sum = 0.0;
  BodyState s = backend.rigid_body_state(body);
  for (std::size_t step = 0; step < steps; ++step) {
    const Wrench wrench = control(s);
    backend.set_external_wrench(body, wrench.force, wrench.torque);
    backend.step();
    s = backend.rigid_body_state(body);
    const double q = quantity(s);
    if (step >= window_start) {
      window_sum += q;
      run.largest_deviation = std::max(run.largest_deviation, deviation(s));
    } else if (step >= earlier_start) {
      earlier_sum += q;
    }
    if ((step + 1) % sample_every == 0) {
      run.time.push_back(backend.time());
      run.history.push_back(q);
    }
  }
  run.mean = window_sum / static_cast<double>(steps - window_start);
  run.mean_earlier = earlier_sum / static_cast<double>(window_start - earlier_start);
  return run;
}

}  // namespace mssph::validation
