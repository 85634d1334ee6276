// Interactions become force kernels for rift::CachedInteraction: a Match is a
// fixed-size record of the slots the force loop reads (vertex slots index
// the integrator's stage arrays ForceInput::x / ::v and the force array f),
// match() walks the explicit pattern from the support dart (or from the dart
// tagged at initialisation), and add_forces() / energy() are straight-line
// code over those slots: no traversal, no allocation, no virtual call.
#include <algorithm>

#include "check/kernels.hpp"
#include "emit/emit_context.hpp"
#include "emit/names.hpp"
#include "lower/kernel_plan.hpp"

namespace rift::emit {

namespace {

std::string slot_field(int k) {
  return "s" + std::to_string(k);
}

/// The raw column pointer add_forces_all() hoists out of its loop.
std::string column_pointer(const std::string& embedding) {
  return "c_" + embedding;
}

std::string dart_path(const std::string& node, const std::vector<int>& hops) {
  std::string d = dart_name(node);
  for (int h : hops)
    d = "g.alpha(" + d + ", " + std::to_string(h) + ")";
  return d;
}

std::string path_text(const std::string& node, const std::vector<int>& hops) {
  std::string out = node;
  for (int h : hops) {
    out += '@';
    out += std::to_string(h);
  }
  return out;
}

std::string orbit_text(const std::vector<int>& dims) {
  std::string out = "<";
  for (std::size_t k = 0; k < dims.size(); ++k) {
    if (k) out += ',';
    out += std::to_string(dims[k]);
  }
  out += '>';
  return out;
}

struct KernelModel {
  const ast::Interaction* inter = nullptr;
  lower::KernelPlan plan;
  std::set<std::string> embeddings;  // every embedding the kernel binds
  std::string cls;                   // StretchKernel
};

KernelModel model_of(const check::CheckedInteraction& ci, const PackModel& model) {
  KernelModel k;
  k.inter = ci.interaction;
  k.plan = lower::plan_kernel(ci, *model.symbols);
  k.cls = kernel_class(ci.interaction->name.text);
  for (const lower::SlotUse& s : k.plan.slots)
    k.embeddings.insert(s.via);
  for (const lower::ForceStore& f : k.plan.forces)
    k.embeddings.insert(f.embedding);
  std::set<std::string> loop;  // read in the force loop; the stage arrays replace these two
  for (const auto& l : k.inter->lets)
    embeddings_read(*l.value, loop);
  for (const auto& e : k.inter->whens)
    embeddings_read(*e, loop);
  for (const auto& f : k.inter->forces)
    embeddings_read(*f.value, loop);
  if (k.inter->energy) embeddings_read(*k.inter->energy, loop);
  loop.erase(check::kVelocityEmbedding);
  k.embeddings.insert(loop.begin(), loop.end());
  for (const ast::Init& init : k.inter->inits) {
    embeddings_read(*init.value, k.embeddings);
    k.embeddings.insert(init.embedding.text);
  }
  return k;
}

/// Expressions of the force loop: positions and velocities from the stage
/// arrays, every other value from its column, all through the match's slots.
ExprContext loop_context(const KernelModel& k, bool hoisted = false) {
  ExprContext ctx;
  ctx.dart = [](const std::string& node) { return dart_name(node); };
  ctx.args = "p_";
  ctx.params = "pack_";
  const lower::KernelPlan* plan = &k.plan;
  ctx.read = [plan, nodes = k.plan.nodes, hoisted](const ast::Expr& e) {
    int node = -1;
    for (std::size_t v = 0; v < nodes.size(); ++v) {
      if (nodes[v] == e.node) node = static_cast<int>(v);
    }
    std::vector<int> orbit = e.embedding->orbit.dims;
    std::sort(orbit.begin(), orbit.end());
    const int slot = plan->find(node, e.hops, orbit);
    const std::string at = "m." + slot_field(slot);
    if (e.name == check::kPositionEmbedding) return "in.x[" + at + "]";
    if (e.name == check::kVelocityEmbedding) return "in.v[" + at + "]";
    if (hoisted) return column_pointer(e.name) + "[" + at + "]";
    return embedding_var(e.name) + ".values()[" + at + "]";
  };
  return ctx;
}

ExprContext init_context() {
  ExprContext ctx;
  ctx.dart = [](const std::string& node) { return dart_name(node); };
  ctx.args = "p_";
  ctx.params = "pack_";
  return ctx;
}

void bind_nodes(Writer& w, const KernelModel& k) {
  for (std::size_t v = 0; v < k.plan.nodes.size(); ++v) {
    w.line("[[maybe_unused]] const rift::Dart " + dart_name(k.plan.nodes[v]) + " = darts[" +
           std::to_string(v) + "];");
  }
}

void write_find(Writer& w, const KernelModel& k) {
  const lower::KernelPlan& plan = k.plan;
  w.open("bool " + k.cls +
         "::find(const rift::GMap& g, rift::Dart support, rift::Dart* darts) const {");
  const std::string hook = dart_name(plan.nodes[static_cast<std::size_t>(plan.match.hooks[0])]);
  if (k.inter->tagged) {
    w.line("const rift::Dart " + hook + " = tagged_dart(g, tag_, support, kSupport);");
    w.line("if (" + hook + " == rift::kNoDart) return false;  // created after initialisation");
  } else {
    w.line("const rift::Dart " + hook + " = support;");
  }
  for (const lower::Follow& f : plan.match.follows) {
    w.line("const rift::Dart " + dart_name(plan.nodes[static_cast<std::size_t>(f.to)]) +
           " = g.alpha(" + dart_name(plan.nodes[static_cast<std::size_t>(f.from)]) + ", " +
           std::to_string(f.dim) + ");");
  }
  for (const lower::ArcCheck& a : plan.match.arc_checks) {
    w.line("if (g.alpha(" + dart_name(plan.nodes[static_cast<std::size_t>(a.a)]) + ", " +
           std::to_string(a.dim) + ") != " + dart_name(plan.nodes[static_cast<std::size_t>(a.b)]) +
           ") return false;");
  }
  // Injective: no dart plays two nodes (a cut edge makes a -2- b meet itself).
  for (std::size_t x = 0; x < plan.nodes.size(); ++x) {
    for (std::size_t y = x + 1; y < plan.nodes.size(); ++y) {
      w.line("if (" + dart_name(plan.nodes[x]) + " == " + dart_name(plan.nodes[y]) +
             ") return false;");
    }
  }
  for (std::size_t v = 0; v < plan.nodes.size(); ++v)
    w.line("darts[" + std::to_string(v) + "] = " + dart_name(plan.nodes[v]) + ";");
  w.line("return true;");
  w.close();
  w.line();
}

void write_initialise(Writer& w, const KernelModel& k, const PackModel& model) {
  const std::string user = "interaction '" + k.inter->name.text + "'";
  w.open("void " + k.cls + "::initialise(rift::GMap& g) {");
  w.line(model.pack_namespace + "::declare_embeddings(g);");
  for (const std::string& name : k.embeddings) {
    const ast::Embedding* emb = model.symbols->embedding(name);
    w.line(embedding_var(name) + " = require_embedding<" + storage_type(emb->type) + ">(g, " +
           quote(name) + ", " + quote(user) + ");");
  }
  if (k.inter->tagged) {
    w.line("// §3.2: the dart each element is first matched from fixes the order of its corners.");
    w.line("tag_ = require_embedding<rift::Bool>(g, " + quote(tag_embedding(k.inter->name.text)) +
           ", " + quote(user) + ");");
    w.line("std::fill(tag_.values().begin(), tag_.values().end(), rift::Bool(false));");
    w.line("g.for_each_cell(kSupport, [&](rift::Dart d) { tag_[d] = true; });");
  }
  const ExprContext ctx = init_context();
  const std::string n = std::to_string(k.plan.nodes.size());
  for (const ast::Init& init : k.inter->inits) {
    w.line("// init " + init.embedding.text + ", once per match");
    w.open("g.for_each_cell(kSupport, [&](rift::Dart support) {");
    w.line("rift::Dart darts[" + n + "];");
    w.line("if (!find(g, support, darts)) return;");
    bind_nodes(w, k);
    write_sourced(w, init.value->loc,
                  embedding_var(init.embedding.text) + "[" + dart_name(init.dart.text) + "] = " +
                      convert(emit_expr(*init.value, ctx), init.value->type, init.target->type) +
                      ";");
    w.close("});");
  }
  w.close();
  w.line();
}

void write_match(Writer& w, const KernelModel& k) {
  w.open("bool " + k.cls + "::match(const rift::GMap& g, rift::Dart support, Match& m) const {");
  w.line("rift::Dart darts[" + std::to_string(k.plan.nodes.size()) + "];");
  w.line("if (!find(g, support, darts)) return false;");
  bind_nodes(w, k);
  for (std::size_t s = 0; s < k.plan.slots.size(); ++s) {
    const lower::SlotUse& u = k.plan.slots[s];
    w.line("m." + slot_field(static_cast<int>(s)) + " = " + embedding_var(u.via) + ".slot(" +
           dart_path(k.plan.nodes[static_cast<std::size_t>(u.node)], u.hops) + ");");
  }
  w.line("return true;");
  w.close();
  w.line();
}

void write_loop_prologue(Writer& w, const KernelModel& k, const ExprContext& ctx,
                         const std::string& on_fail) {
  write_lets(w, k.inter->lets, ctx);
  for (const auto& cond : k.inter->whens) {
    write_sourced(w, cond->loc, "if (!(" + emit_expr(*cond, ctx) + ")) " + on_fail);
  }
}

void write_add_forces(Writer& w, const KernelModel& k) {
  const ExprContext ctx = loop_context(k);
  w.open("void " + k.cls +
         "::add_forces([[maybe_unused]] const Match& m, [[maybe_unused]] const rift::ForceInput& "
         "in, [[maybe_unused]] rift::Vec3* f, [[maybe_unused]] bool store) {");
  write_loop_prologue(w, k, ctx, "{ if (store) reset_stored(m); return; }");
  for (std::size_t i = 0; i < k.inter->forces.size(); ++i) {
    const ast::Assign& a = k.inter->forces[i];
    const lower::ForceStore& fs = k.plan.forces[i];
    const std::string var = "force_" + std::to_string(i);
    write_sourced(w, a.value->loc,
                  "const rift::Vec3 " + var + " = " + emit_expr(*a.value, ctx) + ";");
    w.line("f[m." + slot_field(fs.vertex_slot) + "] += " + var + ";");
    w.line("if (store) " + embedding_var(fs.embedding) + ".values()[m." +
           slot_field(fs.store_slot) + "] = " + var + ";");
  }
  w.close();
  w.line();
}

// The whole force pass in one function: column pointers are loaded once
// instead of once per match (stores through Vec3* may alias anything, so the
// compiler cannot hoist them itself), and the loop body is inlined.
void write_add_forces_all(Writer& w, const KernelModel& k, const PackModel& model) {
  const ExprContext ctx = loop_context(k, true);
  w.open("void " + k.cls +
         "::add_forces_all(std::span<const Match> ms, [[maybe_unused]] const rift::ForceInput& in, "
         "[[maybe_unused]] rift::Vec3* f, [[maybe_unused]] bool store) {");
  for (const std::string& name : k.embeddings) {
    w.line("[[maybe_unused]] " + storage_type(model.symbols->embedding(name)->type) + "* const " +
           column_pointer(name) + " = " + embedding_var(name) + ".values().data();");
  }
  w.open("for (const Match& m : ms) {");
  std::string reset = "{ if (store) { ";
  for (const lower::ForceStore& fs : k.plan.forces) {
    reset += column_pointer(fs.embedding) + "[m." + slot_field(fs.store_slot) +
             "] = rift::Vec3::Zero(); ";
  }
  reset += "} continue; }";
  write_loop_prologue(w, k, ctx, reset);
  for (std::size_t i = 0; i < k.inter->forces.size(); ++i) {
    const ast::Assign& a = k.inter->forces[i];
    const lower::ForceStore& fs = k.plan.forces[i];
    const std::string var = "force_" + std::to_string(i);
    write_sourced(w, a.value->loc,
                  "const rift::Vec3 " + var + " = " + emit_expr(*a.value, ctx) + ";");
    w.line("f[m." + slot_field(fs.vertex_slot) + "] += " + var + ";");
    w.line("if (store) " + column_pointer(fs.embedding) + "[m." + slot_field(fs.store_slot) +
           "] = " + var + ";");
  }
  w.close();
  w.close();
  w.line();
}

void write_reset(Writer& w, const KernelModel& k) {
  w.open("void " + k.cls + "::reset_stored([[maybe_unused]] const Match& m) {");
  for (const lower::ForceStore& fs : k.plan.forces) {
    const std::string col = embedding_var(fs.embedding) + ".values()";
    const std::string at = "m." + slot_field(fs.store_slot);
    w.line("if (" + at + " < " + col + ".size()) " + col + "[" + at + "] = rift::Vec3::Zero();");
  }
  w.close();
  w.line();
}

void write_energy(Writer& w, const KernelModel& k) {
  const ExprContext ctx = loop_context(k);
  w.open("rift::Real " + k.cls +
         "::energy([[maybe_unused]] const Match& m, [[maybe_unused]] const rift::ForceInput& in) "
         "const {");
  if (k.inter->energy) {
    write_loop_prologue(w, k, ctx, "return 0;");
    write_sourced(
        w, k.inter->energy->loc,
        "return " +
            convert(emit_expr(*k.inter->energy, ctx), k.inter->energy->type, ast::Type::Real) +
            ";");
  } else {
    w.line("return 0;");
  }
  w.close();
  w.line();
}

}  // namespace

std::string tag_embedding(std::string_view interaction) {
  return std::string(interaction) + "_first_dart";
}

void declare_kernel(Writer& w, const check::CheckedInteraction& ci, const PackModel& model) {
  const KernelModel k = model_of(ci, model);
  const ast::Interaction& inter = *ci.interaction;
  const std::string params = component_params_struct(inter.name.text);
  declare_component_params(w, params, inter.params);
  w.line("/// Interaction '" + inter.name.text + "' on " + orbit_text(inter.support.dims) +
         (inter.tagged ? ", tagged" : "") + ": a kernel for rift::CachedInteraction.");
  w.open("class " + k.cls + " {");
  w.middle(" public:");
  w.line("/// The slots a match caches (trivially copyable, fixed size).");
  w.open("struct Match {");
  for (std::size_t s = 0; s < k.plan.slots.size(); ++s) {
    const lower::SlotUse& u = k.plan.slots[s];
    w.line("rift::Slot " + slot_field(static_cast<int>(s)) + " = rift::kNoSlot;  // " +
           (u.vertex ? std::string("vertex") : orbit_text(u.orbit)) + " of " +
           path_text(k.plan.nodes[static_cast<std::size_t>(u.node)], u.hops));
  }
  w.close("};");
  w.line("static constexpr rift::Orbit kSupport = " + orbit_code(inter.support.dims) + ";");
  w.line("/// Links from the support dart to the farthest dart a match reads.");
  w.line("static constexpr int kRadius = " + std::to_string(k.plan.radius) + ";");
  w.line("static constexpr bool kTagged = " + std::string(inter.tagged ? "true" : "false") + ";");
  w.line();
  w.line("explicit " + k.cls + "(const " + params + "& p = {}, const Params& pack = {})");
  w.line("    : p_(p), pack_(pack) {}");
  w.line("const std::string& name() const { return name_; }");
  w.line("const " + params + "& params() const { return p_; }");
  w.line("/// Declares the pack's embeddings the map lacks, binds them" +
         std::string(inter.tagged ? ", tags the first dart of every support orbit" : "") +
         " and runs the interaction's inits.");
  w.line("void initialise(rift::GMap& g);");
  w.line("bool match(const rift::GMap& g, rift::Dart support, Match& m) const;");
  w.line("void add_forces(const Match& m, const rift::ForceInput& in, rift::Vec3* f, bool store);");
  w.line("/// add_forces over every match, with the columns read once.");
  w.line(
      "void add_forces_all(std::span<const Match> ms, const rift::ForceInput& in, rift::Vec3* f, "
      "bool store);");
  w.line("void reset_stored(const Match& m);");
  w.line("rift::Real energy(const Match& m, const rift::ForceInput& in) const;");
  w.line();
  w.middle(" private:");
  w.line(
      "/// The pattern's darts from one support dart, in pattern order; false when it does not "
      "match.");
  w.line("bool find(const rift::GMap& g, rift::Dart support, rift::Dart* darts) const;");
  w.line("std::string name_ = " + quote(inter.name.text) + ";");
  w.line(params + " p_;");
  w.line("Params pack_;");
  for (const std::string& name : k.embeddings) {
    w.line("rift::Embedding<" + storage_type(model.symbols->embedding(name)->type) + "> " +
           embedding_var(name) + ";");
  }
  if (inter.tagged) w.line("rift::Embedding<rift::Bool> tag_;");
  w.close("};");
  w.line("using " + interaction_class(inter.name.text) + " = rift::CachedInteraction<" + k.cls +
         ">;");
  w.line();
}

void emit_kernel(Writer& w, const check::CheckedInteraction& ci, const PackModel& model) {
  const KernelModel k = model_of(ci, model);
  w.line("// ---- interaction '" + k.inter->name.text + "'");
  w.line();
  write_find(w, k);
  write_initialise(w, k, model);
  write_match(w, k);
  write_add_forces(w, k);
  write_add_forces_all(w, k, model);
  write_reset(w, k);
  write_energy(w, k);
}

}  // namespace rift::emit
