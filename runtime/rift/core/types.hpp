// Scalar and small fixed-size types shared by the whole runtime and by generated code.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstdint>
#include <limits>

namespace rift {

using Real = double;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

/// A dart is a 32-bit index into the flat arrays of a GMap.
using Dart = std::uint32_t;
inline constexpr Dart kNoDart = std::numeric_limits<Dart>::max();

/// Index of a value in an embedding column (one slot per orbit).
using Slot = std::uint32_t;
inline constexpr Slot kNoSlot = std::numeric_limits<Slot>::max();

/// Largest G-map dimension the runtime supports (alpha_0 .. alpha_3).
inline constexpr int kMaxDimension = 3;

}  // namespace rift
