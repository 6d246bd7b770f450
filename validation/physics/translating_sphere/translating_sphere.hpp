#pragma once
// The fluid's drag on a sphere towed at a prescribed velocity through closed cubes of fluid, and
// its extrapolation to an unbounded fluid; shared by the physics case and its unit test.
#include "config/scene.hpp"

#include <string>
#include <utility>
#include <vector>

namespace mssph::validation {

// The drag factor F / (6 pi mu R V) of a sphere of radius R moving through the centre of a fixed
// concentric spherical container of radius Rc, lambda = R / Rc:
//   K = (1 - lambda^5) / (1 - 9/4 lambda + 5/2 lambda^3 - 9/4 lambda^5 + lambda^6)
// (Williams 1915; Haberman and Sayre 1958; Happel and Brenner, Low Reynolds Number Hydrodynamics,
// 1965, ch. 4).
double concentric_sphere_drag_factor(double lambda);

// The drag factor of a sphere at the centre of a closed cube of side L lies between those of the
// cube's circumscribed (Rc = sqrt(3) L / 2) and inscribed (Rc = L / 2) spheres: with no-slip walls
// a larger container gives less drag (the minimum-dissipation theorem; Hill and Power 1956).
// Returns {low, high}.
std::pair<double, double> cube_drag_factor_bracket(double radius, double side);

struct TowedSphereMeasurement {
  double drag = 0.0;          // mean fluid force against the motion over the last two fifths [N]
  double drag_earlier = 0.0;  // the mean over the fifth before them: settled when close [N]
  double stokes_drag = 0.0;   // 6 pi mu R V, unbounded fluid [N]
  double factor_low = 0.0;    // the cube's drag factor bracket (cube_drag_factor_bracket) [-]
  double factor_high = 0.0;
  double radius = 0.0;                     // of the sphere as sampled: N particles of volume dx^3 [m]
  double side = 0.0;                       // the cube's inner side [m]
  double reynolds = 0.0;                   // rho V R / mu [-]
  double speed_deviation = 0.0;            // largest |v_x - V| / V over the averaging window [-]
  std::vector<double> time, drag_history;  // every 1 % of the run [s], [N]
  std::size_t particles = 0;
};

// The towing speed the sound speed is set by [m/s]: the case tows at it and at twice it.
inline constexpr double kReferenceSpeed = 0.001;

// The case's scene (scene.json) at spacing dx, viscosity mu [Pa s], cube side [m] and towing
// speed [m/s]. The sound speed keeps the viscous pressure mu V0 / R at 1e-6 rho c^2, with V0 the
// reference speed (README.md says why so stiff); dt is 0.8 of the smaller of the viscous
// (0.125 h^2 rho / mu) and acoustic (0.25 h / c) bounds (docs/model.md, "Time step"). The run lasts
// 2 (L / 2)^2 / nu, twice the time viscosity takes to reach the walls, and the sphere starts
// 0.8 V T behind the cube's centre (on a fluid site), so that it crosses the centre in the middle
// of the averaging window. The sphere's own material ("sphere") has the fluid's values; `extra`
// overrides follow.
Scene translating_sphere_scene(double dx, double mu, double side, double speed,
                               const std::vector<std::string>& extra = {});

// Tows the scene's rigid "sphere" along x at `speed` with a controller: each step its external
// force cancels the fluid's force of the last step and drives its velocity to (speed, 0, 0) at rate
// 1 / (10 dt); its external torque holds it from turning. The fluid's drag is averaged over the
// last two fifths of the run.
TowedSphereMeasurement measure_translating_sphere(const std::string& backend, const Scene& scene, double speed);

// The drag's part linear in the speed, from one cube towed at V0 and at 2 V0 (same scene but the
// speed): Stokes' drag is linear in V, and F(V) = a V + b separates it from a part b that does not
// change with the speed (README.md, "Measured").
struct LinearDrag {
  TowedSphereMeasurement slow, fast;  // at V0 and 2 V0
  double factor = 0.0;                // a / (6 pi mu R) = (F(2 V0) - F(V0)) / (6 pi mu R V0) [-]
  double offset = 0.0;                // b / (6 pi mu R V0) = (2 F(V0) - F(2 V0)) / (6 pi mu R V0) [-]
  double radius_over_side = 0.0;      // R / L [-]
};
LinearDrag measure_linear_drag(const std::string& backend, double dx, double mu, double side,
                               const std::vector<std::string>& extra = {});

// Faxen's expansion of the wall effect, F_S / F = 1 - k R / L + O((R / L)^3), fitted by least
// squares to cubes of several sides: the intercept extrapolates the drag to an unbounded fluid.
struct UnboundedDrag {
  double drag_over_stokes = 0.0;  // F_inf / (6 pi mu R V) [-]
  double wall_coefficient = 0.0;  // k, per R / L [-]
};
UnboundedDrag extrapolate_to_unbounded(const std::vector<LinearDrag>& cubes);

// k of the circumscribed and inscribed spheres (9/4 times 2 / sqrt(3) and 2): the cube's lies between.
std::pair<double, double> cube_wall_coefficient_bracket();

}  // namespace mssph::validation
