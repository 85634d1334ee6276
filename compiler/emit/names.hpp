// C++ names for things of the rule language: every identifier mangling of the
// generator lives here, so generated names can never clash with C++ keywords
// or with each other.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "ast/type.hpp"

namespace rift::emit {

/// The C++ type of a value type.
std::string cpp_type(ast::Type t);
/// The C++ type an embedding column of that type holds (bool: rift::Bool).
std::string storage_type(ast::Type t);
/// A C++ expression of the zero value of a type (false for bool).
std::string zero_of(ast::Type t);
/// `rift::ValueType::kReal` ...
std::string value_type_enum(ast::Type t);
/// `rift::Orbit{1, 2}` for a list of dimensions.
std::string orbit_code(const std::vector<int>& dims);

std::string let_name(std::string_view name);       // l_x
std::string dart_name(std::string_view node);      // d_a (left/matched), n_a (right)
std::string embedding_var(std::string_view name);  // e_position
std::string reader_var(std::string_view name);     // r_position, its EmbeddingReader
std::string rule_function(std::string_view rule);  // apply_rule
/// An orbit memo of a criterion (ir::OrbitMemo): the member numbering its
/// orbits, the member holding its value k, the local of a fold's entry.
std::string memo_var(std::size_t memo);                        // memo0_
std::string memo_values_var(std::size_t memo, std::size_t k);  // memo0_1_
std::string memo_entry_name(std::size_t memo);                 // memo0_entry
std::string member_name(std::string_view name);                // fields of Params and Args structs
/// A C++ class name from a rule-language name: "global_edge" -> "GlobalEdge".
std::string camel_name(std::string_view name);
std::string kernel_class(std::string_view interaction);       // StretchKernel
std::string interaction_class(std::string_view interaction);  // StretchInteraction
std::string component_params_struct(std::string_view name);   // StretchParams
std::string criterion_class(std::string_view criterion);      // GlobalEdgeCriterion
std::string rule_class(std::string_view rule);                // SeparateFacesRule

}  // namespace rift::emit
