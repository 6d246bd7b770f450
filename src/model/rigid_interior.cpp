#include "rigid_interior.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace mssph {
namespace {

using Node = std::array<long, 3>;

// The integer offsets within `radius` (lattice units) of the origin, nearest first, so that a
// site near the surface finds an empty node after few tests.
std::vector<Node> offsets_within(double radius) {
  const long r = static_cast<long>(std::floor(radius));
  std::vector<Node> offsets;
  for (long a = -r; a <= r; ++a)
    for (long b = -r; b <= r; ++b)
      for (long c = -r; c <= r; ++c)
        if (static_cast<double>(a * a + b * b + c * c) <= radius * radius) offsets.push_back({a, b, c});
  std::stable_sort(offsets.begin(), offsets.end(), [](const Node& p, const Node& q) {
    return p[0] * p[0] + p[1] * p[1] + p[2] * p[2] < q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
  });
  return offsets;
}

}  // namespace

double rigid_surface_reach(double smoothing_length, double spacing) { return 2.0 * smoothing_length + spacing; }

std::vector<std::uint8_t> sites_within_reach_of_surface(std::span<const Eigen::Vector3d> sites,
                                                        const Eigen::Matrix3d& to_lattice, double dx, double reach) {
  if (sites.empty()) return {};
  // Integer lattice coordinates relative to the first site; a box around them, widened by the
  // reach, whose nodes outside the body stay empty.
  const Eigen::Vector3d origin = to_lattice * sites.front() / dx;
  const double radius = reach / dx;
  const long pad = static_cast<long>(std::floor(radius)) + 1;
  std::vector<Node> node(sites.size());
  Node low{0, 0, 0}, high{0, 0, 0};
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const Eigen::Vector3d q = to_lattice * sites[i] / dx - origin;
    for (int a = 0; a < 3; ++a) {
      node[i][a] = std::lround(q[a]);
      low[a] = std::min(low[a], node[i][a]);
      high[a] = std::max(high[a], node[i][a]);
    }
  }
  Node extent{};
  for (int a = 0; a < 3; ++a) extent[a] = high[a] - low[a] + 1 + 2 * pad;
  const auto index = [&](const Node& n) {
    return static_cast<std::size_t>(((n[2] - low[2] + pad) * extent[1] + (n[1] - low[1] + pad)) * extent[0] +
                                    (n[0] - low[0] + pad));
  };
  std::vector<std::uint8_t> occupied(static_cast<std::size_t>(extent[0] * extent[1] * extent[2]), 0);
  for (const Node& n : node) occupied[index(n)] = 1;

  const std::vector<Node> offsets = offsets_within(radius);
  const auto empty_node_within_reach = [&](const Node& n) {
    return std::any_of(offsets.begin(), offsets.end(), [&](const Node& o) {
      return occupied[index({n[0] + o[0], n[1] + o[1], n[2] + o[2]})] == 0;
    });
  };
  std::vector<std::uint8_t> keep(sites.size(), 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < sites.size(); ++i) keep[i] = empty_node_within_reach(node[i]) ? 1 : 0;
  return keep;
}

void leave_out_rigid_interiors(ParticleSetup& setup, const std::vector<Eigen::Vector3d>& site, double reach) {
  std::vector<std::uint8_t> keep(setup.size(), 1);
  for (const BodySetup& body : setup.bodies) {
    if (body.kind != BodyKind::rigid) continue;
    const std::vector<std::uint8_t> within =
        sites_within_reach_of_surface(std::span(site).subspan(body.first, body.count),
                                      body.orientation.toRotationMatrix().transpose(), setup.spacing, reach);
    std::copy(within.begin(), within.end(), keep.begin() + static_cast<std::ptrdiff_t>(body.first));
  }
  std::size_t kept = 0;
  for (BodySetup& body : setup.bodies) {
    const std::size_t first = body.first, end = body.first + body.count;
    body.first = kept;
    for (std::size_t i = first; i < end; ++i) {
      if (!keep[i]) continue;
      setup.position[kept] = setup.position[i];
      setup.velocity[kept] = setup.velocity[i];
      setup.mass[kept] = setup.mass[i];
      setup.body[kept] = setup.body[i];
      setup.fixed[kept] = setup.fixed[i];
      setup.rest_offset[kept] = setup.rest_offset[i];
      ++kept;
    }
    body.count = kept - body.first;
  }
  setup.position.resize(kept);
  setup.velocity.resize(kept);
  setup.mass.resize(kept);
  setup.body.resize(kept);
  setup.fixed.resize(kept);
  setup.rest_offset.resize(kept);
}

}  // namespace mssph
