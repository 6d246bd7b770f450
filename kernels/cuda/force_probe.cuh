#pragma once
// The force probe: the pressure and viscosity sums of every particle written out instead of
// integrated, so tests and validation compare backends force by force (Backend::evaluate_forces).
#include "device_state.cuh"
#include "sim/backend.hpp"

namespace mssph::kernels {

// Runs the probe after the step's neighbour grid, rotations and densities of the current state,
// and returns every particle's forces, densities and rotations in canonical order.
ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, cudaStream_t stream);

}  // namespace mssph::kernels
