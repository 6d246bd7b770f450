#pragma once
// Corotated SPH elasticity of deformable particles (paper 3.1.2, eq. 4-6), float32, for the CUDA
// kernels and the host build: step 1 (rotations) with the elastic part of step 2 (strain, stress)
// in one pass, the elastic forces of step 3 in a second. Each equation is one function named as
// its float64 twin in cpu_reference/ (tests/equations/ checks each against it): eq. 4
// displacement_gradient, eq. 5 first_piola_kirchhoff (with cauchy_strain,
// green_saint_venant_strain, isotropic_stress) and stress_action, eq. 6 elastic_force_pair,
// plus velocity_gradient (from bond_sums_share's velocity sum), viscous_stress and viscous_stress_action
// (Kelvin-Voigt), zero_energy_force_pair and damping_force. Conventions and derivations are the reference's
// (cpu_reference/elasticity.hpp): (grad u)_ab = du_a/dX_b, d_ij = V0_j L_i grad W(X_i - X_j), K_i = V0_i R_i P_i, f_i =
// sum_j (K_i d_ij - K_j d_ji). The rest state (positions, volumes, corrections L_i, neighbours) comes from the
// reference's rest-state builder, converted to float; each bond's offset, weight and kernel gradient are derived from
// it as the passes read them (rest_bond), and L_i is applied once per particle. The material models (scene key `model`,
// src/config/elastic_model.hpp) are those of the reference's elastic_response(), with the equations and sources given
// there.
#include "config/elastic_model.hpp"
#include "mat3_store.hpp"
#include "particle_views.hpp"
#include "smoothing_kernels.hpp"

#include <cmath>
#include <cstddef>
#include <type_traits>

namespace mssph::kernels {

enum ModelCode : std::uint32_t { kSaintVenantKirchhoff = 0, kCorotatedLinear = 1, kNeoHookean = 2 };

// One per deformable body.
struct ElasticParameters {
  std::uint32_t first_particle;     // canonical index of the body's first particle
  std::uint32_t first_deformable;   // its index among deformable particles
  std::uint32_t model;              // ModelCode
  float lambda;                     // Lame lambda [Pa]
  float mu;                         // shear modulus [Pa]
  float young_modulus;              // E [Pa], scales the zero-energy control
  float zero_energy_stiffness;      // alpha [-], 0 = off
  float damping;                    // mass-proportional rate [1/s], 0 = off (bodies held by fixed regions)
  float retardation_time;           // tau = eta / E of the Kelvin-Voigt viscous stress [s], 0 = off
  float particle_mass;              // m = rho0 dx^3 [kg]
  float lowest_valid_volume_ratio;  // det F at or below which a particle is counted as past the model's range
};

// StressActions: Mat3Records on the host, Mat3Planes on the GPU (mat3_store.hpp says why); the
// passes below take either view.
template <class StressActions>
struct DeformableViewOf {
  const ElasticParameters* bodies;        // per deformable body
  const std::uint32_t* body_of;           // per deformable particle: index into bodies
  const std::uint32_t* bond_count;        // per deformable particle: its number of rest bonds
  const std::uint32_t* bond_neighbour;    // bond-major: the k-th rest neighbour (canonical index) of d at k * count + d
  const Vec4* rest;                       // per deformable particle: X_i in the kernels' frame [m], w: V0_i [m^3]
  const Mat3* correction;                 // per deformable particle: L_i (model/deformable_rest_state.hpp)
  SmoothingKernels smoothing;             // poly6 W (moment matrix, zero-energy weight), spiky grad W (d_ij)
  const Vec4* position;                   // canonical positions (read)
  const Vec4* velocity;                   // canonical velocities (read: viscous stress, damping)
  Quat* rotation;                         // R_i as a quaternion; read as the warm start, then written
  StressActions corrected_stress_action;  // K_i L_i, K_i = V0_i R_i P_i (world frame) [N m] (elastic_force says why)
  Mat3* deformation;                      // world-frame F_i = R_i (I + grad u_i), for the zero-energy control and
                                          // the logged volume ratio det F_i
  Vec4* elastic_force;                    // canonical order (non-deformable entries stay zero) [N]
  std::uint32_t count;                    // deformable particles
};
using HostDeformableView = DeformableViewOf<Mat3Records>;
using DeviceDeformableView = DeformableViewOf<Mat3Planes>;

// Rest neighbour j (deformable index dj) of deformable particle i, derived from their rest positions
// and volumes whenever a pass reads it: the bonds are the deformable passes' largest read, and a
// 4-byte neighbour index per bond moves a twelfth of a stored 48-byte record of offset, weights
// and both d's. The reference builds the same quantities once, in double
// (build_deformable_rest_state). The correction L_i of d_ij = V0_j L_i grad W(X_i - X_j) is not
// applied per bond: each pass takes it out of its sum (corrected_bond_sums, elastic_force).
struct RestBond {
  Vec3 offset;     // X_ij = X_j - X_i [m]
  float kernel;    // W_poly6(|X_ij|) [1/m^3]
  Vec3 grad_w;     // grad W_spiky(X_i - X_j) [1/m^4]
  float volume_j;  // V0_j [m^3]
};

template <class View>
MSSPH_HD RestBond rest_bond(const View& v, Vec4 rest_i, std::uint32_t dj) {
  const Vec4 rest_j = v.rest[dj];
  const Vec3 offset = xyz(rest_j) - xyz(rest_i);
  const float r2 = squared_norm(offset);
  return {offset, v.smoothing.poly6(r2), v.smoothing.spiky_gradient(-1.0f * offset, v.smoothing.pair_distance(r2)),
          rest_j.w};
}

// Deformable index of canonical particle j of `body`.
MSSPH_HD std::uint32_t deformable_index(const ElasticParameters& body, std::uint32_t j) {
  return body.first_deformable + (j - body.first_particle);
}
// Canonical index of deformable particle d of `body` (deformable_index's inverse).
MSSPH_HD std::uint32_t particle_index(const ElasticParameters& body, std::uint32_t d) {
  return body.first_particle + (d - body.first_deformable);
}

// The rotational part of A, the rotation R that maximises tr(R^T A) (the polar decomposition's),
// by Newton's method on that objective, starting from last step's rotation. Rotating R by a small
// omega changes the objective by omega . t - 1/2 omega^T H omega, with the torque
// t = sum_c r_c x a_c and H = tr(B) I - sym(B), B = A R^T = sum_c a_c r_c^T (r_c, a_c: columns of
// R and A), so the step is omega = H^-1 t, which converges quadratically near the solution.
// Mueller et al. 2016 ("A robust method to extract the rotational part of deformations") step by
// t / |tr(B)|, which replaces H by 3/2 of it near a rest shape and keeps a third of the error for
// the next iteration; their step stays a proper rotation and leaves the rotation about a line of
// neighbours as it is. Their step is taken where Newton's is not to be trusted: H not positive
// definite (a line of neighbours, some inverted neighbourhoods, warm starts far off) or a Newton
// step beyond kLargestNewtonStep (H nearly singular). Both are computed from t and B divided by
// |tr(B)|, so that no product overflows or underflows whatever the scale of A. The iteration
// stops when Mueller's step falls below twice float32's machine epsilon: near that, rounding in
// t and in the unit quaternion keeps it from shrinking.
inline constexpr float kRotationTolerance = 2.5e-7f;  // [rad]
inline constexpr float kLargestNewtonStep = 0.5f;     // [rad]
MSSPH_HD Quat extract_rotation(const Mat3& a, Quat q) {
  const Vec3 a0 = column(a, 0), a1 = column(a, 1), a2 = column(a, 2);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Mat3 r = rotation_matrix(q);
    const Vec3 r0 = column(r, 0), r1 = column(r, 1), r2 = column(r, 2);
    const float alignment = dot(r0, a0) + dot(r1, a1) + dot(r2, a2);  // tr(B)
    const float scale = 1.0f / (std::fabs(alignment) + 1e-30f);
    const Vec3 mueller_step = scale * (cross(r0, a0) + cross(r1, a1) + cross(r2, a2));
    const float mueller_angle = norm(mueller_step);
    if (mueller_angle <= kRotationTolerance) break;
    const Mat3 b = scale * (outer(a0, r0) + outer(a1, r1) + outer(a2, r2));
    Mat3 hessian = -0.5f * (b + transpose(b));  // H / |tr(B)|
    for (int k = 0; k < 3; ++k) hessian(k, k) += alignment * scale;
    const Mat3 adjugate = cofactor(hessian);  // symmetric, as the Hessian is
    const float det = dot(column(hessian, 0), column(adjugate, 0));
    const bool positive_definite = hessian(0, 0) > 0.0f && adjugate(2, 2) > 0.0f && det > 0.0f;  // Sylvester
    const Vec3 newton_step = (1.0f / det) * (adjugate * mueller_step);
    const float newton_angle = norm(newton_step);
    const bool trusted = positive_definite && newton_angle > 0.0f && newton_angle <= kLargestNewtonStep;
    const Vec3 omega = trusted ? newton_step : mueller_step;
    const float angle = trusted ? newton_angle : mueller_angle;
    q = normalized(axis_angle((1.0f / angle) * omega, angle) * q);
  }
  return q;
}

// What step 1 and eq. 4 need of deformable particle d's rest bonds, gathered in one pass: the
// moment matrix A = sum_j m_j W_ij x_ij X_ij^T and the two halves of eq. 4,
// sum_j x_ij d_ij^T and sum_j X_ij d_ij^T, each as (sum_j x_ij (V0_j grad W_ij)^T) L_i^T since
// d_ij = L_i V0_j grad W_ij: one product by L_i per particle instead of one per bond. Each half
// sums terms of size |X_ij| |d_ij| as the per-bond form does, so float32 rounding is of the same
// order; the bonds, the step's largest read, are read once instead of twice.
struct BondSums {
  Mat3 moment;
  Mat3 current_gradient;
  Mat3 rest_gradient;
};

// The deformable particles' bond loops are split like the neighbour sums (fluid_physics.hpp):
// lane `lane` of a team of `lanes` takes bonds lane, lane + lanes, ...; the host runs one lane.
// Lane `lane`'s share of deformable particle d's bond sums, before L_i^T (corrected_bond_sums).
// Given a Mat3* `velocity_sum` (bodies with a viscous modulus), the same pass also adds to it the
// share of eq. 4's operator on the velocities, sum_j v_ij (V0_j grad W_ij)^T, before L_i^T
// (velocity_gradient applies it): each bond is gathered and derived once for both sums. Whether
// it is given is known at compile time, so the other bodies' loop has no trace of it.
template <class View, class VelocitySum = std::nullptr_t>
MSSPH_HD BondSums bond_sums_share(const View& v, std::uint32_t d, std::uint32_t lane, std::uint32_t lanes,
                                  VelocitySum velocity_sum = nullptr) {
  constexpr bool with_velocities = !std::is_same_v<VelocitySum, std::nullptr_t>;
  static_assert(!with_velocities || std::is_same_v<VelocitySum, Mat3*>, "velocity_sum is a Mat3* or not given");
  const ElasticParameters& body = v.bodies[v.body_of[d]];
  const std::uint32_t i = particle_index(body, d);
  const Vec3 x_i = xyz(v.position[i]);
  Vec3 v_i{0, 0, 0};
  if constexpr (with_velocities) v_i = xyz(v.velocity[i]);
  BondSums sums{zero_mat3(), zero_mat3(), zero_mat3()};
  const Vec4 rest_i = v.rest[d];
  for (std::uint32_t k = lane; k < v.bond_count[d]; k += lanes) {
    const std::uint32_t j = v.bond_neighbour[k * v.count + d];  // bond-major: FloatScene::bond_count
    const RestBond bond = rest_bond(v, rest_i, deformable_index(body, j));
    const Vec3 x_ij = xyz(v.position[j]) - x_i;
    const Vec3 weighted_gradient = bond.volume_j * bond.grad_w;
    sums.moment = sums.moment + outer((body.particle_mass * bond.kernel) * x_ij, bond.offset);
    sums.current_gradient = sums.current_gradient + outer(x_ij, weighted_gradient);
    sums.rest_gradient = sums.rest_gradient + outer(bond.offset, weighted_gradient);
    if constexpr (with_velocities) *velocity_sum = *velocity_sum + outer(xyz(v.velocity[j]) - v_i, weighted_gradient);
  }
  return sums;
}

// The bond sums of all lanes with L_i^T applied to eq. 4's halves.
MSSPH_HD BondSums corrected_bond_sums(BondSums sums, const Mat3& correction) {
  const Mat3 correction_t = transpose(correction);
  sums.current_gradient = sums.current_gradient * correction_t;
  sums.rest_gradient = sums.rest_gradient * correction_t;
  return sums;
}

// Paper eq. 4, grad u_i = sum_j u_ji (x) d_ij with u_ji = R_i^T x_ij - X_ij, from the bond sums:
// grad u_i = R_i^T (sum_j x_ij d_ij^T) - sum_j X_ij d_ij^T (reference: displacement_gradient,
// which sums per bond). The paper prints V0_i where the quadrature weight is V0_j, inside d_ij.
MSSPH_HD Mat3 displacement_gradient(const Mat3& rotation, const BondSums& sums) {
  return transpose(rotation) * sums.current_gradient - sums.rest_gradient;
}

// The velocity gradient in i's rotated rest frame, grad v_i = R_i^T (sum_j v_ij (V0_j grad W_ij)^T) L_i^T
// from all lanes' velocity sums (bond_sums_share; reference: velocity_gradient, which sums per bond).
MSSPH_HD Mat3 velocity_gradient(const Mat3& rotation, const Mat3& velocity_sum, const Mat3& correction) {
  return transpose(rotation) * (velocity_sum * transpose(correction));
}

// Paper eq. 5's strain, in the two measures of the material models (reference: cauchy_strain,
// green_saint_venant_strain): eps = 1/2 (grad u + grad u^T) and
// E = eps + 1/2 grad u^T grad u = 1/2 (F^T F - I).
MSSPH_HD Mat3 cauchy_strain(const Mat3& grad_u) { return 0.5f * (grad_u + transpose(grad_u)); }
MSSPH_HD Mat3 green_saint_venant_strain(const Mat3& grad_u) {
  return cauchy_strain(grad_u) + 0.5f * (transpose(grad_u) * grad_u);
}

// Paper eq. 5's stress sigma = C eps = lambda tr(eps) I + 2 mu eps.
MSSPH_HD Mat3 isotropic_stress(const ElasticParameters& body, const Mat3& eps) {
  Mat3 stress = (2.0f * body.mu) * eps;
  const float pressure_like = body.lambda * trace(eps);
  stress(0, 0) += pressure_like;
  stress(1, 1) += pressure_like;
  stress(2, 2) += pressure_like;
  return stress;
}

// g(J) = dG/dJ of the Neo-Hookean volumetric energy G = lambda/2 (ln J)^2 - mu ln J, continued
// linearly below J_e = kNeoHookeanBarrierEnd (reference: neo_hookean_volumetric).
MSSPH_HD float neo_hookean_volumetric_derivative(const ElasticParameters& body, float j) {
  constexpr float je = static_cast<float>(kNeoHookeanBarrierEnd);
  const float x = j > je ? j : je;
  const float log_x = std::log(x);
  const float g = (body.lambda * log_x - body.mu) / x;
  if (j >= je) return g;
  const float curvature = (body.lambda * (1.0f - log_x) + body.mu) / (je * je);
  return g + curvature * (j - je);
}

// Paper eq. 5 up to its volumes: P = d psi / d(grad u) in the rotated rest frame, per material
// model (reference: first_piola_kirchhoff):
//   stvk: P = F C E with the Green-Saint-Venant strain E, the paper's (I + grad u^T) sigma in our
//         gradient convention;
//   corotated: P = C eps with the Cauchy strain eps;
//   neo_hookean: P = mu F + g(J) cof F (Bonet and Wood 2008, eq. 6.28).
MSSPH_HD Mat3 first_piola_kirchhoff(const ElasticParameters& body, const Mat3& grad_u) {
  const Mat3 f = identity_mat3() + grad_u;
  if (body.model == kNeoHookean) {
    const Mat3 cof = cofactor(f);
    const float j = dot(column(f, 0), column(cof, 0));
    return body.mu * f + neo_hookean_volumetric_derivative(body, j) * cof;
  }
  if (body.model == kCorotatedLinear) return isotropic_stress(body, cauchy_strain(grad_u));
  return f * isotropic_stress(body, green_saint_venant_strain(grad_u));
}

// Kelvin-Voigt viscous stress sigma_v = tau C : 1/2 (grad v + grad v^T), tau = eta / E (reference:
// viscous_stress, with its source), added to P.
MSSPH_HD Mat3 viscous_stress(const ElasticParameters& body, const Mat3& grad_v) {
  return body.retardation_time * isotropic_stress(body, cauchy_strain(grad_v));
}

// The viscous stress's share of K_i, V0_i R_i (I + grad u_i) sigma_v = V0_i F_i sigma_v with the
// world-frame F_i (reference: stress_action of viscous_first_piola, which says why F).
MSSPH_HD Mat3 viscous_stress_action(float rest_volume, const Mat3& world_deformation, const Mat3& viscous) {
  return rest_volume * (world_deformation * viscous);
}

// K_i = V0_i R_i P_i, the world-frame matrix through which i's strain energy acts on its
// neighbours (paper eq. 5: f_ji = -V0_i P_i d_ij, the 2 of eq. 5 cancelling the 1/2 of eq. 6;
// reference: stress_action).
MSSPH_HD Mat3 stress_action(float rest_volume, const Mat3& rotation, const Mat3& first_piola) {
  return rest_volume * (rotation * first_piola);
}

// The world-frame deformation gradient F_i = R_i (I + grad u_i) (reference:
// world_deformation_gradient), for the zero-energy control and the logged volume ratio det F_i.
MSSPH_HD Mat3 world_deformation_gradient(const Mat3& rotation, const Mat3& grad_u) {
  return rotation * (identity_mat3() + grad_u);
}

// Step 1 and the elastic part of step 2 for deformable particle d, from its bond sums (all lanes'
// shares added): R_i, grad u_i (eq. 4), P_i (eq. 5), K_i and F_i.
template <class View>
MSSPH_HD void store_rotation_and_stress(const View& v, std::uint32_t d, const BondSums& uncorrected) {
  const ElasticParameters& body = v.bodies[v.body_of[d]];
  const BondSums sums = corrected_bond_sums(uncorrected, v.correction[d]);
  const Quat q = extract_rotation(sums.moment, v.rotation[d]);
  const Mat3 rotation = rotation_matrix(q);
  const Mat3 grad_u = displacement_gradient(rotation, sums);
  v.rotation[d] = q;
  v.corrected_stress_action.store(
      d, stress_action(v.rest[d].w, rotation, first_piola_kirchhoff(body, grad_u)) * v.correction[d]);
  v.deformation[d] = world_deformation_gradient(rotation, grad_u);
}

// The Kelvin-Voigt stress of deformable particle d, whose body has a viscous modulus, added to its
// stored K_i L_i, from its velocity sum (all lanes' shares) and the R_i and F_i that
// store_rotation_and_stress stored: K_i = V0_i R_i (P_i + (I + grad u_i) sigma_v). Kept apart
// from the elastic stress so that scenes without viscosity run that function unchanged.
template <class View>
MSSPH_HD void add_viscous_stress(const View& v, std::uint32_t d, const Mat3& velocity_sum) {
  const ElasticParameters& body = v.bodies[v.body_of[d]];
  const Mat3 grad_v = velocity_gradient(rotation_matrix(v.rotation[d]), velocity_sum, v.correction[d]);
  v.corrected_stress_action.store(
      d, v.corrected_stress_action.load(d) +
             viscous_stress_action(v.rest[d].w, v.deformation[d], viscous_stress(body, grad_v)) * v.correction[d]);
}

// The same in one lane (the host).
template <class View>
MSSPH_HD void rotation_and_stress(const View& v, std::uint32_t d) {
  const bool viscous = v.bodies[v.body_of[d]].retardation_time > 0.0f;
  Mat3 velocity_sum = zero_mat3();
  store_rotation_and_stress(v, d, viscous ? bond_sums_share(v, d, 0, 1, &velocity_sum) : bond_sums_share(v, d, 0, 1));
  if (viscous) add_viscous_stress(v, d, velocity_sum);
}

// Paper eq. 6, one neighbour's term of the symmetrised elastic force on i:
// f_i = sum_j (-R_i f_ji + R_j f_ij) = sum_j (K_i d_ij - K_j d_ji) (reference: elastic_force_pair).
MSSPH_HD Vec3 elastic_force_pair(const Mat3& action_i, Vec3 d_ij, const Mat3& action_j, Vec3 d_ji) {
  return action_i * d_ij - action_j * d_ji;
}

// Zero-energy-mode control (Ganzenmueller 2015), one neighbour's force on i: the pair is pulled
// to where both neighbourhoods' deformations put it (reference: zero_energy_force_pair, with the
// formula's derivation),
//   delta = ((F_i + F_j) X_ij - 2 x_ij) . n,  f_i = -(alpha / 2) V0_i V0_j W(|X_ij|) E delta / |X_ij|^2 n.
// Needs |x_ij| > 0: coincident particles have no pair direction, and the caller skips them
// (the reference's twin returns zero for them). The test stays with the caller so that the
// GPU's compiler can fuse the force sum's multiply-add.
MSSPH_HD Vec3 zero_energy_force_pair(const Mat3& world_f_i, const Mat3& world_f_j, Vec3 rest_x_ij, Vec3 x_ij,
                                     float rest_volume_i, float rest_volume_j, float w_rest, float young_modulus,
                                     float alpha) {
  const float r = norm(x_ij);
  const Vec3 n = (1.0f / r) * x_ij;
  const float delta = dot((world_f_i + world_f_j) * rest_x_ij - 2.0f * x_ij, n);
  return (-0.5f * alpha * rest_volume_i * rest_volume_j * w_rest * young_modulus * delta / squared_norm(rest_x_ij)) * n;
}

// Mass-proportional damping f_i = -gamma m_i (v_i - v_ref) with v_ref = 0: on the float side
// only bodies held by fixed regions damp, against the world (reference: damping_force).
MSSPH_HD Vec3 damping_force(float rate, float mass, Vec3 velocity) { return (-rate * mass) * velocity; }

// Step 3 for deformable particle d: the elastic force of eq. 6, plus the zero-energy control and
// the mass-proportional damping when its body has them. With d_ij = V0_j L_i g and
// d_ji = -V0_i L_j g (g = grad W(X_i - X_j), the spiky gradient being odd), eq. 6's
// K_i d_ij - K_j d_ji is (K_i L_i) (V0_j g) - (K_j L_j) (-V0_i g): the pair function reads the
// stress actions with their corrections applied once per particle (rotation_and_stress).
// Lane `lane`'s share: its bonds' terms.
template <class View>
MSSPH_HD Vec3 elastic_force_share(const View& v, std::uint32_t d, std::uint32_t lane, std::uint32_t lanes) {
  const ElasticParameters& body = v.bodies[v.body_of[d]];
  const std::uint32_t i = particle_index(body, d);
  const Vec3 x_i = xyz(v.position[i]);
  const Mat3 k_i = v.corrected_stress_action.load(d);
  const Mat3 f_i = v.deformation[d];
  const Vec4 rest_i = v.rest[d];
  Vec3 force{0, 0, 0};
  for (std::uint32_t k = lane; k < v.bond_count[d]; k += lanes) {
    const std::uint32_t j = v.bond_neighbour[k * v.count + d];  // bond-major: FloatScene::bond_count
    const std::uint32_t dj = deformable_index(body, j);
    const RestBond bond = rest_bond(v, rest_i, dj);
    force += elastic_force_pair(k_i, bond.volume_j * bond.grad_w, v.corrected_stress_action.load(dj),
                                -rest_i.w * bond.grad_w);
    if (body.zero_energy_stiffness > 0.0f) {
      const Vec3 x_ij = xyz(v.position[j]) - x_i;
      if (norm(x_ij) > 0.0f) {
        force += zero_energy_force_pair(f_i, v.deformation[dj], bond.offset, x_ij, rest_i.w, bond.volume_j, bond.kernel,
                                        body.young_modulus, body.zero_energy_stiffness);
      }
    }
  }
  return force;
}

// Stores deformable particle d's elastic force from its bonds' terms (all lanes' shares added),
// with the damping.
template <class View>
MSSPH_HD void store_elastic_force(const View& v, std::uint32_t d, Vec3 force) {
  const ElasticParameters& body = v.bodies[v.body_of[d]];
  const std::uint32_t i = particle_index(body, d);
  if (body.damping > 0.0f) force += damping_force(body.damping, body.particle_mass, xyz(v.velocity[i]));
  v.elastic_force[i] = make_vec4(force, 0.0f);
}

// The same in one lane (the host).
template <class View>
MSSPH_HD void elastic_force(const View& v, std::uint32_t d) {
  store_elastic_force(v, d, elastic_force_share(v, d, 0, 1));
}

}  // namespace mssph::kernels
