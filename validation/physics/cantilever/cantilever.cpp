#include "cantilever.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"

#include <cmath>
#include <map>

namespace mssph::validation {

namespace {
constexpr double kClampLayers = 3.0;
}  // namespace

double CantileverBeam::p_wave_speed() const {
  const double nu = poisson_ratio;
  return std::sqrt(young_modulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) / density);
}

double CantileverBeam::first_bending_omega() const {
  const double beta_l = 1.8751;
  return beta_l * beta_l * std::sqrt(young_modulus * side * side / (12.0 * density * std::pow(length, 4)));
}

CantileverBeam cantilever_beam() {
  const Scene base = case_scene("physics/cantilever");
  const BodyConfig& body = *base.find_body("beam");
  CantileverBeam beam;
  beam.length = body.shape.size.x() - kClampLayers * base.simulation.particle_spacing;
  beam.side = body.shape.size.y();
  beam.young_modulus = body.material.young_modulus;
  beam.poisson_ratio = body.material.poisson_ratio;
  beam.density = body.material.rest_density;
  beam.gravity = base.simulation.gravity.norm();
  return beam;
}

Scene cantilever_scene(const CantileverBeam& beam, double dx, double damping, double duration, bool correction) {
  const double dt = 0.2 * 2.0 * dx / beam.p_wave_speed();
  const double clamp = kClampLayers * dx;
  return case_scene(
      "physics/cantilever",
      {"simulation/particle_spacing=" + exact(dx), "simulation/dt=" + exact(dt),
       "simulation/duration=" + exact(duration), "bodies/beam/damping=" + exact(damping),
       "bodies/beam/kernel_gradient_correction=" + std::string(correction ? "true" : "false"),
       "bodies/beam/shape/size=[" + exact(beam.length + clamp) + "," + exact(beam.side) + "," + exact(beam.side) + "]",
       "bodies/beam/position=[" + exact(0.5 * (beam.length - clamp)) + ",0,0]"});
}

CantileverMeasurement measure_cantilever(const std::string& backend_name, double dx, bool correction) {
  const CantileverBeam beam = cantilever_beam();
  const double length = beam.length;
  const double side = beam.side;
  const double young = beam.young_modulus;
  const double nu = beam.poisson_ratio;
  const double rho = beam.density;
  const double g = beam.gravity;
  const double omega_1 = beam.first_bending_omega();
  const Scene scene = cantilever_scene(beam, dx, 2.0 * omega_1, 12.0 / omega_1, correction);
  const double dt = scene.simulation.dt;
  const ParticleSetup setup = build_particles(scene);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  CantileverMeasurement m;
  m.fixed_particles = setup.bodies[0].fixed_count;
  m.particles = setup.size();
  m.steps = static_cast<std::size_t>(std::ceil(12.0 / omega_1 / dt));
  for (std::size_t s = 0; s < m.steps; ++s) backend->step();
  const ParticleSnapshot snapshot = backend->snapshot();
  m.final_max_speed = backend->body_states().front().max_speed;

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
  m.rest_speed = 0.01 * euler_bernoulli(length) * 0.5 * omega_1;
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
