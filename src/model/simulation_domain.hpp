#pragma once
// The default simulation domain of a scene without simulation/domain: the bounding box of all
// bodies' particles at the start, widened on every side by half its largest side plus the support
// radius h. Half the scene's size leaves room for what a run legitimately does (a splash rising
// above an open tank, a body bouncing off the floor); a particle farther away than that is no
// longer part of the experiment (fluid that fell out of its container falls forever).
#include "config/scene.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph {

inline constexpr double kDomainMarginFraction = 0.5;  // margin / largest side of the starting box [-]

Region default_simulation_domain(const std::vector<Eigen::Vector3d>& positions, double smoothing_length);

}  // namespace mssph
