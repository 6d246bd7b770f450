#pragma once
// Small fits and error measures shared by the validation cases and the unit tests.
#include <Eigen/Core>

#include <utility>
#include <vector>

namespace mssph::validation {

// Least-squares line y = a + b x: returns {a, b}.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y);

// Observed order of convergence: the slope of log(error) against log(spacing).
double observed_order(const std::vector<double>& spacing, const std::vector<double>& error);

// Root-mean-square difference of two series of vectors over the largest norm in the reference.
double normalised_rms(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& reference);

}  // namespace mssph::validation
