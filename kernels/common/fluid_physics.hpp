#pragma once
// Steps 2 to 4 of the paper's loop (3.2) for one particle, float32: density and pressure,
// pressure and viscosity forces (paper eq. 2, 3 inside a fluid; eq. 7 between bodies), leap-frog.
// The same functions run in the CUDA kernels and in the host build; cpu_reference/density.hpp and
// cpu_reference/fluid_forces.hpp document the formulation (spiky number densities read against
// each body's rest density after Solenthaler and Pajarola 2008, clamped equation of state, the
// energy-consistent form of eq. 2 with the lattice calibration 1/g). Each equation is one function
// named as its float64 twin there (tests/equations/ checks each against it): eq. 1 density,
// equation_of_state, eq. 2 pressure_force_pair, eq. 3 viscosity_force_pair (with
// interface_viscosity), eq. 7 interaction_force; for viscosity_model full_stress
// VelocityGradientSums and transposed_stress_force_pair.
//
// Each quantity is a sum over neighbours, assembled once by density_sum_over() and
// force_sum_over() from the candidates a source hands them: on a GPU lane `lane` of a particle's
// team visits every lanes-th candidate of the 27 cells (density_sum), and the lanes' partial sums
// are added (same pair arithmetic, another summation order); one lane alone takes its force sum
// from the candidates within h, found first (force_sum); a team's lanes visit the lists a
// rebuild's density pass recorded instead (density_sum_recording, density_sum_listed,
// force_sum_listed; list_skin.hpp); the host visits the particle's neighbour list. Lists
// (neighbour_list.hpp) give the same bits as the walks they were recorded from, as long as the
// particles stay where they were.
#include "compensated_position.hpp"
#include "near_notes.hpp"
#include "neighbour_list.hpp"
#include "particle_views.hpp"
#include "simulation_domain.hpp"
#include "wall_exclusion.hpp"

#include <cmath>
#include <limits>

namespace mssph::kernels {

// ---- Step 2: density and pressure ----

struct DensitySum {
  float delta;  // number density sum_j W_spiky(|x_i - x_j|) [1/m^3]
  // The squared distance from a particle that takes its own body at rest to the nearest candidate
  // of another body [m^2], +infinity without one: for a rigid or deformable particle, whether one
  // lies within h decides whether its force sums can be anything but zero (may_feel_forces); a
  // boundary particle receives no forces. A fluid particle's walk does not look, as its force pass
  // never skips: 0.
  float nearest_other_body2;
};

// Candidates beyond the support (about 85 % of the 27 cells' volume) are rejected on r^2, the
// force pair's test, before their distance is taken: a branch rather than a select, so that warps
// skip the term together where no lane's candidate is near. Returns r^2, the candidate's squared
// distance.
MSSPH_HD float add_density_pair(DensitySum& sum, const SmoothingKernels& w, Vec3 x_i, Vec3 x_j) {
  const float r2 = squared_norm(x_i - x_j);
  if (r2 < w.h2) sum.delta += w.spiky(w.pair_distance(r2).r);
  return r2;
}
MSSPH_HD float add_density_pair(DensitySum& sum, const SortedView& v, Vec3 x_i, std::uint32_t t) {
  return add_density_pair(sum, v.step.smoothing, x_i, xyz(v.position[t]));
}

// A particle whose density takes its own body's share at rest (own_rest_number_density) and sums
// only the other bodies' neighbours live: a deformable particle, which reads the density of its
// contact layer (model/deformable_rest_state.hpp, reads_contact_layer_density, says why), and a
// rigid or boundary particle, whose share at rest is its live share, as its body's particles keep
// their distances (boundary particles never move), so its walks need not visit its own body
// (body_left_out). The reference sums rigid and boundary bodies' shares live (compute_densities):
// the agreement tests hold the two against each other.
MSSPH_HD bool takes_own_body_at_rest(const BodyParameters& body) { return body.kind != kFluid; }

// The body whose rows of cells a particle's density walk leaves out (CellRanges::for_each_range):
// a rigid, deformable or boundary particle's own, whose pairs add nothing to its sum (taken at
// rest); kNoBody for a fluid one. Inside a large block or a thick wall every row is its own body's,
// and its particles walk nothing. The force walk leaves out nothing: inside a body it is skipped whole
// (may_feel_forces), and near another body the cell checks cost more than the rows they save.
MSSPH_HD std::uint32_t body_left_out(const BodyParameters& body, std::uint32_t body_index) {
  return takes_own_body_at_rest(body) ? body_index : kNoBody;
}
// The body_left_out of a particle at sorted position p (its body in p's w).
MSSPH_HD std::uint32_t body_left_out(const SortedView& v, Vec4 p) {
  return body_left_out(v.bodies[body_of(p)], body_of(p));
}

// The cells around sorted particle s that its density walk leaves out: those holding nothing but
// its body_left_out (CellRanges::cells_holding_only), all 27 checked here; the GPU's lanes split
// the checks (kernels/cuda/warp_cell_checks.cuh).
MSSPH_HD std::uint32_t cells_left_out(const SortedView& v, std::uint32_t s) {
  const Vec4 p = v.position[s];
  return v.grid.cells_holding_only(xyz(p), body_left_out(v, p));
}

// Particle s's live density sum over the candidates that candidates(visit) hands to visit, but
// those of body `own` (its body_left_out, taken at rest; kNoBody: none left out);
// considered(t, r2) is called for every candidate t the sum considers, with its squared distance
// r2; its term is added when r2 < h^2. The walk is written once for a particle that leaves out its
// own body (which also notes its nearest other body) and once for a particle that sums every body,
// so a particle's case is decided once, not at each of its ~200 candidates, and a fluid particle's
// walk does not take the nearest.
template <class Candidates, class Considered>
MSSPH_HD DensitySum density_sum_over(const SortedView& v, std::uint32_t s, std::uint32_t own, Candidates&& candidates,
                                     Considered&& considered) {
  const Vec3 x_i = xyz(v.position[s]);
  DensitySum sum{0.0f, 0.0f};
  if (own != kNoBody) {
    sum.nearest_other_body2 = std::numeric_limits<float>::infinity();
    candidates([&](std::uint32_t t) {
      if (body_of(v.position[t]) == own) return;  // its own body: at rest, in density_from
      const float r2 = add_density_pair(sum, v, x_i, t);
      sum.nearest_other_body2 = std::fmin(sum.nearest_other_body2, r2);
      considered(t, r2);
    });
  } else {  // fluid particles, whose force pass never skips, and walls beside fluid: no nearest
    candidates([&](std::uint32_t t) { considered(t, add_density_pair(sum, v, x_i, t)); });
  }
  return sum;
}
template <class Candidates, class Considered>
MSSPH_HD DensitySum density_sum_over(const SortedView& v, std::uint32_t s, Candidates&& candidates,
                                     Considered&& considered) {
  return density_sum_over(v, s, body_left_out(v, v.position[s]), candidates, considered);
}
template <class Candidates>
MSSPH_HD DensitySum density_sum_over(const SortedView& v, std::uint32_t s, Candidates&& candidates) {
  return density_sum_over(v, s, candidates, [](std::uint32_t, float) {});
}

// Whether a particle's one-lane walks take near notes when the pass has them: a fluid particle's.
MSSPH_HD bool takes_near_notes(const BodyParameters& body) { return body.kind == kFluid; }

// Whose density sums take every body live where their GPU warp holds a fluid particle, so that the
// warp's lanes walk together, one lane a segment at a time (density_sum_noting_near): fluid and
// boundary particles (kernels/cuda/step_kernels.cu, density_body_left_out).
MSSPH_HD bool walks_with_fluid(const BodyParameters& body) { return body.kind == kFluid || body.kind == kBoundary; }

// The live density sum of fluid or boundary particle s in one lane (canonical index i), its own
// body included, over density_sum's walk with no rows left out, a segment at a time
// (CellRanges::for_each_segment): the same candidates in the same order as density_sum's for a
// fluid particle, so the same bits. A fluid particle notes which candidates lie within h
// (NearNotes, when `notes` are taken). A boundary particle, which receives no forces, notes
// nothing, and its sum holds its own body live (it leaves out no body: number_density_of).
MSSPH_HD DensitySum density_sum_noting_near(const SortedView& v, std::uint32_t s, std::uint32_t i,
                                            const NearNotes& notes) {
  const Vec4 p_i = v.position[s];
  const Vec3 x_i = xyz(p_i);
  const bool noting = notes.taken() && takes_near_notes(v.bodies[body_of(p_i)]);
  DensitySum sum{0.0f, 0.0f};
  std::uint32_t k = 0;
  v.grid.for_each_segment(x_i, [&](std::uint32_t first, int size) {
    const Vec4* candidate = v.position + first;  // signed offsets, as near_mask's
    // Each candidate's bit enters at the top and the mask moves down one place; the last shift
    // puts candidate b's at bit b. A variable shift per candidate (1 << b) costs more.
    std::uint32_t near = 0;
    for (int b = 0; b < size; ++b) {
      const bool within = add_density_pair(sum, v.step.smoothing, x_i, xyz(candidate[b])) < v.step.smoothing.h2;
      near = near >> 1 | (within ? 0x80000000u : 0u);
    }
    near >>= 32 - size;
    if (noting) notes.put(i, s, k, near);
    ++k;
  });
  return sum;
}

// Particle s's grid walk as a candidate source: lane `lane` of `lanes`' share of the 27 cells
// around it, less the rows that `left_out` (its cells_left_out) covers.
MSSPH_HD auto grid_share(const SortedView& v, std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                         std::uint32_t left_out) {
  return [&v, x = xyz(v.position[s]), lane, lanes, left_out](auto&& visit) {
    v.grid.for_each_candidate(x, lane, lanes, visit, left_out);
  };
}

// Lane `lane` of `lanes`' share of particle s's live density sum, from the grid, given its
// cells_left_out and the body `own` it leaves out (density_sum_over).
MSSPH_HD DensitySum density_sum(const SortedView& v, std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                std::uint32_t left_out, std::uint32_t own) {
  return density_sum_over(v, s, own, grid_share(v, s, lane, lanes, left_out), [](std::uint32_t, float) {});
}
MSSPH_HD DensitySum density_sum(const SortedView& v, std::uint32_t s, std::uint32_t lane, std::uint32_t lanes) {
  return density_sum(v, s, lane, lanes, cells_left_out(v, s), body_left_out(v, v.position[s]));
}

// Boundary particles receive no force: they skip the force sum.
MSSPH_HD bool receives_forces(const BodyParameters& body) { return body.kind != kBoundary; }

// Whether a particle's force sums can be anything but zero_force_sum(), given whether its density
// sum met another body within h (DensitySum::nearest_other_body2 < h^2): a fluid particle's always
// can; a rigid or deformable particle's take only other bodies' neighbours (add_force_pair), so
// without one they are zero, and the GPU's force pass skips its walk. Inside a large rigid or
// deformable block that is nearly every particle.
MSSPH_HD bool may_feel_forces(const BodyParameters& body, bool near_other_body) {
  return receives_forces(body) && (body.kind == kFluid || near_other_body);
}

// The same share on a step that kept the lists: over list `list`, which a rebuild recorded
// (density_sum_recording) and which the check since then keeps valid (list_skin.hpp). A list that
// overflowed at its rebuild forces the next one, so it is walked only on the rebuild's own step,
// whose grid is fresh. `own`: the body the sum leaves out, as the rebuild left it out of the list.
MSSPH_HD DensitySum density_sum_listed(const SortedView& v, std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                       const NeighbourLists& lists, std::uint32_t list, std::uint32_t own) {
  return density_sum_over(v, s, own, listed_share(v.grid, xyz(v.position[s]), lane, lanes, lists, list),
                          [](std::uint32_t, float) {});
}

// density_sum's share on a step that rebuilt the grid: its walk records in list `list`
// (neighbour_list.hpp) every candidate it would consider that lies closer than record_radius2,
// (h + skin)^2 (list_skin.hpp), and the share is then summed over that list (density_sum_listed),
// the same terms in the same order as the walk, so the same bits. The walk that only records
// issues fewer instructions a candidate than one that also sums, and the list it then reads is
// short. The force pass of this step and the passes of the steps until the next rebuild visit the
// list too (force_sum_listed, density_sum_listed): the body `own` the sum leaves out is not listed
// (a rigid, deformable or boundary particle's own, which its density takes at rest and which adds
// nothing to its force sum, add_force_pair: no pressure or viscosity within such a body).
MSSPH_HD DensitySum density_sum_recording(const SortedView& v, std::uint32_t s, std::uint32_t lane, std::uint32_t lanes,
                                          std::uint32_t left_out, const NeighbourLists& lists, std::uint32_t list,
                                          float record_radius2, std::uint32_t own) {
  const Vec3 x_i = xyz(v.position[s]);
  ListRecorder recorder(lists, list);
  grid_share(v, s, lane, lanes, left_out)([&](std::uint32_t t) {
    const Vec4 p = v.position[t];
    if (squared_norm(x_i - xyz(p)) < record_radius2 && body_of(p) != own) recorder.record(t);
  });
  lists.count[list] = recorder.count();
  return density_sum_listed(v, s, lane, lanes, lists, list, own);
}

// The host's density sum of sorted particle s over its row of `recorded`, which the last rebuild
// recorded within h + skin (list_skin.hpp), copying the entries within h where the particles stand
// now into its row of `within` as it meets them (RowWriter); the force pass reads those, whose
// terms it all keeps. A row that overflowed stays overflowed: its density walked the grid, and so
// will its force pass. Copying as it sums loads each row and its positions once, at the price of a
// mispredicted test on h for about one entry in four of a row with a skin.
MSSPH_HD DensitySum density_sum_keeping_within(const SortedView& v, const NeighbourLists& recorded,
                                               const NeighbourLists& within, std::uint32_t s) {
  RowWriter kept(within, s);
  const float h2 = v.step.smoothing.h2;
  const DensitySum sum =
      density_sum_over(v, s, neighbours_of(v, recorded, s), [&](std::uint32_t t, float r2) { kept.offer(t, r2 < h2); });
  within.count[s] = recorded.count[s] >= recorded.capacity ? within.capacity : kept.count();
  return sum;
}

// The number density behind particle s's pressure from its live sum, which left out body `own`
// (density_sum_over; kNoBody: none): s's own body, whose share at rest it adds.
MSSPH_HD float number_density_of(const DensitySum& sum, const SortedView& v, std::uint32_t s, std::uint32_t own) {
  if (own == kNoBody) return sum.delta;
  return sum.delta + v.own_rest_number_density[v.id[s] - v.bodies[own].own_rest_offset];
}

// Paper eq. 1 read as a number density (Solenthaler and Pajarola 2008): rho_i = rho0 delta_i / delta0
// with delta_i = sum_j W(x_i - x_j) over all bodies, a deformable body's own taken at rest
// (reference: density, which divides by delta0).
MSSPH_HD float density(float rest_density, float number_density, float inverse_rest_number_density) {
  return rest_density * number_density * inverse_rest_number_density;
}

// The paper's equation of state P = k (rho - rho0), clamped at P >= 0 against the tensile
// instability at free surfaces (reference: equation_of_state).
MSSPH_HD float equation_of_state(float pressure_stiffness, float density, float rest_density) {
  return std::fmax(0.0f, pressure_stiffness * (density - rest_density));
}

struct DensityResult {
  float density;  // rho = rho0 delta / delta0 [kg/m^3]
  VolumePressure volume_pressure;
};

// Particle s's density and pressure from its live sum, which left out body `own` (number_density_of).
MSSPH_HD DensityResult density_from(const DensitySum& sum, const SortedView& v, std::uint32_t s, std::uint32_t own) {
  const BodyParameters& body = v.bodies[body_of(v.position[s])];
  const float rho = density(body.rest_density, number_density_of(sum, v, s, own), v.step.inverse_rest_number_density);
  return {rho, {body.sph_mass / rho, equation_of_state(body.pressure_stiffness, rho, body.rest_density)}};
}

// ---- Step 3: pressure and viscosity forces ----

// The mu of eq. 3 between two bodies: the harmonic mean of their viscosities (Morris et al. 1997),
// so a body of zero viscosity exerts no friction (reference: interface_viscosity).
MSSPH_HD float interface_viscosity(float mu_i, float mu_j) {
  return mu_i + mu_j > 0.0f ? fast_quotient(2.0f * mu_i * mu_j, mu_i + mu_j) : 0.0f;
}

// Paper eq. 2 in its energy-consistent form, one neighbour's pressure force on i:
// f_ij = -(1 / g) (V_i^2 P_i + V_j^2 P_j) grad W(x_i - x_j), where eq. 2 as printed has
// V_i V_j (P_i + P_j) / 2; the reference's pressure_force_pair says why, and what the lattice
// calibration g is.
MSSPH_HD Vec3 pressure_force_pair(VolumePressure i, VolumePressure j, float inverse_gradient_consistency, Vec3 grad_w) {
  const float pressure_term = i.volume * i.volume * i.pressure + j.volume * j.volume * j.pressure;
  return (-pressure_term * inverse_gradient_consistency) * grad_w;
}

// Paper eq. 3, one neighbour's viscosity force on i: mu V_i V_j (v_j - v_i) lap W(|x_i - x_j|)
// (reference: viscosity_force_pair).
MSSPH_HD Vec3 viscosity_force_pair(float mu, float volume_i, float volume_j, float laplacian, Vec3 velocity_i,
                                   Vec3 velocity_j) {
  return (mu * volume_i * volume_j * laplacian) * (velocity_j - velocity_i);
}

// The full_stress viscosity's velocity gradient of a fluid particle (reference:
// VelocityGradientSums): A_i = G_i M_i^-1, G_i = sum_j V_j (v_j - v_i) (x) grad W_ij,
// M_i = sum_j V_j (x_j - x_i) (x) grad W_ij, over the neighbours whose pair viscosity is not zero.
struct VelocityGradientSums {
  Mat3 velocity_moment;  // G_i [1/s]
  Mat3 position_moment;  // M_i [-]

  MSSPH_HD void add(float volume_j, Vec3 velocity_ji, Vec3 position_ji, Vec3 grad_w) {
    velocity_moment = velocity_moment + volume_j * outer(velocity_ji, grad_w);
    position_moment = position_moment + volume_j * outer(position_ji, grad_w);
  }
  // A_i = G_i cof(M_i)^T / det M_i; zero where M_i is singular (no neighbours).
  MSSPH_HD Mat3 gradient() const {
    const float det = determinant(position_moment);
    if (det == 0.0f) return zero_mat3();
    return (1.0f / det) * (velocity_moment * transpose(cofactor(position_moment)));
  }
};

MSSPH_HD VelocityGradientSums zero_velocity_gradient_sums() { return {zero_mat3(), zero_mat3()}; }

// The full_stress viscosity's second part, one neighbour's term on i: the divergence of
// mu (grad u)^T in the pair form of eq. 2, f_i = mu (V_i^2 A_i^T + V_j^2 A_j^T) grad W_ij / g
// (reference: transposed_stress_force_pair, which says why).
MSSPH_HD Vec3 transposed_stress_force_pair(float mu, float volume_i, const Mat3& gradient_i, float volume_j,
                                           const Mat3& gradient_j, float inverse_gradient_consistency, Vec3 grad_w) {
  const Mat3 stress = (volume_i * volume_i) * transpose(gradient_i) + (volume_j * volume_j) * transpose(gradient_j);
  return (mu * inverse_gradient_consistency) * (stress * grad_w);
}

// Paper eq. 7: between particles of different bodies the interaction force is the pressure and
// viscosity force of eq. 2 and 3 (reference: interaction_force).
MSSPH_HD Vec3 interaction_force(Vec3 pressure, Vec3 viscosity) { return pressure + viscosity; }

// What the force sum and the leap-frog need of particle i, loaded once, from its cell-ordered
// copy: the grid made it from the canonical state at the step's start (or, while the GPU's lists
// hold, the step before wrote it where it moved the particle), and nothing has moved a particle
// since (its position and velocity are the canonical ones, bit for bit).
struct ForceParticle {
  std::uint32_t s;
  std::uint32_t body;
  BodyParameters parameters;
  Vec3 x;
  Vec3 u;
  float position_carry;  // the last position update's rounding (compensated_position.hpp)
  VolumePressure vp;
};

MSSPH_HD ForceParticle load_force_particle(const SortedView& v, std::uint32_t s) {
  const Vec4 p = v.position[s];
  const std::uint32_t body = body_of(p);
  const Vec4 u = v.velocity[s];
  return {s, body, v.bodies[body], xyz(p), xyz(u), u.w, v.volume_pressure[s]};
}

struct ForceSum {
  Vec3 pressure;     // [N] from all neighbours
  Vec3 viscosity;    // [N] from all neighbours
  Vec3 interaction;  // [N] the part of both from other bodies (eq. 7)
  // The squared distance from i to its nearest boundary particle within h at the start of the
  // step [m^2], +infinity without one. A particle without one cannot end the step within the wall
  // exclusion distance (0.8 dx) of a boundary particle as long as it moves less than h - 0.8 dx in
  // a step (at least 0.2 dx, 1.2 dx at the default h = 2 dx; the CFL bound keeps a step's move far
  // below), nor can one whose nearest is farther than that distance plus its move
  // (surely_clear_of_walls): only the others need the wall check after their leap-frog
  // (wall_exclusion.hpp). A minimum, so the same in any order of the candidates.
  float nearest_boundary2;
};

MSSPH_HD ForceSum zero_force_sum() { return {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, std::numeric_limits<float>::infinity()}; }

// Adds candidate t's pressure and viscosity forces on i, and takes t's distance if it is a
// boundary neighbour. For a fluid particle, t's volume, pressure and velocity are loaded with its
// position, before its distance is tested, and its body's parameters only where its body is not
// i's: a candidate then waits for one round of loads, not for three behind each test (position,
// its body's kind, the rest). Nearly every candidate a one-lane walk hands over is a neighbour
// (CellRanges::for_each_candidate_within), a team's list entries three in four. Within i's own
// body the kind is i's, never a boundary's (boundary particles receive no forces). A rigid or
// deformable particle's own-body neighbours add nothing, and it loads the rest after the test
// that leaves them out, so that its many left-out candidates load nothing more.
// FullStress (viscosity_model full_stress, v.velocity_gradient set) adds the transposed stress term;
// a template parameter, so that eq. 3's scenes run the pair loop without it.
template <bool FullStress>
MSSPH_HD void add_force_pair(ForceSum& sum, const ForceParticle& i, const SortedView& v, std::uint32_t t) {
  if (t == i.s) return;
  const bool fluid = i.parameters.kind == kFluid;
  const Vec4 p_j = load_in_place(v.position, t);
  VolumePressure vp_j{0.0f, 0.0f};
  Vec4 u_j{0.0f, 0.0f, 0.0f, 0.0f};
  if (fluid) {
    vp_j = load_in_place(v.volume_pressure, t);
    u_j = load_in_place(v.velocity, t);
  }
  const Vec3 r_ij = i.x - xyz(p_j);
  const float r2 = squared_norm(r_ij);
  if (r2 >= v.step.smoothing.h2) return;
  const std::uint32_t body_j = body_of(p_j);
  const bool same_body = body_j == i.body;
  float mu = i.parameters.viscosity;
  if (same_body) {
    if (!fluid) return;  // rigid, deformable: no pressure among themselves
  } else {
    const BodyParameters& other = v.bodies[body_j];
    if (other.kind == kBoundary) sum.nearest_boundary2 = std::fmin(sum.nearest_boundary2, r2);
    mu = interface_viscosity(i.parameters.viscosity, other.viscosity);
  }
  if (!fluid) {
    vp_j = v.volume_pressure[t];
    u_j = v.velocity[t];
  }
  const PairDistance d = v.step.smoothing.pair_distance(r2);
  const Vec3 pressure =
      pressure_force_pair(i.vp, vp_j, v.step.inverse_gradient_consistency, v.step.smoothing.spiky_gradient(r_ij, d));
  Vec3 viscosity =
      viscosity_force_pair(mu, i.vp.volume, vp_j.volume, v.step.smoothing.viscosity_laplacian(d.r), i.u, xyz(u_j));
  if constexpr (FullStress) {
    // A rigid, deformable or boundary particle meeting a fluid one takes the fluid's gradient.
    const bool fluid_j = same_body ? fluid : v.bodies[body_j].kind == kFluid;
    if (mu > 0.0f && (fluid || fluid_j)) {
      viscosity += transposed_stress_force_pair(
          mu, i.vp.volume, v.velocity_gradient[fluid ? i.s : t], vp_j.volume, v.velocity_gradient[fluid_j ? t : i.s],
          v.step.inverse_gradient_consistency, v.step.smoothing.spiky_gradient(r_ij, d));
    }
  }
  sum.pressure += pressure;
  sum.viscosity += viscosity;
  if (!same_body) sum.interaction += interaction_force(pressure, viscosity);
}

// Sorted particle s's share of its velocity-gradient sums for the full_stress viscosity, over the
// candidates that candidates(visit) hands to visit (those beyond h add nothing); a particle that is
// not a fluid's sums nothing.
template <class Candidates>
MSSPH_HD VelocityGradientSums velocity_gradient_sums_over(const SortedView& v, std::uint32_t s,
                                                          Candidates&& candidates) {
  VelocityGradientSums sums = zero_velocity_gradient_sums();
  const ForceParticle i = load_force_particle(v, s);
  if (i.parameters.kind != kFluid) return sums;
  candidates([&](std::uint32_t t) {
    if (t == s) return;
    const Vec4 p_j = v.position[t];
    const Vec3 r_ij = i.x - xyz(p_j);
    const float r2 = squared_norm(r_ij);
    if (r2 >= v.step.smoothing.h2) return;
    const std::uint32_t body_j = body_of(p_j);
    const float mu = body_j == i.body ? i.parameters.viscosity
                                      : interface_viscosity(i.parameters.viscosity, v.bodies[body_j].viscosity);
    if (mu <= 0.0f) return;
    const PairDistance d = v.step.smoothing.pair_distance(r2);
    sums.add(v.volume_pressure[t].volume, xyz(v.velocity[t]) - i.u, -r_ij, v.step.smoothing.spiky_gradient(r_ij, d));
  });
  return sums;
}

// Particle i's pressure and viscosity sums over the candidates that candidates(visit) hands to
// visit; FullStress as add_force_pair.
template <bool FullStress = false, class Candidates>
MSSPH_HD ForceSum force_sum_over(const SortedView& v, const ForceParticle& i, Candidates&& candidates) {
  ForceSum sum = zero_force_sum();
  if (receives_forces(i.parameters)) {
    candidates([&](std::uint32_t t) { add_force_pair<FullStress>(sum, i, v, t); });
  }
  return sum;
}

// Particle i's pressure and viscosity sums in one lane, from the grid: the candidates within h,
// found first and their segments kept in `held` (CellRanges::for_each_candidate_within), which
// add_force_pair tests again.
template <bool FullStress = false, class Held>
MSSPH_HD ForceSum force_sum(const SortedView& v, const ForceParticle& i, Held& held) {
  return force_sum_over<FullStress>(
      v, i, [&](auto&& visit) { v.grid.for_each_candidate_within(i.x, v.step.smoothing.h2, v.position, held, visit); });
}

// The same sum, canonical index i, for a particle that took near notes (takes_near_notes): its
// first segments' masks from the notes, those past them tested. One walk for every particle, the
// masks' source chosen per segment, so the force kernel holds one copy of it. Where no notes were
// taken (`notes` empty), every segment is tested, as above.
template <bool FullStress = false, class Held>
MSSPH_HD ForceSum force_sum(const SortedView& v, const ForceParticle& p, std::uint32_t i, const NearNotes& notes,
                            Held& held) {
  const std::uint32_t noted = notes.taken() && takes_near_notes(p.parameters) ? NearNotes::capacity : 0u;
  return force_sum_over<FullStress>(v, p, [&](auto&& visit) {
    v.grid.for_each_candidate_near(
        p.x,
        [&](std::uint32_t k, std::uint32_t first, int size) {
          return k < noted ? notes.get(i, p.s, k) : near_mask(p.x, v.step.smoothing.h2, v.position, first, size);
        },
        held, visit);
  });
}

// Segments a one-lane force walk holds before it visits them: its 9 rows give at most 9 with a
// near candidate, unless a row holds more than 32 candidates (near the walls' denser layers) or
// wraps around the grid; a walk that finds more visits them in two goes, which costs its warp a
// second loop. Twelve leave room for a few such rows; every segment more lengthens each thread's
// column in shared memory, which comes out of L1.
inline constexpr std::uint32_t kHeldSegments = 12;

// The same with the segments in the thread's own array (host tests; the GPU's force probe).
MSSPH_HD ForceSum force_sum(const SortedView& v, const ForceParticle& i) {
  HeldSegments<kHeldSegments> held;
  return force_sum(v, i, held);
}

// The same share from list `list`, which a rebuild's density pass recorded from it
// (density_sum_recording); an overflowed list walks the share itself.
template <bool FullStress = false>
MSSPH_HD ForceSum force_sum_listed(const SortedView& v, const ForceParticle& i, std::uint32_t lane, std::uint32_t lanes,
                                   const NeighbourLists& lists, std::uint32_t list) {
  return force_sum_over<FullStress>(v, i, listed_share(v.grid, i.x, lane, lanes, lists, list));
}

// ---- Step 4: integration ----

// Leap-frog with staggered velocities for fluid and deformable particles:
// v_{n+1/2} = v_{n-1/2} + (f / m + g) dt, x_{n+1} = x_n + v_{n+1/2} dt; held particles stay.
// The position update is compensated: its rounding rides in velocity.w (compensated_position.hpp).
MSSPH_HD void leapfrog(Vec4& position, Vec4& velocity, Vec3 force, float mass, bool held, const StepParameters& step) {
  if (held) {
    velocity = Vec4{0, 0, 0, 0};
    return;
  }
  const Vec3 v = xyz(velocity) + step.dt * (force * (1.0f / mass) + step.gravity);
  Vec3 x = xyz(position);
  float carry = velocity.w;
  move_compensated(x, carry, step.dt * v);
  velocity = make_vec4(v, carry);
  position = make_vec4(x, 0.0f);
}

// Step 4 of sorted particle s before its wall check, in registers: nothing is written, so every
// lane of a GPU team, holding the same force sum, computes the same bits.
struct Advance {
  std::uint32_t i;    // canonical index
  bool integrates;    // fluid or deformable: advanced by the leap-frog; the others only record
                      // their interaction force
  bool may_hit_wall;  // integrates, and its move may end within d_wall of a boundary particle
                      // (ForceSum::nearest_boundary2)
  Vec3 previous;      // x_n [m]
  Vec4 position;      // x_{n+1} [m]
  Vec4 velocity;      // v_{n+1/2} [m/s]
};

// Advances particle p, canonical index i, by the leap-frog under its total force: its pressure and
// viscosity sums and, for a deformable particle, its elastic force. Its position and velocity come
// from its cell-ordered copy (ForceParticle), not from another round trip to the canonical arrays.
MSSPH_HD Advance advance_particle(const StepParameters& step, const CanonicalState& c, const ForceParticle& p,
                                  std::uint32_t i, const ForceSum& f) {
  Advance a{i, false, false, {0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
  if (p.parameters.kind != kFluid && p.parameters.kind != kDeformable) return a;
  Vec3 total = f.pressure + f.viscosity;
  if (c.elastic_force) total += xyz(c.elastic_force[a.i]);
  a.integrates = true;
  a.position = make_vec4(p.x, 0.0f);
  a.velocity = make_vec4(p.u, p.position_carry);
  a.previous = p.x;
  leapfrog(a.position, a.velocity, total, p.parameters.sph_mass, c.fixed[a.i] != 0, step);
  a.may_hit_wall = !surely_clear_of_walls(f.nearest_boundary2, squared_norm(xyz(a.position) - a.previous),
                                          step.wall_exclusion_distance);
  return a;
}

// Lane `lane` of `lanes`' share of the wall check: whether the advanced move is rejected by one of
// its share of the candidates (touches_wall). The move is rejected iff some lane's share is.
MSSPH_HD bool wall_check_share(const SortedView& v, const Advance& a, std::uint32_t lane, std::uint32_t lanes) {
  return a.may_hit_wall && touches_wall(v, a.previous, xyz(a.position), lane, lanes);
}

// The same share for a GPU team's lane from its list `list` (or the walk an overflowed list was
// recorded from): the candidates its force sum visited, instead of its share of the 27 cells
// around the new position. Every boundary particle that can reject the move was within h of the
// particle at the step's start (ForceSum::nearest_boundary2), so some lane of the team lists it,
// and every listed candidate is a real one: the team's decision is keep_out_of_walls'. The lanes
// of 8 each visit ~6 list entries instead of ~36 candidates, each behind two dependent loads: in
// the slowest team, that walk would set the length of a small scene's force pass.
MSSPH_HD bool wall_check_share(const SortedView& v, const Advance& a, std::uint32_t lane, std::uint32_t lanes,
                               const NeighbourLists& lists, std::uint32_t list) {
  return a.may_hit_wall &&
         touches_wall_among(v, a.previous, xyz(a.position), listed_share(v.grid, a.previous, lane, lanes, lists, list));
}

// The rest of steps 3 and 4, in one lane, given whether the wall check rejected the move:
// records s's interaction force and, for fluid and deformable particles, keeps a rejected move out
// of the walls (keep_out_of_walls), deactivates the particle once it leaves the domain
// (simulation_domain.hpp) and stores its canonical state, which `a` then holds. Writes only
// particle s's canonical entries, so all particles can run at once.
MSSPH_HD void store_advance(const SortedView& v, const CanonicalState& c, const ForceSum& f, Advance& a,
                            bool move_rejected) {
  c.interaction_force[a.i] = make_vec4(f.interaction, 0.0f);
  if (!a.integrates) return;
  if (move_rejected) keep_out_of_walls(v, a.previous, a.position, a.velocity);
  deactivate_outside_domain(v.step, a.position, a.velocity, c.fixed[a.i]);
  c.position[a.i] = a.position;
  c.velocity[a.i] = a.velocity;
}

// Steps 3 and 4 joined for particle p in one lane (the host), given its force sum: the
// parts above, the wall check over all of its candidates.
MSSPH_HD void apply_forces(const SortedView& v, const CanonicalState& c, const ForceParticle& p, const ForceSum& f) {
  Advance a = advance_particle(v.step, c, p, v.id[p.s], f);
  store_advance(v, c, f, a, wall_check_share(v, a, 0, 1));
}

// ---- The grid's last stage: particles in cell order ----

// A particle's cell-ordered position record: where it stands, with its body's index in the fourth
// component (body_of).
MSSPH_HD Vec4 cell_ordered_position(Vec3 x, std::uint32_t body) { return make_vec4(x, index_as_float_bits(body)); }

// Canonical particle i as cell order holds it: its position record and its velocity.
struct CellOrderedParticle {
  Vec4 position;  // cell_ordered_position
  Vec4 velocity;
};
MSSPH_HD CellOrderedParticle cell_ordered_particle(std::uint32_t i, const Vec4* position, const Vec4* velocity,
                                                   const std::uint32_t* body) {
  return {cell_ordered_position(xyz(position[i]), body[i]), velocity[i]};
}

// Copies canonical particle i's position (with its body index) and velocity into cell order, as
// sorted particle s. Both are loaded before either is stored: a compiler that cannot tell the
// arrays apart keeps a load after a store that comes before it, and each gather would wait for
// the one before.
MSSPH_HD void place_in_cell_order(std::uint32_t s, std::uint32_t i, const Vec4* position, const Vec4* velocity,
                                  const std::uint32_t* body, Vec4* sorted_position, Vec4* sorted_velocity) {
  const CellOrderedParticle particle = cell_ordered_particle(i, position, velocity, body);
  sorted_position[s] = particle.position;
  sorted_velocity[s] = particle.velocity;
}

}  // namespace mssph::kernels
