#include "cantilever.hpp"

#include "backends/backend_factory.hpp"
#include "framework/backends.hpp"
#include "scene/scene_builder.hpp"

#include <cmath>
#include <map>

namespace mssph::validation {

CantileverMeasurement measure_cantilever(const std::string& backend_name, double dx, bool correction) {
  const Scene base = case_scene("physics/cantilever");
  const BodyConfig& beam = *base.find_body("beam");
  const double clamp_layers = 3.0;
  const double length = beam.shape.size.x() - clamp_layers * base.simulation.particle_spacing;
  const double side = beam.shape.size.y();
  const double young = beam.material.young_modulus;
  const double nu = beam.material.poisson_ratio;
  const double rho = beam.material.rest_density;
  const double g = base.simulation.gravity.norm();
  const double c_p = std::sqrt(young * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) / rho);
  const double dt = 0.2 * 2.0 * dx / c_p;
  const double omega_1 = 3.516 * std::sqrt(young * side * side / (12.0 * rho * std::pow(length, 4)));
  const double clamp = clamp_layers * dx;
  const Scene scene = case_scene(
      "physics/cantilever",
      {"simulation/particle_spacing=" + exact(dx), "simulation/dt=" + exact(dt),
       "simulation/duration=" + exact(12.0 / omega_1), "bodies/beam/damping=" + exact(2.0 * omega_1),
       "bodies/beam/kernel_gradient_correction=" + std::string(correction ? "true" : "false"),
       "bodies/beam/shape/size=[" + exact(length + clamp) + "," + exact(side) + "," + exact(side) + "]",
       "bodies/beam/position=[" + exact(0.5 * (length - clamp)) + ",0,0]"});
  const ParticleSetup setup = build_particles(scene);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  CantileverMeasurement m;
  m.fixed_particles = setup.bodies[0].fixed_count;
  m.particles = setup.size();
  m.steps = static_cast<std::size_t>(std::ceil(12.0 / omega_1 / dt));
  for (std::size_t s = 0; s < m.steps; ++s) backend->step();
  const ParticleSnapshot snapshot = backend->snapshot();

  const double q = rho * side * side * g;
  const double inertia = std::pow(side, 4) / 12.0;
  const auto euler_bernoulli = [&](double x) {
    return q * x * x * (6.0 * length * length - 4.0 * length * x + x * x) / (24.0 * young * inertia);
  };
  double sum = 0.0;
  int count = 0;
  std::map<long, std::pair<double, int>> layers;  // by rest x / dx
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const double rest_x = setup.position[i].x();
    const double sag = setup.position[i].z() - double(snapshot.position[3 * i + 2]);
    auto& layer = layers[std::lround(rest_x / dx - 0.5)];
    layer.first += sag;
    layer.second += 1;
    if (rest_x < length - dx) continue;
    sum += sag;
    ++count;
  }
  m.tip = sum / count;
  m.euler_bernoulli = euler_bernoulli(length - 0.5 * dx);
  const double tip_x = length - 0.5 * dx;
  const double shear_modulus = young / (2.0 * (1.0 + nu));
  m.shear_deflection = q * (length * tip_x - 0.5 * tip_x * tip_x) / (5.0 / 6.0 * shear_modulus * side * side);
  for (const auto& [index, layer] : layers) {
    const double x = (static_cast<double>(index) + 0.5) * dx;
    if (x < 0.0) continue;
    m.x.push_back(x);
    m.deflection.push_back(layer.first / layer.second);
    m.expected.push_back(euler_bernoulli(x));
  }
  return m;
}

}  // namespace mssph::validation
