#include "shear_decay.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mssph::validation {

namespace {

struct Block {
  double bottom = 0.0;  // z0 [m]
  double height = 0.0;  // L [m]
  double speed = 0.0;   // U [m/s], the lower half's
};

Block block_of(const Scene& scene) {
  const BodyConfig& lower = *scene.find_body("lower");
  const BodyConfig& upper = *scene.find_body("upper");
  Block b;
  b.bottom = lower.position.z() - 0.5 * lower.shape.size.z();
  b.height = lower.shape.size.z() + upper.shape.size.z();
  b.speed = lower.velocity.x();
  if (std::abs(upper.velocity.x() + b.speed) > 1e-12 * std::abs(b.speed) || b.speed == 0.0)
    throw std::runtime_error(scene.source_file +
                             ": the shear wave needs \"upper\" moving at minus \"lower\"'s x velocity");
  return b;
}

// The square wave's Fourier series, each mode decayed for time t: u(z) = (4 U / pi)
// sum_m (-1)^m / (2m + 1) cos((2m + 1) k z) exp(-nu (2m + 1)^2 k^2 t), to 200 modes.
double analytic_velocity(const Block& b, double nu, double z, double t) {
  const double k = std::numbers::pi / b.height;
  double u = 0.0;
  for (int m = 0; m < 200; ++m) {
    const double n = 2.0 * m + 1.0;
    u += (m % 2 ? -1.0 : 1.0) / n * std::cos(n * k * z) * std::exp(-nu * n * n * k * k * t);
  }
  return 4.0 * b.speed / std::numbers::pi * u;
}

}  // namespace

Scene shear_decay_scene(double dx, double viscosity, double decay_times) {
  const Scene base = case_scene("physics/shear_decay");
  const Block b = block_of(base);
  const double rho = base.find_body("lower")->material.rest_density;
  const double k = std::numbers::pi / b.height;
  const double duration = decay_times * rho / (viscosity * k * k);
  // U = L nu k^2 / 100: over any time the halves slide past each other by less than
  // 2 U / (nu k^2) = L / 50, so the block keeps its shape.
  const double speed = b.height * viscosity / rho * k * k / 100.0;
  std::vector<std::string> overrides = viscous_resolution_overrides(base, dx, rho, viscosity);
  overrides.push_back("simulation/duration=" + exact(duration));
  overrides.push_back("materials/fluid/viscosity=" + exact(viscosity));
  overrides.push_back("bodies/lower/velocity=[" + exact(speed) + ", 0, 0]");
  overrides.push_back("bodies/upper/velocity=[" + exact(-speed) + ", 0, 0]");
  return case_scene("physics/shear_decay", overrides);
}

ShearDecayMeasurement measure_shear_decay(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup setup = build_particles(scene);
  const Block b = block_of(scene);
  const BodySetup lower = setup.bodies[body_index(setup, "lower", scene)];
  const BodySetup upper = setup.bodies[body_index(setup, "upper", scene)];
  if (upper.first != lower.first + lower.count)
    throw std::runtime_error(scene.source_file + ": \"upper\" must follow \"lower\" in the scene's bodies");
  const double k = std::numbers::pi / b.height;
  const double rho = lower.material.rest_density;
  const double dx = setup.spacing;

  ShearDecayMeasurement m;
  m.viscosity = lower.material.viscosity;
  m.particles = setup.size();
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const std::size_t first = lower.first;
  const std::size_t last = upper.first + upper.count;
  ParticleSnapshot snapshot;
  const auto sample = [&] {
    snapshot = backend->snapshot();
    double projection = 0.0;
    double norm = 0.0;
    for (std::size_t i = first; i < last; ++i) {
      const double c = std::cos(k * (snapshot.position[3 * i + 2] - b.bottom));
      projection += snapshot.velocity[3 * i] * c;
      norm += c * c;
    }
    m.time.push_back(backend->time());
    m.amplitude.push_back(projection / norm);
  };
  sample();
  const int samples = 40;
  const std::size_t sample_steps = std::max<std::size_t>(1, steps_for(scene.simulation.duration / samples, setup.dt));
  for (int s = 0; s < samples; ++s) {
    run_steps(*backend, sample_steps);
    sample();
  }
  std::vector<double> log_amplitude;
  for (const double a : m.amplitude) {
    if (a <= 0.0) throw std::runtime_error(scene.source_file + ": the shear wave's amplitude changed sign");
    log_amplitude.push_back(std::log(a));
  }
  m.effective_viscosity = -fit_line(m.time, log_amplitude).second * rho / (k * k);
  m.decay = m.amplitude.back() / m.amplitude.front();

  // The final profile in layers one spacing thick.
  const int layers = static_cast<int>(std::lround(b.height / dx));
  std::vector<double> sum(layers, 0.0);
  std::vector<double> count(layers, 0.0);
  for (std::size_t i = first; i < last; ++i) {
    const int layer = static_cast<int>(std::floor((snapshot.position[3 * i + 2] - b.bottom) / dx));
    if (layer < 0 || layer >= layers) continue;
    sum[layer] += snapshot.velocity[3 * i];
    count[layer] += 1.0;
  }
  double difference = 0.0;
  double reference = 0.0;
  const double nu = m.viscosity / rho;
  for (int layer = 0; layer < layers; ++layer) {
    if (count[layer] == 0.0) continue;
    const double z = (layer + 0.5) * dx;
    const double exact_u = analytic_velocity(b, nu, z, backend->time());
    m.height.push_back(z);
    m.profile.push_back(sum[layer] / count[layer]);
    m.analytic.push_back(exact_u);
    difference += (m.profile.back() - exact_u) * (m.profile.back() - exact_u);
    reference += exact_u * exact_u;
  }
  m.profile_error = std::sqrt(difference / reference);
  return m;
}

}  // namespace mssph::validation
