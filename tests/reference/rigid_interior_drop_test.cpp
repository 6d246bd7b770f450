// A rigid ball striking a fixed rigid block and a fluid pool feels the same force whether the two
// rigid bodies keep every lattice site or only those within rigid_surface_reach of their surface
// (model/rigid_interior.hpp, the default). The expectation is the argument of that header: a
// rigid particle enters another body's sums only within h, and through its density its own
// neighbours within h, so particles deeper than 2h take part in nothing. A body cut to its
// surface layer alone must feel a different force, or the comparison could not fail.
#include "backend_factory/backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "model/rigid_interior.hpp"
#include "model/scene_builder.hpp"
#include "scene_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mssph {
namespace {

using Eigen::Vector3d;
using nlohmann::json;

constexpr double kBallSpacing = 0.01;  // the ball's radius is 10 spacings, so that a core lies beyond reach
constexpr double kStep = 2.5e-4;       // [s]
constexpr double kStrike = 0.03;       // the ball's travel into the target and its push back [s]

// A ball of radius 10 dx moving down at 1 m/s, one spacing above a 30 x 30 x 12-site target: a
// fixed rigid block, or a fluid pool in a container.
Scene ball_strike_scene(const std::string& target, bool sample_interiors) {
  json bodies = {{"ball",
                  {{"kind", "rigid"},
                   {"material", "solid"},
                   {"density", 500.0},
                   {"shape", {{"type", "sphere"}, {"radius", 0.1}}},
                   {"position", {0.0, 0.0, 0.12 + 0.1 + kBallSpacing}},
                   {"velocity", {0.0, 0.0, -1.0}}}}};
  const json target_box = {{"type", "box"}, {"size", {0.3, 0.3, 0.12}}};
  if (target == "rigid") {
    bodies["block"] = {{"kind", "rigid"},   {"fixed", true},       {"material", "solid"},
                       {"density", 2000.0}, {"shape", target_box}, {"position", {0.0, 0.0, 0.06}}};
  } else {
    bodies["pool"] = {{"kind", "fluid"}, {"material", "liquid"}, {"shape", target_box}, {"position", {0.0, 0.0, 0.06}}};
    bodies["tank"] = {{"kind", "boundary"},
                      {"material", "liquid"},
                      {"shape", {{"type", "container"}, {"inner_size", {0.3, 0.3, 0.4}}}},
                      {"position", {0.0, 0.0, 0.2}}};
  }
  const json doc = {{"name", "rigid_interior_" + target},
                    {"simulation",
                     {{"dt", kStep},
                      {"duration", 0.1},
                      {"particle_spacing", kBallSpacing},
                      {"jitter", 0.02},
                      {"seed", 7},
                      {"sample_rigid_interiors", sample_interiors}}},
                    {"materials",
                     {{"solid", {{"rest_density", 1000.0}, {"pressure_stiffness", 400.0}}},
                      {"liquid", {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}, {"viscosity", 1.0}}}}},
                    {"bodies", bodies}};
  return parse_scene(doc, "rigid_interior_" + target + ".json");
}

// The ball's interaction force, step by step, on the float32 cpu backend.
std::vector<Vector3d> ball_force(ParticleSetup setup) {
  const std::size_t ball = testing::body_index(setup, "ball");
  const auto backend = make_backend("cpu", std::move(setup));
  std::vector<Vector3d> force;
  for (std::size_t s = 0; s < static_cast<std::size_t>(std::lround(kStrike / kStep)); ++s) {
    backend->step();
    force.push_back(backend->body_states()[ball].interaction_force);
  }
  return force;
}

// The largest difference between two force histories over the first's peak.
double largest_difference(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  double peak = 0.0, difference = 0.0;
  for (std::size_t s = 0; s < a.size(); ++s) {
    peak = std::max(peak, a[s].norm());
    difference = std::max(difference, (a[s] - b[s]).norm());
  }
  return difference / peak;
}

class RigidInteriorStrike : public ::testing::TestWithParam<std::string> {};

TEST_P(RigidInteriorStrike, LeavingOutTheInteriorsChangesNoForce) {
  const ParticleSetup full = build_particles(ball_strike_scene(GetParam(), true));
  const ParticleSetup cut = build_particles(ball_strike_scene(GetParam(), false));
  const std::size_t ball = testing::body_index(full, "ball");
  ASSERT_LT(cut.bodies[ball].count, full.bodies[ball].count);
  const std::vector<Vector3d> reference = ball_force(full);
  const double peak = std::max_element(reference.begin(), reference.end(), [](const Vector3d& a, const Vector3d& b) {
                        return a.norm() < b.norm();
                      })->norm();
  // The ball strikes: its peak force is well above its weight (500 kg/m^3 x 4.2e-3 m^3 x g = 20 N).
  ASSERT_GT(peak, 2.0 * full.bodies[ball].mass * 9.81);

  const double cut_difference = largest_difference(reference, ball_force(cut));
  // A body cut to the sites within one spacing of its surface (the planted error); the jittered
  // positions stand for the lattice sites, which they round to.
  ParticleSetup surface_only = build_particles(ball_strike_scene(GetParam(), true));
  leave_out_rigid_interiors(surface_only, full.position, full.spacing);
  const double surface_only_difference = largest_difference(reference, ball_force(surface_only));
  std::cout << GetParam() << ": particles " << full.size() << " -> " << cut.size() << ", peak force " << peak
            << " N, largest difference over the peak: left out beyond reach " << cut_difference
            << ", surface layer only " << surface_only_difference << "\n";
  // The same pairs in the same order: float32 sums that differ only by the zero forces of the
  // left-out particles. 1e-6 of the peak allows a change of summation order in the ball's wrench.
  EXPECT_LT(cut_difference, 1e-6);
  EXPECT_GT(surface_only_difference, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Targets, RigidInteriorStrike, ::testing::Values("rigid", "fluid"));

}  // namespace
}  // namespace mssph
