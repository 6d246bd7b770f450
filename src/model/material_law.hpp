#pragma once
// The material law of elastic bodies: Lame parameters of an isotropic material from its Young's
// modulus and Poisson's ratio. Both precisions take them from here (the float backends through
// the rest state, DeformableRestState::lame).
#include "config/scene.hpp"

namespace mssph {

struct LameParameters {
  double lambda = 0.0;  // [Pa]
  double mu = 0.0;      // shear modulus [Pa]
};

// mu_L = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)).
double lame_mu(const Material& m);
double lame_lambda(const Material& m);
inline LameParameters lame_parameters(const Material& m) { return {lame_lambda(m), lame_mu(m)}; }

}  // namespace mssph
