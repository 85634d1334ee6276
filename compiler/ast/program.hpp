// Every file of one riftc run, in the order they were read (includes first
// seen, first kept). Passes walk all files as one pack.
#pragma once

#include <vector>

#include "ast/decl.hpp"

namespace rift::ast {

struct Program {
  std::vector<File> files;
  int dimension = 2;  // of the first file; included files must agree
};

}  // namespace rift::ast
