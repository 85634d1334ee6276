// An interaction lowered for emission: its force kernel (the walk, the slots
// a match caches, lower/kernel_plan.hpp) and its body in the IR, once: the
// lets and whens in source order, the forces and the energy, all reading
// through the kernel's slots. The generated kernel renders that one body for
// the force pass (forces, stored forces) and for the energy.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "ast/decl.hpp"
#include "ir/body.hpp"
#include "lower/checked.hpp"
#include "lower/kernel_plan.hpp"

namespace rift::lower {

/// `init embedding(node) = value`, once per match on the initial mesh.
struct InitPlan {
  int node = 0;  // index into Body::nodes
  std::string embedding;
  ir::Type type = ir::Type::Real;  // the embedding's (the value is converted)
  ir::ExprId value = ir::kNoExpr;  // reads through the map, not through slots
  diag::Location loc;
};

struct InteractionPlan {
  const ast::Interaction* interaction = nullptr;
  KernelPlan kernel;
  ir::Body body;  // the force loop; inits share its graph
  std::vector<InitPlan> inits;
  /// Every embedding the kernel binds: slots' embeddings, force stores,
  /// reads of the body other than the stage arrays, inits' reads and targets.
  std::set<std::string> embeddings;
};

InteractionPlan plan_interaction(const check::CheckedInteraction& inter,
                                 const resolve::Symbols& symbols, const check::ExprTypes& types);

}  // namespace rift::lower
