// What an interaction's `jacobian a.f by b.position = value;` statements may
// say (docs/language.md, "Derivatives"): `a.f` is a force the interaction
// itself stores, `b` a node of its pattern, the state a position or a
// velocity, and each block is given once. The value's type (mat3) is checked
// with the other expressions (check/types.cpp).
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::check {

void check_jacobian_blocks(const ast::Program& program, diag::Diagnostics& diags);

}  // namespace rift::check
