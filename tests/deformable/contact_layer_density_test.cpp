// The density behind a deformable particle's pressure is its contact layer's
// (model/deformable_rest_state.hpp, reads_contact_layer_density): its own body's neighbours count
// at rest, the other bodies' live. So the body's own compression, which elasticity answers, does
// not raise its pressure (with the own body counted live it did, and that pressure pushed on a
// body held against it through a force no potential gives: results/decisions/005-contact-layer-density.md), while a
// body pressed against it still does. Both precisions: the reference, and the float32 cpu and cuda
// backends (cuda skipped without a CUDA build and a GPU).
#include "backend_factory/backend_factory.hpp"
#include "deformable_fixtures.hpp"
#include "framework/backends.hpp"
#include "model/lattice_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph::testing {
namespace {

constexpr double kDx = 0.04;       // [m]
constexpr double kEdge = 8 * kDx;  // a cube of 8 x 8 x 8 particles [m]
constexpr double kSqueeze = 0.9;   // positions scaled by 0.9 about the centre: J = 0.73

nlohmann::json cube_scene(bool with_second_cube, double gap_in_dx) {
  nlohmann::json doc = elastic_scene(kDx, 1e-4);
  const nlohmann::json material = elastic_material(1e5, 0.3);
  doc["bodies"]["lower"] = deformable_box({kEdge, kEdge, kEdge}, {0, 0, 0}, material);
  // The second cube's bottom layer lies gap_in_dx spacings above the lower cube's top layer.
  if (with_second_cube)
    doc["bodies"]["upper"] = deformable_box({kEdge, kEdge, kEdge}, {0, 0, kEdge - kDx + gap_in_dx * kDx}, material);
  return doc;
}

std::size_t body_named(const ParticleSetup& setup, const std::string& name) {
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == name) return b;
  }
  ADD_FAILURE() << "no body " << name;
  return 0;
}

class ContactLayerDensity : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    const std::string why = why_backend_cannot_run(GetParam());
    if (!why.empty()) GTEST_SKIP() << "backend " << GetParam() << " cannot run here: " << why;
  }
};

// Compressed uniformly to 73 % of its volume, an isolated cube's particles read the densities of
// its rest state; and a particle with a full rest neighbourhood reads rho0, the lattice
// calibration delta0 being the number density of a full rest lattice.
TEST_P(ContactLayerDensity, OwnCompressionDoesNotRaiseThePressure) {
  const ParticleSetup setup = build_particles(parse_scene(cube_scene(false, 0.0), "contact layer test scene"));
  const double rho0 = setup.bodies[0].material.rest_density;
  const double h = setup.smoothing_length;
  const std::unique_ptr<Backend> backend = make_backend(GetParam(), setup);
  const ForceEvaluation rest = backend->evaluate_forces();

  std::vector<Eigen::Vector3d> squeezed = setup.position;
  for (Eigen::Vector3d& x : squeezed) x *= kSqueeze;  // the cube is centred at the origin
  backend->set_particle_positions(squeezed);
  const ForceEvaluation compressed = backend->evaluate_forces();

  // Float32: the same float sum at both positions (no other body), so equal; 1e-6 relative covers
  // a different summation order.
  const double tolerance = GetParam() == "reference" ? 1e-12 : 1e-6;
  std::size_t full = 0;
  for (std::size_t i = 0; i < setup.size(); ++i) {
    EXPECT_NEAR(compressed.density[i] / rest.density[i], 1.0, tolerance) << "particle " << i;
    const Eigen::Vector3d x = setup.position[i];
    if (x.cwiseAbs().maxCoeff() + h <= 0.5 * kEdge) {
      ++full;
      // Float32: delta0 rounded to float, 1e-6 relative.
      EXPECT_NEAR(rest.density[i] / rho0, 1.0, GetParam() == "reference" ? 1e-9 : 1e-6) << "particle " << i;
    }
  }
  EXPECT_EQ(full, 64u);  // 4 x 4 x 4 particles lie h = 2 dx or more inside
}

// A second cube pressed onto the first, its bottom layer 0.75 dx above the first's top layer (a
// quarter spacing closer than the lattice continued): the first cube's top layer has the second's
// particles within h, so its density rises above its rest value, and where its lateral
// neighbourhood is full (h inside the sides) above rho0, the density of a full lattice, so its
// pressure pushes back: the contact is still carried. Its layers more than h below stay at rest.
TEST_P(ContactLayerDensity, ABodyPressedOnItRaisesItsSurfaceDensity) {
  const ParticleSetup setup = build_particles(parse_scene(cube_scene(true, 0.75), "contact layer test scene"));
  const std::size_t lower = body_named(setup, "lower");
  const ParticleSetup alone_setup = build_particles(parse_scene(cube_scene(false, 0.0), "contact layer test scene"));
  const ForceEvaluation pressed = make_backend(GetParam(), setup)->evaluate_forces();
  const ForceEvaluation alone = make_backend(GetParam(), alone_setup)->evaluate_forces();
  const BodySetup& body = setup.bodies[lower];
  const double top = 0.5 * kEdge - 0.5 * kDx;
  std::size_t top_layer = 0, full_lateral = 0;
  for (std::size_t k = 0; k < body.count; ++k) {
    const std::size_t i = body.first + k;
    const double z = setup.position[i].z();
    ASSERT_NEAR((setup.position[i] - alone_setup.position[k]).norm(), 0.0, 1e-12);  // the same lower cube
    if (std::abs(z - top) < 1e-9) {
      ++top_layer;
      // The nearest upper particle is 0.75 dx away, within h = 2 dx: W > 0 adds to the density.
      EXPECT_GT(pressed.density[i], alone.density[i] * (1.0 + 1e-3)) << "particle " << i;
      if (std::max(std::abs(setup.position[i].x()), std::abs(setup.position[i].y())) + setup.smoothing_length <=
          0.5 * kEdge) {
        ++full_lateral;
        EXPECT_GT(pressed.density[i], body.material.rest_density * (1.0 + 1e-3)) << "particle " << i;
        EXPECT_GT(pressed.pressure[i], 0.0) << "particle " << i;
      }
    } else if (z < top - 1.5 * kDx) {  // two layers down and more: the upper cube lies 2.75 dx or more away
      EXPECT_NEAR(pressed.density[i] / alone.density[i], 1.0, 1e-6) << "particle " << i;
    }
  }
  EXPECT_EQ(top_layer, 64u);
  EXPECT_EQ(full_lateral, 16u);
}

INSTANTIATE_TEST_SUITE_P(Backends, ContactLayerDensity, ::testing::ValuesIn(backend_names()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace mssph::testing
