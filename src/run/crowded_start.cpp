#include "crowded_start.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace mssph {

namespace {

struct CellHash {
  std::size_t operator()(const Eigen::Vector3i& c) const {
    return (static_cast<std::size_t>(c.x()) * 73856093u) ^ (static_cast<std::size_t>(c.y()) * 19349663u) ^
           (static_cast<std::size_t>(c.z()) * 83492791u);
  }
};

struct ClosestPair {
  double distance = 0.0;
  Eigen::Vector3d where = Eigen::Vector3d::Zero();
};

}  // namespace

std::vector<std::string> crowded_start_warnings(const ParticleSetup& setup, double jitter) {
  const double dx = setup.spacing;
  const double limit = dx * (0.95 - 2.0 * std::sqrt(3.0) * jitter);
  if (limit <= 0.5 * dx) return {};
  const auto cell_of = [&](const Eigen::Vector3d& x) { return Eigen::Vector3i((x / dx).array().floor().cast<int>()); };
  std::unordered_map<Eigen::Vector3i, std::vector<std::size_t>, CellHash> cells;
  for (std::size_t i = 0; i < setup.size(); ++i) cells[cell_of(setup.position[i])].push_back(i);
  std::map<std::pair<std::uint32_t, std::uint32_t>, ClosestPair> crowded;  // by body pair
  for (std::size_t i = 0; i < setup.size(); ++i) {
    const Eigen::Vector3i c = cell_of(setup.position[i]);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dxc = -1; dxc <= 1; ++dxc) {
          const auto it = cells.find(c + Eigen::Vector3i(dxc, dy, dz));
          if (it == cells.end()) continue;
          for (const std::size_t j : it->second) {
            const std::uint32_t a = setup.body[i];
            const std::uint32_t b = setup.body[j];
            if (a >= b || (setup.bodies[a].is_static() && setup.bodies[b].is_static())) continue;
            const double distance = (setup.position[i] - setup.position[j]).norm();
            if (distance >= limit) continue;
            const auto [entry, inserted] = crowded.try_emplace({a, b}, ClosestPair{distance, setup.position[i]});
            if (!inserted && distance < entry->second.distance) entry->second = {distance, setup.position[i]};
          }
        }
      }
    }
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
