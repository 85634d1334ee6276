// Interactions become force kernels for rift::CachedInteraction: a Match is a
// fixed-size record of the slots the force loop reads (vertex slots index
// the integrator's stage arrays ForceInput::x / ::v and the force array f),
// match() walks the explicit pattern from the support dart (or from the dart
// tagged at initialisation), and add_forces() / energy() are straight-line
// code over those slots: no traversal, no allocation, no virtual call.
#include <algorithm>

#include "check/kernels.hpp"
#include "emit/derivative_emit.hpp"
#include "emit/emit_context.hpp"
#include "emit/names.hpp"
#include "lower/derivative.hpp"
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
  lower::DerivativePlan derivative;  // Jacobians for implicit integrators
  std::set<std::string> embeddings;  // every embedding the kernel binds
  std::string cls;                   // StretchKernel
};

KernelModel model_of(const check::CheckedInteraction& ci, const PackModel& model) {
  KernelModel k;
  k.inter = ci.interaction;
  k.plan = lower::plan_kernel(ci, *model.symbols);
  k.derivative = lower::plan_derivative(*ci.interaction, k.plan);
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

/// The Jacobian vertex (0..k-1) of a position or velocity read.
int jacobian_vertex(const KernelModel& k, const ast::Expr& read) {
  int node = -1;
  for (std::size_t v = 0; v < k.plan.nodes.size(); ++v) {
    if (k.plan.nodes[v] == read.node) node = static_cast<int>(v);
  }
  std::vector<int> orbit = read.embedding->orbit.dims;
  std::sort(orbit.begin(), orbit.end());
  const int slot = k.plan.find(node, read.hops, orbit);
  const auto& vs = k.derivative.vertex_slots;
  return static_cast<int>(std::find(vs.begin(), vs.end(), slot) - vs.begin());
}

int jacobian_vertex_of_slot(const KernelModel& k, int slot) {
  const auto& vs = k.derivative.vertex_slots;
  return static_cast<int>(std::find(vs.begin(), vs.end(), slot) - vs.begin());
}

/// Tangent lets (one per active let, after the force computation's lets),
/// then `per_force(i, tangent)` for each force with a nonzero tangent.
template <class PerForce>
void write_tangents(Writer& w, const KernelModel& k, const ExprContext& primal,
                    PerForce&& per_force) {
  TangentContext t;
  t.primal = &primal;
  t.lets = &k.inter->lets;
  t.active_let = &k.derivative.active_let;
  t.state_tangent = [&k](const ast::Expr& read) {
    const std::string j = std::to_string(jacobian_vertex(k, read));
    return std::string(read.name == check::kPositionEmbedding ? "tx[" : "tv[") + j + "]";
  };
  for (std::size_t i = 0; i < k.inter->lets.size(); ++i) {
    if (!k.derivative.active_let[i]) continue;
    const ast::Let& l = k.inter->lets[i];
    std::string code = tangent_expr(*l.value, t);
    if (code.empty()) code = cpp_type(l.value->type) + "(" + cpp_type(l.value->type) + "::Zero())";
    write_sourced(w, l.value->loc,
                  "[[maybe_unused]] const " + cpp_type(l.value->type) + " " +
                      tangent_name(l.name.text) + " = " + code + ";");
  }
  for (std::size_t i = 0; i < k.inter->forces.size(); ++i) {
    const std::string code = tangent_expr(*k.inter->forces[i].value, t);
    if (!code.empty()) per_force(i, code);
  }
}

void write_vertex_slots(Writer& w, const KernelModel& k) {
  w.open("void " + k.cls + "::vertex_slots(const Match& m, rift::Slot* out) const {");
  for (std::size_t j = 0; j < k.derivative.vertex_slots.size(); ++j) {
    w.line("out[" + std::to_string(j) + "] = m." + slot_field(k.derivative.vertex_slots[j]) + ";");
  }
  w.close();
  w.line();
}

// Dense blocks by forward mode: one tangent pass per direction (a
// coordinate of one vertex's position or velocity), each giving one column
// of the blocks of every force. Directions the forces do not depend on
// (velocities of an undamped law) are skipped.
void write_jacobian(Writer& w, const KernelModel& k) {
  const ExprContext ctx = loop_context(k);
  const int n = static_cast<int>(k.derivative.vertex_slots.size());
  const std::string kk = std::to_string(n * n), k3 = std::to_string(3 * n);
  w.open("void " + k.cls +
         "::jacobian([[maybe_unused]] const Match& m, [[maybe_unused]] const rift::ForceInput& in, "
         "rift::Mat3* dfdx, rift::Mat3* dfdv) {");
  w.open("for (int b = 0; b < " + kk + "; ++b) {");
  w.line("dfdx[b].setZero();");
  w.line("dfdv[b].setZero();");
  w.close();
  write_loop_prologue(w, k, ctx, "return;");
  const std::string first = k.derivative.depends_on_x ? "0" : k3;
  const std::string last = k.derivative.depends_on_v ? std::to_string(6 * n) : k3;
  w.open("for (int dir = " + first + "; dir < " + last + "; ++dir) {");
  w.line("const bool wrt_x = dir < " + k3 + ";");
  w.line("const int j = (dir % " + k3 + ") / 3, c = dir % 3;");
  w.line("rift::Vec3 tx[" + std::to_string(n) + "], tv[" + std::to_string(n) + "];");
  w.open("for (int v = 0; v < " + std::to_string(n) + "; ++v) {");
  w.line("tx[v].setZero();");
  w.line("tv[v].setZero();");
  w.close();
  w.line("(wrt_x ? tx : tv)[j][c] = 1;");
  write_tangents(w, k, ctx, [&](std::size_t i, const std::string& code) {
    const int vi = jacobian_vertex_of_slot(k, k.plan.forces[i].vertex_slot);
    w.line("(wrt_x ? dfdx : dfdv)[" + std::to_string(vi * n) + " + j].col(c) += rift::Vec3(" +
           code + ");");
  });
  w.close();
  w.close();
  w.line();
}

// J·p in one tangent pass seeded with p's values at the match's vertices.
void write_jacobian_product(Writer& w, const KernelModel& k) {
  const ExprContext ctx = loop_context(k);
  const int n = static_cast<int>(k.derivative.vertex_slots.size());
  w.open("void " + k.cls +
         "::jacobian_product([[maybe_unused]] const Match& m, [[maybe_unused]] const "
         "rift::ForceInput& in, [[maybe_unused]] const rift::Vec3* px, [[maybe_unused]] const "
         "rift::Vec3* pv, rift::Vec3* out) {");
  write_loop_prologue(w, k, ctx, "return;");
  std::string tx = "[[maybe_unused]] const rift::Vec3 tx[" + std::to_string(n) + "] = {";
  std::string tv = "[[maybe_unused]] const rift::Vec3 tv[" + std::to_string(n) + "] = {";
  for (int j = 0; j < n; ++j) {
    const std::string at =
        "m." + slot_field(k.derivative.vertex_slots[static_cast<std::size_t>(j)]);
    tx += (j ? ", " : "") + std::string("px[") + at + "]";
    tv += (j ? ", " : "") + std::string("pv[") + at + "]";
  }
  w.line(tx + "};");
  w.line(tv + "};");
  write_tangents(w, k, ctx, [&](std::size_t i, const std::string& code) {
    w.line("out[m." + slot_field(k.plan.forces[i].vertex_slot) + "] += rift::Vec3(" + code + ");");
  });
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
  if (k.derivative.available) {
    w.line("/// Jacobians derived by riftc (forward mode): the match's vertices, the blocks");
    w.line("/// df_i/dx_j and df_i/dv_j (row-major), and the product J p.");
    w.line("static constexpr int kJacobianVertices = " +
           std::to_string(k.derivative.vertex_slots.size()) + ";");
    w.line("void vertex_slots(const Match& m, rift::Slot* out) const;");
    w.line(
        "void jacobian(const Match& m, const rift::ForceInput& in, rift::Mat3* dfdx, rift::Mat3* "
        "dfdv);");
    w.line(
        "void jacobian_product(const Match& m, const rift::ForceInput& in, const rift::Vec3* px, "
        "const rift::Vec3* pv, rift::Vec3* out);");
  } else {
    w.line("/// Why riftc formed no Jacobian (an implicit integrator reports it).");
    w.line("static constexpr const char* kJacobianUnavailable = " +
           quote(w.where(k.derivative.where) + "interaction '" + inter.name.text +
                 "' has no Jacobian: " + k.derivative.why) +
           ";");
  }
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
  if (k.derivative.available) {
    write_vertex_slots(w, k);
    write_jacobian(w, k);
    write_jacobian_product(w, k);
  }
}

}  // namespace rift::emit
