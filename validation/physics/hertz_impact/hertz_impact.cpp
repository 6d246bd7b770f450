#include "hertz_impact.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"
#include "physics/hertz/hertz.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace mssph::validation {

HertzImpact hertz_impact(double mass, double speed, double stiffness, double fraction) {
  HertzImpact out;
  out.max_indentation = std::pow(15.0 * mass * speed * speed / (16.0 * 0.75 * stiffness), 0.4);
  out.peak_force = stiffness * std::pow(out.max_indentation, 1.5);
  out.duration = 2.94 * out.max_indentation / speed;
  // State (d, d'); d'' = -K max(d, 0)^1.5 / m, from d = 0 at speed V until d < 0 again.
  using State = std::array<double, 2>;
  const auto rate = [&](const State& s) -> State {
    return {s[1], -stiffness * std::pow(std::max(s[0], 0.0), 1.5) / mass};
  };
  const double step = out.duration / 100000.0;
  State s{0.0, speed};
  for (double t = 0.0; s[0] >= 0.0 && t < 2.0 * out.duration; t += step) {
    const State k1 = rate(s);
    const State k2 = rate({s[0] + 0.5 * step * k1[0], s[1] + 0.5 * step * k1[1]});
    const State k3 = rate({s[0] + 0.5 * step * k2[0], s[1] + 0.5 * step * k2[1]});
    const State k4 = rate({s[0] + step * k3[0], s[1] + step * k3[1]});
    for (int k = 0; k < 2; ++k) s[k] += step / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
    if (stiffness * std::pow(std::max(s[0], 0.0), 1.5) > fraction * out.peak_force) out.duration_above += step;
  }
  return out;
}

double hertz_impact_tolerance(double max_indentation, double dx) { return max_indentation > 3.0 * dx ? 0.15 : 0.30; }

Scene hertz_impact_scene(double dx) {
  const Scene base = case_scene("physics/hertz_impact");
  const BodyConfig& sphere = *base.find_body("sphere");
  std::vector<std::string> overrides = resolution_overrides(base, dx);
  overrides.push_back("bodies/sphere/position=[0,0," + exact(sphere.shape.radius + 1.5 * dx) + "]");
  return case_scene("physics/hertz_impact", overrides);
}

HertzImpactMeasurement measure_hertz_impact(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup lattice = build_particles(scene);
  const std::size_t sphere = body_index(lattice, "sphere", scene);
  const BodyConfig& sphere_config = *scene.find_body("sphere");
  const BodyConfig& block_config = *scene.find_body("block");
  const double dx = lattice.spacing;
  const double radius = sphere_config.shape.radius;
  const Eigen::Vector3d centre = sphere_config.position;
  const double block_top = block_config.position.z() + 0.5 * block_config.shape.size.z();

  // The sphere as round shells; its mass and inertia those of the solid sphere it stands for.
  ParticleSetup setup = with_body_particles(lattice, sphere, spherical_shells(centre, radius, dx, centre.z() + radius));
  BodySetup& ball = setup.bodies[sphere];
  ball.mass = sphere_config.density * 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3);
  ball.inertia_body = 0.4 * ball.mass * radius * radius * Eigen::Matrix3d::Identity();
  ball.centre_of_mass = centre;
  for (std::size_t i = ball.first; i < ball.first + ball.count; ++i) setup.rest_offset[i] = setup.position[i] - centre;

  HertzImpactMeasurement m;
  m.speed = -ball.velocity.z();
  m.mass = ball.mass;
  m.radius = radius;
  const Material& block = setup.bodies[body_index(setup, "block", scene)].material;
  m.stiffness = 4.0 / 3.0 * block.young_modulus / (1.0 - block.poisson_ratio * block.poisson_ratio) * std::sqrt(radius);
  m.particles = setup.size();
  std::unique_ptr<Backend> backend = make_backend(backend_name, std::move(setup));
  const double dt = scene.simulation.dt;
  const std::size_t steps = steps_for(scene.simulation.duration, dt);
  for (std::size_t s = 1; s <= steps; ++s) {
    backend->step();
    const BodyState state = backend->rigid_body_state(sphere);
    const double indentation = block_top + radius - state.centre_of_mass.z();
    m.time.push_back(static_cast<double>(s) * dt);
    m.force.push_back(state.interaction_force.z());
    m.indentation.push_back(indentation);
    m.rebound_speed = state.linear_momentum.z() / state.mass;
    // Done once the sphere moves up beyond the interaction's reach.
    if (m.rebound_speed > 0.0 && indentation < -(lattice.smoothing_length - dx)) {
      m.left_block = true;
      break;
    }
  }
  m.max_indentation = *std::max_element(m.indentation.begin(), m.indentation.end());
  m.peak_force = *std::max_element(m.force.begin(), m.force.end());
  for (double f : m.force)
    if (f > kPulseFraction * m.peak_force) m.duration_above += dt;
  return m;
}

}  // namespace mssph::validation
