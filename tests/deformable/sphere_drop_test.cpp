// The paper's Figure 3 deformable case, configs/sphere_drop_deformable.json at the CI spacing
// (dx = 4 cm): a 20 cm sphere of 500 kg/m^3 dropped from 5 cm onto an elastic block glued to the
// ground. The block must take the impact by compressing and push the sphere back up, and, being
// passive (elastic, damped by its viscous modulus), never return more energy than the drop gave it.
//
// Run on the float32 cpu backend, whose path on this very scene follows the reference within 2 %
// (BackendAgreement.DeformableDropFollowsTheReference): the reference would take minutes here.
#include "backend_factory/backend_factory.hpp"
#include "config/scene_loader.hpp"
#include "model/scene_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace mssph {
namespace {

TEST(SphereDrop, DeformableBlockIsCompressedAndPushesTheSphereBack) {
  const Scene scene = load_scene(std::string(MSSPH_SOURCE_DIR) + "/configs/sphere_drop_deformable.json",
                                 {"simulation/particle_spacing=0.04"});
  ParticleSetup setup = build_particles(scene);
  std::size_t sphere = 0, block = 0;
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    if (setup.bodies[b].name == "sphere") sphere = b;
    if (setup.bodies[b].name == "block") block = b;
  }
  const double weight = setup.bodies[sphere].mass * setup.gravity.norm();  // 16.8 kg * 9.81 m/s^2
  const auto backend = make_backend("cpu", std::move(setup));

  // 0.32 s: the first impact (contact from ~0.08 s) and the rebound that follows it.
  const std::size_t steps = static_cast<std::size_t>(0.32 / scene.simulation.dt);
  std::vector<double> sphere_z, block_z, sphere_vz;
  double peak_force = 0.0;
  for (std::size_t s = 0; s < steps; ++s) {
    backend->step();
    const std::vector<BodyState> states = backend->body_states();
    sphere_z.push_back(states[sphere].centre_of_mass.z());
    sphere_vz.push_back(states[sphere].linear_momentum.z() / states[sphere].mass);
    block_z.push_back(states[block].centre_of_mass.z());
    peak_force = std::max(peak_force, states[sphere].interaction_force.z());
  }
  const double drop_height = sphere_z.front();
  const auto lowest = std::min_element(sphere_z.begin(), sphere_z.end());
  const double highest_after = *std::max_element(lowest, sphere_z.end());
  const double block_dip = block_z.front() - *std::min_element(block_z.begin(), block_z.end());
  const double rising_speed = *std::max_element(sphere_vz.begin() + (lowest - sphere_z.begin()), sphere_vz.end());
  std::cout << "lowest sphere centre " << *lowest << " m, highest after " << highest_after << " m, block dip "
            << block_dip << " m, peak force " << peak_force << " N (weight " << weight << " N), rising speed "
            << rising_speed << " m/s\n";

  // Stopping a 1 m/s sphere within centimetres takes more than its weight.
  EXPECT_GT(peak_force, 2.0 * weight);
  // Compression: the block's centre of mass goes down under the impact, and the sphere sinks
  // below where it would rest on an undeformed surface layer, 5 cm below its release height.
  EXPECT_GT(block_dip, 5e-4);
  EXPECT_LT(*lowest, drop_height - 0.05);
  // Rebound: the block pushes the sphere back up, by more than 2 cm...
  EXPECT_GT(rising_speed, 0.1);
  EXPECT_GT(highest_after - *lowest, 0.02);
  // ...but no higher than it fell from: the block is passive.
  EXPECT_LT(highest_after, drop_height);
}

}  // namespace
}  // namespace mssph
