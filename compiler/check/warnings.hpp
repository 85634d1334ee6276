// Named warnings that need the whole resolved program: unused lets, unused
// parameters and unused functions. (float-equality is raised while typing.)
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"
#include "resolve/symbols.hpp"

namespace rift::check {

void check_unused(const ast::Program& program, const resolve::Symbols& symbols,
                  diag::Diagnostics& diags);

}  // namespace rift::check
