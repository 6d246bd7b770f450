#include "backend_support.hpp"

#include "config/json_reader.hpp"
#include "util/errors.hpp"

namespace mssph::cli {
namespace {

// Where a body's damping was given: inline, else in its material.
std::string damping_pointer(const Scene& scene, const BodyConfig& body) {
  const std::string in_body = "/bodies/" + escape_pointer_token(body.name);
  const nlohmann::json& document = scene.document.at("bodies").at(body.name);
  if (document.contains("damping") || !document.contains("material")) return in_body + "/damping";
  return "/materials/" + escape_pointer_token(document.at("material").get<std::string>()) + "/damping";
}

}  // namespace

void check_backend_supports(const Scene& scene, const std::string& backend) {
  if (backend == "reference") return;
  for (const BodyConfig& body : scene.bodies) {
    if (body.kind != BodyKind::deformable || body.material.damping <= 0.0 || !body.fixed_regions.empty()) continue;
    const std::string pointer = damping_pointer(scene, body);
    throw InputError(scene.source_file + ": " + pointer +
                         ": damping of a deformable body that no fixed region holds is available in the reference "
                         "backend only (use --backend reference, or hold body \"" +
                         body.name + "\" with fixed_regions)",
                     pointer);
  }
}

}  // namespace mssph::cli
