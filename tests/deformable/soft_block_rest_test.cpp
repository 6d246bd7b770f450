// A heavy sphere resting on a soft block: configs/sphere_drop_deformable.json with the block
// softened to E = 2.5e4 Pa (the soft end of the stiffness sweep, nu = 0.3), where the paper's
// St Venant-Kirchhoff block collapses under the sphere (densities ~2.1 rho0, the sphere hovering
// over a crushed surface). With the Neo-Hookean model the sphere must come to rest ON the block,
// at an indentation near Hertz's, with no particle past the model's valid range or denser than
// the contact can explain.
//
// Resolution: the CI spacing dx = 4 cm (h = 8 cm): the 20 cm sphere is 5 spacings in radius,
// the block 5 layers deep. The sphere starts one spacing above the block's surface, and the
// block is damped at 40 /s besides the scene's viscous modulus, so that the sphere's bounce on
// the block decays within the 0.6 s simulated; damping changes no equilibrium.
//
// Run on the float32 cpu backend (which follows the reference on this scene within 2 %,
// BackendAgreement.DeformableDropFollowsTheReference).
#include "../backends/backend_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace mssph {
namespace {

constexpr double kDx = 0.04;
constexpr double kYoung = 2.5e4;
constexpr double kPoisson = 0.3;
constexpr double kRadius = 0.2;       // sphere [m]
constexpr double kBlockTop = 0.2;     // the block's nominal top face [m]
constexpr double kDuration = 0.6;     // [s]
constexpr double kAverageFrom = 0.3;  // the sphere's rest height is its mean height from here on [s]

TEST(SoftBlockRest, NeoHookeanBlockCarriesTheSphereAtHertzIndentation) {
  ParticleSetup setup = testing::coarse_scene(
      "sphere_drop_deformable.json", kDuration,
      {"bodies/block/young_modulus=" + std::to_string(kYoung), "bodies/block/poisson_ratio=" + std::to_string(kPoisson),
       "bodies/block/model=neo_hookean", "bodies/block/damping=40", "bodies/sphere/position=[0, 0, 0.44]"});
  const std::size_t sphere = testing::find_body(setup, "sphere");
  const std::size_t block = testing::find_body(setup, "block");
  const double weight = setup.bodies[sphere].mass * setup.gravity.norm();
  const double rest_density = setup.bodies[block].material.rest_density;
  const BodySetup block_body = setup.bodies[block];
  const BodySetup sphere_body = setup.bodies[sphere];
  const auto total = static_cast<std::size_t>(std::llround(kDuration / setup.dt));
  const auto backend = make_backend("cpu", std::move(setup));

  double height_sum = 0.0;
  std::size_t height_samples = 0;
  double max_density = 0.0;  // over the whole run [kg/m^3]
  std::size_t past_valid_range = 0;
  for (std::size_t s = 1; s <= total; ++s) {
    backend->step();
    if (s % 40 != 0) continue;  // every 40 steps, 10 ms
    const std::vector<BodyState> states = backend->body_states();
    past_valid_range = std::max(past_valid_range, states[block].compressed_count);
    if (backend->time() >= kAverageFrom) {
      height_sum += states[sphere].centre_of_mass.z();
      ++height_samples;
    }
    const ParticleSnapshot snap = backend->snapshot();
    for (std::size_t i = block_body.first; i < block_body.first + block_body.count; ++i) {
      max_density = std::max(max_density, static_cast<double>(snap.density[i]));
    }
  }
  ASSERT_GT(height_samples, 20u);
  const double rest_height = height_sum / static_cast<double>(height_samples);

  // Where the sphere rests on the block: the gap between its lowest particle and the block's
  // particles right under it, at the end.
  const ParticleSnapshot snap = backend->snapshot();
  const auto z_of = [&](std::size_t i) { return static_cast<double>(snap.position[3 * i + 2]); };
  const auto near_axis = [&](std::size_t i) {
    return std::hypot(snap.position[3 * i], snap.position[3 * i + 1]) < 0.5 * kDx;
  };
  double sphere_bottom = 1e300, block_top = -1e300, final_density = 0.0;
  for (std::size_t i = block_body.first; i < block_body.first + block_body.count; ++i) {
    final_density = std::max(final_density, static_cast<double>(snap.density[i]));
  }
  for (std::size_t i = sphere_body.first; i < sphere_body.first + sphere_body.count; ++i) {
    if (near_axis(i)) sphere_bottom = std::min(sphere_bottom, z_of(i));
  }
  for (std::size_t i = block_body.first; i < block_body.first + block_body.count; ++i) {
    if (near_axis(i)) block_top = std::max(block_top, z_of(i));
  }

  // Hertz, rigid sphere on an elastic half-space: d = (3 W / (4 E* sqrt(R)))^(2/3),
  // E* = E / (1 - nu^2) (Johnson, Contact Mechanics, eq. 4.23). W, the weight of the sphere as
  // sampled at 4 cm (14.4 kg), gives d = 4.42 cm.
  const double e_star = kYoung / (1.0 - kPoisson * kPoisson);
  const double hertz = std::pow(3.0 * weight / (4.0 * e_star * std::sqrt(kRadius)), 2.0 / 3.0);
  // The sphere centre's sink below where a continuum sphere would touch the continuum block.
  const double indentation = kRadius + kBlockTop - rest_height;
  std::cout << "rest height " << rest_height << " m, indentation " << indentation << " m (Hertz " << hertz
            << " m), sphere bottom " << sphere_bottom << " m over block top " << block_top << " m (gap "
            << (sphere_bottom - block_top) / kDx << " dx), max block density " << final_density / rest_density
            << " rho0 at the end, " << max_density / rest_density << " rho0 over the run\n";

  // 30 %: at 4 cm the lattice sphere is no smooth sphere. Its lowest layer lies 4 cm above its
  // nominal bottom (its particles' cells reach 2 cm lower, so the sphere sits ~2 cm deeper than a
  // continuum one at the same contact), and that layer is a facet ~24 cm across: a flat punch,
  // stiffer than a sphere (hertz_contact_test.cpp). Both are offsets of order dx / 2 = 2 cm, in
  // opposite directions; the block is moreover a bonded 20 cm layer, not a half-space, which
  // stiffens it. At 1 cm the Hertz test gets within 25 %.
  //
  // The same run with model stvk (measured): the sphere sinks 6.1 cm (1.37 times Hertz), hovering
  // 1.8 dx over a surface crushed 8 cm down, det F down to -1.3, 1.76 rho0 at rest and 2.07 rho0
  // at the impact: it fails every check below.
  EXPECT_NEAR(indentation / hertz, 1.0, 0.3);
  // ON the block: SPH contact holds particle layers of two bodies about one spacing apart (their
  // cells touching). The collapsed stvk block left a gap of 1.8 dx.
  EXPECT_GT(sphere_bottom - block_top, 0.5 * kDx);
  EXPECT_LT(sphere_bottom - block_top, 1.3 * kDx);
  // The block's surface under the sphere is pushed down (its rest top layer is at 0.18 m).
  EXPECT_LT(block_top, kBlockTop - 0.5 * kDx - 0.002);
  // No particle past the Neo-Hookean model's valid range at any logged time.
  EXPECT_EQ(past_valid_range, 0u);
  // Density bound at the end (the sphere within ~1 cm of its rest height), 1.35 rho0: Hertz's
  // peak pressure p0 = 3 W / (2 pi a^2), a = sqrt(R d) = 9.4 cm, is 7.6 kPa; compressed that hard with its sides held
  // (the stiffest case, uniaxial strain), the material keeps J = 1 - p0 / (lambda + 2 mu) = 0.77 of its volume: rho0 /
  // J = 1.29 rho0. The collapsed block reached 2.1 rho0.
  EXPECT_LT(final_density, 1.35 * rest_density);
  // Over the whole run, the first impact and the swings that follow included (the sphere falls
  // one spacing onto the block and overshoots its rest indentation; measured 1.52 rho0, and
  // 1.38 rho0 from 0.3 s on), 1.6 rho0: this bound only separates the impact from a collapse
  // (2.1 rho0); it is set from the measurement, not from a formula.
  EXPECT_LT(max_density, 1.6 * rest_density);
}

}  // namespace
}  // namespace mssph
