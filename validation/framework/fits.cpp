#include "fits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mssph::validation {

std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - slope * sx) / n, slope};
}

double observed_order(const std::vector<double>& spacing, const std::vector<double>& error) {
  std::vector<double> lx, ly;
  for (std::size_t k = 0; k < spacing.size(); ++k) {
    lx.push_back(std::log(spacing[k]));
    ly.push_back(std::log(std::abs(error[k])));
  }
  return fit_line(lx, ly).second;
}

GridConvergence grid_convergence(const std::array<double, 3>& spacing, const std::array<double, 3>& value) {
  GridConvergence g;
  g.order = std::numeric_limits<double>::quiet_NaN();
  g.limit = std::numeric_limits<double>::quiet_NaN();
  const double e32 = value[1] - value[0];  // middle minus coarse
  const double e21 = value[2] - value[1];  // fine minus middle
  if (e32 == 0.0 || e21 == 0.0 || (e32 > 0.0) != (e21 > 0.0) || std::abs(e21) >= std::abs(e32)) return g;
  const double r21 = spacing[1] / spacing[2];
  const double r32 = spacing[0] / spacing[1];
  const double log_ratio = std::log(std::abs(e32 / e21));
  double p = log_ratio / std::log(r21);
  for (int k = 0; k < 100; ++k)
    p = std::abs(log_ratio + std::log((std::pow(r21, p) - 1.0) / (std::pow(r32, p) - 1.0))) / std::log(r21);
  g.monotone = true;
  g.order = p;
  g.limit = (std::pow(r21, p) * value[2] - value[1]) / (std::pow(r21, p) - 1.0);
  return g;
}

double normalised_rms(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& reference) {
  double sum = 0.0;
  double scale = 0.0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    sum += (a[k] - reference[k]).squaredNorm();
    scale = std::max(scale, reference[k].norm());
  }
  return std::sqrt(sum / static_cast<double>(reference.size())) / scale;
}

}  // namespace mssph::validation
