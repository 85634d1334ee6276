#include "emit/names.hpp"

#include <algorithm>
#include <set>

#include "ast/camel_case.hpp"

namespace rift::emit {

std::string cpp_type(ast::Type t) {
  switch (t) {
    case ast::Type::Real:
      return "rift::Real";
    case ast::Type::Int:
      return "std::int64_t";
    case ast::Type::Bool:
      return "bool";
    case ast::Type::Vec3:
      return "rift::Vec3";
    case ast::Type::Mat3:
      return "rift::Mat3";
    case ast::Type::Error:
      break;
  }
  return "void";
}

std::string zero_of(ast::Type t) {
  switch (t) {
    case ast::Type::Vec3:
      return "rift::Vec3::Zero()";
    case ast::Type::Mat3:
      return "rift::Mat3::Zero()";
    case ast::Type::Bool:
      return "false";
    case ast::Type::Int:
      return "std::int64_t{0}";
    default:
      return "rift::Real(0)";
  }
}

std::string storage_type(ast::Type t) {
  return t == ast::Type::Bool ? "rift::Bool" : cpp_type(t);
}

std::string camel_name(std::string_view name) {
  return ast::camel_case(name);
}

std::string kernel_class(std::string_view interaction) {
  return camel_name(interaction) + "Kernel";
}
std::string interaction_class(std::string_view interaction) {
  return camel_name(interaction) + "Interaction";
}
std::string component_params_struct(std::string_view name) {
  return camel_name(name) + "Params";
}
std::string criterion_class(std::string_view criterion) {
  return camel_name(criterion) + "Criterion";
}
std::string rule_class(std::string_view rule) {
  return camel_name(rule) + "Rule";
}

std::string value_type_enum(ast::Type t) {
  switch (t) {
    case ast::Type::Real:
      return "rift::ValueType::kReal";
    case ast::Type::Int:
      return "rift::ValueType::kInt";
    case ast::Type::Bool:
      return "rift::ValueType::kBool";
    case ast::Type::Vec3:
      return "rift::ValueType::kVec3";
    case ast::Type::Mat3:
      return "rift::ValueType::kMat3";
    case ast::Type::Error:
      break;
  }
  return "rift::ValueType::kReal";
}

// Rule-language identifiers are [A-Za-z_][A-Za-z0-9_]*; a prefix keeps them
// apart from C++ keywords and from the generator's own locals.
std::string let_name(std::string_view name) {
  return "l_" + std::string(name);
}
std::string dart_name(std::string_view node) {
  return "d_" + std::string(node);
}
std::string embedding_var(std::string_view name) {
  return "e_" + std::string(name);
}
std::string reader_var(std::string_view name) {
  return "r_" + std::string(name);
}
std::string memo_var(std::size_t memo) {
  return "memo" + std::to_string(memo) + "_";
}
std::string memo_values_var(std::size_t memo, std::size_t k) {
  return memo_var(memo) + std::to_string(k) + "_";
}
std::string memo_entry_name(std::size_t memo) {
  return "memo" + std::to_string(memo) + "_entry";
}
std::string rule_function(std::string_view rule) {
  return "apply_" + std::string(rule);
}
std::string member_name(std::string_view name) {
  // Fields are part of the generated API, so they keep the rule's spelling;
  // only C++ keywords get a trailing underscore.
  static const std::set<std::string, std::less<>> kKeywords = {
      "alignas",   "alignof",   "and",       "asm",       "auto",      "bitand",   "bitor",
      "bool",      "break",     "case",      "catch",     "char",      "class",    "compl",
      "concept",   "const",     "consteval", "constexpr", "constinit", "continue", "co_await",
      "co_return", "co_yield",  "decltype",  "default",   "delete",    "do",       "double",
      "else",      "enum",      "explicit",  "export",    "extern",    "false",    "float",
      "for",       "friend",    "goto",      "if",        "inline",    "int",      "long",
      "mutable",   "namespace", "new",       "noexcept",  "not",       "nullptr",  "operator",
      "or",        "private",   "protected", "public",    "register",  "requires", "return",
      "short",     "signed",    "sizeof",    "static",    "struct",    "switch",   "template",
      "this",      "throw",     "true",      "try",       "typedef",   "typeid",   "typename",
      "union",     "unsigned",  "using",     "virtual",   "void",      "volatile", "while",
      "xor"};
  std::string out(name);
  if (kKeywords.count(name)) out += '_';
  return out;
}

std::string orbit_code(const std::vector<int>& dims) {
  std::vector<int> sorted;
  for (int d : dims) {
    if (d >= 0 && d < 8 && std::find(sorted.begin(), sorted.end(), d) == sorted.end())
      sorted.push_back(d);
  }
  std::sort(sorted.begin(), sorted.end());
  std::string out = "rift::Orbit{";
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (k) out += ", ";
    out += std::to_string(sorted[k]);
  }
  return out + "}";
}

}  // namespace rift::emit
