// The value types of the rule language.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace rift::ast {

enum class Type { Real, Int, Bool, Vec3, Mat3, Error };

std::string_view to_string(Type t);
std::optional<Type> parse_type(std::string_view name);
/// How many reals a value of the type takes in a tear candidate's payload
/// (rift/core/candidate_payload.hpp): 1 for real, int and bool, 3 for vec3, 9 for mat3.
std::size_t payload_reals(Type t);

}  // namespace rift::ast
