// A rule becomes one function: build the rows of the hook orbit, reach every
// left node by its explicit arcs, verify links and injectivity, evaluate the
// precondition and the right-node expressions on the match, then delete,
// create, relink, fix embedding slots, write values and run the updates.
#include <algorithm>

#include "emit/emit_context.hpp"
#include "emit/names.hpp"
#include "lower/rule_plan.hpp"

namespace rift::emit {

namespace {

std::string left_name(int v) {
  return "left_" + std::to_string(v);
}
std::string right_name(int v) {
  return "right_" + std::to_string(v);
}

std::string int_list(const std::vector<int>& v) {
  std::string out;
  for (std::size_t k = 0; k < v.size(); ++k)
    out += (k ? ", " : "") + std::to_string(v[k]);
  return out;
}

/// Opens the per-row loop and binds `d_<node>` for the nodes of a side
/// (the first nodes of `body`) that `roots` read, directly or through the
/// lets they read, or that `written` names.
void open_row_loop(Writer& w, const std::vector<std::string>& side, bool right,
                   const ir::Body& body, std::vector<ir::ExprId> roots,
                   const std::vector<int>& written = {}) {
  std::vector<bool> lets(body.lets.size(), false);
  for (ir::ExprId root : roots)
    lower::lets_read(body, root, lets);
  for (std::size_t i = 0; i < lets.size(); ++i) {
    if (lets[i]) roots.push_back(body.lets[i].value);
  }
  std::vector<bool> used(side.size(), false);
  for (int v : written)
    used[static_cast<std::size_t>(v)] = true;
  for (ir::ExprId root : roots) {
    ir::visit(body.graph, root, [&](const ir::Node& n) {
      const bool placed = n.op == ir::Op::Position || n.op == ir::Op::Velocity ||
                          n.op == ir::Op::Read || n.op == ir::Op::Fold;
      const auto v = static_cast<std::size_t>(n.place.node);
      if (placed && n.place.node >= 0 && v < used.size()) used[v] = true;
    });
  }
  w.open("for (std::size_t r = 0; r < rows; ++r) {");
  for (std::size_t v = 0; v < side.size(); ++v) {
    if (!used[v]) continue;
    const int i = static_cast<int>(v);
    w.line("const rift::Dart " + dart_name(side[v]) + " = " +
           (right ? right_name(i) : left_name(i)) + "[r];");
  }
}

}  // namespace

void emit_match(Writer& w, const std::vector<std::string>& left, const lower::MatchPlan& match,
                const std::string& fail) {
  const std::size_t nl = left.size();
  w.line("s.left.resize(" + std::to_string(nl) + " * rows);");
  for (std::size_t v = 0; v < nl; ++v) {
    w.line("[[maybe_unused]] rift::Dart* const " + left_name(static_cast<int>(v)) +
           " = s.left.data() + " + std::to_string(v) + " * rows;  // " + left[v]);
  }
  for (std::size_t j = 0; j < match.hooks.size(); ++j) {
    w.line("std::copy_n(s.rows.data() + " + std::to_string(j) + " * rows, rows, " +
           left_name(match.hooks[j]) + ");");
  }
  for (const lower::Follow& f : match.follows) {
    w.line("for (std::size_t r = 0; r < rows; ++r) " + left_name(f.to) + "[r] = g.alpha(" +
           left_name(f.from) + "[r], " + std::to_string(f.dim) + ");");
  }
  for (const lower::ArcCheck& a : match.arc_checks) {
    w.open("for (std::size_t r = 0; r < rows; ++r) {");
    w.line("if (g.alpha(" + left_name(a.a) + "[r], " + std::to_string(a.dim) +
           ") != " + left_name(a.b) + "[r]) " + fail);
    w.close();
  }
  for (const lower::LabelLink& c : match.label_checks) {
    w.open("for (std::size_t r = 0; r < rows; ++r) {");
    w.line("if (g.alpha(" + left_name(c.node) + "[r], " + std::to_string(c.dim) + ") != " +
           left_name(c.node) + "[s.nbr[r * label + " + std::to_string(c.pos) + "]]) " + fail);
    w.close();
  }
  if (nl > 0) w.line("if (!distinct_darts(g, s.left.data(), s.left.size())) " + fail);
}

void emit_rule(Writer& w, const lower::RulePlan& plan, const PackModel& model) {
  const ast::Rule& rule = *plan.rule;
  const lower::RuleValues& values = plan.values;
  const lower::MatchPlan& match = plan.match;
  const lower::RewritePlan& rewrite = plan.rewrite;
  const std::string user = "rule '" + rule.name.text + "'";
  const RenderContext on_match = dart_context(values.match);
  const RenderContext on_right = dart_context(values.rewritten);

  w.line("// " + user + " (" + std::to_string(plan.hooks) + " hook(s))");
  w.open("bool " + rule_function(rule.name.text) +
         "(rift::GMap& g, std::span<const rift::Dart> hooks, const " + rule.name.text +
         "_args& args, const Params& params, std::vector<rift::Dart>* touched) {");
  w.line("(void)args;");
  w.line("(void)params;");
  w.line("if (g.dimension() != " + std::to_string(plan.dimension) +
         ") throw std::invalid_argument(" +
         quote(user + " needs a G-map of dimension " + std::to_string(plan.dimension)) + ");");
  w.line("if (hooks.size() != " + std::to_string(plan.hooks) + ") return false;");
  w.open("for (rift::Dart h : hooks) {");
  w.line("if (!g.is_alive(h)) return false;");
  w.close();
  w.line("Scratch& s = scratch();");
  if (match.hook_dims.empty()) {
    w.line("const int* const hook_dims = nullptr;");
  } else {
    w.line("static constexpr int hook_dims[] = {" + int_list(match.hook_dims) + "};");
  }
  w.line("std::size_t rows = 1;");
  w.line("if (!build_rows(g, hooks.data(), hooks.size(), hook_dims, " +
         std::to_string(match.label_length) + ", s, rows)) return false;");
  w.line("[[maybe_unused]] const std::size_t label = " + std::to_string(match.label_length) + ";");
  fetch_embeddings(w, values.embeddings, model, user);

  emit_match(w, plan.left, match, "return false;");

  // ---- precondition and values, on the match
  const ir::Graph& mg = values.match.graph;
  const bool guarded =
      std::any_of(values.match.stmts.begin(), values.match.stmts.end(),
                  [](const ir::Stmt& s) { return s.kind == ir::Stmt::Kind::When; });
  if (guarded) {
    const std::string fail = "return false;";
    std::vector<ir::ExprId> conds;
    for (const ir::Stmt& s : values.match.stmts) {
      if (s.kind == ir::Stmt::Kind::When) conds.push_back(s.cond);
    }
    open_row_loop(w, plan.left, false, values.match, conds);
    write_statements(w, values.match, on_match, conds, &fail);
    w.close();
  }
  // Stored as the embedding stores them: a bool as rift::Bool, which a
  // std::vector<bool> element (a proxy) would not convert to.
  for (std::size_t k = 0; k < values.assigns.size(); ++k) {
    w.line("std::vector<" + storage_type(mg[values.assigns[k].value].type) + "> value_" +
           std::to_string(k) + "(rows);");
  }
  if (!values.assigns.empty()) {
    std::vector<ir::ExprId> written;
    written.reserve(values.assigns.size());
    for (const lower::Write& a : values.assigns)
      written.push_back(a.value);
    open_row_loop(w, plan.left, false, values.match, written);
    write_statements(w, values.match, on_match, written, nullptr);
    for (std::size_t k = 0; k < values.assigns.size(); ++k) {
      const lower::Write& a = values.assigns[k];
      write_sourced(w, a.loc,
                    "value_" + std::to_string(k) + "[r] = " + render(mg, a.value, on_match) + ";");
    }
    w.close();
  }

  // ---- rewrite: every dart of the match may change (relinked or deleted)
  if (!plan.left.empty())
    w.line("if (touched) touched->insert(touched->end(), s.left.begin(), s.left.end());");
  for (int v : rewrite.deleted) {
    w.line("for (std::size_t r = 0; r < rows; ++r) g.delete_dart(" + left_name(v) + "[r]);");
  }
  const std::size_t nr = plan.right.size();
  w.line("s.right.resize(" + std::to_string(nr) + " * rows);");
  for (std::size_t v = 0; v < nr; ++v) {
    const int l = rewrite.right_from_left[v];
    const std::string rv = right_name(static_cast<int>(v));
    w.line("[[maybe_unused]] rift::Dart* const " + rv + " = s.right.data() + " + std::to_string(v) +
           " * rows;  // " + plan.right[v] + (l < 0 ? " (created)" : ""));
    if (l >= 0) {
      w.line("std::copy_n(" + left_name(l) + ", rows, " + rv + ");");
    } else {
      w.line("for (std::size_t r = 0; r < rows; ++r) " + rv + "[r] = g.create_dart();");
      w.line("if (touched) touched->insert(touched->end(), " + rv + ", " + rv + " + rows);");
    }
  }
  for (const lower::ArcCheck& u : rewrite.unlinks) {
    const std::string x = right_name(u.a) + "[r]";
    const std::string d = std::to_string(u.dim);
    w.open("for (std::size_t r = 0; r < rows; ++r) {");
    w.line("if (touched) touched->push_back(g.alpha(" + x + ", " + d + "));");
    w.line("g.unlink(" + x + ", " + d + ");");
    w.close();
  }
  auto link = [&](const std::string& x, const std::string& y, int dim) {
    const std::string d = std::to_string(dim);
    w.open("for (std::size_t r = 0; r < rows; ++r) {");
    w.line("const rift::Dart x = " + x + ";");
    w.line("const rift::Dart y = " + y + ";");
    w.line("if (x != y && g.is_free(x, " + d + ") && g.is_free(y, " + d + ")) g.link(x, y, " + d +
           ");");
    w.close();
  };
  for (const lower::ArcCheck& a : rewrite.arcs) {
    if (a.a != a.b) link(right_name(a.a) + "[r]", right_name(a.b) + "[r]", a.dim);
  }
  for (const lower::LabelLink& l : rewrite.label_links) {
    link(right_name(l.node) + "[r]",
         right_name(l.node) + "[s.nbr[r * label + " + std::to_string(l.pos) + "]]", l.dim);
  }
  if (nr > 0) {
    // What the rewrite changes, for the upkeep to skip the attachments whose
    // orbits it leaves as they were (slot_upkeep.hpp, rule_plan.hpp).
    w.line(
        "update_embedding_slots(g, s.right.data(), s.right.size(), s, touched, "
        "{rift::Orbit::from_mask(" +
        std::to_string(rewrite.relinked_dims) + "), " +
        (rewrite.darts_come_or_go ? "true" : "false") + "});");
  }
  for (std::size_t k = 0; k < rule.right.assigns.size(); ++k) {
    const ast::Assign& a = rule.right.assigns[k];
    const int v = plan.assign_nodes[k];
    w.line("for (std::size_t r = 0; r < rows; ++r) " + embedding_var(a.embedding.text) + "[" +
           right_name(v) + "[r]] = value_" + std::to_string(k) + "[r];");
  }
  if (!values.updates.empty()) {
    std::vector<ir::ExprId> updated;
    std::vector<int> targets;
    for (const lower::Write& u : values.updates) {
      updated.push_back(u.value);
      targets.push_back(u.node);
    }
    open_row_loop(w, plan.right, true, values.rewritten, updated, targets);
    for (const lower::Write& u : values.updates) {
      write_sourced(w, u.loc,
                    embedding_var(u.embedding) + "[" + on_right.dart(u.node) +
                        "] = " + render(values.rewritten.graph, u.value, on_right) + ";");
    }
    w.close();
  }
  // A Debug build of the runtime checks the map after every rewrite.
  w.line("g.check_after_rewrite(\"rule '" + rule.name.text + "'\");");
  w.line("return true;");
  w.close();
  w.line();
}

}  // namespace rift::emit
