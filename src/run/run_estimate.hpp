#pragma once
// What a run will cost, known from the scene alone before anything is allocated: particles per
// body, host and device memory, steps. A run that would not fit is refused with both numbers
// instead of failing in an allocation (std::bad_alloc) or swapping after minutes of set-up; a
// scene whose float32 backends could not resolve its particle spacing is refused too.
#include "config/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mssph::cli {

struct BodyEstimate {
  std::string name;
  double particles = 0.0;  // a double: an absurd scene's count may exceed any integer type
};

struct RunEstimate {
  std::vector<BodyEstimate> bodies;
  double particles = 0.0;
  double host_bytes = 0.0;
  double device_bytes = 0.0;  // cuda only
  double steps = 0.0;
  // Half the largest extent of the bodies' bounding box divided by the spacing: how many
  // spacings float32 positions must resolve from the kernels' origin (the box's centre).
  double extent_in_spacings = 0.0;
};

// Particles per body (from the shapes' volumes on the lattice), memory and steps on `backend`.
RunEstimate estimate_run(const Scene& scene, const std::string& backend);

// Memory this process may still use [bytes]: MemAvailable from /proc/meminfo, lowered to the
// control group's limit when there is one. nullopt when neither can be read.
std::optional<double> available_host_memory();

// Throws InputError naming the scene file when the estimate exceeds what the machine has
// (`device_memory`: the GPU's, for cuda), or when float32 cannot resolve the scene's extent.
void check_run_fits(const Scene& scene, const std::string& backend, const RunEstimate& estimate,
                    std::optional<double> host_memory, std::optional<double> device_memory);

// "12.3 MiB", "4.56 GiB".
std::string format_bytes(double bytes);

}  // namespace mssph::cli
