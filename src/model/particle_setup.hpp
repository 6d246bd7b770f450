#pragma once
// The initial state of a scene as particles: what the scene builder produces and every backend
// starts from. Particles of one body are contiguous. Double precision, SI units.
#include "config/scene.hpp"

#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mssph {

struct BodySetup {
  std::string name;
  BodyKind kind = BodyKind::fluid;
  Material material;
  std::size_t first = 0;          // first particle
  std::size_t count = 0;          // number of particles
  std::size_t lattice_sites = 0;  // sites of its shape's lattice: count, plus a rigid body's interior
                                  // left out (rigid_interior.hpp); lattice_sites dx^3 is its volume
  std::size_t fixed_count = 0;    // deformable: particles held by fixed regions

  // Rigid bodies: physical mass properties from the body's density and its particles.
  double mass = 0.0;                                           // [kg]
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Identity();  // about the centre of mass, body frame [kg m^2]
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();    // [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // [rad/s]
  bool fixed = false;                                          // immovable rigid body

  bool moves_as_rigid_body() const { return kind == BodyKind::rigid && !fixed; }
  bool is_static() const { return kind == BodyKind::boundary || (kind == BodyKind::rigid && fixed); }
};

struct ParticleSetup {
  double spacing = 0.0;               // lattice spacing dx [m]
  double smoothing_length = 0.0;      // support radius h [m]
  double rest_number_density = 0.0;   // delta0 = sum_j W_ij in a rest lattice [1/m^3]
  double gradient_consistency = 1.0;  // g = dx^3 sum_j x_ji (x) grad W_ij in a rest lattice (x I) [-]
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  double dt = 0.0;
  double max_speed = 0.0;
  Region domain;                        // particles leaving it are deactivated [m]
  double max_lost_mass_fraction = 0.0;  // of a body's mass, before the run fails [-]
  ViscosityModel viscosity_model = ViscosityModel::paper;
  NeighbourListUse neighbour_lists = NeighbourListUse::automatic;

  std::vector<Eigen::Vector3d> position;     // [m]
  std::vector<Eigen::Vector3d> velocity;     // [m/s]
  std::vector<double> mass;                  // SPH mass m_i = rho0 dx^3 [kg]
  std::vector<std::uint32_t> body;           // index into bodies
  std::vector<std::uint8_t> fixed;           // 1: held in place (deformable fixed regions)
  std::vector<Eigen::Vector3d> rest_offset;  // rigid bodies: offset from the centre of mass, body frame [m]
  std::vector<BodySetup> bodies;

  std::size_t size() const { return position.size(); }
};

}  // namespace mssph
