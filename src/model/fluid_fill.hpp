#pragma once
// Fluids that fill around the bodies placed in them (a fluid body's `fill_around_bodies`): the
// fluid's lattice sites closer than one spacing to another body's sites are left out, so a body
// starts inside the fluid with a gap of about one spacing, as scene generators fill fluid around
// solids.
#include <Eigen/Core>

#include <vector>

namespace mssph {

// The candidates farther than `distance` from every point of `others` (a hash grid of cell size
// `distance` keeps this linear), in their order.
std::vector<Eigen::Vector3d> sites_clear_of(const std::vector<Eigen::Vector3d>& candidates,
                                            const std::vector<Eigen::Vector3d>& others, double distance);

}  // namespace mssph
