#include "crowded_start.hpp"

#include "model/hashed_cells.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace mssph {

namespace {

struct ClosestPair {
  double distance = 0.0;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
};

}  // namespace

std::vector<std::string> crowded_start_warnings(const ParticleSetup& setup, double jitter) {
  const double dx = setup.spacing;
  const double limit = dx * (0.95 - 2.0 * std::sqrt(3.0) * jitter);
  if (limit <= 0.5 * dx) return {};
  const HashedCells cells(setup.position, dx);
  std::map<std::pair<std::uint32_t, std::uint32_t>, ClosestPair> crowded;  // by body pair
  for (std::size_t i = 0; i < setup.size(); ++i) {
    cells.for_each_in_neighbourhood(cells.cell(i), [&](std::size_t j, const Eigen::Vector3d& x_j) {
      const std::uint32_t a = setup.body[i];
      const std::uint32_t b = setup.body[j];
      if (a >= b || (setup.bodies[a].is_static() && setup.bodies[b].is_static())) return;
      const double distance = (setup.position[i] - x_j).norm();
      if (distance >= limit) return;
      const auto [entry, inserted] = crowded.try_emplace({a, b}, ClosestPair{distance, setup.position[i]});
      if (!inserted && distance < entry->second.distance) entry->second = {distance, setup.position[i]};
    });
  }
  std::vector<std::string> warnings;
  for (const auto& [bodies, pair] : crowded) {
    std::ostringstream out;
    out << "bodies \"" << setup.bodies[bodies.first].name << "\" and \"" << setup.bodies[bodies.second].name
        << "\" start with particles " << pair.distance / dx << " spacings apart near [" << pair.where.x() << ", "
        << pair.where.y() << ", " << pair.where.z()
        << "] m: they start compressed and push apart in the first steps (is a container's inner size a whole "
           "number of spacings, and do the bodies' lattices line up?)";
    warnings.push_back(out.str());
  }
  return warnings;
}

}  // namespace mssph
