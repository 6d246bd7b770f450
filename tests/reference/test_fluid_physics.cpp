// Fluid physics of the reference backend against independent expectations: hydrostatics,
// momentum conservation and Archimedes' principle.
#include "scene_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace mssph::testing {
namespace {

constexpr double kG = 9.81;

// Water and a free-slip wall material: the wall's zero viscosity makes the interface viscosity
// (harmonic mean) zero, so the walls carry no weight by friction and the floor carries all of it.
nlohmann::json water_and_walls(double viscosity) {
  return {{"water", {{"rest_density", 1000.0}, {"pressure_stiffness", 400.0}, {"viscosity", viscosity}}},
          {"wall", {{"rest_density", 1000.0}, {"pressure_stiffness", 400.0}, {"viscosity", 0.0}}}};
}

// Least-squares line y = a + b x.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - slope * sx) / n, slope};
}

// A 40 cm column of water settles in a free-slip tank. Hydrostatics then fixes two quantities
// independently of any SPH detail: the pressure gradient dP/dz = -rho0 g, and the pressure at the
// floor = the column's weight over the floor area, M g / A. Both are checked within the issue's
// 5% on slab-averaged pressures averaged over the last 0.5 s (SPH pressures are noisy per
// particle), over slabs at least two smoothing lengths below the free surface (where the kernel
// support is full); the tall column gives the fitted slope a long lever arm against the +-10%
// slab-to-slab scatter of SPH pressures at h = 2 dx. Measured (cpu backend, same scene): slope
// 3.4% steep, floor pressure 1.8% high: the settled, slightly disordered particles have a
// discrete gradient ~3% weaker than the rest lattice the pressure force is calibrated on.
TEST(FluidPhysics, SettledColumnHasHydrostaticPressure) {
  const double dx = 0.02;
  const double rho0 = 1000.0;
  const double width = 0.2;
  nlohmann::json doc = scene_document(dx, 2.5e-4, 1.5);
  doc["materials"] = water_and_walls(1.0);
  doc["bodies"]["tank"] = {{"kind", "boundary"}, {"material", "wall"},
                           {"shape", {{"type", "container"}, {"inner_size", vec(width, width, 0.5)}}},
                           {"position", vec(0, 0, 0.25)}};
  doc["bodies"]["column"] = {{"kind", "fluid"}, {"material", "water"},
                             {"shape", {{"type", "box"}, {"size", vec(width, width, 0.4)}}},
                             {"position", vec(0, 0, 0.2)}};
  auto sim = make_reference(doc);
  const BodySetup& column = sim.setup().bodies[body_index(sim.setup(), "column")];
  run_steps(sim, 4000);  // 1 s: the column settles (kinetic energy falls 10-fold)

  // Slab k holds the particle layer centred at z = (k + 1/2) dx above the floor (z = 0).
  const int slabs = 20;
  std::vector<double> pressure_sum(slabs, 0.0);
  std::vector<double> samples(slabs, 0.0);
  for (int sample = 0; sample < 50; ++sample) {
    run_steps(sim, 40);  // every 0.01 s over the last 0.5 s
    for (std::size_t i = column.first; i < column.first + column.count; ++i) {
      const int k = static_cast<int>(std::floor(sim.particles().position[i].z() / dx));
      if (k < 0 || k >= slabs) continue;
      pressure_sum[k] += sim.particles().pressure[i];
      samples[k] += 1.0;
    }
  }
  double top = -1e9;
  for (std::size_t i = column.first; i < column.first + column.count; ++i) top = std::max(top, sim.particles().position[i].z());
  std::vector<double> height, pressure;
  for (int k = 0; k < slabs; ++k) {
    const double z = (k + 0.5) * dx;
    if (samples[k] == 0.0 || z > top - 2.0 * sim.setup().smoothing_length) continue;
    height.push_back(z);
    pressure.push_back(pressure_sum[k] / samples[k]);
  }
  ASSERT_GE(height.size(), 5u);
  const auto [floor_pressure, slope] = fit_line(height, pressure);
  EXPECT_NEAR(-slope, rho0 * kG, 0.05 * rho0 * kG);
  double mass = 0.0;
  for (std::size_t i = column.first; i < column.first + column.count; ++i) mass += sim.setup().mass[i];
  const double weight_per_area = mass * kG / (width * width);
  EXPECT_NEAR(floor_pressure, weight_per_area, 0.05 * weight_per_area);
  // Settled: the fastest particle moves slower than 1% of the sound speed sqrt(k) = 20 m/s.
  EXPECT_LT(sim.body_states()[body_index(sim.setup(), "column")].max_speed, 0.2);
}

// Pairwise pressure and viscosity forces are antisymmetric, and rigid bodies sum the same forces:
// without gravity and boundaries the total linear momentum of fluids and rigid bodies is
// conserved to rounding while they collide.
TEST(FluidPhysics, MomentumIsConservedBetweenFluidsAndRigidBodies) {
  const double dx = 0.02;
  nlohmann::json doc = scene_document(dx, 2.5e-4, 1.0, vec(0, 0, 0));
  doc["simulation"]["jitter"] = 0.1;
  doc["simulation"]["seed"] = 3;
  doc["materials"]["water"] = {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}, {"viscosity", 1.0}};
  doc["materials"]["oil"] = {{"rest_density", 800.0}, {"pressure_stiffness", 150.0}, {"viscosity", 3.0}};
  doc["bodies"]["water"] = {{"kind", "fluid"}, {"material", "water"}, {"shape", {{"type", "box"}, {"size", vec(0.16, 0.16, 0.16)}}},
                            {"velocity", vec(0.0, 0, 0)}};
  doc["bodies"]["oil"] = {{"kind", "fluid"}, {"material", "oil"}, {"shape", {{"type", "box"}, {"size", vec(0.12, 0.12, 0.12)}}},
                          {"position", vec(0.15, 0.02, 0)}, {"velocity", vec(-1.0, 0, 0.5)}};
  doc["bodies"]["ball"] = {{"kind", "rigid"}, {"material", "water"}, {"density", 700.0}, {"shape", {{"type", "sphere"}, {"radius", 0.06}}},
                           {"position", vec(-0.16, 0, 0.03)}, {"velocity", vec(1.0, 0, 0)}, {"angular_velocity", vec(0, 3, 0)}};
  auto sim = make_reference(doc);
  const std::size_t ball = body_index(sim.setup(), "ball");
  const auto total_momentum = [&] {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (const BodyState& s : sim.body_states()) p += s.linear_momentum;
    return p;
  };
  const Eigen::Vector3d before = total_momentum();
  const Eigen::Vector3d ball_before = sim.body_states()[ball].linear_momentum;
  double scale = 0.0;  // sum of |m v|: the momentum that moves around
  for (const BodyState& s : sim.body_states()) scale += s.linear_momentum.norm();
  run_steps(sim, 400);
  // The bodies did interact (momentum changed hands) ...
  EXPECT_GT((sim.body_states()[ball].linear_momentum - ball_before).norm(), 1e-3 * scale);
  // ... and the total is conserved to rounding (400 steps of sums of ~1e4 terms in double).
  EXPECT_LT((total_momentum() - before).norm(), 1e-10 * scale);
}

// A sphere of density 500 floats in water (1000) with half its volume submerged: the depth of
// its lowest point below the free surface follows from the spherical cap whose volume is
// M / rho_water. Tolerance 10% (the issue's), for a sphere of radius 5 spacings.
TEST(FluidPhysics, LightSphereFloatsAtArchimedesDepth) {
  const double dx = 0.02;
  const double rho_fluid = 1000.0;
  nlohmann::json doc = scene_document(dx, 2.5e-4, 2.0);
  doc["materials"] = water_and_walls(3.0);
  doc["bodies"]["tank"] = {{"kind", "boundary"}, {"material", "wall"},
                           {"shape", {{"type", "container"}, {"inner_size", vec(0.36, 0.36, 0.4)}}},
                           {"position", vec(0, 0, 0.2)}};
  doc["bodies"]["water"] = {{"kind", "fluid"}, {"material", "water"},
                            {"shape", {{"type", "box"}, {"size", vec(0.36, 0.36, 0.2)}}}, {"position", vec(0, 0, 0.1)}};
  doc["bodies"]["ball"] = {{"kind", "rigid"}, {"material", "water"}, {"density", 500.0},
                           {"shape", {{"type", "sphere"}, {"radius", 0.1}}}, {"position", vec(0, 0, 0.31)}};
  auto sim = make_reference(doc);
  run_steps(sim, 6000);  // 1.5 s: the bobbing (period ~0.5 s) dies out under viscosity

  const std::size_t ball = body_index(sim.setup(), "ball");
  const BodySetup& water = sim.setup().bodies[body_index(sim.setup(), "water")];
  const BodySetup& ball_setup = sim.setup().bodies[ball];
  // The sphere as sampled: N particles of volume dx^3 make a ball of this radius.
  const double radius = std::cbrt(3.0 * static_cast<double>(ball_setup.count) * dx * dx * dx / (4.0 * std::numbers::pi));
  const double submerged_volume = ball_setup.mass / rho_fluid;
  // Cap depth d with pi d^2 (3 R - d) / 3 = V, by bisection on [0, 2R].
  double lo = 0.0;
  double hi = 2.0 * radius;
  for (int k = 0; k < 60; ++k) {
    const double d = 0.5 * (lo + hi);
    (std::numbers::pi * d * d * (3.0 * radius - d) / 3.0 < submerged_volume ? lo : hi) = d;
  }
  const double expected_depth = 0.5 * (lo + hi);
  // Free surface away from the sphere: the top particle layer's mean height plus half a spacing
  // (each particle stands for a cell of side dx), over particles beyond the sphere's meniscus.
  const auto& x = sim.particles().position;
  double top = -1e9;
  for (std::size_t i = water.first; i < water.first + water.count; ++i) top = std::max(top, x[i].z());
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = water.first; i < water.first + water.count; ++i) {
    if (x[i].z() > top - 0.5 * dx && x[i].head<2>().norm() > radius + 2.0 * dx) {
      sum += x[i].z();
      ++count;
    }
  }
  ASSERT_GT(count, 0);
  const double surface = sum / count + 0.5 * dx;
  const BodyState state = sim.rigid_body_state(ball);
  const double depth = surface - (state.centre_of_mass.z() - radius);
  EXPECT_NEAR(depth, expected_depth, 0.1 * expected_depth);
  EXPECT_LT(std::abs(state.linear_momentum.z() / state.mass), 0.02);  // settled
}

}  // namespace
}  // namespace mssph::testing
