#include "viscous_bar.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::validation {
namespace {

double end_to_end_length(const std::vector<float>& xyz) {
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < xyz.size(); k += 3) {
    lo = std::min(lo, static_cast<double>(xyz[k]));
    hi = std::max(hi, static_cast<double>(xyz[k]));
  }
  return hi - lo;
}

}  // namespace

Decrement logarithmic_decrement(const std::vector<double>& time, const std::vector<double>& signal) {
  std::vector<std::size_t> crossings;  // k with signal[k - 1] > 0 >= signal[k]
  for (std::size_t k = 1; k < signal.size(); ++k) {
    if (signal[k - 1] > 0.0 && signal[k] <= 0.0) crossings.push_back(k);
  }
  std::vector<double> peak_time, log_peak;
  for (std::size_t c = 1; c < crossings.size(); ++c) {
    const auto first = signal.begin() + static_cast<std::ptrdiff_t>(crossings[c - 1]);
    const auto last = signal.begin() + static_cast<std::ptrdiff_t>(crossings[c]);
    const auto peak = std::max_element(first, last);
    if (*peak <= 0.0) continue;
    peak_time.push_back(time[static_cast<std::size_t>(peak - signal.begin())]);
    log_peak.push_back(std::log(*peak));
  }
  if (peak_time.size() < 3) return {};
  const double decay = -fit_line(peak_time, log_peak).second;  // sigma = zeta omega_n
  const double damped_period =
      (time[crossings.back()] - time[crossings.front()]) / static_cast<double>(crossings.size() - 1);
  const double damped = 2.0 * std::numbers::pi / damped_period;
  const double natural = std::sqrt(damped * damped + decay * decay);
  return {decay / natural, natural, peak_time.size()};
}

ViscousBarMeasurement measure_viscous_bar(const std::string& backend_name, const std::vector<std::string>& settings,
                                          double periods) {
  const Scene scene = case_scene("physics/bar_vibration", settings);
  const BodyConfig& bar = scene.bodies.front();
  const ParticleSetup setup = build_particles(scene);
  // Uniaxial stress: 1 % along x, -nu % across, about the bar's centre.
  const double e = 0.01, nu = bar.material.poisson_ratio;
  const Eigen::Vector3d stretch(1.0 + e, 1.0 - nu * e, 1.0 - nu * e);
  std::vector<Eigen::Vector3d> positions = setup.position;
  for (Eigen::Vector3d& x : positions) x = bar.position + stretch.asDiagonal() * (x - bar.position);

  double lo = 1e300, hi = -1e300;
  for (const Eigen::Vector3d& x : setup.position) {
    lo = std::min(lo, x.x());
    hi = std::max(hi, x.x());
  }
  const double rest_length = hi - lo;

  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  backend->set_particle_positions(positions);
  // 2 L / c with each particle standing for a cell dx wide (bar_period's measure).
  const double length = rest_length + setup.spacing;
  const double period = 2.0 * length / std::sqrt(bar.material.young_modulus / bar.material.rest_density);
  const auto steps = static_cast<std::size_t>(std::round(periods * period / setup.dt));

  ViscousBarMeasurement m;
  m.particles = setup.size();
  for (std::size_t s = 0; s < steps; ++s) {
    backend->step();
    m.time.push_back(static_cast<double>(s + 1) * setup.dt);
    m.elongation.push_back(end_to_end_length(backend->snapshot().position) - rest_length);
  }
  const Decrement d = logarithmic_decrement(m.time, m.elongation);
  m.damping_ratio = d.damping_ratio;
  m.angular_frequency = d.angular_frequency;
  m.peaks = d.peaks;
  m.expected_ratio = bar.material.viscous_modulus * d.angular_frequency / (2.0 * bar.material.young_modulus);
  return m;
}

}  // namespace mssph::validation
