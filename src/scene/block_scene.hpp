#pragma once
// The paper's Figure 2 scene: one block of a single medium, a cuboid of square base 0.5 m (here
// 0.5 x 0.5 x 0.2 m, the Figure 3 block), in an open container, sampled with about N particles
// (the spacing follows N, so every size is the same physical scene at a finer resolution).
#include "config/scene.hpp"

#include <cstddef>

namespace mssph {

// medium: fluid, deformable or rigid. Deformable blocks are fixed at their base; a rigid block
// rests on the container floor.
Scene block_scene(BodyKind medium, std::size_t block_particles);

}  // namespace mssph
