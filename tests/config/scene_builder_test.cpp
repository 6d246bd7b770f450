// build_particles: placement, rotation and jitter of each body, SPH and rigid-body masses, fixed
// regions, and the scenes it refuses (empty or overlapping bodies; the overlap reported the same
// whatever the thread count).
#include "model/scene_builder.hpp"

#include "config/scene_loader.hpp"
#include "config_test_support.hpp"
#include "model/lattice.hpp"
#include "model/smoothing_kernels.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <omp.h>

namespace mssph {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using nlohmann::json;
using test::input_error_of;
using testing::HasSubstr;
using testing::StartsWith;

constexpr double kDx = 0.02;

// Positions are sums and rotations of a few O(1 m) terms: 1e-12 m is far below any spacing and
// far above double rounding.
constexpr double kPositionTolerance = 1e-12;

// A scene of the given bodies at spacing kDx and h = 2 dx.
Scene scene_of(const json& bodies, double jitter = 0.0, std::uint64_t seed = 0) {
  const json doc = {
      {"name", "builder_test"},
      {"simulation", {{"dt", 0.001}, {"duration", 0.1}, {"particle_spacing", kDx}, {"jitter", jitter}, {"seed", seed}}},
      {"bodies", bodies}};
  return parse_scene(doc, "builder_test.json");
}

json body(const std::string& kind, const json& shape, const Vector3d& position = Vector3d::Zero()) {
  json b = {{"kind", kind},
            {"shape", shape},
            {"position", {position.x(), position.y(), position.z()}},
            {"rest_density", 1000.0},
            {"pressure_stiffness", 100.0}};
  if (kind == "rigid") b["density"] = 500.0;
  if (kind == "deformable") {
    b["young_modulus"] = 1.0e4;
    b["poisson_ratio"] = 0.3;
  }
  return b;
}

json box(const Vector3d& size) { return {{"type", "box"}, {"size", {size.x(), size.y(), size.z()}}}; }

std::vector<Vector3d> positions_of(const ParticleSetup& setup, const BodySetup& b) {
  return {setup.position.begin() + static_cast<long>(b.first),
          setup.position.begin() + static_cast<long>(b.first + b.count)};
}

TEST(SceneBuilder, ShippedScenesBuildWithoutOverlaps) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(MSSPH_SOURCE_DIR) + "/configs")) {
    const std::string name = entry.path().filename().string();
    // Not scenes: the schemas and the sweep files (sweep_*.json, checked by tests/sweep).
    if (entry.path().extension() != ".json" || name.find(".schema.") != std::string::npos ||
        name.rfind("sweep_", 0) == 0) {
      continue;
    }
    SCOPED_TRACE(name);
    const Scene scene = load_scene(entry.path().string());
    const ParticleSetup setup = build_particles(scene);
    ASSERT_EQ(setup.bodies.size(), scene.bodies.size());
    for (const BodySetup& b : setup.bodies) EXPECT_GT(b.count, 0u) << b.name;
  }
}

TEST(SceneBuilder, BodiesAreContiguousRangesCoveringEveryParticle) {
  const ParticleSetup setup = build_particles(
      scene_of({{"a", body("fluid", box({0.1, 0.1, 0.1}))}, {"b", body("rigid", box({0.1, 0.1, 0.1}), {0.5, 0, 0})}}));
  std::size_t next = 0;
  for (std::size_t i = 0; i < setup.bodies.size(); ++i) {
    const BodySetup& b = setup.bodies[i];
    EXPECT_EQ(b.first, next);
    for (std::size_t p = b.first; p < b.first + b.count; ++p) EXPECT_EQ(setup.body[p], i);
    next += b.count;
  }
  EXPECT_EQ(next, setup.size());
  EXPECT_EQ(setup.velocity.size(), setup.size());
  EXPECT_EQ(setup.mass.size(), setup.size());
  EXPECT_EQ(setup.fixed.size(), setup.size());
  EXPECT_EQ(setup.rest_offset.size(), setup.size());
}

TEST(SceneBuilder, BoxParticlesAreCentredOnTheBodyPosition) {
  const Vector3d position(0.3, -0.2, 0.45);
  const ParticleSetup setup = build_particles(scene_of({{"a", body("fluid", box({0.1, 0.06, 0.08}), position)}}));
  const std::vector<Vector3d> x = positions_of(setup, setup.bodies[0]);
  ASSERT_EQ(x.size(), 5u * 3 * 4);
  Vector3d mean = Vector3d::Zero();
  for (const Vector3d& p : x) mean += p;
  mean /= static_cast<double>(x.size());
  EXPECT_LT((mean - position).norm(), kPositionTolerance);
}

TEST(SceneBuilder, OrientationRotatesTheShapeAboutItsCentre) {
  // A quarter turn about z maps the box's long x edge onto y.
  const Vector3d position(0.1, 0.2, 0.3);
  const double s = std::sqrt(0.5);
  json b = body("rigid", box({0.12, 0.04, 0.06}), position);
  b["orientation"] = {0.0, 0.0, s, s};
  const ParticleSetup setup = build_particles(scene_of({{"turned", b}}));
  const std::vector<Vector3d> local = sample_box({0.12, 0.04, 0.06}, kDx);
  const std::vector<Vector3d> world = positions_of(setup, setup.bodies[0]);
  ASSERT_EQ(world.size(), local.size());
  Vector3d extent = Vector3d::Zero();
  for (std::size_t i = 0; i < world.size(); ++i) {
    // Here x_local = (a, b, c) lands on (-b, a, c) + position: no rotation matrix in the check.
    const Vector3d expected = position + Vector3d(-local[i].y(), local[i].x(), local[i].z());
    EXPECT_LT((world[i] - expected).norm(), kPositionTolerance) << i;
    extent = extent.cwiseMax((world[i] - position).cwiseAbs());
    // Rigid bodies keep each particle's offset in the body frame: the unrotated local point.
    EXPECT_LT((setup.rest_offset[i] - local[i]).norm(), kPositionTolerance) << i;
  }
  EXPECT_NEAR(extent.x(), 0.5 * 0.04 - 0.5 * kDx, kPositionTolerance);
  EXPECT_NEAR(extent.y(), 0.5 * 0.12 - 0.5 * kDx, kPositionTolerance);
}

TEST(SceneBuilder, JitterIsBoundedAndReproducible) {
  const double jitter = 0.2;
  const json bodies = {{"a", body("fluid", box({0.1, 0.1, 0.1}))}};
  const ParticleSetup plain = build_particles(scene_of(bodies));
  const ParticleSetup first = build_particles(scene_of(bodies, jitter, 42));
  const ParticleSetup again = build_particles(scene_of(bodies, jitter, 42));
  const ParticleSetup other = build_particles(scene_of(bodies, jitter, 43));
  ASSERT_EQ(first.size(), plain.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    const Vector3d offset = first.position[i] - plain.position[i];
    // Each component is uniform in [-jitter dx, jitter dx]; the bound holds up to rounding.
    EXPECT_LE(offset.cwiseAbs().maxCoeff(), jitter * kDx * (1.0 + 1e-12)) << i;
    largest = std::max(largest, offset.cwiseAbs().maxCoeff());
    EXPECT_EQ(first.position[i], again.position[i]) << i;
  }
  // 375 uniform components all below half the bound would have probability 2^-375.
  EXPECT_GT(largest, 0.5 * jitter * kDx);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) moved += first.position[i] != other.position[i] ? 1 : 0;
  EXPECT_EQ(moved, plain.size()) << "another seed must give other offsets";
}

TEST(SceneBuilder, RestLatticeIsAtRestDensityAndParticlesCarryTheirCellsMass) {
  // delta0 is the kernel sum of a particle inside the lattice. Recompute it from the built
  // particles: the centre of a 9-cell cube sees its full support (h = 2 dx) inside the cube.
  json b = body("fluid", box({9 * kDx, 9 * kDx, 9 * kDx}));
  b["rest_density"] = 997.0;
  const ParticleSetup setup = build_particles(scene_of({{"water", b}}));
  const SpikyKernel w(setup.smoothing_length);
  const Vector3d centre = Vector3d::Zero();
  double delta = 0.0;
  for (const Vector3d& x : setup.position) delta += w((x - centre).norm());
  // Both sums add the same non-zero terms in different orders: 1e-12 relative covers rounding.
  EXPECT_NEAR(setup.rest_number_density / delta, 1.0, 1e-12);
  // Each particle stands for its lattice cell: m = rho0 dx^3, so the body weighs rho0 V.
  for (const double m : setup.mass) EXPECT_DOUBLE_EQ(m, 997.0 * kDx * kDx * kDx);
}

TEST(SceneBuilder, RigidMassIsDensityTimesTheSampledVolume) {
  const ParticleSetup setup =
      build_particles(scene_of({{"ball", body("rigid", {{"type", "sphere"}, {"radius", 0.1}})}}));
  const BodySetup& ball = setup.bodies[0];
  EXPECT_DOUBLE_EQ(ball.mass, 500.0 * static_cast<double>(ball.count) * kDx * kDx * kDx);
}

TEST(SceneBuilder, SampledBoxInertiaIsTheAnalyticBoxInertia) {
  // For cell-centred particles each carrying its own cube's inertia, the sum over n cells of
  // ((i - (n - 1) / 2) dx)^2 plus n dx^2 / 12 is exactly (n dx)^2 n / 12: the sampled inertia
  // equals M (b^2 + c^2) / 12 for edges that are multiples of dx. Only rounding separates them,
  // hence 1e-12 relative; the rotation must not change the body-frame inertia.
  const Vector3d size(0.12, 0.08, 0.04);
  const double s = std::sqrt(0.5);
  for (const bool turned : {false, true}) {
    SCOPED_TRACE(turned ? "rotated" : "unrotated");
    json b = body("rigid", box(size), {0.2, 0.1, 0.3});
    if (turned) b["orientation"] = {s, 0.0, 0.0, s};
    const ParticleSetup setup = build_particles(scene_of({{"block", b}}));
    const BodySetup& block = setup.bodies[0];
    const double mass = 500.0 * size.prod();
    EXPECT_NEAR(block.mass / mass, 1.0, 1e-12);
    EXPECT_LT((block.centre_of_mass - Vector3d(0.2, 0.1, 0.3)).norm(), kPositionTolerance);
    const Vector3d analytic(mass / 12 * (size.y() * size.y() + size.z() * size.z()),
                            mass / 12 * (size.x() * size.x() + size.z() * size.z()),
                            mass / 12 * (size.x() * size.x() + size.y() * size.y()));
    const double scale = analytic.maxCoeff();
    EXPECT_LT((block.inertia_body - Matrix3d(analytic.asDiagonal())).cwiseAbs().maxCoeff(), 1e-12 * scale)
        << block.inertia_body;
  }
}

TEST(SceneBuilder, InitialVelocitiesFollowEachKind) {
  json fluid = body("fluid", box({0.06, 0.06, 0.06}));
  fluid["velocity"] = {1.0, 0.0, 0.0};
  json spinning = body("rigid", box({0.06, 0.06, 0.06}), {0.5, 0.0, 0.0});
  spinning["velocity"] = {0.0, 0.0, 2.0};
  spinning["angular_velocity"] = {0.0, 0.0, 3.0};
  json anchored = body("rigid", box({0.06, 0.06, 0.06}), {1.0, 0.0, 0.0});
  anchored["fixed"] = true;
  anchored["velocity"] = {5.0, 0.0, 0.0};
  const ParticleSetup setup =
      build_particles(scene_of({{"a_fluid", fluid},
                                {"b_spinning", spinning},
                                {"c_anchored", anchored},
                                {"d_wall", body("boundary", box({0.06, 0.06, 0.06}), {1.5, 0, 0})}}));
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const Vector3d& x = setup.position[i];
    Vector3d expected = Vector3d::Zero();  // fixed rigid bodies and boundaries do not move
    if (setup.body[i] == 0) expected = {1.0, 0.0, 0.0};
    if (setup.body[i] == 1) expected = Vector3d(0.0, 0.0, 2.0) + Vector3d(0.0, 0.0, 3.0).cross(x - Vector3d(0.5, 0, 0));
    EXPECT_LT((setup.velocity[i] - expected).norm(), 1e-12) << "particle " << i << " of body " << setup.body[i];
  }
  EXPECT_TRUE(setup.bodies[2].fixed);
  EXPECT_TRUE(setup.bodies[2].is_static());
  EXPECT_TRUE(setup.bodies[1].moves_as_rigid_body());
}

TEST(SceneBuilder, FixedRegionsHoldTheParticlesInsideThem) {
  // A 5 x 5 x 5 block at the origin; the region takes its bottom layer (z = -0.04) only.
  json block = body("deformable", box({0.1, 0.1, 0.1}));
  block["velocity"] = {0.0, 0.0, -1.0};
  block["fixed_regions"] = json::array({json{{"min", {-1.0, -1.0, -0.05}}, {"max", {1.0, 1.0, -0.03}}}});
  const ParticleSetup setup = build_particles(scene_of({{"block", block}}));
  EXPECT_EQ(setup.bodies[0].fixed_count, 25u);
  std::size_t flagged = 0;
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const bool bottom = setup.position[i].z() < -0.03;
    EXPECT_EQ(setup.fixed[i], bottom ? 1 : 0) << i;
    EXPECT_EQ(setup.velocity[i], bottom ? Vector3d::Zero() : Vector3d(0.0, 0.0, -1.0)) << i;
    flagged += setup.fixed[i];
  }
  EXPECT_EQ(flagged, 25u);
}

TEST(SceneBuilder, RejectsAnEmptyBodyByName) {
  // 0.009 m is under half the 0.02 m spacing: no layer of particles.
  const Scene scene = scene_of({{"sheet", body("boundary", box({0.5, 0.5, 0.009}))}});
  const std::string message = input_error_of([&] { build_particles(scene); });
  EXPECT_THAT(message, StartsWith("builder_test.json: /bodies/sheet/shape: the shape holds no particle"));
  EXPECT_THAT(message, HasSubstr("make it larger or the spacing smaller"));
}

TEST(SceneBuilder, RejectsOverlappingBodiesNamingFileKeyAndBoth) {
  const Scene scene = scene_of({{"left", body("fluid", box({0.1, 0.1, 0.1}))},
                                {"right", body("rigid", box({0.1, 0.1, 0.1}), {0.05, 0.0, 0.0})}});
  EXPECT_THAT(input_error_of([&] { build_particles(scene); }),
              StartsWith("builder_test.json: /bodies/right/position: bodies \"left\" and \"right\" overlap near"));
}

TEST(SceneBuilder, RejectsABodyInsideAnotherWhateverTheirLatticesOffset) {
  // A ball inside a block, its lattice shifted by half a spacing on every axis: no particle pair
  // is closer than 0.87 dx, yet the volumes coincide.
  const double shift = 0.5 * kDx;
  json ball = body("rigid", {{"type", "sphere"}, {"radius", 0.05}}, {shift, shift, shift});
  const Scene scene = scene_of({{"block", body("deformable", box({0.3, 0.3, 0.3}))}, {"ball", ball}});
  EXPECT_THAT(input_error_of([&] { build_particles(scene); }), HasSubstr("bodies \"ball\" and \"block\" overlap"));
  // Rotated by 45 degrees about z, the block still holds it.
  json turned = body("deformable", box({0.3, 0.3, 0.3}));
  turned["orientation"] = {0.0, 0.0, std::sin(std::numbers::pi / 8), std::cos(std::numbers::pi / 8)};
  EXPECT_THROW(build_particles(scene_of({{"block", turned}, {"ball", ball}})), InputError);
}

// Many particle pairs overlap; the error names the one a single thread meets first, whatever the
// number of threads that search.
TEST(SceneBuilder, TheOverlapReportedIsTheSameWhateverTheThreadCount) {
  json ball = body("rigid", {{"type", "sphere"}, {"radius", 0.05}}, {0.5 * kDx, 0.5 * kDx, 0.5 * kDx});
  const Scene scene = scene_of({{"block", body("deformable", box({0.3, 0.3, 0.3}))}, {"ball", ball}});
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::string one = input_error_of([&] { build_particles(scene); });
  omp_set_num_threads(3);
  const std::string three = input_error_of([&] { build_particles(scene); });
  omp_set_num_threads(threads);
  EXPECT_THAT(one, HasSubstr("overlap near"));
  EXPECT_EQ(three, one);
}

TEST(SceneBuilder, OverlapMeansCloserThanHalfASpacing) {
  // Two boxes side by side along x whose facing particle layers are `gap` apart.
  const auto with_gap = [](double gap) {
    const double offset = 0.1 - kDx + gap;  // 0.1 m boxes: outer layers at +-0.04 m
    return scene_of(
        {{"a", body("fluid", box({0.1, 0.1, 0.1}))}, {"b", body("fluid", box({0.1, 0.1, 0.1}), {offset, 0, 0})}});
  };
  EXPECT_NO_THROW(build_particles(with_gap(kDx)));  // one lattice continued: touching, not overlapping
  EXPECT_NO_THROW(build_particles(with_gap(0.55 * kDx)));
  EXPECT_THROW(build_particles(with_gap(0.45 * kDx)), InputError);
}

// A fluid that fills around bodies leaves out exactly its sites closer than one spacing to another
// body's (here a ball whose lattice is offset by 0.27 spacings, so that no pair is exactly one
// spacing apart), keeps every other site where it was, and the scene then builds; without the key
// the same scene overlaps.
TEST(SceneBuilder, FluidFillingAroundABodyLeavesOutTheSitesWithinASpacing) {
  const double shift = 0.27 * kDx;
  const json ball = body("rigid", {{"type", "sphere"}, {"radius", 0.05}}, {shift, shift, shift});
  json water = body("fluid", box({0.3, 0.3, 0.3}));
  EXPECT_THAT(input_error_of([&] {
                build_particles(scene_of({{"water", water}, {"ball", ball}}));
              }),
              HasSubstr("overlap"));

  const ParticleSetup alone = build_particles(scene_of({{"water", water}}));
  const ParticleSetup ball_alone = build_particles(scene_of({{"ball", ball}}));
  water["fill_around_bodies"] = true;
  const ParticleSetup filled = build_particles(scene_of({{"water", water}, {"ball", ball}}));
  const std::vector<Vector3d> ball_sites = positions_of(ball_alone, ball_alone.bodies[0]);
  // Bodies come in the order of their names: "ball", then "water".
  ASSERT_EQ(filled.bodies[1].name, "water");
  const std::vector<Vector3d> kept = positions_of(filled, filled.bodies[1]);
  std::size_t expected_kept = 0;
  for (const Vector3d& x : positions_of(alone, alone.bodies[0])) {
    const bool near =
        std::any_of(ball_sites.begin(), ball_sites.end(), [&](const Vector3d& y) { return (x - y).norm() < kDx; });
    if (!near) {
      ++expected_kept;
      EXPECT_TRUE(std::find(kept.begin(), kept.end(), x) != kept.end()) << "a clear site was left out";
    }
  }
  EXPECT_EQ(kept.size(), expected_kept);
  EXPECT_LT(kept.size(), alone.bodies[0].count);
  for (const Vector3d& x : kept) {
    for (const Vector3d& y : ball_sites) ASSERT_GE((x - y).norm(), kDx);
  }
  EXPECT_EQ(filled.bodies[0].count, ball_alone.bodies[0].count);
}

// A sphere centred on a site of the fluid's lattice (a box of 15 cells a side centred on the
// origin has its sites at multiples of dx, as a sphere centred there has) is sampled on the
// fluid's own lattice: the fluid sites exactly one spacing from its particles stay, so the fluid
// meets it at one spacing, as inside the fluid.
TEST(SceneBuilder, FluidFillingAroundABodyOnItsLatticeKeepsTheSitesOneSpacingAway) {
  const json ball = body("rigid", {{"type", "sphere"}, {"radius", 0.05}});
  json water = body("fluid", box({0.3, 0.3, 0.3}));
  const ParticleSetup alone = build_particles(scene_of({{"water", water}}));
  water["fill_around_bodies"] = true;
  const ParticleSetup filled = build_particles(scene_of({{"water", water}, {"ball", ball}}));
  ASSERT_EQ(filled.bodies[1].name, "water");
  const std::vector<Vector3d> ball_sites = positions_of(filled, filled.bodies[0]);
  const auto sites_one_spacing_away = [&](const std::vector<Vector3d>& sites) {
    std::size_t count = 0;
    for (const Vector3d& x : sites) {
      double nearest = 1e9;
      for (const Vector3d& y : ball_sites) nearest = std::min(nearest, (x - y).norm());
      if (std::abs(nearest - kDx) < 1e-6 * kDx) ++count;
    }
    return count;
  };
  const std::size_t on_the_lattice = sites_one_spacing_away(positions_of(alone, alone.bodies[0]));
  ASSERT_GT(on_the_lattice, 0u);
  EXPECT_EQ(sites_one_spacing_away(positions_of(filled, filled.bodies[1])), on_the_lattice);
}

TEST(SceneBuilder, FillAroundBodiesIsAFluidKey) {
  json block = body("rigid", box({0.1, 0.1, 0.1}));
  block["fill_around_bodies"] = true;
  EXPECT_THAT(input_error_of([&] {
                scene_of({{"block", block}});
              }),
              HasSubstr("/bodies/block/fill_around_bodies: applies to fluid bodies only"));
}

}  // namespace
}  // namespace mssph
