// Corotation (paper 3.1.2, step 1 of the loop): a rigidly rotated body gives R_i = Q at every
// particle and no elastic force; the polar decomposition copes with flat, inverted and linear
// neighbourhoods.
#include "corotation.hpp"
#include "deformable_fixtures.hpp"
#include "physics/elastic_statics.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace mssph {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// The block and the 12 rigid motions are the physics case's (validation/physics/rotation_invariance).
// Tolerances: positions are exact rotations of the rest positions up to rounding (~1e-16
// relative), so R_i matches Q to ~1e-15 and the residual strain is ~1e-15; 1e-12 on R and 1e-9 of
// E h^2 on forces (the brief's bound) leave orders of magnitude of margin while catching any
// real strain (a strain of 1e-9 already gives forces ~1e-9 E h^2).
void expect_rigid_motion_is_free(bool jitter, bool correction) {
  const validation::RigidMotionResiduals r = validation::rigid_motion_residuals(jitter, correction);
  EXPECT_LT(r.worst_rotation, 1e-12) << "R_i differs from Q";
  EXPECT_LT(r.worst_force, 1e-9) << "elastic force under a rigid rotation";
}

TEST(RotationInvariance, RigidRotationGivesQAndNoForceOnALattice) { expect_rigid_motion_is_free(false, false); }

TEST(RotationInvariance, RigidRotationGivesQAndNoForceOnAJitteredLatticeWithCorrection) {
  expect_rigid_motion_is_free(true, true);
}

// A flat neighbourhood (rank 2 moment matrix, e.g. one layer of particles): the missing third
// direction follows from the determinant, so R is still Q.
TEST(PolarRotation, FlatNeighbourhoodGivesTheRotation) {
  const Matrix3d q = Eigen::AngleAxisd(2.0, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Matrix3d a = Matrix3d::Zero();
  for (const Vector3d& rest : {Vector3d(1, 0, 0), Vector3d(0, 1, 0), Vector3d(-1, 0.5, 0), Vector3d(0.3, -1, 0)}) {
    a += reference::moment_matrix_term(0.7, q * rest, rest);
  }
  // 1e-12: the SVD of a 3x3 matrix in double is accurate to ~1e-15.
  EXPECT_LT((reference::rotation_from_moment_matrix(a, Matrix3d::Identity()) - q).cwiseAbs().maxCoeff(), 1e-12);
}

// An inverted neighbourhood (det A < 0): R is a proper rotation, not the reflection U V^T.
TEST(PolarRotation, InvertedNeighbourhoodGivesAProperRotation) {
  const Matrix3d mirror = Vector3d(1, 1, -1).asDiagonal();
  const Matrix3d a = mirror * Vector3d(3.0, 2.0, 1.0).asDiagonal();
  const Matrix3d r = reference::rotation_from_moment_matrix(a, Matrix3d::Identity());
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  // The proper rotation nearest to diag(3, 2, -1) flips the direction of the smallest singular
  // value: the identity.
  EXPECT_LT((r - Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

// A neighbourhood on one line fixes only where the line goes: R maps the line onto its image
// and keeps the last rotation about it; with no neighbour R stays as it was.
TEST(PolarRotation, LinearAndEmptyNeighbourhoodsKeepThePreviousRotation) {
  const Matrix3d q = Eigen::AngleAxisd(0.8, Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  const Vector3d line(1.0, 0.0, 0.0);
  const Matrix3d a =
      reference::moment_matrix_term(1.0, q * line, line) + reference::moment_matrix_term(1.0, -q * line, -line);
  EXPECT_LT((reference::rotation_from_moment_matrix(a, q) - q).cwiseAbs().maxCoeff(), 1e-12);
  const Matrix3d r = reference::rotation_from_moment_matrix(a, Matrix3d::Identity());
  EXPECT_LT((r * line - q * line).norm(), 1e-12);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  EXPECT_EQ(reference::rotation_from_moment_matrix(Matrix3d::Zero(), q), q);
}

}  // namespace
}  // namespace mssph
