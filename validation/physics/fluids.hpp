#pragma once
// Fluid statics measured on any backend: the hydrostatic pressure of a settled column and the
// floating depth of a light sphere. Shared by the physics and convergence cases and
// tests/reference/fluid_physics_test.cpp.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The scene's fluid body "column" in a tank whose floor is at z = 0 settles for 1 s; then over
// 0.5 s, every 0.01 s, particle pressures are averaged per horizontal slab one spacing thick
// (slab k holds the layer centred at z = (k + 1/2) dx), over the interior slabs: at least two
// smoothing lengths below the free surface (where the kernel support is full) and at least one
// above the floor (where the wall particles' boundary pressure lifts the slabs' pressure: +10 %
// in the floor slab at dx = 3.3 cm, enough to steepen a fit over few slabs by 10 %). A line
// fitted through them gives dP/dz and, extrapolated, the floor pressure P(0).
struct HydrostaticMeasurement {
  double slope = 0.0;                    // dP/dz of the fit [Pa/m]
  double floor_pressure = 0.0;           // the fit at z = 0 [Pa]
  double expected_slope = 0.0;           // -rho0 |g| [Pa/m]
  double weight_per_area = 0.0;          // the column's weight over the floor area, M |g| / A [Pa]
  double max_speed = 0.0;                // the column's fastest particle at the end [m/s]
  double sound_speed = 0.0;              // sqrt(k) [m/s]
  std::vector<double> height, pressure;  // the slabs used [m], [Pa]
  std::size_t particles = 0;
};
HydrostaticMeasurement measure_hydrostatic(const std::string& backend, const Scene& scene);

// The scene's rigid "ball" floating in its fluid "water" for the scene's duration. The depth of
// its lowest point below the free surface against Archimedes: the spherical cap of volume
// M / rho_water, pi d^2 (3 R - d) / 3 = M / rho_water, with R the radius of the sphere as
// sampled (N particles of volume dx^3). The free surface, away from the sphere's meniscus, is the
// median of the particle columns' tops plus half a spacing.
struct FloatingMeasurement {
  double depth = 0.0;                       // at the end [m]
  double expected_depth = 0.0;              // [m]
  double vertical_speed = 0.0;              // |v_z| of the ball at the end [m/s]
  double radius = 0.0;                      // of the sampled sphere [m]
  std::vector<double> time, depth_history;  // every 0.01 s [s], [m]
  std::size_t particles = 0;
};
FloatingMeasurement measure_floating(const std::string& backend, const Scene& scene);

// The archimedes case's --quick spacing [m]: its sphere of radius 10 cm is 3 spacings across in
// radius, coarse enough for 2 CPU cores. The reference's unit test runs it too.
inline constexpr double kArchimedesQuickSpacing = 0.2 / 6.0;

}  // namespace mssph::validation
