// Rigid bodies keep the particles within reach of their surface (model/rigid_interior.hpp): which
// sites a box and a turned ball keep, against a count and a brute-force distance, and what
// build_particles keeps of a scene with and without sample_rigid_interiors.
#include "model/rigid_interior.hpp"

#include "config/scene_loader.hpp"
#include "config_test_support.hpp"
#include "model/lattice.hpp"
#include "model/scene_builder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mssph {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using nlohmann::json;

constexpr double kLatticeSpacing = 0.02;

std::size_t sites_kept(const std::vector<std::uint8_t>& keep) {
  return static_cast<std::size_t>(std::count(keep.begin(), keep.end(), std::uint8_t{1}));
}

// A box of n sites an edge: the nearest empty node of a site i sites from a face lies along that
// face's normal, i + 1 spacings away, so a reach of r spacings keeps all but the (n - 2r)^3 core.
TEST(RigidInterior, BoxKeepsItsOuterLayers) {
  const int n = 16;
  const std::vector<Vector3d> sites = sample_box(Vector3d::Constant(n * kLatticeSpacing), kLatticeSpacing);
  ASSERT_EQ(sites.size(), 16u * 16u * 16u);
  for (const int layers : {1, 3, 5}) {
    const auto keep =
        sites_within_reach_of_surface(sites, Matrix3d::Identity(), kLatticeSpacing, layers * kLatticeSpacing);
    const std::size_t core = static_cast<std::size_t>(std::pow(n - 2 * layers, 3));
    EXPECT_EQ(sites_kept(keep), sites.size() - core) << layers << " layers";
  }
}

// A ball turned by an arbitrary rotation, against the definition checked by brute force: a site
// is kept when a node of the ball's lattice within the reach holds no site.
TEST(RigidInterior, TurnedBallKeepsTheSitesWithinReachOfAnEmptyNode) {
  const double radius = 7.0 * kLatticeSpacing, reach = 4.5 * kLatticeSpacing;
  const std::vector<Vector3d> local = sample_sphere(radius, kLatticeSpacing);
  const Matrix3d turn = Eigen::AngleAxisd(0.7, Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Vector3d centre(0.31, -0.12, 0.05);
  std::vector<Vector3d> world;
  for (const Vector3d& p : local) world.push_back(centre + turn * p);
  const auto keep = sites_within_reach_of_surface(world, turn.transpose(), kLatticeSpacing, reach);

  const auto is_site = [&](const Eigen::Vector3i& node) {
    return std::any_of(local.begin(), local.end(),
                       [&](const Vector3d& p) { return (p / kLatticeSpacing - node.cast<double>()).norm() < 1e-6; });
  };
  const int span = static_cast<int>(std::ceil((radius + reach) / kLatticeSpacing)) + 1;
  std::vector<Eigen::Vector3i> empty_nodes;
  for (int a = -span; a <= span; ++a)
    for (int b = -span; b <= span; ++b)
      for (int c = -span; c <= span; ++c)
        if (!is_site({a, b, c})) empty_nodes.emplace_back(a, b, c);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < local.size(); ++i) {
    const bool near = std::any_of(empty_nodes.begin(), empty_nodes.end(), [&](const Eigen::Vector3i& e) {
      return (e.cast<double>() * kLatticeSpacing - local[i]).norm() <= reach + 1e-9;
    });
    EXPECT_EQ(keep[i], near ? 1 : 0) << "site " << local[i].transpose();
    expected += near ? 1 : 0;
  }
  EXPECT_EQ(sites_kept(keep), expected);
  EXPECT_LT(expected, local.size());  // the ball has an interior beyond reach
}

Scene ball_in_box_scene(bool sample_interiors, const Vector3d& ball_at) {
  const json doc = {{"name", "rigid_interior_test"},
                    {"simulation",
                     {{"dt", 0.001},
                      {"duration", 0.1},
                      {"particle_spacing", kLatticeSpacing},
                      {"sample_rigid_interiors", sample_interiors}}},
                    {"materials", {{"m", {{"rest_density", 1000.0}, {"pressure_stiffness", 100.0}}}}},
                    {"bodies",
                     {{"block",
                       {{"kind", "rigid"},
                        {"fixed", true},
                        {"material", "m"},
                        {"density", 2000.0},
                        {"shape", {{"type", "box"}, {"size", {0.4, 0.4, 0.3}}}},
                        {"position", {0.0, 0.0, 0.15}}}},
                      {"ball",
                       {{"kind", "rigid"},
                        {"material", "m"},
                        {"density", 500.0},
                        {"shape", {{"type", "sphere"}, {"radius", 0.15}}},
                        {"position", {ball_at.x(), ball_at.y(), ball_at.z()}}}}}}};
  return parse_scene(doc, "rigid_interior_test.json");
}

// build_particles leaves out the interiors by default, with the mass properties of every site; a
// ball placed inside the block's left-out interior is refused as an overlap all the same.
TEST(RigidInterior, SceneKeepsMassPropertiesAndStillRefusesOverlaps) {
  const Vector3d above(0.0, 0.0, 0.5);
  const ParticleSetup full = build_particles(ball_in_box_scene(true, above));
  const ParticleSetup kept = build_particles(ball_in_box_scene(false, above));
  ASSERT_EQ(full.bodies.size(), 2u);
  const std::size_t block = full.bodies[0].name == "block" ? 0 : 1, ball = 1 - block;
  const double reach = rigid_surface_reach(full.smoothing_length, full.spacing);
  EXPECT_DOUBLE_EQ(reach, 5.0 * kLatticeSpacing);
  // The block, 20 x 20 x 15 sites, keeps all but its 10 x 10 x 5 core.
  EXPECT_EQ(full.bodies[block].count, 20u * 20u * 15u);
  EXPECT_EQ(kept.bodies[block].count, 20u * 20u * 15u - 10u * 10u * 5u);
  EXPECT_LT(kept.bodies[ball].count, full.bodies[ball].count);
  EXPECT_EQ(kept.size(), kept.bodies[0].count + kept.bodies[1].count);
  EXPECT_EQ(kept.bodies[1].first, kept.bodies[0].count);  // consecutive ranges
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_EQ(kept.bodies[b].mass, full.bodies[b].mass);
    EXPECT_EQ(kept.bodies[b].centre_of_mass, full.bodies[b].centre_of_mass);
    EXPECT_EQ(kept.bodies[b].inertia_body, full.bodies[b].inertia_body);
    EXPECT_EQ(kept.bodies[b].lattice_sites, full.bodies[b].count);  // the volume the body stands for
  }
  // Every kept particle is one of the full body's, with its velocity and rest offset.
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const auto match = std::find(full.position.begin(), full.position.end(), kept.position[i]);
    ASSERT_NE(match, full.position.end());
    const std::size_t j = static_cast<std::size_t>(match - full.position.begin());
    EXPECT_EQ(kept.body[i], full.body[j]);
    EXPECT_EQ(kept.rest_offset[i], full.rest_offset[j]);
    EXPECT_EQ(kept.velocity[i], full.velocity[j]);
  }
  const std::string message =
      test::input_error_of([] { build_particles(ball_in_box_scene(false, Vector3d(0.01, 0.01, 0.16))); });
  EXPECT_THAT(message, testing::HasSubstr("overlap"));
}

}  // namespace
}  // namespace mssph
