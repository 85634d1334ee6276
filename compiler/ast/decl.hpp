// Declarations of a pack: what one .rules file (and its includes) says.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ast/expr.hpp"

namespace rift::ast {

struct NodeDecl {
  Ident name;
  Label label;
};

/// a -dim- b; a loop when a and b are the same name.
struct Arc {
  Ident a;
  Ident b;
  int dim = 0;
  Location dim_loc;
  Location loc;
};

/// node.embedding = value (right-node expressions, updates, forces).
struct Assign {
  Ident node;
  Ident embedding;
  ExprPtr value;
  Location loc;
};

struct Pattern {
  bool present = false;
  Location loc;  // the `left` / `right` / `pattern` keyword
  std::vector<NodeDecl> nodes;
  std::vector<Arc> arcs;
  std::vector<Assign> assigns;  // only meaningful on the right
};

/// One `let` or `when` of a body, in the order the file writes them: a guard
/// runs before the lets that follow it (`when n > 0; let q = 1 / n;`).
struct BodyStmt {
  enum class Kind { Let, When };
  Kind kind = Kind::Let;
  std::size_t index = 0;  // into the body's `lets` or `whens`
};

/// A parameter of a rule (given by its caller) or of an interaction or a
/// criterion (given by the scene: default, bound and description allowed).
struct Param {
  enum class Bound { None, Positive, NonNegative };
  Ident name;
  Type type = Type::Error;
  Location type_loc;
  ExprPtr default_value;  // interaction and criterion parameters only
  Bound bound = Bound::None;
  Location bound_loc;
  std::string description;
};

struct Rule {
  Ident name;
  std::vector<Param> params;
  std::vector<Ident> hooks;
  Location hook_loc;
  Pattern left;
  Pattern right;
  std::vector<Let> lets;
  std::vector<ExprPtr> whens;
  std::vector<BodyStmt> body;  // lets and whens in source order
  std::vector<Assign> updates;
};

struct Init {
  Ident embedding;
  Ident dart;
  ExprPtr value;
  Location loc;
};

/// `jacobian a.f by b.position = value;` (or `by b.velocity`): the rule gives
/// the 3×3 block ∂(force f at node a)/∂(position or velocity of node b)
/// itself; riftc uses it in place of deriving that block (docs/language.md,
/// "Derivatives").
struct JacobianBlock {
  Ident force_node;
  Ident force;
  Ident by_node;
  Ident by_state;  // "position" or "velocity"
  ExprPtr value;   // a mat3
  Location loc;
};

struct Interaction {
  Ident name;
  std::string description;  // the `///` comment above it
  Label support;
  bool tagged = false;  // `tagged`: matches start from the dart tagged at initialisation (§3.2)
  Location tagged_loc;
  std::vector<Param> params;  // given by the scene
  std::vector<Init> inits;    // run once per match of the pattern, at initialisation
  Pattern pattern;
  std::vector<Let> lets;
  std::vector<ExprPtr> whens;
  std::vector<BodyStmt> body;  // lets and whens in source order
  std::vector<Assign> forces;
  /// `store n.E = value;`: a value of the force pass (an element's stress)
  /// written into E at n's orbit on the evaluation whose forces are stored,
  /// for criteria to read; it adds nothing to any force.
  std::vector<Assign> stores;
  /// `store v.E += value;`: E is on the vertex orbit of a node the
  /// interaction exerts a force on; zeroed before the evaluation whose
  /// forces are stored and added to by every match there, in the coloured
  /// order of the forces' scatter (per-vertex sums for criteria).
  std::vector<Assign> accumulations;
  std::vector<JacobianBlock> jacobians;  // blocks the rule gives explicitly
  ExprPtr energy;
  /// `semidefinite;`: the rule's author states that -∂f/∂x and -∂f/∂v of
  /// every match are positive semidefinite at every state (with the
  /// stop_gradient values held constant), so the implicit solver need not
  /// test or project its element matrices (docs/language.md).
  bool semidefinite = false;
  Location semidefinite_loc;
};

struct ApplyArg {
  Ident name;
  ExprPtr value;
};

/// `node NAME = FROM@i@j...;` of a criterion: a pattern node, the dart that
/// path reaches from the criterion's dart or an earlier node. The criterion
/// holds only where every link the path crosses is sewn and the nodes are
/// pairwise distinct darts (an injective match, as Jerboa's).
struct CriterionNode {
  Ident name;
  Ident from;
  std::vector<int> hops;
  Location path_loc;  // the whole path `FROM@i@j`
};

struct Criterion {
  Ident name;
  std::string description;  // the `///` comment above it
  Label orbit;
  Ident dart;
  std::vector<Param> params;         // given by the scene
  std::vector<CriterionNode> nodes;  // in source order, before every let
  std::vector<Let> lets;
  ExprPtr measure;  // a comparison: measure OP threshold
  bool has_apply = false;
  Ident rule;
  std::vector<Ident> apply_hooks;
  std::vector<ApplyArg> apply_args;
  Location apply_loc;
};

/// `for each <sub>(var) in <outer>(dart)`: one dart per sub-orbit <sub>
/// inside the orbit <outer> of a dart (the sub-orbits of a script, §4.3).
struct Each {
  bool present = false;
  Label sub;
  Ident var;
  Label outer;
  ExprPtr dart;  // a Read without an embedding: node@hops
  Location loc;
};

/// A statement of a script, run in order on the current map.
struct ScriptStmt {
  enum class Kind { Let, Set, Apply };
  Kind kind = Kind::Let;
  Location loc;
  std::size_t let = 0;         // Let: index in Script::lets
  Assign set;                  // Set: var.embedding = value
  Ident rule;                  // Apply: the rule (or earlier script) applied
  std::vector<ExprPtr> hooks;  // Apply: dart paths, one per hook
  std::vector<ApplyArg> args;  // Apply: its parameters, by name
  Each each;                   // Set, Apply: repeated once per sub-orbit
  ExprPtr where;               // Set, Apply: skipped where false
};

/// Jerboa's scripts: rules (and earlier scripts) applied in sequence, possibly
/// at every sub-orbit of an orbit, with embeddings set in between.
struct Script {
  Ident name;
  std::string description;  // the `///` comment above it
  std::vector<Param> params;
  std::vector<Ident> hooks;  // the darts a caller gives
  std::vector<Let> lets;
  std::vector<ScriptStmt> stmts;
};

/// `def NAME(PARAMS) -> TYPE { let ...; return VALUE; }`: a pure function of
/// its parameters (and the pack's `param`s), which reads no embedding and no
/// dart. Calls are inlined by lower/ (expr_lower.cpp), so every pass after it
/// sees the function's expressions as if written at the call.
struct Function {
  Ident name;
  std::vector<Param> params;
  Type result = Type::Error;
  Location result_loc;
  std::vector<Let> lets;  // in source order; each sees the ones before it
  ExprPtr value;          // what `return` gives
};

struct Embedding {
  Ident name;
  Type type = Type::Error;
  Location type_loc;
  Label orbit;
  ExprPtr default_value;
  std::optional<Ident> merge;
};

struct PackParam {
  Ident name;
  Type type = Type::Error;
  Location type_loc;
  ExprPtr value;
};

/// `include "f.rules";` reads f's declarations into this pack (a header:
/// common2d.rules, laws.rules). `import "f.rules";` (import = true) makes the
/// declarations of pack f visible while f keeps them: its rules, scripts,
/// interactions, criteria and inits are generated and registered by f's own
/// pack, and this pack calls f's generated code.
struct Include {
  std::string path;
  Location loc;
  bool import = false;
};

/// One parsed file.
struct File {
  int file_id = -1;
  /// The simulator's state embeddings, which rift declares in every pack
  /// (parse/state_embeddings.hpp); the pack's own files are not builtin.
  bool builtin = false;
  bool included = false;  // read through an `include`, not named to riftc
  /// The imported pack that owns this file's rules, scripts, interactions,
  /// criteria and inits (its pack header's name); empty for the pack riftc
  /// compiles. A file an imported pack includes belongs to that pack.
  std::string owner;
  bool has_header = false;
  Ident pack;
  std::string description;  // the `///` comment above the header
  int dimension = 2;
  Location dimension_loc;
  std::vector<Include> includes;
  std::vector<Embedding> embeddings;
  std::vector<PackParam> params;
  std::vector<Init> inits;
  std::vector<Rule> rules;
  std::vector<Script> scripts;
  std::vector<Function> functions;
  std::vector<Interaction> interactions;
  std::vector<Criterion> criteria;
};

/// A pack of functions only: a library, which reads no G-map (so any
/// dimension may include it) and need not call what it declares.
inline bool declares_only_functions(const File& f) {
  return !f.functions.empty() && f.embeddings.empty() && f.params.empty() && f.inits.empty() &&
         f.rules.empty() && f.scripts.empty() && f.interactions.empty() && f.criteria.empty();
}

}  // namespace rift::ast
