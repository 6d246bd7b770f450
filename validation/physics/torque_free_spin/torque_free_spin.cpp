#include "torque_free_spin.hpp"

#include "backend_factory/backend_factory.hpp"
#include "model/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::validation {

SpinMeasurement measure_torque_free_spin(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup setup = build_particles(scene);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const BodyState start = backend->rigid_body_state(0);
  const auto body_axes = [](const BodyState& s) {
    return (s.orientation.conjugate() * s.angular_velocity).normalized();
  };
  const double energy_start = 0.5 * start.angular_velocity.dot(start.angular_momentum);
  SpinMeasurement m;
  const auto samples = static_cast<int>(std::llround(scene.simulation.duration / setup.dt / 100.0));
  for (int k = 0; k < samples; ++k) {
    for (int s = 0; s < 100; ++s) backend->step();
    const BodyState state = backend->rigid_body_state(0);
    const double momentum = (state.angular_momentum - start.angular_momentum).norm() / start.angular_momentum.norm();
    const double energy =
        std::abs(0.5 * state.angular_velocity.dot(state.angular_momentum) - energy_start) / energy_start;
    const double turn =
        std::acos(std::clamp(body_axes(state).dot(body_axes(start)), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    m.worst_momentum_error = std::max(m.worst_momentum_error, momentum);
    m.worst_energy_drift = std::max(m.worst_energy_drift, energy);
    m.largest_turn_degrees = std::max(m.largest_turn_degrees, turn);
    m.time.push_back(backend->time());
    m.momentum_error.push_back(momentum);
    m.energy_drift.push_back(energy);
  }
  m.final_linear_momentum = backend->rigid_body_state(0).linear_momentum.norm();
  return m;
}

}  // namespace mssph::validation
