#pragma once
// Step 3 of the loop (paper 3.2), pressure and viscosity: inside fluids (paper eq. 2, 3) and
// between particles of different bodies of any kind (paper eq. 7, the whole coupling between
// media).
#include "neighbour_search.hpp"
#include "particle_state.hpp"
#include "scene/particle_setup.hpp"

namespace mssph::reference {

// Pressure force, paper eq. 2 with the paper's factor 1/2 removed and the lattice calibration c:
//   f_i = -(1 / c) V_i sum_j V_j (P_i + P_j) grad W(x_i - x_j).
// With the 1/2, a linear pressure field P = a.x gives sum_j V_j (P_i + P_j)/2 grad W_ij ~= a/2
// inside a lattice (sum_j V_j grad W_ij ~= 0 and sum_j V_j (x_j - x_i) (x) grad W_ij ~= I), so
// eq. 2 as printed feels half the pressure gradient and a settled column would carry twice the
// hydrostatic pressure. Without it the form equals the symmetric SPH pressure force
// -m_i sum_j m_j (P_i / rho_i^2 + P_j / rho_j^2) grad W_ij at uniform density. c (see
// lattice_gradient_consistency) makes the gradient of a linear field exact inside a rest
// lattice (c = 0.947 at h = 2 dx). Pinned by the hydrostatic-column test.
//
// Viscosity force, paper eq. 3: f_i = mu V_i sum_j V_j (v_j - v_i) lap W(|x_i - x_j|), with
// mu = (mu_i + mu_j) / 2 between bodies of different viscosity.
//
// Forces between particles of one fluid body go to internal_force, forces between particles of
// different bodies to interaction_force. Rigid, deformable and boundary bodies feel no pressure or
// viscosity from their own particles (their internal forces are rigidity and elasticity).
// Boundary particles receive no force.
void compute_pressure_viscosity_forces(const ParticleSetup& setup, const NeighbourLists& neighbours,
                                       ParticleState& state);

}  // namespace mssph::reference
