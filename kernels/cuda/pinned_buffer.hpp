#pragma once
// Page-locked host memory for n elements of T (cudaHostAlloc): a device-to-host copy into it goes
// straight to its destination, without the driver's staging copy that pageable memory needs, which
// matters for the few bytes a haptic tick reads back. Only for copies the host waits for before it
// touches the memory again: an asynchronous copy out of it would read whatever the host wrote
// meanwhile.
#include "cuda_check.hpp"

#include <cstddef>
#include <utility>

namespace mssph::kernels {

template <class T>
class PinnedBuffer {
 public:
  PinnedBuffer() = default;
  explicit PinnedBuffer(std::size_t count) : count_(count) {
    if (count_ > 0) {
      cuda_check(cudaHostAlloc(reinterpret_cast<void**>(&data_), count_ * sizeof(T), cudaHostAllocDefault),
                 "allocate pinned host memory");
    }
  }
  ~PinnedBuffer() {
    if (data_) cudaFreeHost(data_);
  }
  PinnedBuffer(PinnedBuffer&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), count_(std::exchange(other.count_, 0)) {}
  PinnedBuffer& operator=(PinnedBuffer&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(count_, other.count_);
    return *this;
  }
  PinnedBuffer(const PinnedBuffer&) = delete;
  PinnedBuffer& operator=(const PinnedBuffer&) = delete;

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return count_; }
  std::size_t bytes() const { return count_ * sizeof(T); }

 private:
  T* data_ = nullptr;
  std::size_t count_ = 0;
};

}  // namespace mssph::kernels
