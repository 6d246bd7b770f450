#pragma once
// The no-penetration condition of boundary bodies after step 4's leap-frog, float64
// (model/wall_exclusion.hpp says why and with what distance; float twin:
// kernels::keep_out_of_walls).
#include "model/neighbour_search.hpp"
#include "model/particle_setup.hpp"

#include <Eigen/Core>

namespace mssph::reference {

// Particle i moved from `previous` to `position` with `velocity`. If the move brings it within
// kWallExclusionFraction dx of a boundary particle while coming closer to it, the move is
// rejected: the particle returns to `previous` and loses its velocity component towards each such
// boundary particle. Only the boundary entries of `positions` are read (they never move). The
// candidates are i's neighbours at the start of the step (within h of `previous`): they hold every
// boundary particle within d_wall of the new position unless the particle moved more than
// h - d_wall (1.2 dx) in one step, far beyond any stable step.
void keep_out_of_walls(const ParticleSetup& setup, const NeighbourLists& neighbours, std::size_t i,
                       const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& previous,
                       Eigen::Vector3d& position, Eigen::Vector3d& velocity);

}  // namespace mssph::reference
