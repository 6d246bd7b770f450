#include "translating_sphere.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"
#include "physics/controlled_run.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mssph::validation {
namespace {

// A vector as --set writes it: [x, y, z].
std::string vector_text(double x, double y, double z) {
  std::string text = "[";
  text += exact(x);
  text += ", ";
  text += exact(y);
  text += ", ";
  text += exact(z);
  text += "]";
  return text;
}

}  // namespace

double concentric_sphere_drag_factor(double lambda) {
  const double l3 = lambda * lambda * lambda;
  const double l5 = l3 * lambda * lambda;
  return (1.0 - l5) / (1.0 - 2.25 * lambda + 2.5 * l3 - 2.25 * l5 + l5 * lambda);
}

double cylinder_drag_factor(double lambda) {
  const double l3 = lambda * lambda * lambda;
  const double l5 = l3 * lambda * lambda;
  return (1.0 - 0.75857 * l5) / (1.0 - 2.1050 * lambda + 2.0865 * l3 - 1.7068 * l5 + 0.72603 * l5 * lambda);
}

std::pair<double, double> cube_drag_factor_bracket(double radius, double side) {
  return {cylinder_drag_factor(radius / (side / std::sqrt(2.0))), concentric_sphere_drag_factor(radius / (0.5 * side))};
}

Scene translating_sphere_scene(double dx, double mu, double side, double speed, const std::vector<std::string>& extra) {
  const double rho = 1000.0;
  const double radius = 0.05;
  const double h = 2.0 * dx;
  const double nu = mu / rho;
  const double c = std::sqrt(1.0e6 * mu * kReferenceSpeed / (rho * radius));
  const double dt = 0.8 * std::min(0.125 * h * h / nu, 0.25 * h / c);
  const double duration = 2.0 * 0.25 * side * side / nu;
  // The cube holds an even number of cells, so its fluid sites lie at (k + 1/2) dx.
  const std::string cube = vector_text(side, side, side);
  std::vector<std::string> overrides{"simulation/particle_spacing=" + exact(dx),
                                     "simulation/dt=" + exact(dt),
                                     "simulation/duration=" + exact(duration),
                                     "materials/fluid/viscosity=" + exact(mu),
                                     "materials/fluid/pressure_stiffness=" + exact(c * c),
                                     "materials/sphere/viscosity=" + exact(mu),
                                     "materials/sphere/pressure_stiffness=" + exact(c * c),
                                     "bodies/box/shape/inner_size=" + cube,
                                     "bodies/fluid/shape/size=" + cube,
                                     "bodies/sphere/velocity=" + vector_text(speed, 0.0, 0.0),
                                     "bodies/sphere/position=" + vector_text(0.5 * dx, 0.5 * dx, 0.5 * dx)};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return case_scene("physics/translating_sphere", overrides);
}

TowedSphereMeasurement measure_translating_sphere(const std::string& backend_name, const Scene& scene, double speed) {
  const ParticleSetup setup = build_particles(scene);
  const std::size_t sphere = body_index(setup, "sphere", scene);
  const BodySetup& fluid = setup.bodies[body_index(setup, "fluid", scene)];
  const BodyConfig& box = scene.bodies[body_index(setup, "box", scene)];
  const BodySetup ball = setup.bodies[sphere];
  const double dx = setup.spacing;
  const double mu = fluid.material.viscosity;
  const double rho = fluid.material.rest_density;

  TowedSphereMeasurement m;
  m.particles = setup.size();
  m.radius = sampled_sphere_radius(ball.lattice_sites, dx);
  m.side = box.shape.size.minCoeff();
  m.reynolds = rho * speed * m.radius / mu;
  m.stokes_drag = 6.0 * std::numbers::pi * mu * m.radius * speed;
  std::tie(m.factor_low, m.factor_high) = cube_drag_factor_bracket(m.radius, m.side);

  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const double rate = 1.0 / (10.0 * setup.dt);  // the controller's approach rate [1/s]
  const Eigen::Matrix3d inertia = ball.inertia_body;
  const Eigen::Vector3d target(speed, 0.0, 0.0);
  ControlledRun run = run_controlled(
      *backend, sphere, steps_for(scene.simulation.duration, setup.dt),
      [&](const BodyState& s) {
        const Eigen::Vector3d velocity = s.linear_momentum / s.mass;
        return Wrench{-s.interaction_force + s.mass * rate * (target - velocity),
                      -s.interaction_torque - rate * (inertia * s.angular_velocity)};
      },
      [](const BodyState& s) { return -s.interaction_force.x(); },
      [&](const BodyState& s) { return std::abs(s.linear_momentum.x() / s.mass - speed) / speed; });
  m.drag = run.mean;
  m.drag_earlier = run.mean_earlier;
  m.speed_deviation = run.largest_deviation;
  m.time = std::move(run.time);
  m.drag_history = std::move(run.history);
  return m;
}

LinearDrag measure_linear_drag(const std::string& backend, double dx, double mu, double side,
                               const std::vector<std::string>& extra) {
  LinearDrag d;
  d.slow = measure_translating_sphere(backend, translating_sphere_scene(dx, mu, side, kReferenceSpeed, extra),
                                      kReferenceSpeed);
  d.fast = measure_translating_sphere(backend, translating_sphere_scene(dx, mu, side, 2.0 * kReferenceSpeed, extra),
                                      2.0 * kReferenceSpeed);
  d.factor = (d.fast.drag - d.slow.drag) / d.slow.stokes_drag;
  d.offset = (2.0 * d.slow.drag - d.fast.drag) / d.slow.stokes_drag;
  d.radius_over_side = d.slow.radius / d.slow.side;
  return d;
}

UnboundedDrag fit_faxen(const std::vector<double>& radius_over_side, const std::vector<double>& drag_factor) {
  if (radius_over_side.size() < 2) throw std::invalid_argument("the extrapolation needs cubes of at least two sides");
  std::vector<double> inverse;
  for (const double k : drag_factor) inverse.push_back(1.0 / k);
  const auto [intercept, slope] = fit_line(radius_over_side, inverse);
  return {1.0 / intercept, -slope / intercept};
}

UnboundedDrag extrapolate_to_unbounded(const std::vector<LinearDrag>& cubes) {
  std::vector<double> x, factor;
  for (const LinearDrag& c : cubes) {
    x.push_back(c.radius_over_side);
    factor.push_back(c.factor);
  }
  return fit_faxen(x, factor);
}

}  // namespace mssph::validation
