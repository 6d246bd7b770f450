// Rigid-body physics of the reference backend against mechanics: a body at rest on the ground
// stays at rest, and a torque-free body keeps its angular momentum and energy while it tumbles.
#include "framework/backends.hpp"
#include "physics/torque_free_spin/torque_free_spin.hpp"
#include "scene_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

namespace mssph::testing {
namespace {

// A 10 x 10 x 6 cm box of density 500 set on a boundary plate: it sinks into the SPH contact
// layer until the pressure carries its weight, then stays put. After settling (0.3 s) it may not
// move by more than 1 mm or turn by more than 0.5 degree in the next 0.5 s (a drift that small
// over 2000 steps means no creeping or sliding), and it never sinks by half a spacing.
TEST(RigidPhysics, BoxRestingOnTheGroundStaysPut) {
  const double dx = 0.02;
  nlohmann::json doc = scene_document(dx, 2.5e-4, 1.0);
  doc["materials"]["contact"] = {{"rest_density", 1000.0}, {"pressure_stiffness", 500.0}, {"viscosity", 5.0}};
  doc["bodies"]["ground"] = {{"kind", "boundary"},
                             {"material", "contact"},
                             {"shape", {{"type", "box"}, {"size", vec(0.3, 0.3, 0.04)}}},
                             {"position", vec(0, 0, -0.02)}};
  // The box's lattice continues the plate's: its bottom layer sits one spacing above the plate's top.
  doc["bodies"]["box"] = {{"kind", "rigid"},
                          {"material", "contact"},
                          {"density", 500.0},
                          {"shape", {{"type", "box"}, {"size", vec(0.1, 0.1, 0.06)}}},
                          {"position", vec(0, 0, 0.03)}};
  auto sim = make_reference(doc);
  const std::size_t box = body_index(sim.setup(), "box");
  const Eigen::Vector3d start = sim.rigid_body_state(box).centre_of_mass;
  run_steps(sim, 1200);
  const BodyState settled = sim.rigid_body_state(box);
  double lowest = settled.centre_of_mass.z();
  double support = 0.0;  // the ground's push, averaged over the last 0.5 s
  for (int k = 0; k < 200; ++k) {
    run_steps(sim, 10);
    const BodyState s = sim.rigid_body_state(box);
    lowest = std::min(lowest, s.centre_of_mass.z());
    support += s.interaction_force.z() / 200.0;
  }
  const BodyState later = sim.rigid_body_state(box);
  EXPECT_LT((later.centre_of_mass - settled.centre_of_mass).norm(), 1e-3);
  EXPECT_LT(later.linear_momentum.norm() / later.mass, 0.01);
  EXPECT_LT(later.orientation.angularDistance(settled.orientation) * 180.0 / std::numbers::pi, 0.5);
  EXPECT_GT(lowest, start.z() - 0.5 * dx);
  // The ground carries the weight: on average the interaction force balances gravity (2%).
  EXPECT_NEAR(support, later.mass * 9.81, 0.02 * later.mass * 9.81);
}

// A box of three different edge lengths spinning about an axis close to its intermediate
// principal axis tumbles (the tennis-racket instability) in free space. Without torque its
// angular momentum L is constant: the integrator advances L itself, so it holds to rounding
// (1e-12 relative over 8000 steps). Its rotational energy L . omega / 2 is not built in: the
// orientation update exp(omega dt) with omega = I(q)^-1 L is first order, so energy drifts by
// O(|omega| dt) = 1.3e-3 per tumble; 0.5% is allowed over 2 s (measured 0.15%). The test also
// asserts that the body flipped: its angular velocity in body axes, along +y at the start, must
// swing by more than 90 degrees, so a body that never tumbled cannot pass.
TEST(RigidPhysics, TorqueFreeTumblingKeepsAngularMomentumAndEnergy) {
  // The scene and the measurement are the physics case's (validation/physics/torque_free_spin).
  const validation::SpinMeasurement m =
      validation::measure_torque_free_spin("reference", validation::case_scene("physics/torque_free_spin"));
  EXPECT_LT(m.worst_momentum_error, 1e-12);
  std::cout << "energy drift " << m.worst_energy_drift << ", body-axis omega turned " << m.largest_turn_degrees
            << " deg\n";
  EXPECT_LT(m.worst_energy_drift, 5e-3);
  EXPECT_GT(m.largest_turn_degrees, 90.0);
  EXPECT_LT(m.final_linear_momentum, 1e-12);  // nothing pushed it
}

}  // namespace
}  // namespace mssph::testing
