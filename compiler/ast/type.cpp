#include "ast/type.hpp"

namespace rift::ast {

std::string_view to_string(Type t) {
  switch (t) {
    case Type::Real:
      return "real";
    case Type::Int:
      return "int";
    case Type::Bool:
      return "bool";
    case Type::Vec3:
      return "vec3";
    case Type::Mat3:
      return "mat3";
    case Type::Error:
      break;
  }
  return "<error>";
}

std::optional<Type> parse_type(std::string_view name) {
  if (name == "real") return Type::Real;
  if (name == "int") return Type::Int;
  if (name == "bool") return Type::Bool;
  if (name == "vec3") return Type::Vec3;
  if (name == "mat3") return Type::Mat3;
  return std::nullopt;
}

std::size_t payload_reals(Type t) {
  switch (t) {
    case Type::Vec3:
      return 3;
    case Type::Mat3:
      return 9;
    default:
      return 1;
  }
}

}  // namespace rift::ast
