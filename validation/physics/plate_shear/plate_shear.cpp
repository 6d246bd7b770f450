#include "plate_shear.hpp"

#include "backend_factory/backend_factory.hpp"
#include "framework/backends.hpp"
#include "model/scene_builder.hpp"
#include "physics/stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mssph::validation {

Scene plate_shear_scene(double dx, double viscosity, const std::vector<std::string>& overrides) {
  const Scene base = case_scene("physics/plate_shear");
  const BodyConfig& fluid = *base.find_body("fluid");
  const double rho = fluid.material.rest_density;
  const double height = fluid.shape.size.z();
  std::vector<std::string> all = viscous_resolution_overrides(base, dx, rho, viscosity);
  all.push_back("simulation/duration=" + exact(height * height * rho / (16.0 * viscosity)));
  all.push_back("materials/fluid/viscosity=" + exact(viscosity));
  all.push_back("materials/plate/viscosity=" + exact(viscosity));
  all.insert(all.end(), overrides.begin(), overrides.end());
  return case_scene("physics/plate_shear", all);
}

PlateShearMeasurement measure_plate_shear(const std::string& backend_name, const Scene& scene) {
  const ParticleSetup setup = build_particles(scene);
  const std::size_t plate = body_index(setup, "plate", scene);
  const BodySetup fluid = setup.bodies[body_index(setup, "fluid", scene)];
  const BodyConfig& fluid_config = *scene.find_body("fluid");
  const double speed = scene.find_body("plate")->velocity.x();
  if (speed == 0.0) throw std::runtime_error(scene.source_file + ": the plate must start moving along x");
  const double mu = fluid.material.viscosity;
  const double nu = mu / fluid.material.rest_density;
  const double area = fluid_config.shape.size.x() * fluid_config.shape.size.y();

  PlateShearMeasurement m;
  m.viscosity = mu;
  m.particles = setup.size();
  std::unique_ptr<Backend> backend = make_backend(backend_name, setup);
  const std::size_t steps = steps_for(scene.simulation.duration, setup.dt);
  std::vector<double> ratio;
  for (std::size_t s = 1; s <= steps; ++s) {
    backend->step();
    // The step's interaction force was summed at its start, one dt before the backend's time.
    const double t = backend->time() - setup.dt;
    if (t <= 0.0) continue;
    const double expected = -mu * speed * area / std::sqrt(std::numbers::pi * nu * t);
    const double force = backend->rigid_body_state(plate).interaction_force.x();
    m.time.push_back(t);
    m.force.push_back(force);
    m.expected.push_back(expected);
    if (4 * s > steps) ratio.push_back(force / expected);
  }
  if (ratio.empty()) throw std::runtime_error(scene.source_file + ": the run is too short to measure the drag");
  double sum = 0.0;
  for (const double r : ratio) sum += r;
  m.ratio = sum / static_cast<double>(ratio.size());
  const auto [lo, hi] = std::minmax_element(ratio.begin(), ratio.end());
  m.ratio_spread = *hi - *lo;
  return m;
}

}  // namespace mssph::validation
