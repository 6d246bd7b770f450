#pragma once
// The chunk tables of the `cuda` backend's per-body reductions, built on the host (no CUDA here,
// so they are tested without a GPU). A body of a million particles is summed by many blocks, one
// per chunk of at most kChunk particles; every sum runs in a fixed order (strided per thread,
// CUB's block tree, then the chunks in a fixed order): no atomics, so runs repeat bit for bit.
#include "../common/float_scene.hpp"
#include "thread_blocks.cuh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mssph::kernels {

inline constexpr std::uint32_t kChunk = 4096;

// A movable rigid body's chunks (rigid_bodies.cu) hold a whole number of strides of a block's
// kBlock threads: as many as leave the body at least kRigidChunksPerBody chunks (one stride when
// it is smaller), at most kChunk particles. A 30k-particle body is summed by 118 blocks, a thread
// per particle, rather than by 8 chunks of kChunk that take each thread through 16 particles in
// turn; a 1M-particle body keeps chunks of kChunk, whose fewer partial wrenches add up faster.
inline constexpr std::uint32_t kRigidChunksPerBody = 128;

inline std::uint32_t rigid_chunk_size(std::uint32_t particles) {
  const std::uint32_t stride = kBlock;
  return std::clamp(particles / (stride * kRigidChunksPerBody), 1u, kChunk / stride) * stride;
}

// A run of at most rigid_chunk_size(body particles) of one movable rigid body: its interaction wrench.
struct RigidChunk {
  std::uint32_t rigid;  // index of the rigid body
  std::uint32_t first;  // canonical particle range
  std::uint32_t count;
};

inline constexpr std::uint32_t kNotDeformable = 0xffffffffu;

// A run of at most kChunk particles of one body (any kind), for the logged per-body sums.
struct BodyChunk {
  std::uint32_t body;
  std::uint32_t first;
  std::uint32_t count;
  std::uint32_t first_deformable;   // deformable index of particle `first`, else kNotDeformable
  float lowest_valid_volume_ratio;  // deformable bodies: the model's lowest valid det F
};

struct ChunkTables {
  std::vector<RigidChunk> rigid;
  std::vector<std::uint32_t> first_rigid_chunk;  // per rigid body, plus the end
  std::uint32_t rigid_chunk_strides = 0;         // the most strides of kBlock particles in one rigid chunk
  std::vector<BodyChunk> body;
};

inline ChunkTables make_chunk_tables(const FloatScene& scene, const std::vector<BodySetup>& bodies) {
  ChunkTables tables;
  for (std::uint32_t r = 0; r < scene.rigid_bodies.size(); ++r) {
    tables.first_rigid_chunk.push_back(static_cast<std::uint32_t>(tables.rigid.size()));
    const RigidBody& body = scene.rigid_bodies[r];
    const std::uint32_t chunk = rigid_chunk_size(body.count);
    tables.rigid_chunk_strides = std::max(tables.rigid_chunk_strides, chunk / std::uint32_t{kBlock});
    for (std::uint32_t first = body.first; first < body.first + body.count; first += chunk) {
      tables.rigid.push_back({r, first, std::min(chunk, body.first + body.count - first)});
    }
  }
  tables.first_rigid_chunk.push_back(static_cast<std::uint32_t>(tables.rigid.size()));
  for (std::uint32_t b = 0; b < bodies.size(); ++b) {
    const auto first = static_cast<std::uint32_t>(bodies[b].first);
    const auto end = first + static_cast<std::uint32_t>(bodies[b].count);
    const ElasticParameters* elastic = nullptr;
    for (const ElasticParameters& e : scene.elastic_bodies) {
      if (e.first_particle == first && bodies[b].kind == BodyKind::deformable) elastic = &e;
    }
    for (std::uint32_t f = first; f < end; f += kChunk) {
      tables.body.push_back({b, f, std::min(kChunk, end - f),
                             elastic ? elastic->first_deformable + (f - first) : kNotDeformable,
                             elastic ? elastic->lowest_valid_volume_ratio : 0.0f});
    }
  }
  return tables;
}

}  // namespace mssph::kernels
