#include "wall_exclusion.hpp"

#include "model/wall_exclusion.hpp"

namespace mssph::reference {

void keep_out_of_walls(const ParticleSetup& setup, const NeighbourLists& neighbours, std::size_t i,
                       const std::vector<Eigen::Vector3d>& positions, const Eigen::Vector3d& previous,
                       Eigen::Vector3d& position, Eigen::Vector3d& velocity) {
  const double limit = kWallExclusionFraction * setup.spacing;
  bool rejected = false;
  for (const std::size_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) {
    if (setup.bodies[setup.body[*j]].kind != BodyKind::boundary) continue;
    const Eigen::Vector3d& x_b = positions[*j];
    const double r_new = (position - x_b).norm();
    const Eigen::Vector3d away = previous - x_b;
    const double r_old = away.norm();
    if (r_new >= limit || r_new >= r_old) continue;
    rejected = true;
    const Eigen::Vector3d n = away / r_old;  // r_old > r_new >= 0
    const double approach = velocity.dot(n);
    if (approach < 0.0) velocity -= approach * n;
  }
  if (rejected) position = previous;
}

}  // namespace mssph::reference
