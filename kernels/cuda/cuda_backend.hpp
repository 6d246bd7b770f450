#pragma once
// The `cuda` backend: float32 kernels for the whole step on an NVIDIA GPU, captured in one CUDA
// graph. Declared without CUDA types so code built by the host compiler can create it.
#include "backend/backend.hpp"
#include "model/particle_setup.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mssph::kernels {

struct CudaDeviceInfo {
  int index;
  std::string name;
  int compute_major, compute_minor;
  std::size_t total_memory;  // [bytes]
  int multiprocessors;
};

// The CUDA devices visible to this process (empty without a driver or a GPU).
std::vector<CudaDeviceInfo> cuda_devices();

// Throws InputError when no usable device is present, the device is older than the code was built
// for, or the scene does not fit in its memory (naming particles and bytes).
std::unique_ptr<Backend> make_cuda_backend(ParticleSetup setup);

// Device memory the backend allocates for a scene on the current device [bytes]: counted from the
// list that allocates (device_arrays.hpp), and checked against the free memory before allocating.
std::size_t cuda_backend_bytes(const ParticleSetup& setup);

}  // namespace mssph::kernels
