#include "dam_break.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "framework/fits.hpp"
#include "model/scene_builder.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

namespace mssph::validation {

Scene dam_break_scene(double dx, const std::vector<std::string>& overrides) {
  std::vector<std::string> all = resolution_overrides(case_scene("physics/dam_break"), dx);
  all.insert(all.end(), overrides.begin(), overrides.end());
  return case_scene("physics/dam_break", all);
}

DamBreakMeasurement measure_dam_break(const std::string& backend_name, const Scene& scene, double sample_interval) {
  const ParticleSetup setup = build_particles(scene);
  const BodySetup water = setup.bodies[body_index(setup, "water", scene)];
  const BodyConfig& water_config = *scene.find_body("water");
  const double dx = setup.spacing;
  // The tank's wall and floor: the column's box touches both.
  const double wall_x = water_config.position.x() - 0.5 * water_config.shape.size.x();
  const double floor_z = water_config.position.z() - 0.5 * water_config.shape.size.z();
  if (std::abs(floor_z) > 0.5 * dx)
    throw std::runtime_error(scene.source_file + ": the dam break's column must stand on the floor z = 0");

  DamBreakMeasurement m;
  m.width = water_config.shape.size.x();
  m.height = water_config.shape.size.z();
  m.gravity = setup.gravity.norm();
  m.particles = setup.size();
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const std::size_t row =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(water_config.shape.size.y() / dx)));
  std::vector<double> xs(water.count);
  std::vector<double> zs;
  const auto sample = [&] {
    const ParticleSnapshot snapshot = backend->snapshot();
    zs.clear();
    for (std::size_t i = water.first; i < water.first + water.count; ++i) {
      const double x = snapshot.position[3 * i];
      xs[i - water.first] = x;
      if (x - wall_x <= dx) zs.push_back(snapshot.position[3 * i + 2]);
    }
    std::nth_element(xs.begin(), xs.begin() + (row - 1), xs.end(), std::greater<>());
    double column = floor_z - 0.5 * dx;
    if (zs.size() >= row) {
      std::nth_element(zs.begin(), zs.begin() + (row - 1), zs.end(), std::greater<>());
      column = zs[row - 1];
    }
    m.time.push_back(backend->time());
    m.front.push_back(xs[row - 1] + 0.5 * dx - wall_x);
    m.column.push_back(column + 0.5 * dx - floor_z);
  };
  sample();
  const std::size_t sample_steps = std::max<std::size_t>(1, steps_for(sample_interval, setup.dt));
  const std::size_t samples = steps_for(scene.simulation.duration, static_cast<double>(sample_steps) * setup.dt);
  for (std::size_t k = 0; k < samples; ++k) {
    run_steps(*backend, sample_steps);
    sample();
  }
  return m;
}

NondimensionalCollapse nondimensional(const DamBreakMeasurement& m) {
  const double front_time_scale = std::sqrt(2.0 * m.gravity / m.width);
  const double height_time_scale = std::sqrt(m.gravity / m.width);
  NondimensionalCollapse c;
  for (std::size_t k = 0; k < m.time.size(); ++k) {
    c.T.push_back(m.time[k] * front_time_scale);
    c.Z.push_back(m.front[k] / m.width);
    c.tau.push_back(m.time[k] * height_time_scale);
    c.H.push_back(m.column[k] / m.height);
  }
  return c;
}

SurgeComparison compare_surge(const NondimensionalCollapse& c, const DamBreakExperiment& experiment) {
  return compare_surge(c.T, c.Z, experiment.front_time, experiment.front, kSurgeFirstFront, kSurgeLastFront);
}

double largest_height_deviation(const NondimensionalCollapse& c, const DamBreakExperiment& experiment) {
  double largest = 0.0;
  for (std::size_t k = 0; k < experiment.height_time.size() && experiment.height_time[k] <= c.tau.back(); ++k)
    largest =
        std::max(largest, std::abs(interpolate(c.tau, c.H, experiment.height_time[k]) / experiment.height[k] - 1.0));
  return largest;
}

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const auto upper = std::upper_bound(xs.begin(), xs.end(), x);
  if (upper == xs.begin()) return ys.front();
  if (upper == xs.end()) return ys.back();
  const std::size_t k = static_cast<std::size_t>(upper - xs.begin());
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + w * (ys[k] - ys[k - 1]);
}

namespace {

// The slope of a least-squares line through the samples whose Z lies in [lo, hi], and the first
// T at which Z reaches lo (interpolated).
std::pair<double, double> surge_speed_and_arrival(const std::vector<double>& T, const std::vector<double>& Z, double lo,
                                                  double hi) {
  std::vector<double> t;
  std::vector<double> z;
  double arrival = 0.0;
  bool arrived = false;
  for (std::size_t k = 0; k < T.size(); ++k) {
    if (Z[k] >= lo && !arrived) {
      arrival = k == 0 ? T[0] : T[k - 1] + (lo - Z[k - 1]) / (Z[k] - Z[k - 1]) * (T[k] - T[k - 1]);
      arrived = true;
    }
    if (Z[k] >= lo && Z[k] <= hi) {
      t.push_back(T[k]);
      z.push_back(Z[k]);
    }
  }
  if (t.size() < 2)
    throw std::runtime_error("dam break: fewer than two front samples between Z = " + exact(lo) + " and " + exact(hi));
  return {fit_line(t, z).second, arrival};
}

}  // namespace

SurgeComparison compare_surge(const std::vector<double>& T, const std::vector<double>& Z,
                              const std::vector<double>& experiment_T, const std::vector<double>& experiment_Z,
                              double first_front, double last_front) {
  SurgeComparison c;
  const auto [speed, arrival] = surge_speed_and_arrival(T, Z, first_front, last_front);
  const auto [expected_speed, expected_arrival] =
      surge_speed_and_arrival(experiment_T, experiment_Z, first_front, last_front);
  c.speed = speed;
  c.expected_speed = expected_speed;
  c.offset = expected_arrival - arrival;
  for (std::size_t k = 0; k < experiment_T.size(); ++k) {
    if (experiment_Z[k] < first_front || experiment_Z[k] > last_front) continue;
    const double simulated = interpolate(T, Z, experiment_T[k] - c.offset);
    c.largest_deviation = std::max(c.largest_deviation, std::abs(simulated / experiment_Z[k] - 1.0));
    ++c.compared_points;
  }
  return c;
}

}  // namespace mssph::validation
