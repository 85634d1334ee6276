// Named warnings that need the whole resolved program: unused lets and unused
// rule parameters. (float-equality is raised while typing.)
#pragma once

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::check {

void check_unused(const ast::Program& program, diag::Diagnostics& diags);

}  // namespace rift::check
