// Preconditioned conjugate gradients over per-vertex Vec3 arrays, with
// constrained vertices as Dirichlet degrees of freedom filtered out of the
// iteration (Baraff & Witkin 1998, §5.3 "modified PCG", with the filter
// reduced to "constrained or free" per vertex): the residual, the search
// directions and the preconditioned residual are kept at zero on constrained
// vertices, so the prescribed values of x there never change. The caller
// puts the prescribed values into x before calling.
//
// Every sweep runs on every core; the dot products are fixed-block sums
// (rift/core/parallel.hpp), so the iterates are the same bits whatever the
// thread count.
#pragma once

#include <cmath>
#include <vector>

#include "rift/core/parallel.hpp"
#include "rift/core/types.hpp"

namespace rift {

struct PcgResult {
  int iterations = 0;
  Real relative_residual = 0;  ///< |r| / |b| on the free vertices at exit
};

/// Scratch arrays kept between solves (a warm solve allocates nothing).
struct PcgScratch {
  std::vector<Vec3> r, z, d, q;
};

/// Solves A x = b on the vertices with is_free[i] != 0, x holding the
/// prescribed values elsewhere. apply_a(const Vec3* p, Vec3* out) writes
/// A p; precondition(const Vec3* r, Vec3* z) writes z ≈ A⁻¹ r. Stops when
/// |r| <= tolerance |b| (free part) or after max_iterations.
template <class ApplyA, class Precondition>
PcgResult filtered_pcg(ApplyA&& apply_a, Precondition&& precondition,
                       const std::vector<char>& is_free, const std::vector<Vec3>& b,
                       std::vector<Vec3>& x, Real tolerance, int max_iterations, PcgScratch& s) {
  const std::size_t n = b.size();
  s.r.resize(n), s.z.resize(n), s.d.resize(n), s.q.resize(n);
  auto filter = [&](std::vector<Vec3>& a) {
    parallel_for(n, [&](std::size_t i) {
      if (!is_free[i]) a[i].setZero();
    });
  };
  auto dot = [&](const std::vector<Vec3>& a, const std::vector<Vec3>& c) {
    return parallel_sum(n, [&](std::size_t i) { return a[i].dot(c[i]); });
  };
  // r = b - A x: the prescribed values of x enter the free rows here.
  apply_a(x.data(), s.r.data());
  parallel_for(n, [&](std::size_t i) { s.r[i] = b[i] - s.r[i]; });
  const Real b_norm2 =
      parallel_sum(n, [&](std::size_t i) { return is_free[i] ? b[i].squaredNorm() : Real(0); });
  filter(s.r);
  PcgResult result;
  Real r_norm2 = dot(s.r, s.r);
  const Real stop2 = tolerance * tolerance * std::max(b_norm2, r_norm2);
  if (r_norm2 == 0 || r_norm2 <= stop2) {
    result.relative_residual = b_norm2 > 0 ? std::sqrt(r_norm2 / b_norm2) : 0;
    return result;
  }
  precondition(s.r.data(), s.z.data());
  filter(s.z);
  parallel_for(n, [&](std::size_t i) { s.d[i] = s.z[i]; });
  Real delta = dot(s.r, s.z);
  // Each filter is fused with the dot product that reads the filtered
  // vector next, and the update of x and r with the residual's norm: a pass
  // fewer each (a wake-up of the threads, a sweep over memory). The terms
  // and their block order are those of the separate passes: the same bits.
  auto filter_dot = [&](std::vector<Vec3>& filtered, const std::vector<Vec3>& other) {
    return parallel_sum(n, [&](std::size_t i) {
      if (!is_free[i]) filtered[i].setZero();
      return other[i].dot(filtered[i]);
    });
  };
  for (int it = 0; it < max_iterations; ++it) {
    apply_a(s.d.data(), s.q.data());
    const Real dq = filter_dot(s.q, s.d);
    if (!(dq > 0)) break;  // not positive definite along d: keep the best so far
    const Real alpha = delta / dq;
    r_norm2 = parallel_sum(n, [&](std::size_t i) {
      x[i] += alpha * s.d[i];
      s.r[i] -= alpha * s.q[i];
      return s.r[i].dot(s.r[i]);
    });
    result.iterations = it + 1;
    if (r_norm2 <= stop2) break;
    precondition(s.r.data(), s.z.data());
    const Real delta_new = filter_dot(s.z, s.r);
    const Real beta = delta_new / delta;
    delta = delta_new;
    parallel_for(n, [&](std::size_t i) { s.d[i] = s.z[i] + beta * s.d[i]; });
  }
  result.relative_residual =
      std::sqrt(r_norm2 / std::max(b_norm2, std::numeric_limits<Real>::min()));
  return result;
}

}  // namespace rift
