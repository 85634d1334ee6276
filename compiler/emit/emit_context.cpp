#include "emit/emit_context.hpp"

#include "emit/names.hpp"

namespace rift::emit {

namespace {

std::string callee_scope(const PackModel& model, const std::string& callee) {
  const auto it = model.plan->imported_callees.find(callee);
  return it == model.plan->imported_callees.end() ? "" : "rift::packs::" + it->second + "::";
}

}  // namespace

std::string callee_args(const PackModel& model, const std::string& callee) {
  return callee_scope(model, callee) + callee + "_args";
}

std::string callee_function(const PackModel& model, const std::string& callee) {
  return callee_scope(model, callee) + rule_function(callee);
}

std::string callee_params(const PackModel& model, const std::string& callee,
                          const std::string& pack_params) {
  return model.plan->imported_callees.count(callee) ? "{}" : pack_params;
}

std::string embedding_storage(const PackModel& model, const std::string& name) {
  return storage_type(model.plan->embedding_types.at(name));
}

void fetch_embeddings(Writer& w, const std::vector<std::string>& names, const PackModel& model,
                      const std::string& user) {
  for (const std::string& name : names) {
    w.line("auto " + embedding_var(name) + " = require_embedding<" +
           embedding_storage(model, name) + ">(g, " + quote(name) + ", " + quote(user) + ");");
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

RenderContext dart_context(const ir::Body& body) {
  RenderContext ctx;
  ctx.dart = [&body](int node) { return dart_name(body.nodes[static_cast<std::size_t>(node)]); };
  return ctx;
}

void write_statements(Writer& w, const ir::Body& body, const RenderContext& ctx,
                      const std::vector<ir::ExprId>& roots, const std::string* on_fail) {
  std::vector<bool> wanted(body.lets.size(), false);
  for (ir::ExprId root : roots)
    lower::lets_read(body, root, wanted);
  for (const ir::Stmt& st : body.stmts) {
    if (st.kind == ir::Stmt::Kind::Let) {
      const auto i = static_cast<std::size_t>(st.let);
      if (!wanted[i]) continue;
      const ir::Let& l = body.lets[i];
      write_sourced(w, l.loc,
                    "const " + cpp_type(body.graph[l.value].type) + " " + let_name(l.name) + " = " +
                        render(body.graph, l.value, ctx) + ";");
    } else if (on_fail) {
      write_sourced(w, st.loc, "if (!(" + render(body.graph, st.cond, ctx) + ")) " + *on_fail);
    }
  }
}

}  // namespace rift::emit
