#pragma once
// The force probe: the pressure and viscosity sums of every particle written out instead of
// integrated, so tests and validation compare backends force by force (Backend::evaluate_forces).
#include "backend/backend.hpp"
#include "device_state.cuh"

namespace mssph::kernels {

// Near notes for a probe's density pass (near_notes.hpp), in arrays of their own: outside a step
// the canonical velocity and interaction force are the state, not free words. Empty (no notes)
// for zero particles.
class ProbeNearNotes {
 public:
  explicit ProbeNearNotes(std::size_t particles)
      : canonical_first_(particles),
        canonical_second_(particles),
        sorted_eighth_(particles),
        sorted_ninth_(particles) {}
  NearNotes view() {
    return {canonical_first_.data(), canonical_second_.data(), sorted_eighth_.data(), sorted_ninth_.data()};
  }

 private:
  DeviceBuffer<Vec4> canonical_first_, canonical_second_;
  DeviceBuffer<float> sorted_eighth_, sorted_ninth_;
};

// Runs the probe after the step's neighbour grid, rotations and densities of the current state
// (over `notes`, those the density pass took, as the force pass does), and returns every
// particle's forces, densities and rotations in canonical order.
ForceEvaluation probe_forces(const FloatScene& scene, DeviceState& state, const NearNotes& notes, cudaStream_t stream);

}  // namespace mssph::kernels
