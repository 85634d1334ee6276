// The value types an embedding column can hold, and the policies that decide
// what a merged orbit's value becomes.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

#include "rift/core/types.hpp"

namespace rift {

enum class ValueType : std::uint8_t { kReal, kInt, kBool, kVec3, kMat3 };

/// What a sew that merges two orbits does with their two values.
enum class MergePolicy : std::uint8_t {
  kKeepFirst,  ///< the orbit of the first dart given to sew() keeps its value
  kSum,        ///< a + b (bool: a || b)
  kMean,       ///< (a + b) / 2 (int: rounded toward zero; bool: a || b)
  kRefuse,     ///< the sew is refused unless both values are equal
};

/// A boolean embedding value. A distinct type (rather than bool) so that
/// columns are plain arrays with addressable elements, unlike std::vector<bool>.
struct Bool {
  bool value = false;
  constexpr Bool() = default;
  constexpr Bool(bool v) : value(v) {}               // NOLINT(google-explicit-constructor)
  constexpr operator bool() const { return value; }  // NOLINT(google-explicit-constructor)
  friend constexpr bool operator==(Bool a, Bool b) { return a.value == b.value; }
};

using Value = std::variant<Real, std::int64_t, Bool, Vec3, Mat3>;

std::string_view to_string(ValueType type);
std::string_view to_string(MergePolicy policy);
std::optional<ValueType> parse_value_type(std::string_view name);
std::optional<MergePolicy> parse_merge_policy(std::string_view name);

template <class T>
struct ValueTypeOf;
template <>
struct ValueTypeOf<Real> {
  static constexpr ValueType value = ValueType::kReal;
};
template <>
struct ValueTypeOf<std::int64_t> {
  static constexpr ValueType value = ValueType::kInt;
};
template <>
struct ValueTypeOf<Bool> {
  static constexpr ValueType value = ValueType::kBool;
};
template <>
struct ValueTypeOf<Vec3> {
  static constexpr ValueType value = ValueType::kVec3;
};
template <>
struct ValueTypeOf<Mat3> {
  static constexpr ValueType value = ValueType::kMat3;
};

}  // namespace rift
