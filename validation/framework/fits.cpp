#include "fits.hpp"

#include <algorithm>
#include <cmath>

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
