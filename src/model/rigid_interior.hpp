#pragma once
// The lattice sites of a rigid body that no other body's particle ever reaches through the
// smoothing kernel. A rigid particle acts on the rest of the scene only through pairs within h: a
// particle of another body within h of rigid particle j reads j's position and its density, and
// j's density sums j's neighbours within h. So only the rigid particles within 2h of another
// body's particles take part in any sum that changes; those deeper inside add their mass and
// inertia to the body (set from every site before any is left out) and nothing else. Akinci et
// al. 2012 ("Versatile rigid-fluid coupling for incompressible SPH") sample rigid bodies at their
// surface only for the same reason.
#include "particle_setup.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

namespace mssph {

// The depth a rigid body keeps: 2h, plus one spacing for another body's particles that come
// closer to this body than the first lattice node it leaves empty (a contact compresses the gap
// between two bodies' layers below one spacing) and for the lattice jitter.
double rigid_surface_reach(double smoothing_length, double spacing);

// Which of a body's lattice sites (one lattice of spacing dx, in any frame the lattice is aligned
// with: `to_lattice` maps a site into it) lie within `reach` of a lattice node the body leaves
// empty, i.e. of the space outside it (1), or not (0): its interior beyond reach.
std::vector<std::uint8_t> sites_within_reach_of_surface(std::span<const Eigen::Vector3d> sites,
                                                        const Eigen::Matrix3d& to_lattice, double dx, double reach);

// Leaves out each rigid body's particles beyond `reach` of its surface, keeping the order of the
// others and every body's mass properties. `site`: every particle's lattice site, before jitter.
void leave_out_rigid_interiors(ParticleSetup& setup, const std::vector<Eigen::Vector3d>& site, double reach);

}  // namespace mssph
