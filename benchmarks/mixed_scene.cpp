#include "mixed_scene.hpp"

#include "config/scene_loader.hpp"

#include <cmath>

namespace mssph::bench {

Scene mixed_scene(std::size_t particles) {
  const double side = 0.5;   // container floor [m]
  const double depth = 0.1;  // pool and block height [m]
  const double half = 0.24;  // pool and block width, a 2 cm gap between them [m]
  const double cube = 0.1;   // proxy edge [m]
  const double volume = 2.0 * half * side * depth + cube * cube * cube;
  const double dx = std::cbrt(volume / static_cast<double>(particles));
  const double k = 100.0;  // sound speed 10 m/s, as block_scene
  // dt at the acoustic bound 0.25 h / c with h = 2 dx, as block_scene (E below is the same).
  const double dt = 0.2 * 2.0 * dx / std::sqrt(k);
  const double x_pool = -0.5 * (half + 0.02);
  const nlohmann::json document = {
      {"name", "mixed"},
      {"description",
       "benchmark: fluid pool, glued deformable block and the coupled rigid proxy pressed into the pool"},
      {"simulation", {{"dt", dt}, {"duration", 1000 * dt}, {"particle_spacing", dx}}},
      {"materials",
       {{"liquid", {{"rest_density", 1000.0}, {"pressure_stiffness", k}, {"viscosity", 1.0}}},
        {"soft",
         {{"rest_density", 1000.0},
          {"pressure_stiffness", k},
          {"viscosity", 1.0},
          {"young_modulus", 5e4},
          {"poisson_ratio", 0.3}}},
        {"wall", {{"rest_density", 1000.0}, {"pressure_stiffness", k}, {"viscosity", 0.0}}}}},
      {"bodies",
       {{"container",
         {{"kind", "boundary"},
          {"material", "wall"},
          {"shape", {{"type", "container"}, {"inner_size", {side, side, 4.0 * depth}}}},
          {"position", {0.0, 0.0, 2.0 * depth}}}},
        {"pool",
         {{"kind", "fluid"},
          {"material", "liquid"},
          {"shape", {{"type", "box"}, {"size", {half, side, depth}}}},
          {"position", {x_pool, 0.0, 0.5 * depth}}}},
        {"block",
         {{"kind", "deformable"},
          {"material", "soft"},
          {"shape", {{"type", "box"}, {"size", {half, side, depth}}}},
          {"position", {-x_pool, 0.0, 0.5 * depth}},
          {"fixed_regions", nlohmann::json::array({{{"min", {0.0, -side, 0.0}}, {"max", {side, side, dx}}}})}}},
        {"proxy",
         {{"kind", "rigid"},
          {"material", "wall"},
          {"density", 500.0},
          {"shape", {{"type", "box"}, {"size", {cube, cube, cube}}}},
          {"position", {x_pool, 0.0, depth + 0.5 * cube + dx}}}}}},
      // The cube starts one spacing above the pool's surface, within the kernel's reach, so that
      // even the first steps have fluid-rigid contact; the hand presses it 5 cm in over 0.3 s.
      {"proxy",
       {{"body", "proxy"},
        {"trajectory",
         {{"source", "scripted"},
          {"keyframes",
           {{{"time", 0.0}, {"position", {0.0, 0.0, 0.0}}}, {{"time", 0.3}, {"position", {0.0, 0.0, -0.05}}}}}}}}}};
  return parse_scene(document, "mixed benchmark scene");
}

}  // namespace mssph::bench
