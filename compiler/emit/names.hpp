// C++ names for things of the rule language: every identifier mangling of the
// generator lives here, so generated names can never clash with C++ keywords
// or with each other.
#pragma once

#include <string>
#include <string_view>

#include "ast/type.hpp"

namespace rift::emit {

/// The C++ type of a value type.
std::string cpp_type(ast::Type t);
/// `rift::ValueType::kReal` ...
std::string value_type_enum(ast::Type t);

std::string let_name(std::string_view name);       // l_x
std::string dart_name(std::string_view node);      // d_a (left/matched), n_a (right)
std::string embedding_var(std::string_view name);  // e_position
std::string rule_function(std::string_view rule);  // apply_rule
std::string member_name(std::string_view name);    // fields of Params and Args structs

}  // namespace rift::emit
