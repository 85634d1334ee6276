#include "lower/expr_lower.hpp"

#include <algorithm>

#include "check/builtins.hpp"
#include "check/kernels.hpp"

namespace rift::lower {

namespace {

using ast::Expr;
using ir::ExprId;
using ir::Op;
using ir::Type;

bool scalar(Type t) {
  return t == Type::Int || t == Type::Real;
}

Op binary_op(const std::string& op) {
  if (op == "+") return Op::Add;
  if (op == "-") return Op::Sub;
  if (op == "*") return Op::Mul;
  if (op == "/") return Op::Div;
  if (op == "<") return Op::Lt;
  if (op == "<=") return Op::Le;
  if (op == ">") return Op::Gt;
  if (op == ">=") return Op::Ge;
  if (op == "==") return Op::Eq;
  if (op == "!=") return Op::Ne;
  if (op == "and") return Op::And;
  return Op::Or;
}

}  // namespace

ExprLowering::ExprLowering(ir::Graph& graph, std::vector<std::string>& nodes,
                           const KernelPlan* kernel, const resolve::Symbols& symbols,
                           const check::ExprTypes& types)
    : g_(graph), nodes_(nodes), kernel_(kernel), symbols_(symbols), types_(types) {}

void ExprLowering::add_let(const ast::Let* let, int index) {
  lets_[let] = index;
}

ExprId ExprLowering::convert(ExprId id, Type to) {
  const ir::Node& n = g_[id];
  if (n.type != Type::Int || to != Type::Real) return id;
  // A literal is converted now, so that `2 * x` renders as `2.0 * x`.
  if (n.op == Op::Literal) {
    ir::Node lit = n;
    lit.type = Type::Real;
    lit.real = static_cast<double>(n.integer);
    return g_.add(std::move(lit));
  }
  ir::Node c;
  c.op = Op::ToReal;
  c.type = Type::Real;
  c.a = id;
  c.loc = n.loc;
  return g_.add(std::move(c));
}

ExprId ExprLowering::lower_as(const Expr& e, Type to) {
  return convert(lower(e), to);
}

int ExprLowering::node_index(const std::string& name) const {
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    if (nodes_[k] == name) return static_cast<int>(k);
  }
  return -1;
}

ir::Place ExprLowering::place(const Expr& e) const {
  ir::Place p;
  p.node = node_index(e.node);
  p.hops = e.hops;
  return p;
}

ExprId ExprLowering::read(const Expr& e) {
  ir::Node n;
  n.loc = e.loc;
  n.type = types_.of(e);
  n.place = place(e);
  n.embedding = e.name;
  n.op = Op::Read;
  if (kernel_) {
    std::vector<int> orbit = symbols_.binding(e).embedding->orbit.dims;
    std::sort(orbit.begin(), orbit.end());
    n.place.slot = kernel_->find(n.place.node, e.hops, orbit);
    if (e.name == check::kPositionEmbedding) n.op = Op::Position;
    if (e.name == check::kVelocityEmbedding) n.op = Op::Velocity;
  }
  return g_.add(std::move(n));
}

ExprId ExprLowering::binary(const Expr& e) {
  const Expr& a = *e.args[0];
  const Expr& b = *e.args[1];
  const Op op = binary_op(e.op);
  // Scalars meet in a common type; next to a vector or matrix they are reals.
  Type ta = types_.of(a), tb = types_.of(b);
  ExprId x, y;
  if (scalar(ta) && scalar(tb)) {
    const Type common = ta == Type::Real || tb == Type::Real ? Type::Real : Type::Int;
    x = lower_as(a, common);
    y = lower_as(b, common);
  } else {
    x = scalar(ta) ? lower_as(a, Type::Real) : lower(a);
    y = scalar(tb) ? lower_as(b, Type::Real) : lower(b);
  }
  return g_.binary(op, types_.of(e), x, y);
}

ExprId ExprLowering::named(ExprId id, ExprId before, const std::string& name) {
  // Only a node this let created takes its name (a let that only renames an
  // argument or an earlier value adds nothing to name).
  const ir::Node& n = g_[id];
  if (id < before || !n.value_name.empty() || n.op == Op::Literal) return id;
  ir::Node copy = n;
  copy.value_name = name;
  return g_.add(std::move(copy));
}

ExprId ExprLowering::inline_call(const Expr& e, const ast::Function& f) {
  Frame frame;
  for (std::size_t k = 0; k < e.args.size(); ++k)
    frame.params[&f.params[k]] = lower_as(*e.args[k], f.params[k].type);
  frames_.push_back(std::move(frame));
  for (const ast::Let& let : f.lets) {
    const auto before = static_cast<ExprId>(g_.size());
    frames_.back().lets[&let] = named(lower(*let.value), before, f.name.text + "_" + let.name.text);
  }
  const ExprId result = lower_as(*f.value, f.result);
  frames_.pop_back();
  return result;
}

ExprId ExprLowering::call(const Expr& e) {
  if (const ast::Function* f = symbols_.binding(e).function) return inline_call(e, *f);
  std::vector<Type> types;
  types.reserve(e.args.size());
  for (const auto& a : e.args)
    types.push_back(types_.of(*a));
  const check::Signature* sig = check::select_overload(*check::builtin(e.name), types);
  std::vector<ExprId> args;
  args.reserve(e.args.size());
  for (std::size_t k = 0; k < e.args.size(); ++k)
    args.push_back(lower_as(*e.args[k], sig->params[k]));
  ir::Builtin fn{};
  ir::builtin_from_name(e.name, fn);
  // real(x) of a real and int(n) of an int are the value itself.
  if ((fn == ir::Builtin::Real || fn == ir::Builtin::Int) && g_[args[0]].type == sig->result) {
    return args[0];
  }
  return g_.call(fn, sig->result, std::move(args), e.loc);
}

ir::Node ExprLowering::fold_node(const Expr& e) const {
  ir::Node n;
  n.op = Op::Fold;
  n.type = types_.of(e);
  n.loc = e.loc;
  n.place = place(e);
  ir::aggregate_from_name(e.op, n.aggregate);
  return n;
}

ExprId ExprLowering::fold(const Expr& e) {
  ir::Node n = fold_node(e);
  n.orbit = e.orbit.dims;
  n.outer = e.outer.dims;
  nodes_.push_back(e.var);
  n.var = static_cast<int>(nodes_.size() - 1);
  // A let of the fold's body is its value's node (inlined, as a function's
  // let is), named after it where the renderer computes it into a local.
  for (const ast::Let& let : e.lets) {
    const auto before = static_cast<ExprId>(g_.size());
    fold_lets_[&let] = named(lower(*let.value), before, "fold_" + let.name.text);
  }
  const Expr& body = *e.args[0];
  n.a = e.op == "count" ? lower(body) : lower_as(body, types_.of(e));
  // The variable stays in `nodes` (its index is taken) but no longer resolves.
  nodes_[static_cast<std::size_t>(n.var)] = e.var;
  return g_.add(std::move(n));
}

/// `OP E over <o>(d)`: the fold of `x.E` over the sub-orbits <e ∩ o> of
/// <o>(d), e the orbit E is attached to. Each sub-orbit is one piece of an
/// E-orbit inside <o>(d), so a value counts once per piece: once per
/// E-orbit, except where <o>(d) meets an E-orbit in several pieces (a face
/// that passes twice through one vertex counts it twice, as its corners).
ExprId ExprLowering::over(const Expr& e) {
  const ast::Embedding& embedding = *symbols_.binding(e).embedding;
  ir::Node n = fold_node(e);
  n.outer = e.orbit.dims;
  for (int d : e.orbit.dims) {
    if (std::find(embedding.orbit.dims.begin(), embedding.orbit.dims.end(), d) !=
        embedding.orbit.dims.end())
      n.orbit.push_back(d);
  }
  // `over` is a keyword: no name of the rules can be this variable's.
  nodes_.emplace_back("over");
  n.var = static_cast<int>(nodes_.size() - 1);
  if (n.aggregate == ir::Aggregate::Count) {
    n.a = g_.boolean(true);
  } else {
    ir::Node value;
    value.op = Op::Read;
    value.type = embedding.type;
    value.loc = e.loc;
    value.place.node = n.var;
    value.embedding = e.name;
    n.a = convert(g_.add(std::move(value)), n.type);
  }
  return g_.add(std::move(n));
}

ExprId ExprLowering::lower(const Expr& e) {
  ExprId id = ir::kNoExpr;
  switch (e.kind) {
    case Expr::Kind::IntLit:
      id = g_.integer(e.integer);
      break;
    case Expr::Kind::RealLit:
      id = g_.real(e.real);
      break;
    case Expr::Kind::BoolLit:
      id = g_.boolean(e.boolean);
      break;
    case Expr::Kind::Name: {
      const resolve::Binding& b = symbols_.binding(e);
      if (const auto it = fold_lets_.find(b.let); b.let && it != fold_lets_.end())
        return it->second;
      if (b.function) {  // a parameter or a let of the function being inlined
        const Frame& frame = frames_.back();
        return b.let ? frame.lets.at(b.let) : frame.params.at(b.param);
      }
      ir::Node n;
      n.type = types_.of(e);
      n.name = e.name;
      if (b.let) {
        n.op = Op::Let;
        const auto it = lets_.find(b.let);
        n.index = it == lets_.end() ? -1 : it->second;
      } else if (b.param) {
        n.op = Op::Param;
      } else {
        n.op = Op::PackParam;
      }
      id = g_.add(std::move(n));
      break;
    }
    case Expr::Kind::Read:
      return read(e);
    case Expr::Kind::Collect:
      return over(e);
    case Expr::Kind::Unary:
      id = g_.unary(e.op == "not" ? Op::Not : Op::Neg, types_.of(e), lower(*e.args[0]));
      break;
    case Expr::Kind::Binary:
      id = binary(e);
      break;
    case Expr::Kind::Cond: {
      ir::Node n;
      n.op = Op::Cond;
      n.type = types_.of(e);
      n.a = lower(*e.args[0]);
      n.b = lower_as(*e.args[1], types_.of(e));
      n.c = lower_as(*e.args[2], types_.of(e));
      id = g_.add(std::move(n));
      break;
    }
    case Expr::Kind::Index: {
      ir::Node n;
      n.op = Op::Index;
      n.type = types_.of(e);
      n.a = lower(*e.args[0]);
      n.b = lower(*e.args[1]);
      if (e.args.size() > 2) n.c = lower(*e.args[2]);
      id = g_.add(std::move(n));
      break;
    }
    case Expr::Kind::Call:
      id = call(e);
      break;
    case Expr::Kind::Fold:
      return fold(e);
  }
  return id;
}

}  // namespace rift::lower
