#pragma once
// Fluids that fill around the bodies placed in them (a fluid body's `fill_around_bodies`): the
// fluid's lattice sites closer than one spacing to another body's sites are left out, so a body
// starts inside the fluid, as scene generators fill fluid around solids. A body sampled on the
// fluid's lattice then meets the fluid at one spacing, as inside the fluid; one whose lattice is
// offset by half a cell keeps its nearest fluid particles 1.5-1.7 spacings away.
#include <Eigen/Core>

#include <vector>

namespace mssph {

// The candidates no closer than `distance` to any point of `others` (a hash grid of cell size
// `distance` keeps this linear), in their order.
std::vector<Eigen::Vector3d> sites_clear_of(const std::vector<Eigen::Vector3d>& candidates,
                                            const std::vector<Eigen::Vector3d>& others, double distance);

}  // namespace mssph
