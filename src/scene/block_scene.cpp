#include "scene/block_scene.hpp"

#include "config/scene_loader.hpp"

#include <cmath>
#include <stdexcept>

namespace mssph {

Scene block_scene(BodyKind medium, std::size_t block_particles) {
  const double side = 0.5;
  const double height = 0.2;
  const double dx = std::cbrt(side * side * height / static_cast<double>(block_particles));
  const double k = 100.0;  // sound speed 10 m/s
  // dt at the acoustic bound 0.25 h / c with h = 2 dx, and within the elastic bound for E below.
  const double dt = 0.2 * 2.0 * dx / std::sqrt(k);
  nlohmann::json block = {{"kind", to_string(medium)},
                          {"material", "block"},
                          {"shape", {{"type", "box"}, {"size", {side, side, height}}}},
                          {"position", {0.0, 0.0, 0.5 * height}}};
  nlohmann::json material = {{"rest_density", 1000.0}, {"pressure_stiffness", k}, {"viscosity", 1.0}};
  if (medium == BodyKind::deformable) {
    material["young_modulus"] = 5e4;
    material["poisson_ratio"] = 0.3;
    block["fixed_regions"] = nlohmann::json::array({{{"min", {-side, -side, 0.0}}, {"max", {side, side, dx}}}});
  } else if (medium == BodyKind::rigid) {
    block["density"] = 1000.0;
  } else if (medium != BodyKind::fluid) {
    throw std::invalid_argument("a block scene is fluid, deformable or rigid");
  }
  const nlohmann::json document = {
      {"name", std::string("block_") + to_string(medium)},
      {"description", "Figure 2 benchmark block"},
      {"simulation", {{"dt", dt}, {"duration", 1000 * dt}, {"particle_spacing", dx}}},
      {"materials", {{"block", material},
                     {"wall", {{"rest_density", 1000.0}, {"pressure_stiffness", k}, {"viscosity", 0.0}}}}},
      {"bodies",
       {{"container", {{"kind", "boundary"},
                       {"material", "wall"},
                       {"shape", {{"type", "container"}, {"inner_size", {side, side, 2.0 * height}}}},
                       {"position", {0.0, 0.0, height}}}},
        {"block", block}}}};
  return parse_scene(document, "block scene");
}

}  // namespace mssph
