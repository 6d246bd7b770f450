#pragma once
// Step 2 of the loop (paper 3.2): densities and pressures.
#include "neighbour_search.hpp"
#include "particle_state.hpp"
#include "scene/particle_setup.hpp"

namespace mssph::reference {

// Multi-material density after Solenthaler and Pajarola 2008 ("Density contrast SPH
// interfaces"): the number density delta_i = sum_j W(x_i - x_j) runs over ALL particles of any
// body (paper eq. 1 with A = 1/V), V_i = 1 / delta_i and rho_i = m_i delta_i, where each body's
// particle mass m_i = rho0 / delta0 makes a rest lattice exactly rho0. Plain mass sums would
// smear densities across interfaces of different rest density; number densities do not, and
// boundaries many layers thick give fluid next to a wall a full kernel support.
//
// Equation of state (paper): P_i = k (rho_i - rho0), clamped at P >= 0: free-surface particles
// lack neighbours, and a negative pressure there would pull them into clumps (tensile
// instability).
void compute_densities(const ParticleSetup& setup, const NeighbourLists& neighbours, ParticleState& state);

}  // namespace mssph::reference
