#include "corotation.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace mssph::reference {
namespace {

// Relative size below which a singular value counts as zero: far above the rounding of a 3x3 SVD
// in double (~1e-15) and far below any physical aspect ratio of a neighbourhood.
constexpr double kRankTolerance = 1e-9;

}  // namespace

Eigen::Matrix3d rotation_from_moment_matrix(const Eigen::Matrix3d& a, const Eigen::Matrix3d& previous) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Vector3d sigma = svd.singularValues();
  if (!(sigma(0) > 0.0)) return previous;
  if (sigma(1) <= kRankTolerance * sigma(0)) {
    // Rank 1: rotate previous minimally so that it maps the rest direction v onto u.
    const Eigen::Vector3d u = svd.matrixU().col(0);
    const Eigen::Vector3d v = svd.matrixV().col(0);
    const Eigen::Quaterniond align = Eigen::Quaterniond::FromTwoVectors(previous * v, u);
    return align.toRotationMatrix() * previous;
  }
  Eigen::Matrix3d u = svd.matrixU();
  const Eigen::Matrix3d& v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) = -u.col(2);
  return u * v.transpose();
}

}  // namespace mssph::reference
