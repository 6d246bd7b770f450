#pragma once
// The material models of deformable bodies (scene key `model`) and the range of compression each
// is valid for. The equations are in cpu_reference/elasticity.hpp (float64) and
// kernels/common/elastic_physics.hpp (float32).
namespace mssph {

enum class ElasticModel {
  // St Venant-Kirchhoff: Green-Saint-Venant strain, linear stress (the paper's eq. 5). Its stress
  // under compression peaks and then falls back to zero as a neighbourhood collapses.
  saint_venant_kirchhoff,
  // Corotated linear elasticity: Cauchy strain in the rotated rest frame (Becker et al. 2009).
  // The stress grows linearly with compression, without bound.
  corotated_linear,
  // Compressible Neo-Hookean (Bonet and Wood 2008, eq. 6.28): the volumetric energy
  // lambda/2 (ln J)^2 - mu ln J grows without bound as J = det F goes to 0.
  neo_hookean,
};

// The scene file's spelling: "stvk", "corotated", "neo_hookean".
const char* to_string(ElasticModel model);

// The Neo-Hookean energy is continued below this volume ratio J by its second-order Taylor
// expansion in J, so that float32 never takes the logarithm of a vanishing or negative J and the
// force stays finite (and still grows) for a neighbourhood pushed through itself.
inline constexpr double kNeoHookeanBarrierEnd = 0.1;

// The smallest volume ratio J = det F for which a model is what it claims to be; particles below
// it are counted and warned about (src/run/simulation_run.cpp).
//   stvk: 1/sqrt(3). Under confined (uniaxial-strain) compression F = diag(s, 1, 1), the one a
//     block squeezed against the ground sees under a load, P_xx = (lambda + 2 mu) s (s^2 - 1) / 2
//     has dP/ds = 0 at s = 1/sqrt(3): beyond it the material pushes back less the more it is
//     compressed, and collapses (the known St Venant-Kirchhoff compression instability).
//   corotated: 0. Its stress is linear in F in the rotated frame; only an inverted neighbourhood
//     (J <= 0) is outside what the model describes.
//   neo_hookean: kNeoHookeanBarrierEnd, where its energy stops being the Neo-Hookean one.
inline constexpr double lowest_valid_volume_ratio(ElasticModel model) {
  switch (model) {
    case ElasticModel::saint_venant_kirchhoff:
      return 0.57735026918962576;  // 1 / sqrt(3)
    case ElasticModel::corotated_linear:
      return 0.0;
    case ElasticModel::neo_hookean:
      return kNeoHookeanBarrierEnd;
  }
  return 0.0;
}

}  // namespace mssph
