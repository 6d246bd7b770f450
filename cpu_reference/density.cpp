#include "density.hpp"

#include "model/smoothing_kernels.hpp"

namespace mssph::reference {

void compute_densities(const ParticleSetup& setup, const NeighbourLists& neighbours, ParticleState& state) {
  const SpikyKernel w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double delta = 0.0;
    for (const std::size_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) {
      delta += w((state.position[i] - state.position[*j]).norm());
    }
    const Material& material = setup.bodies[setup.body[i]].material;
    state.number_density[i] = delta;
    state.density[i] = density(material.rest_density, delta, setup.rest_number_density);
    state.volume[i] = setup.mass[i] / state.density[i];
    state.pressure[i] = equation_of_state(material.pressure_stiffness, state.density[i], material.rest_density);
  }
}

}  // namespace mssph::reference
