// The rotation of a 3×3 matrix (polar decomposition F = R S with det R = +1),
// as the co-rotational finite elements need it: fast, allocation-free, and a
// proper rotation for every input, inverted (det F < 0) or degenerate.
#pragma once

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "rift/core/types.hpp"

namespace rift {

/// The reference: R = U diag(1, 1, det(U Vᵀ)) Vᵀ from a Jacobi SVD F = U Σ Vᵀ
/// (Σ sorted descending, so the flipped axis is the smallest singular value's).
/// Slow (~0.5 µs); kept for tests and as the fallback of polar_rotation.
inline Mat3 polar_rotation_svd(const Mat3& f) {
  Eigen::JacobiSVD<Mat3> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 u = svd.matrixU();
  const Mat3 v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0) u.col(2) = -u.col(2);
  return u * v.transpose();
}

/// The proper rotation R closest to F in the Frobenius norm, i.e. the one that
/// maximises tr(Rᵀ F) over SO(3). For det F > 0 it is the polar factor of
/// F = R S; for det F < 0 (an inverted element) it is U diag(1, 1, -1) Vᵀ,
/// the rotation the co-rotational FEM needs to push the element back.
///
/// Method (Horn 1987; characteristic polynomial solved as in Theobald's QCP,
/// 2005). With the unit quaternion q = (w, x, y, z) of R, tr(Rᵀ F) = qᵀ K q
/// with the symmetric, trace-free
///   K = [ F00+F11+F22   F21-F12       F02-F20       F10-F01     ]
///       [ F21-F12       F00-F11-F22   F01+F10       F02+F20     ]
///       [ F02-F20       F01+F10      -F00+F11-F22   F12+F21     ]
///       [ F10-F01       F02+F20       F12+F21      -F00-F11+F22 ]
/// so q is the eigenvector of K's largest eigenvalue λ. With signed singular
/// values s1 ≥ s2 ≥ |s3| (sign s3 = sign det F) the eigenvalues are
/// s1+s2+s3, s1-s2-s3, -s1+s2-s3, -s1-s2+s3; the characteristic polynomial is
///   P(λ) = λ⁴ - 2‖F‖²λ² - 8 det(F) λ + det K.
/// Its roots are real, so Newton's method started above the largest one,
/// at √3‖F‖ ≥ s1+s2+|s3|, decreases monotonically onto λ (2-3 iterations for
/// a nearly rigid element, where the start is nearly exact). The eigenvector
/// is a column of adj(K - λI) = Π_{j≠1}(λj - λ) q qᵀ: the column whose
/// diagonal entry (a principal 3×3 minor) is largest in magnitude. When Newton
/// is slow or every minor is tiny, λ is (nearly) a multiple root — F of rank
/// ≤ 1, or inverted with s2 ≈ -s3 — and R is ill-determined (not unique at
/// the limit); then the SVD decides. That is rare, so its cost does not count.
inline Mat3 polar_rotation(const Mat3& f) {
  const Real k00 = f(0, 0) + f(1, 1) + f(2, 2);
  const Real k11 = f(0, 0) - f(1, 1) - f(2, 2);
  const Real k22 = -f(0, 0) + f(1, 1) - f(2, 2);
  const Real k33 = -f(0, 0) - f(1, 1) + f(2, 2);
  const Real k01 = f(2, 1) - f(1, 2), k02 = f(0, 2) - f(2, 0), k03 = f(1, 0) - f(0, 1);
  const Real k12 = f(0, 1) + f(1, 0), k13 = f(0, 2) + f(2, 0), k23 = f(1, 2) + f(2, 1);

  const Real norm2 = f.squaredNorm();
  // A non-finite F (an exploded element) gives a non-finite R, so that the
  // loop's check reports the explosion instead of a made-up rotation.
  if (!std::isfinite(norm2)) return Mat3::Constant(std::numeric_limits<Real>::quiet_NaN());
  if (!(norm2 > 0)) return Mat3::Identity();  // a point: every rotation is as close
  const Real det_f = f.determinant();
  // det K by 2×2 minors of its first two rows and last two rows (Laplace).
  const Real a01 = k00 * k11 - k01 * k01, a02 = k00 * k12 - k02 * k01, a03 = k00 * k13 - k03 * k01,
             a12 = k01 * k12 - k02 * k11, a13 = k01 * k13 - k03 * k11, a23 = k02 * k13 - k03 * k12;
  const Real b01 = k02 * k13 - k12 * k03, b02 = k02 * k23 - k22 * k03, b03 = k02 * k33 - k23 * k03,
             b12 = k12 * k23 - k22 * k13, b13 = k12 * k33 - k23 * k13, b23 = k22 * k33 - k23 * k23;
  const Real det_k = a01 * b23 - a02 * b13 + a03 * b12 + a12 * b03 - a13 * b02 + a23 * b01;
  const Real c2 = -2 * norm2, c1 = -8 * det_f, c0 = det_k;

  // Newton from above. A nearly rigid element converges in 2-3 iterations, a
  // random matrix in ~6 (rarely 15); slower means λ is a (nearly) multiple
  // root, whose eigenvector is ill-determined: the SVD decides then.
  Real lambda = std::sqrt(3 * norm2);
  bool converged = false;
  for (int it = 0; it < 24 && !converged; ++it) {
    const Real l2 = lambda * lambda;
    const Real p = (l2 + c2) * l2 + c1 * lambda + c0;
    const Real dp = 4 * l2 * lambda + 2 * c2 * lambda + c1;
    if (!(dp > 0)) break;  // rounding put λ at or below a multiple root
    const Real step = p / dp;
    lambda -= step;
    converged = std::abs(step) <= 1e-14 * lambda;
  }
  if (!converged) return polar_rotation_svd(f);

  // A = K - λI; its principal 3×3 minors m_i (row and column i removed).
  const Real d0 = k00 - lambda, d1 = k11 - lambda, d2 = k22 - lambda, d3 = k33 - lambda;
  auto det3 = [](Real a, Real b, Real c, Real d, Real e, Real g, Real h, Real i, Real j) {
    return a * (e * j - g * i) - b * (d * j - g * h) + c * (d * i - e * h);
  };
  const Real m0 = det3(d1, k12, k13, k12, d2, k23, k13, k23, d3);
  const Real m1 = det3(d0, k02, k03, k02, d2, k23, k03, k23, d3);
  const Real m2 = det3(d0, k01, k03, k01, d1, k13, k03, k13, d3);
  const Real m3 = det3(d0, k01, k02, k01, d1, k12, k02, k12, d2);
  const Real a0 = std::abs(m0), a1 = std::abs(m1), a2 = std::abs(m2), a3 = std::abs(m3);
  const Real best = std::max(std::max(a0, a1), std::max(a2, a3));
  // |m_i| = Π gaps · q_i² ≥ Π gaps / 4, and Π gaps ~ λ³ for a well separated
  // λ. Below 1e-6 λ³ the top gap is below ~1e-6 λ and the eigenvector would
  // lose more than ~1e-10 of precision (R itself is then ill-conditioned).
  const Real scale = lambda > 0 ? lambda : std::sqrt(norm2);
  if (!(best > 1e-6 * scale * scale * scale)) return polar_rotation_svd(f);

  // Column i of adj(A): cofactors C_ji = (-1)^(i+j) · minor(row i, column j
  // removed); by symmetry of A, column i = row i of cofactors.
  Real q[4];
  if (best == a0) {
    q[0] = m0;
    q[1] = -det3(k01, k12, k13, k02, d2, k23, k03, k23, d3);
    q[2] = det3(k01, d1, k13, k02, k12, k23, k03, k13, d3);
    q[3] = -det3(k01, d1, k12, k02, k12, d2, k03, k13, k23);
  } else if (best == a1) {
    q[0] = -det3(k01, k02, k03, k12, d2, k23, k13, k23, d3);
    q[1] = m1;
    q[2] = -det3(d0, k01, k03, k02, k12, k23, k03, k13, d3);
    q[3] = det3(d0, k01, k02, k02, k12, d2, k03, k13, k23);
  } else if (best == a2) {
    q[0] = det3(k01, k02, k03, d1, k12, k13, k13, k23, d3);
    q[1] = -det3(d0, k02, k03, k01, k12, k13, k03, k23, d3);
    q[2] = m2;
    q[3] = -det3(d0, k01, k02, k01, d1, k12, k03, k13, k23);
  } else {
    q[0] = -det3(k01, k02, k03, d1, k12, k13, k12, d2, k23);
    q[1] = det3(d0, k02, k03, k01, k12, k13, k02, d2, k23);
    q[2] = -det3(d0, k01, k03, k01, d1, k13, k02, k12, k23);
    q[3] = m3;
  }
  const Real inv = 1 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const Real w = q[0] * inv, x = q[1] * inv, y = q[2] * inv, z = q[3] * inv;
  Mat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

}  // namespace rift
