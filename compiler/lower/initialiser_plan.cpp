#include "lower/initialiser_plan.hpp"

#include "lower/expr_lower.hpp"

namespace rift::lower {

std::vector<InitialiserPlan> lower_initialisers(const ast::Program& program,
                                                const resolve::Symbols& symbols,
                                                const check::ExprTypes& types) {
  std::vector<InitialiserPlan> out;
  for (const ast::File& file : program.files) {
    if (!file.owner.empty()) continue;  // an imported pack runs its own inits
    for (const ast::Init& init : file.inits) {
      const ast::Embedding* target = symbols.target(init);
      InitialiserPlan plan;
      plan.orbit = target->orbit.dims;
      plan.body.nodes.push_back(init.dart.text);
      ExprLowering lowering(plan.body.graph, plan.body.nodes, nullptr, symbols, types);
      plan.write.node = 0;
      plan.write.embedding = init.embedding.text;
      plan.write.value = lowering.lower_as(*init.value, target->type);
      plan.write.loc = init.value->loc;
      embeddings_read(plan.body.graph, plan.write.value, plan.embeddings);
      add_name(plan.embeddings, init.embedding.text);
      out.push_back(std::move(plan));
    }
  }
  return out;
}

Constants lower_constants(const ast::Program& program, const resolve::Symbols& symbols,
                          const check::ExprTypes& types) {
  Constants out;
  std::vector<std::string> no_nodes;
  ExprLowering lowering(out.graph, no_nodes, nullptr, symbols, types);
  auto add = [&](const ast::ExprPtr& e, ast::Type to) {
    if (e) out.of.emplace(e.get(), lowering.lower_as(*e, to));
  };
  auto add_params = [&](const std::vector<ast::Param>& params) {
    for (const ast::Param& p : params)
      add(p.default_value, p.type);
  };
  for (const ast::File& file : program.files) {
    for (const ast::Embedding& e : file.embeddings)
      add(e.default_value, e.type);
    for (const ast::PackParam& p : file.params)
      add(p.value, p.type);
    for (const ast::Rule& r : file.rules)
      add_params(r.params);
    for (const ast::Script& s : file.scripts)
      add_params(s.params);
    for (const ast::Interaction& i : file.interactions)
      add_params(i.params);
    for (const ast::Criterion& c : file.criteria)
      add_params(c.params);
  }
  return out;
}

}  // namespace rift::lower
