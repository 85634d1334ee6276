// Bison grammar of the rift rule language (docs/language.md).
// Body statements of rules, interactions and criteria may come in any order:
// their actions write into the declaration held open in ParseContext.

%require "3.8"
%language "c++"
%skeleton "lalr1.cc"
%header
%define api.namespace {rift::grammar}
%define api.parser.class {Parser}
%define api.token.constructor
%define api.value.type variant
%define api.value.automove
%define api.location.type {rift::diag::Location}
%define parse.error detailed
%define parse.assert
%locations

%param {rift::parse::ParseContext& ctx}

%code requires {
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ast/decl.hpp"
#include "diag/location.hpp"
#include "parse/context.hpp"

// Locations carry their file id, which Bison's default rule would drop.
#define YYLLOC_DEFAULT(Current, Rhs, N)                              \
  do {                                                               \
    if (N) {                                                         \
      (Current) = YYRHSLOC(Rhs, 1);                                  \
      (Current).end = YYRHSLOC(Rhs, N).end;                          \
    } else {                                                         \
      (Current) = YYRHSLOC(Rhs, 0);                                  \
      (Current).begin = (Current).end;                               \
    }                                                                \
  } while (false)
}

%code {
#include "parse/lexer.hpp"

namespace rift::grammar {

static Parser::symbol_type yylex(parse::ParseContext& ctx) { return ctx.lexer.next(); }

}  // namespace rift::grammar

namespace {

using rift::ast::Expr;
using rift::ast::ExprPtr;
using rift::ast::make_expr;

/// Records the depth of a new node; past kMaxExprDepth the tree is replaced by
/// a literal and the error is reported (once per file).
ExprPtr deepen(ExprPtr e, rift::parse::ParseContext& ctx) {
  for (const auto& a : e->args) e->depth = std::max(e->depth, a->depth + 1);
  if (e->depth <= rift::parse::kMaxExprDepth) return e;
  if (!ctx.reported_depth) {
    ctx.reported_depth = true;
    ctx.diags.error(e->loc, "expression is nested too deeply (more than " +
                                std::to_string(rift::parse::kMaxExprDepth) + " levels)");
  }
  return make_expr(Expr::Kind::IntLit, e->loc);
}

ExprPtr binary(std::string op, ExprPtr a, ExprPtr b, const rift::diag::Location& loc,
               const rift::diag::Location& op_loc) {
  ExprPtr e = make_expr(Expr::Kind::Binary, loc);
  e->op_loc = op_loc;
  e->op = std::move(op);
  e->args.push_back(std::move(a));
  e->args.push_back(std::move(b));
  return e;
}

ExprPtr unary(std::string op, ExprPtr a, const rift::diag::Location& loc,
              const rift::diag::Location& op_loc) {
  ExprPtr e = make_expr(Expr::Kind::Unary, loc);
  e->op_loc = op_loc;
  e->op = std::move(op);
  e->args.push_back(std::move(a));
  return e;
}

ExprPtr call(std::string name, std::vector<ExprPtr> args, const rift::diag::Location& loc,
             const rift::diag::Location& name_loc) {
  ExprPtr e = make_expr(Expr::Kind::Call, loc);
  e->op_loc = name_loc;
  e->name = std::move(name);
  e->args = std::move(args);
  return e;
}

}  // namespace
}

%token END 0 "end of file"
%token <std::string> IDENT "identifier"
%token <std::int64_t> INT "integer"
%token <double> REAL "real number"
%token <std::string> STRING "string"

%token PACK "pack" DIMENSION "dimension" INCLUDE "include" IMPORT "import" EMBEDDING "embedding" ON "on"
       MERGE "merge" PARAM "param" INIT "init" RULE "rule" HOOK "hook" LEFT "left"
       RIGHT "right" WHEN "when" LET "let" UPDATE "update" INTERACTION "interaction"
       PATTERN "pattern" FORCE "force" ENERGY "energy" SEMIDEFINITE "semidefinite"
       CRITERION "criterion"
       MEASURE "measure" APPLY "apply" AT "at" WITH "with" IF "if" THEN "then" ELSE "else"
       TRUE "true" FALSE "false" OVER "over" SUM "sum" MEAN "mean" COUNT "count" MIN "min"
       MAX "max" T_REAL "real" T_INT "int" T_BOOL "bool" T_VEC3 "vec3" T_MAT3 "mat3"
       AND "and" OR "or" NOT "not" TAGGED "tagged" SCRIPT "script" SET "set" FOR "for"
       EACH "each" IN "in" OF "of" WHERE "where"
%token JACOBIAN "jacobian"
/* functions */
%token DEF "def" RETURN "return" ARROW "->"

%token SEMI ";" COLON ":" COMMA "," DOT "." AT_SIGN "@" ASSIGN "=" LBRACE "{" RBRACE "}"
       LPAREN "(" RPAREN ")" LBRACKET "[" RBRACKET "]" LT "<" GT ">" LE "<=" GE ">="
       EQ "==" NE "!=" PLUS "+" PLUS_ASSIGN "+=" MINUS "-" STAR "*" SLASH "/" UNDERSCORE "_"

%type <rift::ast::ExprPtr> expr primary node_path
%type <std::vector<rift::ast::ExprPtr>> args args1
%type <rift::ast::Label> orbit
%type <std::vector<int>> orbit_entries
%type <int> orbit_entry
%type <rift::ast::Ident> ident arc_chain
%type <std::vector<rift::ast::Ident>> ident_list
%type <rift::ast::Type> type
%type <std::string> collect_op type_call
%type <rift::ast::Param> param_decl
%type <std::vector<rift::ast::Param>> params params1 component_params component_params1
%type <rift::ast::Param> component_param
%type <rift::ast::Param::Bound> opt_bound
%type <std::string> opt_description
%type <bool> opt_tagged
%type <std::string> interaction_kw criterion_kw pack_kw script_kw
%type <std::vector<rift::ast::ApplyArg>> apply_with apply_args
%type <rift::ast::ApplyArg> apply_arg
%type <rift::ast::Each> opt_each
%type <rift::ast::ExprPtr> opt_where
%type <std::vector<rift::ast::ExprPtr>> dart_list
%type <rift::ast::ExprPtr> opt_default
%type <std::optional<rift::ast::Ident>> opt_merge
%type <std::vector<rift::ast::Param>> function_params
%type <std::vector<rift::ast::Let>> fold_lets
%type <rift::ast::ExprPtr> fold_body

%precedence ELSE
%left OR
%left AND
%nonassoc EQ NE
%nonassoc LT LE GT GE
%left PLUS MINUS
%left STAR SLASH
%precedence NOT UMINUS

%start file

%%

file
  : header items
  ;

header
  : pack_kw ident DIMENSION INT SEMI {
      ctx.file.has_header = true;
      ctx.file.description = $1;
      ctx.file.pack = $2;
      const std::int64_t dim = $4;
      ctx.file.dimension = static_cast<int>(dim > 1000 ? 1000 : dim);
      ctx.file.dimension_loc = @4;
    }
  | error SEMI
  ;

items
  : %empty
  | items item
  ;

item
  : INCLUDE STRING SEMI { ctx.file.includes.push_back(rift::ast::Include{$2, @2, false}); }
  | IMPORT STRING SEMI { ctx.file.includes.push_back(rift::ast::Include{$2, @2, true}); }
  | EMBEDDING ident COLON type ON orbit opt_default opt_merge SEMI {
      rift::ast::Embedding e;
      e.name = $2;
      e.type = $4;
      e.type_loc = @4;
      e.orbit = $6;
      e.default_value = $7;
      e.merge = $8;
      ctx.file.embeddings.push_back(std::move(e));
    }
  | PARAM ident COLON type ASSIGN expr SEMI {
      ctx.file.params.push_back(rift::ast::PackParam{$2, $4, @4, $6});
    }
  | INIT ident LPAREN ident RPAREN ASSIGN expr SEMI {
      ctx.file.inits.push_back(rift::ast::Init{$2, $4, $7, @$});
    }
  | rule
  | interaction
  | criterion
  | script
  | function
  | error SEMI
  | error RBRACE
  ;

opt_default
  : %empty { $$ = nullptr; }
  | ASSIGN expr { $$ = $2; }
  ;

opt_merge
  : %empty { $$ = std::nullopt; }
  | MERGE ident { $$ = $2; }
  | MERGE SUM { $$ = rift::ast::Ident{"sum", @2}; }
  | MERGE MEAN { $$ = rift::ast::Ident{"mean", @2}; }
  ;

type
  : T_REAL { $$ = rift::ast::Type::Real; }
  | T_INT  { $$ = rift::ast::Type::Int; }
  | T_BOOL { $$ = rift::ast::Type::Bool; }
  | T_VEC3 { $$ = rift::ast::Type::Vec3; }
  | T_MAT3 { $$ = rift::ast::Type::Mat3; }
  ;

ident
  : IDENT { $$ = rift::ast::Ident{$1, @1}; }
  ;

ident_list
  : ident { $$.push_back($1); }
  | ident_list COMMA ident { $$ = $1; $$.push_back($3); }
  ;

orbit
  : LT orbit_entries GT { $$ = rift::ast::Label{$2, @$}; }
  | LT GT { $$ = rift::ast::Label{{}, @$}; }
  ;

orbit_entries
  : orbit_entry { $$.push_back($1); }
  | orbit_entries COMMA orbit_entry { $$ = $1; $$.push_back($3); }
  ;

orbit_entry
  : INT {
      // Out-of-range values are kept (clamped to stay an int) for the checker to report.
      const std::int64_t dim = $1;
      $$ = dim > 1000 ? 1000 : static_cast<int>(dim);
    }
  | UNDERSCORE { $$ = -1; }
  ;

/* ---- rules ------------------------------------------------------------------ */

rule
  : RULE ident params {
      ctx.rule = rift::ast::Rule{};
      ctx.rule.name = $2;
      ctx.rule.params = $3;
      ctx.lets = &ctx.rule.lets;
      ctx.whens = &ctx.rule.whens;
      ctx.body = &ctx.rule.body;
    }
    LBRACE rule_stmts RBRACE {
      ctx.file.rules.push_back(std::move(ctx.rule));
      ctx.lets = nullptr;
      ctx.whens = nullptr;
      ctx.body = nullptr;
    }
  ;

params
  : %empty { }
  | LPAREN RPAREN { }
  | LPAREN params1 RPAREN { $$ = $2; }
  ;

params1
  : param_decl { $$.push_back($1); }
  | params1 COMMA param_decl { $$ = $1; $$.push_back($3); }
  ;

param_decl
  : ident COLON type {
      $$.name = $1;
      $$.type = $3;
      $$.type_loc = @3;
    }
  ;

rule_stmts
  : %empty
  | rule_stmts rule_stmt
  ;

rule_stmt
  : HOOK ident_list SEMI {
      std::vector<rift::ast::Ident> hooks = $2;
      for (auto& h : hooks) ctx.rule.hooks.push_back(h);
      ctx.rule.hook_loc = @1;
    }
  | LEFT { ctx.pattern = &ctx.rule.left; ctx.pattern->present = true; ctx.pattern->loc = @1; }
    LBRACE pattern_stmts RBRACE
  | RIGHT { ctx.pattern = &ctx.rule.right; ctx.pattern->present = true; ctx.pattern->loc = @1; }
    LBRACE pattern_stmts RBRACE
  | UPDATE ident DOT ident ASSIGN expr SEMI {
      ctx.rule.updates.push_back(rift::ast::Assign{$2, $4, $6, @$});
    }
  | body_stmt
  | error SEMI
  ;

/* let and when: shared by rules, interactions and criteria */
body_stmt
  : LET ident ASSIGN expr SEMI {
      if (ctx.lets) {
        if (ctx.body) ctx.body->push_back({rift::ast::BodyStmt::Kind::Let, ctx.lets->size()});
        ctx.lets->push_back(rift::ast::Let{$2, $4});
      }
    }
  | WHEN expr SEMI {
      if (ctx.whens) {
        if (ctx.body) ctx.body->push_back({rift::ast::BodyStmt::Kind::When, ctx.whens->size()});
        ctx.whens->push_back($2);
      } else {
        ctx.diags.error(@1, "'when' is not allowed here; a criterion states its condition with 'measure'");
      }
    }
  ;

pattern_stmts
  : %empty
  | pattern_stmts pattern_stmt
  ;

pattern_stmt
  : ident COLON orbit SEMI {
      ctx.pattern->nodes.push_back(rift::ast::NodeDecl{$1, $3});
    }
  | arc_chain SEMI
  | ident DOT ident ASSIGN expr SEMI {
      ctx.pattern->assigns.push_back(rift::ast::Assign{$1, $3, $5, @$});
    }
  | error SEMI
  ;

arc_chain
  : ident MINUS INT MINUS ident {
      const std::int64_t dim = $3;
      rift::ast::Arc arc{$1, $5, static_cast<int>(dim > 1000 ? 1000 : dim), @3, @$};
      ctx.pattern->arcs.push_back(arc);
      $$ = arc.b;
    }
  | arc_chain MINUS INT MINUS ident {
      rift::ast::Ident from = $1;
      const std::int64_t dim = $3;
      rift::ast::Arc arc{from, $5, static_cast<int>(dim > 1000 ? 1000 : dim), @3,
                         rift::diag::span(from.loc, @5)};
      ctx.pattern->arcs.push_back(arc);
      $$ = arc.b;
    }
  ;

/* ---- interactions ------------------------------------------------------------ */

/* A `///` comment right above a declaration describes it (rift list shows it). */
pack_kw : PACK { $$ = ctx.lexer.doc_before(@1.begin.line); } ;
interaction_kw : INTERACTION { $$ = ctx.lexer.doc_before(@1.begin.line); } ;
criterion_kw : CRITERION { $$ = ctx.lexer.doc_before(@1.begin.line); } ;

interaction
  : interaction_kw ident ON orbit opt_tagged component_params {
      ctx.interaction = rift::ast::Interaction{};
      ctx.interaction.description = $1;
      ctx.interaction.name = $2;
      ctx.interaction.support = $4;
      ctx.interaction.tagged = $5;
      ctx.interaction.tagged_loc = @5;
      ctx.interaction.params = $6;
      ctx.lets = &ctx.interaction.lets;
      ctx.whens = &ctx.interaction.whens;
      ctx.body = &ctx.interaction.body;
    }
    LBRACE interaction_stmts RBRACE {
      ctx.file.interactions.push_back(std::move(ctx.interaction));
      ctx.lets = nullptr;
      ctx.whens = nullptr;
      ctx.body = nullptr;
    }
  ;

interaction_stmts
  : %empty
  | interaction_stmts interaction_stmt
  ;

interaction_stmt
  : PATTERN {
      ctx.pattern = &ctx.interaction.pattern;
      ctx.pattern->present = true;
      ctx.pattern->loc = @1;
    }
    LBRACE pattern_stmts RBRACE
  | INIT ident LPAREN ident RPAREN ASSIGN expr SEMI {
      ctx.interaction.inits.push_back(rift::ast::Init{$2, $4, $7, @$});
    }
  | FORCE ident DOT ident ASSIGN expr SEMI {
      ctx.interaction.forces.push_back(rift::ast::Assign{$2, $4, $6, @$});
    }
  /* `store` is a word of this statement only, not a keyword: names may be `store`. */
  | ident ident DOT ident ASSIGN expr SEMI {
      if ($1.text != "store") {
        ctx.diags.error(@1, "expected a statement of an interaction ('store NODE.EMBEDDING = "
                            "...;' stores a value for criteria), not '" + $1.text + "'");
      }
      ctx.interaction.stores.push_back(rift::ast::Assign{$2, $4, $6, @$});
    }
  | ident ident DOT ident PLUS_ASSIGN expr SEMI {
      if ($1.text != "store") {
        ctx.diags.error(@1, "expected a statement of an interaction ('store NODE.EMBEDDING += "
                            "...;' accumulates a value per vertex for criteria), not '" +
                            $1.text + "'");
      }
      ctx.interaction.accumulations.push_back(rift::ast::Assign{$2, $4, $6, @$});
    }
  | ENERGY expr SEMI {
      if (ctx.interaction.energy) ctx.diags.error(@1, "the interaction already has an energy");
      ctx.interaction.energy = $2;
    }
  /* `by` is a word of this statement only, not a keyword: names may be `by`. */
  | JACOBIAN ident DOT ident ident ident DOT ident ASSIGN expr SEMI {
      if ($5.text != "by") {
        ctx.diags.error(@5, "expected 'by' in 'jacobian " + $2.text + "." + $4.text +
                                " by NODE.position = ...;', not '" + $5.text + "'");
      }
      ctx.interaction.jacobians.push_back(rift::ast::JacobianBlock{$2, $4, $6, $8, $10, @$});
    }
  | SEMIDEFINITE SEMI {
      if (ctx.interaction.semidefinite) {
        ctx.diags.error(@1, "the interaction is already declared semidefinite");
      }
      ctx.interaction.semidefinite = true;
      ctx.interaction.semidefinite_loc = @1;
    }
  | body_stmt
  | error SEMI
  ;

/* ---- parameters given by the scene ------------------------------------------- */

opt_tagged
  : %empty { $$ = false; }
  | TAGGED { $$ = true; }
  ;

component_params
  : %empty { }
  | LPAREN RPAREN { }
  | LPAREN component_params1 RPAREN { $$ = $2; }
  ;

component_params1
  : component_param { $$.push_back($1); }
  | component_params1 COMMA component_param { $$ = $1; $$.push_back($3); }
  ;

/* stiffness : real > 0 = 60.0 "N/m" */
component_param
  : ident COLON type opt_bound opt_default opt_description {
      $$.name = $1;
      $$.type = $3;
      $$.type_loc = @3;
      $$.bound = $4;
      $$.bound_loc = @4;
      $$.default_value = $5;
      $$.description = $6;
    }
  ;

opt_bound
  : %empty { $$ = rift::ast::Param::Bound::None; }
  | GT bound_zero { $$ = rift::ast::Param::Bound::Positive; }
  | GE bound_zero { $$ = rift::ast::Param::Bound::NonNegative; }
  | LT bound_zero {
      ctx.diags.error(@1, "a parameter bound is '> 0' or '>= 0'");
      $$ = rift::ast::Param::Bound::None;
    }
  | LE bound_zero {
      ctx.diags.error(@1, "a parameter bound is '> 0' or '>= 0'");
      $$ = rift::ast::Param::Bound::None;
    }
  ;

bound_zero
  : INT {
      if ($1 != 0) ctx.diags.error(@1, "a parameter bound is '> 0' or '>= 0'; other limits are not supported");
    }
  | REAL {
      if ($1 != 0.0) ctx.diags.error(@1, "a parameter bound is '> 0' or '>= 0'; other limits are not supported");
    }
  ;

opt_description
  : %empty { }
  | STRING { $$ = $1; }
  ;

/* ---- criteria ----------------------------------------------------------------- */

criterion
  : criterion_kw ident ON orbit LPAREN ident RPAREN component_params {
      ctx.criterion = rift::ast::Criterion{};
      ctx.criterion.description = $1;
      ctx.criterion.name = $2;
      ctx.criterion.orbit = $4;
      ctx.criterion.dart = $6;
      ctx.criterion.params = $8;
      ctx.lets = &ctx.criterion.lets;
      ctx.whens = nullptr;
      ctx.body = nullptr;
    }
    LBRACE criterion_stmts RBRACE {
      ctx.file.criteria.push_back(std::move(ctx.criterion));
      ctx.lets = nullptr;
    }
  ;

criterion_stmts
  : %empty
  | criterion_stmts criterion_stmt
  ;

criterion_stmt
  : MEASURE expr SEMI {
      if (ctx.criterion.measure) ctx.diags.error(@1, "the criterion already has a measure");
      ctx.criterion.measure = $2;
    }
  | APPLY ident AT ident_list apply_with SEMI {
      if (ctx.criterion.has_apply) ctx.diags.error(@1, "the criterion already applies a rule");
      ctx.criterion.has_apply = true;
      ctx.criterion.rule = $2;
      ctx.criterion.apply_hooks = $4;
      ctx.criterion.apply_args = $5;
      ctx.criterion.apply_loc = @$;
    }
  /* `node` is a word of this statement only, not a keyword: names may be `node`. */
  | ident ident ASSIGN node_path SEMI {
      const rift::ast::Ident word = $1;
      const rift::ast::Ident name = $2;
      const ExprPtr path = $4;
      if (word.text != "node") {
        ctx.diags.error(@1, "expected 'node', 'let', 'measure' or 'apply' in a criterion, not '" +
                                word.text + "'");
      } else if (!ctx.criterion.lets.empty()) {
        ctx.diags.error(@1, "node '" + name.text + "' comes after a 'let'; a criterion's nodes "
                                "are its pattern and come first")
            .notes.push_back({ctx.criterion.lets.front().name.loc, "first let"});
      }
      ctx.criterion.nodes.push_back(rift::ast::CriterionNode{
          name, rift::ast::Ident{path->node, path->node_loc}, path->hops, @4});
    }
  | body_stmt
  | error SEMI
  ;

apply_with
  : %empty { }
  | WITH apply_args { $$ = $2; }
  ;

apply_args
  : apply_arg { $$.push_back($1); }
  | apply_args COMMA apply_arg { $$ = $1; $$.push_back($3); }
  ;

apply_arg
  : ident ASSIGN expr { $$ = rift::ast::ApplyArg{$1, $3}; }
  ;

/* ---- scripts ------------------------------------------------------------------ */

script_kw : SCRIPT { $$ = ctx.lexer.doc_before(@1.begin.line); } ;

script
  : script_kw ident params AT ident_list {
      ctx.script = rift::ast::Script{};
      ctx.script.description = $1;
      ctx.script.name = $2;
      ctx.script.params = $3;
      ctx.script.hooks = $5;
      ctx.lets = nullptr;
      ctx.whens = nullptr;
      ctx.body = nullptr;
    }
    LBRACE script_stmts RBRACE {
      ctx.file.scripts.push_back(std::move(ctx.script));
    }
  ;

script_stmts
  : %empty
  | script_stmts script_stmt
  ;

script_stmt
  : LET ident ASSIGN expr SEMI {
      rift::ast::ScriptStmt s;
      s.kind = rift::ast::ScriptStmt::Kind::Let;
      s.loc = @$;
      s.let = ctx.script.lets.size();
      ctx.script.lets.push_back(rift::ast::Let{$2, $4});
      ctx.script.stmts.push_back(std::move(s));
    }
  | SET ident DOT ident ASSIGN expr opt_each opt_where SEMI {
      rift::ast::ScriptStmt s;
      s.kind = rift::ast::ScriptStmt::Kind::Set;
      s.loc = @$;
      s.set = rift::ast::Assign{$2, $4, $6, @$};
      s.each = $7;
      s.where = $8;
      ctx.script.stmts.push_back(std::move(s));
    }
  | APPLY ident AT dart_list opt_each opt_where apply_with SEMI {
      rift::ast::ScriptStmt s;
      s.kind = rift::ast::ScriptStmt::Kind::Apply;
      s.loc = @$;
      s.rule = $2;
      s.hooks = $4;
      s.each = $5;
      s.where = $6;
      s.args = $7;
      ctx.script.stmts.push_back(std::move(s));
    }
  | WHEN expr SEMI {
      ctx.diags.error(@1, "'when' is not allowed in a script; give an 'apply' or a 'set' a 'where' condition");
    }
  | error SEMI
  ;

dart_list
  : node_path { $$.push_back($1); }
  | dart_list COMMA node_path { $$ = $1; $$.push_back($3); }
  ;

/* for each <sub>(x) in <outer>(d) */
opt_each
  : %empty { }
  | FOR EACH orbit LPAREN ident RPAREN IN orbit LPAREN node_path RPAREN {
      $$.present = true;
      $$.sub = $3;
      $$.var = $5;
      $$.outer = $8;
      $$.dart = $10;
      $$.loc = @$;
    }
  ;

opt_where
  : %empty { }
  | WHERE expr { $$ = $2; }
  ;

/* ---- functions ---------------------------------------------------------------- */
/* def NAME(p : T, ...) -> T { let x = e; ... return e; }   or   def NAME(...) -> T = e; */
function
  : DEF ident function_params ARROW type {
      ctx.function = rift::ast::Function{};
      ctx.function.name = $2;
      ctx.function.params = $3;
      ctx.function.result = $5;
      ctx.function.result_loc = @5;
    }
    function_body {
      ctx.file.functions.push_back(std::move(ctx.function));
    }
  ;

function_params
  : LPAREN RPAREN { }
  | LPAREN params1 RPAREN { $$ = $2; }
  ;

function_body
  : ASSIGN expr SEMI { ctx.function.value = $2; }
  | LBRACE function_lets RETURN expr SEMI RBRACE { ctx.function.value = $4; }
  ;

function_lets
  : %empty
  | function_lets LET ident ASSIGN expr SEMI {
      ctx.function.lets.push_back(rift::ast::Let{$3, $5});
    }
  ;

/* ---- expressions ----------------------------------------------------------------- */

expr
  : primary { $$ = $1; }
  | MINUS expr %prec UMINUS { $$ = deepen(unary("-", $2, @$, @1), ctx); }
  | NOT expr { $$ = deepen(unary("not", $2, @$, @1), ctx); }
  | expr PLUS expr { $$ = deepen(binary("+", $1, $3, @$, @2), ctx); }
  | expr MINUS expr { $$ = deepen(binary("-", $1, $3, @$, @2), ctx); }
  | expr STAR expr { $$ = deepen(binary("*", $1, $3, @$, @2), ctx); }
  | expr SLASH expr { $$ = deepen(binary("/", $1, $3, @$, @2), ctx); }
  | expr LT expr { $$ = deepen(binary("<", $1, $3, @$, @2), ctx); }
  | expr LE expr { $$ = deepen(binary("<=", $1, $3, @$, @2), ctx); }
  | expr GT expr { $$ = deepen(binary(">", $1, $3, @$, @2), ctx); }
  | expr GE expr { $$ = deepen(binary(">=", $1, $3, @$, @2), ctx); }
  | expr EQ expr { $$ = deepen(binary("==", $1, $3, @$, @2), ctx); }
  | expr NE expr { $$ = deepen(binary("!=", $1, $3, @$, @2), ctx); }
  | expr AND expr { $$ = deepen(binary("and", $1, $3, @$, @2), ctx); }
  | expr OR expr { $$ = deepen(binary("or", $1, $3, @$, @2), ctx); }
  | IF expr THEN expr ELSE expr {
      ExprPtr e = make_expr(Expr::Kind::Cond, @$);
      e->op_loc = @1;
      e->args.push_back($2);
      e->args.push_back($4);
      e->args.push_back($6);
      $$ = deepen(std::move(e), ctx);
    }
  ;

primary
  : INT { $$ = make_expr(Expr::Kind::IntLit, @$); $$->integer = $1; }
  | REAL { $$ = make_expr(Expr::Kind::RealLit, @$); $$->real = $1; }
  | TRUE { $$ = make_expr(Expr::Kind::BoolLit, @$); $$->boolean = true; }
  | FALSE { $$ = make_expr(Expr::Kind::BoolLit, @$); $$->boolean = false; }
  | IDENT { $$ = make_expr(Expr::Kind::Name, @$); $$->name = $1; }
  | IDENT LPAREN args RPAREN { $$ = deepen(call($1, $3, @$, @1), ctx); }
  | type_call LPAREN args RPAREN { $$ = deepen(call($1, $3, @$, @1), ctx); }
  | LPAREN expr RPAREN { $$ = $2; }
  | node_path DOT IDENT {
      $$ = $1;
      $$->name = $3;
      $$->loc = @$;
    }
  | collect_op IDENT OVER orbit LPAREN node_path RPAREN {
      ExprPtr path = $6;
      $$ = make_expr(Expr::Kind::Collect, @$);
      $$->op = $1;
      $$->name = $2;
      $$->orbit = $4;
      $$->node = path->node;
      $$->node_loc = path->node_loc;
      $$->hops = path->hops;
    }
  | collect_op OF fold_body FOR EACH orbit LPAREN ident RPAREN IN orbit LPAREN node_path RPAREN {
      ExprPtr path = $13;
      rift::ast::Ident var = $8;
      $$ = std::move($3);  // the Fold fold_body made, with its lets
      $$->loc = @$;
      $$->op = $1;
      $$->op_loc = @1;
      $$->orbit = $6;
      $$->var = var.text;
      $$->var_loc = var.loc;
      $$->outer = $11;
      $$->node = path->node;
      $$->node_loc = path->node_loc;
      $$->hops = path->hops;
      $$ = deepen(std::move($$), ctx);
    }
  | primary LBRACKET expr RBRACKET {
      $$ = make_expr(Expr::Kind::Index, @$);
      $$->op_loc = @2;
      $$->args.push_back($1);
      $$->args.push_back($3);
      $$ = deepen(std::move($$), ctx);
    }
  | primary LBRACKET expr COMMA expr RBRACKET {
      $$ = make_expr(Expr::Kind::Index, @$);
      $$->op_loc = @2;
      $$->args.push_back($1);
      $$->args.push_back($3);
      $$->args.push_back($5);
      $$ = deepen(std::move($$), ctx);
    }
  ;

/* The value a fold aggregates: an expression, or lets then `return` the
   value, as in a function body. Makes the Fold node; the rule above fills it. */
fold_body
  : expr {
      $$ = make_expr(Expr::Kind::Fold, @$);
      $$->args.push_back($1);
    }
  | LBRACE fold_lets RETURN expr SEMI RBRACE {
      $$ = make_expr(Expr::Kind::Fold, @$);
      $$->lets = $2;
      for (const rift::ast::Let& l : $$->lets) $$->depth = std::max($$->depth, l.value->depth + 1);
      $$->args.push_back($4);
    }
  ;

fold_lets
  : %empty { }
  | fold_lets LET ident ASSIGN expr SEMI {
      $$ = $1;
      $$.push_back(rift::ast::Let{$3, $5});
    }
  ;

/* `min` / `max` are both functions of two values and orbit collections. */
type_call
  : T_REAL { $$ = "real"; }
  | T_INT { $$ = "int"; }
  | T_VEC3 { $$ = "vec3"; }
  | T_MAT3 { $$ = "mat3"; }
  | MIN { $$ = "min"; }
  | MAX { $$ = "max"; }
  ;

collect_op
  : SUM { $$ = "sum"; }
  | MEAN { $$ = "mean"; }
  | COUNT { $$ = "count"; }
  | MIN { $$ = "min"; }
  | MAX { $$ = "max"; }
  ;

node_path
  : IDENT {
      $$ = make_expr(Expr::Kind::Read, @$);
      $$->node = $1;
      $$->node_loc = @1;
    }
  | node_path AT_SIGN INT {
      $$ = $1;
      const std::int64_t dim = $3;
      $$->hops.push_back(static_cast<int>(dim > 1000 ? 1000 : dim));
    }
  ;

args
  : %empty { }
  | args1 { $$ = $1; }
  ;

args1
  : expr { $$.push_back($1); }
  | args1 COMMA expr { $$ = $1; $$.push_back($3); }
  ;

%%

void rift::grammar::Parser::error(const location_type& loc, const std::string& message) {
  ctx.diags.error(loc, message);
}
