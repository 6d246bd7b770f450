#pragma once
// The neighbour grid on the GPU: the cell table and the cell-ordered copies of the particles that
// the density and force sums walk (kernels/common/cell_grid.hpp). One cooperative kernel
// (neighbour_grid.cu).
#include "device_state.cuh"

#include <cstddef>
#include <cstdint>

namespace mssph::kernels {

// Blocks of the grid kernel for a scene: the size of its per-block array (block_total).
unsigned grid_kernel_blocks(std::size_t particles, std::uint32_t cells);

// Sorts the particles into the grid's cells from their canonical positions: cell_start,
// sorted_id and the cell-ordered positions and velocities. With the teams' lists, also where each
// particle stands, for the check below, and that this step's density pass records the lists.
void launch_neighbour_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream);

// With the teams' lists, a step's start: when the lists are no longer valid (list_skin.hpp),
// rebuilds the grid as launch_neighbour_grid does; while they hold, the step before has written
// the particles in cell order (next_cell_order.cuh). The decision is taken on the device.
void launch_list_step_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream);

// Copies the particles' canonical state into the last rebuild's cell order, for a step that keeps
// the lists after the host has replaced that state (a restart).
void launch_cell_order_copy(DeviceState& state, const GridShape& grid, cudaStream_t stream);

}  // namespace mssph::kernels
