#include "density.hpp"

#include "model/smoothing_kernels.hpp"

namespace mssph::reference {

void compute_densities(const ParticleSetup& setup, const std::vector<double>& own_rest_number_density,
                       const NeighbourLists& neighbours, ParticleState& state) {
  const SpikyKernel w(setup.smoothing_length);
  const std::size_t n = setup.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const BodySetup& body = setup.bodies[setup.body[i]];
    const bool contact_layer = reads_contact_layer_density(body.kind);
    double delta = 0.0;
    for (const std::size_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) {
      if (contact_layer && setup.body[*j] == setup.body[i]) continue;  // its own body: at rest, below
      delta += w((state.position[i] - state.position[*j]).norm());
    }
    if (contact_layer) delta += own_rest_number_density[i];
    const Material& material = body.material;
    state.number_density[i] = delta;
    state.density[i] = density(material.rest_density, delta, setup.rest_number_density);
    state.volume[i] = setup.mass[i] / state.density[i];
    state.pressure[i] = equation_of_state(material.pressure_stiffness, state.density[i], material.rest_density);
  }
}

}  // namespace mssph::reference
