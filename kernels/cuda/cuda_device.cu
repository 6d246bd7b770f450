#include "cuda_device.cuh"

#include "cuda_backend.hpp"
#include "cuda_check.hpp"
#include "step_kernels.cuh"
#include "util/errors.hpp"

namespace mssph::kernels {

std::string require_usable_device() {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess || count == 0) {
    throw InputError(std::string("--backend cuda: no CUDA device is available (") +
                     (status != cudaSuccess ? cudaGetErrorString(status) : "no GPU found") +
                     "); use --backend cpu or --backend auto");
  }
  cudaDeviceProp properties{};
  cuda_check(cudaGetDeviceProperties(&properties, 0), "read device properties");
  const std::string name = properties.name;
  if (step_kernels_loadable() != cudaSuccess) {
    cudaGetLastError();  // clear the sticky error of the failed query
    throw InputError("--backend cuda: the GPU " + name + " (compute capability " + std::to_string(properties.major) +
                     "." + std::to_string(properties.minor) + ") is not supported by this build (CUDA architectures " +
                     MSSPH_CUDA_ARCHITECTURES_TEXT + "): rebuild with -DCMAKE_CUDA_ARCHITECTURES=" +
                     std::to_string(properties.major) + std::to_string(properties.minor));
  }
  return name;
}

std::size_t resident_threads() {
  cudaDeviceProp properties{};
  cuda_check(cudaGetDeviceProperties(&properties, 0), "read device properties");
  return static_cast<std::size_t>(properties.multiProcessorCount) *
         static_cast<std::size_t>(properties.maxThreadsPerMultiProcessor);
}

std::vector<CudaDeviceInfo> cuda_devices() {
  std::vector<CudaDeviceInfo> devices;
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    cudaGetLastError();
    return devices;
  }
  for (int d = 0; d < count; ++d) {
    cudaDeviceProp p{};
    if (cudaGetDeviceProperties(&p, d) != cudaSuccess) continue;
    devices.push_back({d, p.name, p.major, p.minor, p.totalGlobalMem, p.multiProcessorCount});
  }
  return devices;
}

}  // namespace mssph::kernels
