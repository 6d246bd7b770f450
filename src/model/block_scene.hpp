#pragma once
// The paper's Figure 2 scene: one block of a single medium, a cuboid with a 0.5 m square base, in
// an open container, sampled with about N particles. Two geometries:
// - paper (section 5.1 of Cirio et al. 2011): a FIXED particle spacing of 2 cm (the spacing of the
//   paper's Figure 3 block, 50 x 50 x 20 cm in 6,250 particles) and a height that grows with N:
//   2,000 particles make a 6.4 cm slab, 30,000 a 0.96 m column;
// - fixed_height: the Figure 3 block's 0.5 x 0.5 x 0.2 m at a spacing that shrinks with N, so every
//   size is the same physical scene at a finer resolution (the benchmarks' block).
// Pressure stiffness and Young's modulus grow with the height so that every size is equally
// compressed by its own weight (see block_scene.cpp); the cost of a step does not depend on them.
#include "config/scene.hpp"

#include <cstddef>
#include <string>

namespace mssph {

enum class BlockGeometry { paper, fixed_height };

std::string to_string(BlockGeometry geometry);
// Throws std::invalid_argument for a name other than "paper" or "fixed-height".
BlockGeometry block_geometry_from_string(const std::string& name);

// The paper geometry's particle spacing [m].
inline constexpr double kPaperBlockSpacing = 0.02;

// medium: fluid, deformable or rigid. Deformable blocks are fixed at their base; a rigid block
// rests on the container floor.
Scene block_scene(BodyKind medium, std::size_t block_particles, BlockGeometry geometry = BlockGeometry::fixed_height);

}  // namespace mssph
