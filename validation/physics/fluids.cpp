#include "fluids.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"
#include "stepping.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace mssph::validation {

HydrostaticMeasurement measure_hydrostatic(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup setup = build_particles(scene);
  const std::size_t column_index = body_index(setup, "column", scene);
  const BodySetup column = setup.bodies[column_index];
  const double dx = setup.spacing;
  const double dt = setup.dt;
  const double g = setup.gravity.norm();
  const double sampling = 0.5;  // [s], sampled every 0.01 s
  const std::size_t sample_steps = steps_for(0.01, dt);
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  run_steps(*backend, steps_for(scene.simulation.duration - sampling, dt));  // the column settles

  const BodyConfig& column_config = *scene.find_body("column");
  const int slabs = static_cast<int>(std::lround(column_config.shape.size.z() / dx));
  std::vector<double> pressure_sum(slabs, 0.0);
  std::vector<double> samples(slabs, 0.0);
  ParticleSnapshot snapshot;
  for (std::size_t sample = 0; sample < steps_for(sampling, 0.01); ++sample) {
    run_steps(*backend, sample_steps);
    snapshot = backend->snapshot();
    for (std::size_t i = column.first; i < column.first + column.count; ++i) {
      const int k = static_cast<int>(std::floor(snapshot.position[3 * i + 2] / dx));
      if (k < 0 || k >= slabs) continue;
      pressure_sum[k] += snapshot.pressure[i];
      samples[k] += 1.0;
    }
  }
  double top = -1e9;
  for (std::size_t i = column.first; i < column.first + column.count; ++i)
    top = std::max(top, double(snapshot.position[3 * i + 2]));
  HydrostaticMeasurement m;
  for (int k = 0; k < slabs; ++k) {
    const double z = (k + 0.5) * dx;
    if (samples[k] == 0.0 || z > top - 2.0 * setup.smoothing_length || z < setup.smoothing_length) continue;
    m.height.push_back(z);
    m.pressure.push_back(pressure_sum[k] / samples[k]);
  }
  if (m.height.size() >= 2) std::tie(m.floor_pressure, m.slope) = fit_line(m.height, m.pressure);
  double mass = 0.0;
  for (std::size_t i = column.first; i < column.first + column.count; ++i) mass += setup.mass[i];
  const double width_x = column_config.shape.size.x();
  const double width_y = column_config.shape.size.y();
  m.weight_per_area = mass * g / (width_x * width_y);
  m.expected_slope = -column.material.rest_density * g;
  m.max_speed = backend->body_states()[column_index].max_speed;
  m.sound_speed = std::sqrt(column.material.pressure_stiffness);
  m.particles = setup.size();
  return m;
}

FloatingMeasurement measure_floating(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup setup = build_particles(scene);
  const std::size_t ball = body_index(setup, "ball", scene);
  const BodySetup water = setup.bodies[body_index(setup, "water", scene)];
  const BodySetup ball_setup = setup.bodies[ball];
  const double dx = setup.spacing;
  const double rho_fluid = water.material.rest_density;
  FloatingMeasurement m;
  m.particles = setup.size();
  // The sphere as sampled: N lattice sites of volume dx^3 make a ball of this radius.
  m.radius = sampled_sphere_radius(ball_setup.lattice_sites, dx);
  const double submerged_volume = ball_setup.mass / rho_fluid;
  // Cap depth d with pi d^2 (3 R - d) / 3 = V, by bisection on [0, 2R].
  double lo = 0.0;
  double hi = 2.0 * m.radius;
  for (int k = 0; k < 60; ++k) {
    const double d = 0.5 * (lo + hi);
    (std::numbers::pi * d * d * (3.0 * m.radius - d) / 3.0 < submerged_volume ? lo : hi) = d;
  }
  m.expected_depth = 0.5 * (lo + hi);

  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const auto depth_now = [&] {
    // Free surface away from the sphere: beyond its meniscus (R + 2 dx from its axis), the top
    // particle of each column of side dx; the median over the columns plus half a spacing (each
    // particle stands for a cell of side dx). The median ignores a droplet the sphere splashed up,
    // which as the highest particle would otherwise define the top layer.
    const ParticleSnapshot snapshot = backend->snapshot();
    std::map<std::pair<long, long>, double> column_tops;
    for (std::size_t i = water.first; i < water.first + water.count; ++i) {
      const double x = snapshot.position[3 * i];
      const double y = snapshot.position[3 * i + 1];
      if (std::hypot(x, y) <= m.radius + 2.0 * dx) continue;
      const std::pair<long, long> column{std::lround(std::floor(x / dx)), std::lround(std::floor(y / dx))};
      const double z = snapshot.position[3 * i + 2];
      const auto [it, inserted] = column_tops.emplace(column, z);
      if (!inserted) it->second = std::max(it->second, z);
    }
    if (column_tops.empty())
      throw std::runtime_error(scene.source_file + ": no free surface beyond the sphere's meniscus");
    std::vector<double> tops;
    for (const auto& [column, z] : column_tops) tops.push_back(z);
    std::sort(tops.begin(), tops.end());
    const std::size_t n = tops.size();
    const double median = n % 2 ? tops[n / 2] : 0.5 * (tops[n / 2 - 1] + tops[n / 2]);
    const double surface = median + 0.5 * dx;
    return surface - (backend->rigid_body_state(ball).centre_of_mass.z() - m.radius);
  };
  const std::size_t sample_steps = steps_for(0.01, setup.dt);
  const std::size_t samples = steps_for(scene.simulation.duration, 0.01);
  for (std::size_t k = 1; k <= samples; ++k) {
    run_steps(*backend, sample_steps);
    m.time.push_back(backend->time());
    m.depth_history.push_back(depth_now());
  }
  m.depth = m.depth_history.back();
  const BodyState state = backend->rigid_body_state(ball);
  m.vertical_speed = std::abs(state.linear_momentum.z() / state.mass);
  return m;
}

}  // namespace mssph::validation
