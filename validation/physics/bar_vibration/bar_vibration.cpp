#include "bar_vibration.hpp"

#include "elastic_forces.hpp"
#include "framework/backends.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"
#include "physics/elastic_bodies.hpp"

#include <cmath>

namespace mssph::validation {

reference::ReferenceBackend stretched_bar(double damping) {
  const Scene scene = case_scene("physics/bar_vibration", {"bodies/bar/damping=" + exact(damping)});
  reference::ReferenceBackend backend(build_particles(scene));
  const double e = 0.01;
  const double nu = scene.bodies.front().material.poisson_ratio;
  deform_body(backend, 0, Eigen::Vector3d(1.0 + e, 1.0 - nu * e, 1.0 - nu * e).asDiagonal(),
              scene.bodies.front().position);
  return backend;
}

double bar_period(const reference::ReferenceBackend& backend) {
  const BodySetup& bar = backend.setup().bodies[0];
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = bar.first; i < bar.first + bar.count; ++i) {
    lo = std::min(lo, backend.setup().position[i].x());
    hi = std::max(hi, backend.setup().position[i].x());
  }
  const double length = hi - lo + backend.setup().spacing;  // each particle stands for a cell dx wide
  return 2.0 * length / std::sqrt(bar.material.young_modulus / bar.material.rest_density);
}

BarHistory run_bar(reference::ReferenceBackend& backend, double duration) {
  BarHistory history;
  const double dt = backend.setup().dt;
  const auto steps = static_cast<std::size_t>(std::round(duration / dt));
  const std::vector<double>& mass = backend.setup().mass;
  double rest_lo = 1e300, rest_hi = -1e300;
  for (const Eigen::Vector3d& x : backend.setup().position) {
    rest_lo = std::min(rest_lo, x.x());
    rest_hi = std::max(rest_hi, x.x());
  }
  for (std::size_t s = 0; s < steps; ++s) {
    const std::vector<Eigen::Vector3d> v_before = backend.particles().velocity;  // v_{n-1/2}
    backend.step();  // strain energy at x_n, then v_{n+1/2} and x_{n+1}
    double kinetic = 0.0;
    for (std::size_t i = 0; i < mass.size(); ++i) {
      // Leap-frog velocities are staggered: v_n = (v_{n-1/2} + v_{n+1/2}) / 2.
      kinetic += 0.5 * mass[i] * (0.5 * (v_before[i] + backend.particles().velocity[i])).squaredNorm();
    }
    double lo = 1e300;
    double hi = -1e300;
    for (const Eigen::Vector3d& x : backend.particles().position) {
      lo = std::min(lo, x.x());
      hi = std::max(hi, x.x());
    }
    history.time.push_back(static_cast<double>(s) * dt);
    history.energy.push_back(reference::body_strain_energy(backend.setup(), backend.deformables(), 0) + kinetic);
    history.elongation.push_back(hi - lo - (rest_hi - rest_lo));
  }
  return history;
}

double measured_period(const BarHistory& history) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < history.time.size(); ++k) {
    const double a = history.elongation[k - 1];
    const double b = history.elongation[k];
    const double dt = history.time[k] - history.time[k - 1];
    if (a > 0.0 && b <= 0.0) crossings.push_back(history.time[k - 1] + dt * a / (a - b));
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

double energy_drift(const BarHistory& history) {
  double drift = 0.0;
  for (double e : history.energy) drift = std::max(drift, std::abs(e / history.energy.front() - 1.0));
  return drift;
}

double energy_decay_rate(const BarHistory& history) {
  std::vector<double> log_energy;
  for (const double e : history.energy) log_energy.push_back(std::log(e));
  return fit_line(history.time, log_energy).second;
}

}  // namespace mssph::validation
