#include "crowded_start.hpp"

#include "model/hashed_cells.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <utility>

#include <omp.h>

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
  // Threads take ascending ranges of particles, each noting by body pair the first closest pair it
  // meets; merged in thread order, a tie keeps the pair met first, as a single thread would.
  using ByBodyPair = std::map<std::pair<std::uint32_t, std::uint32_t>, ClosestPair>;
  const auto keep_closer = [](ByBodyPair& crowded, std::pair<std::uint32_t, std::uint32_t> bodies, ClosestPair pair) {
    const auto [entry, inserted] = crowded.try_emplace(bodies, pair);
    if (!inserted && pair.distance < entry->second.distance) entry->second = pair;
  };
  std::vector<ByBodyPair> of_thread;
  const auto n = static_cast<std::int64_t>(setup.size());
#pragma omp parallel
  {
#pragma omp single
    of_thread.resize(static_cast<std::size_t>(omp_get_num_threads()));
    ByBodyPair& mine = of_thread[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      cells.for_each_in_neighbourhood(cells.cell(i), [&](std::size_t j, const Eigen::Vector3d& x_j) {
        const std::uint32_t a = setup.body[i];
        const std::uint32_t b = setup.body[j];
        if (a >= b || (setup.bodies[a].is_static() && setup.bodies[b].is_static())) return;
        const double distance = (setup.position[i] - x_j).norm();
        if (distance < limit) keep_closer(mine, {a, b}, ClosestPair{distance, setup.position[i]});
      });
    }
  }
  ByBodyPair crowded;
  for (const ByBodyPair& part : of_thread) {
    for (const auto& [bodies, pair] : part) keep_closer(crowded, bodies, pair);
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
