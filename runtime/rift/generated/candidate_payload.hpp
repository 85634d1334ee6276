// The values of a criterion's `apply` arguments in a TearCandidate's payload:
// collect() puts each where riftc laid it out (CriterionPlan::payload),
// apply() reads it back as the rule's argument. The layout is the one of
// rift/core/candidate_payload.hpp: real, int and bool one real, vec3 three,
// mat3 nine (column by column); reading back gives the value written, bit for
// bit (an int up to 2^53).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "rift/sim/criterion.hpp"

namespace rift::generated {

/// How many reals a value of type T takes in a payload.
template <class T>
inline constexpr std::size_t kPayloadReals = 1;
template <>
inline constexpr std::size_t kPayloadReals<Vec3> = 3;
template <>
inline constexpr std::size_t kPayloadReals<Mat3> = 9;

/// Writes `value` at `offset` (in reals) and extends the candidate's count.
template <class T>
void put_payload(TearCandidate& c, std::size_t offset, const T& value) {
  Real* at = c.payload.data() + offset;
  if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
    std::copy(value.data(), value.data() + kPayloadReals<T>, at);
  } else if constexpr (std::is_same_v<T, bool>) {
    *at = value ? Real{1} : Real{0};
  } else {
    *at = static_cast<Real>(value);
  }
  c.payload_reals =
      std::max(c.payload_reals, static_cast<std::uint32_t>(offset + kPayloadReals<T>));
}

/// The value of type T that put_payload wrote at `offset`.
template <class T>
T payload_as(const TearCandidate& c, std::size_t offset) {
  const Real* at = c.payload.data() + offset;
  if constexpr (std::is_same_v<T, Vec3> || std::is_same_v<T, Mat3>) {
    T value;
    std::copy(at, at + kPayloadReals<T>, value.data());
    return value;
  } else if constexpr (std::is_same_v<T, bool>) {
    return *at != Real{0};
  } else {
    return static_cast<T>(*at);
  }
}

}  // namespace rift::generated
