// The typed expression IR: what every expression of a checked program is
// lowered to. The checks have decided everything by then (types, the overload
// of each built-in, int-to-real promotions, what each name refers to), and the
// IR writes those decisions down as nodes, so that later passes transform it
// without re-deciding anything and `emit/` only renders it.
//
// A Graph is an arena of nodes addressed by ExprId; a node refers to its
// operands by id, so a pass may share a sub-expression (a DAG) and append new
// nodes (a derivative, a simplification) next to the ones it reads. Nodes are
// immutable once added: a transformation builds new nodes. Lets are not
// inlined: a `Let` node names the value of a let of the enclosing Body
// (ir/body.hpp), which keeps the rendered code readable and lets a
// differentiating pass apply the chain rule once per let.
//
// Conventions a pass can rely on:
//  - every node has a concrete type (never Error);
//  - operands of arithmetic are already of the types the operation takes:
//    int operands next to a real are wrapped in ToReal, and so are the
//    arguments of a built-in call whose chosen overload takes real;
//  - Add/Sub take two operands of the node's type (real, int, vec3, mat3);
//    Mul and Div take (scalar, T), (T, scalar) or (mat3, vec3|mat3);
//  - comparisons and logic produce bool;
//  - a Literal of type vec3 or mat3 is the zero vector or matrix (derivative
//    passes need it; the language has no such literal).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "ast/type.hpp"
#include "diag/location.hpp"

namespace rift::ir {

using Type = ast::Type;  // Real, Int, Bool, Vec3, Mat3 (never Error in the IR)

/// Index of a node in its Graph.
using ExprId = std::int32_t;
inline constexpr ExprId kNoExpr = -1;

enum class Op : std::uint8_t {
  // ---- leaves
  Literal,    // real / integer / boolean by type; vec3 and mat3: zero
  Position,   // position of a pattern vertex (force loop: the integrator's stage x), `place`
  Velocity,   // velocity of a pattern vertex (force loop: the stage v), `place`
  Read,       // any other embedding at a dart, `place` and `embedding`
  Param,      // a parameter given by the scene or the caller: `name`
  PackParam,  // a constant of the pack: `name`
  Let,        // the value of let `index` of the enclosing body
  // ---- leaves of derivative passes (lower/derivative.hpp), never lowered from the language
  PositionTangent,  // the direction the position of the vertex at `place` moves in
  VelocityTangent,  // the direction the velocity of the vertex at `place` moves in
  // ---- arithmetic and logic
  Neg,     // -a            (real, int, vec3, mat3)
  Not,     // not a
  ToReal,  // int -> real, where the checks promoted
  Add,
  Sub,
  Mul,
  Div,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  And,
  Or,
  Cond,   // if a then b else c (b and c already of the node's type)
  Index,  // a[i] of a vec3, a[i, j] of a mat3 (indices int)
  Call,   // built-in `fn`, operands converted to its chosen overload
  // ---- over the map (never in a force loop)
  // `op` of operand 0 for each sub-orbit `orbit` (dart variable `var`) in
  // `outer` of `place`. The language's one aggregation: its short form
  // `sum E over <o>(d)` is the fold of `x.E` over the sub-orbits <e ∩ o> of
  // <o>(d), e the orbit E is attached to (lower/expr_lower.cpp).
  Fold,
};

/// The built-in functions, one per name of the language (check/builtins.cpp).
enum class Builtin : std::uint8_t {
  Sqrt,
  Exp,
  Log,
  Sin,
  Cos,
  Tan,
  Acos,
  Asin,
  Atan,
  Atan2,
  Pow,
  Abs,
  Min,
  Max,
  Clamp,
  Real,
  Int,
  Vec3,
  Mat3,
  Identity,
  Dot,
  Cross,
  Norm,
  Normalize,
  Outer,
  Transpose,
  Inverse,
  Det,
  Trace,
  Rotation,
  MaxEigenvalue,
  MaxEigenvector,
  Eigenvalues,
  StopGradient,  // its operand's value, held constant by differentiation
};

/// Aggregations of a Fold.
enum class Aggregate : std::uint8_t { Sum, Mean, Min, Max, Count };

/// A dart a read starts from: `node@hops...`, with `node` an index into the
/// node names of the enclosing body (pattern nodes, then fold variables).
struct Place {
  int node = 0;
  std::vector<int> hops;
  /// The slot a force kernel caches for this read (lower/kernel_plan.hpp),
  /// -1 where reads go through the map. For Position and Velocity in a
  /// force loop it indexes ForceInput::x, ::v and the force array.
  int slot = -1;
};

struct Node {
  Op op = Op::Literal;
  Type type = Type::Real;
  ExprId a = kNoExpr, b = kNoExpr, c = kNoExpr;  // operands, in order
  std::vector<ExprId> more;                      // operands past the third (Call: mat3 of nine)
  // Literal
  double real = 0;
  std::int64_t integer = 0;
  bool boolean = false;
  // Call
  Builtin fn = Builtin::Sqrt;
  // Position, Velocity, Read, Fold
  Place place;
  std::string embedding;  // Read
  // Param, PackParam: the name as written; Let: its name, for rendering
  std::string name;
  int index = -1;  // Let: index into Body::lets
  // Fold
  Aggregate aggregate = Aggregate::Sum;
  std::vector<int> orbit;  // the sub-orbit
  std::vector<int> outer;  // the orbit walked
  int var = -1;            // the node index its dart variable takes
  diag::Location loc;      // where the expression is written
  /// What the source calls this value, when it is the value of a function's
  /// let inlined at a call (`spring_force_d`): the renderer names the local
  /// it computes the value into so. Not part of what the node computes
  /// (sharing ignores it), and not carried to derived nodes.
  std::string value_name;

  /// Number of operands (0..3 + more.size()).
  std::size_t arity() const;
  /// Operand k, k < arity().
  ExprId operand(std::size_t k) const;
};

/// An arena of nodes. Ids stay valid as nodes are added.
class Graph {
 public:
  ExprId add(Node n);
  const Node& operator[](ExprId id) const { return nodes_[static_cast<std::size_t>(id)]; }
  std::size_t size() const { return nodes_.size(); }

  // Builders for the common cases; each returns the new node's id.
  ExprId real(double v);
  ExprId integer(std::int64_t v);
  ExprId boolean(bool v);
  ExprId unary(Op op, Type type, ExprId a);
  ExprId binary(Op op, Type type, ExprId a, ExprId b);
  ExprId call(Builtin fn, Type type, std::vector<ExprId> args, diag::Location loc = {});

 private:
  std::vector<Node> nodes_;
};

/// Calls f(node) on `root` and every node below it, operands before the
/// node that uses them (a node shared in a DAG is visited once per use).
template <class F>
void visit(const Graph& g, ExprId root, F&& f) {
  const Node& n = g[root];
  for (std::size_t k = 0; k < n.arity(); ++k)
    visit(g, n.operand(k), f);
  f(n);
}

/// For each node of `g`, how many times it is referenced from `roots` (each
/// root once) and as an operand of the distinct nodes reachable from them: a
/// node used more than once is worth computing once.
std::vector<int> count_uses(const Graph& g, const std::vector<ExprId>& roots);

/// The language's name of a built-in ("max_eigenvalue"), and back (false when unknown).
std::string_view builtin_name(Builtin fn);
bool builtin_from_name(std::string_view name, Builtin& out);
std::string_view aggregate_name(Aggregate a);
bool aggregate_from_name(std::string_view name, Aggregate& out);
/// The operator as the language writes it ("+", "<=", "and"), or the node's kind.
std::string_view op_name(Op op);

/// The expression in the language's own syntax, fully parenthesised, with
/// `node_names` naming the darts of places (tests, debugging).
std::string to_text(const Graph& g, ExprId id, const std::vector<std::string>& node_names);

}  // namespace rift::ir
