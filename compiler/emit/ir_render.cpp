#include "emit/ir_render.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "emit/lanes.hpp"
#include "emit/names.hpp"

namespace rift::emit {

namespace {

using ir::ExprId;
using ir::Node;
using ir::Op;
using ir::Type;

/// The deepest fold whose variable a node reads (0: none).
int level_of(std::uint32_t fold_vars) {
  int level = 0;
  for (int d = 1; d < 32; ++d) {
    if ((fold_vars >> d) & 1U) level = d;
  }
  return level;
}

/// Whether `root` reads the dart of the fold variable `var` (a fold that
/// counts does not need to: `count of true for each ...`).
bool reads_dart(const ir::Graph& g, ExprId root, int var) {
  bool reads = false;
  ir::visit(g, root, [&](const Node& n) {
    const bool placed =
        n.op == Op::Position || n.op == Op::Velocity || n.op == Op::Read || n.op == Op::Fold;
    reads = reads || (placed && n.place.node == var);
  });
  return reads;
}

const ir::Sharing& no_sharing() {
  static const ir::Sharing kNone;
  return kNone;
}

}  // namespace

std::string real_literal(double v) {
  if (std::isinf(v)) {
    return v > 0 ? "std::numeric_limits<rift::Real>::infinity()"
                 : "(-std::numeric_limits<rift::Real>::infinity())";
  }
  // The shortest decimal that reads back as the same double: 0.1, not 0.10000000000000001.
  char buf[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string render(const ir::Graph& g, ir::ExprId id, const RenderContext& ctx) {
  return BodyRenderer(g, no_sharing(), ctx, {id}).expr(id);
}

BodyRenderer::BodyRenderer(const ir::Graph& g, const ir::Sharing& sharing, const RenderContext& ctx,
                           const std::vector<ir::ExprId>& roots)
    : g_(g), sharing_(sharing), ctx_(ctx) {
  blocks_.emplace_back();
  if (ctx_.memos && !sharing_.fold_vars.empty()) {
    for (std::size_t m = 0; m < ctx_.memos->size(); ++m) {
      const std::vector<ExprId>& values = (*ctx_.memos)[m].values;
      for (std::size_t k = 0; k < values.size(); ++k)
        memo_of_.emplace(values[k], std::make_pair(m, k));
    }
  }
  segment(roots);
}

void BodyRenderer::segment(const std::vector<ExprId>& roots) {
  uses_.clear();
  groups_.clear();
  group_index_.clear();
  if (sharing_.fold_vars.empty()) return;
  uses_ = ir::count_uses(g_, roots);
  // Statement-level folds over the same sub-orbits of the same dart, each
  // computable ahead of where it is written: one walk for all.
  std::map<std::string, std::vector<ExprId>> by_walk;
  for (std::size_t i = 0; i < uses_.size(); ++i) {
    const Node& n = g_[static_cast<ExprId>(i)];
    if (uses_[i] == 0 || n.op != Op::Fold || sharing_.fold_vars[i] != 0 || !sharing_.speculable[i])
      continue;
    if (known(static_cast<ExprId>(i), 0)) continue;
    std::string key = std::to_string(n.place.node) + "@";
    for (int h : n.place.hops)
      key += std::to_string(h) + ",";
    key += orbit_code(n.outer) + orbit_code(n.orbit) + std::to_string(n.var);
    by_walk[key].push_back(static_cast<ExprId>(i));
  }
  for (auto& [key, group] : by_walk) {
    if (group.size() < 2) continue;
    for (ExprId id : group)
      group_index_[id] = groups_.size();
    groups_.push_back(std::move(group));
  }
}

const std::vector<ExprId>* BodyRenderer::group_of(ExprId id) const {
  const auto it = group_index_.find(id);
  return it == group_index_.end() ? nullptr : &groups_[it->second];
}

std::string BodyRenderer::expr(ExprId root) {
  // The root itself is the statement's value: only its operands are named.
  if (const std::string* name = known(root, 0)) return *name;
  if (const std::vector<ExprId>* group = group_of(root)) {
    fused(*group);
    return *known(root, 0);
  }
  return node(root);
}

std::vector<std::string> BodyRenderer::take_locals() {
  return std::exchange(locals_, {});
}

void BodyRenderer::computed(ExprId id, const std::string& name) {
  blocks_.back().emplace(id, name);
}

void BodyRenderer::precompute(ExprId id) {
  const auto i = static_cast<std::size_t>(id);
  if (known(id, 0) || cheap(g_[id])) return;
  if (i < sharing_.fold_vars.size() && (sharing_.fold_vars[i] != 0 || !sharing_.speculable[i]))
    return;
  const std::string code = expr(id);
  if (known(id, 0)) return;  // a fold computed by a fused walk
  std::string name = local_name(id);
  locals_.push_back(local_statement(id, name, code));
  blocks_.back().emplace(id, name);
}

std::string BodyRenderer::value_type(Type t) const {
  return ctx_.lanes ? lanes_type(t) : cpp_type(t);
}

std::string BodyRenderer::local_statement(ExprId id, const std::string& name,
                                          const std::string& code) {
  // A lanes body's uniform values (a parameter, a literal) become lane values
  // where they are named.
  const std::string value = ctx_.lanes ? std::string("rift::lanes::as_lanes(") + code + ")" : code;
  return std::string("const ") + value_type(g_[id].type) + " " + name + " = " + value + ";";
}

std::string BodyRenderer::local_name(ExprId id) {
  const std::string& given = g_[id].value_name;
  if (given.empty()) return std::string("s") + std::to_string(next_local_++);
  // A function called twice in one body: its lets' values are numbered.
  const int n = ++value_names_[given];
  return n == 1 ? given : given + "_" + std::to_string(n);
}

void BodyRenderer::open_block() {
  blocks_.emplace_back();
}

void BodyRenderer::close_block() {
  blocks_.pop_back();
}

/// Not worth a local: leaves, and what Eigen or the C++ compiler computes
/// for free or nearly (a conversion, a transpose, a sign, a constant index)
/// of such a node.
bool BodyRenderer::cheap(const Node& n) const {
  switch (n.op) {
    case Op::Literal:
    case Op::Param:
    case Op::PackParam:
    case Op::Let:
      return true;
    case Op::Position:
    case Op::Velocity:
    case Op::Read:
      return n.place.hops.empty();
    case Op::PositionTangent:
    case Op::VelocityTangent:
      return true;
    case Op::ToReal:
    case Op::Neg:
      return cheap(g_[n.a]);
    case Op::Index:
      return cheap(g_[n.a]) && g_[n.b].op == Op::Literal &&
             (n.c == ir::kNoExpr || g_[n.c].op == Op::Literal);
    case Op::Call:
      return n.fn == ir::Builtin::Identity ||
             ((n.fn == ir::Builtin::Transpose || n.fn == ir::Builtin::StopGradient) &&
              cheap(g_[n.a]));
    default:
      return false;
  }
}

const std::string* BodyRenderer::known(ExprId id, int level) const {
  if (level > 0) {
    const auto& names = folds_[static_cast<std::size_t>(level - 1)].names;
    const auto it = names.find(id);
    return it == names.end() ? nullptr : &it->second;
  }
  for (auto b = blocks_.rbegin(); b != blocks_.rend(); ++b) {
    const auto it = b->find(id);
    if (it != b->end()) return &it->second;
  }
  return nullptr;
}

std::string BodyRenderer::value(ExprId id) {
  const Node& n = g_[id];
  const auto i = static_cast<std::size_t>(id);
  if (i >= uses_.size() || cheap(n) || !sharing_.speculable[i]) return node(id);
  const int level = level_of(sharing_.fold_vars[i]);
  if (const std::string* name = known(id, level)) return *name;
  if (const auto memo = memo_of_.find(id); memo != memo_of_.end() && level > 0)
    return memoised(id, level, memo->second.first, memo->second.second);
  if (const std::vector<ExprId>* group = level == 0 ? group_of(id) : nullptr) {
    fused(*group);
    return *known(id, 0);
  }
  // Named when computed more than once: used twice, or inside a fold whose
  // variable it does not read (it is then computed once before that fold).
  if (uses_[i] < 2 && level == fold_depth_) return node(id);
  const std::string code = node(id);
  std::string name = local_name(id);
  std::string local = local_statement(id, name, code);
  if (level > 0) {
    FoldScope& scope = folds_[static_cast<std::size_t>(level - 1)];
    scope.locals.push_back(std::move(local));
    scope.names.emplace(id, name);
  } else {
    locals_.push_back(std::move(local));
    blocks_.back().emplace(id, name);
  }
  return name;
}

std::string BodyRenderer::memoised(ExprId id, int level, std::size_t memo, std::size_t k) {
  const auto scope = static_cast<std::size_t>(level - 1);
  // The orbit's entry: found (or numbered) once per iteration of the fold.
  std::string entry;
  if (const auto it = folds_[scope].memo_entries.find(memo);
      it != folds_[scope].memo_entries.end()) {
    entry = it->second;
  } else {
    const ir::OrbitMemo& m = (*ctx_.memos)[memo];
    entry = memo_entry_name(memo);
    folds_[scope].locals.push_back("const std::uint32_t " + entry + " = " + memo_var(memo) +
                                   ".entry(" + ctx_.map + ", " + ctx_.dart(m.var) + ", " +
                                   orbit_code(m.orbit) + ");");
    folds_[scope].memo_entries.emplace(memo, entry);
  }
  const std::string t = cpp_type(g_[id].type);
  const std::string code = node(id);  // may open scopes of its own: folds_ is indexed after
  const std::string name = local_name(id);
  folds_[scope].locals.push_back(
      "const " + t + " " + name + " = " + memo_values_var(memo, k) + ".get(" + memo_var(memo) +
      ", " + entry + ", " + std::to_string(k) + ", [&]() -> " + t + " { return " + code + "; });");
  folds_[scope].names.emplace(id, name);
  return name;
}

std::string BodyRenderer::node(ExprId id) {
  const Node& n = g_[id];
  switch (n.op) {
    case Op::Literal:
      if (n.type == Type::Bool) return n.boolean ? "true" : "false";
      if (n.type == Type::Int)
        return std::string("std::int64_t{") + std::to_string(n.integer) + "}";
      if (ctx_.lanes && n.type == Type::Vec3) return "rift::lanes::Vec3{}";
      if (n.type == Type::Vec3 || n.type == Type::Mat3) return zero_of(n.type);
      return real_literal(n.real);
    case Op::PositionTangent:
    case Op::VelocityTangent:  // only derivative passes have them, and give `read`
    case Op::Position:
    case Op::Velocity:
    case Op::Read:
      if (ctx_.read) return ctx_.read(n);
      return embedding_access(n.embedding) + "[" + place(n.place) + "]";
    case Op::Param:
    case Op::PackParam: {
      const std::string p =
          (n.op == Op::Param ? ctx_.args : ctx_.params) + "." + member_name(n.name);
      // Every vec3 of a lanes body is a lane value: its operators need no other.
      return ctx_.lanes && n.type == Type::Vec3 ? std::string("rift::lanes::Vec3(") + p + ")" : p;
    }
    case Op::Let:
      return let_name(n.name);
    case Op::Neg:
      return std::string("(-") + value(n.a) + ")";
    case Op::Not:
      if (ctx_.lanes) return std::string("(~rift::lanes::as_lanes(") + value(n.a) + "))";
      return std::string("(!") + value(n.a) + ")";
    case Op::ToReal:
      return std::string("static_cast<rift::Real>(") + value(n.a) + ")";
    case Op::Cond: {
      // Operands one statement each: the order names are given in must not
      // depend on the compiler that built riftc.
      const std::string a = value(n.a);
      const std::string b = value(n.b);
      const std::string c = value(n.c);
      if (ctx_.lanes) {
        // Both branches are computed; each lane keeps its own.
        return std::string("rift::lanes::select(rift::lanes::as_lanes(") + a +
               "), rift::lanes::as_lanes(" + b + "), rift::lanes::as_lanes(" + c + "))";
      }
      const std::string t = cpp_type(n.type);
      if (n.type == Type::Vec3 || n.type == Type::Mat3)
        return std::string("(") + a + " ? " + t + "(" + b + ") : " + t + "(" + c + "))";
      return std::string("(") + a + " ? " + b + " : " + c + ")";
    }
    case Op::Index: {
      if (ctx_.lanes)
        return std::string("(") + value(n.a) + ")(" + index(n.b) + ")";  // a vec3's coordinate
      std::string out = std::string("(") + value(n.a) + ")(" + index(n.b);
      if (n.c != ir::kNoExpr) out += std::string(", ") + index(n.c);
      return out + ")";
    }
    case Op::Call:
      return call(n);
    case Op::Fold:
      return fold(n);
    default: {
      const std::string a = value(n.a);
      const std::string b = value(n.b);
      if (ctx_.lanes && (n.op == Op::And || n.op == Op::Or)) {
        // Per lane, both operands computed (no lane may skip the other).
        return std::string("(rift::lanes::as_lanes(") + a + ") " + (n.op == Op::And ? "&" : "|") +
               " rift::lanes::as_lanes(" + b + "))";
      }
      const char* op = n.op == Op::And ? "&&" : n.op == Op::Or ? "||" : nullptr;
      return std::string("(") + a + " " + (op ? std::string(op) : std::string(ir::op_name(n.op))) +
             " " + b + ")";
    }
  }
}

/// A constant index as a plain number: `(h)(0, 2)`.
std::string BodyRenderer::index(ExprId id) {
  const Node& n = g_[id];
  if (n.op == Op::Literal && n.type == Type::Int) return std::to_string(n.integer);
  return value(id);
}

std::string BodyRenderer::place(const ir::Place& p) {
  return render_place(p, ctx_);
}

std::string BodyRenderer::embedding_access(const std::string& name) const {
  return ctx_.readers ? reader_var(name) : embedding_var(name);
}

std::string render_place(const ir::Place& p, const RenderContext& ctx) {
  std::string d = ctx.dart(p.node);
  for (int h : p.hops)
    d = ctx.map + ".alpha(" + d + ", " + std::to_string(h) + ")";
  return d;
}

/// An immediately invoked lambda: one dart per sub-orbit, the body per dart,
/// the values shared inside the body computed at its top.
std::string BodyRenderer::fold(const Node& n) {
  if (std::string short_form = fold_of_embedding(n); !short_form.empty()) return short_form;
  const bool mean = n.aggregate == ir::Aggregate::Mean;
  const bool count = n.aggregate == ir::Aggregate::Count;
  // Folds nest: each gets its own names, so that no inner one shadows another.
  // Named by nesting depth, not by a running count: sibling folds are
  // separate lambdas and may share names, and the names do not depend on
  // the order in which the compiler that built riftc evaluates operands.
  const std::string id = std::to_string(fold_depth_);
  const std::string start = place(n.place);
  const std::string acc = std::string("acc") + id, cnt = std::string("n") + id;
  const std::string t = cpp_type(n.type);
  std::string init = zero_of(n.type);
  if (n.aggregate == ir::Aggregate::Min)
    init = std::string("std::numeric_limits<") + t + ">::max()";
  if (n.aggregate == ir::Aggregate::Max)
    init = std::string("std::numeric_limits<") + t + ">::lowest()";
  ++fold_depth_;
  folds_.emplace_back();
  const std::string body = value(n.a);
  FoldScope scope = std::move(folds_.back());
  folds_.pop_back();
  --fold_depth_;
  std::string step;
  for (const std::string& local : scope.locals)
    step += local + " ";
  if (count) {
    step += std::string("if (") + body + ") ++" + acc + ";";
  } else if (n.aggregate == ir::Aggregate::Min || n.aggregate == ir::Aggregate::Max) {
    step += acc + " = std::" + std::string(ir::aggregate_name(n.aggregate)) + "<" + t + ">(" + acc +
            ", " + body + ");";
  } else {
    step += acc + " += " + body + ";";
  }
  if (mean) step += std::string(" ++") + cnt + ";";
  std::string out = std::string("[&]() { ") + t + " " + acc + " = " + init + ";";
  if (mean) out += std::string(" std::int64_t ") + cnt + " = 0;";
  out += std::string(" for_each_sub_orbit(") + ctx_.map + ", " + start + ", " +
         orbit_code(n.outer) + ", " + orbit_code(n.orbit) + ", [&](rift::Dart " +
         dart_parameter(n.var, {n.a}) + ") { " + step + " });";
  if (mean) {
    out += std::string(" return ") + cnt + " > 0 ? " + t + "(" + acc +
           " / static_cast<rift::Real>(" + cnt + ")) : " + t + "(" + zero_of(n.type) + ");";
  } else {
    out += std::string(" return ") + acc + ";";
  }
  return out + " }()";
}

/// A fold whose body only reads an embedding at its dart, or counts every
/// sub-orbit (the short form `OP E over <o>(d)` lowers to those): one call of
/// the runtime's fold_OP / count_sub_orbits. Empty for any other fold.
std::string BodyRenderer::fold_of_embedding(const Node& n) {
  const Node& body = g_[n.a];
  const std::string walk = place(n.place) + ", " + orbit_code(n.outer) + ", " + orbit_code(n.orbit);
  if (n.aggregate == ir::Aggregate::Count) {
    if (body.op != Op::Literal || body.type != Type::Bool || !body.boolean) return {};
    return std::string("count_sub_orbits(") + ctx_.map + ", " + walk + ")";
  }
  // A mean of integers reads them through their conversion to real.
  const Node& read = body.op == Op::ToReal ? g_[body.a] : body;
  if (ctx_.read || read.op != Op::Read || read.place.node != n.var || !read.place.hops.empty())
    return {};
  if (body.op == Op::ToReal && n.aggregate != ir::Aggregate::Mean) return {};
  return std::string("fold_") + std::string(ir::aggregate_name(n.aggregate)) + "(" + ctx_.map +
         ", " + embedding_access(read.embedding) + ", " + walk + ")";
}

std::string BodyRenderer::dart_parameter(int var, const std::vector<ExprId>& bodies) const {
  for (ExprId body : bodies) {
    if (reads_dart(g_, body, var)) return ctx_.dart(var);
  }
  return std::string("/*") + ctx_.dart(var) + "*/";
}

std::vector<ExprId> BodyRenderer::bodies_of(const std::vector<ExprId>& group) const {
  std::vector<ExprId> bodies;
  bodies.reserve(group.size());
  for (ExprId id : group)
    bodies.push_back(g_[id].a);
  return bodies;
}

void BodyRenderer::fused(const std::vector<ExprId>& group) {
  const Node& first = g_[group[0]];
  const std::string start = place(first.place);
  std::vector<std::string> names;
  names.reserve(group.size());
  for (std::size_t k = 0; k < group.size(); ++k)
    names.push_back(std::string("s") + std::to_string(next_local_++));
  ++fold_depth_;
  folds_.emplace_back();
  std::vector<std::string> bodies;
  bodies.reserve(group.size());
  for (ExprId id : group)
    bodies.push_back(value(g_[id].a));
  FoldScope scope = std::move(folds_.back());
  folds_.pop_back();
  --fold_depth_;
  std::string step;
  for (const std::string& local : scope.locals)
    step += local + " ";
  std::vector<std::string> after;
  for (std::size_t k = 0; k < group.size(); ++k) {
    const Node& n = g_[group[k]];
    const std::string& acc = names[k];
    const std::string t = cpp_type(n.type);
    std::string init = zero_of(n.type);
    if (n.aggregate == ir::Aggregate::Min)
      init = std::string("std::numeric_limits<") + t + ">::max()";
    if (n.aggregate == ir::Aggregate::Max)
      init = std::string("std::numeric_limits<") + t + ">::lowest()";
    locals_.push_back(t + " " + acc + " = " + init + ";");
    if (n.aggregate == ir::Aggregate::Count) {
      step += std::string("if (") + bodies[k] + ") ++" + acc + "; ";
    } else if (n.aggregate == ir::Aggregate::Min || n.aggregate == ir::Aggregate::Max) {
      step += acc + " = std::" + std::string(ir::aggregate_name(n.aggregate)) + "<" + t + ">(" +
              acc + ", " + bodies[k] + "); ";
    } else {
      step += acc + " += " + bodies[k] + "; ";
    }
    if (n.aggregate == ir::Aggregate::Mean) {
      const std::string cnt = acc + "_n";
      locals_.push_back(std::string("std::int64_t ") + cnt + " = 0;");
      step += std::string("++") + cnt + "; ";
      after.push_back(acc + " = " + cnt + " > 0 ? " + t + "(" + acc +
                      " / static_cast<rift::Real>(" + cnt + ")) : " + t + "(" + zero_of(n.type) +
                      ");");
    }
  }
  step.pop_back();
  locals_.push_back("for_each_sub_orbit(" + ctx_.map + ", " + start + ", " +
                    orbit_code(first.outer) + ", " + orbit_code(first.orbit) + ", [&](rift::Dart " +
                    dart_parameter(first.var, bodies_of(group)) + ") { " + step + " });");
  locals_.insert(locals_.end(), after.begin(), after.end());
  for (std::size_t k = 0; k < group.size(); ++k)
    blocks_.back().emplace(group[k], names[k]);
}

std::string BodyRenderer::call(const Node& n) {
  std::vector<std::string> x;
  x.reserve(n.arity());
  for (std::size_t k = 0; k < n.arity(); ++k)
    x.push_back(value(n.operand(k)));
  auto join = [&] {
    std::string out;
    for (std::size_t k = 0; k < x.size(); ++k) {
      if (k) out += ", ";
      out += x[k];
    }
    return out;
  };
  if (ctx_.lanes) return lanes_call(n, x);
  using B = ir::Builtin;
  switch (n.fn) {
    case B::Vec3:
      return std::string("rift::Vec3(") + join() + ")";
    case B::Mat3:
      return std::string("(rift::Mat3() << ") + join() + ").finished()";
    case B::Identity:
      return "rift::Mat3::Identity()";
    case B::StopGradient:
      return x[0];
    case B::Real:
      return std::string("static_cast<rift::Real>(") + x[0] + ")";
    case B::Int:
      return std::string("static_cast<std::int64_t>(") + x[0] + ")";
    case B::Min:
    case B::Max:
    case B::Clamp:
      return std::string("std::") + std::string(ir::builtin_name(n.fn)) + "<" + cpp_type(n.type) +
             ">(" + join() + ")";
    case B::Dot:
      return std::string("(") + x[0] + ").dot(" + x[1] + ")";
    case B::Cross:
      return std::string("(") + x[0] + ").cross(" + x[1] + ")";
    case B::Norm:
      return std::string("(") + x[0] + ").norm()";
    case B::Normalize:
      return std::string("(") + x[0] + ").normalized()";
    case B::Outer:
      return std::string("(") + x[0] + ") * (" + x[1] + ").transpose()";
    case B::Transpose:
      return std::string("(") + x[0] + ").transpose()";
    case B::Inverse:
      return std::string("(") + x[0] + ").inverse()";
    case B::Det:
      return std::string("(") + x[0] + ").determinant()";
    case B::Trace:
      return std::string("(") + x[0] + ").trace()";
    case B::Rotation:
      return std::string("polar_rotation(") + x[0] + ")";
    case B::MaxEigenvalue:
      return std::string("symmetric_max_eigenvalue(") + x[0] + ")";
    case B::MaxEigenvector:
      return std::string("symmetric_max_eigenvector(") + x[0] + ")";
    case B::Eigenvalues:
      return std::string("symmetric_eigenvalues(") + x[0] + ")";
    default:  // abs sqrt exp log sin cos tan acos asin atan atan2 pow
      return std::string("std::") + std::string(ir::builtin_name(n.fn)) + "(" + join() + ")";
  }
}

std::string BodyRenderer::lanes_call(const Node& n, const std::vector<std::string>& x) {
  std::string args;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (k) args += ", ";
    args += std::string("rift::lanes::as_lanes(") + x[k] + ")";
  }
  using B = ir::Builtin;
  switch (n.fn) {
    case B::Vec3:
      return std::string("rift::lanes::Vec3(") + args + ")";
    case B::StopGradient:
    case B::Real:  // of a real: the value itself (renders_in_lanes)
      return x[0];
    case B::Sqrt:
    case B::Abs:
    case B::Min:
    case B::Max:
    case B::Clamp:
    case B::Dot:
    case B::Cross:
    case B::Norm:
      return std::string("rift::lanes::") + std::string(ir::builtin_name(n.fn)) + "(" + args + ")";
    case B::Normalize:
      return std::string("rift::lanes::normalized(") + args + ")";
    default:  // renders_in_lanes admits no other
      throw std::logic_error(std::string("riftc: no lanes form of built-in '") +
                             std::string(ir::builtin_name(n.fn)) + "'");
  }
}

}  // namespace rift::emit
