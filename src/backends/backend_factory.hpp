#pragma once
// Chooses and constructs a backend by name: reference, cpu, cuda or auto.
#include "scene/particle_setup.hpp"
#include "sim/backend.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mssph {

// The backends this binary can run, e.g. {"reference"}.
std::vector<std::string> available_backends();

// `auto` picks cuda when a GPU is present, else cpu (else reference). An unavailable backend is
// an InputError that says why.
std::string resolve_backend_name(const std::string& requested);
std::unique_ptr<Backend> make_backend(const std::string& name, ParticleSetup setup);

}  // namespace mssph
