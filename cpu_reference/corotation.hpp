#pragma once
// Step 1 of the loop (paper 3.2): the rotation R_i of each deformable particle's neighbourhood,
// which makes the elastic forces of eq. 4-6 invariant under rigid rotations (the corotational
// approach of Becker, Ihmsen and Teschner 2009, the paper's reference [1]).
#include <Eigen/Core>

namespace mssph::reference {

// One neighbour's contribution to the moment matrix A_i = sum_j m_j W(|X_ij|) x_ij X_ij^T, where
// X_ij = X_j - X_i is the rest offset and x_ij = x_j - x_i the current one.
inline Eigen::Matrix3d moment_matrix_term(double weight, const Eigen::Vector3d& x_ij,
                                          const Eigen::Vector3d& rest_x_ij) {
  return weight * x_ij * rest_x_ij.transpose();
}

// The rotational part of A (polar decomposition A = R S, S symmetric positive semi-definite).
//
// Method: singular value decomposition A = U Sigma V^T (Eigen's two-sided Jacobi SVD, singular
// values in decreasing order) and R = U V^T. When det(U V^T) < 0 (a reflection, from an inverted
// or flat neighbourhood) the column of U of the smallest singular value is negated, which gives
// the proper rotation closest to A. This covers every neighbourhood of rank 2 or 3, flat ones
// included: the third direction follows from the other two by the determinant condition.
//
// A neighbourhood of rank 1 (all neighbours on one line) fixes only the image u of the line's
// rest direction v; R is then the rotation nearest to `previous` that maps v onto u (the rotation
// about the line is unobservable and is kept from the last step). Rank 0 (no neighbours) keeps
// `previous`. Rank is judged by the singular values relative to the largest (below 1e-9: absent).
Eigen::Matrix3d rotation_from_moment_matrix(const Eigen::Matrix3d& a, const Eigen::Matrix3d& previous);

}  // namespace mssph::reference
