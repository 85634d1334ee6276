#include "emit/emit_context.hpp"

#include "emit/names.hpp"

namespace rift::emit {

void embeddings_read(const ast::Expr& e, std::set<std::string>& out) {
  if (e.kind == ast::Expr::Kind::Read || e.kind == ast::Expr::Kind::Collect) out.insert(e.name);
  for (const auto& a : e.args)
    embeddings_read(*a, out);
}

void fetch_embeddings(Writer& w, const std::set<std::string>& names,
                      const resolve::Symbols& symbols, const std::string& user) {
  for (const std::string& name : names) {
    const ast::Embedding* emb = symbols.embedding(name);
    w.line("auto " + embedding_var(name) + " = require_embedding<" + storage_type(emb->type) +
           ">(g, " + quote(name) + ", " + quote(user) + ");");
  }
}

void write_sourced(Writer& w, const diag::Location& loc, const std::string& statement) {
  w.from_source(loc);
  w.line(statement);
  w.resume();
}

std::string write_rendered(Writer& w, BodyRenderer& r, const diag::Location& loc,
                           const std::string& before, ir::ExprId id, const std::string& after) {
  std::string code = r.expr(id);
  w.from_source(loc);
  for (const std::string& local : r.take_locals())
    w.line(local);
  w.line(before + code + after);
  w.resume();
  return code;
}

void write_lets(Writer& w, const std::vector<ast::Let>& lets, const ExprContext& ctx) {
  for (const ast::Let& l : lets) {
    write_sourced(w, l.value->loc,
                  "[[maybe_unused]] const " + cpp_type(ctx.types->of(*l.value)) + " " +
                      let_name(l.name.text) + " = " + emit_expr(*l.value, ctx) + ";");
  }
}

void write_body(Writer& w, const std::vector<ast::Let>& lets,
                const std::vector<ast::ExprPtr>& whens, const std::vector<ast::BodyStmt>& body,
                const ExprContext& ctx, const std::string& on_fail) {
  for (const ast::BodyStmt& st : body) {
    if (st.kind == ast::BodyStmt::Kind::Let) {
      const ast::Let& l = lets[st.index];
      write_sourced(w, l.value->loc,
                    "[[maybe_unused]] const " + cpp_type(ctx.types->of(*l.value)) + " " +
                        let_name(l.name.text) + " = " + emit_expr(*l.value, ctx) + ";");
    } else {
      const ast::Expr& cond = *whens[st.index];
      write_sourced(w, cond.loc, "if (!(" + emit_expr(cond, ctx) + ")) " + on_fail);
    }
  }
}

}  // namespace rift::emit
