// A script lowered to the IR: its statements in source order over one body
// whose nodes are the script's hooks and the variables of its `for each`
// statements. Lets are computed where they are written; a `set` or an
// `apply` may repeat over the sub-orbits of a dart and be skipped by its
// `where`. Every value is of the type of what it fills (an embedding, a
// parameter of the rule applied), int -> real made explicit.
#pragma once

#include <string>
#include <vector>

#include "ast/decl.hpp"
#include "ir/body.hpp"
#include "lower/checked.hpp"
#include "lower/rule_values.hpp"

namespace rift::lower {

struct ScriptStep {
  enum class Kind { Let, Set, Apply };
  Kind kind = Kind::Let;
  int let = -1;  // Let: index into ScriptPlan::body.lets
  /// Set and Apply: repeated for one dart `each_var` (a node) of each
  /// sub-orbit `each_sub` of orbit `each_outer` of `each_dart`, when `each`.
  bool each = false;
  ir::Place each_dart;
  std::vector<int> each_outer, each_sub;
  int each_var = -1;
  ir::ExprId where = ir::kNoExpr;  // a bool, or kNoExpr
  diag::Location where_loc;
  Write set;  // Set
  // Apply: the rule (or earlier script), its arguments by parameter, its hooks.
  std::string rule;
  struct Arg {
    std::string param;
    ir::ExprId value = ir::kNoExpr;  // of the parameter's type
    diag::Location loc;
  };
  std::vector<Arg> args;
  std::vector<ir::Place> hooks;
};

struct ScriptPlan {
  const ast::Script* script = nullptr;
  ir::Body body;  // nodes: the hooks, then `for each` and fold variables
  std::vector<ScriptStep> steps;
  std::vector<std::string> embeddings;  // every embedding read or written, sorted
};

ScriptPlan lower_script(const ast::Script& script, const resolve::Symbols& symbols,
                        const check::ExprTypes& types);

}  // namespace rift::lower
