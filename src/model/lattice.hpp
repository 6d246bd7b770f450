#pragma once
// Lattice sampling of shapes in their local frame (centred at the origin), spacing dx.
#include "config/scene.hpp"

#include <Eigen/Core>

#include <vector>

namespace mssph {

// A box of full edge lengths `size`: cell centres, round(size / dx) particles per axis, so N dx^3
// is the box volume when size is a multiple of dx. An edge under half a spacing rounds to zero:
// the result is empty and the scene builder rejects the body.
std::vector<Eigen::Vector3d> sample_box(const Eigen::Vector3d& size, double dx);

// A ball of `radius`: lattice nodes (one at the centre) strictly inside the sphere; never empty.
std::vector<Eigen::Vector3d> sample_sphere(double radius, double dx);

// The walls (and floor, and lid when closed) of a container of inner size `inner`, `layers`
// particles thick, on the cell-centred lattice that continues the inner box's lattice. Empty when
// an inner edge is under half a spacing (no cavity to hold anything).
std::vector<Eigen::Vector3d> sample_container(const Eigen::Vector3d& inner, int layers, bool open_top, double dx);

// The shell of a closed spherical container of inner radius `inner_radius`, `layers` particles
// thick: the nodes of the sphere's lattice at a distance d from the centre with inner_radius <=
// d < inner_radius + layers dx, so a fluid `sphere` of radius `inner_radius` at the same position
// fills its cavity exactly (the same lattice, the nodes at d < inner_radius).
std::vector<Eigen::Vector3d> sample_spherical_container(double inner_radius, int layers, double dx);

std::vector<Eigen::Vector3d> sample_shape(const Shape& shape, double dx);

}  // namespace mssph
