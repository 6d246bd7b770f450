#include "float_scene.hpp"

#include "eigen_conversion.hpp"
#include "list_skin.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/wall_exclusion.hpp"
#include "util/errors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace mssph::kernels {
namespace {

Vec4 to_vec4(const Eigen::Vector3d& v) { return make_vec4(to_vec3(v), 0.0f); }

BodyKindCode kind_code(BodyKind kind) {
  switch (kind) {
    case BodyKind::fluid:
      return kFluid;
    case BodyKind::deformable:
      return kDeformable;
    case BodyKind::rigid:
      return kRigid;
    case BodyKind::boundary:
      return kBoundary;
  }
  return kBoundary;
}

Eigen::Vector3d to_eigen(const double v[3]) { return {v[0], v[1], v[2]}; }

// The SPH mass m_i of a body's particles, as the scene builder set it (the float backends keep
// one per body): throws if the body's particles differ.
double body_particle_mass(const ParticleSetup& setup, const BodySetup& body) {
  if (body.count == 0) return 0.0;
  const double m = setup.mass[body.first];
  for (std::size_t i = body.first; i < body.first + body.count; ++i) {
    if (setup.mass[i] != m) {
      throw InputError("body \"" + body.name +
                       "\": particles of different SPH masses; the float backends keep one per body");
    }
  }
  return m;
}

// The own-body number densities at rest of rigid, deformable and boundary particles and the rest
// bonds, volumes, corrections and Lame parameters of deformable bodies, computed once in double by
// the model's rest-state builder, so every backend starts from the same rest configuration.
void add_rest_state(const ParticleSetup& setup, FloatScene& scene) {
  bool any = false;
  for (const BodySetup& b : setup.bodies) any = any || has_own_rest_number_density(b.kind);
  if (!any) return;
  const DeformableRestState rest = build_deformable_rest_state(setup);
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    const BodySetup& body = setup.bodies[b];
    if (!has_own_rest_number_density(body.kind)) continue;
    scene.bodies[b].own_rest_offset = static_cast<std::uint32_t>(body.first - scene.own_rest_number_density.size());
    for (std::size_t i = body.first; i < body.first + body.count; ++i)
      scene.own_rest_number_density.push_back(static_cast<float>(rest.own_rest_number_density[i]));
  }
  std::vector<std::vector<std::uint32_t>> neighbours_of;  // per deformable particle
  for (std::size_t b = 0; b < setup.bodies.size(); ++b) {
    const BodySetup& body = setup.bodies[b];
    if (body.kind != BodyKind::deformable) continue;
    const Material& m = body.material;
    if (m.damping > 0.0 && body.fixed_count == 0) {
      throw InputError("body \"" + body.name +
                       "\": damping of a deformable body that no fixed region holds is available in the reference "
                       "backend only (use --backend reference, or hold the body with fixed_regions)");
    }
    ElasticParameters p{};
    p.first_particle = static_cast<std::uint32_t>(body.first);
    p.first_deformable = static_cast<std::uint32_t>(scene.deformable_body.size());
    p.model = m.model == ElasticModel::neo_hookean        ? kNeoHookean
              : m.model == ElasticModel::corotated_linear ? kCorotatedLinear
                                                          : kSaintVenantKirchhoff;
    // The model's values: the rest state's Lame parameters and the scene's particle mass.
    const LameParameters lame = body.count > 0 ? rest.lame[body.first] : LameParameters{};
    p.lambda = static_cast<float>(lame.lambda);
    p.mu = static_cast<float>(lame.mu);
    p.young_modulus = static_cast<float>(m.young_modulus);
    p.zero_energy_stiffness = static_cast<float>(m.zero_energy_stiffness);
    p.damping = static_cast<float>(m.damping);
    p.retardation_time = static_cast<float>(m.viscous_modulus / m.young_modulus);
    p.particle_mass = static_cast<float>(body_particle_mass(setup, body));
    p.lowest_valid_volume_ratio = static_cast<float>(lowest_valid_volume_ratio(m.model));
    const auto index = static_cast<std::uint32_t>(scene.elastic_bodies.size());
    scene.elastic_bodies.push_back(p);
    for (std::size_t i = body.first; i < body.first + body.count; ++i) {
      scene.deformable_body.push_back(index);
      scene.rest.push_back(make_vec4(scene.to_kernel_frame(rest.position[i]), static_cast<float>(rest.volume[i])));
      scene.correction.push_back(to_mat3(rest.correction[i]));
      std::vector<std::uint32_t>& neighbours = neighbours_of.emplace_back();
      for (std::size_t k = rest.neighbours.offsets[i]; k < rest.neighbours.offsets[i + 1]; ++k) {
        neighbours.push_back(static_cast<std::uint32_t>(rest.neighbours.indices[k]));
      }
    }
  }
  // Bond-major (FloatScene::bond_count), each particle's bonds in the reference's order.
  std::size_t longest = 0;
  for (const std::vector<std::uint32_t>& neighbours : neighbours_of) longest = std::max(longest, neighbours.size());
  const std::size_t deformables = neighbours_of.size();
  scene.bond_neighbour.assign(longest * deformables, 0u);
  for (std::size_t d = 0; d < deformables; ++d) {
    scene.bond_count.push_back(static_cast<std::uint32_t>(neighbours_of[d].size()));
    for (std::size_t k = 0; k < neighbours_of[d].size(); ++k)
      scene.bond_neighbour[k * deformables + d] = neighbours_of[d][k];
  }
}

}  // namespace

GridShape choose_grid_shape(const std::vector<Vec4>& positions, double h) {
  GridShape shape;
  shape.inverse_cell_size = static_cast<float>(1.0 / h);
  float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                 std::numeric_limits<float>::max()};
  float hi[3] = {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
                 std::numeric_limits<float>::lowest()};
  for (const Vec4& p : positions) {
    const float c[3] = {p.x, p.y, p.z};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], c[a]);
      hi[a] = std::max(hi[a], c[a]);
    }
  }
  std::uint32_t bits[3];
  for (int a = 0; a < 3; ++a) {
    const double cells = positions.empty() ? 4.0 : std::ceil((hi[a] - lo[a]) / h) + 3.0;
    bits[a] = static_cast<std::uint32_t>(std::bit_width(static_cast<std::uint64_t>(std::max(4.0, cells)) - 1));
  }
  // Cap the table near two cells per particle: beyond that the extra cells are empty anyway.
  const auto budget = static_cast<std::uint32_t>(std::bit_width(std::max<std::size_t>(2 * positions.size(), 64) - 1));
  while (bits[0] + bits[1] + bits[2] > std::max<std::uint32_t>(budget, 6)) {
    std::uint32_t* largest = std::max_element(bits, bits + 3);
    if (*largest <= 2) break;
    --*largest;
  }
  shape.bits_x = bits[0];
  shape.bits_y = bits[1];
  shape.bits_z = bits[2];
  // The scene's lowest cell along x takes key column 1, so that its rows of cells (from column 0)
  // do not wrap as long as the scene spans fewer than 2^bits_x - 2 cells (GridShape::origin_x).
  if (!positions.empty()) {
    int lowest_x, lowest_y, lowest_z;
    shape.cell_of(Vec3{lo[0], lo[1], lo[2]}, lowest_x, lowest_y, lowest_z);
    shape.origin_x = 1u - static_cast<std::uint32_t>(lowest_x);
  }
  return shape;
}

FloatScene make_float_scene(const ParticleSetup& setup) {
  FloatScene scene;
  scene.full_stress_viscosity = setup.viscosity_model == ViscosityModel::full_stress;
  scene.step.smoothing = SmoothingKernels::for_support(setup.smoothing_length);
  scene.step.dt = static_cast<float>(setup.dt);
  scene.step.gravity = to_vec3(setup.gravity);
  scene.step.inverse_rest_number_density = static_cast<float>(1.0 / setup.rest_number_density);
  scene.step.inverse_gradient_consistency = static_cast<float>(1.0 / setup.gradient_consistency);
  scene.step.wall_exclusion_distance = static_cast<float>(kWallExclusionFraction * setup.spacing);
  scene.step.particle_count = static_cast<std::uint32_t>(setup.size());

  if (setup.size() > 0) {
    Eigen::Vector3d lo = setup.position.front(), hi = setup.position.front();
    for (const Eigen::Vector3d& x : setup.position) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    scene.origin = 0.5 * (lo + hi);
  }
  scene.step.domain_min = scene.to_kernel_frame(setup.domain.min);
  scene.step.domain_max = scene.to_kernel_frame(setup.domain.max);

  for (const BodySetup& b : setup.bodies) {
    BodyParameters p{};
    p.kind = kind_code(b.kind);
    p.rigid_index = kNotRigid;
    p.sph_mass = static_cast<float>(body_particle_mass(setup, b));
    p.rest_density = static_cast<float>(b.material.rest_density);
    p.pressure_stiffness = static_cast<float>(b.material.pressure_stiffness);
    p.viscosity = static_cast<float>(b.material.viscosity);
    if (b.moves_as_rigid_body()) {
      p.rigid_index = static_cast<std::uint32_t>(scene.rigid_bodies.size());
      RigidBody r{};
      r.first = static_cast<std::uint32_t>(b.first);
      r.count = static_cast<std::uint32_t>(b.count);
      r.mass = static_cast<float>(b.mass);
      const Eigen::Matrix3d inverse = b.inertia_body.inverse();
      for (int k = 0; k < 9; ++k) r.inverse_inertia_body.m[k] = static_cast<float>(inverse(k / 3, k % 3));
      r.position = scene.to_kernel_frame(b.centre_of_mass);
      r.orientation = {static_cast<float>(b.orientation.x()), static_cast<float>(b.orientation.y()),
                       static_cast<float>(b.orientation.z()), static_cast<float>(b.orientation.w())};
      r.velocity = to_vec3(b.velocity);
      const Eigen::Matrix3d rot = b.orientation.toRotationMatrix();
      r.angular_momentum = to_vec3(rot * b.inertia_body * rot.transpose() * b.angular_velocity);
      scene.rigid_bodies.push_back(r);
    }
    scene.bodies.push_back(p);
  }

  const std::size_t n = setup.size();
  scene.position.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    scene.position.push_back(make_vec4(scene.to_kernel_frame(setup.position[i]), 0.0f));
    scene.velocity.push_back(to_vec4(setup.velocity[i]));
    scene.rest_offset.push_back(to_vec4(setup.rest_offset[i]));
    scene.body.push_back(setup.body[i]);
    scene.fixed.push_back(setup.fixed[i] ? kFixedRegion : kFree);
  }
  scene.grid = choose_grid_shape(scene.position, setup.smoothing_length);
  add_rest_state(setup, scene);
  return scene;
}

FloatScene make_float_scene_with_list_cells(const ParticleSetup& setup) {
  FloatScene scene = make_float_scene(setup);
  scene.grid = choose_grid_shape(scene.position, list_cell_size(setup.smoothing_length));
  scene.list_trigger2 = list_triggers2(scene.bodies, list_skin(scene.step.smoothing.h));
  return scene;
}

BodyState to_body_state(const FloatScene& scene, const BodySums& sums, const RigidBody* rigid, const BodySetup& body) {
  BodyState s;
  s.max_speed = std::sqrt(sums.max_speed);
  if (rigid) {
    s.mass = rigid->mass;
    s.centre_of_mass = scene.to_world(rigid->position);
    s.linear_momentum = rigid->mass * Eigen::Vector3d(rigid->velocity.x, rigid->velocity.y, rigid->velocity.z);
    s.angular_momentum = {rigid->angular_momentum.x, rigid->angular_momentum.y, rigid->angular_momentum.z};
    s.orientation =
        Eigen::Quaterniond(rigid->orientation.w, rigid->orientation.x, rigid->orientation.y, rigid->orientation.z);
    const Vec3 omega = angular_velocity(*rigid);
    s.angular_velocity = {omega.x, omega.y, omega.z};
    s.kinetic_energy =
        0.5 * s.linear_momentum.squaredNorm() / s.mass + 0.5 * s.angular_velocity.dot(s.angular_momentum);
    s.interaction_force = {rigid->interaction_force.x, rigid->interaction_force.y, rigid->interaction_force.z};
    s.interaction_torque = {rigid->interaction_torque.x, rigid->interaction_torque.y, rigid->interaction_torque.z};
    return s;
  }
  s.mass = sums.mass;
  const Eigen::Vector3d centre = to_eigen(sums.moment) / sums.mass;  // kernels' frame
  s.centre_of_mass = scene.origin + centre;
  s.linear_momentum = to_eigen(sums.momentum);
  // Shift from the kernels' origin to the centre of mass: L_c = L_o - c x p, tau_c = tau_o - c x F.
  s.angular_momentum = to_eigen(sums.angular_origin) - centre.cross(s.linear_momentum);
  s.kinetic_energy = sums.kinetic_energy;
  s.interaction_force = to_eigen(sums.force);
  s.interaction_torque = to_eigen(sums.torque_origin) - centre.cross(s.interaction_force);
  if (body.kind == BodyKind::rigid) s.orientation = body.orientation;  // a fixed rigid body
  if (body.kind == BodyKind::deformable && sums.min_volume_ratio < kNoVolumeRatio) {
    s.min_volume_ratio = sums.min_volume_ratio;
    s.compressed_count = static_cast<std::size_t>(sums.compressed_count);
  }
  s.left_domain_count = static_cast<std::size_t>(sums.left_domain_count);
  return s;
}

}  // namespace mssph::kernels
