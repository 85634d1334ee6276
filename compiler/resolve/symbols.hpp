// The pack-level names of a program: embeddings, parameters, rules,
// interactions and criteria share one namespace.
#pragma once

#include <map>
#include <string>
#include <unordered_map>

#include "ast/program.hpp"
#include "diag/diagnostics.hpp"

namespace rift::resolve {

/// What a bare name (one of let, param, pack_param) or an embedding read or
/// collection (embedding) of an expression refers to, and the function a call
/// of a `def` calls (function).
struct Binding {
  const ast::Let* let = nullptr;
  const ast::Param* param = nullptr;
  const ast::PackParam* pack_param = nullptr;
  const ast::Embedding* embedding = nullptr;
  /// A Call: the `def` it calls (nullptr for a built-in). A Name: the
  /// function whose parameter or let it is (nullptr outside functions).
  const ast::Function* function = nullptr;
};

struct Symbols {
  std::map<std::string, const ast::Embedding*, std::less<>> embeddings;
  std::map<std::string, const ast::PackParam*, std::less<>> params;
  std::map<std::string, const ast::Rule*, std::less<>> rules;
  std::map<std::string, const ast::Interaction*, std::less<>> interactions;
  std::map<std::string, const ast::Criterion*, std::less<>> criteria;
  std::map<std::string, const ast::Script*, std::less<>> scripts;
  std::map<std::string, const ast::Function*, std::less<>> functions;

  const ast::Embedding* embedding(std::string_view name) const;
  const ast::PackParam* param(std::string_view name) const;
  const ast::Rule* rule(std::string_view name) const;
  const ast::Script* script(std::string_view name) const;
  const ast::Function* function(std::string_view name) const;
  /// The parameters of the rule or script `name`, or nullptr when there is none.
  const std::vector<ast::Param>* callee_params(std::string_view name) const;

  /// The embedding each assignment (right-node expression, update, force,
  /// script `set`) and each init writes, as resolve_names bound it: a side
  /// table, so that the AST stays as the parser built it. nullptr when the
  /// name is unknown (reported by resolve_names).
  const ast::Embedding* target(const ast::Assign& assign) const;
  const ast::Embedding* target(const ast::Init& init) const;
  std::unordered_map<const ast::Assign*, const ast::Embedding*> assign_targets;
  std::unordered_map<const ast::Init*, const ast::Embedding*> init_targets;

  /// What each name and each embedding read of an expression refers to, as
  /// resolve_names bound it (all null when it did not resolve).
  const Binding& binding(const ast::Expr& e) const;
  std::unordered_map<const ast::Expr*, Binding> bindings;

  /// How many calls name each function (for -Wunused-function).
  std::unordered_map<const ast::Function*, int> calls;

  /// How many names read each let and each parameter (for -Wunused-variable
  /// and -Wunused-parameter), counted by resolve_names here rather than in
  /// the AST; a duplicate declaration counts as used, being reported already.
  int uses(const ast::Let& let) const;
  int uses(const ast::Param& param) const;
  std::unordered_map<const ast::Let*, int> let_uses;
  std::unordered_map<const ast::Param*, int> param_uses;
};

/// Collects every declaration; a name declared twice is an error with a note
/// at the first declaration.
Symbols collect_symbols(const ast::Program& program, diag::Diagnostics& diags);

}  // namespace rift::resolve
