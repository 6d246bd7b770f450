#include "stability.hpp"

#include "model/material_law.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mssph {
namespace {

std::string bound_message(const std::string& body, const std::string& bound, double dt, double limit,
                          const std::string& detail) {
  std::ostringstream out;
  out << "body \"" << body << "\": dt = " << dt << " s exceeds the " << bound << " bound " << limit << " s (" << detail
      << "); the run may blow up";
  return out.str();
}

}  // namespace

std::vector<TimeStepBound> time_step_bounds(const ParticleSetup& setup) {
  std::vector<TimeStepBound> bounds;
  const double h = setup.smoothing_length;
  const double g = setup.gravity.norm();
  if (g > 0.0) bounds.push_back({"(all)", "body-force", 0.25 * std::sqrt(h / g), "0.25 sqrt(h / |g|)"});
  for (const BodySetup& body : setup.bodies) {
    if (body.is_static()) continue;
    const Material& m = body.material;
    double v_max = 0.0;
    for (std::size_t i = body.first; i < body.first + body.count; ++i)
      v_max = std::max(v_max, setup.velocity[i].norm());
    const double c = std::sqrt(m.pressure_stiffness);
    std::ostringstream acoustic;
    acoustic << "0.25 h / (c + v_max) with c = sqrt(k) = " << c << " m/s";
    bounds.push_back({body.name, "acoustic", 0.25 * h / (c + v_max), acoustic.str()});
    if (m.viscosity > 0.0) {
      bounds.push_back({body.name, "viscous", 0.125 * h * h * m.rest_density / m.viscosity, "0.125 h^2 rho0 / mu"});
    }
    if (body.kind == BodyKind::deformable) {
      const double c_p = std::sqrt((lame_lambda(m) + 2.0 * lame_mu(m)) / m.rest_density);
      std::ostringstream elastic;
      elastic << "0.25 h / c_p with c_p = sqrt((lambda + 2 mu) / rho0) = " << c_p << " m/s";
      bounds.push_back({body.name, "elastic", 0.25 * h / c_p, elastic.str()});
      if (m.viscous_modulus > 0.0) {
        // The explicit Kelvin-Voigt stress is a diffusion of velocity with viscosity
        // (eta / E) (lambda + 2 mu); the free bar (validation/physics/bar_vibration) turns
        // unstable between 0.054 and 0.081 in units of h^2 rho0 / that viscosity.
        const double viscosity = m.viscous_modulus / m.young_modulus * (lame_lambda(m) + 2.0 * lame_mu(m));
        bounds.push_back({body.name, "viscoelastic", 0.05 * h * h * m.rest_density / viscosity,
                          "0.05 h^2 rho0 / ((eta / E) (lambda + 2 mu))"});
      }
    }
  }
  return bounds;
}

std::vector<std::string> stability_warnings(const ParticleSetup& setup) {
  std::vector<std::string> warnings;
  for (const TimeStepBound& b : time_step_bounds(setup)) {
    if (setup.dt > b.limit) warnings.push_back(bound_message(b.body, b.name, setup.dt, b.limit, b.formula));
  }
  for (const BodySetup& body : setup.bodies) {
    const Material& m = body.material;
    if (!body.is_static() && body.kind == BodyKind::deformable && m.poisson_ratio > 0.45) {
      std::ostringstream out;
      out << "body \"" << body.name << "\": poisson_ratio = " << m.poisson_ratio
          << " > 0.45: nearly incompressible elasticity stiffens the explicit step (lambda >> mu)";
      warnings.push_back(out.str());
    }
  }
  return warnings;
}

}  // namespace mssph
