// Expression trees. One node type with a kind tag keeps the parser actions and
// the passes short; the fields a kind uses are listed next to it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ast/type.hpp"
#include "diag/location.hpp"

namespace rift::ast {

using diag::Location;

/// An orbit label as written: dimensions, with -1 for `_`.
struct Label {
  std::vector<int> dims;
  Location loc;
};

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Ident {
  std::string text;
  Location loc;
};

/// `let name = value;` of a body, a function or a fold.
struct Let {
  Ident name;
  ExprPtr value;
};

struct Expr {
  enum class Kind {
    IntLit,   // integer
    RealLit,  // real
    BoolLit,  // boolean
    Name,     // name
    Call,     // name(args...)
    Unary,    // op args[0]      op: "-", "not"
    Binary,   // args[0] op args[1]
    Cond,     // if args[0] then args[1] else args[2]
    Read,     // node@hops... . name
    Collect,  // op name over <orbit>(node)   op: sum mean min max count
    Index,    // args[0][args[1]] or args[0][args[1], args[2]]
    Fold,  // op of args[0] for each <orbit>(var) in <outer>(node@hops)   op: sum mean min max count
  };

  Kind kind = Kind::IntLit;
  Location loc;     // the whole expression
  Location op_loc;  // the operator, function name, `if` or `[`: where operator errors point
  std::int64_t integer = 0;
  double real = 0.0;
  bool boolean = false;
  std::string name;
  std::string op;
  std::string node;
  Location node_loc;
  std::vector<int> hops;
  Label orbit;
  Label outer;      // Fold: the orbit whose sub-orbits are visited
  std::string var;  // Fold: the dart variable bound to each sub-orbit
  Location var_loc;
  std::vector<ExprPtr> args;
  /// Fold: the lets of its body (`sum of { let a = ...; return a * a; } for
  /// each ...`), in order, each seeing the dart variable and the ones before it.
  std::vector<Let> lets;
  int depth = 1;  // of the tree below; the parser caps it so passes may recurse safely
  // What names refer to and the types of expressions are not here: resolve/
  // and check/ record them in side tables (resolve::Symbols::binding,
  // check::ExprTypes), so that no pass writes into the tree.
};

ExprPtr make_expr(Expr::Kind kind, const Location& loc);

}  // namespace rift::ast
