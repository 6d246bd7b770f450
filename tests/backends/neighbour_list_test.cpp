// The host's neighbour lists (kernels/common/neighbour_list.hpp): a particle's list must hold
// exactly the particles within the support h, in the grid walk's order, and the density and force
// sums over it must be the grid walk's sums bit for bit, which is what lets the cpu backend use
// them without changing a result. Checked on a jittered, compressed lattice of three bodies
// (walls, fluid, a deformable block whose own neighbours the density sum skips) in a grid small
// enough to wrap, so periodic images share cells with real neighbours.
#include "common/fluid_physics.hpp"
#include "common/neighbour_list.hpp"
#include "sorted_particles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::Vec3;
using kernels::Vec4;

constexpr std::uint32_t kWallBody = 0, kFluidBody = 1, kDeformableBody = 2;

// 12 x 12 x 12 lattice sites, spacing dx compressed by up to 4 %, jittered by 0.1 dx: the lowest
// two layers are wall, the sites with x above the middle deformable, the rest fluid. Cells of side
// h = 2 dx, 4 per axis: the lattice spans 6 cells, so the grid wraps.
class JitteredLattice {
 public:
  explicit JitteredLattice(std::mt19937_64& random) {
    const float dx = 0.02f * std::uniform_real_distribution<float>(0.96f, 1.0f)(random);
    std::uniform_real_distribution<float> jitter(-0.1f * dx, 0.1f * dx);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<Vec4> particles;
    const int sites = 12;
    for (int i = 0; i < sites; ++i) {
      for (int j = 0; j < sites; ++j) {
        for (int k = 0; k < sites; ++k) {
          const std::uint32_t body = k < 2 ? kWallBody : (i >= sites / 2 ? kDeformableBody : kFluidBody);
          const Vec3 site{static_cast<float>(i) * dx, static_cast<float>(j) * dx, static_cast<float>(k) * dx};
          particles.push_back(kernels::make_vec4(site + Vec3{jitter(random), jitter(random), jitter(random)},
                                                 kernels::index_as_float_bits(body)));
        }
      }
    }
    kernels::GridShape shape;
    shape.inverse_cell_size = 1.0f / (2.0f * dx);
    sorted_ = sort_into_grid(particles, shape);
    for (std::size_t s = 0; s < particles.size(); ++s) {
      velocity_.push_back(Vec4{unit(random), unit(random), unit(random), 0.0f});
      volume_pressure_.push_back({dx * dx * dx * (1.0f + 0.1f * unit(random)), 1000.0f * (1.0f + unit(random))});
    }
    bodies_ = {{kernels::kBoundary, kernels::kNotRigid, 0, 1000, 100, 0.0f},
               {kernels::kFluid, kernels::kNotRigid, 0, 1000, 100, 1.0f},
               {kernels::kDeformable, kernels::kNotRigid, 0, 1000, 100, 2.0f}};
    step_.smoothing = kernels::SmoothingKernels::for_support(2.0 * dx);
    step_.inverse_gradient_consistency = 1.0f;
    step_.particle_count = static_cast<std::uint32_t>(particles.size());
  }

  kernels::SortedView view() const {
    kernels::SortedView v{};
    v.step = step_;
    v.bodies = bodies_.data();
    v.grid = sorted_.grid();
    v.position = sorted_.position.data();
    v.velocity = velocity_.data();
    v.volume_pressure = volume_pressure_.data();
    return v;
  }
  std::uint32_t size() const { return step_.particle_count; }

 private:
  SortedParticles sorted_;
  std::vector<Vec4> velocity_;
  std::vector<kernels::VolumePressure> volume_pressure_;
  std::vector<kernels::BodyParameters> bodies_;
  kernels::StepParameters step_{};
};

// Lists of `capacity` entries for every particle of the view.
struct Lists {
  std::vector<std::uint32_t> count, index;
  kernels::NeighbourLists lists;

  Lists(const kernels::SortedView& v, std::uint32_t capacity)
      : count(v.step.particle_count), index(std::size_t{v.step.particle_count} * capacity) {
    lists = {capacity, count.data(), index.data()};
    for (std::uint32_t s = 0; s < v.step.particle_count; ++s) kernels::record_neighbours(v, lists, s);
  }
};

std::vector<std::uint32_t> visited(const kernels::SortedView& v, const kernels::NeighbourLists& lists, std::uint32_t s) {
  std::vector<std::uint32_t> out;
  kernels::for_each_neighbour(v, lists, s, [&](std::uint32_t t) { out.push_back(t); });
  return out;
}

bool within_support(const kernels::SortedView& v, std::uint32_t s, std::uint32_t t) {
  return kernels::squared_norm(kernels::xyz(v.position[s]) - kernels::xyz(v.position[t])) < v.step.smoothing.h2;
}

// The grid walk's candidates within the support, in its order.
std::vector<std::uint32_t> walk_within_support(const kernels::SortedView& v, std::uint32_t s) {
  std::vector<std::uint32_t> out;
  v.grid.for_each_candidate(kernels::xyz(v.position[s]), [&](std::uint32_t t) {
    if (within_support(v, s, t)) out.push_back(t);
  });
  return out;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(Vec3 a, Vec3 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z); }

TEST(NeighbourLists, HoldExactlyTheParticlesWithinTheSupportInTheWalksOrder) {
  std::mt19937_64 random(20110319);
  const JitteredLattice lattice(random);
  const kernels::SortedView v = lattice.view();
  const Lists lists(v, 64);
  std::uint32_t most = 0;
  for (std::uint32_t s = 0; s < lattice.size(); ++s) {
    const std::vector<std::uint32_t> list = visited(v, lists.lists, s);
    ASSERT_LT(lists.count[s], 64u) << "particle " << s << " overflowed: the test needs the list itself";
    most = std::max(most, lists.count[s]);
    // Independent of the grid: every particle tested against every other.
    std::vector<std::uint32_t> brute_force;
    for (std::uint32_t t = 0; t < lattice.size(); ++t) {
      if (within_support(v, s, t)) brute_force.push_back(t);
    }
    std::vector<std::uint32_t> as_set = list;
    std::sort(as_set.begin(), as_set.end());
    ASSERT_EQ(as_set, brute_force) << "particle " << s;
    ASSERT_EQ(list, walk_within_support(v, s)) << "particle " << s;
  }
  // h = 2 dx holds ~30 neighbours; compression and jitter push some above the lattice's 27.
  EXPECT_GT(most, 27u);
}

TEST(NeighbourLists, SumsOverTheListAreTheGridWalksBits) {
  std::mt19937_64 random(7);
  const JitteredLattice lattice(random);
  const kernels::SortedView v = lattice.view();
  const Lists lists(v, 64);
  int deformable_with_foreign_neighbours = 0;
  for (std::uint32_t s = 0; s < lattice.size(); ++s) {
    const kernels::DensitySum walked = kernels::density_sum(v, s, 0, 1);
    const kernels::DensitySum listed = kernels::density_sum_over(v, s, kernels::neighbours_of(v, lists.lists, s));
    ASSERT_TRUE(same_bits(walked.delta, listed.delta)) << "particle " << s << ": " << walked.delta << " vs " << listed.delta;
    const kernels::ForceParticle i = kernels::load_force_particle(v, s);
    const kernels::ForceSum walked_force = kernels::force_sum(v, i, 0, 1);
    const kernels::ForceSum listed_force = kernels::force_sum_over(v, i, kernels::neighbours_of(v, lists.lists, s));
    ASSERT_TRUE(same_bits(walked_force.pressure, listed_force.pressure)) << "particle " << s;
    ASSERT_TRUE(same_bits(walked_force.viscosity, listed_force.viscosity)) << "particle " << s;
    ASSERT_TRUE(same_bits(walked_force.interaction, listed_force.interaction)) << "particle " << s;
    ASSERT_EQ(walked_force.boundary_neighbours, listed_force.boundary_neighbours) << "particle " << s;
    if (i.body == kDeformableBody && !same_bits(walked_force.interaction, Vec3{0, 0, 0})) ++deformable_with_foreign_neighbours;
  }
  // The deformable block meets the fluid and the walls: its particles' sums take the body tests.
  EXPECT_GT(deformable_with_foreign_neighbours, 100);
}

// A list holds capacity - 1 neighbours (its last entry takes every candidate once the list is
// full); a particle with capacity or more walks the grid, and both give the walk's sums.
TEST(NeighbourLists, AFullListFallsBackToTheGridWalk) {
  std::mt19937_64 random(11);
  const JitteredLattice lattice(random);
  const kernels::SortedView v = lattice.view();
  const Lists wide(v, 64);
  const std::uint32_t s = lattice.size() / 2;
  const std::uint32_t neighbours = wide.count[s];
  std::uint32_t candidates = 0;
  v.grid.for_each_candidate(kernels::xyz(v.position[s]), [&](std::uint32_t) { ++candidates; });
  ASSERT_GT(candidates, neighbours);

  const Lists just_enough(v, neighbours + 1);
  EXPECT_EQ(visited(v, just_enough.lists, s), walk_within_support(v, s));

  const Lists too_small(v, neighbours);
  EXPECT_EQ(too_small.count[s], neighbours);
  EXPECT_EQ(visited(v, too_small.lists, s).size(), candidates) << "an overflowed list walks every candidate";
  const float walked = kernels::density_sum(v, s, 0, 1).delta;
  EXPECT_TRUE(same_bits(walked, kernels::density_sum_over(v, s, kernels::neighbours_of(v, too_small.lists, s)).delta));
  EXPECT_TRUE(same_bits(walked, kernels::density_sum_over(v, s, kernels::neighbours_of(v, just_enough.lists, s)).delta));
}

}  // namespace
}  // namespace mssph::testing
