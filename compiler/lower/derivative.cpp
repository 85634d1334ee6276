#include "lower/derivative.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <utility>

#include "check/kernels.hpp"
#include "lower/share.hpp"

namespace rift::lower {

namespace {

using ir::Builtin;
using ir::ExprId;
using ir::kNoExpr;
using ir::Node;
using ir::Op;
using ir::Type;

bool differentiable(Type t) {
  return t == Type::Real || t == Type::Vec3 || t == Type::Mat3;
}

// Built-ins whose value has no usable derivative: a rule marks their result
// constant with stop_gradient(...) (the rotation of a polar decomposition
// for co-rotational elements), or gives up implicit integration.
bool without_derivative(Builtin f) {
  return f == Builtin::Rotation || f == Builtin::MaxEigenvalue || f == Builtin::MaxEigenvector ||
         f == Builtin::Eigenvalues;
}

bool reads_state_through_map(const Node& n) {
  return n.op == Op::Read &&
         (n.embedding == check::kPositionEmbedding || n.embedding == check::kVelocityEmbedding);
}

/// The (vertex slot, velocity?) pairs whose blocks the rule gives for one
/// force: its tangent is not derived along them.
using Given = std::set<std::pair<int, bool>>;

/// Whether a Position or Velocity read seeds the tangents.
using Seeded = std::function<bool(const Node&)>;

/// Which nodes depend on a seeded position or velocity, and the first active
/// subexpression without a derivative.
class Activity {
 public:
  Activity(const ir::Body& body, DerivativePlan& out, Seeded seeded)
      : body_(body), out_(out), seeded_(std::move(seeded)), memo_(body.graph.size(), -1) {}

  bool active(ExprId id) {
    auto& m = memo_[static_cast<std::size_t>(id)];
    if (m < 0) m = compute(id) ? 1 : 0;
    return m == 1;
  }

 private:
  bool compute(ExprId id) {
    const Node& n = body_.graph[id];
    switch (n.op) {
      case Op::Position:
        out_.depends_on_x = true;
        return seeded_(n);
      case Op::Velocity:
        out_.depends_on_v = true;
        return seeded_(n);
      case Op::Let:
        return active(body_.lets[static_cast<std::size_t>(n.index)].value);
      case Op::Call:
        if (n.fn == Builtin::StopGradient) {
          flags_only(n.a);  // constant for differentiation, whatever it holds
          return false;
        }
        break;
      default:
        break;
    }
    bool any = reads_state_through_map(n);
    for (std::size_t k = 0; k < n.arity(); ++k)
      any = active(n.operand(k)) || any;
    if (!any) return false;
    if (n.op == Op::Call && without_derivative(n.fn)) {
      // Appended (GCC 12's -Wrestrict misfires on `"'" + std::string` once inlined).
      std::string why = "'";
      why.append(ir::builtin_name(n.fn))
          .append(
              "(...)' depends on a position or a velocity and has no derivative; wrap it "
              "in stop_gradient(...) to hold it constant for the Jacobian (co-rotational "
              "elements hold their rotation so)");
      fail(n, std::move(why));
    }
    if (n.op == Op::Fold) {
      fail(n,
           "a fold over the map depends on a position or a velocity: its derivative is not "
           "formed");
    }
    // Integer and boolean results are piecewise constant: zero derivative.
    return differentiable(n.type);
  }

  // Under stop_gradient: what the forces depend on, nothing else.
  void flags_only(ExprId id) {
    ir::visit(body_.graph, id, [this](const Node& n) {
      if (n.op == Op::Position) out_.depends_on_x = true;
      if (n.op == Op::Velocity) out_.depends_on_v = true;
      if (n.op == Op::Let) flags_only(body_.lets[static_cast<std::size_t>(n.index)].value);
    });
  }

  void fail(const Node& n, std::string why) {
    if (!out_.why.empty()) return;
    out_.where = n.loc;
    out_.why = std::move(why);
  }

  const ir::Body& body_;
  DerivativePlan& out_;
  Seeded seeded_;
  std::vector<std::int8_t> memo_;  // per node: -1 not yet known, 0, 1
};

/// The blocks the rule gives for force statement `i` (those of its node and
/// embedding), restricted to the kinds `seed` differentiates by.
Given given_blocks(const ir::Body& body, std::size_t i, Seed seed = {true, true}) {
  Given out;
  const ir::Force& f = body.forces[i];
  for (const ir::JacobianBlock& j : body.jacobians) {
    if (j.node == f.node && j.embedding == f.embedding && (j.velocity ? seed.v : seed.x))
      out.emplace(j.by_slot, j.velocity);
  }
  return out;
}

bool is_given(const Given& given, const Node& n) {
  return given.count({n.place.slot, n.op == Op::Velocity || n.op == Op::VelocityTangent}) != 0;
}

/// Builds the tangent nodes of one pass into `g` (the body's graph, extended).
class Tangents {
 public:
  /// Along the `given` blocks the tangent is not derived (the rule gives them).
  Tangents(ir::Graph& g, const ir::Body& body, Seed seed, Given given = {})
      : g_(g),
        body_(body),
        seed_(seed),
        given_(std::move(given)),
        let_(body.lets.size(), kUnknown) {}

  /// The tangent of node `id`, kNoExpr when identically zero.
  ExprId of(ExprId id) {
    const auto it = memo_.find(id);
    if (it != memo_.end()) return it->second;
    const auto before = static_cast<ExprId>(g_.size());
    ExprId t = compute(id);
    // The tangent of a function's let is named after it (t_spring_force_l).
    if (t >= before && !g_[id].value_name.empty() && g_[t].value_name.empty()) {
      Node named = g_[t];
      named.value_name = "t_" + g_[id].value_name;
      t = g_.add(std::move(named));
    }
    memo_.emplace(id, t);
    return t;
  }

  ExprId of_let(std::size_t i) {
    if (let_[i] == kUnknown) let_[i] = of(body_.lets[i].value);
    return let_[i];
  }

 private:
  static constexpr ExprId kUnknown = -2;

  const Node& at(ExprId id) const { return g_[id]; }
  Type type(ExprId id) const { return g_[id].type; }

  ExprId zero(Type t) {
    if (t == Type::Real) return g_.real(0);
    Node n;
    n.op = Op::Literal;
    n.type = t;
    return g_.add(std::move(n));
  }
  ExprId or_zero(ExprId t, Type type) { return t == kNoExpr ? zero(type) : t; }
  ExprId real(double v) { return g_.real(v); }
  ExprId neg(ExprId a) { return a == kNoExpr ? a : g_.unary(Op::Neg, type(a), a); }
  ExprId add(ExprId a, ExprId b) {
    if (a == kNoExpr) return b;
    if (b == kNoExpr) return a;
    return g_.binary(Op::Add, type(a), a, b);
  }
  ExprId sub(ExprId a, ExprId b) {
    if (b == kNoExpr) return a;
    if (a == kNoExpr) return neg(b);
    return g_.binary(Op::Sub, type(a), a, b);
  }
  /// a * b, of type t (kNoExpr when either is zero).
  ExprId mul(Type t, ExprId a, ExprId b) {
    if (a == kNoExpr || b == kNoExpr) return kNoExpr;
    return g_.binary(Op::Mul, t, a, b);
  }
  ExprId div(Type t, ExprId a, ExprId b) {
    if (a == kNoExpr) return kNoExpr;
    return g_.binary(Op::Div, t, a, b);
  }
  ExprId call(Builtin f, Type t, std::vector<ExprId> args) {
    for (ExprId a : args) {
      if (a == kNoExpr) return kNoExpr;
    }
    return g_.call(f, t, std::move(args));
  }
  ExprId cond(Type t, ExprId c, ExprId yes, ExprId no) {
    if (yes == kNoExpr && no == kNoExpr) return kNoExpr;
    Node n;
    n.op = Op::Cond;
    n.type = t;
    n.a = c;
    n.b = or_zero(yes, t);
    n.c = or_zero(no, t);
    return g_.add(std::move(n));
  }
  ExprId compare(Op op, ExprId a, ExprId b) { return g_.binary(op, Type::Bool, a, b); }
  ExprId index(ExprId m, int row, int col) {
    Node n;
    n.op = Op::Index;
    n.type = Type::Real;
    n.a = m;
    n.b = g_.integer(row);
    n.c = g_.integer(col);
    return g_.add(std::move(n));
  }
  /// Column k of a mat3 as a vec3.
  ExprId column(ExprId m, int k) {
    return g_.call(Builtin::Vec3, Type::Vec3, {index(m, 0, k), index(m, 1, k), index(m, 2, k)});
  }

  ExprId compute(ExprId id) {
    // Copied: adding nodes may move the graph's storage.
    const Node n = at(id);
    if (!differentiable(n.type)) return kNoExpr;  // piecewise constant
    switch (n.op) {
      case Op::Position:
      case Op::Velocity: {
        if (n.op == Op::Position ? !seed_.x : !seed_.v) return kNoExpr;
        if (is_given(given_, n)) return kNoExpr;
        Node t;
        t.op = n.op == Op::Position ? Op::PositionTangent : Op::VelocityTangent;
        t.type = Type::Vec3;
        t.place = n.place;
        return g_.add(std::move(t));
      }
      case Op::Let:
        return of_let(static_cast<std::size_t>(n.index));
      case Op::Neg:
        return neg(of(n.a));
      case Op::Add:
        return add(of(n.a), of(n.b));
      case Op::Sub:
        return sub(of(n.a), of(n.b));
      case Op::Mul:  // product rule, operand order kept (matrices)
        return add(mul(n.type, of(n.a), n.b), mul(n.type, n.a, of(n.b)));
      case Op::Div: {  // the divisor is a scalar: d(a/b) = (da - (a/b) db) / b
        const ExprId ta = of(n.a), tb = of(n.b);
        if (ta == kNoExpr && tb == kNoExpr) return kNoExpr;
        return div(n.type, sub(ta, mul(n.type, id, tb)), n.b);
      }
      case Op::Cond:
        return cond(n.type, n.a, of(n.b), of(n.c));
      case Op::Index: {
        const ExprId ta = of(n.a);
        if (ta == kNoExpr) return kNoExpr;
        Node t = n;
        t.a = ta;
        t.value_name.clear();  // names the value, not its tangent
        return g_.add(std::move(t));
      }
      case Op::Call:
        return builtin(id, n);
      default:
        // Literals, parameters, other embeddings, ints made real: constant.
        // Folds and map reads of the state are refused by plan_derivative.
        return kNoExpr;
    }
  }

  ExprId builtin(ExprId id, const Node& n) {
    std::vector<ExprId> t;
    bool any = false;
    for (std::size_t k = 0; k < n.arity(); ++k) {
      t.push_back(of(n.operand(k)));
      any = any || t.back() != kNoExpr;
    }
    if (!any) return kNoExpr;
    auto x = [&n](std::size_t k) { return n.operand(k); };
    auto tz = [&](std::size_t k) { return or_zero(t[k], type(x(k))); };
    const Type r = n.type;
    switch (n.fn) {
      case Builtin::Real:
        return t[0];
      case Builtin::Vec3:
      case Builtin::Mat3: {
        std::vector<ExprId> args;
        args.reserve(t.size());
        for (std::size_t k = 0; k < t.size(); ++k)
          args.push_back(tz(k));
        return g_.call(n.fn, r, std::move(args));
      }
      case Builtin::Min:
      case Builtin::Max:
        return cond(r, compare(n.fn == Builtin::Min ? Op::Le : Op::Ge, x(0), x(1)), t[0], t[1]);
      case Builtin::Clamp:
        return cond(r, compare(Op::Lt, x(0), x(1)), t[1],
                    cond(r, compare(Op::Gt, x(0), x(2)), t[2], t[0]));
      case Builtin::Abs:
        return cond(r, compare(Op::Ge, x(0), real(0)), t[0], neg(t[0]));
      case Builtin::Sqrt:  // d√a = da / (2√a)
        return div(r, t[0], g_.binary(Op::Mul, r, real(2), id));
      case Builtin::Exp:
        return mul(r, id, t[0]);
      case Builtin::Log:
        return div(r, t[0], x(0));
      case Builtin::Sin:
        return mul(r, g_.call(Builtin::Cos, r, {x(0)}), t[0]);
      case Builtin::Cos:
        return neg(mul(r, g_.call(Builtin::Sin, r, {x(0)}), t[0]));
      case Builtin::Tan:  // d tan a = (1 + tan² a) da
        return mul(r, g_.binary(Op::Add, r, real(1), g_.binary(Op::Mul, r, id, id)), t[0]);
      case Builtin::Asin:
      case Builtin::Acos: {
        const ExprId root = g_.call(
            Builtin::Sqrt, r, {g_.binary(Op::Sub, r, real(1), g_.binary(Op::Mul, r, x(0), x(0)))});
        const ExprId d = div(r, t[0], root);
        return n.fn == Builtin::Asin ? d : neg(d);
      }
      case Builtin::Atan:
        return div(r, t[0], g_.binary(Op::Add, r, real(1), g_.binary(Op::Mul, r, x(0), x(0))));
      case Builtin::Atan2: {  // atan2(y, x): (x dy - y dx) / (x² + y²)
        const ExprId y0 = x(0), x0 = x(1);
        const ExprId num = sub(mul(r, x0, t[0]), mul(r, y0, t[1]));
        return div(
            r, num,
            g_.binary(Op::Add, r, g_.binary(Op::Mul, r, x0, x0), g_.binary(Op::Mul, r, y0, y0)));
      }
      case Builtin::Pow: {
        if (t[1] == kNoExpr) {  // d aᵇ = b aᵇ⁻¹ da
          const ExprId p = g_.call(Builtin::Pow, r, {x(0), g_.binary(Op::Sub, r, x(1), real(1))});
          return mul(r, g_.binary(Op::Mul, r, x(1), p), t[0]);
        }
        // d aᵇ = aᵇ (b da / a + log a db)
        const ExprId da = mul(r, t[0], g_.binary(Op::Div, r, x(1), x(0)));
        const ExprId db = mul(r, g_.call(Builtin::Log, r, {x(0)}), t[1]);
        return mul(r, id, add(da, db));
      }
      case Builtin::Dot:
      case Builtin::Cross:
      case Builtin::Outer:
        return add(call(n.fn, r, {t[0], x(1)}), call(n.fn, r, {x(0), t[1]}));
      case Builtin::Norm:  // d|a| = a·da / |a|
        return div(r, g_.call(Builtin::Dot, Type::Real, {x(0), t[0]}), id);
      case Builtin::Normalize: {  // d(a/|a|) = (da - n (n·da)) / |a|, n = a/|a|
        const ExprId along =
            g_.binary(Op::Mul, r, id, g_.call(Builtin::Dot, Type::Real, {id, t[0]}));
        return div(r, g_.binary(Op::Sub, r, t[0], along),
                   g_.call(Builtin::Norm, Type::Real, {x(0)}));
      }
      case Builtin::Transpose:
      case Builtin::Trace:
        return g_.call(n.fn, r, {t[0]});
      case Builtin::Inverse:  // d(A⁻¹) = -A⁻¹ dA A⁻¹
        return neg(g_.binary(Op::Mul, r, g_.binary(Op::Mul, r, id, t[0]), id));
      case Builtin::Det: {
        // d det A = Σ_k det(A with column k replaced by dA's): no inverse,
        // so it stays finite for a singular A.
        const ExprId a = x(0), da = t[0];
        const ExprId a0 = column(a, 0), a1 = column(a, 1), a2 = column(a, 2);
        auto triple = [&](ExprId u, ExprId v, ExprId w) {
          return g_.call(Builtin::Dot, Type::Real,
                         {u, g_.call(Builtin::Cross, Type::Vec3, {v, w})});
        };
        return add(add(triple(column(da, 0), a1, a2), triple(a0, column(da, 1), a2)),
                   triple(a0, a1, column(da, 2)));
      }
      default:
        // stop_gradient, identity, int: constant. rotation and the
        // eigen-solvers are refused by plan_derivative.
        return kNoExpr;
    }
  }

  ir::Graph& g_;
  const ir::Body& body_;
  Seed seed_;
  Given given_;
  std::vector<ExprId> let_;
  std::map<ExprId, ExprId> memo_;
};

/// `out` says why force `i` has no derivative: names the first state read
/// through which it fails (a block the rule could give) in the remedy.
void name_missing_block(const ir::Body& body, const KernelPlan& kernel, std::size_t i,
                        const Given& given, DerivativePlan& out) {
  const ir::Force& f = body.forces[i];
  for (std::size_t s = 0; s < kernel.slots.size(); ++s) {
    const SlotUse& slot = kernel.slots[s];
    if (!slot.vertex || !slot.hops.empty()) continue;
    for (const bool velocity : {false, true}) {
      if (given.count({static_cast<int>(s), velocity})) continue;
      DerivativePlan one;
      Activity activity(body, one, [&](const Node& n) {
        return n.place.slot == static_cast<int>(s) && (n.op == Op::Velocity) == velocity;
      });
      activity.active(f.value);
      // Only a built-in without a derivative can be replaced by given blocks
      // (a fold also reads vertices outside the match).
      if (one.why.empty() || one.why.front() != '\'') continue;
      out.why += ", or give the Jacobian blocks it enters (the first missing: 'jacobian " +
                 body.nodes[static_cast<std::size_t>(f.node)] + "." + f.embedding + " by " +
                 kernel.nodes[static_cast<std::size_t>(slot.node)] +
                 (velocity ? ".velocity" : ".position") + " = <mat3>;')";
      return;
    }
  }
}

}  // namespace

int DerivativePlan::vertex_of_slot(int slot) const {
  return static_cast<int>(std::find(vertex_slots.begin(), vertex_slots.end(), slot) -
                          vertex_slots.begin());
}

DerivativePlan plan_derivative(const ir::Body& body, const KernelPlan& kernel,
                               const diag::Location& declared) {
  DerivativePlan out;
  for (std::size_t s = 0; s < kernel.slots.size(); ++s)
    if (kernel.slots[s].vertex) out.vertex_slots.push_back(static_cast<int>(s));
  {
    // Whether the body reads positions (velocities) at all: which tangent
    // passes the Jacobian has. Every let counts, as every force.
    DerivativePlan flags;
    Activity activity(body, flags, [](const Node&) { return true; });
    for (const ir::Let& l : body.lets)
      activity.active(l.value);
    for (const ir::Force& f : body.forces)
      activity.active(f.value);
    out.depends_on_x = flags.depends_on_x;
    out.depends_on_v = flags.depends_on_v;
  }
  // Per force: is every tangent it needs formed, along every position and
  // velocity but those of the blocks the rule gives?
  for (std::size_t i = 0; i < body.forces.size() && out.why.empty(); ++i) {
    const Given given = given_blocks(body, i);
    Activity activity(body, out, [&given](const Node& n) { return !is_given(given, n); });
    activity.active(body.forces[i].value);
    if (!out.why.empty()) name_missing_block(body, kernel, i, given, out);
  }
  for (const ir::JacobianBlock& j : body.jacobians)
    (j.velocity ? out.depends_on_v : out.depends_on_x) = true;
  out.available = out.why.empty() && !out.vertex_slots.empty();
  if (out.why.empty() && out.vertex_slots.empty()) {
    out.where = declared;
    out.why = "the interaction reads no vertex";
  }
  return out;
}

DifferentiatedBody differentiate(const ir::Body& body, const std::vector<Seed>& seeds) {
  DifferentiatedBody out;
  out.body = body;
  for (const Seed& seed : seeds) {
    // One tangent builder per set of given blocks (forces without any share
    // the first, whose let tangents the renderer names).
    std::map<Given, Tangents> by_given;
    by_given.try_emplace(Given{}, out.body.graph, body, seed);
    TangentPass pass;
    pass.seed = seed;
    for (std::size_t i = 0; i < body.lets.size(); ++i)
      pass.lets.push_back(by_given.at(Given{}).of_let(i));
    std::set<std::pair<int, std::string>> added;  // forces whose given blocks are in
    for (std::size_t i = 0; i < body.forces.size(); ++i) {
      const ir::Force& f = body.forces[i];
      Given given = given_blocks(body, i, seed);
      auto it = by_given.try_emplace(given, out.body.graph, body, seed, given).first;
      ExprId t = it->second.of(f.value);
      // The given blocks times the directions, once per stored force.
      if (added.emplace(f.node, f.embedding).second) {
        for (const ir::JacobianBlock& j : body.jacobians) {
          if (j.node != f.node || j.embedding != f.embedding || (j.velocity ? !seed.v : !seed.x))
            continue;
          Node leaf;
          leaf.op = j.velocity ? Op::VelocityTangent : Op::PositionTangent;
          leaf.type = Type::Vec3;
          leaf.place.node = j.by_node;
          leaf.place.slot = j.by_slot;
          const ExprId d = out.body.graph.add(std::move(leaf));
          const ExprId term = out.body.graph.binary(Op::Mul, Type::Vec3, j.value, d);
          t = t == kNoExpr ? term : out.body.graph.binary(Op::Add, Type::Vec3, t, term);
        }
      }
      pass.forces.push_back(t);
    }
    out.passes.push_back(std::move(pass));
  }
  // The primal and the tangents as one graph: equal values become one node,
  // whether the forces or a tangent wrote them first.
  std::vector<ExprId*> roots;
  for (TangentPass& p : out.passes) {
    for (ExprId& l : p.lets)
      if (l != kNoExpr) roots.push_back(&l);
    for (ExprId& f : p.forces)
      if (f != kNoExpr) roots.push_back(&f);
  }
  share_common_subexpressions(out.body, roots);
  return out;
}

}  // namespace rift::lower
