// The initialisers of a pack lowered to the IR (one sweep over the cells of
// their embedding's orbit, in the order they are written), and the constant
// expressions of its declarations (parameter defaults, pack parameters,
// embedding defaults), each of the type of what it initialises.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "ast/program.hpp"
#include "ir/body.hpp"
#include "lower/checked.hpp"
#include "lower/rule_values.hpp"

namespace rift::lower {

struct InitialiserPlan {
  std::vector<int> orbit;               // of the embedding written
  ir::Body body;                        // nodes: the init's dart, then fold variables
  Write write;                          // node 0
  std::vector<std::string> embeddings;  // read or written, sorted
};

/// Every init of the program, in source order.
std::vector<InitialiserPlan> lower_initialisers(const ast::Program& program,
                                                const resolve::Symbols& symbols,
                                                const check::ExprTypes& types);

/// The constant expressions of the declarations, one graph for all.
struct Constants {
  ir::Graph graph;
  /// Each constant expression of the program, of the type of what it initialises.
  std::unordered_map<const ast::Expr*, ir::ExprId> of;
};

Constants lower_constants(const ast::Program& program, const resolve::Symbols& symbols,
                          const check::ExprTypes& types);

}  // namespace rift::lower
