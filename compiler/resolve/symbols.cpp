#include "resolve/symbols.hpp"

#include <optional>
#include <set>

#include "ast/orbit_text.hpp"

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

  /// The pack whose file is being collected: empty for this pack, else the
  /// imported pack that owns it.
  void set_owner(const std::string& owner) { owner_ = owner; }

  template <class Decl>
  void add(std::map<std::string, const Decl*, std::less<>>& map, const Decl& decl,
           const char* what) {
    const ast::Ident& name = decl.name;
    auto first = first_.find(name.text);
    if (first != first_.end() && owners_[name.text] != owner_) {
      // One of the two belongs to an imported pack: report it at this pack's
      // own declaration when there is one, as the local name is the one to change.
      const std::string& other = owners_[name.text];
      const bool first_local = other.empty();
      const diag::Location at = first_local ? first->second : name.loc;
      const diag::Location there = first_local ? name.loc : first->second;
      const std::string& imported = first_local ? owner_ : other;
      diags_
          .error(at, std::string(what) + " '" + name.text + "' clashes with a declaration of " +
                         "imported pack '" + imported +
                         "', whose names are visible here: rename it")
          .notes.push_back({there, "'" + name.text + "' declared by '" +
                                       (first_local ? owner_ : other) + "' here"});
      return;
    }
    if (first != first_.end() && state_.count(name.text)) {
      diags_
          .error(name.loc, std::string(what) + " '" + name.text +
                               "' has the name of a state embedding of the simulator, which rift "
                               "declares in every pack: choose another name")
          .notes.push_back({first->second, "declared by rift here"});
      return;
    }
    if (first != first_.end()) {
      diags_.error(name.loc, std::string(what) + " '" + name.text + "' is already declared")
          .notes.push_back({first->second, "first declared here"});
      return;
    }
    first_.emplace(name.text, name.loc);
    owners_.emplace(name.text, owner_);
    map.emplace(name.text, &decl);
  }

  /// Declarations of the simulator's state, collected first.
  void add_state(std::map<std::string, const ast::Embedding*, std::less<>>& map,
                 const ast::Embedding& decl) {
    add(map, decl, "embedding");
    state_.insert(decl.name.text);
  }

 private:
  diag::Diagnostics& diags_;
  std::map<std::string, diag::Location, std::less<>> first_;
  std::map<std::string, std::string, std::less<>> owners_;  // the pack of each first declaration
  std::string owner_;
  std::set<std::string, std::less<>> state_;
};

/// The components of a literal default (`1.0`, `-1`, `false`,
/// `vec3(0, 0, 0)`), or nothing when the expression is not a literal.
std::optional<std::vector<double>> literal_components(const ast::Expr& e) {
  using Kind = ast::Expr::Kind;
  switch (e.kind) {
    case Kind::IntLit:
      return std::vector<double>{static_cast<double>(e.integer)};
    case Kind::RealLit:
      return std::vector<double>{e.real};
    case Kind::BoolLit:
      return std::vector<double>{e.boolean ? 1.0 : 0.0};
    case Kind::Unary:
      if (e.op == "-" && e.args.size() == 1) {
        auto inner = literal_components(*e.args[0]);
        if (inner) {
          for (double& c : *inner)
            c = -c;
        }
        return inner;
      }
      return std::nullopt;
    case Kind::Call: {
      if (e.name != "vec3") return std::nullopt;
      std::vector<double> out;
      for (const ast::ExprPtr& a : e.args) {
        auto c = a ? literal_components(*a) : std::nullopt;
        if (!c || c->size() != 1) return std::nullopt;
        out.push_back(c->front());
      }
      return out;
    }
    default:
      return std::nullopt;
  }
}

/// A pack may restate a state embedding (older packs declare `position`
/// themselves), but only as rift declares it: the same type and orbit, and
/// no other merge policy or default, which would silently differ from what
/// the simulator does with the column.
void check_restated(const ast::Embedding& restated, const ast::Embedding& state,
                    diag::Diagnostics& diags) {
  if (!state.merge) return;  // never: the state table gives each embedding its policy
  const std::string what = "'" + state.name.text + "' is a state embedding of the simulator (" +
                           std::string(ast::to_string(state.type)) + " on " +
                           ast::orbit_text(state.orbit.dims) + ", merge " + state.merge->text +
                           "), which rift declares in every pack";
  auto fail = [&](const diag::Location& at, const std::string& why) {
    diags.error(at, what + "; " + why + ": remove this declaration")
        .notes.push_back({state.name.loc, "declared by rift here"});
  };
  if (restated.type != state.type) {
    fail(restated.type_loc, "it cannot be " + std::string(ast::to_string(restated.type)));
  } else if (restated.orbit.dims != state.orbit.dims) {
    fail(restated.orbit.loc, "it cannot live on " + ast::orbit_text(restated.orbit.dims));
  } else if (restated.merge && restated.merge->text != state.merge->text) {
    fail(restated.merge->loc, "its merge policy cannot be '" + restated.merge->text + "'");
  } else if (restated.default_value) {
    const auto given = literal_components(*restated.default_value);
    const auto wanted = literal_components(*state.default_value);
    if (!given || given != wanted) {
      fail(restated.default_value->loc, "its default cannot differ from rift's");
    }
  }
}

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
  // The state embeddings first: a pack's own declaration of one is a
  // restatement, checked against rift's.
  std::map<std::string, const ast::Embedding*, std::less<>> state;
  for (const ast::File& file : program.files) {
    if (!file.builtin) continue;
    for (const auto& e : file.embeddings) {
      collector.add_state(symbols.embeddings, e);
      state.emplace(e.name.text, &e);
    }
  }
  for (const ast::File& file : program.files) {
    if (file.builtin) continue;
    collector.set_owner(file.owner);
    for (const auto& e : file.embeddings) {
      if (const ast::Embedding* declared = lookup(state, e.name.text)) {
        check_restated(e, *declared, diags);
        continue;
      }
      collector.add(symbols.embeddings, e, "embedding");
    }
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

int Symbols::uses(const ast::Let& let) const {
  const auto it = let_uses.find(&let);
  return it == let_uses.end() ? 0 : it->second;
}

int Symbols::uses(const ast::Param& param) const {
  const auto it = param_uses.find(&param);
  return it == param_uses.end() ? 0 : it->second;
}

const Binding& Symbols::binding(const ast::Expr& e) const {
  static const Binding kUnresolved;
  const auto it = bindings.find(&e);
  return it == bindings.end() ? kUnresolved : it->second;
}

}  // namespace rift::resolve
