#pragma once
// CUDA runtime calls checked: a failing call throws with the call's purpose and CUDA's message.
#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace mssph::kernels {

class CudaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline void cuda_check(cudaError_t status, const char* what) {
  if (status != cudaSuccess) {
    throw CudaError(std::string("CUDA: ") + what + ": " + cudaGetErrorName(status) + " (" + cudaGetErrorString(status) +
                    ")");
  }
}

}  // namespace mssph::kernels
