// Every file of one riftc run, in the order they were read (includes first
// seen, first kept). Passes walk all files as one pack.
#pragma once

#include <string>
#include <vector>

#include "ast/decl.hpp"

namespace rift::ast {

struct Program {
  std::vector<File> files;
  int dimension = 2;  // of the first file; included files must agree
  /// The packs this pack imports (directly), in the order of their `import`:
  /// their generated headers are included, their inits run first, and
  /// registering this pack registers them.
  std::vector<std::string> imports;
};

}  // namespace rift::ast
