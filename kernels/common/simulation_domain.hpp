#pragma once
// Particles that leave the simulation domain, float32 (reference twin: the reference backend's
// integrate; scene/simulation_domain.hpp says what the default domain is).
#include "particle_views.hpp"

namespace mssph::kernels {

// Region::contains in the kernels' frame: inside or on the faces.
MSSPH_HD bool inside_domain(const StepParameters& step, Vec3 x) {
  return x.x >= step.domain_min.x && x.y >= step.domain_min.y && x.z >= step.domain_min.z && x.x <= step.domain_max.x &&
         x.y <= step.domain_max.y && x.z <= step.domain_max.z;
}

// A fluid or deformable particle that has just left the domain is deactivated: held from now on
// where it left (no velocity, so leapfrog no longer moves it and it carries no momentum or
// energy into the body sums). It stays a neighbour of particles within h of that spot, which lies
// outside the domain, away from the scene's bodies. The count per body is logged
// (add_domain_status) and the run fails past the scene's fraction (sim/lost_mass_watch.hpp).
MSSPH_HD void deactivate_outside_domain(const StepParameters& step, const Vec4& position, Vec4& velocity,
                                        std::uint8_t& hold) {
  if (hold != kFree || inside_domain(step, xyz(position))) return;
  hold = kLeftDomain;
  velocity = Vec4{0, 0, 0, 0};
}

}  // namespace mssph::kernels
