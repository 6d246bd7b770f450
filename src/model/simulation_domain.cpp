#include "simulation_domain.hpp"

namespace mssph {

Region default_simulation_domain(const std::vector<Eigen::Vector3d>& positions, double smoothing_length) {
  if (positions.empty()) return Region{};
  Region box{positions.front(), positions.front()};
  for (const Eigen::Vector3d& x : positions) {
    box.min = box.min.cwiseMin(x);
    box.max = box.max.cwiseMax(x);
  }
  const double margin = kDomainMarginFraction * (box.max - box.min).maxCoeff() + smoothing_length;
  box.min.array() -= margin;
  box.max.array() += margin;
  return box;
}

}  // namespace mssph
