#pragma once
// Helpers for the elasticity cases that read the reference backend's deformable state: which
// particles have complete neighbourhoods, and uniform deformations of a body. Used by the
// physics cases and tests/deformable.
#include "reference_backend.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mssph::validation {

// Particles of `body` whose rest neighbourhood is complete: at least `margin` from every face of
// the body's bounding box (margin >= h: the support lies inside the body).
std::vector<std::size_t> interior_particles(const reference::ReferenceBackend& backend, std::size_t body,
                                            double margin);

// Places every particle of `body` at x = centre + G (X - centre) + t from its rest position X:
// a uniform deformation G (a rotation, a stretch, a shear) and a translation t.
void deform_body(reference::ReferenceBackend& backend, std::size_t body, const Eigen::Matrix3d& g,
                 const Eigen::Vector3d& centre, const Eigen::Vector3d& translation = Eigen::Vector3d::Zero());

}  // namespace mssph::validation
