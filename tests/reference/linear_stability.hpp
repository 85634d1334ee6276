// Linear stability of an explicit integrator on the reference cloth: the
// Jacobian J of y' = (v, a(x, v)) at a state (central differences), its
// eigenvalues, and the RK4 amplification factor R(z) = 1 + z + z^2/2 + z^3/6
// + z^4/24. A step dt is linearly stable when |R(lambda dt)| <= 1 for every
// eigenvalue lambda with Re(lambda) <= 0; eigenvalues with Re(lambda) > 0 are
// physical instabilities (a compressed sheet buckling out of its plane) that
// the exact flow shares, so they are reported apart.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <complex>
#include <vector>

#include "reference_cloth.hpp"

namespace rift::reference {

inline Real rk4_amplification(std::complex<Real> z) {
  const std::complex<Real> z2 = z * z;
  return std::abs(1.0 + z + z2 / 2.0 + z2 * z / 6.0 + z2 * z2 / 24.0);
}

struct Spectrum {
  std::vector<std::complex<Real>> eigenvalues;
  Real max_modulus = 0;           ///< largest |lambda| with Re(lambda) <= 0, 1/s
  Real max_imaginary = 0;         ///< largest |Im(lambda)|, rad/s
  Real most_negative_real = 0;    ///< smallest Re(lambda), 1/s
  Real largest_real = 0;          ///< largest Re(lambda) (> 0: physical instability)
  std::size_t growing_modes = 0;  ///< eigenvalues with Re(lambda) > 1e-6 max |lambda|

  /// Largest |R(lambda dt)| over the decaying or neutral eigenvalues.
  Real max_amplification(Real dt) const {
    Real worst = 0;
    for (const auto& l : eigenvalues) {
      if (l.real() <= 1e-6 * max_modulus) worst = std::max(worst, rk4_amplification(l * dt));
    }
    return worst;
  }
  /// The largest dt with max_amplification(dt) <= 1 + 1e-9 (bisection).
  Real rk4_limit() const {
    Real lo = 0, hi = 1;
    for (int it = 0; it < 80; ++it) {
      const Real mid = (lo + hi) / 2;
      (max_amplification(mid) <= 1 + 1e-9 ? lo : hi) = mid;
    }
    return lo;
  }
};

/// Eigenvalues of d(x, v)'/d(x, v) at the cloth's current state.
inline Spectrum linear_spectrum(ReferenceCloth& cloth) {
  const int n = static_cast<int>(cloth.vertex_count());
  const int dofs = 3 * n;
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(2 * dofs, 2 * dofs);
  std::vector<Vec3> x = cloth.positions(), v = cloth.velocities(), ap(n), am(n);
  const Real eps = 1e-7;
  for (int pass = 0; pass < 2; ++pass) {  // columns of d/dx, then of d/dv
    std::vector<Vec3>& y = pass == 0 ? x : v;
    for (int j = 0; j < dofs; ++j) {
      const Real saved = y[j / 3][j % 3];
      y[j / 3][j % 3] = saved + eps;
      cloth.accelerations(x.data(), v.data(), ap.data());
      y[j / 3][j % 3] = saved - eps;
      cloth.accelerations(x.data(), v.data(), am.data());
      y[j / 3][j % 3] = saved;
      for (int i = 0; i < dofs; ++i)
        jac(dofs + i, pass * dofs + j) = (ap[i / 3][i % 3] - am[i / 3][i % 3]) / (2 * eps);
    }
  }
  for (int j = 0; j < dofs; ++j)
    jac(j, dofs + j) = 1;  // x' = v
  Eigen::EigenSolver<Eigen::MatrixXd> solver(jac, /*computeEigenvectors=*/false);
  Spectrum s;
  for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
    s.eigenvalues.push_back(solver.eigenvalues()[i]);
  for (const auto& l : s.eigenvalues)
    s.largest_real = std::max(s.largest_real, l.real());
  Real scale = 0;  // finite differences leave neutral modes slightly off the axis
  for (const auto& l : s.eigenvalues)
    scale = std::max(scale, std::abs(l));
  for (const auto& l : s.eigenvalues) {
    if (l.real() <= 1e-6 * scale) s.max_modulus = std::max(s.max_modulus, std::abs(l));
    s.max_imaginary = std::max(s.max_imaginary, std::abs(l.imag()));
    s.most_negative_real = std::min(s.most_negative_real, l.real());
  }
  for (const auto& l : s.eigenvalues)
    s.growing_modes += l.real() > 1e-6 * scale ? 1 : 0;
  return s;
}

}  // namespace rift::reference
