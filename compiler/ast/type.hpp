// The value types of the rule language.
#pragma once

#include <optional>
#include <string_view>

namespace rift::ast {

enum class Type { Real, Int, Bool, Vec3, Mat3, Error };

std::string_view to_string(Type t);
std::optional<Type> parse_type(std::string_view name);

}  // namespace rift::ast
