#pragma once
// Small fits and error measures shared by the validation cases and the unit tests.
#include <Eigen/Core>

#include <array>
#include <utility>
#include <vector>

namespace mssph::validation {

// Least-squares line y = a + b x: returns {a, b}.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y);

// Observed order of convergence: the slope of log(error) against log(spacing).
double observed_order(const std::vector<double>& spacing, const std::vector<double>& error);

// Grid convergence of a value q measured at three spacings h_coarse > h_middle > h_fine whose
// ratios may differ (Celik et al., J. Fluids Eng. 130, 078001, 2008): the apparent order p, by
// fixed-point iteration of p = |ln|e32 / e21| + ln((r21^p - 1) / (r32^p - 1))| / ln r21, and
// Richardson's limit (r21^p q_fine - q_middle) / (r21^p - 1). Defined only where the values
// converge monotonically (the two changes of one sign, the finer smaller); otherwise
// `monotone` is false and order and limit are NaN.
struct GridConvergence {
  bool monotone = false;
  double order = 0.0;
  double limit = 0.0;
};
GridConvergence grid_convergence(const std::array<double, 3>& spacing, const std::array<double, 3>& value);

// Root-mean-square difference of two series of vectors over the largest norm in the reference.
double normalised_rms(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& reference);

}  // namespace mssph::validation
