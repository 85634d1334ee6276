// How many reals a tear candidate carries for its rule (TearCandidate::payload,
// rift/sim/criterion.hpp): the values of a criterion's `apply` arguments,
// computed when the criterion holds. riftc includes this header (and nothing
// else of the runtime) to lay out each criterion's payload and to reject a
// criterion whose arguments do not fit. Plain data on purpose.
//
// Each argument takes, in the order written: real, int, bool one real (an int
// is exact below 2^53, a bool is 0 or 1), vec3 three (x, y, z), mat3 nine
// (column by column). Twelve covers two vec3 and six reals, or a mat3 and a
// vec3, and keeps a candidate at 120 bytes: collection sorts and copies them.
#pragma once

#include <cstddef>

namespace rift {

inline constexpr std::size_t kCandidatePayloadReals = 12;

}  // namespace rift
