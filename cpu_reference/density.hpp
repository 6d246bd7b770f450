#pragma once
// Step 2 of the loop (paper 3.2): densities and pressures.
#include "model/deformable_rest_state.hpp"
#include "model/neighbour_search.hpp"
#include "model/particle_setup.hpp"
#include "particle_state.hpp"

#include <algorithm>
#include <vector>

namespace mssph::reference {

// Multi-material density after Solenthaler and Pajarola 2008 ("Density contrast SPH
// interfaces"): the number density delta_i = sum_j W(x_i - x_j) runs over ALL particles of any
// body (paper eq. 1 with A = 1/V), and each body reads it against its own rest density:
// rho_i = rho0 delta_i / delta0, V_i = m_i / rho_i = dx^3 delta0 / delta_i, with m_i = rho0 dx^3 (a
// particle stands for its lattice cell) and delta0 the number density inside a rest lattice. Plain
// mass sums would smear densities across interfaces of different rest density; number densities
// do not, and boundaries at least h thick give fluid next to a wall a full kernel support.
//
// W is the spiky kernel, whose gradient drives the pressure force: density and force then derive
// from one potential energy. With poly6 densities (Mueller et al. 2003) the pair is not
// energy-consistent and a settling water column gains kinetic energy exponentially (x10 in
// 0.5 s at mu = 0.5 Pa s); with the spiky pair it calms down.
//
// Paper eq. 1 read as a number density: rho_i = rho0 delta_i / delta0 (float twin:
// kernels::density, which multiplies by 1 / delta0).
inline double density(double rest_density, double number_density, double rest_number_density) {
  return rest_density * number_density / rest_number_density;
}

// Equation of state (paper): P_i = k (rho_i - rho0), clamped at P >= 0: free-surface particles
// lack neighbours, and a negative pressure there would pull them into clumps (tensile
// instability). Float twin: kernels::equation_of_state.
inline double equation_of_state(double pressure_stiffness, double density, double rest_density) {
  return std::max(0.0, pressure_stiffness * (density - rest_density));
}

// Densities, volumes V_i = m_i / rho_i and pressures of all particles. A deformable particle reads
// the density of its contact layer (model/deformable_rest_state.hpp, reads_contact_layer_density):
// its live sum skips its own body, whose share `own_rest_number_density` (DeformableRestState,
// n entries) it takes at rest.
void compute_densities(const ParticleSetup& setup, const std::vector<double>& own_rest_number_density,
                       const NeighbourLists& neighbours, ParticleState& state);

}  // namespace mssph::reference
