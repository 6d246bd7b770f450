#pragma once
// The viscous drag of a plate started impulsively under a fluid layer (Stokes' first problem),
// measured on any backend. Shared by plate_shear_case.cpp and tests/reference/plate_shear_test.cpp.
#include "config/scene.hpp"

#include <string>
#include <vector>

namespace mssph::validation {

// The scene's rigid "plate" starts at velocity U along x under the fluid body "fluid", a layer
// of height H and footprint A at rest. Stokes' first problem (Stokes 1851; Batchelor, An
// Introduction to Fluid Dynamics, 1967, sec. 4.3): the fluid's velocity is U erfc(z / (2 sqrt(nu
// t))), and the plate feels the wall shear stress mu U / sqrt(pi nu t) over A, so
// F_x(t) = -mu U A / sqrt(pi nu t), while the layer is deep enough that its free top does not
// move (t < H^2 / (16 nu): erfc(2) = 0.5 %). Sampled every step: the fluid's force on the plate
// along x over the expected one; their ratio averaged over the run's last three quarters (the
// first quarter, where the layer is thinner than a few spacings, is left out).
struct PlateShearMeasurement {
  double ratio = 0.0;                         // mean F_x / F_Stokes over the last three quarters
  double ratio_spread = 0.0;                  // largest minus smallest ratio there
  double viscosity = 0.0;                     // mu [Pa s]
  std::vector<double> time, force, expected;  // [s], F_x [N], Stokes [N]
  std::size_t particles = 0;
};
PlateShearMeasurement measure_plate_shear(const std::string& backend, const Scene& scene);

// The case's scene at spacing dx with the plate and the fluid of viscosity mu, for H^2 / (16 nu);
// dt the smaller of the scene's, scaled with dx (acoustic), and 0.8 of the viscous bound
// 0.125 h^2 rho0 / mu; then `overrides` (--set syntax).
Scene plate_shear_scene(double dx, double viscosity, const std::vector<std::string>& overrides = {});

}  // namespace mssph::validation
