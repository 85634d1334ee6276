// Lanes: one scalar computation carried out on kWidth independent inputs at
// once, for the force passes riftc generates (compiler/emit/kernel_emit.cpp,
// "evaluate_lanes"): kWidth consecutive springs share one vsqrtpd, one
// vdivpd and one of each multiply and add.
//
// Each lane does exactly the operations, in exactly the order, that the
// scalar code does on its own match, so a force computed in a lane is the
// force computed alone, to the bit:
//  - Eigen sums a fixed-size Vec3 as (x + y) + z (dot, squaredNorm, norm);
//    cross, a product or quotient with a scalar, sums and differences are per
//    coordinate;
//  - normalized() divides by the square root where the squared norm is > 0;
//  - std::min, std::max and std::clamp pick as their definitions do (ties,
//    NaNs);
//  - the build never fuses a multiply and an add (-ffp-contract=off,
//    cmake/RiftArch.cmake), in scalar or vector code.
// A lane whose `when` fails computes on regardless (IEEE arithmetic does not
// trap here) and its results are dropped. tests/sim/lanes_test.cpp checks
// every generated kernel that has lanes against its scalar pass.
//
// The width follows the vector registers the build targets: 4 doubles with
// AVX (x86-64-v3), else 2 (SSE2, every x86-64). A vector wider than the target
// has would change how these inline functions pass values (GCC's -Wpsabi)
// and be split in two anyway.
//
// Generated code mixes lane values with uniform ones (a parameter, a
// literal, a vec3 the same for every lane): as_lanes() makes either a lane
// value, and the operators take a double or a rift::Vec3 on either side.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "rift/core/types.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace rift::lanes {

#if defined(__AVX__)
inline constexpr int kWidth = 4;
#else
inline constexpr int kWidth = 2;
#endif

/// kWidth reals, one per lane. GCC's vector arithmetic, and arithmetic with a
/// double, which it broadcasts.
using Real = double __attribute__((vector_size(kWidth * sizeof(double))));
/// A truth value per lane, all bits set where true: the type comparisons of
/// Real give (GCC's vector of long, clang's of long long).
using Mask = decltype(Real{} < Real{});
/// The slot each lane reads.
using Slots = std::array<Slot, kWidth>;

/// Three coordinates of kWidth vectors, one vector per lane.
/// Like Eigen's, a default-constructed one is uninitialised: a kernel's
/// ResultLanes is filled by evaluate_lanes, and zeroing it first was a
/// `rep stos` of 384 bytes per four matches in a storing pass. `Vec3{}` (a
/// literal zero of a lanes body) is zero.
struct Vec3 {
  Real x, y, z;

  Vec3() = default;
  Vec3(Real x_, Real y_, Real z_) : x(x_), y(y_), z(z_) {}
  /// The same vector in every lane (a parameter, a constant).
  Vec3(const rift::Vec3& v) : x(Real{} + v.x()), y(Real{} + v.y()), z(Real{} + v.z()) {}

  /// Coordinate i (0, 1, 2) of every lane, as Eigen's v(i).
  Real operator()(int i) const { return i == 0 ? x : i == 1 ? y : z; }
  /// Lane k as one rift::Vec3.
  rift::Vec3 lane(int k) const { return {x[k], y[k], z[k]}; }
};

// ---- a lane value from a lane or a uniform value

inline Real as_lanes(Real a) {
  return a;
}
inline Real as_lanes(double a) {
  return Real{} + a;
}
inline Mask as_lanes(Mask a) {
  return a;
}
inline Mask as_lanes(bool a) {
  return Mask{} - (a ? 1 : 0);
}
inline Vec3 as_lanes(const Vec3& a) {
  return a;
}
inline Vec3 as_lanes(const rift::Vec3& a) {
  return Vec3(a);
}

inline Mask all_true() {
  return Mask{} - 1;
}

// ---- per-lane functions

/// Correctly rounded in every lane, as std::sqrt. The instruction itself:
/// GCC keeps a loop of std::sqrt scalar, since it may set errno.
inline Real sqrt(Real a) {
#if defined(__AVX__)
  return _mm256_sqrt_pd(a);
#elif defined(__SSE2__)
  return _mm_sqrt_pd(a);
#else
  Real r;
  for (int k = 0; k < kWidth; ++k)
    r[k] = std::sqrt(a[k]);
  return r;
#endif
}

inline Real abs(Real a) {
  Real r;
  for (int k = 0; k < kWidth; ++k)
    r[k] = std::fabs(a[k]);
  return r;
}

/// Per lane m ? a : b.
inline Real select(Mask m, Real a, Real b) {
  return m ? a : b;
}
inline Mask select(Mask m, Mask a, Mask b) {
  return m ? a : b;
}
inline Vec3 select(Mask m, const Vec3& a, const Vec3& b) {
  return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}

/// std::min<T>(a, b), std::max<T>(a, b), std::clamp(v, lo, hi) per lane:
/// the same choice on ties and NaNs.
inline Real min(Real a, Real b) {
  return select(b < a, b, a);
}
inline Real max(Real a, Real b) {
  return select(a < b, b, a);
}
inline Real clamp(Real v, Real lo, Real hi) {
  return select(v < lo, lo, select(hi < v, hi, v));
}

inline Real dot(const Vec3& a, const Vec3& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}
inline Real squared_norm(const Vec3& a) {
  return (a.x * a.x + a.y * a.y) + a.z * a.z;
}
inline Real norm(const Vec3& a) {
  return lanes::sqrt(squared_norm(a));
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Eigen's normalized(): v / sqrt(|v|²) where |v|² > 0, else v unchanged.
inline Vec3 normalized(const Vec3& a) {
  const Real n = squared_norm(a);
  const Real s = lanes::sqrt(n);
  return select(n > 0.0, Vec3{a.x / s, a.y / s, a.z / s}, a);
}

// ---- Vec3 arithmetic (a rift::Vec3 operand converts: the same in every lane)

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator-(const Vec3& a) {
  return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(Real s, const Vec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline Vec3 operator*(const Vec3& a, Real s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline Vec3 operator*(double s, const Vec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline Vec3 operator*(const Vec3& a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline Vec3 operator/(const Vec3& a, Real s) {
  return {a.x / s, a.y / s, a.z / s};
}
inline Vec3 operator/(const Vec3& a, double s) {
  return {a.x / s, a.y / s, a.z / s};
}

// ---- reads

/// The slots `field` of kWidth consecutive matches.
template <class Match>
inline Slots slots(const Match* m, Slot Match::*field) {
  Slots s;
  for (int k = 0; k < kWidth; ++k)
    s[static_cast<std::size_t>(k)] = m[k].*field;
  return s;
}

namespace detail {
// Built as one vector literal per coordinate rather than lane by lane: GCC
// then loads the kWidth values straight into a register instead of merging
// each one into the register's previous contents.
template <std::size_t... K>
inline Real gather(const double* column, const Slots& s, std::index_sequence<K...>) {
  return Real{column[s[K]]...};
}
template <std::size_t... K>
inline Vec3 gather(const rift::Vec3* column, const Slots& s, std::index_sequence<K...>) {
  return {Real{column[s[K]].x()...}, Real{column[s[K]].y()...}, Real{column[s[K]].z()...}};
}
template <std::size_t... K>
inline Real load(const double* values, std::index_sequence<K...>) {
  return Real{values[K]...};
}
}  // namespace detail

/// The values of a column at each lane's slot.
inline Real gather(const double* column, const Slots& s) {
  return detail::gather(column, s, std::make_index_sequence<kWidth>());
}
inline Vec3 gather(const rift::Vec3* column, const Slots& s) {
  return detail::gather(column, s, std::make_index_sequence<kWidth>());
}

/// kWidth consecutive values of an array (a group's counts).
inline Real load(const double* values) {
  return detail::load(values, std::make_index_sequence<kWidth>());
}

}  // namespace rift::lanes
