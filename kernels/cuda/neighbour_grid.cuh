#pragma once
// The neighbour grid on the GPU: the cell table and the cell-ordered copies of the particles that
// the density and force sums walk (kernels/common/cell_grid.hpp).
#include "../common/list_skin.hpp"
#include "device_state.cuh"

#include <cstddef>
#include <cstdint>

namespace mssph::kernels {

// Temporary storage of the cell table's scan over cells + 1 counts [bytes].
std::size_t scan_temp_bytes(std::uint32_t cells);

// Sorts the particles into the grid's cells from their canonical positions: cell_start,
// sorted_id and the cell-ordered positions and velocities. With the teams' lists, also where each
// particle stands, for the check below, and that this step's density pass records the lists.
void launch_neighbour_grid(DeviceState& state, const GridShape& grid, cudaStream_t stream);

// With the teams' lists, a step's start: copies the particles into the cell order of the last
// rebuild and sets the condition `rebuild` (of the graph being captured) when the lists are no
// longer valid (list_skin.hpp), so that a conditional node runs launch_neighbour_grid.
void launch_list_check(DeviceState& state, const ListSkin& skin, cudaGraphConditionalHandle rebuild,
                       cudaStream_t stream);

}  // namespace mssph::kernels
