// The built-in functions of the language: generic mathematics only (no
// built-in knows a spring or a finite element), with their signatures.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ast/type.hpp"

namespace rift::check {

struct Signature {
  std::vector<ast::Type> params;
  ast::Type result;
};

/// Every overload of a built-in, or nullptr for an unknown name.
const std::vector<Signature>* builtin(std::string_view name);

/// The overload `args` selects: an exact match first, then one where int
/// arguments are promoted to real. nullptr when none fits.
const Signature* select_overload(const std::vector<Signature>& overloads,
                                 const std::vector<ast::Type>& args);

/// "(vec3, real)".
std::string describe(const std::vector<ast::Type>& types);

}  // namespace rift::check
