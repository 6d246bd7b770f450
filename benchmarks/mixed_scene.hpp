#pragma once
// The suite's mixed scene: every medium at once with the haptic proxy coupled, about N particles
// (the spacing follows N, as in block_scene). In a container, a fluid pool and a deformable
// block (glued at its base) share the floor; a rigid cube, the proxy, rests on the pool's surface
// and is pressed into it by the scripted hand, so every step has fluid-rigid, fluid-deformable
// and coupling work.
#include "config/scene.hpp"

#include <cstddef>

namespace mssph::bench {

Scene mixed_scene(std::size_t particles);

}  // namespace mssph::bench
