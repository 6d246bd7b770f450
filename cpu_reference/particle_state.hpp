#pragma once
// The evolving state of the reference simulation: particles (structure of arrays, double) and
// rigid bodies.
#include <Eigen/Geometry>

#include <vector>

namespace mssph::reference {

struct ParticleState {
  std::vector<Eigen::Vector3d> position;  // x_n [m]
  std::vector<Eigen::Vector3d> velocity;  // leap-frog: v_{n-1/2} before a step, v_{n+1/2} after [m/s]
  // Filled by each step:
  std::vector<double> number_density;              // delta_i = sum_j W_ij [1/m^3]
  std::vector<double> density;                     // rho_i = m_i delta_i [kg/m^3]
  std::vector<double> volume;                      // V_i = 1 / delta_i [m^3]
  std::vector<double> pressure;                    // P_i [Pa]
  std::vector<Eigen::Vector3d> internal_force;     // from particles of the same body [N]
  std::vector<Eigen::Vector3d> interaction_force;  // from particles of other bodies, eq. 7 [N]
  std::vector<Eigen::Vector3d> pressure_force;     // the pressure part of both (eq. 2, 7) [N]
  std::vector<Eigen::Vector3d> viscosity_force;    // the viscosity part of both (eq. 3, 7) [N]
  std::vector<Eigen::Matrix3d> velocity_gradient;  // A_i, fluid particles, full_stress viscosity only [1/s]

  void resize(std::size_t n) {
    position.resize(n);
    velocity.resize(n);
    number_density.assign(n, 0.0);
    density.assign(n, 0.0);
    volume.assign(n, 0.0);
    pressure.assign(n, 0.0);
    internal_force.assign(n, Eigen::Vector3d::Zero());
    interaction_force.assign(n, Eigen::Vector3d::Zero());
    pressure_force.assign(n, Eigen::Vector3d::Zero());
    viscosity_force.assign(n, Eigen::Vector3d::Zero());
    velocity_gradient.assign(n, Eigen::Matrix3d::Zero());
  }
};

// A movable rigid body: centre of mass, orientation and momenta, world frame.
struct RigidBodyState {
  std::size_t body = 0;  // index into ParticleSetup::bodies
  double mass = 0.0;
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inertia_body_inverse = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of mass [m]
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // [m/s]
  Eigen::Vector3d angular_momentum = Eigen::Vector3d::Zero();    // L [kg m^2/s]
  Eigen::Vector3d external_force = Eigen::Vector3d::Zero();      // haptic coupling [N]
  Eigen::Vector3d external_torque = Eigen::Vector3d::Zero();     // [N m]
  Eigen::Vector3d interaction_force = Eigen::Vector3d::Zero();   // last step's sum, eq. 8 [N]
  Eigen::Vector3d interaction_torque = Eigen::Vector3d::Zero();  // about the centre of mass, eq. 9 [N m]

  // omega = I_world^-1 L with I_world = R I_body R^T.
  Eigen::Vector3d angular_velocity() const {
    const Eigen::Matrix3d r = orientation.toRotationMatrix();
    return r * (inertia_body_inverse * (r.transpose() * angular_momentum));
  }
};

}  // namespace mssph::reference
