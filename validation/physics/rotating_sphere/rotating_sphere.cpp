#include "rotating_sphere.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"
#include "physics/controlled_run.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mssph::validation {

double concentric_wall_factor(double radius, double container_radius) {
  return 1.0 / (1.0 - std::pow(radius / container_radius, 3));
}

Scene rotating_sphere_scene(double dx, double support, double mu, double omega) {
  const double rho = kRotatingSphereFluidDensity;
  const double radius = kRotatingSphereRadius;
  const double h = 2.0 * dx;  // the step's bounds at the default support, the smaller: one dt for both
  const double nu = mu / rho;
  // Mach number omega R / c <= 0.01 and viscous stress over rho c^2 <= 4e-4 (decision 058: the
  // torque settles lower as mu omega / (rho c^2) grows).
  const double c = std::max(100.0 * omega * radius, std::sqrt(mu * omega / (4.0e-4 * rho)));
  const double dt = 0.8 * std::min(0.125 * h * h / nu, 0.25 * h / c);
  // The sphere, the fluid and the container share one centre and so one lattice: the fluid meets
  // the sphere and the container's wall at one spacing (src/model/fluid_fill.hpp, lattice.hpp).
  // The container's wall is ceil(h / dx) layers thick by default: a full support of wall.
  const std::vector<std::string> overrides{"simulation/particle_spacing=" + exact(dx),
                                           "simulation/smoothing_length=" + exact(support * dx),
                                           "simulation/dt=" + exact(dt),
                                           "simulation/duration=" + exact(30.0 * radius * radius / nu),
                                           "materials/fluid/viscosity=" + exact(mu),
                                           "materials/fluid/pressure_stiffness=" + exact(c * c),
                                           "bodies/sphere/angular_velocity=[0, 0, " + exact(omega) + "]"};
  return case_scene("physics/rotating_sphere", overrides);
}

RotatingSphereMeasurement measure_rotating_sphere(const std::string& backend_name, const Scene& scene, double omega) {
  const ParticleSetup setup = build_particles(scene);
  const std::size_t sphere = body_index(setup, "sphere", scene);
  const BodySetup& fluid = setup.bodies[body_index(setup, "fluid", scene)];
  const BodySetup ball = setup.bodies[sphere];
  const double dx = setup.spacing;
  const double mu = fluid.material.viscosity;
  const double rho = fluid.material.rest_density;

  RotatingSphereMeasurement m;
  m.particles = setup.size();
  m.radius = sampled_sphere_radius(ball.lattice_sites, dx);
  m.reynolds = rho * omega * m.radius * m.radius / mu;
  m.container_radius = sampled_sphere_radius(fluid.lattice_sites + ball.lattice_sites, dx);
  m.wall_factor = concentric_wall_factor(m.radius, m.container_radius);
  m.expected_torque = -8.0 * std::numbers::pi * mu * std::pow(m.radius, 3) * omega * m.wall_factor;

  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const double rate = 1.0 / (10.0 * setup.dt);  // the controller's approach rate [1/s]
  const double inertia = ball.inertia_body(2, 2);
  const Eigen::Vector3d target(0.0, 0.0, omega);
  const Eigen::Vector3d centre = ball.centre_of_mass;
  ControlledRun run = run_controlled(
      *backend, sphere, steps_for(scene.simulation.duration, setup.dt),
      [&](const BodyState& s) {
        const Eigen::Vector3d velocity = s.linear_momentum / s.mass;
        return Wrench{
            -s.interaction_force - s.mass * rate * rate * (s.centre_of_mass - centre) - 2.0 * s.mass * rate * velocity,
            -s.interaction_torque + inertia * rate * (target - s.angular_velocity)};
      },
      [](const BodyState& s) { return s.interaction_torque.z(); },
      [&](const BodyState& s) { return std::abs(s.angular_velocity.z() - omega) / omega; });
  m.torque = run.mean;
  m.torque_earlier = run.mean_earlier;
  m.omega_deviation = run.largest_deviation;
  m.time = std::move(run.time);
  m.torque_history = std::move(run.history);
  return m;
}

}  // namespace mssph::validation
