#include "sim/stability.hpp"

#include <cmath>
#include <sstream>

namespace mssph {
namespace {

std::string bound_message(const std::string& body, const std::string& bound, double dt, double limit,
                          const std::string& detail) {
  std::ostringstream out;
  out << "body \"" << body << "\": dt = " << dt << " s exceeds the " << bound << " bound " << limit << " s ("
      << detail << "); the run may blow up";
  return out.str();
}

}  // namespace

double lame_mu(const Material& m) { return m.young_modulus / (2.0 * (1.0 + m.poisson_ratio)); }
double lame_lambda(const Material& m) {
  return m.young_modulus * m.poisson_ratio / ((1.0 + m.poisson_ratio) * (1.0 - 2.0 * m.poisson_ratio));
}

std::vector<std::string> stability_warnings(const ParticleSetup& setup) {
  std::vector<std::string> warnings;
  const double h = setup.smoothing_length;
  const double dt = setup.dt;
  const double g = setup.gravity.norm();
  if (g > 0.0 && dt > 0.25 * std::sqrt(h / g)) {
    warnings.push_back(bound_message("(all)", "body-force", dt, 0.25 * std::sqrt(h / g), "0.25 sqrt(h / |g|)"));
  }
  for (const BodySetup& body : setup.bodies) {
    if (body.is_static()) continue;
    const Material& m = body.material;
    double v_max = 0.0;
    for (std::size_t i = body.first; i < body.first + body.count; ++i) v_max = std::max(v_max, setup.velocity[i].norm());
    const double c = std::sqrt(m.pressure_stiffness);
    const double acoustic = 0.25 * h / (c + v_max);
    if (dt > acoustic) {
      std::ostringstream detail;
      detail << "0.25 h / (c + v_max) with c = sqrt(k) = " << c << " m/s";
      warnings.push_back(bound_message(body.name, "acoustic", dt, acoustic, detail.str()));
    }
    if (m.viscosity > 0.0) {
      const double viscous = 0.125 * h * h * m.rest_density / m.viscosity;
      if (dt > viscous) warnings.push_back(bound_message(body.name, "viscous", dt, viscous, "0.125 h^2 rho0 / mu"));
    }
    if (body.kind == BodyKind::deformable) {
      const double c_p = std::sqrt((lame_lambda(m) + 2.0 * lame_mu(m)) / m.rest_density);
      const double elastic = 0.25 * h / c_p;
      if (dt > elastic) {
        std::ostringstream detail;
        detail << "0.25 h / c_p with c_p = sqrt((lambda + 2 mu) / rho0) = " << c_p << " m/s";
        warnings.push_back(bound_message(body.name, "elastic", dt, elastic, detail.str()));
      }
      if (m.poisson_ratio > 0.45) {
        std::ostringstream out;
        out << "body \"" << body.name << "\": poisson_ratio = " << m.poisson_ratio
            << " > 0.45: nearly incompressible elasticity stiffens the explicit step (lambda >> mu)";
        warnings.push_back(out.str());
      }
    }
  }
  return warnings;
}

}  // namespace mssph
