#pragma once
// The GPU the `cuda` backend runs on (device 0): whether it can, and what it offers.
#include <cstddef>
#include <string>

namespace mssph::kernels {

// The device's name. Throws InputError when no device is present or this build's kernels were
// compiled for other architectures than the device's (saying how to rebuild).
std::string require_usable_device();

// Threads the device keeps resident at once (multiprocessors x threads per multiprocessor).
std::size_t resident_threads();

}  // namespace mssph::kernels
