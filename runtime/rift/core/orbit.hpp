// An orbit type <i,j,...>: a set of alpha dimensions, stored as a bit mask.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "rift/core/types.hpp"

namespace rift {

class Orbit {
 public:
  constexpr Orbit() = default;
  constexpr Orbit(std::initializer_list<int> dims) {
    for (int i : dims)
      mask_ = static_cast<std::uint8_t>(mask_ | (1u << i));
  }
  static constexpr Orbit from_mask(std::uint8_t mask) {
    Orbit o;
    o.mask_ = mask;
    return o;
  }
  /// <0,...,n>: the connected component.
  static constexpr Orbit all(int dimension) {
    return from_mask(static_cast<std::uint8_t>((1u << (dimension + 1)) - 1));
  }
  /// The orbit of a k-cell in a map of the given dimension: every alpha but alpha_k.
  static constexpr Orbit cell(int k, int dimension) { return all(dimension).without(k); }
  /// The orbit along which sew/unsew in dimension i pairs darts: <0..i-2, i+2..n>.
  static constexpr Orbit sewing(int i, int dimension) {
    Orbit o = all(dimension).without(i);
    if (i > 0) o = o.without(i - 1);
    if (i < dimension) o = o.without(i + 1);
    return o;
  }

  constexpr bool contains(int i) const { return (mask_ >> i) & 1u; }
  constexpr Orbit with(int i) const {
    return from_mask(static_cast<std::uint8_t>(mask_ | (1u << i)));
  }
  constexpr Orbit without(int i) const {
    return from_mask(static_cast<std::uint8_t>(mask_ & ~(1u << i)));
  }
  /// The number of dimensions. Walks ask for it on every call, and without
  /// -mpopcnt (the build targets baseline x86-64) `__builtin_popcount` is a
  /// call into libgcc; an 8-bit mask needs only three shift-and-add steps.
  constexpr int size() const {
    const unsigned pairs = mask_ - ((mask_ >> 1) & 0x55u);
    const unsigned nibbles = (pairs & 0x33u) + ((pairs >> 2) & 0x33u);
    return static_cast<int>((nibbles + (nibbles >> 4)) & 0x0Fu);
  }
  constexpr bool empty() const { return mask_ == 0; }
  constexpr std::uint8_t mask() const { return mask_; }
  /// Smallest dimension of a non-empty orbit.
  constexpr int first() const { return __builtin_ctz(mask_ | 0x80u); }
  /// Second smallest dimension of an orbit with at least two dimensions.
  constexpr int second() const { return Orbit::from_mask(mask_ & (mask_ - 1u)).first(); }
  /// True when every dimension of the orbit lies in [0, dimension].
  constexpr bool fits(int dimension) const { return (mask_ >> (dimension + 1)) == 0; }

  friend constexpr bool operator==(Orbit a, Orbit b) { return a.mask_ == b.mask_; }

  /// "<1,2>", "<>" for the single dart.
  std::string str() const;
  /// Parses "<1,2>" / "<>" (spaces allowed); nullopt when malformed.
  static std::optional<Orbit> parse(std::string_view text);

 private:
  std::uint8_t mask_ = 0;
};

}  // namespace rift
