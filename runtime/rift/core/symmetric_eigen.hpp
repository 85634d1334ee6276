// Eigenvalues and eigenvectors of a symmetric 3×3 matrix, as the rule
// language's eigen built-ins compute them (principal stresses of the vertex
// stress criterion, §5.2 of the paper).
//
// For a symmetric M there is an orthonormal basis of eigenvectors:
// M = Q diag(λ1, λ2, λ3) Qᵀ with real λ1 ≤ λ2 ≤ λ3. They are computed by
// Eigen's SelfAdjointEigenSolver: a Householder reduction to tridiagonal form
// followed by implicit symmetric QR steps, accurate to a few ulps of ‖M‖ even
// for repeated eigenvalues, which closed-form (trigonometric) solutions are
// not. The eigenvector of a repeated largest eigenvalue is any unit vector of
// its eigenspace.
#pragma once

#include <Eigen/Eigenvalues>

#include "rift/core/types.hpp"

namespace rift {

/// λ1 ≤ λ2 ≤ λ3 of the symmetric m (only its lower triangle is read).
inline Vec3 symmetric_eigenvalues(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(m, Eigen::EigenvaluesOnly).eigenvalues();
}

/// λ3, the largest eigenvalue of the symmetric m.
inline Real symmetric_max_eigenvalue(const Mat3& m) {
  return symmetric_eigenvalues(m)(2);
}

/// A unit eigenvector of λ3 (its sign is arbitrary).
inline Vec3 symmetric_max_eigenvector(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(m).eigenvectors().col(2);
}

}  // namespace rift
