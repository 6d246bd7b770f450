#pragma once
// The one place that knows every backend: their names, the GPUs they can use, and construction by
// name. Code above this layer includes no backend's header.
#include "backend/backend.hpp"
#include "model/particle_setup.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mssph {

// Every backend mssph has, built into this binary or not: reference, cpu, cuda.
const std::vector<std::string>& backend_names();

// The float32 backends, compared with the float64 reference: every backend but `reference`.
std::vector<std::string> float_backend_names();

// What --backend accepts: backend_names() and "auto".
const std::vector<std::string>& backend_choices();

// Whether the backend computes on a GPU (its steps cost device time, not host instructions).
bool backend_runs_on_gpu(const std::string& name);

// The backends this binary can run, e.g. {"reference", "cpu"}.
std::vector<std::string> available_backends();

struct GpuDevice {
  int index;
  std::string name;
  int compute_major, compute_minor;
  std::size_t total_memory;  // [bytes]
  int multiprocessors;
};

// The GPUs a backend of this binary can run on (empty without a GPU backend, driver or device).
std::vector<GpuDevice> gpu_devices();

// The memory of the GPU a run of the backend `name` would use [bytes]; nullopt for the host
// backends, or when no GPU is found.
std::optional<double> gpu_memory_for(const std::string& name);

// "" when `name` can run here, else why not (not built, or no GPU for a GPU backend).
std::string why_backend_cannot_run(const std::string& name);

// `auto` picks cuda when a GPU is present, else cpu (else reference). An unavailable backend is
// an InputError that says why.
std::string resolve_backend_name(const std::string& requested);
std::unique_ptr<Backend> make_backend(const std::string& name, ParticleSetup setup);

// Device memory the backend `name` allocates for a scene [bytes]; nullopt for host backends.
std::optional<std::size_t> backend_device_bytes(const std::string& name, const ParticleSetup& setup);

}  // namespace mssph
