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
// its eigenspace. The largest eigenvalue alone, which criteria ask for at
// every cell, has a closed form where it is well conditioned (below).
#pragma once

#include <Eigen/Eigenvalues>
#include <cmath>

#include "rift/core/types.hpp"

namespace rift {

/// λ1 ≤ λ2 ≤ λ3 of the symmetric m (only its lower triangle is read).
inline Vec3 symmetric_eigenvalues(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(m, Eigen::EigenvaluesOnly).eigenvalues();
}

/// λ3, the largest eigenvalue of the symmetric m (only its lower triangle is
/// read). Criteria ask for it at every cell of every step (vertex_stress), so
/// it is the closed form of the characteristic cubic: with q = tr(m) / 3,
/// p = sqrt(‖m - qI‖² / 6) and r = det((m - qI) / p) / 2 in [-1, 1],
/// λ3 = q + 2p cos(acos(r) / 3). Its error is a few ulps of ‖m‖ times
/// 1 / sqrt(1 - r²), the condition of acos: near r = ±1 (two eigenvalues
/// equal to within 1e-3 of the spread, or all three equal) the solver above
/// takes over, so that λ3 stays within about 1e-12 ‖m‖ of it everywhere
/// (tests/runtime: SymmetricEigen.*, on random and near-degenerate spectra).
inline Real symmetric_max_eigenvalue(const Mat3& m) {
  const Real q = (m(0, 0) + m(1, 1) + m(2, 2)) / 3;
  const Real a = m(0, 0) - q;
  const Real b = m(1, 1) - q;
  const Real c = m(2, 2) - q;
  const Real d = m(1, 0);
  const Real e = m(2, 1);
  const Real f = m(2, 0);
  const Real p2 = (a * a + b * b + c * c + 2 * (d * d + e * e + f * f)) / 6;
  // 1 - |r| below this: acos amplifies rounding by more than ~1e3.
  constexpr Real kNearDegenerate = 1e-6;
  if (p2 > 0 && std::isfinite(p2)) {
    const Real p = std::sqrt(p2);
    const Real det = a * (b * c - e * e) - d * (d * c - e * f) + f * (d * e - b * f);
    const Real r = det / (2 * p2 * p);
    if (std::abs(r) < 1 - kNearDegenerate) return q + 2 * p * std::cos(std::acos(r) / 3);
  }
  return symmetric_eigenvalues(m)(2);
}

/// A unit eigenvector of λ3 (its sign is arbitrary).
inline Vec3 symmetric_max_eigenvector(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(m).eigenvectors().col(2);
}

}  // namespace rift
