// Criteria become rift::Criterion classes: collect() evaluates the measure on
// every orbit of the criterion's type and proposes a TearCandidate where it
// holds; apply() matches the rule again at the candidate and rewrites,
// reporting the darts it touched. Rules also get a rift::Rule class, for
// simulators and scripts that apply them by name with run-time arguments.
#include "emit/emit_context.hpp"
#include "emit/names.hpp"
#include "lower/criterion_plan.hpp"

namespace rift::emit {

namespace {

RenderContext criterion_context(const ir::Body& body) {
  RenderContext ctx;
  ctx.dart = [&body](int node) { return dart_name(body.nodes[static_cast<std::size_t>(node)]); };
  ctx.args = "p_";
  ctx.params = "pack_";
  return ctx;
}

/// The lets in `wanted` not written yet, in source order; each is then written.
void write_wanted_lets(Writer& w, BodyRenderer& r, const ir::Body& body,
                       const std::vector<bool>& wanted, std::vector<bool>& written) {
  for (std::size_t i = 0; i < body.lets.size(); ++i) {
    if (!wanted[i] || written[i]) continue;
    written[i] = true;
    const ir::Let& l = body.lets[i];
    write_rendered(w, r, l.loc,
                   "const " + cpp_type(body.graph[l.value].type) + " " + let_name(l.name) + " = ",
                   l.value, ";");
    r.computed(l.value, let_name(l.name));
  }
}

std::vector<std::string> criterion_embeddings(const lower::CriterionPlan& plan) {
  std::vector<std::string> used;
  const ir::Graph& g = plan.body.graph;
  for (const ir::Let& l : plan.body.lets)
    lower::embeddings_read(g, l.value, used);
  lower::embeddings_read(g, plan.measure, used);
  lower::embeddings_read(g, plan.threshold, used);
  for (const lower::PayloadField& f : plan.payload)
    lower::embeddings_read(g, f.value, used);
  return used;
}

/// Whether an orbit may hold any number of darts: it has two consecutive
/// dimensions (<0,1>: a face's edges, <1,2>: a vertex's star in 2D). Of
/// dimensions two apart or more the involutions commute, and the orbit has
/// at most 2^k darts.
bool unbounded_orbit(const std::vector<int>& dims) {
  for (const int i : dims) {
    for (const int j : dims) {
      if (j == i + 1) return true;
    }
  }
  return false;
}

/// Whether a cell's body walks an orbit of unbounded size (in a fold, or
/// through an orbit memo).
bool walks_unbounded_orbits(const lower::CriterionPlan& plan) {
  const ir::Graph& g = plan.body.graph;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const ir::Node& n = g[static_cast<ir::ExprId>(i)];
    if (n.op == ir::Op::Fold && unbounded_orbit(n.outer)) return true;
  }
  for (const ir::OrbitMemo& memo : plan.memos) {
    if (unbounded_orbit(memo.orbit)) return true;
  }
  return false;
}

/// Which of the body's nodes the code rendering `roots` reads (hooks aside).
std::vector<bool> nodes_read(const ir::Body& body, const std::vector<ir::ExprId>& roots) {
  std::vector<bool> read(body.nodes.size(), false);
  for (ir::ExprId root : roots) {
    if (root == ir::kNoExpr) continue;
    ir::visit(body.graph, root,
              [&](const ir::Node& n) { read[static_cast<std::size_t>(n.place.node)] = true; });
  }
  return read;
}

/// The criterion's pattern nodes, before anything else of the cell: each
/// dart from its path where every link crossed is sewn, and none of the
/// earlier nodes (an injective match); `fail` runs where the pattern does not
/// match. `read`: the nodes the code after it reads (the others are tested,
/// not named, when nothing else reads them).
void write_pattern(Writer& w, const lower::CriterionPlan& plan, std::vector<bool> read,
                   const std::string& fail) {
  const ir::Body& b = plan.body;
  for (const lower::PatternNode& n : plan.pattern) {
    read[static_cast<std::size_t>(n.from)] = true;
    for (int k : n.distinct_from)
      read[static_cast<std::size_t>(k)] = true;
  }
  for (std::size_t k = 0; k < plan.pattern.size(); ++k) {
    const lower::PatternNode& n = plan.pattern[k];
    const std::string name = dart_name(b.nodes[k + 1]);
    std::string at = dart_name(b.nodes[static_cast<std::size_t>(n.from)]);
    std::string free;
    for (int h : n.hops) {
      free += (free.empty() ? "" : " || ") + std::string("g.is_free(") + at + ", " +
              std::to_string(h) + ")";
      at = "g.alpha(" + at + ", " + std::to_string(h) + ")";
    }
    write_sourced(w, n.loc, "if (" + free + ") " + fail);
    const bool named = read[k + 1];
    std::string same;
    for (int other : n.distinct_from) {
      same += (same.empty() ? "" : " || ") + (named ? name : at) +
              " == " + dart_name(b.nodes[static_cast<std::size_t>(other)]);
    }
    if (named) write_sourced(w, n.loc, "const rift::Dart " + name + " = " + at + ";");
    if (!same.empty()) write_sourced(w, n.loc, "if (" + same + ") " + fail);
  }
}

}  // namespace

void declare_criterion(Writer& w, const lower::CriterionPlan& plan, const PackModel& model) {
  const ast::Criterion& crit = *plan.criterion;
  const std::string cls = criterion_class(crit.name.text);
  const std::string params = component_params_struct(crit.name.text);
  declare_component_params(w, params, crit.params, model);
  w.line("/// Criterion '" + crit.name.text + "': applies rule '" + crit.rule.text +
         "' where its measure passes.");
  w.open("class " + cls + " final : public rift::Criterion {");
  w.middle(" public:");
  w.line("explicit " + cls + "(const " + params + "& p = {}, const Params& pack = {})");
  w.line("    : p_(p), pack_(pack) {}");
  w.line("const std::string& name() const override { return name_; }");
  w.line("const " + params + "& params() const { return p_; }");
  w.line("void initialise(rift::GMap& g) override;");
  w.line(
      "void collect(const rift::GMap& g, std::vector<rift::TearCandidate>& out) const override;");
  w.line("bool apply(rift::GMap& g, const rift::TearCandidate& candidate,");
  w.line("           std::vector<rift::Dart>& touched) override;");
  w.line("void topology_changed(const rift::GMap& g, std::span<const rift::Dart> touched,");
  w.line("                      std::uint64_t from) override {");
  w.line("  cells_.note_changed(g, touched, from);");
  w.line("}");
  w.line("void report_memory(rift::MemoryReport& report) const override {");
  w.line("  cells_.report_memory(report, \"criterion \" + name_);");
  w.line("}");
  w.line();
  w.middle(" private:");
  w.line("std::string name_ = " + quote(crit.name.text) + ";");
  w.line(params + " p_;");
  // Not every body reads a pack-level parameter; clang warns of an unused field.
  w.line("[[maybe_unused]] Params pack_;");
  for (const std::string& name : criterion_embeddings(plan)) {
    w.line("rift::Embedding<" + embedding_storage(model, name) + "> " + embedding_var(name) + ";");
  }
  // collect() is const to its callers; its cells and block lists are its scratch.
  w.line("/// The cells collect() visits, kept while the map's links do not change.");
  w.line("mutable rift::generated::CellCollection cells_;");
  for (std::size_t m = 0; m < plan.memos.size(); ++m) {
    const ir::OrbitMemo& memo = plan.memos[m];
    // collect() is const to its callers; the memos are its scratch, reset by each call.
    w.line("/// Values collect() computes once per orbit " + orbit_code(memo.orbit) +
           " it meets (rift/generated/orbit_memo.hpp).");
    w.line("mutable rift::generated::OrbitMemo " + memo_var(m) + ";");
    for (std::size_t k = 0; k < memo.values.size(); ++k) {
      w.line("mutable rift::generated::OrbitMemoValues<" +
             cpp_type(plan.body.graph[memo.values[k]].type) + "> " + memo_values_var(m, k) + ";");
    }
  }
  w.close("};");
  w.line();
}

void emit_criterion(Writer& w, const lower::CriterionPlan& plan, const PackModel& model) {
  const ast::Criterion& crit = *plan.criterion;
  const std::string cls = criterion_class(crit.name.text);
  const std::string user = "criterion '" + crit.name.text + "'";
  const ir::Body& b = plan.body;
  RenderContext collect_ctx = criterion_context(b);
  collect_ctx.memos = &plan.memos;
  collect_ctx.readers = true;
  const std::string d = dart_name(crit.dart.text);
  w.line("// ---- criterion '" + crit.name.text + "' on " + orbit_code(crit.orbit.dims));
  w.line();
  w.open("void " + cls + "::initialise(rift::GMap& g) {");
  w.line(model.pack_namespace + "::declare_embeddings(g);");
  for (const std::string& name : criterion_embeddings(plan)) {
    w.line(embedding_var(name) + " = require_embedding<" + embedding_storage(model, name) +
           ">(g, " + quote(name) + ", " + quote(user) + ");");
  }
  w.close();
  w.line();

  // collect: the lets the measure reads, the measure; only where it passes,
  // the lets the candidate's payload reads and the payload.
  w.open("void " + cls +
         "::collect(const rift::GMap& g, std::vector<rift::TearCandidate>& out) const {");
  for (std::size_t m = 0; m < plan.memos.size(); ++m)
    w.line(memo_var(m) + ".begin(g, " + orbit_code(plan.memos[m].orbit) + ");");
  // A criterion riftc proves free of shared scratch (CriterionPlan::parallel_collect)
  // evaluates blocks of cells on every core; the candidates come out in the
  // cells' order whatever the number of threads.
  w.open("cells_.collect(g, " + orbit_code(crit.orbit.dims) + ", " +
         (plan.parallel_collect ? "rift::generated::CollectOn::kEveryCore"
                                : "rift::generated::CollectOn::kOneThread") +
         ", out, [&](std::span<const rift::Dart> cells, std::vector<rift::TearCandidate>& found) "
         "{");
  // The map does not change during collect: each embedding's arrays are
  // taken once per block (EmbeddingReader), locals of the block that the
  // cells' loop keeps in registers, not checked again at every read.
  // Each reader knows how its attachment holds slots (ReadBy): a value on
  // <> is read by dart, the others through the slot array, no test per read.
  for (const std::string& name : criterion_embeddings(plan)) {
    const std::string by =
        model.plan->per_dart.count(name) ? "rift::ReadBy::kDart" : "rift::ReadBy::kSlot";
    w.line("[[maybe_unused]] const rift::EmbeddingReader<" + embedding_storage(model, name) + ", " +
           by + "> " + reader_var(name) + " = " + embedding_var(name) + ".reader<" + by + ">();");
  }
  // The cell's body is a lambda (it leaves a cell by `return`), inlined into
  // the loop.
  w.open("for (const rift::Dart " + d + " : cells) {");
  w.open("[&]() RIFT_CELL_BODY {");
  // The block polls the interrupt before it starts. A body that walks an
  // orbit of unbounded size (a face's edges, a vertex's star) also polls
  // per cell, one relaxed load, so that Ctrl-C is seen within a long pass.
  if (walks_unbounded_orbits(plan)) w.line("rift::throw_if_interrupted();");
  {
    std::vector<bool> written(b.lets.size(), false), wanted(b.lets.size(), false);
    std::vector<bool> for_payload(b.lets.size(), false);
    lower::lets_read(b, plan.measure, wanted);
    lower::lets_read(b, plan.threshold, wanted);
    // Two segments: what every cell computes, and what only a candidate does
    // (values are shared across both, folds are walked together within each).
    std::vector<ir::ExprId> roots = {plan.measure, plan.threshold}, payload;
    roots.insert(roots.end(), plan.guards.begin(), plan.guards.end());
    for (const lower::PayloadField& f : plan.payload) {
      lower::lets_read(b, f.value, for_payload);
      payload.push_back(f.value);
    }
    for (std::size_t i = 0; i < b.lets.size(); ++i) {
      if (wanted[i]) roots.push_back(b.lets[i].value);
      if (for_payload[i] && !wanted[i]) payload.push_back(b.lets[i].value);
    }
    if (!plan.pattern.empty()) {
      std::vector<ir::ExprId> all = roots;
      all.insert(all.end(), payload.begin(), payload.end());
      write_pattern(w, plan, nodes_read(b, all), "return;");
    }
    BodyRenderer r(b.graph, b.sharing, collect_ctx, roots);
    // A cell that fails a guard cannot pass: it is left before the lets
    // only the rest of the measure reads (lower/measure_guards.hpp).
    for (std::size_t k = 0; k < plan.guards.size(); ++k) {
      const ir::ExprId guard = plan.guards[k];
      std::vector<bool> needs(b.lets.size(), false);
      lower::lets_read(b, guard, needs);
      write_wanted_lets(w, r, b, needs, written);
      const diag::Location& loc = crit.measure->args[0]->loc;
      if (b.graph[guard].op == ir::Op::Let) {
        write_rendered(w, r, loc, "if (!", guard, ") return;");
        continue;
      }
      const std::string name = "guard" + std::to_string(k);
      write_rendered(w, r, loc, "const bool " + name + " = ", guard, ";");
      r.computed(guard, name);
      w.line("if (!" + name + ") return;");
    }
    write_wanted_lets(w, r, b, wanted, written);
    write_rendered(w, r, crit.measure->args[0]->loc, "const rift::Real measure = ", plan.measure,
                   ";");
    write_rendered(w, r, crit.measure->args[1]->loc,
                   "const rift::Real threshold = ", plan.threshold, ";");
    w.line("if (!(measure " + crit.measure->op + " threshold)) return;");
    w.line("rift::TearCandidate c;");
    w.line("c.at = " + d + ";");
    // Candidates are applied largest first: the margin by which the measure
    // passed, oriented by the comparison, puts the most critical first whether
    // the criterion is written with > or <.
    const bool above = crit.measure->op == ">" || crit.measure->op == ">=";
    w.line(std::string("c.measure = ") + (above ? "measure - threshold;" : "threshold - measure;"));
    r.segment(payload);
    write_wanted_lets(w, r, b, for_payload, written);
    // Every argument is the value at detection: an earlier tear of the step
    // may change what the criterion reads before this candidate applies.
    for (const lower::PayloadField& f : plan.payload) {
      write_rendered(w, r, f.loc,
                     "rift::generated::put_payload<" + cpp_type(f.type) + ">(c, " +
                         std::to_string(f.offset) + ", ",
                     f.value, ");  // " + f.param);
    }
  }
  w.line("found.push_back(c);");
  w.close("}();");
  w.close();
  w.close("});");
  w.close();
  w.line();

  // apply: the rule is matched again at the candidate's dart, with the
  // arguments the candidate carries.
  w.open("bool " + cls +
         "::apply(rift::GMap& g, const rift::TearCandidate& candidate, std::vector<rift::Dart>& "
         "touched) {");
  w.line("if (!g.is_alive(candidate.at)) return false;");
  // On a large map the rewrite and the re-matches after it read a few
  // hundred lines around the candidate, one miss after another: asked for
  // first, their misses overlap (GMap::prefetch_around).
  w.line("g.prefetch_around(candidate.at);");
  w.line("const rift::Dart " + d + " = candidate.at;");
  if (!plan.pattern.empty()) {
    // The map may have changed since collect(): the candidate is applied only
    // where the criterion's pattern still matches. Only the hooks are read
    // (the arguments come with the candidate).
    std::vector<bool> read(b.nodes.size(), false);
    for (const ast::Ident& h : crit.apply_hooks) {
      for (std::size_t k = 0; k < b.nodes.size(); ++k) {
        if (b.nodes[k] == h.text) read[k] = true;
      }
    }
    write_pattern(w, plan, read, "return false;");
  }
  w.line(callee_args(model, crit.rule.text) + " args;");
  for (const lower::PayloadField& f : plan.payload) {
    w.line("args." + member_name(f.param) + " = rift::generated::payload_as<" + cpp_type(f.type) +
           ">(candidate, " + std::to_string(f.offset) + ");");
  }
  std::string hooks;
  for (std::size_t k = 0; k < crit.apply_hooks.size(); ++k)
    hooks += (k ? ", " : "") + dart_name(crit.apply_hooks[k].text);
  w.line("const rift::Dart hooks[] = {" + hooks + "};");
  w.line("return " + callee_function(model, crit.rule.text) + "(g, hooks, args, " +
         callee_params(model, crit.rule.text, "pack_") + ", &touched);");
  w.close();
  w.line();
}

void declare_rule_class(Writer& w, const std::string& name, std::size_t hook_count) {
  const std::string cls = rule_class(name);
  w.line("/// Rule '" + name + "' as a rift::Rule: arguments by position.");
  w.open("class " + cls + " final : public rift::Rule {");
  w.middle(" public:");
  w.line("explicit " + cls + "(const Params& pack = {});");
  w.line("const std::string& name() const override { return name_; }");
  w.line("int hook_count() const override { return " + std::to_string(hook_count) + "; }");
  w.line("const std::vector<rift::ParamSpec>& params() const override { return specs_; }");
  w.line("bool apply(rift::GMap& g, std::span<const rift::Dart> hooks,");
  w.line(
      "           std::span<const rift::Value> args, std::vector<rift::Dart>& touched) override;");
  w.line();
  w.middle(" private:");
  w.line("std::string name_ = " + quote(name) + ";");
  // Not every body reads a pack-level parameter; clang warns of an unused field.
  w.line("[[maybe_unused]] Params pack_;");
  w.line("std::vector<rift::ParamSpec> specs_;");
  w.close("};");
  w.line();
}

void emit_rule_class(Writer& w, const std::string& name, const std::vector<ast::Param>& params,
                     const PackModel& model) {
  const std::string cls = rule_class(name);
  w.open(cls + "::" + cls + "(const Params& pack) : pack_(pack) {");
  if (!params.empty()) {
    w.open("specs_ = {");
    write_param_specs(w, params, false, model);
    w.close("};");
  }
  w.close();
  w.line();
  w.open("bool " + cls +
         "::apply(rift::GMap& g, std::span<const rift::Dart> hooks, std::span<const rift::Value> "
         "args, std::vector<rift::Dart>& touched) {");
  w.open("if (args.size() != " + std::to_string(params.size()) + ") {");
  w.line(
      "throw std::invalid_argument(" +
      quote("rule '" + name + "' takes " + std::to_string(params.size()) + " argument(s), got ") +
      " + std::to_string(args.size()));");
  w.close();
  w.line(name + "_args a;");
  for (std::size_t k = 0; k < params.size(); ++k) {
    const ast::Param& p = params[k];
    w.line("a." + member_name(p.name.text) + " = value_as<" + cpp_type(p.type) + ">(args[" +
           std::to_string(k) + "], " +
           quote("argument '" + p.name.text + "' of rule '" + name + "'") + ");");
  }
  w.line("return " + rule_function(name) + "(g, hooks, a, pack_, &touched);");
  w.close();
  w.line();
}

}  // namespace rift::emit
