#include "resolve/symbols.hpp"

namespace rift::resolve {

namespace {

template <class Map>
auto lookup(const Map& map, std::string_view name) -> typename Map::mapped_type {
  auto it = map.find(name);
  return it == map.end() ? nullptr : it->second;
}

class Collector {
 public:
  explicit Collector(diag::Diagnostics& diags) : diags_(diags) {}

  template <class Decl>
  void add(std::map<std::string, const Decl*, std::less<>>& map, const Decl& decl,
           const char* what) {
    const ast::Ident& name = decl.name;
    auto first = first_.find(name.text);
    if (first != first_.end()) {
      diags_.error(name.loc, std::string(what) + " '" + name.text + "' is already declared")
          .notes.push_back({first->second, "first declared here"});
      return;
    }
    first_.emplace(name.text, name.loc);
    map.emplace(name.text, &decl);
  }

 private:
  diag::Diagnostics& diags_;
  std::map<std::string, diag::Location, std::less<>> first_;
};

}  // namespace

const ast::Embedding* Symbols::embedding(std::string_view name) const {
  return lookup(embeddings, name);
}
const ast::PackParam* Symbols::param(std::string_view name) const {
  return lookup(params, name);
}
const ast::Rule* Symbols::rule(std::string_view name) const {
  return lookup(rules, name);
}
const ast::Script* Symbols::script(std::string_view name) const {
  return lookup(scripts, name);
}
const ast::Function* Symbols::function(std::string_view name) const {
  return lookup(functions, name);
}
const std::vector<ast::Param>* Symbols::callee_params(std::string_view name) const {
  if (const ast::Rule* r = rule(name)) return &r->params;
  if (const ast::Script* s = script(name)) return &s->params;
  return nullptr;
}

Symbols collect_symbols(const ast::Program& program, diag::Diagnostics& diags) {
  Symbols symbols;
  Collector collector(diags);
  for (const ast::File& file : program.files) {
    for (const auto& e : file.embeddings)
      collector.add(symbols.embeddings, e, "embedding");
    for (const auto& p : file.params)
      collector.add(symbols.params, p, "parameter");
    for (const auto& r : file.rules)
      collector.add(symbols.rules, r, "rule");
    for (const auto& s : file.scripts)
      collector.add(symbols.scripts, s, "script");
    for (const auto& f : file.functions)
      collector.add(symbols.functions, f, "function");
    for (const auto& i : file.interactions)
      collector.add(symbols.interactions, i, "interaction");
    for (const auto& c : file.criteria)
      collector.add(symbols.criteria, c, "criterion");
  }
  return symbols;
}

const ast::Embedding* Symbols::target(const ast::Assign& assign) const {
  const auto it = assign_targets.find(&assign);
  return it == assign_targets.end() ? nullptr : it->second;
}

const ast::Embedding* Symbols::target(const ast::Init& init) const {
  const auto it = init_targets.find(&init);
  return it == init_targets.end() ? nullptr : it->second;
}

const Binding& Symbols::binding(const ast::Expr& e) const {
  static const Binding kUnresolved;
  const auto it = bindings.find(&e);
  return it == bindings.end() ? kUnresolved : it->second;
}

}  // namespace rift::resolve
