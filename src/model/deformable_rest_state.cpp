#include "model/deformable_rest_state.hpp"

#include "model/smoothing_kernels.hpp"

#include <Eigen/SVD>

namespace mssph {

Eigen::Matrix3d kernel_gradient_correction(const Eigen::Matrix3d& b) {
  // Below this relative singular value a direction is unsampled: inverting it would amplify
  // rounding into forces.
  constexpr double kCutoff = 1e-6;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(b, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d sigma = svd.singularValues();
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    if (sigma(k) > kCutoff * sigma(0)) inverse(k) = 1.0 / sigma(k);
  }
  // B = U S V^T, B^+ = V S^+ U^T, L = (B^+)^T = U S^+ V^T.
  return svd.matrixU() * inverse.asDiagonal() * svd.matrixV().transpose();
}

namespace {

// Each particle's neighbours within h in its own body, itself included, as find_neighbours lists
// them (the same order within a body); none for a fluid particle, whose rest state holds nothing.
// Searched body by body: a fluid, often most of a scene, is never searched.
NeighbourLists same_body_neighbours(const ParticleSetup& setup, double h) {
  const std::size_t n = setup.size();
  std::vector<NeighbourLists> of_body(setup.bodies.size());
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    const BodySetup& body = setup.bodies[b];
    if (body.kind == BodyKind::fluid) continue;
    const auto first = setup.position.begin() + static_cast<std::ptrdiff_t>(body.first);
    of_body[b] = find_neighbours({first, first + static_cast<std::ptrdiff_t>(body.count)}, h);
  }
  NeighbourLists lists;
  lists.offsets.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const BodySetup& body = setup.bodies[setup.body[i]];
    const NeighbourLists& local = of_body[setup.body[i]];
    lists.offsets[i + 1] = lists.offsets[i] + (local.offsets.empty() ? 0 : local.count(i - body.first));
  }
  lists.indices.reserve(lists.offsets[n]);
  for (std::size_t i = 0; i < n; ++i) {
    const BodySetup& body = setup.bodies[setup.body[i]];
    const NeighbourLists& local = of_body[setup.body[i]];
    if (local.offsets.empty()) continue;
    for (const std::size_t* j = local.begin(i - body.first); j != local.end(i - body.first); ++j) {
      lists.indices.push_back(body.first + *j);
    }
  }
  return lists;
}

}  // namespace

DeformableRestState build_deformable_rest_state(const ParticleSetup& setup) {
  const std::size_t n = setup.size();
  const double h = setup.smoothing_length;
  const Poly6Kernel w(h);
  const SpikyGradient grad_w(h);
  DeformableRestState rest;
  rest.position = setup.position;
  rest.volume.assign(n, 0.0);
  rest.correction.assign(n, Eigen::Matrix3d::Identity());
  rest.lame.assign(n, LameParameters{});
  rest.own_rest_number_density.assign(n, 0.0);

  // Same-body pairs of deformable particles within h, self excluded.
  const NeighbourLists own_body = same_body_neighbours(setup, h);
  rest.neighbours.offsets.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    rest.neighbours.offsets[i + 1] = rest.neighbours.offsets[i];
    if (!is_deformable(setup, i)) continue;
    for (const std::size_t* j = own_body.begin(i); j != own_body.end(i); ++j) {
      if (*j == i) continue;
      rest.neighbours.indices.push_back(*j);
      ++rest.neighbours.offsets[i + 1];
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i)) continue;
    const Material& material = setup.bodies[setup.body[i]].material;
    rest.lame[i] = lame_parameters(material);
    double mass_density = setup.mass[i] * w(0.0);
    for (const std::size_t* j = rest.neighbours.begin(i); j != rest.neighbours.end(i); ++j) {
      mass_density += setup.mass[*j] * w((setup.position[*j] - setup.position[i]).squaredNorm());
    }
    rest.volume[i] = setup.mass[i] / mass_density;
  }

  // The own-body number density at rest, with the density pass's spiky kernel: over the same-body
  // neighbours in the order of the rest neighbours (for a deformable particle, they are those).
  const SpikyKernel w_density(h);
  for (std::size_t i = 0; i < n; ++i) {
    if (!has_own_rest_number_density(setup.bodies[setup.body[i]].kind)) continue;
    double delta = w_density(0.0);
    for (const std::size_t* j = own_body.begin(i); j != own_body.end(i); ++j) {
      if (*j == i) continue;
      delta += w_density((setup.position[*j] - setup.position[i]).norm());
    }
    rest.own_rest_number_density[i] = delta;
  }

  for (std::size_t i = 0; i < n; ++i) {
    if (!is_deformable(setup, i) || !setup.bodies[setup.body[i]].material.kernel_gradient_correction) continue;
    Eigen::Matrix3d b = Eigen::Matrix3d::Zero();
    for (const std::size_t* j = rest.neighbours.begin(i); j != rest.neighbours.end(i); ++j) {
      const Eigen::Vector3d rest_x_ij = setup.position[*j] - setup.position[i];
      b += rest.volume[*j] * rest_x_ij * grad_w(-rest_x_ij).transpose();
    }
    rest.correction[i] = kernel_gradient_correction(b);
  }

  rest.bonds.resize(rest.neighbours.indices.size());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
      const std::size_t j = rest.neighbours.indices[k];
      RestBond& bond = rest.bonds[k];
      bond.offset = setup.position[j] - setup.position[i];
      bond.kernel = w(bond.offset.squaredNorm());
      bond.moment_weight = setup.mass[j] * bond.kernel;
      bond.d_ij = rest_gradient(rest.volume[j], rest.correction[i], grad_w(-bond.offset));
      bond.d_ji = rest_gradient(rest.volume[i], rest.correction[j], grad_w(bond.offset));
    }
  }
  return rest;
}

}  // namespace mssph
