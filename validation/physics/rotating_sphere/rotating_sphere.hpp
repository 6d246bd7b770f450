#pragma once
// The fluid's torque on a sphere turned at a prescribed angular velocity, on any backend: the
// physics case's measurement.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The scene's rigid "sphere" at the centre of the fluid "fluid" in the closed spherical container
// "container" is turned about z at `omega` by a controller: each step its external torque cancels
// the fluid's torque of the last step and drives the angular velocity to (0, 0, omega) at rate
// 1 / (10 dt), and a spring-damper holds its centre. The fluid's torque about z, averaged over the
// last two fifths of the run, is compared with the Stokes (Kirchhoff) torque of a sphere rotating
// in an unbounded fluid, T = -8 pi mu R^3 omega (Lamb, Hydrodynamics, sec. 334), times the wall
// factor of the concentric container (concentric_wall_factor).
struct RotatingSphereMeasurement {
  double torque = 0.0;                       // mean fluid torque about z over the last two fifths [N m]
  double torque_earlier = 0.0;               // mean over the fifth before them: the run has settled when close [N m]
  double expected_torque = 0.0;              // -8 pi mu R^3 omega times the wall factor [N m]
  double wall_factor = 0.0;                  // of the container [-]
  double radius = 0.0;                       // of the sphere as sampled: N particles of volume dx^3 [m]
  double container_radius = 0.0;             // of the cavity as sampled: its fluid and sphere particles [m]
  double reynolds = 0.0;                     // rho omega R^2 / mu [-]
  double omega_deviation = 0.0;              // largest |omega_z - omega| / omega over the averaging window [-]
  std::vector<double> time, torque_history;  // every 1 % of the run [s], [N m]
  std::size_t particles = 0;
};

// A concentric spherical container of radius Rc multiplies the torque on a sphere of radius R
// turning at its centre by 1 / (1 - (R / Rc)^3) (Lamb, sec. 334; Happel and Brenner, Low Reynolds
// Number Hydrodynamics, sec. 5-3).
double concentric_wall_factor(double radius, double container_radius);

// The sphere's radius [m] and the fluid's rest density [kg/m^3] of the case's scene (scene.json).
inline constexpr double kRotatingSphereRadius = 0.05;
inline constexpr double kRotatingSphereFluidDensity = 1000.0;

// The case's scene (scene.json) at spacing dx with kernel support h = support * dx, viscosity mu
// [Pa s], the sphere turning at omega [rad/s] from the start: the sound speed keeps the flow's Mach
// number omega R / c at or below 0.01 and its viscous stress over rho c^2, mu omega / (rho c^2), at
// or below 4e-4; dt is 0.8 of the smaller of the viscous (0.125 h^2 rho / mu) and acoustic
// (0.25 h / c) bounds at h = 2 dx (docs/model.md, "Time step"), so every support takes the same
// step; the run lasts 30 R^2 / nu, in which the torque settles at Re = 0.25 (decision 058).
Scene rotating_sphere_scene(double dx, double support, double mu, double omega);

RotatingSphereMeasurement measure_rotating_sphere(const std::string& backend, const Scene& scene, double omega);

}  // namespace mssph::validation
