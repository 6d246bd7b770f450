#pragma once
// The step's per-particle phases on the GPU, each a thin loop around one of the shared functions
// of kernels/common: rotations and elastic forces of deformable particles, densities, forces with
// the leap-frog integration of the particles.
#include "device_state.cuh"

#include <cstddef>

namespace mssph::kernels {

// Rotations and stresses of every deformable particle, then their elastic forces; false, and
// nothing launched, without deformable bodies.
bool launch_elasticity(const FloatScene& scene, DeviceState& state, unsigned team_lanes, cudaStream_t stream);
// Volume and pressure of every sorted particle; with one lane per particle, each fluid particle's
// near notes for the force pass when `notes` are given (near_notes.hpp).
void launch_densities(const FloatScene& scene, DeviceState& state, unsigned team_lanes, const NearNotes& notes,
                      cudaStream_t stream);
// Pressure, viscosity and interaction forces of every sorted particle, integrated (leap-frog),
// over the density pass's near notes where it took them (the same `notes`); launched right after
// launch_elasticity's kernels when `after_elastic_forces`, which lets it sum beside them.
void launch_forces(const FloatScene& scene, DeviceState& state, unsigned team_lanes, const NearNotes& notes,
                   bool after_elastic_forces, cudaStream_t stream);

// cudaSuccess when this build's kernels can run on the current device (its compute capability
// is among the architectures compiled for).
cudaError_t step_kernels_loadable();

}  // namespace mssph::kernels
