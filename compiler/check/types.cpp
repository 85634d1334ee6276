#include "check/types.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "check/builtins.hpp"
#include "rift/core/candidate_payload.hpp"
#include "rift/core/state_embeddings.hpp"

namespace rift::check {

namespace {

using ast::Expr;
using ast::Type;

bool numeric(Type t) {
  return t == Type::Int || t == Type::Real;
}
std::string str(Type t) {
  return std::string(ast::to_string(t));
}

/// Whether a value of type `from` may be stored where `to` is expected.
bool assignable(Type from, Type to) {
  return from == to || (from == Type::Int && to == Type::Real);
}

class TypeChecker {
 public:
  TypeChecker(int dimension, const resolve::Symbols& symbols, ExprTypes& types,
              diag::Diagnostics& diags)
      : dimension_(dimension), symbols_(symbols), types_(types), diags_(diags) {}

  /// The type of `e`, recorded in the side table for lower/ and emit/.
  Type expr(const Expr& e) {
    const Type t = compute(e);
    types_.set(e, t);
    return t;
  }

  /// Checks that `e` has a type assignable to `want`; `what` names the place.
  void expect(const Expr& e, Type want, const std::string& what) {
    const Type t = expr(e);
    if (t == Type::Error || want == Type::Error || assignable(t, want)) return;
    diags_.error(e.loc, what + " must be " + str(want) + ", not " + str(t));
  }

  void lets(const std::vector<ast::Let>& lets) {
    for (const auto& l : lets)
      expr(*l.value);
  }

 private:
  Type compute(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::IntLit:
        return Type::Int;
      case Expr::Kind::RealLit:
        return Type::Real;
      case Expr::Kind::BoolLit:
        return Type::Bool;
      case Expr::Kind::Name: {
        const resolve::Binding& b = symbols_.binding(e);
        if (b.let) return types_.of(*b.let->value);
        if (b.param) return b.param->type;
        if (b.pack_param) return b.pack_param->type;
        return Type::Error;
      }
      case Expr::Kind::Read:
        return read(e);
      case Expr::Kind::Collect:
        return collect(e);
      case Expr::Kind::Unary:
        return unary(e);
      case Expr::Kind::Binary:
        return binary(e);
      case Expr::Kind::Cond:
        return cond(e);
      case Expr::Kind::Index:
        return index(e);
      case Expr::Kind::Call:
        return call(e);
      case Expr::Kind::Fold:
        return fold(e);
    }
    return Type::Error;
  }

  /// `op of BODY for each <sub>(x) in <outer>(d)`.
  Type fold(const Expr& e) {
    check_hops(e);
    check_orbit_type(e.orbit, dimension_, "a 'for each'", diags_);
    check_orbit_type(e.outer, dimension_, "a 'for each'", diags_);
    lets(e.lets);
    const Type t = expr(*e.args[0]);
    if (t == Type::Error) return t;
    if (e.op == "count") {
      if (t == Type::Bool) return Type::Int;
      diags_.error(e.args[0]->loc,
                   "'count of' counts where a condition holds: it needs a bool, not " + str(t));
      return Type::Error;
    }
    if (e.op == "min" || e.op == "max") {
      if (numeric(t)) return t;
      diags_.error(e.args[0]->loc, "'" + e.op + " of' needs real or int values, not " + str(t));
      return Type::Error;
    }
    if (t == Type::Bool) {
      diags_.error(e.args[0]->loc, "'" + e.op + " of' cannot combine bool values");
      return Type::Error;
    }
    return e.op == "mean" && t == Type::Int ? Type::Real : t;
  }

  void check_hops(const Expr& e) {
    for (int h : e.hops) {
      if (h < 0 || h > dimension_) {
        diags_.error(e.node_loc, "link dimension " + std::to_string(h) + " is out of range 0.." +
                                     std::to_string(dimension_));
      }
    }
  }

  Type read(const Expr& e) {
    check_hops(e);
    const ast::Embedding* embedding = symbols_.binding(e).embedding;
    return embedding ? embedding->type : Type::Error;
  }

  Type collect(const Expr& e) {
    check_hops(e);
    check_orbit_type(e.orbit, dimension_, "a collection", diags_);
    const ast::Embedding* embedding = symbols_.binding(e).embedding;
    if (!embedding) return Type::Error;
    const Type t = embedding->type;
    if (e.op == "count") return Type::Int;
    if (e.op == "min" || e.op == "max") {
      if (numeric(t)) return t;
      diags_.error(e.loc, "'" + e.op + "' over an orbit needs real or int values; '" + e.name +
                              "' holds " + str(t));
      return Type::Error;
    }
    if (t == Type::Bool) {
      diags_.error(e.loc,
                   "'" + e.op + "' over an orbit cannot combine bool values of '" + e.name + "'");
      return Type::Error;
    }
    return e.op == "mean" && t == Type::Int ? Type::Real : t;
  }

  Type unary(const Expr& e) {
    const Type a = expr(*e.args[0]);
    if (a == Type::Error) return a;
    if (e.op == "not") {
      if (a == Type::Bool) return a;
    } else if (a != Type::Bool) {
      return a;
    }
    diags_.error(e.op_loc, "operator '" + e.op + "' cannot be applied to " + str(a));
    return Type::Error;
  }

  Type binary(const Expr& e) {
    const Type a = expr(*e.args[0]);
    const Type b = expr(*e.args[1]);
    if (a == Type::Error || b == Type::Error) return Type::Error;
    const std::string& op = e.op;
    const bool scalars = numeric(a) && numeric(b);
    const Type scalar = a == Type::Real || b == Type::Real ? Type::Real : Type::Int;
    if (op == "and" || op == "or") {
      if (a == Type::Bool && b == Type::Bool) return Type::Bool;
    } else if (op == "<" || op == "<=" || op == ">" || op == ">=") {
      if (scalars) return Type::Bool;
    } else if (op == "==" || op == "!=") {
      if (scalars || a == b) {
        if (a == Type::Real || b == Type::Real) {
          diags_.warning(
              "float-equality", e.op_loc,
              "comparing real numbers with '" + op + "' is fragile; compare with a tolerance");
        }
        return Type::Bool;
      }
    } else if (op == "+" || op == "-") {
      if (scalars) return scalar;
      if (a == b && (a == Type::Vec3 || a == Type::Mat3)) return a;
    } else if (op == "*") {
      if (scalars) return scalar;
      if (numeric(a) && (b == Type::Vec3 || b == Type::Mat3)) return b;
      if (numeric(b) && (a == Type::Vec3 || a == Type::Mat3)) return a;
      if (a == Type::Mat3 && (b == Type::Vec3 || b == Type::Mat3)) return b;
    } else if (op == "/") {
      if (scalars) return scalar;
      if (numeric(b) && (a == Type::Vec3 || a == Type::Mat3)) return a;
    }
    diags_.error(e.op_loc, "operator '" + op + "' cannot combine " + str(a) + " and " + str(b));
    return Type::Error;
  }

  Type cond(const Expr& e) {
    expect(*e.args[0], Type::Bool, "the condition of 'if'");
    const Type a = expr(*e.args[1]);
    const Type b = expr(*e.args[2]);
    if (a == Type::Error || b == Type::Error) return Type::Error;
    if (a == b) return a;
    if (numeric(a) && numeric(b)) return Type::Real;
    diags_.error(e.op_loc,
                 "the branches of 'if' have different types: " + str(a) + " and " + str(b));
    return Type::Error;
  }

  Type index(const Expr& e) {
    const Type base = expr(*e.args[0]);
    for (std::size_t k = 1; k < e.args.size(); ++k)
      expect(*e.args[k], Type::Int, "an index");
    if (base == Type::Error) return base;
    const std::size_t want = base == Type::Vec3 ? 1 : base == Type::Mat3 ? 2 : 0;
    if (want == 0) {
      diags_.error(e.op_loc, "only vec3 and mat3 values can be indexed, not " + str(base));
      return Type::Error;
    }
    if (e.args.size() - 1 != want) {
      diags_.error(e.op_loc, "a " + str(base) + " takes " + std::to_string(want) +
                                 (want == 1 ? " index" : " indices"));
      return Type::Error;
    }
    for (std::size_t k = 1; k < e.args.size(); ++k) {
      const Expr& i = *e.args[k];
      if (i.kind == Expr::Kind::IntLit && (i.integer < 0 || i.integer > 2)) {
        diags_.error(i.loc, "index " + std::to_string(i.integer) + " is out of range 0..2");
      }
    }
    return Type::Real;
  }

  Type call(const Expr& e) {
    std::vector<Type> args;
    bool bad = false;
    for (const auto& a : e.args) {
      args.push_back(expr(*a));
      bad = bad || args.back() == Type::Error;
    }
    if (const ast::Function* f = symbols_.binding(e).function) return function_call(e, *f, args);
    const std::vector<Signature>* overloads = builtin(e.name);
    if (!overloads) {
      diags_.error(e.op_loc, "unknown function '" + e.name + "'");
      return Type::Error;
    }
    if (bad) return Type::Error;
    if (const Signature* s = select_overload(*overloads, args)) return s->result;
    std::string expected;
    for (const Signature& s : *overloads) {
      expected += (expected.empty() ? "" : " or ") + describe(s.params);
    }
    diags_.error(e.op_loc, "'" + e.name + "' expects " + expected + ", got " + describe(args));
    return Type::Error;
  }

  /// A call of a `def`: one argument per parameter, each of the parameter's
  /// type (an int is promoted to real); the call has the declared result type.
  Type function_call(const Expr& e, const ast::Function& f, const std::vector<Type>& args) {
    std::vector<Type> params;
    params.reserve(f.params.size());
    for (const ast::Param& p : f.params)
      params.push_back(p.type);
    if (args.size() != params.size()) {
      diags_
          .error(e.op_loc, "function '" + f.name.text + "' takes " + std::to_string(params.size()) +
                               (params.size() == 1 ? " argument " : " arguments ") +
                               describe(params) + ", got " + std::to_string(args.size()))
          .notes.push_back({f.name.loc, "declared here"});
      return f.result;
    }
    for (std::size_t k = 0; k < args.size(); ++k) {
      if (args[k] == Type::Error || assignable(args[k], params[k])) continue;
      diags_
          .error(e.args[k]->loc, "argument " + std::to_string(k + 1) + " of '" + f.name.text +
                                     "' ('" + f.params[k].name.text + "') must be " +
                                     str(params[k]) + ", not " + str(args[k]))
          .notes.push_back({f.params[k].name.loc, "declared here"});
    }
    return f.result;
  }

  int dimension_;
  const resolve::Symbols& symbols_;
  ExprTypes& types_;
  diag::Diagnostics& diags_;
};

void check_embedding(const ast::Embedding& e, int dimension, TypeChecker& tc,
                     diag::Diagnostics& diags) {
  check_orbit_type(e.orbit, dimension, "an embedding", diags);
  if (e.default_value) tc.expect(*e.default_value, e.type, "the default of '" + e.name.text + "'");
  if (e.merge) {
    static const std::set<std::string> kPolicies = {"keep", "sum", "mean", "refuse"};
    if (!kPolicies.count(e.merge->text)) {
      diags.error(e.merge->loc, "unknown merge policy '" + e.merge->text +
                                    "'; expected keep, sum, mean or refuse");
    } else if (e.merge->text == "mean" && e.type == Type::Bool) {
      // `sum` of bools is their logical or (a vertex merged with a pinned
      // one is pinned); a mean of truth values has no such reading.
      diags.error(e.merge->loc,
                  "merge policy 'mean' needs numbers, not bool; 'sum' merges bools by 'or'");
    }
  }
}

void check_assign(const ast::Assign& a, const resolve::Symbols& symbols, TypeChecker& tc,
                  const char* what) {
  const ast::Embedding* target = symbols.target(a);
  if (!target) {
    tc.expr(*a.value);
    return;
  }
  tc.expect(*a.value, target->type, std::string(what) + " '" + a.embedding.text + "'");
}

/// The masses are the simulator's state: it sets corner_mass from the scene's
/// [mass] (by area or volume) and sums vertex_mass from it after the pack's
/// inits have run, and again after every rewrite, so a value an init gave
/// them would be overwritten without a word. An init of either is an error.
void reject_mass_init(const ast::Init& init, diag::Diagnostics& diags) {
  const std::string& name = init.embedding.text;
  if (name != state::kCornerMass && name != state::kVertexMass) return;
  diags.error(init.embedding.loc,
              "an init cannot set '" + name +
                  "': the simulator computes the masses from the scene's [mass] section "
                  "(by area or volume) after the pack's inits, and would overwrite this value; "
                  "remove this init");
}

/// Whether `embedding`, which a store of `inter` writes, is also one of its
/// forces or init targets (reported, `as_force` / `as_init` saying why the
/// store may not write it).
bool written_by_forces_or_inits(const ast::Interaction& inter, const ast::Ident& embedding,
                                const std::string& as_force, const std::string& as_init,
                                diag::Diagnostics& diags) {
  const std::string& name = embedding.text;
  for (const ast::Assign& f : inter.forces) {
    if (f.embedding.text != name) continue;
    diags
        .error(embedding.loc,
               "'" + name + "' is a force of interaction '" + inter.name.text + "'; " + as_force)
        .notes.push_back({f.embedding.loc, "the force"});
    return true;
  }
  for (const ast::Init& init : inter.inits) {
    if (init.embedding.text != name) continue;
    diags
        .error(embedding.loc,
               "'" + name + "' is initialised by interaction '" + inter.name.text + "'; " + as_init)
        .notes.push_back({init.embedding.loc, "the init"});
    return true;
  }
  return false;
}

/// A `store` writes an embedding no other statement of the simulation
/// writes: not the simulator's state (positions, masses, ... are its own),
/// not a force of the same interaction, not one of its inits' embeddings,
/// and no two stores of the interaction the same embedding at the same node.
void check_stored_value(const ast::Interaction& inter, const ast::Assign& st,
                        diag::Diagnostics& diags) {
  const std::string& name = st.embedding.text;
  if (state::find(name) != nullptr) {
    diags.error(st.embedding.loc, "'" + name +
                                      "' is the simulator's state and cannot be stored by an "
                                      "interaction; store into an embedding of the pack");
    return;
  }
  if (written_by_forces_or_inits(inter, st.embedding, "a store cannot also write it",
                                 "a store would overwrite it", diags))
    return;
  for (const ast::Assign& other : inter.stores) {
    if (&other == &st) break;
    if (other.embedding.text != name || other.node.text != st.node.text) continue;
    diags.error(st.embedding.loc, "'" + name + "' is stored twice at '" + st.node.text + "'")
        .notes.push_back({other.embedding.loc, "the first store"});
    return;
  }
}

/// A `store v.E += value` adds into a per-vertex embedding during the force
/// pass. The matches add without synchronisation in the coloured order of
/// the forces' scatter, which keeps apart only the vertices the interaction
/// exerts forces on: so E lives on the vertex orbit, at a node a `force`
/// statement acts on, holds a value that adds (real, vec3, mat3), and is no
/// state, force, init or `store =` of the same interaction.
void check_accumulated_value(const ast::Interaction& inter, const ast::Assign& acc,
                             const resolve::Symbols& symbols, int dimension,
                             diag::Diagnostics& diags) {
  const std::string& name = acc.embedding.text;
  if (state::find(name) != nullptr) {
    diags.error(acc.embedding.loc, "'" + name +
                                       "' is the simulator's state and cannot be accumulated "
                                       "by an interaction; accumulate into an embedding of the "
                                       "pack");
    return;
  }
  const ast::Embedding* target = symbols.target(acc);
  if (!target) return;
  if (target->type != Type::Real && target->type != Type::Vec3 && target->type != Type::Mat3) {
    diags
        .error(acc.embedding.loc, "'" + name + "' holds " + std::string(to_string(target->type)) +
                                      " values, which do not add: 'store ... +=' accumulates "
                                      "real, vec3 or mat3")
        .notes.push_back({target->name.loc, "declared here"});
    return;
  }
  std::vector<int> vertex;
  for (int d = 1; d <= dimension; ++d)
    vertex.push_back(d);
  std::vector<int> dims = target->orbit.dims;
  std::sort(dims.begin(), dims.end());
  if (dims != vertex) {
    std::string orbit = "<";
    for (std::size_t i = 0; i < vertex.size(); ++i) {
      if (i > 0) orbit += ',';
      orbit += std::to_string(vertex[i]);
    }
    orbit += ">";
    diags
        .error(acc.embedding.loc,
               "'" + name + "' is not on the vertex orbit " + orbit +
                   ": 'store ... +=' adds per vertex, in the order the forces' scatter gives each "
                   "vertex (use 'store ... =' for a value of the match's own orbit)")
        .notes.push_back({target->orbit.loc, "its orbit"});
    return;
  }
  if (written_by_forces_or_inits(inter, acc.embedding, "a store cannot also add to it",
                                 "accumulating would overwrite it", diags))
    return;
  for (const ast::Assign& st : inter.stores) {
    if (st.embedding.text != name) continue;
    diags
        .error(acc.embedding.loc,
               "'" + name + "' is both stored ('=') and accumulated ('+=') by interaction '" +
                   inter.name.text + "'")
        .notes.push_back({st.embedding.loc, "the store"});
    return;
  }
  for (const ast::Assign& other : inter.accumulations) {
    if (&other == &acc) break;
    if (other.embedding.text != name || other.node.text != acc.node.text) continue;
    diags
        .error(acc.embedding.loc, "'" + name + "' is accumulated twice at '" + acc.node.text +
                                      "'; add the two values in one statement")
        .notes.push_back({other.embedding.loc, "the first"});
    return;
  }
  const bool pushed =
      std::any_of(inter.forces.begin(), inter.forces.end(),
                  [&](const ast::Assign& f) { return f.node.text == acc.node.text; });
  if (!pushed) {
    diags.error(acc.node.loc,
                "interaction '" + inter.name.text + "' exerts no force on '" + acc.node.text +
                    "': 'store ... +=' adds at the vertices of the forces, which the coloured "
                    "scatter keeps apart between threads (deterministic sums)");
  }
}

void check_component_params(const std::vector<ast::Param>& params, TypeChecker& tc,
                            diag::Diagnostics& diags) {
  for (const ast::Param& p : params) {
    if (p.default_value) {
      tc.expect(*p.default_value, p.type, "the default of '" + p.name.text + "'");
    }
    if (p.bound != ast::Param::Bound::None && !numeric(p.type)) {
      diags.error(p.bound_loc, "only real and int parameters can have a bound, and '" +
                                   p.name.text + "' is " + str(p.type));
    }
  }
}

/// The arguments of an `apply`: every one names a parameter of the callee,
/// with its type, and every parameter is given.
void check_call_args(const ast::Ident& callee, const resolve::Symbols& symbols,
                     const std::vector<ast::ApplyArg>& args, const diag::Location& loc,
                     TypeChecker& tc, diag::Diagnostics& diags) {
  const std::vector<ast::Param>* params = symbols.callee_params(callee.text);
  const std::string kind = symbols.script(callee.text) ? "script" : "rule";
  for (const auto& arg : args) {
    const ast::Param* param = nullptr;
    if (params) {
      for (const auto& p : *params) {
        if (p.name.text == arg.name.text) param = &p;
      }
      if (!param) {
        diags.error(arg.name.loc,
                    kind + " '" + callee.text + "' has no parameter '" + arg.name.text + "'");
      }
    }
    tc.expect(*arg.value, param ? param->type : Type::Error, "parameter '" + arg.name.text + "'");
  }
  if (!params) return;
  for (const auto& p : *params) {
    bool given = false;
    for (const auto& arg : args)
      given = given || arg.name.text == p.name.text;
    if (!given) {
      diags
          .error(loc, "parameter '" + p.name.text + "' of " + kind + " '" + callee.text +
                          "' is not given")
          .notes.push_back({p.name.loc, "declared here"});
    }
  }
}

/// A criterion's apply arguments travel with its candidates, in a payload of
/// fixed capacity (rift/core/candidate_payload.hpp): they must fit in it.
void check_payload_size(const ast::Criterion& crit, const resolve::Symbols& symbols,
                        diag::Diagnostics& diags) {
  const std::vector<ast::Param>* params = symbols.callee_params(crit.rule.text);
  if (!params) return;
  std::size_t total = 0;
  std::string sizes;
  for (const auto& arg : crit.apply_args) {
    for (const auto& p : *params) {
      if (p.name.text != arg.name.text) continue;
      const std::size_t n = ast::payload_reals(p.type);
      total += n;
      sizes += (sizes.empty() ? "'" : ", '") + arg.name.text + "': " + std::to_string(n) +
               " for a " + str(p.type);
    }
  }
  if (total <= kCandidatePayloadReals) return;
  const std::string kind = symbols.script(crit.rule.text) ? "script" : "rule";
  diags.error(crit.apply_loc, "criterion '" + crit.name.text + "' passes " + std::to_string(total) +
                                  " reals to " + kind + " '" + crit.rule.text + "' (" + sizes +
                                  "), but a tear candidate carries at most " +
                                  std::to_string(kCandidatePayloadReals) +
                                  " (rift/core/candidate_payload.hpp)");
}

void check_script(const ast::Script& script, const resolve::Symbols& symbols, int dimension,
                  TypeChecker& tc, diag::Diagnostics& diags) {
  for (const ast::ScriptStmt& st : script.stmts) {
    if (st.kind == ast::ScriptStmt::Kind::Let) {
      tc.expr(*script.lets[st.let].value);
      continue;
    }
    if (st.each.present) {
      check_orbit_type(st.each.sub, dimension, "a 'for each'", diags);
      check_orbit_type(st.each.outer, dimension, "a 'for each'", diags);
    }
    if (st.where) tc.expect(*st.where, Type::Bool, "a 'where' condition");
    if (st.kind == ast::ScriptStmt::Kind::Set) {
      check_assign(st.set, symbols, tc, "the value of");
      continue;
    }
    check_call_args(st.rule, symbols, st.args, st.loc, tc, diags);
  }
}

}  // namespace

bool check_orbit_type(const ast::Label& label, int dimension, const char* what,
                      diag::Diagnostics& diags) {
  std::set<int> seen;
  for (int d : label.dims) {
    if (d < 0) {
      diags.error(label.loc, std::string("the orbit of ") + what + " cannot contain '_'");
      return false;
    }
    if (d > dimension) {
      diags.error(label.loc, "dimension " + std::to_string(d) + " is out of range 0.." +
                                 std::to_string(dimension));
      return false;
    }
    if (!seen.insert(d).second) {
      diags.error(label.loc, "dimension " + std::to_string(d) + " appears twice in an orbit");
      return false;
    }
  }
  return true;
}

void check_types(const ast::Program& program, const resolve::Symbols& symbols, ExprTypes& types,
                 diag::Diagnostics& diags) {
  TypeChecker tc(program.dimension, symbols, types, diags);
  std::map<std::string, diag::Location> initialised;
  // Functions first: a let of a caller may be typed by a call, and the types
  // of a function's lets are read when the call is lowered.
  for (const ast::File& file : program.files) {
    for (const ast::Function& f : file.functions) {
      if (builtin(f.name.text)) {
        diags.error(f.name.loc, "function '" + f.name.text +
                                    "' has the name of a built-in function; choose another name");
      }
      tc.lets(f.lets);
      tc.expect(*f.value, f.result, "the result of function '" + f.name.text + "'");
    }
  }
  for (const ast::File& file : program.files) {
    for (const auto& e : file.embeddings)
      check_embedding(e, program.dimension, tc, diags);
    for (const auto& p : file.params)
      tc.expect(*p.value, p.type, "the value of '" + p.name.text + "'");
    for (const auto& init : file.inits) {
      const ast::Embedding* emb = symbols.target(init);
      if (!emb) {
        tc.expr(*init.value);
        continue;
      }
      tc.expect(*init.value, emb->type, "the initial value of '" + init.embedding.text + "'");
      reject_mass_init(init, diags);
      auto [it, fresh] = initialised.emplace(init.embedding.text, init.embedding.loc);
      if (!fresh) {
        diags.error(init.embedding.loc, "'" + init.embedding.text + "' is initialised twice")
            .notes.push_back({it->second, "first initialised here"});
      }
    }
    for (const auto& rule : file.rules) {
      tc.lets(rule.lets);
      for (const auto& w : rule.whens)
        tc.expect(*w, Type::Bool, "a precondition");
      for (const auto& a : rule.right.assigns)
        check_assign(a, symbols, tc, "the value of");
      for (const auto& u : rule.updates)
        check_assign(u, symbols, tc, "the update of");
    }
    for (const auto& script : file.scripts)
      check_script(script, symbols, program.dimension, tc, diags);
    for (const auto& inter : file.interactions) {
      check_component_params(inter.params, tc, diags);
      for (const auto& init : inter.inits) {
        const ast::Embedding* target = symbols.target(init);
        if (!target) {
          tc.expr(*init.value);
          continue;
        }
        tc.expect(*init.value, target->type, "the initial value of '" + init.embedding.text + "'");
        reject_mass_init(init, diags);
        auto [it, fresh] = initialised.emplace(init.embedding.text, init.embedding.loc);
        if (!fresh) {
          diags.error(init.embedding.loc, "'" + init.embedding.text + "' is initialised twice")
              .notes.push_back({it->second, "first initialised here"});
        }
      }
      tc.lets(inter.lets);
      for (const auto& w : inter.whens)
        tc.expect(*w, Type::Bool, "a precondition");
      for (const auto& f : inter.forces) {
        check_assign(f, symbols, tc, "the force");
        const ast::Embedding* target = symbols.target(f);
        if (target && target->type != Type::Vec3) {
          diags
              .error(f.embedding.loc, "force embedding '" + f.embedding.text +
                                          "' must hold vec3 values, not " + str(target->type))
              .notes.push_back({target->name.loc, "declared here"});
        }
      }
      for (const auto& st : inter.stores) {
        check_assign(st, symbols, tc, "the stored value of");
        check_stored_value(inter, st, diags);
      }
      for (const auto& acc : inter.accumulations) {
        check_assign(acc, symbols, tc, "the accumulated value of");
        check_accumulated_value(inter, acc, symbols, program.dimension, diags);
      }
      for (const auto& j : inter.jacobians)
        tc.expect(*j.value, Type::Mat3, "a Jacobian block");
      if (inter.energy) tc.expect(*inter.energy, Type::Real, "the energy");
    }
    for (const auto& crit : file.criteria) {
      check_component_params(crit.params, tc, diags);
      tc.lets(crit.lets);
      if (!crit.measure) {
        diags.error(crit.name.loc, "criterion '" + crit.name.text + "' has no 'measure'");
      } else {
        const Expr& m = *crit.measure;
        const bool comparison = m.kind == Expr::Kind::Binary &&
                                (m.op == "<" || m.op == "<=" || m.op == ">" || m.op == ">=");
        tc.expr(m);
        if (!comparison) {
          diags.error(m.loc, "a measure is a comparison 'VALUE > THRESHOLD' (or <, <=, >=)");
        }
      }
      if (!crit.has_apply) {
        diags.error(crit.name.loc, "criterion '" + crit.name.text + "' applies no rule");
      }
      if (crit.has_apply) {
        check_call_args(crit.rule, symbols, crit.apply_args, crit.apply_loc, tc, diags);
        check_payload_size(crit, symbols, diags);
      }
    }
  }
}

}  // namespace rift::check
