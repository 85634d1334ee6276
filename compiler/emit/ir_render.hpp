// Rendering of the expression IR (ir/expr.hpp) as C++ over Eigen fixed-size
// types. Rendering decides nothing: every type, overload and conversion is in
// the IR. Operands are left as Eigen expressions inside one C++ expression
// (they live until its end); a value is materialised where it is named (a
// let, a force, a shared value) and where the two branches of an `if` must
// agree on a type.
//
// A body that went through lower::share_common_subexpressions is rendered by
// a BodyRenderer, which computes each value used more than once (or inside a
// fold that does not change it) into one local `const T sN` (or named after
// the let of an inlined function it is the value of), at the level
// where its inputs exist: before the statement that first needs it, or at
// the top of the fold body whose variable it reads. Folds of the statement
// level over the same sub-orbits of the same dart (a vertex's faces) are
// computed by one walk, whose body computes each shared term once (fusion).
// In a criterion's collect(), a value of one orbit that other cells fold over
// too is read from the criterion's orbit memo (lower/orbit_memo.hpp).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ir/body.hpp"
#include "ir/expr.hpp"

namespace rift::emit {

struct RenderContext {
  /// The C++ expression of a dart place (pattern node or fold variable).
  std::function<std::string(int node)> dart;
  /// Position, Velocity and Read nodes; when empty, reads are `e_NAME[dart]`,
  /// or `r_NAME[dart]` with `readers`.
  std::function<std::string(const ir::Node& read)> read;
  std::string args = "args";      // the declaration's parameters
  std::string params = "params";  // the pack's parameters
  std::string map = "g";          // the rift::GMap
  /// Reads go through the locals reader_var(NAME), the EmbeddingReaders a
  /// pass over an unchanging map takes first (a criterion's collect).
  bool readers = false;
  /// A criterion's collect(): the values it computes once per orbit
  /// (lower/orbit_memo.hpp), read through the members memo_var() and
  /// memo_values_var(). Null elsewhere: nothing is memoised.
  const std::vector<ir::OrbitMemo>* memos = nullptr;
  /// A force kernel's evaluate_lanes (rift/core/lanes.hpp): values of type
  /// real, vec3 and bool are those of kWidth matches at once. Only bodies
  /// renders_in_lanes accepts (emit/lanes.hpp). `read` gives lane values.
  bool lanes = false;
};

/// The expressions of one body rendered into one C++ function, in the order
/// of its statements: a shared value is computed once and then read by name.
class BodyRenderer {
 public:
  /// `roots`: every expression this function will render (how often each
  /// value is used is counted over them). `sharing` may be empty: nothing is
  /// then named.
  BodyRenderer(const ir::Graph& g, const ir::Sharing& sharing, const RenderContext& ctx,
               const std::vector<ir::ExprId>& roots);

  /// The C++ of `root`, for one statement. The locals it reads that are not
  /// computed yet are queued: write them (take_locals) before the statement.
  std::string expr(ir::ExprId root);
  /// `const T sN = ...;` statements queued by expr(), in the order to write them.
  std::vector<std::string> take_locals();
  /// The statement just written computed `id` into the C++ variable `name`
  /// (a let): later statements read it.
  void computed(ir::ExprId id, const std::string& name);
  /// Computes `id` into a statement-level local now (queued, as by expr())
  /// unless it is known or not worth a local: a value every iteration of a
  /// loop written next reads (a Jacobian's primal factors) is computed once.
  void precompute(ir::ExprId id);
  /// A C++ block (`{`, an `if constexpr` branch) opens or closes: what is
  /// computed inside is not visible after it.
  void open_block();
  void close_block();
  /// The statements written from now on render `roots` (how often values
  /// are used, which folds are walked together); what is computed stays known.
  void segment(const std::vector<ir::ExprId>& roots);

 private:
  struct FoldScope {
    std::map<ir::ExprId, std::string> names;
    std::map<std::size_t, std::string> memo_entries;  ///< memo -> local of its orbit's entry
    std::vector<std::string> locals;
  };

  std::string value(ir::ExprId id);
  std::string node(ir::ExprId id);
  std::string index(ir::ExprId id);
  std::string place(const ir::Place& p);
  /// How the body names an embedding it reads (RenderContext::readers).
  std::string embedding_access(const std::string& name) const;
  std::string fold(const ir::Node& n);
  /// A memoised node (`memo`, value `k`), computed into a local of the fold at `level`.
  std::string memoised(ir::ExprId id, int level, std::size_t memo, std::size_t k);
  /// Computes the folds of `group` (one walk) into statement-level locals.
  void fused(const std::vector<ir::ExprId>& group);
  /// A fold of an embedding's values as one runtime call, or empty.
  std::string fold_of_embedding(const ir::Node& n);
  /// The name of a fold's dart parameter, commented out when no body reads it.
  std::string dart_parameter(int var, const std::vector<ir::ExprId>& bodies) const;
  std::vector<ir::ExprId> bodies_of(const std::vector<ir::ExprId>& group) const;
  /// The fold group `id` belongs to, or nullptr when it is walked alone.
  const std::vector<ir::ExprId>* group_of(ir::ExprId id) const;
  std::string call(const ir::Node& n);
  /// call() of a lanes body: rift::lanes' functions, every operand a lane value.
  std::string lanes_call(const ir::Node& n, const std::vector<std::string>& x);
  /// The C++ type of a value of type t (a lane type in a lanes body).
  std::string value_type(ir::Type t) const;
  /// `const T name = code;` for a local computing `id`.
  std::string local_statement(ir::ExprId id, const std::string& name, const std::string& code);
  bool cheap(const ir::Node& n) const;
  const std::string* known(ir::ExprId id, int level) const;
  /// The C++ name of a new local computing `id`: `sN`, or the name of the
  /// function's let it is the value of (ir::Node::value_name).
  std::string local_name(ir::ExprId id);

  const ir::Graph& g_;
  const ir::Sharing& sharing_;
  const RenderContext& ctx_;
  std::vector<int> uses_;  ///< per node, by the roots of the current segment
  std::map<ir::ExprId, std::size_t> group_index_;  ///< statement-level fold -> groups_
  std::vector<std::vector<ir::ExprId>> groups_;    ///< folds walked together, in node order
  int fold_depth_ = 0;                             ///< folds enclosing the node being rendered
  int next_local_ = 0;                             ///< sN: numbered in rendering order
  std::map<std::string, int> value_names_;         ///< locals named after a function's let
  std::vector<std::map<ir::ExprId, std::string>> blocks_;  ///< statement-level names, per block
  std::vector<std::string> locals_;  ///< statement-level locals not yet written
  std::vector<FoldScope> folds_;     ///< one per enclosing fold
  std::map<ir::ExprId, std::pair<std::size_t, std::size_t>> memo_of_;  ///< node -> (memo, k)
};

/// One expression of a body without sharing.
std::string render(const ir::Graph& g, ir::ExprId id, const RenderContext& ctx);

/// The dart a place stands for: `g.alpha(d_a, 1)` for `a@1`.
std::string render_place(const ir::Place& p, const RenderContext& ctx);

/// A real literal as C++ ("0.5", "2.0").
std::string real_literal(double v);

}  // namespace rift::emit
