// The cuda backend's device arrays come from one list (kernels/cuda/device_arrays.hpp) that both
// allocates them and counts their bytes for the memory check and cuda_backend_bytes; its chunk
// tables cut bodies for the fixed-order reductions. Both are host code: checked here without a GPU
// (and without a CUDA build).
#include "backend_fixtures.hpp"
#include "cuda/device_arrays.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace mssph::testing {
namespace {

using kernels::ArraySize;
using kernels::ChunkTables;
using kernels::DeviceArrays;
using kernels::FloatScene;
using kernels::kChunk;

struct ListedArray {
  std::string name;
  std::size_t bytes;
};

template <class T>
std::size_t element_bytes(const ArraySize<T>&) {
  return sizeof(T);
}

// Every array the list visits, with its bytes, in the list's order.
std::vector<ListedArray> listed_arrays(const FloatScene& scene, const ChunkTables& chunks, std::size_t grid_blocks,
                                       unsigned team_lanes) {
  DeviceArrays<ArraySize> arrays;
  std::vector<ListedArray> listed;
  kernels::for_each_device_array(arrays, scene, chunks, grid_blocks, team_lanes,
                                 [&](const char* name, auto& array, const auto& contents) {
                                   listed.push_back({name, element_bytes(array) * contents.count});
                                 });
  return listed;
}

std::size_t bytes_of(const std::vector<ListedArray>& listed, const std::string& name) {
  for (const ListedArray& a : listed) {
    if (a.name == name) return a.bytes;
  }
  ADD_FAILURE() << "no device array " << name;
  return 0;
}

std::size_t chunks_of(std::size_t particles) { return (particles + kChunk - 1) / kChunk; }

// The deformable scene has every kind of array: fluid-free, but an elastic block, a rigid sphere
// and a boundary.
struct DeviceArraysTest : ::testing::Test {
  ParticleSetup setup = coarse_scene("sphere_drop_deformable.json", 0.01);
  FloatScene scene = kernels::make_float_scene(setup);
  ChunkTables chunks = kernels::make_chunk_tables(scene, setup.bodies);
  static constexpr std::size_t kGridBlocks = 264;  // stands in for grid_kernel_blocks (needs a device)
  static constexpr unsigned kTeamLanes = 4;        // stands in for choose_team_lanes' (needs a device)
};

TEST_F(DeviceArraysTest, CountedBytesAreTheSumOfTheListedArrays) {
  const std::vector<ListedArray> listed = listed_arrays(scene, chunks, kGridBlocks, kTeamLanes);
  std::size_t sum = 0;
  for (const ListedArray& a : listed) sum += a.bytes;
  EXPECT_EQ(kernels::device_array_sizes(scene, chunks, kGridBlocks, kTeamLanes).total_bytes, sum);
  EXPECT_EQ(bytes_of(listed, "block_total"), kGridBlocks * sizeof(std::uint32_t));
}

// An array declared in DeviceArrays but allocated outside the list would escape the count: every
// member must be listed once. All ArraySize<T> are one std::size_t, so the members are counted by
// size.
TEST_F(DeviceArraysTest, EveryDeclaredArrayIsListedOnce) {
  static_assert(sizeof(ArraySize<kernels::Mat3>) == sizeof(std::size_t) &&
                sizeof(ArraySize<char>) == sizeof(std::size_t));
  constexpr std::size_t declared = sizeof(DeviceArrays<ArraySize>) / sizeof(std::size_t);
  ASSERT_FALSE(scene.deformable_body.empty());
  ASSERT_FALSE(scene.rigid_bodies.empty());
  const std::vector<ListedArray> listed = listed_arrays(scene, chunks, kGridBlocks, kTeamLanes);
  std::set<std::string> names;
  for (const ListedArray& a : listed) names.insert(a.name);
  EXPECT_EQ(names.size(), listed.size()) << "an array is listed twice";
  EXPECT_EQ(listed.size(), declared);
}

// The sizes follow from the scene alone: n particles, the grid's cells, deformable particles and
// their bonds, chunks of at most kChunk particles (a rigid body's: rigid_chunk_size).
TEST_F(DeviceArraysTest, ArraysHaveTheScenesSizes) {
  const std::size_t n = setup.size();
  const std::size_t cells = scene.grid.cell_count();
  const std::size_t deformables = scene.deformable_body.size();
  std::size_t rigid_chunks = 0;
  std::size_t body_chunks = 0;
  std::size_t rigid_bodies = 0;
  std::size_t deformable_particles = 0;
  std::size_t rigid_particles = 0;
  for (const BodySetup& body : setup.bodies) {
    body_chunks += chunks_of(body.count);
    if (body.moves_as_rigid_body()) {
      const std::size_t chunk = kernels::rigid_chunk_size(static_cast<std::uint32_t>(body.count));
      rigid_chunks += (body.count + chunk - 1) / chunk;
      ++rigid_bodies;
    }
    if (body.kind == BodyKind::deformable) deformable_particles += body.count;
    if (body.kind == BodyKind::rigid) rigid_particles += body.count;
  }
  ASSERT_EQ(deformables, deformable_particles);
  const std::vector<ListedArray> listed = listed_arrays(scene, chunks, kGridBlocks, kTeamLanes);
  EXPECT_EQ(bytes_of(listed, "position"), n * 16);
  ASSERT_GT(rigid_bodies, 0u);
  EXPECT_EQ(bytes_of(listed, "rest_offset"), n * 16);
  EXPECT_EQ(bytes_of(listed, "sorted_id"), n * 4);
  EXPECT_EQ(bytes_of(listed, "force_walk"), n);
  EXPECT_EQ(bytes_of(listed, "contact_order"), 0u);
  EXPECT_EQ(bytes_of(listed, "cell_start"), (cells + 1) * 4);
  EXPECT_EQ(bytes_of(listed, "cell_middle"), (cells + 1) * 4);
  EXPECT_EQ(bytes_of(listed, "elastic_force"), n * 16);
  EXPECT_EQ(bytes_of(listed, "own_rest_number_density"), n * 4);
  EXPECT_EQ(bytes_of(listed, "cell_body"), (cells + 1) * 2);
  EXPECT_EQ(bytes_of(listed, "rotation"), deformables * sizeof(kernels::Quat));
  EXPECT_EQ(bytes_of(listed, "bond_count"), deformables * 4);
  EXPECT_EQ(bytes_of(listed, "bond_neighbour"), scene.bond_neighbour.size() * 4);
  EXPECT_EQ(bytes_of(listed, "rest"), deformables * 16);
  // One lane a particle keeps no lists but a contact order with places for a quarter of the rigid
  // and deformable particles (contact_order.hpp).
  ASSERT_GT(rigid_particles, 0u);
  const std::vector<ListedArray> one_lane = listed_arrays(scene, chunks, kGridBlocks, 1);
  EXPECT_EQ(bytes_of(one_lane, "contact_order"), (rigid_particles + deformables + 3) / 4 * 4);
  EXPECT_EQ(bytes_of(one_lane, "contact_taken"), 4u);
  EXPECT_EQ(bytes_of(one_lane, "force_walk"), n);
  EXPECT_EQ(bytes_of(one_lane, "list_count"), 0u);
  EXPECT_EQ(bytes_of(listed, "list_count"), n * kTeamLanes * 4);
  EXPECT_EQ(bytes_of(listed, "list_index"), n * kTeamLanes * kernels::team_list_capacity(kTeamLanes) * 4);
  // With lists, the next step's cell-ordered copy and, with rigid bodies, each particle's place
  // (next_cell_order.cuh); one lane copies at every rebuild instead.
  EXPECT_EQ(bytes_of(listed, "next_sorted_position"), n * 16);
  EXPECT_EQ(bytes_of(listed, "next_sorted_velocity"), n * 16);
  EXPECT_EQ(bytes_of(listed, "place_of"), n * 4);
  EXPECT_EQ(bytes_of(one_lane, "next_sorted_position"), 0u);
  EXPECT_EQ(bytes_of(one_lane, "place_of"), 0u);
  EXPECT_EQ(bytes_of(listed, "correction"), deformables * sizeof(kernels::Mat3));
  EXPECT_EQ(bytes_of(listed, "corrected_stress_action"), 9 * deformables * sizeof(float));
  EXPECT_EQ(bytes_of(listed, "rigid_bodies"), rigid_bodies * sizeof(kernels::RigidBody));
  EXPECT_EQ(bytes_of(listed, "rigid_chunks"), rigid_chunks * sizeof(kernels::RigidChunk));
  EXPECT_EQ(bytes_of(listed, "chunk_wrench"), rigid_chunks * sizeof(kernels::Wrench));
  EXPECT_EQ(bytes_of(listed, "body_chunks"), body_chunks * sizeof(kernels::BodyChunk));
}

// The count changes exactly by the arrays a scene adds: the same scene without its deformable
// data loses the deformable arrays' bytes, summed here by hand from their element types; without
// its own-body densities at rest (a scene of fluid alone), it loses those
// and the cells' bodies (CellRanges::cell_body).
TEST_F(DeviceArraysTest, DeformableAndRestDensityArraysAddExactlyTheirBytes) {
  FloatScene without = scene;
  without.elastic_bodies.clear();
  without.deformable_body.clear();
  without.bond_count.clear();
  without.bond_neighbour.clear();
  without.rest.clear();
  without.correction.clear();
  const std::size_t n = setup.size();
  const std::size_t d = scene.deformable_body.size();
  const std::size_t deformable_bytes =
      n * sizeof(kernels::Vec4) +                                                    // elastic_force
      scene.elastic_bodies.size() * sizeof(kernels::ElasticParameters) +             // elastic_bodies
      d * (sizeof(std::uint32_t) + sizeof(kernels::Vec4) + sizeof(kernels::Quat)) +  // deformable_body, rest, rotation
      d * 2 * sizeof(kernels::Mat3) +                                                // correction, deformation
      9 * d * sizeof(float) +                               // corrected_stress_action (nine planes)
      d * sizeof(std::uint32_t) +                           // bond_count
      scene.bond_neighbour.size() * sizeof(std::uint32_t);  // bond_neighbour
  EXPECT_EQ(kernels::device_array_sizes(scene, chunks, kGridBlocks, kTeamLanes).total_bytes -
                kernels::device_array_sizes(without, chunks, kGridBlocks, kTeamLanes).total_bytes,
            deformable_bytes);
  FloatScene without_rest_densities = without;
  without_rest_densities.own_rest_number_density.clear();
  const std::size_t cell_table = std::size_t{scene.grid.cell_count()} + 1;
  EXPECT_EQ(kernels::device_array_sizes(without, chunks, kGridBlocks, kTeamLanes).total_bytes -
                kernels::device_array_sizes(without_rest_densities, chunks, kGridBlocks, kTeamLanes).total_bytes,
            n * sizeof(float) + cell_table * sizeof(std::uint16_t));
}

// Rest offsets place the particles of movable rigid bodies: a scene without one (here the same
// scene with its rigid sphere taken out of the rigid-body list) holds none: 16 bytes per particle
// less, 4 more with lists (place_of, for the rigid placement's cell-ordered writes), and the
// body's record and ticket.
TEST_F(DeviceArraysTest, OnlyScenesWithRigidBodiesHoldRestOffsets) {
  FloatScene without = scene;
  without.rigid_bodies.clear();
  EXPECT_EQ(bytes_of(listed_arrays(without, chunks, kGridBlocks, kTeamLanes), "rest_offset"), 0u);
  EXPECT_EQ(kernels::device_array_sizes(scene, chunks, kGridBlocks, kTeamLanes).total_bytes -
                kernels::device_array_sizes(without, chunks, kGridBlocks, kTeamLanes).total_bytes,
            setup.size() * (sizeof(kernels::Vec4) + sizeof(std::uint32_t)) +
                scene.rigid_bodies.size() * (sizeof(kernels::RigidBody) + sizeof(std::uint32_t)));
}

// Only a team keeps neighbour lists: one lane per particle (large scenes) spends no bytes on them,
// and every team size has lists of at least two entries (a list holds capacity - 1 neighbours),
// each particle's position at the rebuild (16 bytes), the next step's cell-ordered copy (32) and
// its place in cell order (4: the scene has a rigid body), each body's trigger and one refresh
// state (list_skin.hpp, next_cell_order.cuh). The scene's cells are those of a team's (h + skin).
TEST_F(DeviceArraysTest, OnlyTeamsKeepNeighbourLists) {
  const FloatScene listing = kernels::make_float_scene_with_list_cells(setup);
  const std::size_t n = setup.size();
  const std::vector<ListedArray> listed = listed_arrays(listing, chunks, kGridBlocks, 1);
  // Less the contact order, which teams do not keep.
  const std::size_t one_lane = kernels::device_array_sizes(listing, chunks, kGridBlocks, 1).total_bytes -
                               bytes_of(listed, "contact_order") - bytes_of(listed, "contact_taken");
  for (const char* name : {"list_count", "list_index", "list_origin", "list_trigger2", "list_refresh",
                           "next_sorted_position", "next_sorted_velocity", "place_of"}) {
    EXPECT_EQ(bytes_of(listed, name), 0u) << name;
  }
  ASSERT_EQ(listing.list_trigger2.size(), setup.bodies.size());
  for (const unsigned lanes : {2u, 4u, 8u}) {
    SCOPED_TRACE(::testing::Message() << lanes << " lanes");
    const std::uint32_t capacity = kernels::team_list_capacity(lanes);
    EXPECT_GE(capacity, 2u);
    EXPECT_EQ(kernels::device_array_sizes(listing, chunks, kGridBlocks, lanes).total_bytes - one_lane,
              n * lanes * (1 + capacity) * sizeof(std::uint32_t) + 3 * n * sizeof(kernels::Vec4) +
                  n * sizeof(std::uint32_t) + setup.bodies.size() * sizeof(float) + sizeof(kernels::ListRefreshState));
  }
}

// Synthetic bodies: a rigid body of 2 kChunk + 5 particles and a deformable one of 3 particles
// behind a fluid of 10. The rigid body's chunks are of rigid_chunk_size: one stride of kBlock
// particles at this size.
TEST(ChunkTables, ChunksCoverEachBodyInOrderWithAtMostKChunkParticles) {
  FloatScene scene;
  kernels::RigidBody rigid{};
  rigid.first = 10;
  rigid.count = 2 * kChunk + 5;
  scene.rigid_bodies = {rigid};
  kernels::ElasticParameters elastic{};
  elastic.first_particle = 10 + rigid.count;
  elastic.first_deformable = 0;
  elastic.lowest_valid_volume_ratio = 0.25f;
  scene.elastic_bodies = {elastic};
  std::vector<BodySetup> bodies(3);
  bodies[0].kind = BodyKind::fluid;
  bodies[0].count = 10;
  bodies[1].kind = BodyKind::rigid;
  bodies[1].first = 10;
  bodies[1].count = rigid.count;
  bodies[2].kind = BodyKind::deformable;
  bodies[2].first = elastic.first_particle;
  bodies[2].count = 3;

  const ChunkTables tables = kernels::make_chunk_tables(scene, bodies);
  const std::uint32_t stride = kernels::kBlock;
  ASSERT_EQ(kernels::rigid_chunk_size(rigid.count), stride);
  const std::uint32_t full_chunks = rigid.count / stride;  // and one of the 5 left over
  ASSERT_EQ(tables.rigid.size(), full_chunks + 1);
  EXPECT_EQ(tables.first_rigid_chunk, (std::vector<std::uint32_t>{0, full_chunks + 1}));
  EXPECT_EQ(tables.rigid_chunk_strides, 1u);
  std::uint32_t next = 10;
  for (std::size_t c = 0; c < tables.rigid.size(); ++c) {
    EXPECT_EQ(tables.rigid[c].rigid, 0u);
    EXPECT_EQ(tables.rigid[c].first, next);
    EXPECT_EQ(tables.rigid[c].count, c < full_chunks ? stride : 5u);
    next += tables.rigid[c].count;
  }
  // Body chunks: the fluid's one, the rigid body's three, the deformable body's one (which knows
  // its deformable index and its model's limit).
  ASSERT_EQ(tables.body.size(), 5u);
  EXPECT_EQ(tables.body[0].body, 0u);
  EXPECT_EQ(tables.body[0].first_deformable, kernels::kNotDeformable);
  EXPECT_EQ(tables.body[3].first, 10 + kChunk * 2);
  EXPECT_EQ(tables.body[4].body, 2u);
  EXPECT_EQ(tables.body[4].first, elastic.first_particle);
  EXPECT_EQ(tables.body[4].first_deformable, 0u);
  EXPECT_EQ(tables.body[4].lowest_valid_volume_ratio, 0.25f);
}

// A rigid body's chunk: whole strides of kBlock particles, at most kChunk; a body of at least
// kRigidChunksPerBody strides is spread over at least kRigidChunksPerBody blocks unless its chunks
// are already kChunk long, and a longer chunk would leave it fewer.
TEST(ChunkTables, RigidChunksSpreadABodyOverEnoughBlocks) {
  const std::uint32_t stride = kernels::kBlock;
  for (const std::uint32_t particles : {1u, 255u, 256u, 30000u, 65535u, 65536u, 100000u, 370000u, 1000000u, 5000000u}) {
    const std::uint32_t chunk = kernels::rigid_chunk_size(particles);
    const std::uint32_t chunks = (particles + chunk - 1) / chunk;
    EXPECT_EQ(chunk % stride, 0u) << particles;
    EXPECT_GE(chunk, stride) << particles;
    EXPECT_LE(chunk, kChunk) << particles;
    if (particles >= stride * kernels::kRigidChunksPerBody && chunk < kChunk) {
      EXPECT_GE(chunks, kernels::kRigidChunksPerBody) << particles;
      EXPECT_LT(particles / (chunk + stride), kernels::kRigidChunksPerBody) << particles;
    }
  }
  EXPECT_EQ(kernels::rigid_chunk_size(30000), stride);
  EXPECT_EQ(kernels::rigid_chunk_size(1000000), kChunk);
}

}  // namespace
}  // namespace mssph::testing
