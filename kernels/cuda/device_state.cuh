#pragma once
// A scene's device arrays (the list in device_arrays.hpp, allocated) and the views the kernels
// take of them.
#include "../common/elastic_physics.hpp"
#include "../common/near_notes.hpp"
#include "../common/neighbour_list.hpp"
#include "../common/particle_views.hpp"
#include "device_arrays.hpp"
#include "device_buffer.hpp"

#include <string>

namespace mssph::kernels {

using DeviceState = DeviceArrays<DeviceBuffer>;

// Allocates and fills every array of for_each_device_array. Throws InputError before allocating
// when they do not fit into the device's free memory (naming particles and bytes).
DeviceState allocate_device_state(const FloatScene& scene, const ChunkTables& chunks, std::size_t grid_blocks,
                                  unsigned team_lanes, const std::string& device_name);

SortedView sorted_view(const FloatScene& scene, const DeviceState& state);
// The lanes' neighbour lists of teams of `team_lanes` (the lanes the state was allocated for).
NeighbourLists team_lists(DeviceState& state, unsigned team_lanes);
CanonicalState canonical_state(DeviceState& state);
ForceWalks force_walks(DeviceState& state);
// Where a step's density pass leaves its near notes for the force pass (near_notes.hpp).
NearNotes step_near_notes(DeviceState& state);
DeviceDeformableView deformable_view(const FloatScene& scene, DeviceState& state);

}  // namespace mssph::kernels
