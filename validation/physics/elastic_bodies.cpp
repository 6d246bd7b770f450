#include "elastic_bodies.hpp"

namespace mssph::validation {

std::vector<std::size_t> interior_particles(const reference::ReferenceBackend& backend, std::size_t body,
                                            double margin) {
  const BodySetup& b = backend.setup().bodies[body];
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    lo = lo.cwiseMin(backend.setup().position[i]);
    hi = hi.cwiseMax(backend.setup().position[i]);
  }
  std::vector<std::size_t> inside;
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    const Eigen::Vector3d& x = backend.setup().position[i];
    if (((x - lo).array() >= margin - 1e-12).all() && ((hi - x).array() >= margin - 1e-12).all()) inside.push_back(i);
  }
  return inside;
}

void deform_body(reference::ReferenceBackend& backend, std::size_t body, const Eigen::Matrix3d& g,
                 const Eigen::Vector3d& centre, const Eigen::Vector3d& translation) {
  const BodySetup& b = backend.setup().bodies[body];
  for (std::size_t i = b.first; i < b.first + b.count; ++i) {
    backend.particles().position[i] = centre + g * (backend.setup().position[i] - centre) + translation;
  }
}

}  // namespace mssph::validation
