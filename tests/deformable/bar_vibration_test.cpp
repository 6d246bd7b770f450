// Dynamics of a free elastic bar: released from a uniform 1 % stretch it vibrates at its first
// longitudinal frequency f = (1 / 2L) sqrt(E / rho) and, without damping, keeps its energy; with
// mass-proportional damping at rate gamma its vibration energy decays as exp(-gamma t).
//
// Resolution: dx = 1 cm, h = 2 dx, a 30 x 6 x 6 particle bar (L = 0.3 m, slender enough that the
// lateral-inertia correction (pi nu r_g / L)^2 is 0.6 %), kernel-gradient correction on. Without
// correction the scheme is not conservative (its forces leave out how the rotations R_i depend on
// the positions, a term that vanishes only where sum_j y_ij (x) d_ij = F, i.e. with correction):
// this bar's energy then grows by 54 % in 10 periods (period 0.955 T), so these tests run with
// correction on.
#include "deformable_fixtures.hpp"
#include "elastic_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mssph {
namespace {

using Eigen::Vector3d;

constexpr double kDx = 0.01;
constexpr double kLength = 0.3;
constexpr double kSide = 0.06;
constexpr double kYoung = 1.0e5;
constexpr double kPoisson = 0.3;
constexpr double kDensity = 1000.0;
// The elastic bound 0.25 h / c_p is 4.3e-4 s here (c_p = 11.6 m/s).
constexpr double kDt = 3.0e-4;

reference::ReferenceBackend stretched_bar(double damping) {
  nlohmann::json doc = testing::elastic_scene(kDx, kDt);
  nlohmann::json material = testing::elastic_material(kYoung, kPoisson);
  material["kernel_gradient_correction"] = true;
  material["damping"] = damping;
  doc["bodies"]["bar"] = testing::deformable_box({kLength, kSide, kSide}, Vector3d::Zero(), material);
  reference::ReferenceBackend backend = testing::make_backend(doc);
  // Uniaxial stress: 1 % stretch along the bar, lateral contraction nu times that.
  const double e = 0.01;
  testing::deform_body(backend, 0, Vector3d(1.0 + e, 1.0 - kPoisson * e, 1.0 - kPoisson * e).asDiagonal(),
                       Vector3d::Zero());
  return backend;
}

// The bar's total energy and elongation, sampled every step.
struct BarHistory {
  std::vector<double> time;
  std::vector<double> energy;      // strain energy at x_n + kinetic energy at v_n [J]
  std::vector<double> elongation;  // end-to-end length minus its rest value [m]
};

BarHistory run(reference::ReferenceBackend& backend, double duration) {
  BarHistory history;
  const auto steps = static_cast<std::size_t>(std::round(duration / kDt));
  const std::vector<double>& mass = backend.setup().mass;
  for (std::size_t s = 0; s < steps; ++s) {
    const std::vector<Vector3d> v_before = backend.particles().velocity;  // v_{n-1/2}
    backend.step();  // strain energy at x_n, then v_{n+1/2} and x_{n+1}
    double kinetic = 0.0;
    for (std::size_t i = 0; i < mass.size(); ++i) {
      // Leap-frog velocities are staggered: v_n = (v_{n-1/2} + v_{n+1/2}) / 2.
      kinetic += 0.5 * mass[i] * (0.5 * (v_before[i] + backend.particles().velocity[i])).squaredNorm();
    }
    double lo = 1e300;
    double hi = -1e300;
    for (const Vector3d& x : backend.particles().position) {
      lo = std::min(lo, x.x());
      hi = std::max(hi, x.x());
    }
    history.time.push_back(static_cast<double>(s) * kDt);
    history.energy.push_back(reference::body_strain_energy(backend.setup(), backend.deformables(), 0) + kinetic);
    history.elongation.push_back(hi - lo - (kLength - kDx));
  }
  return history;
}

// The mean period between successive downward zero crossings of the elongation.
double measured_period(const BarHistory& history) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < history.time.size(); ++k) {
    const double a = history.elongation[k - 1];
    const double b = history.elongation[k];
    if (a > 0.0 && b <= 0.0) crossings.push_back(history.time[k - 1] + kDt * a / (a - b));
  }
  if (crossings.size() < 2) return 0.0;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// 10 % (the brief's bound) on the frequency: the particles' Shepard volumes V0_i at the surface
// exceed their share of the bar's volume (its strain energy at the start is 12 % above
// 1/2 E e^2 V), which stiffens this bar; measured period 0.932 T. 2 % on the energy over 10
// periods (the brief's bound); measured drift 0.5 %.
TEST(BarVibration, FreeBarOscillatesAtItsLongitudinalFrequencyAndKeepsItsEnergy) {
  reference::ReferenceBackend backend = stretched_bar(0.0);
  const double period = 2.0 * kLength / std::sqrt(kYoung / kDensity);
  const BarHistory history = run(backend, 10.0 * period);
  EXPECT_NEAR(measured_period(history) / period, 1.0, 0.10);
  double drift = 0.0;
  for (double e : history.energy) drift = std::max(drift, std::abs(e / history.energy.front() - 1.0));
  EXPECT_LT(drift, 0.02);
}

// Mass-proportional damping at gamma = 5 /s: energy decays as exp(-gamma t). The decay rate is a
// least-squares fit of log(energy) over 4 whole periods (the energy ripples at twice the
// vibration frequency as it moves between strain and motion; whole periods average that out).
// 5 %: the fit over a rippled decay at gamma / omega = 0.05, and the explicit damping's first-order
// error gamma dt / 2 = 0.08 %.
TEST(BarVibration, DampingDecaysTheVibrationAtTheConfiguredRate) {
  const double gamma = 5.0;
  reference::ReferenceBackend backend = stretched_bar(gamma);
  const double period = 2.0 * kLength / std::sqrt(kYoung / kDensity);
  const BarHistory history = run(backend, 4.0 * period);
  double st = 0.0, sl = 0.0, stt = 0.0, stl = 0.0;
  const auto n = static_cast<double>(history.time.size());
  for (std::size_t k = 0; k < history.time.size(); ++k) {
    const double t = history.time[k];
    const double l = std::log(history.energy[k]);
    st += t;
    sl += l;
    stt += t * t;
    stl += t * l;
  }
  const double slope = (n * stl - st * sl) / (n * stt - st * st);
  EXPECT_NEAR(-slope / gamma, 1.0, 0.05);
}

}  // namespace
}  // namespace mssph
