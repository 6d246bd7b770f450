// The density walk's cell checks as the GPU's warps share them (kernels/cuda/warp_cell_checks.cuh,
// cells_left_out_by_warp) give every particle the mask its own one-lane checks give
// (kernels/common/fluid_physics.hpp, cells_left_out), whatever the warp's lanes hold: particles of
// one cell and one body, of several cells, of several bodies (fluid ones among them, which check
// nothing), teams of lanes on one particle, and a last warp that is not full.
#include "common/fluid_physics.hpp"
#include "cuda/device_buffer.hpp"
#include "cuda/warp_cell_checks.cuh"
#include "sorted_particles.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace mssph::testing {
namespace {

// Both masks of particle thread / lanes, as the density kernel's threads take their particles.
__global__ void cell_masks_kernel(kernels::SortedView v, std::uint32_t count, std::uint32_t lanes,
                                  std::uint32_t* by_warp, std::uint32_t* by_lane) {
  const std::uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  const std::uint32_t s = thread / lanes;
  if (s >= count) return;
  by_warp[thread] = kernels::cells_left_out_by_warp(v, s, kernels::body_left_out(v, v.position[s]));
  by_lane[thread] = kernels::cells_left_out(v, s);
}

// A block of 2 particles a cell along each axis over cells 2 to 11 of a 16^3 grid of 1 m cells:
// rigid body 1 below x = 7 m, deformable body 2 above it, every 11th particle rigid body 3 and
// every 17th fluid (body 0); sorted and noted as the GPU's grid sorts and notes them.
SortedParticles mixed_block() {
  std::vector<kernels::Vec4> particles;
  std::uint32_t k = 0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 20; ++j) {
      for (int l = 0; l < 20; ++l, ++k) {
        const float x = 2.25f + 0.5f * static_cast<float>(i);
        const std::uint32_t body = k % 17 == 0 ? 0u : k % 11 == 0 ? 3u : x < 7.0f ? 1u : 2u;
        particles.push_back({x, 2.25f + 0.5f * static_cast<float>(j), 2.25f + 0.5f * static_cast<float>(l),
                             kernels::index_as_float_bits(body)});
      }
    }
  }
  particles.pop_back();  // 7999 particles: the last warp is not full
  SortedParticles sorted = sort_into_half_cells(particles, metre_cells(4, 4, 4));
  sorted.note_cell_bodies(kernels::kMixedCell);
  return sorted;
}

TEST(CudaCellsLeftOut, AWarpsSharedChecksGiveEachParticleItsOwnMask) {
  int devices = 0;
  if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0) GTEST_SKIP() << "no CUDA device";
  const SortedParticles sorted = mixed_block();
  const auto count = static_cast<std::uint32_t>(sorted.position.size());
  const std::vector<kernels::BodyParameters> bodies = {{kernels::kFluid, kernels::kNotRigid, 1, 1000, 1, 0, 0},
                                                       {kernels::kRigid, 0, 1, 1000, 1, 0, 0},
                                                       {kernels::kDeformable, kernels::kNotRigid, 1, 1000, 1, 0, 0},
                                                       {kernels::kRigid, 1, 1, 1000, 1, 0, 0}};
  const kernels::DeviceBuffer<kernels::Vec4> position(sorted.position);
  const kernels::DeviceBuffer<kernels::BodyParameters> body_parameters(bodies);
  const kernels::DeviceBuffer<std::uint32_t> cell_start(sorted.cell_start), cell_middle(sorted.cell_middle);
  const kernels::DeviceBuffer<std::uint16_t> cell_body(sorted.cell_body);
  kernels::SortedView v{};
  v.bodies = body_parameters.data();
  v.position = position.data();
  v.grid = kernels::CellRanges{sorted.shape, cell_start.data(), cell_body.data(), cell_middle.data()};

  for (const std::uint32_t lanes : {1u, 2u, 8u}) {
    SCOPED_TRACE(::testing::Message() << lanes << " lanes a particle");
    const std::uint32_t threads = count * lanes;
    kernels::DeviceBuffer<std::uint32_t> by_warp(threads), by_lane(threads);
    cell_masks_kernel<<<(threads + 127) / 128, 128>>>(v, count, lanes, by_warp.data(), by_lane.data());
    ASSERT_EQ(cudaDeviceSynchronize(), cudaSuccess);
    const std::vector<std::uint32_t> shared = by_warp.download(), own = by_lane.download();
    std::size_t left_out = 0;
    for (std::uint32_t t = 0; t < threads; ++t) {
      ASSERT_EQ(shared[t], own[t]) << "thread " << t << ", particle " << t / lanes;
      left_out += own[t] != 0 ? 1 : 0;
    }
    // Not vacuous: most rigid and deformable particles leave out cells; fluid ones none.
    EXPECT_GT(left_out, threads / 2);
    EXPECT_LT(left_out, threads);
  }
}

}  // namespace
}  // namespace mssph::testing
