#pragma once
// The collapse of a water column on a dry floor (dam break): measured on any backend, and
// compared with an experiment in non-dimensional form. Shared by dam_break_case.cpp and
// tests/reference/dam_break_test.cpp.
#include "config/scene.hpp"
#include "physics/dam_break/experiments.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The scene's fluid body "water" is a column of width a (its box's x size) standing on the floor
// z = 0 against the tank's wall. Sampled every `sample_interval` seconds, with a row the
// particles of one lattice row across the slab (so that a lone particle jetting ahead or clinging
// above does not count): the surge front, the row-th largest x of the water's particles; and the
// column's height at the wall, the row-th largest z of those within one spacing of the wall. Each
// is measured from the wall or the floor, plus half a spacing (a particle stands for a cell of
// side dx).
struct DamBreakMeasurement {
  double width = 0.0;                       // a [m]
  double height = 0.0;                      // the column's initial height [m]
  double gravity = 0.0;                     // |g| [m/s^2]
  std::vector<double> time, front, column;  // [s], front [m], height at the wall [m]
  std::size_t particles = 0;
};
DamBreakMeasurement measure_dam_break(const std::string& backend, const Scene& scene, double sample_interval);

// The column's width a of the case's scene (scene.json, the water box's x size) [m].
inline constexpr double kDamBreakColumnWidth = 0.146;

// The case's scene at spacing dx (a divisor of a / 2, the slab's thickness), the step in
// proportion to dx (the acoustic bound), then `overrides` (--set syntax).
Scene dam_break_scene(double dx, const std::vector<std::string>& overrides = {});

// The front Z = x / a against T = t sqrt(2 g / a) compared with an experiment's (T_e, Z_e) over
// the surge, Z_e in [first_front, last_front]:
// - speed: least-squares dZ/dT of each over its own samples in that range;
// - offset: T_e - T where each first reaches first_front (the experiment's later release);
// - largest_deviation: max |Z(T_e - offset) / Z_e - 1| over the experiment's points in range.
struct SurgeComparison {
  double speed = 0.0;
  double expected_speed = 0.0;
  double offset = 0.0;
  double largest_deviation = 0.0;
  std::size_t compared_points = 0;
};
SurgeComparison compare_surge(const std::vector<double>& T, const std::vector<double>& Z,
                              const std::vector<double>& experiment_T, const std::vector<double>& experiment_Z,
                              double first_front, double last_front);

// The measurement in the experiments' variables: T = t sqrt(2 g / a), Z = x / a,
// tau = t sqrt(g / a) and H / 2a.
struct NondimensionalCollapse {
  std::vector<double> T, Z, tau, H;
};
NondimensionalCollapse nondimensional(const DamBreakMeasurement& m);

// The surge compared: from where the front has moved half a column width to half a column width
// short of the far wall (README.md says why).
inline constexpr double kSurgeFirstFront = 1.5;
inline constexpr double kSurgeLastFront = 3.5;

// compare_surge over that range, against the experiment's front.
SurgeComparison compare_surge(const NondimensionalCollapse& c, const DamBreakExperiment& experiment);

// The largest |H / H_exp - 1| over the experiment's heights within the simulated times.
double largest_height_deviation(const NondimensionalCollapse& c, const DamBreakExperiment& experiment);

// y at x by linear interpolation in the increasing samples xs, held constant beyond them.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x);

}  // namespace mssph::validation
