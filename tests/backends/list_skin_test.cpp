// The neighbour lists with a skin (kernels/common/list_skin.hpp), the cpu backend's and the GPU
// teams' (recorded on the host): recorded once, they must give every particle the same neighbours
// as a fresh search for as long as no particle has moved past its body's trigger, and a trigger
// must fire before a pair can come within the support unlisted.
#include "common/list_skin.hpp"
#include "common/fluid_physics.hpp"
#include "neighbour_list_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

constexpr std::uint32_t kCapacity = 64;  // holds every list of these tests (asserted)

// What a density or force sum of s must take where the particles stand now, found by testing every
// particle, no grid, no list: the particles within h, but the own body of one taken at rest.
std::vector<std::uint32_t> neighbours_by_brute_force(const kernels::SortedView& v, std::uint32_t s) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t t = 0; t < v.step.particle_count; ++t) {
    if (!own_body_at_rest(v, s, t) && within_support(v, s, t)) out.push_back(t);
  }
  return out;
}

// The entries of s's lists (all its lanes) within h where the particles stand now: what the
// passes of a step that keeps the lists sum over.
std::vector<std::uint32_t> neighbours_from_lists(const kernels::SortedView& v, const TeamLists& team, std::uint32_t s) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t lane = 0; lane < team.lanes; ++lane) {
    const std::uint32_t list = team.list_of(s, lane);
    EXPECT_LT(team.count[list], team.lists.capacity) << "particle " << s << ": the test needs the list itself";
    for (const std::uint32_t t : team.entries(list)) {
      if (within_support(v, s, t)) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The cpu backend's lists: one row per particle (record_neighbours) within record_radius2, but a
// deformable particle's own body.
struct HostLists {
  std::vector<std::uint32_t> count, index;
  kernels::NeighbourLists lists;

  HostLists(const kernels::SortedView& v, float record_radius2)
      : count(v.step.particle_count), index(std::size_t{v.step.particle_count} * kCapacity) {
    lists = kernels::particle_lists(kCapacity, count.data(), index.data());
    for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
      kernels::record_neighbours(v, lists, s, record_radius2, kernels::body_left_out(v, v.position[s]));
    }
  }
};

// The entries of s's row within h where the particles stand now, but its own deformable body's
// (its density sum skips them, its force sum adds nothing for them): what the cpu backend's passes
// of a step that keeps the lists take.
std::vector<std::uint32_t> neighbours_from_lists(const kernels::SortedView& v, const HostLists& host, std::uint32_t s) {
  EXPECT_LT(host.count[s], kCapacity) << "particle " << s << ": the test needs the list itself";
  std::vector<std::uint32_t> out;
  for (std::uint32_t k = 0; k < host.count[s] && k < kCapacity; ++k) {
    const std::uint32_t t = host.index[std::size_t{s} * kCapacity + k];
    if (!own_body_at_rest(v, s, t) && within_support(v, s, t)) out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Whether some particle stands farther from where it was recorded than its body's trigger.
bool some_trigger_fired(const kernels::SortedView& v, const std::vector<Vec3>& recorded,
                        const std::vector<float>& triggers2) {
  for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
    const Vec4 p = v.position[s];
    if (kernels::moved_past_trigger(kernels::xyz(p), recorded[s], triggers2[kernels::body_of(p)])) return true;
  }
  return false;
}

Vec3 random_direction(std::mt19937_64& random) {
  std::normal_distribution<float> normal;
  const Vec3 d{normal(random), normal(random), normal(random)};
  return d * (1.0f / std::sqrt(kernels::squared_norm(d)));
}

// Every particle moves by just under its body's trigger, in a random direction; the lists recorded
// before must still hold every particle's neighbours, among them pairs that were beyond h when
// recorded. lanes = 1: the cpu backend's lists; 2, 4, 8: a GPU team's.
TEST(ListSkin, ListsHoldEveryNeighbourWhileNoParticleMovedPastItsTrigger) {
  for (const std::uint32_t lanes : {1u, 2u, 4u, 8u}) {
    SCOPED_TRACE(::testing::Message() << lanes << " lanes");
    std::mt19937_64 random(1967 + lanes);
    JitteredLattice lattice(random, compressed_by_up_to_4_percent(random),
                            static_cast<float>(kernels::list_cell_size(1.0)));
    const kernels::SortedView v = lattice.view();  // views the lattice's positions, which move below
    const kernels::ListSkin skin = kernels::list_skin(v.step.smoothing.h);
    const std::vector<float> triggers2 = kernels::list_triggers2(lattice.bodies(), skin);
    std::unique_ptr<HostLists> host;
    std::unique_ptr<TeamLists> team;
    if (lanes == 1) {
      host = std::make_unique<HostLists>(v, skin.record_radius2);
    } else {
      team = std::make_unique<TeamLists>(v, lanes, kCapacity, skin.record_radius2);
    }
    const auto listed = [&](std::uint32_t s) {
      return host ? neighbours_from_lists(v, *host, s) : neighbours_from_lists(v, *team, s);
    };

    std::vector<Vec3> recorded(lattice.size());
    std::vector<std::vector<std::uint32_t>> neighbours_then(lattice.size());
    for (std::uint32_t s = 0; s < lattice.size(); ++s) {
      recorded[s] = kernels::xyz(v.position[s]);
      neighbours_then[s] = neighbours_by_brute_force(v, s);
    }
    std::uniform_real_distribution<float> fraction(0.9f, 1.0f);
    for (std::uint32_t s = 0; s < lattice.size(); ++s) {
      const float trigger = std::sqrt(triggers2[kernels::body_of(v.position[s])]);
      lattice.move(s, random_direction(random) * (0.999f * fraction(random) * trigger));
    }

    ASSERT_FALSE(some_trigger_fired(v, recorded, triggers2));
    std::size_t entered_the_support = 0;
    for (std::uint32_t s = 0; s < lattice.size(); ++s) {
      const std::vector<std::uint32_t> now = neighbours_by_brute_force(v, s);
      ASSERT_EQ(listed(s), now) << "particle " << s;
      for (const std::uint32_t t : now) {
        entered_the_support += std::binary_search(neighbours_then[s].begin(), neighbours_then[s].end(), t) ? 0 : 1;
      }
    }
    // Not vacuous: the moves brought pairs within h that were beyond it when the lists were recorded.
    EXPECT_GT(entered_the_support, 100u);
  }
}

// The cpu backend's density pass on a step that keeps the lists (density_sum_keeping_within): after
// every particle has moved by just under half the skin (the lattice's triggers), it copies out of
// each recorded row exactly the entries within h, in the row's order, and its sum has the bits of
// the sum over that copy, the one the force pass reads.
TEST(ListSkin, TheHostsDensitySumCopiesExactlyTheEntriesWithinTheSupport) {
  std::mt19937_64 random(2011);
  JitteredLattice lattice(random, compressed_by_up_to_4_percent(random),
                          static_cast<float>(kernels::list_cell_size(1.0)));
  const kernels::SortedView v = lattice.view();
  const kernels::ListSkin skin = kernels::list_skin(v.step.smoothing.h);
  const HostLists host(v, skin.record_radius2);
  for (std::uint32_t s = 0; s < lattice.size(); ++s) {
    lattice.move(s, random_direction(random) * (0.999f * 0.5f * skin.closing));
  }
  std::vector<std::uint32_t> count(lattice.size()), index(std::size_t{lattice.size()} * kCapacity);
  const kernels::NeighbourLists within = kernels::particle_lists(kCapacity, count.data(), index.data());
  std::size_t dropped = 0;
  for (std::uint32_t s = 0; s < lattice.size(); ++s) {
    const kernels::DensitySum fused = kernels::density_sum_keeping_within(v, host.lists, within, s);
    ASSERT_LT(host.count[s], kCapacity) << "particle " << s << ": the test needs the list itself";
    std::vector<std::uint32_t> expected;  // the recorded row's entries within h now, in its order
    for (std::uint32_t k = 0; k < host.count[s]; ++k) {
      const std::uint32_t t = host.index[std::size_t{s} * kCapacity + k];
      if (within_support(v, s, t)) expected.push_back(t);
    }
    dropped += host.count[s] - expected.size();
    const std::vector<std::uint32_t> kept(index.begin() + std::ptrdiff_t{s} * kCapacity,
                                          index.begin() + std::ptrdiff_t{s} * kCapacity + count[s]);
    ASSERT_EQ(kept, expected) << "particle " << s;
    std::vector<std::uint32_t> as_set = kept;
    std::sort(as_set.begin(), as_set.end());
    ASSERT_EQ(as_set, neighbours_by_brute_force(v, s)) << "particle " << s;
    const kernels::DensitySum over_copy = kernels::density_sum_over(v, s, kernels::neighbours_of(v, within, s));
    ASSERT_TRUE(same_bits(fused.delta, over_copy.delta)) << "particle " << s;
  }
  // Not vacuous: the rows held entries beyond h, which the copy left out.
  EXPECT_GT(dropped, std::size_t{lattice.size()});
}

// The walls and the lattice's fluid, made a second wall, rest while its block, rigid (movable) or
// deformable, moves as one towards them by just under the whole skin: the triggers let it (the
// only body that moves never lists its own particles), and the lists still give every particle
// its neighbours, among them pairs the move brought within h.
TEST(ListSkin, AToolMovingOverARestingSceneKeepsTheListsForAWholeSkin) {
  for (const std::uint32_t block_kind : {kernels::kRigid, kernels::kDeformable}) {
    for (const std::uint32_t lanes : {1u, 2u}) {
      SCOPED_TRACE(::testing::Message() << "block kind " << block_kind << ", " << lanes << " lanes");
      std::mt19937_64 random(2011 + lanes + block_kind);
      JitteredLattice lattice(random, compressed_by_up_to_4_percent(random),
                              static_cast<float>(kernels::list_cell_size(1.0)), block_kind);
      lattice.body_parameters(kFluidBody).kind = kernels::kBoundary;  // the resting scene
      lattice.body_parameters(kDeformableBody).rigid_index = block_kind == kernels::kRigid ? 0 : kernels::kNotRigid;
      const kernels::SortedView v = lattice.view();
      const kernels::ListSkin skin = kernels::list_skin(v.step.smoothing.h);
      const std::vector<float> triggers2 = kernels::list_triggers2(lattice.bodies(), skin);
      ASSERT_EQ(triggers2, (std::vector<float>{0.0f, 0.0f, skin.closing * skin.closing}));
      const HostLists host(v, skin.record_radius2);
      const TeamLists team(v, lanes, kCapacity, skin.record_radius2);
      std::vector<Vec3> recorded(lattice.size());
      for (std::uint32_t s = 0; s < lattice.size(); ++s) recorded[s] = kernels::xyz(v.position[s]);

      // The block holds the sites with x above the middle: towards the rest is -x.
      const Vec3 move = Vec3{-0.999f * skin.closing, 0.0f, 0.0f};
      for (std::uint32_t s = 0; s < lattice.size(); ++s) {
        if (kernels::body_of(v.position[s]) == kDeformableBody) lattice.move(s, move);
      }
      ASSERT_FALSE(some_trigger_fired(v, recorded, triggers2));
      std::size_t entered_the_support = 0;
      for (std::uint32_t s = 0; s < lattice.size(); ++s) {
        const std::vector<std::uint32_t> now = neighbours_by_brute_force(v, s);
        ASSERT_EQ(lanes == 1 ? neighbours_from_lists(v, host, s) : neighbours_from_lists(v, team, s), now)
            << "particle " << s;
        for (const std::uint32_t t : now) {
          entered_the_support += kernels::squared_norm(recorded[s] - recorded[t]) >= v.step.smoothing.h2 ? 1 : 0;
        }
      }
      EXPECT_GT(entered_the_support, 100u) << "not vacuous: the block's move brought pairs within h";
    }
  }
}

// A scene of the test below: the bodies of its two particles.
struct TwoBodies {
  kernels::BodyParameters a, b;
  bool one_body;  // a and b are one body (its parameters a's)
};

// Two particles just beyond the recording radius h + skin: unlisted. Each moving towards the other
// by just under its body's trigger (a resting body's is zero), they stay beyond h, so the lists
// are still right; closer by a little more than the skin, they come within h, unlisted, and a
// trigger must have fired. Four scenes: two particles of one fluid (half the skin each); a moving
// rigid tool and a wall (the tool the whole skin); a moving tool and a fluid, and two moving
// tools (half each). A fluid taken for a body that does not list itself fails the first scene;
// every moving body given the whole skin fails the first, the third and the fourth.
TEST(ListSkin, ATriggerFiresBeforeAPairComesWithinTheSupportUnlisted) {
  const float h = 0.04f;
  const kernels::ListSkin skin = kernels::list_skin(h);
  const float skin_width = kernels::kSkinOverSupport * h;
  const Vec3 a{0.1f, 0.1f, 0.1f};
  const Vec3 b = a + Vec3{h + 1.002f * skin_width, 0, 0};
  const Vec3 towards_b{1, 0, 0};
  const kernels::BodyParameters fluid{kernels::kFluid, kernels::kNotRigid, 0, 1000, 100, 1.0f, 0};
  const kernels::BodyParameters wall{kernels::kBoundary, kernels::kNotRigid, 0, 1000, 100, 0.0f, 0};
  const kernels::BodyParameters tool{kernels::kRigid, 0, 0, 1000, 100, 1.0f, 0};
  const kernels::BodyParameters other_tool{kernels::kRigid, 1, 0, 1000, 100, 1.0f, 0};
  for (const TwoBodies& scene : {TwoBodies{fluid, fluid, true}, TwoBodies{tool, wall, false},
                                 TwoBodies{tool, fluid, false}, TwoBodies{tool, other_tool, false}}) {
    SCOPED_TRACE(::testing::Message() << "kinds " << scene.a.kind << " and " << scene.b.kind);
    const std::vector<kernels::BodyParameters> bodies =
        scene.one_body ? std::vector<kernels::BodyParameters>{scene.a} : std::vector{scene.a, scene.b};
    const std::vector<float> triggers2 = kernels::list_triggers2(bodies, skin);
    const std::uint32_t body_b = scene.one_body ? 0 : 1;
    kernels::GridShape shape;
    shape.inverse_cell_size = static_cast<float>(1.0 / kernels::list_cell_size(h));
    SortedParticles sorted = sort_into_grid({kernels::make_vec4(a, kernels::index_as_float_bits(0)),
                                             kernels::make_vec4(b, kernels::index_as_float_bits(body_b))},
                                            shape);
    kernels::SortedView v{};
    v.step.smoothing = kernels::SmoothingKernels::for_support(h);
    v.step.particle_count = 2;
    v.bodies = bodies.data();
    v.grid = sorted.grid();
    v.position = sorted.position.data();
    const TeamLists team(v, 2, kCapacity, skin.record_radius2);
    const HostLists host(v, skin.record_radius2);
    const std::uint32_t s_a = kernels::xyz(sorted.position[0]).x == a.x ? 0 : 1, s_b = 1 - s_a;
    std::vector<Vec3> recorded(2);
    recorded[s_a] = a;
    recorded[s_b] = b;
    const auto lists_hold_the_pair = [&](const auto& lists) {
      const std::vector<std::uint32_t> listed = neighbours_from_lists(v, lists, s_a);
      return std::find(listed.begin(), listed.end(), s_b) != listed.end();
    };
    ASSERT_FALSE(lists_hold_the_pair(team) || lists_hold_the_pair(host)) << "b is not listed";

    const float trigger_a = std::sqrt(triggers2[0]), trigger_b = std::sqrt(triggers2[body_b]);
    const auto place = [&](float by_a, float by_b) {
      sorted.position[s_a] = kernels::make_vec4(a + towards_b * by_a, sorted.position[s_a].w);
      sorted.position[s_b] = kernels::make_vec4(b - towards_b * by_b, sorted.position[s_b].w);
    };
    place(0.999f * trigger_a, 0.999f * trigger_b);
    EXPECT_FALSE(some_trigger_fired(v, recorded, triggers2));
    EXPECT_FALSE(within_support(v, s_a, s_b)) << "within their triggers the pair stays beyond h";

    const float closer = 1.01f * skin_width / (trigger_a + trigger_b);  // the skin in proportion to the triggers
    place(closer * trigger_a, closer * trigger_b);
    EXPECT_TRUE(within_support(v, s_a, s_b)) << "closer by more than the skin, the pair comes within h";
    EXPECT_FALSE(lists_hold_the_pair(team)) << "and the lists miss it";
    EXPECT_FALSE(lists_hold_the_pair(host)) << "and the host's too";
    EXPECT_TRUE(some_trigger_fired(v, recorded, triggers2));
  }
}

}  // namespace
}  // namespace mssph::testing
