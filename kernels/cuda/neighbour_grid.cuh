#pragma once
// The neighbour grid on the GPU: the cell table and the cell-ordered copies of the particles that
// the density and force sums walk (kernels/common/cell_grid.hpp).
#include "device_state.cuh"

#include <cstddef>
#include <cstdint>

namespace mssph::kernels {

// Temporary storage of the cell table's scan over cells + 1 counts [bytes].
std::size_t scan_temp_bytes(std::uint32_t cells);

// Sorts the particles into the grid's cells from their canonical positions: cell_start,
// sorted_id and the cell-ordered positions and velocities.
void launch_neighbour_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream);

}  // namespace mssph::kernels
