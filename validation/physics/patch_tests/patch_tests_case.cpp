// Physics case: uniaxial stress, uniaxial strain and simple shear patch tests (README.md beside
// this file). Reference backend: the stresses are the reference's internal state.
#include "framework/case_functions.hpp"
#include "model/material_law.hpp"
#include "physics/elastic_statics.hpp"

namespace mssph::validation {
namespace {

double xx(const Eigen::Matrix3d& s) { return s(0, 0); }
double yy(const Eigen::Matrix3d& s) { return s(1, 1); }
double xy(const Eigen::Matrix3d& s) { return s(0, 1); }

}  // namespace

CaseResult run_patch_tests_case(const CaseContext&) {
  CaseResult result;
  result.resolution =
      "dx = 1 cm, h = 2 dx, 10^3 particles, kernel-gradient correction on; stresses at the interior "
      "particles (at least h from every face); strain 1e-3";
  const Material& m = case_scene("physics/patch_tests").bodies.front().material;
  const double young = m.young_modulus;
  const double lambda = lame_lambda(m);
  const double mu = lame_mu(m);
  const double e = 1e-3;
  const double nu = m.poisson_ratio;
  // 2 % (the bound): with correction the gradient of a linear field is exact, so what
  // remains is the Green-Saint-Venant strain's quadratic term, e / 2 = 0.05 %.
  const double tolerance = 0.02;
  for (const char* strain : {"green_saint_venant", "cauchy"}) {
    const std::string tag = std::string(" (") + strain + ")";
    {
      reference::ReferenceBackend block = patch_block(true, strain);
      const auto s = interior_stresses(block, Eigen::Vector3d(1.0 + e, 1.0 - nu * e, 1.0 - nu * e).asDiagonal());
      result.checks.push_back(relative_check("uniaxial stress: sigma_xx / (E e), worst" + tag, "-", 1.0,
                                             farthest_from(s, young * e, xx) / (young * e), tolerance));
      result.checks.push_back(absolute_check("uniaxial stress: sigma_yy / (E e), worst" + tag, "-", 0.0,
                                             farthest_from(s, 0.0, yy) / (young * e), tolerance));
    }
    {
      reference::ReferenceBackend block = patch_block(true, strain);
      Eigen::Matrix3d g = Eigen::Matrix3d::Identity();
      g(0, 1) = e;
      const auto s = interior_stresses(block, g);
      result.checks.push_back(relative_check("simple shear: sigma_xy / (mu gamma), worst" + tag, "-", 1.0,
                                             farthest_from(s, mu * e, xy) / (mu * e), tolerance));
    }
  }
  reference::ReferenceBackend block = patch_block(true, "green_saint_venant");
  const auto s = interior_stresses(block, Eigen::Vector3d(1.0 + e, 1.0, 1.0).asDiagonal());
  result.checks.push_back(relative_check("uniaxial strain: sigma_xx / ((lambda + 2 mu) e), worst", "-", 1.0,
                                         farthest_from(s, (lambda + 2.0 * mu) * e, xx) / ((lambda + 2.0 * mu) * e),
                                         tolerance));
  result.checks.push_back(relative_check("uniaxial strain: sigma_yy / (lambda e), worst", "-", 1.0,
                                         farthest_from(s, lambda * e, yy) / (lambda * e), tolerance));
  for (Check& c : result.checks) c.backend = "reference";
  return result;
}

}  // namespace mssph::validation
