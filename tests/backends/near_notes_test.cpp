// The near notes of the GPU's one-lane walks (kernels/common/near_notes.hpp): a fluid particle's
// density walk by segments notes which candidates lie within h, and its force walk takes those
// masks instead of testing the candidates again. Checked on the neighbour-list tests' lattice
// (walls, fluid, a deformable block; on a grid that wraps within it, walks of more segments than
// the notes hold): the density sums by segments have the bits of the plain walk's over every
// candidate, own body included; a boundary particle notes nothing (its notes' words are its
// canonical velocity in a step); the force sums over the notes have the bits of the walk that tests
// every candidate; and the force walk does take the notes: with them cleared it visits nothing in
// the segments they cover.
#include "common/near_notes.hpp"
#include "common/fluid_physics.hpp"
#include "neighbour_list_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace mssph::testing {
namespace {

// The notes' words before the walks: a boundary particle's must keep it.
const float kUnwritten = kernels::index_as_float_bits(0xdeadbeefu);

// The lattice on 2^grid_bits cells per axis, its particles given canonical indices in a shuffled
// order (as the GPU's cell order scatters them), and the words the notes are kept in, filled with
// kUnwritten.
struct NotedLattice {
  NotedLattice(std::mt19937_64& random, std::uint32_t grid_bits)
      : lattice(random, compressed_by_up_to_4_percent(random), 1.0f, kernels::kDeformable, grid_bits),
        id(lattice.size()),
        canonical_first(lattice.size(), Vec4{kUnwritten, kUnwritten, kUnwritten, kUnwritten}),
        canonical_second(canonical_first),
        sorted_eighth(lattice.size(), kUnwritten),
        sorted_ninth(sorted_eighth) {
    std::iota(id.begin(), id.end(), 0u);
    std::shuffle(id.begin(), id.end(), random);
  }
  kernels::SortedView view() const {
    kernels::SortedView v = lattice.view();
    v.id = id.data();
    return v;
  }
  kernels::NearNotes notes() {
    return {canonical_first.data(), canonical_second.data(), sorted_eighth.data(), sorted_ninth.data()};
  }
  // Whether particle s's words still hold kUnwritten.
  bool unwritten(std::uint32_t s) const {
    const std::uint32_t i = id[s];
    for (const Vec4& record : {canonical_first[i], canonical_second[i]}) {
      for (const float word : {record.x, record.y, record.z, record.w}) {
        if (!same_bits(word, kUnwritten)) return false;
      }
    }
    return same_bits(sorted_eighth[s], kUnwritten) && same_bits(sorted_ninth[s], kUnwritten);
  }

  JitteredLattice lattice;
  std::vector<std::uint32_t> id;
  std::vector<Vec4> canonical_first, canonical_second;
  std::vector<float> sorted_eighth, sorted_ninth;
};

const kernels::BodyParameters& body_of_particle(const kernels::SortedView& v, std::uint32_t s) {
  return v.bodies[kernels::body_of(v.position[s])];
}

// The plain walk's live density sum of sorted particle s over every candidate, its own body's
// included, as a walk by segments takes it.
float live_sum_over_every_candidate(const kernels::SortedView& v, std::uint32_t s) {
  kernels::DensitySum sum{0.0f, 0.0f};
  const Vec3 x = kernels::xyz(v.position[s]);
  kernels::grid_share(v, s, 0, 1, 0)([&](std::uint32_t t) { kernels::add_density_pair(sum, v, x, t); });
  return sum.delta;
}

// Whether sorted particle s's walk has more segments than the notes hold.
bool walks_past_notes(const kernels::SortedView& v, std::uint32_t s) {
  std::uint32_t segments = 0;
  v.grid.for_each_segment(kernels::xyz(v.position[s]), [&](std::uint32_t, int) { ++segments; });
  return segments > kernels::NearNotes::capacity;
}

// The density pass of the GPU's step with notes: fluid and boundary particles walk by segments
// (walks_with_fluid; the block's particles walk as before, noting nothing).
void take_notes(const kernels::SortedView& v, const kernels::NearNotes& notes) {
  for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
    if (!kernels::walks_with_fluid(body_of_particle(v, s))) continue;
    kernels::density_sum_noting_near(v, s, v.id[s], notes);
  }
}

// On the lattice's 4 cells per axis, which it spans one and a half times, every walk meets
// periodic images and many rows wrap: walks of more segments than the notes hold.
TEST(NearNotes, SumsOverTheNotesHaveTheBitsOfTheWalksThatTestEveryCandidate) {
  std::mt19937_64 random(20261128);
  NotedLattice noted(random, 2);
  const kernels::SortedView v = noted.view();
  const kernels::NearNotes notes = noted.notes();
  std::size_t boundary = 0, fluid_pushed = 0, walks_past = 0;
  // The density pass (take_notes), each sum checked as it is taken.
  for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
    SCOPED_TRACE(::testing::Message() << "particle " << s);
    const kernels::BodyParameters& body = body_of_particle(v, s);
    if (!kernels::walks_with_fluid(body)) continue;
    if (walks_past_notes(v, s)) ++walks_past;
    const kernels::DensitySum by_segments = kernels::density_sum_noting_near(v, s, v.id[s], notes);
    ASSERT_TRUE(same_bits(by_segments.delta, live_sum_over_every_candidate(v, s)));
    if (body.kind == kernels::kBoundary) {
      ++boundary;
      ASSERT_TRUE(noted.unwritten(s));
    } else {
      ASSERT_FALSE(noted.unwritten(s));
    }
  }
  for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
    SCOPED_TRACE(::testing::Message() << "particle " << s);
    const kernels::ForceParticle p = kernels::load_force_particle(v, s);
    kernels::HeldSegments<kernels::kHeldSegments> held;
    const kernels::ForceSum over_notes = kernels::force_sum(v, p, v.id[s], notes, held);
    const kernels::ForceSum walked = kernels::force_sum(v, p);
    ASSERT_TRUE(same_bits(over_notes.pressure, walked.pressure));
    ASSERT_TRUE(same_bits(over_notes.viscosity, walked.viscosity));
    ASSERT_TRUE(same_bits(over_notes.interaction, walked.interaction));
    ASSERT_TRUE(same_bits(over_notes.nearest_boundary2, walked.nearest_boundary2));
    if (p.parameters.kind == kernels::kFluid && kernels::squared_norm(walked.pressure) > 0.0f) ++fluid_pushed;
  }
  // Not vacuous: walls, fluid particles with forces, and walks whose last segments are tested.
  EXPECT_GT(boundary, 100u);
  EXPECT_GT(fluid_pushed, 100u);
  EXPECT_GT(walks_past, 0u);
}

// On 8 cells per axis, where most walks fit the notes.
TEST(NearNotes, TheForceWalkTakesTheNotesInsteadOfTestingTheirCandidates) {
  std::mt19937_64 random(20261128);
  NotedLattice noted(random, 3);
  const kernels::SortedView v = noted.view();
  const kernels::NearNotes notes = noted.notes();
  take_notes(v, notes);
  // Every note says "nothing near": a walk that takes them visits nothing in their segments.
  std::fill(noted.canonical_first.begin(), noted.canonical_first.end(), Vec4{0, 0, 0, 0});
  std::fill(noted.canonical_second.begin(), noted.canonical_second.end(), Vec4{0, 0, 0, 0});
  std::fill(noted.sorted_eighth.begin(), noted.sorted_eighth.end(), 0.0f);
  std::fill(noted.sorted_ninth.begin(), noted.sorted_ninth.end(), 0.0f);
  std::size_t fluid_within_notes = 0;
  for (std::uint32_t s = 0; s < v.step.particle_count; ++s) {
    SCOPED_TRACE(::testing::Message() << "particle " << s);
    const kernels::ForceParticle p = kernels::load_force_particle(v, s);
    if (p.parameters.kind != kernels::kFluid || walks_past_notes(v, s)) continue;
    ++fluid_within_notes;
    kernels::HeldSegments<kernels::kHeldSegments> held;
    const kernels::ForceSum over_notes = kernels::force_sum(v, p, v.id[s], notes, held);
    const kernels::ForceSum nothing = kernels::zero_force_sum();
    ASSERT_TRUE(same_bits(over_notes.pressure, nothing.pressure));
    ASSERT_TRUE(same_bits(over_notes.viscosity, nothing.viscosity));
    ASSERT_TRUE(same_bits(over_notes.nearest_boundary2, nothing.nearest_boundary2));
  }
  EXPECT_GT(fluid_within_notes, 100u);
}

}  // namespace
}  // namespace mssph::testing
