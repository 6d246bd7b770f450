// Paper eq. 4-6 with step 1's rotation, the Kelvin-Voigt viscous stress, the zero-energy control and
// the damping, float32
// (kernels/common/elastic_physics.hpp) against the float64 twins of the same names
// (cpu_reference/elasticity.hpp, elastic_forces.hpp, corotation.hpp, zero_energy_control.hpp,
// deformable_damping.hpp). Method and tolerance: twin_support.hpp. Lengths are those of a
// 2 cm lattice (h = 4 cm), moduli those of the scenes (E up to 1e6 Pa, Poisson ratio up to 0.45).
#include "common/elastic_physics.hpp"
#include "corotation.hpp"
#include "deformable_damping.hpp"
#include "elastic_forces.hpp"
#include "elasticity.hpp"
#include "model/deformable_rest_state.hpp"
#include "model/smoothing_kernels.hpp"
#include "twin_support.hpp"
#include "zero_energy_control.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace mssph::testing {
namespace {

constexpr double kSupport = 0.04;  // h [m]

// Lame parameters from E in [1e3, 1e6] Pa and nu in [0, 0.45], as float32 values.
LameParameters draw_lame(TwinDraws& draws) {
  const double e = draws.uniform(1e3, 1e6), nu = draws.uniform(0.0, 0.45);
  return {TwinDraws::rounded(e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))), TwinDraws::rounded(e / (2.0 * (1.0 + nu)))};
}

kernels::ElasticParameters float_body(const LameParameters& lame, ElasticModel model) {
  kernels::ElasticParameters body{};
  body.model = model == ElasticModel::neo_hookean        ? kernels::kNeoHookean
               : model == ElasticModel::corotated_linear ? kernels::kCorotatedLinear
                                                         : kernels::kSaintVenantKirchhoff;
  body.lambda = static_cast<float>(lame.lambda);
  body.mu = static_cast<float>(lame.mu);
  return body;
}

// A rest offset X_ij inside the support, not closer than 0.2 h.
Eigen::Vector3d draw_rest_offset(TwinDraws& draws) {
  for (;;) {
    const Eigen::Vector3d x = draws.vector(kSupport);
    if (x.norm() < kSupport && x.norm() > 0.2 * kSupport) return x;
  }
}

// Deformable particle 0 and its rest bonds to particles 1..n, deformed by R (I + G) plus noise,
// held in both precisions' data structures. The rest state (positions, volumes, corrections) is
// drawn; the reference's bonds are built from it by build_deformable_rest_state's formulas, the
// float code derives its own as it reads them (kernels::rest_bond).
struct Neighbourhood {
  DeformableRestState rest;
  std::vector<Eigen::Vector3d> positions;
  double moment_scale = 0.0;    // sum_j m_j W_ij |x_ij| |X_ij|
  double gradient_scale = 0.0;  // sum_j (|x_ij| + |X_ij|) |d_ij|

  kernels::ElasticParameters body{};
  std::vector<std::uint32_t> body_of, bond_count, bond_neighbour;
  std::vector<kernels::Vec4> position, rest_float;
  std::vector<kernels::Mat3> correction;
  std::vector<Eigen::Vector3d> velocities;  // empty unless add_velocities drew them
  std::vector<kernels::Vec4> velocity;
  double velocity_gradient_scale = 0.0;  // sum_j |v_ij| |d_ij|

  kernels::HostDeformableView view() const {
    kernels::HostDeformableView v{};
    v.bodies = &body;
    v.body_of = body_of.data();
    v.bond_count = bond_count.data();
    v.bond_neighbour = bond_neighbour.data();  // one deformable particle with bonds: bond k at k
    v.rest = rest_float.data();
    v.correction = correction.data();
    v.smoothing = kernels::SmoothingKernels::for_support(kSupport);
    v.position = position.data();
    v.velocity = velocity.empty() ? nullptr : velocity.data();
    v.count = 1;
    return v;
  }
};

Neighbourhood draw_neighbourhood(TwinDraws& draws, const Eigen::Matrix3d& rotation) {
  Neighbourhood n;
  const int bonds = static_cast<int>(draws.uniform(8.0, 41.0));
  const Eigen::Matrix3d deformation = rotation * (Eigen::Matrix3d::Identity() + draws.matrix(0.5));
  const double mass = TwinDraws::rounded(draws.uniform(1e-3, 1e-1));
  n.body.particle_mass = static_cast<float>(mass);
  const Eigen::Vector3d rest_i = TwinDraws::rounded(draws.vector(1.0));
  const Eigen::Vector3d x_i = draws.vector(1.0);
  std::vector<Eigen::Vector3d> rest_positions{rest_i};
  for (int j = 1; j <= bonds; ++j) rest_positions.push_back(TwinDraws::rounded(rest_i + draw_rest_offset(draws)));
  // Volumes of a 2 cm lattice within a factor 2, corrections within 30 % of the identity.
  for (int j = 0; j <= bonds; ++j) {
    n.rest.volume.push_back(TwinDraws::rounded(draws.uniform(0.5, 2.0) * 8e-6));
    n.rest.correction.push_back(TwinDraws::rounded(Eigen::Matrix3d(Eigen::Matrix3d::Identity() + draws.matrix(0.3))));
    n.rest_float.push_back(
        to_float4(rest_positions[static_cast<std::size_t>(j)], static_cast<float>(n.rest.volume.back())));
    n.correction.push_back(to_float(n.rest.correction.back()));
    n.body_of.push_back(0);
  }
  const Poly6Kernel w(kSupport);
  const SpikyGradient grad_w(kSupport);
  n.positions.push_back(x_i);
  n.rest.neighbours.offsets = {0, static_cast<std::size_t>(bonds)};
  n.bond_count = {static_cast<std::uint32_t>(bonds)};
  n.position.push_back(to_float4(x_i, 0.0f));
  for (int j = 1; j <= bonds; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    RestBond bond;
    bond.offset = rest_positions[uj] - rest_i;
    bond.kernel = w(bond.offset.squaredNorm());
    bond.moment_weight = mass * bond.kernel;
    bond.d_ij = rest_gradient(n.rest.volume[uj], n.rest.correction[0], grad_w(-bond.offset));
    bond.d_ji = rest_gradient(n.rest.volume[0], n.rest.correction[uj], grad_w(bond.offset));
    const Eigen::Vector3d x_j = TwinDraws::rounded(x_i + deformation * bond.offset + draws.vector(0.05 * kSupport));
    n.positions.push_back(x_j);
    n.rest.neighbours.indices.push_back(uj);
    n.rest.bonds.push_back(bond);
    n.position.push_back(to_float4(x_j, 0.0f));
    n.bond_neighbour.push_back(static_cast<std::uint32_t>(j));
    const double x_ij = (x_j - x_i).norm();
    n.moment_scale += bond.moment_weight * x_ij * bond.offset.norm();
    n.gradient_scale += (x_ij + bond.offset.norm()) * bond.d_ij.norm();
  }
  return n;
}

// Velocities up to 2 m/s for particle 0 and its neighbours, and a retardation time (the body is
// viscous).
void add_velocities(TwinDraws& draws, Neighbourhood& n) {
  n.body.retardation_time = static_cast<float>(draws.uniform(1e-4, 1e-2));
  for (const Eigen::Vector3d& x : n.positions) {
    (void)x;
    n.velocities.push_back(draws.vector(2.0));
    n.velocity.push_back(to_float4(n.velocities.back(), 0.0f));
  }
  for (std::size_t b = 0; b < n.rest.bonds.size(); ++b) {
    n.velocity_gradient_scale += (n.velocities[b + 1] - n.velocities[0]).norm() * n.rest.bonds[b].d_ij.norm();
  }
}

// The rest bond the float code derives as it reads it (kernels::rest_bond: X_ij, W and the kernel
// gradient g = grad W(X_i - X_j)) against the reference's, built once in double from the same rest
// state (build_deformable_rest_state's formulas): d_ij = L_i (V0_j g) and d_ji = -L_j (V0_i g),
// the forms the float passes use with L applied once per particle.
TEST(ElasticEquationTwins, RestBondFromTheRestState) {
  TwinDraws draws("ElasticEquationTwins.RestBondFromTheRestState");
  // The offsets fill the support uniformly, so about a third lie where W and grad W are below 1 %
  // of their peaks (the "informative" bar): half the draws above it still let the check fail.
  TwinComparison d_ij("d_ij = V0_j L_i grad W(X_i - X_j)", 0.5);
  TwinComparison d_ji("d_ji = V0_i L_j grad W(X_j - X_i)", 0.5);
  TwinComparison kernel("W_poly6(|X_ij|) of the moment matrix", 0.5);
  // Scales: the kernel's peak W(0) and the largest d a bond can have, V0 |L| max |grad W| with
  // max |grad W| = 45 / (pi h^4). Near the support's edge W and grad W vanish as (h - r)^2 and
  // (h^2 - r^2)^3: the float code forms h^2 - r^2 from a float r^2, so relative to the vanishing
  // value itself its error grows without bound while staying of float32 rounding against the
  // values the sums add it to.
  const double peak_w = Poly6Kernel(kSupport)(0.0);
  const double peak_grad_w = 45.0 / (std::numbers::pi * std::pow(kSupport, 4));
  for (int k = 0; k < kDraws; ++k) {
    const Neighbourhood n = draw_neighbourhood(draws, Eigen::Matrix3d::Identity());
    const kernels::HostDeformableView v = n.view();
    for (std::size_t b = 0; b < n.rest.bonds.size(); ++b) {
      const RestBond& expected = n.rest.bonds[b];
      const std::uint32_t j = n.bond_neighbour[b];
      const kernels::RestBond bond = kernels::rest_bond(v, v.rest[0], j);
      const Eigen::Vector3d g = to_double(bond.grad_w);
      d_ij.add(to_double(v.correction[0]) * (static_cast<double>(bond.volume_j) * g), expected.d_ij,
               n.rest.volume[j] * n.rest.correction[0].norm() * peak_grad_w);
      d_ji.add(-(to_double(v.correction[j]) * (static_cast<double>(v.rest[0].w) * g)), expected.d_ji,
               n.rest.volume[0] * n.rest.correction[j].norm() * peak_grad_w);
      kernel.add(bond.kernel, expected.kernel, peak_w);
    }
  }
}

// Step 1's moment matrix and eq. 4: kernels::bond_sums_share gathers A_i and eq. 4's two halves
// in one pass; reference::moment_matrix and reference::displacement_gradient sum per bond. One
// lane takes every bond (the host); a team of 3 lanes (the GPU uses 1 to 8) splits them, and
// their shares added must be the same sums.
TEST(ElasticEquationTwins, MomentMatrixAndDisplacementGradient) {
  TwinDraws draws("ElasticEquationTwins.MomentMatrixAndDisplacementGradient");
  TwinComparison moment("moment matrix A_i (step 1)");
  TwinComparison gradient("displacement gradient (eq. 4)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d rotation = draws.rotation();
    const Neighbourhood n = draw_neighbourhood(draws, rotation);
    for (const std::uint32_t lanes : {1u, 3u}) {
      kernels::BondSums team{kernels::zero_mat3(), kernels::zero_mat3(), kernels::zero_mat3()};
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        const kernels::BondSums share = kernels::bond_sums_share(n.view(), 0, lane, lanes);
        team = {team.moment + share.moment, team.current_gradient + share.current_gradient,
                team.rest_gradient + share.rest_gradient};
      }
      const kernels::BondSums sums = kernels::corrected_bond_sums(team, n.correction[0]);
      moment.add(to_double(sums.moment), reference::moment_matrix(n.rest, n.positions, 0), n.moment_scale);
      gradient.add(to_double(kernels::displacement_gradient(to_float(rotation), sums)),
                   reference::displacement_gradient(rotation, n.rest, n.positions, 0), n.gradient_scale);
    }
  }
}

// The velocity gradient of the Kelvin-Voigt stress, grad v_i = R_i^T sum_j v_ij d_ij^T: the
// float code's lanes (one, and a team of 3) gather sum_j v_ij (V0_j grad W_ij)^T in their pass
// over the bonds (bond_sums_share, whose bond sums must not change with it) and apply L_i^T once,
// the reference sums per bond.
TEST(ElasticEquationTwins, VelocityGradient) {
  TwinDraws draws("ElasticEquationTwins.VelocityGradient");
  TwinComparison gradient("velocity gradient grad v_i (Kelvin-Voigt strain rate)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d rotation = draws.rotation();
    Neighbourhood n = draw_neighbourhood(draws, rotation);
    add_velocities(draws, n);
    for (const std::uint32_t lanes : {1u, 3u}) {
      kernels::Mat3 velocity_sum = kernels::zero_mat3();
      for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        kernels::Mat3 share = kernels::zero_mat3();  // each lane's own, added as the GPU's team does
        const kernels::BondSums with = kernels::bond_sums_share(n.view(), 0, lane, lanes, &share);
        velocity_sum = velocity_sum + share;
        const kernels::BondSums without = kernels::bond_sums_share(n.view(), 0, lane, lanes);
        for (int e = 0; e < 9; ++e) {
          ASSERT_EQ(with.moment.m[e], without.moment.m[e]);
          ASSERT_EQ(with.current_gradient.m[e], without.current_gradient.m[e]);
          ASSERT_EQ(with.rest_gradient.m[e], without.rest_gradient.m[e]);
        }
      }
      gradient.add(to_double(kernels::velocity_gradient(to_float(rotation), velocity_sum, n.correction[0])),
                   reference::velocity_gradient(rotation, n.rest, n.velocities, 0), n.velocity_gradient_scale);
    }
  }
}

// Step 1: the float code's rotation extraction (Newton's method on tr(R^T A)) and the
// reference's polar decomposition by SVD agree on A = R S, S symmetric positive definite,
// warm-started 0.3 rad away, after one call (20 iterations at most), for stretches up to 25 % and
// up to a factor 2 (one axis squeezed to half, another doubled). Mueller et al.'s fixed step,
// which the extraction keeps where Newton's is not to be trusted, fails the second case in one
// call: it takes a third or more of the error into each next iteration.
TEST(ElasticEquationTwins, RotationOfTheMomentMatrix) {
  TwinDraws draws("ElasticEquationTwins.RotationOfTheMomentMatrix");
  struct Case {
    double largest_stretch;
    const char* name;
  };
  // A function that returned its warm start would be off by |R(0.3 rad) - I| = 0.42 (scale 1).
  for (const Case c :
       {Case{1.25, "R_i from A_i (step 1), stretches to 1.25"}, Case{2.0, "R_i from A_i (step 1), stretches to 2"}}) {
    const double largest_stretch = c.largest_stretch;
    TwinComparison rotation(c.name);
    for (int k = 0; k < kDraws; ++k) {
      const Eigen::Quaterniond q = draws.quaternion();
      const Eigen::Matrix3d axes = draws.rotation();
      const Eigen::Vector3d stretch(draws.uniform(1.0 / largest_stretch, largest_stretch),
                                    draws.uniform(1.0 / largest_stretch, largest_stretch),
                                    draws.uniform(1.0 / largest_stretch, largest_stretch));
      const double size = draws.uniform(1e-6, 1.0);
      const Eigen::Matrix3d a =
          TwinDraws::rounded(size * q.toRotationMatrix() * axes * stretch.asDiagonal() * axes.transpose());
      const Eigen::Vector3d axis = draws.vector(1.0).normalized();
      const Eigen::Quaterniond start = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, axis)) * q;
      const Eigen::Matrix3d expected = reference::rotation_from_moment_matrix(a, start.toRotationMatrix());
      const kernels::Quat got = kernels::extract_rotation(to_float(a), to_float(start));
      rotation.add(to_double(kernels::rotation_matrix(got)), expected, 1.0);
    }
  }
}

// Step 1 where Newton's step is not to be trusted: the float extraction returns what the
// reference's polar decomposition returns, a proper rotation. Flat (one layer, rank 2), 0.3 rad
// off: Q. Inverted (det A < 0), 0.3 rad off: the identity, not a reflection. A Hessian that fails
// Sylvester's second minor at the start (its first minor and determinant positive): the
// reference's rotation. Nearly on a line (stretches 1, 0.01, 0.01), 0.3 rad off, where H is
// nearly singular and an unbounded Newton step turns by up to pi: the reference's rotation. On a
// line: the line goes to Q's image of it. Empty: the warm start. Tolerances: 1e-5, float32
// rounding of a rotation (as kTolerance); 1e-4 nearly on a line, where rounding of A's 1 %
// directions (1e-7 of |A|) moves the rotation about the line by ~1e-5; 1e-6 on a quaternion's norm
// and on the empty case, which returns its start rounded to float.
TEST(ElasticEquationTwins, RotationWhereNewtonsStepIsNotTrusted) {
  TwinDraws draws("ElasticEquationTwins.RotationWhereNewtonsStepIsNotTrusted");
  const Eigen::Matrix3d q = Eigen::AngleAxisd(2.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  auto off_by_0_3_rad = [](const Eigen::Quaterniond& start) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized())) * start;
  };
  auto rotation_of = [](const Eigen::Matrix3d& a, const Eigen::Quaterniond& start) {
    const kernels::Quat got = kernels::extract_rotation(to_float(a), to_float(start));
    EXPECT_NEAR(to_double(got).norm(), 1.0, 1e-6) << "not a unit quaternion";
    return to_double(kernels::rotation_matrix(got));
  };
  Eigen::Matrix3d flat = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& rest :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(-1, 0.5, 0), Eigen::Vector3d(0.3, -1, 0)}) {
    flat += reference::moment_matrix_term(0.7, q * rest, rest);
  }
  EXPECT_LT((rotation_of(flat, off_by_0_3_rad(Eigen::Quaterniond(q))) - q).norm(), 1e-5) << "flat";

  const Eigen::Matrix3d inverted = Eigen::Vector3d(3.0, 2.0, -1.0).asDiagonal();
  const Eigen::Matrix3d from_inverted = rotation_of(inverted, off_by_0_3_rad(Eigen::Quaterniond::Identity()));
  EXPECT_LT((from_inverted - Eigen::Matrix3d::Identity()).norm(), 1e-5) << "inverted";

  // From R = I, H = tr(S) I - S for the symmetric part S of A: H = [[1, 2, 0], [2, -1, 0], [0, 0, -1]].
  Eigen::Matrix3d indefinite;
  indefinite << -1.5, -2.0, 0.1, -2.0, 0.5, 0.0, -0.1, 0.0, 0.5;
  EXPECT_LT((rotation_of(indefinite, Eigen::Quaterniond::Identity()) -
             reference::rotation_from_moment_matrix(indefinite, Eigen::Matrix3d::Identity()))
                .norm(),
            1e-5)
      << "indefinite Hessian";

  for (int k = 0; k < 200; ++k) {
    const Eigen::Quaterniond turn = draws.quaternion();
    const Eigen::Matrix3d axes = draws.rotation();
    const Eigen::Matrix3d nearly_linear =
        turn.toRotationMatrix() * axes * Eigen::Vector3d(1.0, 0.01, 0.01).asDiagonal() * axes.transpose();
    EXPECT_LT((rotation_of(nearly_linear, off_by_0_3_rad(turn)) - turn.toRotationMatrix()).norm(), 1e-4)
        << "nearly on a line, draw " << k;
  }

  const Eigen::Vector3d line(1.0, 0.0, 0.0);
  const Eigen::Matrix3d linear =
      reference::moment_matrix_term(1.0, q * line, line) + reference::moment_matrix_term(1.0, -q * line, -line);
  EXPECT_LT((rotation_of(linear, Eigen::Quaterniond::Identity()) * line - q * line).norm(), 1e-5) << "linear";

  const Eigen::Quaterniond start = off_by_0_3_rad(Eigen::Quaterniond(q));
  EXPECT_LT((rotation_of(Eigen::Matrix3d::Zero(), start) - start.toRotationMatrix()).norm(), 1e-6) << "empty";
}

TEST(ElasticEquationTwins, Strains) {
  TwinDraws draws("ElasticEquationTwins.Strains");
  TwinComparison cauchy("Cauchy strain (eq. 5, corotated)");
  TwinComparison green("Green-Saint-Venant strain (eq. 5)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d grad_u = draws.matrix(0.5);
    const double size = grad_u.norm();
    cauchy.add(to_double(kernels::cauchy_strain(to_float(grad_u))), reference::cauchy_strain(grad_u), size);
    green.add(to_double(kernels::green_saint_venant_strain(to_float(grad_u))),
              reference::green_saint_venant_strain(grad_u), size * (1.0 + size));
  }
}

TEST(ElasticEquationTwins, IsotropicStress) {
  TwinDraws draws("ElasticEquationTwins.IsotropicStress");
  TwinComparison stress("sigma = C eps (eq. 5)");
  for (int k = 0; k < kDraws; ++k) {
    const LameParameters lame = draw_lame(draws);
    const Eigen::Matrix3d eps = draws.matrix(0.2);
    const Eigen::Matrix3d eps_symmetric = TwinDraws::rounded(0.5 * (eps + eps.transpose()));
    stress.add(to_double(kernels::isotropic_stress(float_body(lame, ElasticModel::saint_venant_kirchhoff),
                                                   to_float(eps_symmetric))),
               reference::isotropic_stress(eps_symmetric, lame),
               (3.0 * lame.lambda + 2.0 * lame.mu) * eps_symmetric.norm());
  }
}

// sigma_v = tau C : 1/2 (grad v + grad v^T) with tau up to 0.1 s and strain rates up to 10 /s.
TEST(ElasticEquationTwins, ViscousStress) {
  TwinDraws draws("ElasticEquationTwins.ViscousStress");
  TwinComparison stress("Kelvin-Voigt viscous stress sigma_v");
  for (int k = 0; k < kDraws; ++k) {
    const LameParameters lame = draw_lame(draws);
    const Eigen::Matrix3d grad_v = draws.matrix(10.0);
    const double tau = draws.uniform(1e-5, 0.1);
    kernels::ElasticParameters body = float_body(lame, ElasticModel::saint_venant_kirchhoff);
    body.retardation_time = static_cast<float>(tau);
    stress.add(to_double(kernels::viscous_stress(body, to_float(grad_v))),
               reference::viscous_stress(grad_v, lame, static_cast<double>(body.retardation_time)),
               tau * (3.0 * lame.lambda + 2.0 * lame.mu) * grad_v.norm());
  }
}

// The viscous stress's share of K_i: the float code's V0_i F_i sigma_v from the world-frame F_i
// against the reference's V0_i R_i (I + grad u_i) sigma_v (stress_action of viscous_first_piola),
// with gradients up to 0.5 and viscous stresses up to 1e4 Pa.
TEST(ElasticEquationTwins, ViscousStressAction) {
  TwinDraws draws("ElasticEquationTwins.ViscousStressAction");
  TwinComparison action("V0 R (I + grad u) sigma_v (Kelvin-Voigt)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d rotation = draws.rotation();
    const Eigen::Matrix3d grad_u = draws.matrix(0.5);
    const Eigen::Matrix3d viscous = draws.matrix(1e4);
    const double volume = draws.uniform(1e-6, 1e-5);
    const Eigen::Matrix3d world_f =
        TwinDraws::rounded(Eigen::Matrix3d(rotation * (Eigen::Matrix3d::Identity() + grad_u)));
    action.add(
        to_double(kernels::viscous_stress_action(static_cast<float>(volume), to_float(world_f), to_float(viscous))),
        reference::stress_action(volume, rotation, reference::viscous_first_piola(grad_u, viscous)),
        volume * (1.0 + grad_u.norm()) * viscous.norm());
  }
}

// Eq. 5's P for each material model, on gradients up to 0.5 and, for Neo-Hookean, compressions
// down to J = 0.02, past the barrier's end J = 0.1 where the continued energy takes over.
TEST(ElasticEquationTwins, FirstPiolaKirchhoff) {
  TwinDraws draws("ElasticEquationTwins.FirstPiolaKirchhoff");
  for (const ElasticModel model :
       {ElasticModel::saint_venant_kirchhoff, ElasticModel::corotated_linear, ElasticModel::neo_hookean}) {
    TwinComparison piola(std::string("P (eq. 5), ") + to_string(model));
    int past_barrier = 0;
    for (int k = 0; k < kDraws; ++k) {
      const LameParameters lame = draw_lame(draws);
      Eigen::Matrix3d grad_u = draws.matrix(0.5);
      if (model == ElasticModel::neo_hookean && k % 2 == 1) {  // squeezed along z
        grad_u = TwinDraws::rounded(0.1 * grad_u);
        grad_u(2, 2) = draws.uniform(-0.98, -0.5);
      }
      const Eigen::Matrix3d f = Eigen::Matrix3d::Identity() + grad_u;
      double scale = 0.0;
      if (model == ElasticModel::neo_hookean) {
        // P = mu F + g(J) cof F: each term's size.
        const double j = f.determinant();
        if (j < kNeoHookeanBarrierEnd) ++past_barrier;
        const double g = reference::neo_hookean_volumetric(j, lame).derivative;
        scale = lame.mu * f.norm() + std::abs(g) * (j * f.inverse().transpose()).norm();
      } else {
        // P = F C E or C eps: |F| (3 lambda + 2 mu) |E|.
        scale = f.norm() * (3.0 * lame.lambda + 2.0 * lame.mu) * grad_u.norm() * (1.0 + grad_u.norm());
      }
      piola.add(to_double(kernels::first_piola_kirchhoff(float_body(lame, model), to_float(grad_u))),
                reference::first_piola_kirchhoff(grad_u, lame, model), scale);
    }
    if (model == ElasticModel::neo_hookean) {
      EXPECT_GT(past_barrier, kDraws / 20);
    }
  }
}

TEST(ElasticEquationTwins, StressActionAndWorldDeformationGradient) {
  TwinDraws draws("ElasticEquationTwins.StressActionAndWorldDeformationGradient");
  TwinComparison action("K_i = V0_i R_i P_i (eq. 5, 6)");
  TwinComparison deformation("F_i = R_i (I + grad u_i)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d rotation = draws.rotation();
    const Eigen::Matrix3d first_piola = draws.matrix(1e5);
    const double rest_volume = draws.uniform(1e-6, 1e-4);
    action.add(
        to_double(kernels::stress_action(static_cast<float>(rest_volume), to_float(rotation), to_float(first_piola))),
        reference::stress_action(rest_volume, rotation, first_piola), rest_volume * first_piola.norm());
    const Eigen::Matrix3d grad_u = draws.matrix(0.5);
    deformation.add(to_double(kernels::world_deformation_gradient(to_float(rotation), to_float(grad_u))),
                    reference::world_deformation_gradient(rotation, grad_u),
                    (Eigen::Matrix3d::Identity() + grad_u).norm());
  }
}

TEST(ElasticEquationTwins, ElasticForcePair) {
  TwinDraws draws("ElasticEquationTwins.ElasticForcePair");
  TwinComparison force("elastic force pair (eq. 6)");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d action_i = draws.matrix(0.1), action_j = draws.matrix(0.1);
    const Eigen::Vector3d d_ij = draws.vector(2.0 / kSupport), d_ji = draws.vector(2.0 / kSupport);
    force.add(
        to_double(kernels::elastic_force_pair(to_float(action_i), to_float(d_ij), to_float(action_j), to_float(d_ji))),
        reference::elastic_force_pair(action_i, d_ij, action_j, d_ji),
        action_i.norm() * d_ij.norm() + action_j.norm() * d_ji.norm());
  }
}

// Ganzenmueller 2015's pair force on pairs displaced by up to 30 % of |X_ij| from where the two
// neighbourhoods' deformations put them.
TEST(ElasticEquationTwins, ZeroEnergyForcePair) {
  TwinDraws draws("ElasticEquationTwins.ZeroEnergyForcePair");
  TwinComparison force("zero-energy control pair force");
  for (int k = 0; k < kDraws; ++k) {
    const Eigen::Matrix3d rotation = draws.rotation();
    const Eigen::Matrix3d f_i = TwinDraws::rounded(rotation * (Eigen::Matrix3d::Identity() + draws.matrix(0.2)));
    const Eigen::Matrix3d f_j = TwinDraws::rounded(rotation * (Eigen::Matrix3d::Identity() + draws.matrix(0.2)));
    const Eigen::Vector3d rest = draw_rest_offset(draws);
    const Eigen::Vector3d x_ij = TwinDraws::rounded(f_i * rest + draws.vector(0.3 * rest.norm()));
    const double volume_i = draws.uniform(1e-6, 1e-4), volume_j = draws.uniform(1e-6, 1e-4);
    const double w = draws.uniform(0.0, 1.0) * 315.0 / (64.0 * 3.14159265358979 * std::pow(kSupport, 3));
    const double w_float = TwinDraws::rounded(w);
    const double young = draws.uniform(1e3, 1e6), alpha = draws.uniform(0.01, 1.0);
    // The reference takes V0_i V0_j as one product (exact in double for float inputs).
    const Eigen::Vector3d expected =
        reference::zero_energy_force_pair(f_i, f_j, rest, x_ij, volume_i * volume_j, w_float, young, alpha);
    const kernels::Vec3 got = kernels::zero_energy_force_pair(to_float(f_i), to_float(f_j), to_float(rest),
                                                              to_float(x_ij), static_cast<float>(volume_i),
                                                              static_cast<float>(volume_j), static_cast<float>(w_float),
                                                              static_cast<float>(young), static_cast<float>(alpha));
    // delta = ((F_i + F_j) X_ij - 2 x_ij) . n cancels: the scale holds its terms.
    const double coefficient = 0.5 * alpha * volume_i * volume_j * w_float * young / rest.squaredNorm();
    force.add(to_double(got), expected, coefficient * ((f_i + f_j) * rest).norm() + 2.0 * coefficient * x_ij.norm());
  }
  // Coincident particles: no direction, no force (the float code's caller skips them).
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  EXPECT_EQ(reference::zero_energy_force_pair(identity, identity, Eigen::Vector3d(0.01, 0.0, 0.0),
                                              Eigen::Vector3d::Zero(), 1e-6, 1.0, 1e5, 0.1),
            Eigen::Vector3d::Zero());
}

// The float code damps bodies held by fixed regions only, against the world: v_ref = 0.
TEST(ElasticEquationTwins, DampingForce) {
  TwinDraws draws("ElasticEquationTwins.DampingForce");
  TwinComparison force("mass-proportional damping force");
  for (int k = 0; k < kDraws; ++k) {
    const double rate = draws.uniform(0.1, 100.0), mass = draws.uniform(1e-4, 1.0);
    const Eigen::Vector3d velocity = draws.vector(2.0);
    const Eigen::Vector3d expected = reference::damping_force(rate, mass, velocity, Eigen::Vector3d::Zero());
    force.add(to_double(kernels::damping_force(static_cast<float>(rate), static_cast<float>(mass), to_float(velocity))),
              expected, expected.norm());
  }
}

}  // namespace
}  // namespace mssph::testing
