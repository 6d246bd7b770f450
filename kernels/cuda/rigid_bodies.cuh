#pragma once
// Rigid-body dynamics on the GPU (paper eq. 8, 9): each movable body's interaction wrench summed
// over its particles by chunks (chunk_tables.hpp), the body integrated, its particles placed.
#include "device_state.cuh"

namespace mssph::kernels {

// Nothing without movable rigid bodies. `chunks`: the tables the state was allocated with. Each
// body, once integrated, is also stored to `host_copy` (mapped host memory, BodyReadback), where
// the haptic loop reads it.
void launch_rigid_bodies(const FloatScene& scene, const ChunkTables& chunks, DeviceState& state, RigidBody* host_copy,
                         cudaStream_t stream);

}  // namespace mssph::kernels
