#pragma once
// Page-locked host memory for n elements of T, mapped into the GPU's address space
// (cudaHostAllocMapped): kernels store into it directly, so what the host reads back after a step
// (a haptic tick's rigid body, a logged sample's sums) needs no copy in the stream, only a wait
// for the stream. The host reads it only after that wait, and writes it only while no kernel that
// stores into it is in flight.
#include "cuda_check.hpp"

#include <cstddef>
#include <utility>

namespace mssph::kernels {

template <class T>
class MappedHostBuffer {
 public:
  MappedHostBuffer() = default;
  explicit MappedHostBuffer(std::size_t count) : count_(count) {
    if (count_ == 0) return;
    // Portable: mapped for every device's context, as a sweep may run one backend per GPU.
    cuda_check(cudaHostAlloc(reinterpret_cast<void**>(&data_), count_ * sizeof(T),
                             cudaHostAllocMapped | cudaHostAllocPortable),
               "allocate mapped host memory");
    cuda_check(cudaHostGetDevicePointer(reinterpret_cast<void**>(&device_data_), data_, 0),
               "map host memory for the device");
  }
  ~MappedHostBuffer() {
    if (data_) cudaFreeHost(data_);
  }
  MappedHostBuffer(MappedHostBuffer&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)),
        device_data_(std::exchange(other.device_data_, nullptr)),
        count_(std::exchange(other.count_, 0)) {}
  MappedHostBuffer& operator=(MappedHostBuffer&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(device_data_, other.device_data_);
    std::swap(count_, other.count_);
    return *this;
  }
  MappedHostBuffer(const MappedHostBuffer&) = delete;
  MappedHostBuffer& operator=(const MappedHostBuffer&) = delete;

  T* data() { return data_; }
  const T* data() const { return data_; }
  T* device_data() { return device_data_; }  // the same memory, as kernels address it
  std::size_t size() const { return count_; }

 private:
  T* data_ = nullptr;
  T* device_data_ = nullptr;
  std::size_t count_ = 0;
};

}  // namespace mssph::kernels
