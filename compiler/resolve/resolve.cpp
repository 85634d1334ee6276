#include "resolve/resolve.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace rift::resolve {

namespace {

using ast::Expr;

/// What an expression may see: which lets (in order), parameters, and which
/// node names it may read — and names that exist but may not be read here,
/// so the message can say why.
struct Scope {
  const std::vector<ast::Let>* lets = nullptr;
  std::size_t visible_lets = 0;
  const std::vector<ast::Param>* params = nullptr;
  std::set<std::string> nodes;
  std::set<std::string> hidden_nodes;
  std::string hidden_reason;
  bool constant = false;  // embedding defaults and pack parameters: no names at all
  const std::vector<ast::Let>* match_lets = nullptr;  // lets that exist but may not be read
  std::string match_lets_reason;
  const ast::Function* function = nullptr;  // the body of this `def`: no darts, no embeddings
  /// The lets of the enclosing folds' bodies, innermost last, each with how
  /// many of them are visible: they are seen before the lets of the body.
  std::vector<std::pair<const std::vector<ast::Let>*, std::size_t>> fold_lets;
};

/// Calls between functions, for the recursion check: caller -> (callee, call site).
using FunctionCalls =
    std::map<const ast::Function*, std::vector<std::pair<const ast::Function*, diag::Location>>>;

class Resolver {
 public:
  Resolver(Symbols& symbols, diag::Diagnostics& diags) : symbols_(symbols), diags_(diags) {}

  void expr(const Expr& e, const Scope& scope) {
    switch (e.kind) {
      case Expr::Kind::Name:
        name(e, scope);
        break;
      case Expr::Kind::Call:
        call(e, scope);
        break;
      case Expr::Kind::Read:
      case Expr::Kind::Collect:
      case Expr::Kind::Fold:
        if (scope.function) {
          diags_.error(e.loc, "function '" + scope.function->name.text +
                                  "' cannot read the map (embeddings, darts); pass the values "
                                  "it needs as parameters");
          return;
        }
        if (e.kind == Expr::Kind::Fold) break;
        if (scope.constant) {
          diags_.error(e.loc, "a constant expression cannot read embeddings");
          return;
        }
        node(e.node, e.node_loc, scope);
        symbols_.bindings[&e].embedding = embedding(e.name, e.loc);
        break;
      default:
        break;
    }
    if (e.kind == Expr::Kind::Fold) {
      if (scope.constant) {
        diags_.error(e.loc, "a constant expression cannot traverse the map");
        return;
      }
      node(e.node, e.node_loc, scope);
      // Each dart is one C++ local of the function the fold is rendered in.
      if (scope.nodes.count(e.var)) {
        diags_.error(e.var_loc,
                     "'" + e.var + "' is already a node here; give the fold's dart another name");
      }
      Scope inner = scope;
      inner.nodes.insert(e.var);
      inner.hidden_nodes.erase(e.var);
      inner.fold_lets.emplace_back(&e.lets, 0);
      for (std::size_t k = 0; k < e.lets.size(); ++k) {
        inner.fold_lets.back().second = k;
        fold_let(e.lets[k], inner);
        expr(*e.lets[k].value, inner);
      }
      inner.fold_lets.back().second = e.lets.size();
      for (const auto& a : e.args)
        expr(*a, inner);
      for (const ast::Let& l : e.lets) {
        if (symbols_.uses(l) == 0)
          diags_.warning("unused-variable", l.name.loc, "'" + l.name.text + "' is never used");
      }
      return;
    }
    for (const auto& a : e.args)
      expr(*a, scope);
  }

  const FunctionCalls& function_calls() const { return function_calls_; }

  const ast::Embedding* embedding(const std::string& name, const diag::Location& loc) {
    const ast::Embedding* emb = symbols_.embedding(name);
    if (!emb) diags_.error(loc, "unknown embedding '" + name + "'");
    return emb;
  }

  /// Binds the embedding an assignment or an init writes (Symbols::target).
  void bind_target(const ast::Assign& a) {
    symbols_.assign_targets[&a] = embedding(a.embedding.text, a.embedding.loc);
  }
  void bind_target(const ast::Init& init) {
    symbols_.init_targets[&init] = embedding(init.embedding.text, init.embedding.loc);
  }

  /// Checks that `name` is a node readable in `scope`.
  bool node(const std::string& name, const diag::Location& loc, const Scope& scope) {
    if (scope.nodes.count(name)) return true;
    if (scope.hidden_nodes.count(name)) {
      diags_.error(loc, "node '" + name + "' " + scope.hidden_reason);
    } else {
      diags_.error(loc, "unknown node '" + name + "'");
    }
    return false;
  }

  diag::Diagnostics& diags() { return diags_; }
  /// A name read a let or a parameter, or a duplicate was reported (which
  /// must not be reported again as unused): Symbols::uses.
  void count_use(const ast::Let& let) { ++symbols_.let_uses[&let]; }
  void count_use(const ast::Param& param) { ++symbols_.param_uses[&param]; }

  /// Each `when` of a body sees the lets written before it, and no later one.
  void whens(const std::vector<ast::Let>& lets, const std::vector<ast::ExprPtr>& whens,
             const std::vector<ast::BodyStmt>& body, Scope scope) {
    scope.lets = &lets;
    std::size_t lets_before = 0;
    for (const ast::BodyStmt& st : body) {
      if (st.kind == ast::BodyStmt::Kind::Let) {
        ++lets_before;
        continue;
      }
      scope.visible_lets = lets_before;
      expr(*whens[st.index], scope);
    }
  }

  void lets(const std::vector<ast::Let>& lets, Scope scope) {
    scope.lets = &lets;
    for (std::size_t k = 0; k < lets.size(); ++k) {
      scope.visible_lets = k;
      expr(*lets[k].value, scope);
    }
  }

 private:
  /// A call of a `def` is bound to it (a built-in's name binds nothing:
  /// check/ knows the built-ins and reports unknown functions).
  void call(const Expr& e, const Scope& scope) {
    const ast::Function* f = symbols_.function(e.name);
    if (!f) return;
    if (scope.constant) {
      diags_.error(e.op_loc, "a constant expression cannot call function '" + e.name + "'");
      return;
    }
    symbols_.bindings[&e].function = f;
    ++symbols_.calls[f];
    if (scope.function) function_calls_[scope.function].emplace_back(f, e.op_loc);
  }

  /// A let of a fold's body may not take the name of a let it could read
  /// (each let is one C++ local of the function the fold is rendered in).
  void fold_let(const ast::Let& let, const Scope& scope) {
    const ast::Let* taken = visible_let(let.name.text, scope);
    if (!taken) return;
    diags_
        .error(let.name.loc, "'" + let.name.text + "' is already a let here; give it another name")
        .notes.push_back({taken->name.loc, "defined here"});
  }

  /// The let a name written in `scope` refers to, or nullptr.
  static const ast::Let* visible_let(const std::string& name, const Scope& scope) {
    for (auto f = scope.fold_lets.rbegin(); f != scope.fold_lets.rend(); ++f) {
      for (std::size_t k = f->second; k-- > 0;) {
        if ((*f->first)[k].name.text == name) return &(*f->first)[k];
      }
    }
    if (scope.lets) {
      // The latest visible let of that name wins.
      for (std::size_t k = scope.visible_lets; k-- > 0;) {
        if ((*scope.lets)[k].name.text == name) return &(*scope.lets)[k];
      }
    }
    return nullptr;
  }

  /// Binds a bare name (Symbols::binding) or reports why it cannot be read.
  void name(const Expr& e, const Scope& scope) {
    for (auto f = scope.fold_lets.rbegin(); f != scope.fold_lets.rend(); ++f) {
      for (std::size_t k = f->second; k-- > 0;) {
        const ast::Let& let = (*f->first)[k];
        if (let.name.text == e.name) {
          symbols_.bindings[&e].let = &let;
          count_use(let);
          return;
        }
      }
    }
    if (scope.lets) {
      // The latest visible let of that name wins.
      for (std::size_t k = scope.visible_lets; k-- > 0;) {
        const ast::Let& let = (*scope.lets)[k];
        if (let.name.text == e.name) {
          symbols_.bindings[&e].let = &let;
          symbols_.bindings[&e].function = scope.function;
          count_use(let);
          return;
        }
      }
    }
    if (scope.params) {
      for (const ast::Param& p : *scope.params) {
        if (p.name.text == e.name) {
          symbols_.bindings[&e].param = &p;
          symbols_.bindings[&e].function = scope.function;
          count_use(p);
          return;
        }
      }
    }
    if (scope.constant) {
      diags_.error(e.loc, "'" + e.name + "' is not a constant; default values must be constant");
      return;
    }
    if (const ast::PackParam* p = symbols_.param(e.name)) {
      symbols_.bindings[&e].pack_param = p;
      return;
    }
    if (scope.nodes.count(e.name) || scope.hidden_nodes.count(e.name)) {
      diags_.error(e.loc, "node '" + e.name +
                              "' is not a value; read one of its embeddings, as in '" + e.name +
                              ".position'");
      return;
    }
    if (scope.lets) {
      for (std::size_t k = scope.visible_lets; k < scope.lets->size(); ++k) {
        if ((*scope.lets)[k].name.text == e.name) {
          diags_.error(e.loc, "'" + e.name + "' is used before its 'let'")
              .notes.push_back({(*scope.lets)[k].name.loc, "defined here"});
          return;
        }
      }
    }
    if (scope.match_lets) {
      for (const ast::Let& let : *scope.match_lets) {
        if (let.name.text != e.name) continue;
        count_use(let);  // reported here; no second report as unused
        diags_.error(e.loc, "'" + e.name + "' " + scope.match_lets_reason)
            .notes.push_back({let.name.loc, "defined here"});
        return;
      }
    }
    diags_.error(e.loc, "unknown name '" + e.name + "'");
  }

  Symbols& symbols_;
  diag::Diagnostics& diags_;
  FunctionCalls function_calls_;
};

std::set<std::string> node_names(const ast::Pattern& p) {
  std::set<std::string> names;
  for (const auto& n : p.nodes)
    names.insert(n.name.text);
  return names;
}

void resolve_rule(const ast::Rule& rule, Resolver& r) {
  Scope before;  // expressions evaluated on the match, before the rewrite
  before.params = &rule.params;
  before.nodes = node_names(rule.left);
  for (const auto& n : rule.right.nodes) {
    if (!before.nodes.count(n.name.text)) before.hidden_nodes.insert(n.name.text);
  }
  before.hidden_reason = "is created by the rule and has no value before the rewrite";
  r.lets(rule.lets, before);
  r.whens(rule.lets, rule.whens, rule.body, before);
  before.lets = &rule.lets;
  before.visible_lets = rule.lets.size();
  const std::set<std::string> right = node_names(rule.right);
  for (const auto& a : rule.right.assigns) {
    r.bind_target(a);
    r.expr(*a.value, before);
  }
  Scope after;  // updates read the rewritten map; lets describe the match, so they are not visible
  after.params = &rule.params;
  after.match_lets = &rule.lets;
  after.match_lets_reason =
      "is a value of the match; an update runs after the rewrite and cannot read it";
  after.nodes = right;
  for (const auto& n : rule.left.nodes) {
    if (!right.count(n.name.text)) after.hidden_nodes.insert(n.name.text);
  }
  after.hidden_reason = "is deleted by the rule; an update reads the map after the rewrite";
  for (const auto& u : rule.updates) {
    r.bind_target(u);
    if (!right.count(u.node.text)) {
      r.node(u.node.text, u.node.loc, after);
    }
    r.expr(*u.value, after);
  }
}

/// Defaults of scene-given parameters are constants; a name is declared once.
void component_params(const std::vector<ast::Param>& params, Resolver& r, const Scope& constant) {
  for (std::size_t k = 0; k < params.size(); ++k) {
    if (params[k].default_value) r.expr(*params[k].default_value, constant);
    for (std::size_t j = 0; j < k; ++j) {
      if (params[j].name.text != params[k].name.text) continue;
      r.count_use(params[k]);  // reported here; no second report as unused
      r.diags()
          .error(params[k].name.loc, "parameter '" + params[k].name.text + "' is declared twice")
          .notes.push_back({params[j].name.loc, "first declared here"});
      break;
    }
  }
}

/// A criterion's pattern nodes (`node b = a@2;`): each path starts at the
/// criterion's dart or an earlier node and crosses at least one link; a node
/// takes a name no other node, parameter or let of the criterion has. Adds
/// the nodes to `s`.
void criterion_nodes(const ast::Criterion& crit, Resolver& r, Scope& s) {
  for (std::size_t k = 0; k < crit.nodes.size(); ++k) {
    const ast::CriterionNode& n = crit.nodes[k];
    Scope path = s;
    for (std::size_t j = k; j < crit.nodes.size(); ++j) {
      if (!path.nodes.count(crit.nodes[j].name.text))
        path.hidden_nodes.insert(crit.nodes[j].name.text);
    }
    path.hidden_reason =
        "is not declared yet; a node's path starts at the criterion's dart or an earlier node";
    r.node(n.from.text, n.from.loc, path);
    if (n.hops.empty()) {
      r.diags().error(n.path_loc, "node '" + n.name.text + "' is '" + n.from.text +
                                      "' itself; its path crosses at least one link, as in '" +
                                      n.from.text + "@0'");
    }
    if (n.name.text == crit.dart.text) {
      r.diags()
          .error(n.name.loc, "node '" + n.name.text + "' is declared twice")
          .notes.push_back({crit.dart.loc, "the criterion's dart"});
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (crit.nodes[j].name.text != n.name.text) continue;
      r.diags()
          .error(n.name.loc, "node '" + n.name.text + "' is declared twice")
          .notes.push_back({crit.nodes[j].name.loc, "first declared here"});
      break;
    }
    for (const ast::Param& p : crit.params) {
      if (p.name.text != n.name.text) continue;
      r.diags()
          .error(n.name.loc,
                 "node '" + n.name.text + "' has the name of a parameter of the criterion")
          .notes.push_back({p.name.loc, "parameter declared here"});
    }
    for (const ast::Let& l : crit.lets) {
      if (l.name.text != n.name.text) continue;
      r.diags()
          .error(l.name.loc, "let '" + l.name.text + "' has the name of a node of the criterion")
          .notes.push_back({n.name.loc, "node declared here"});
    }
    s.nodes.insert(n.name.text);
  }
}

/// Scripts: statements see the hooks, the parameters and the lets written
/// before them; `for each` binds its dart variable for the statement only.
/// Script calls, for the recursion check: caller -> (callee, call site).
using CallGraph = std::map<std::string, std::vector<std::pair<std::string, diag::Location>>>;

void resolve_script(const ast::Script& script, const Symbols& symbols, Resolver& r,
                    CallGraph& calls) {
  Scope s;
  s.params = &script.params;
  s.lets = &script.lets;
  for (const auto& h : script.hooks)
    s.nodes.insert(h.text);
  auto& mine = calls[script.name.text];
  for (const ast::ScriptStmt& st : script.stmts) {
    if (st.kind == ast::ScriptStmt::Kind::Let) {
      s.visible_lets = st.let;
      r.expr(*script.lets[st.let].value, s);
      s.visible_lets = st.let + 1;
      continue;
    }
    Scope inner = s;
    if (st.each.present) {
      r.node(st.each.dart->node, st.each.dart->node_loc, s);
      inner.nodes.insert(st.each.var.text);
    }
    if (st.where) r.expr(*st.where, inner);
    if (st.kind == ast::ScriptStmt::Kind::Set) {
      r.bind_target(st.set);
      r.node(st.set.node.text, st.set.node.loc, inner);
      r.expr(*st.set.value, inner);
      continue;
    }
    for (const auto& h : st.hooks)
      r.node(h->node, h->node_loc, inner);
    for (const auto& a : st.args)
      r.expr(*a.value, inner);
    if (symbols.rule(st.rule.text)) continue;
    if (symbols.script(st.rule.text)) {
      mine.emplace_back(st.rule.text, st.rule.loc);
      continue;
    }
    r.diags().error(st.rule.loc, "unknown rule or script '" + st.rule.text + "'");
  }
}

/// A script may not apply itself, directly or through other scripts: each
/// call that closes a cycle is reported.
void check_recursion(const CallGraph& calls, diag::Diagnostics& diags) {
  std::map<std::string, int> state;  // 0 unvisited, 1 on the path, 2 done
  std::vector<std::string> path;
  std::function<void(const std::string&)> visit = [&](const std::string& s) {
    state[s] = 1;
    path.push_back(s);
    auto it = calls.find(s);
    if (it != calls.end()) {
      for (const auto& [callee, loc] : it->second) {
        if (state[callee] == 1) {
          std::string cycle;
          for (auto p = std::find(path.begin(), path.end(), callee); p != path.end(); ++p)
            cycle += "'" + *p + "' -> ";
          diags.error(loc, "script '" + s + "' applies script '" + callee +
                               "', which applies it again (" + cycle + "'" + callee +
                               "'); scripts cannot recurse");
        } else if (state[callee] == 0) {
          visit(callee);
        }
      }
    }
    path.pop_back();
    state[s] = 2;
  };
  for (const auto& [s, callees] : calls) {
    if (state[s] == 0) visit(s);
  }
}

/// A function's body sees its parameters, its lets written before, and the
/// pack's `param`s; its parameters have distinct names.
void resolve_function(const ast::Function& f, Resolver& r) {
  for (std::size_t k = 0; k < f.params.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (f.params[j].name.text != f.params[k].name.text) continue;
      r.count_use(f.params[k]);  // reported here; no second report as unused
      r.diags()
          .error(f.params[k].name.loc, "parameter '" + f.params[k].name.text + "' of function '" +
                                           f.name.text + "' is declared twice")
          .notes.push_back({f.params[j].name.loc, "first declared here"});
      break;
    }
  }
  Scope s;
  s.function = &f;
  s.params = &f.params;
  r.lets(f.lets, s);
  s.lets = &f.lets;
  s.visible_lets = f.lets.size();
  r.expr(*f.value, s);
}

/// A function may not call itself, directly or through others: its calls are
/// inlined. Each call that closes a cycle is reported with the cycle.
void check_function_recursion(const ast::Program& program, const FunctionCalls& calls,
                              diag::Diagnostics& diags) {
  std::map<const ast::Function*, int> state;  // 0 unvisited, 1 on the path, 2 done
  std::vector<const ast::Function*> path;
  std::function<void(const ast::Function*)> visit = [&](const ast::Function* f) {
    state[f] = 1;
    path.push_back(f);
    auto it = calls.find(f);
    if (it != calls.end()) {
      for (const auto& [callee, loc] : it->second) {
        if (state[callee] == 1) {
          std::string cycle;
          for (auto p = std::find(path.begin(), path.end(), callee); p != path.end(); ++p)
            cycle += "'" + (*p)->name.text + "' -> ";
          const std::string what = callee == f
                                       ? "calls itself"
                                       : "calls '" + callee->name.text + "', which calls it again";
          diags.error(loc, "function '" + f->name.text + "' " + what + " (" + cycle + "'" +
                               callee->name.text + "'); functions cannot recurse");
        } else if (state[callee] == 0) {
          visit(callee);
        }
      }
    }
    path.pop_back();
    state[f] = 2;
  };
  // In declaration order, so that the same call is reported on every run.
  for (const ast::File& file : program.files) {
    for (const ast::Function& f : file.functions) {
      if (state[&f] == 0) visit(&f);
    }
  }
}

}  // namespace

void resolve_names(const ast::Program& program, Symbols& symbols, diag::Diagnostics& diags) {
  Resolver r(symbols, diags);
  Scope constant;
  constant.constant = true;
  CallGraph script_calls;
  for (const ast::File& file : program.files) {
    for (const auto& f : file.functions)
      resolve_function(f, r);
    for (const auto& e : file.embeddings) {
      if (e.default_value) r.expr(*e.default_value, constant);
    }
    for (const auto& p : file.params)
      r.expr(*p.value, constant);
    for (const auto& init : file.inits) {
      r.bind_target(init);
      Scope s;
      s.nodes.insert(init.dart.text);
      r.expr(*init.value, s);
    }
    for (const auto& rule : file.rules)
      resolve_rule(rule, r);
    for (const auto& script : file.scripts)
      resolve_script(script, symbols, r, script_calls);
    for (const auto& inter : file.interactions) {
      component_params(inter.params, r, constant);
      Scope s;
      s.params = &inter.params;
      s.nodes = node_names(inter.pattern);
      Scope at_init = s;  // once per match on the initial mesh: no force-loop values
      at_init.match_lets = &inter.lets;
      at_init.match_lets_reason =
          "is a value of the force loop; an init runs once on the initial mesh and cannot read it";
      for (const auto& init : inter.inits) {
        r.bind_target(init);
        if (!s.nodes.count(init.dart.text)) {
          diags
              .error(init.dart.loc, "an interaction's init writes at one of its pattern nodes; '" +
                                        init.dart.text + "' is not one")
              .notes.push_back({inter.pattern.loc, "the pattern"});
        }
        r.expr(*init.value, at_init);
      }
      r.lets(inter.lets, s);
      r.whens(inter.lets, inter.whens, inter.body, s);
      s.lets = &inter.lets;
      s.visible_lets = inter.lets.size();
      for (const auto& f : inter.forces) {
        r.bind_target(f);
        r.node(f.node.text, f.node.loc, s);
        r.expr(*f.value, s);
      }
      for (const auto& st : inter.stores) {
        r.bind_target(st);
        r.node(st.node.text, st.node.loc, s);
        r.expr(*st.value, s);
      }
      for (const auto& acc : inter.accumulations) {
        r.bind_target(acc);
        r.node(acc.node.text, acc.node.loc, s);
        r.expr(*acc.value, s);
      }
      for (const auto& j : inter.jacobians)
        r.expr(*j.value, s);
      if (inter.energy) r.expr(*inter.energy, s);
    }
    for (const auto& crit : file.criteria) {
      component_params(crit.params, r, constant);
      Scope s;
      s.params = &crit.params;
      s.nodes.insert(crit.dart.text);
      criterion_nodes(crit, r, s);
      r.lets(crit.lets, s);
      s.lets = &crit.lets;
      s.visible_lets = crit.lets.size();
      if (crit.measure) r.expr(*crit.measure, s);
      for (const auto& h : crit.apply_hooks)
        r.node(h.text, h.loc, s);
      if (crit.has_apply && !symbols.callee_params(crit.rule.text))
        diags.error(crit.rule.loc, "unknown rule or script '" + crit.rule.text + "'");
      for (const auto& a : crit.apply_args)
        r.expr(*a.value, s);
    }
  }
  check_recursion(script_calls, diags);
  check_function_recursion(program, r.function_calls(), diags);
}

}  // namespace rift::resolve
