#include "block_scene.hpp"

#include "config/scene_loader.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mssph {
namespace {

constexpr double kSide = 0.5;            // square base [m]
constexpr double kFixedHeight = 0.2;     // the Figure 3 block's height [m]
constexpr double kRestDensity = 1000.0;  // [kg/m^3]
constexpr double kGravity = 9.81;        // [m/s^2]

}  // namespace

std::string to_string(BlockGeometry geometry) { return geometry == BlockGeometry::paper ? "paper" : "fixed-height"; }

BlockGeometry block_geometry_from_string(const std::string& name) {
  if (name == "paper") return BlockGeometry::paper;
  if (name == "fixed-height") return BlockGeometry::fixed_height;
  throw std::invalid_argument("block geometry '" + name + "': expected paper or fixed-height");
}

Scene block_scene(BodyKind medium, std::size_t block_particles, BlockGeometry geometry) {
  const double n = static_cast<double>(block_particles);
  const bool paper = geometry == BlockGeometry::paper;
  const double dx = paper ? kPaperBlockSpacing : std::cbrt(kSide * kSide * kFixedHeight / n);
  const double height = paper ? n * dx * dx * dx / (kSide * kSide) : kFixedHeight;
  // Equation of state P = k (rho - rho0) under a column of height H compresses its base by
  // rho0 g H / (k rho0) = g H / k: k = 50 g H keeps that at 2 % (k = 100, c = 10 m/s, at 20 cm).
  const double k = std::max(100.0, 50.0 * kGravity * height);
  // Likewise the elastic strain under the block's own weight, rho0 g H / E, stays at 4 %
  // (E = 50 kPa at 20 cm).
  const double young_modulus = std::max(5e4, 25.0 * kRestDensity * kGravity * height);
  // dt at the acoustic bound 0.25 h / c with h = 2 dx (c = sqrt(k)), within the elastic bound.
  const double dt = 0.2 * 2.0 * dx / std::sqrt(k);
  // The fixed-height container is twice the block's height (the benchmarks' scene since their
  // first baseline); the paper geometry's leaves 10 cm of headroom, since a container twice a
  // 1 m column would add as many wall particles as the block has.
  const double container_height = paper ? height + 0.1 : 2.0 * height;
  nlohmann::json block = {{"kind", to_string(medium)},
                          {"material", "block"},
                          {"shape", {{"type", "box"}, {"size", {kSide, kSide, height}}}},
                          {"position", {0.0, 0.0, 0.5 * height}}};
  nlohmann::json material = {{"rest_density", kRestDensity}, {"pressure_stiffness", k}, {"viscosity", 1.0}};
  if (medium == BodyKind::deformable) {
    material["young_modulus"] = young_modulus;
    material["poisson_ratio"] = 0.3;
    block["fixed_regions"] = nlohmann::json::array({{{"min", {-kSide, -kSide, 0.0}}, {"max", {kSide, kSide, dx}}}});
  } else if (medium == BodyKind::rigid) {
    block["density"] = kRestDensity;
  } else if (medium != BodyKind::fluid) {
    throw std::invalid_argument("a block scene is fluid, deformable or rigid");
  }
  const nlohmann::json document = {
      {"name", std::string("block_") + to_string(medium)},
      {"description", "Figure 2 benchmark block, " + to_string(geometry) + " geometry"},
      {"simulation", {{"dt", dt}, {"duration", 1000 * dt}, {"particle_spacing", dx}, {"sample_rigid_interiors", true}}},
      {"materials",
       {{"block", material},
        {"wall", {{"rest_density", kRestDensity}, {"pressure_stiffness", k}, {"viscosity", 0.0}}}}},
      {"bodies",
       {{"container",
         {{"kind", "boundary"},
          {"material", "wall"},
          {"shape", {{"type", "container"}, {"inner_size", {kSide, kSide, container_height}}}},
          {"position", {0.0, 0.0, 0.5 * container_height}}}},
        {"block", block}}}};
  return parse_scene(document, "block scene");
}

}  // namespace mssph
