#include "lower/share.hpp"

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>

namespace rift::lower {

namespace {

using ir::ExprId;
using ir::Node;
using ir::Op;

bool has_place(Op op) {
  return op == Op::Position || op == Op::Velocity || op == Op::Read || op == Op::Fold ||
         op == Op::PositionTangent || op == Op::VelocityTangent;
}

/// Everything that makes two nodes compute the same value, operands by
/// their (already shared) ids; not the source location.
std::string key_of(const Node& n) {
  std::string k;
  auto num = [&k](std::int64_t v) {
    k += std::to_string(v);
    k += ',';
  };
  num(static_cast<int>(n.op));
  num(static_cast<int>(n.type));
  for (std::size_t i = 0; i < n.arity(); ++i)
    num(n.operand(i));
  k += '|';
  std::uint64_t bits = 0;
  std::memcpy(&bits, &n.real, sizeof bits);
  num(static_cast<std::int64_t>(bits));
  num(n.integer);
  num(n.boolean ? 1 : 0);
  num(static_cast<int>(n.fn));
  num(n.place.node);
  num(n.place.slot);
  k += '@';
  for (int h : n.place.hops)
    num(h);
  k += '|' + n.embedding + '|' + n.name + '|';
  num(n.index);
  num(static_cast<int>(n.aggregate));
  k += '<';
  for (int d : n.orbit)
    num(d);
  k += '<';
  for (int d : n.outer)
    num(d);
  k += '|';
  num(n.var);
  return k;
}

class Sharer {
 public:
  Sharer(const ir::Graph& old, const std::vector<std::string>& nodes) : old_(old), nodes_(nodes) {}

  ExprId copy(ExprId id) {
    if (id == ir::kNoExpr) return id;
    // Outside folds a node means the same wherever it is used: copy it once
    // (graphs built by passes may share nodes heavily).
    const bool top = enclosing_.empty();
    if (top) {
      const auto it = memo_.find(id);
      if (it != memo_.end()) return it->second;
    }
    Node n = old_[id];
    if (has_place(n.op)) n.place.node = variable(n.place.node);
    if (n.op == Op::Fold) {
      const int depth = static_cast<int>(enclosing_.size()) + 1;
      const auto key = std::make_pair(depth, nodes_[static_cast<std::size_t>(n.var)]);
      const int canonical = canonical_.emplace(key, n.var).first->second;
      depth_of_var_[canonical] = depth;
      enclosing_.emplace_back(n.var, canonical);
      n.a = copy(n.a);
      enclosing_.pop_back();
      n.var = canonical;
    } else {
      // Operands in order: the new ids, and so the names rendered, follow the body.
      n.a = copy(n.a);
      n.b = copy(n.b);
      n.c = copy(n.c);
      for (ExprId& m : n.more)
        m = copy(m);
    }
    const ExprId out = intern(std::move(n));
    if (top) memo_[id] = out;
    return out;
  }

  ir::Graph take_graph() { return std::move(out_); }
  std::vector<std::uint32_t> take_fold_vars() { return std::move(fold_vars_); }
  std::vector<bool> take_speculable() { return std::move(speculable_); }

 private:
  /// A place's dart after renumbering: a fold variable becomes its canonical number.
  int variable(int node) const {
    for (auto it = enclosing_.rbegin(); it != enclosing_.rend(); ++it) {
      if (it->first == node) return it->second;
    }
    return node;
  }

  ExprId intern(Node n) {
    std::string key = key_of(n);
    const auto it = by_key_.find(key);
    if (it != by_key_.end()) return it->second;
    std::uint32_t vars = 0;
    bool speculable = true;
    for (std::size_t k = 0; k < n.arity(); ++k) {
      const auto operand = static_cast<std::size_t>(n.operand(k));
      vars |= fold_vars_[operand];
      speculable = speculable && speculable_[operand];
    }
    if (has_place(n.op)) {
      const auto d = depth_of_var_.find(n.place.node);
      if (d != depth_of_var_.end()) vars |= std::uint32_t{1} << d->second;
    }
    if (n.op == Op::Fold) vars &= ~(std::uint32_t{1} << depth_of_var_.at(n.var));
    // Undefined behaviour if evaluated where the rules would not: a division
    // of integers (by zero), an index computed at run time (out of range).
    if (n.op == Op::Div && n.type == ir::Type::Int) speculable = false;
    if (n.op == Op::Index) {
      for (ExprId i : {n.b, n.c}) {
        if (i != ir::kNoExpr && out_[i].op != Op::Literal) speculable = false;
      }
    }
    const ExprId id = out_.add(std::move(n));
    fold_vars_.push_back(vars);
    speculable_.push_back(speculable);
    by_key_.emplace(std::move(key), id);
    return id;
  }

  const ir::Graph& old_;
  const std::vector<std::string>& nodes_;
  ir::Graph out_;
  std::map<std::string, ExprId> by_key_;
  std::map<ExprId, ExprId> memo_;                         // old id -> new id, outside folds
  std::vector<std::pair<int, int>> enclosing_;            // folds being copied: old var, canonical
  std::map<std::pair<int, std::string>, int> canonical_;  // (depth, name) -> var
  std::map<int, int> depth_of_var_;                       // canonical var -> depth
  std::vector<std::uint32_t> fold_vars_;                  // per new node
  std::vector<bool> speculable_;                          // per new node
};

}  // namespace

void share_common_subexpressions(ir::Body& body, const std::vector<ir::ExprId*>& extra_roots) {
  std::vector<ExprId*> roots;
  for (ir::Stmt& s : body.stmts) {
    if (s.kind == ir::Stmt::Kind::Let) {
      roots.push_back(&body.lets[static_cast<std::size_t>(s.let)].value);
    } else {
      roots.push_back(&s.cond);
    }
  }
  for (ir::Force& f : body.forces)
    roots.push_back(&f.value);
  for (ir::Store& st : body.stores)
    roots.push_back(&st.value);
  roots.push_back(&body.energy);
  for (ir::JacobianBlock& j : body.jacobians)
    roots.push_back(&j.value);
  roots.insert(roots.end(), extra_roots.begin(), extra_roots.end());

  Sharer sharer(body.graph, body.nodes);
  for (ExprId* r : roots)
    *r = sharer.copy(*r);
  body.graph = sharer.take_graph();
  body.sharing.fold_vars = sharer.take_fold_vars();
  body.sharing.speculable = sharer.take_speculable();
}

}  // namespace rift::lower
