#include "backend_factory.hpp"

#include "reference_backend.hpp"
#include "util/errors.hpp"

namespace mssph {

std::vector<std::string> available_backends() { return {"reference"}; }

std::string resolve_backend_name(const std::string& requested) {
  if (requested == "auto") return "reference";
  const std::vector<std::string> available = available_backends();
  if (std::find(available.begin(), available.end(), requested) == available.end()) {
    throw InputError("--backend " + requested + ": this build of mssph has no " + requested +
                     " backend (available: reference)");
  }
  return requested;
}

std::unique_ptr<Backend> make_backend(const std::string& name, ParticleSetup setup) {
  if (name == "reference") return std::make_unique<reference::ReferenceBackend>(std::move(setup));
  throw InputError("unknown backend \"" + name + "\"");
}

}  // namespace mssph
