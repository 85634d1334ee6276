// Interactions become force kernels for rift::CachedInteraction: a Match is a
// fixed-size record of the slots the force loop reads (vertex slots index
// the integrator's stage arrays ForceInput::x / ::v and the force array f),
// match() walks the explicit pattern from the support dart (or from the dart
// tagged at initialisation), and the interaction's body is rendered once, as
// evaluate<kForces>(): straight-line code over those slots (no traversal, no
// allocation, no virtual call) that the force pass and energy() share.
#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "ast/orbit_text.hpp"
#include "emit/emit_context.hpp"
#include "emit/ir_render.hpp"
#include "emit/lanes.hpp"
#include "emit/names.hpp"
#include "lower/derivative.hpp"
#include "lower/interaction_plan.hpp"

namespace rift::emit {

namespace {

using lower::InteractionPlan;

/// rift::ReachWord::kMaxLinks (runtime/rift/sim/reach.hpp): a kernel with a
/// longer word gets no kReach, and is re-matched within its radius.
constexpr int kMaxReachLinks = 15;

using ast::orbit_text;
using ast::path_text;

/// Names of the match's slots, from the orbit and the dart: `vertex_a` for
/// the vertex of node a, `orbit0_b_1` for the orbit <0> of b@1, `dart_c`.
/// Every embedding on that orbit is read through it.
std::vector<std::string> slot_names(const lower::KernelPlan& plan) {
  std::vector<std::string> names;
  for (const lower::SlotUse& u : plan.slots) {
    std::string name = u.vertex ? "vertex" : u.orbit.empty() ? "dart" : "orbit";
    if (!u.vertex) {
      for (int d : u.orbit)
        name += std::to_string(d);
    }
    name += '_';
    name += plan.nodes[static_cast<std::size_t>(u.node)];
    for (int h : u.hops) {
      name += '_';
      name += std::to_string(h);
    }
    if (std::find(names.begin(), names.end(), name) != names.end())
      name += std::string("_s") + std::to_string(names.size());
    names.push_back(name);
  }
  return names;
}

/// The field of Result a force is returned in: `f_stretch_a`.
std::string force_field(const ir::Body& body, const ir::Force& f) {
  return f.embedding + "_" + body.nodes[static_cast<std::size_t>(f.node)];
}

/// The earlier force whose value force i's is the negation of (`force b.f =
/// -l_f` after `force a.f = l_f`: the body is shared, so both read one node),
/// or -1. A scatter subtracts that force instead of adding this one: x - y
/// is exactly x + (-y), and count * (-y) exactly -(count * y), so the same
/// bits for three negations and (grouped) three products fewer.
int negated_force(const ir::Body& b, std::size_t i) {
  const ir::Node& n = b.graph[b.forces[i].value];
  if (n.op != ir::Op::Neg) return -1;
  for (std::size_t j = 0; j < i; ++j) {
    if (b.forces[j].value == n.operand(0)) return static_cast<int>(j);
  }
  return -1;
}

/// The field of Result a `store` is returned in: `stored_fem_stress_c0`.
std::string store_field(const ir::Body& body, const ir::Store& st) {
  return "stored_" + st.embedding + "_" + body.nodes[static_cast<std::size_t>(st.node)];
}

bool accumulates(const ir::Body& b) {
  return std::any_of(b.stores.begin(), b.stores.end(),
                     [](const ir::Store& st) { return st.accumulate; });
}

struct Kernel {
  const InteractionPlan* plan = nullptr;
  const ast::Interaction* inter = nullptr;
  std::string cls;
  std::vector<std::string> slots;
  std::set<std::string> columns;                // embeddings the body reads through column pointers
  std::set<std::pair<std::string, int>> reads;  // (embedding, slot) the forces depend on
  bool reads_state = false;                     // the body reads ForceInput (positions, velocities)
  lower::DerivativePlan derivative;             // Jacobians for implicit integrators
  // Per slot: only a stored force or a `store` writes it and nothing reads it.
  // Such slots are cached apart, in Stored, which an interaction that does not
  // store does not keep (rift::CachedInteraction).
  std::vector<bool> stored_only;
  // Embeddings only those slots reach: bound only when the interaction stores,
  // so that a scene that stores nothing leaves their orbit's attachment
  // without slots (rift::GMap's dormant attachments).
  std::set<std::string> store_only_embeddings;
  // The body has a lanes form (emit/lanes.hpp): the force passes without
  // stores evaluate rift::lanes::kWidth matches at once.
  bool lanes = false;
};

/// The embeddings a body's forces are stored in, each once.
std::set<std::string> force_embeddings(const ir::Body& b) {
  std::set<std::string> names;
  for (const ir::Force& f : b.forces)
    names.insert(f.embedding);
  return names;
}

/// Where the force pass finds slot s: the match's field or, for a slot only
/// stores write, the field of its Stored `stored` (e.g. "ss[i]" or "s").
std::string slot_at(const Kernel& k, int s, const std::string& stored) {
  const auto i = static_cast<std::size_t>(s);
  return (k.stored_only[i] ? stored + "." : std::string("m.")) + k.slots[i];
}

Kernel kernel_of(const InteractionPlan& plan) {
  Kernel k;
  k.plan = &plan;
  k.inter = plan.interaction;
  k.cls = kernel_class(k.inter->name.text);
  k.slots = slot_names(plan.kernel);
  k.derivative = lower::plan_derivative(plan.body, plan.kernel, k.inter->name.loc);
  k.lanes = renders_in_lanes(plan.body);
  const ir::Body& b = plan.body;
  auto scan = [&](ir::ExprId root) {
    if (root == ir::kNoExpr) return;
    ir::visit(b.graph, root, [&](const ir::Node& n) {
      if (n.op == ir::Op::Read) k.columns.insert(n.embedding);
      if (n.op == ir::Op::Position || n.op == ir::Op::Velocity) k.reads_state = true;
    });
  };
  for (const ir::Let& l : b.lets)
    scan(l.value);
  for (const ir::Stmt& s : b.stmts)
    scan(s.cond);
  for (const ir::Force& f : b.forces)
    scan(f.value);
  for (const ir::Store& st : b.stores)
    scan(st.value);
  scan(b.energy);
  // What the forces depend on besides the state: every read of the lets,
  // whens and forces (the energy is never grouped).
  auto scan_reads = [&](ir::ExprId root) {
    if (root == ir::kNoExpr) return;
    ir::visit(b.graph, root, [&](const ir::Node& n) {
      if (n.op == ir::Op::Read) k.reads.insert({n.embedding, n.place.slot});
    });
  };
  for (const ir::Let& l : b.lets)
    scan_reads(l.value);
  for (const ir::Stmt& s : b.stmts)
    scan_reads(s.cond);
  for (const ir::Force& f : b.forces)
    scan_reads(f.value);
  const std::vector<lower::SlotUse>& uses = plan.kernel.slots;
  k.stored_only.assign(uses.size(), false);
  for (const ir::Force& f : b.forces)
    k.stored_only[static_cast<std::size_t>(f.store_slot)] = true;
  for (const ir::Store& st : b.stores)
    k.stored_only[static_cast<std::size_t>(st.store_slot)] = true;
  for (std::size_t s = 0; s < uses.size(); ++s)
    if (uses[s].vertex) k.stored_only[s] = false;
  for (const ir::Force& f : b.forces)
    k.stored_only[static_cast<std::size_t>(f.vertex_slot)] = false;
  for (int s : k.derivative.vertex_slots)
    k.stored_only[static_cast<std::size_t>(s)] = false;
  // Any read through a slot keeps it in the match (every node of the body,
  // whether or not a root reaches it: the conservative choice).
  for (std::size_t i = 0; i < b.graph.size(); ++i) {
    const ir::Node& n = b.graph[static_cast<ir::ExprId>(i)];
    if (n.place.slot >= 0 && static_cast<std::size_t>(n.place.slot) < uses.size())
      k.stored_only[static_cast<std::size_t>(n.place.slot)] = false;
  }
  std::set<std::string> written;
  for (const ir::Force& f : b.forces)
    written.insert(f.embedding);
  for (const ir::Store& st : b.stores)
    written.insert(st.embedding);
  std::set<std::string> kept = k.columns;  // read by the body
  for (const lower::InitPlan& init : plan.inits) {
    kept.insert(init.embedding);
    ir::visit(b.graph, init.value, [&](const ir::Node& n) {
      if (n.op == ir::Op::Read || n.op == ir::Op::Fold) kept.insert(n.embedding);
    });
  }
  for (std::size_t s = 0; s < uses.size(); ++s)
    if (!k.stored_only[s]) kept.insert(uses[s].via);
  for (const std::string& e : written)
    if (!kept.contains(e) && plan.embeddings.contains(e)) k.store_only_embeddings.insert(e);
  return k;
}

bool has_stored_slots(const Kernel& k) {
  return std::find(k.stored_only.begin(), k.stored_only.end(), true) != k.stored_only.end();
}

/// Words of a group key: one per vertex slot, then the values read.
int group_key_words(const Kernel& k, const PackModel& model) {
  int words = 0;
  for (const lower::SlotUse& u : k.plan->kernel.slots)
    if (u.vertex) ++words;
  for (const auto& [name, slot] : k.reads) {
    const ast::Type t = model.plan->embedding_types.at(name);
    words += t == ast::Type::Vec3 ? 3 : t == ast::Type::Mat3 ? 9 : 1;
  }
  return words;
}

/// The match's vertex slots (Match fields), in the Match's order.
std::vector<std::string> vertex_fields(const Kernel& k) {
  std::vector<std::string> out;
  const lower::KernelPlan& plan = k.plan->kernel;
  for (std::size_t s = 0; s < plan.slots.size(); ++s)
    if (plan.slots[s].vertex) out.push_back(k.slots[s]);
  return out;
}

/// An untagged kernel with forces chooses the dart its support orbit is
/// matched from by its vertices (rift::generated::smallest_support_match).
bool chooses_support_dart(const Kernel& k) {
  return !k.inter->tagged && !k.plan->body.forces.empty() && !vertex_fields(k).empty();
}

/// A kernel with inits and forces hands each match its inits find to a
/// rift::SupportSink (rift/sim/support_sink.hpp): the support dart and the
/// pattern's darts. The simulator's match cache then takes the match from
/// them, without choosing the support dart or finding the pattern again.
bool hands_out_supports(const Kernel& k) {
  return !k.plan->body.forces.empty() && !k.plan->inits.empty();
}

/// Render context of the force loop: stage arrays and column pointers, by slot.
RenderContext loop_context(const Kernel& k) {
  RenderContext ctx;
  ctx.dart = [&k](int node) {
    return dart_name(k.plan->body.nodes[static_cast<std::size_t>(node)]);
  };
  ctx.args = "p_";
  ctx.params = "pack_";
  ctx.read = [&k](const ir::Node& n) {
    const std::string at = std::string("m.") + k.slots[static_cast<std::size_t>(n.place.slot)];
    if (n.op == ir::Op::Position) return std::string("in.x[") + at + "]";
    if (n.op == ir::Op::Velocity) return std::string("in.v[") + at + "]";
    return std::string("c.") + member_name(n.embedding) + "[" + at + "]";
  };
  return ctx;
}

/// Lets reachable from `root`, through the values of other lets.
void lets_used(const ir::Body& b, ir::ExprId root, std::vector<bool>& used) {
  if (root == ir::kNoExpr) return;
  ir::visit(b.graph, root, [&](const ir::Node& n) {
    if (n.op != ir::Op::Let || n.index < 0) return;
    const auto i = static_cast<std::size_t>(n.index);
    if (used[i]) return;
    used[i] = true;
    lets_used(b, b.lets[i].value, used);
  });
}

/// The values of the lets and the conditions of the whens, in source order.
std::vector<ir::ExprId> statement_roots(const ir::Body& b) {
  std::vector<ir::ExprId> roots;
  roots.reserve(b.stmts.size());
  for (const ir::Stmt& s : b.stmts)
    roots.push_back(s.kind == ir::Stmt::Kind::When ? s.cond
                                                   : b.lets[static_cast<std::size_t>(s.let)].value);
  return roots;
}

void write_find(Writer& w, const Kernel& k) {
  const lower::KernelPlan& plan = k.plan->kernel;
  auto node = [&](int v) { return dart_name(plan.nodes[static_cast<std::size_t>(v)]); };
  w.open("bool " + k.cls +
         "::find(const rift::GMap& g, rift::Dart support, rift::Dart* darts) const {");
  const std::string hook = node(plan.match.hooks[0]);
  if (k.inter->tagged) {
    // A kernel of a map never rewritten keeps no tag: it is matched only
    // from the dart the initialisation's walk gives, which is the one tagged.
    w.line("const rift::Dart " + hook +
           " = tag_ ? tagged_dart(g, tag_, support, kSupport) : support;");
    w.line("if (" + hook + " == rift::kNoDart) return false;  // created after initialisation");
  } else {
    w.line("const rift::Dart " + hook + " = support;");
  }
  for (const lower::Follow& f : plan.match.follows) {
    w.line("const rift::Dart " + node(f.to) + " = g.alpha(" + node(f.from) + ", " +
           std::to_string(f.dim) + ");");
  }
  for (const lower::ArcCheck& a : plan.match.arc_checks) {
    w.line("if (g.alpha(" + node(a.a) + ", " + std::to_string(a.dim) + ") != " + node(a.b) +
           ") return false;");
  }
  // Injective: no dart plays two nodes (a cut edge makes a -2- b meet
  // itself). One pair per class of pairs that collide together, given the
  // arcs checked above (lower/distinct_pairs.hpp).
  for (const auto& [x, y] : plan.distinct)
    w.line("if (" + node(x) + " == " + node(y) + ") return false;");
  for (std::size_t v = 0; v < plan.nodes.size(); ++v)
    w.line("darts[" + std::to_string(v) + "] = " + dart_name(plan.nodes[v]) + ";");
  w.line("return true;");
  w.close();
  w.line();
}

/// The inits of an interaction in passes over its matches: consecutive
/// inits share one pass (one cell walk and one find per match instead of one
/// each, most of a 10^6-hexahedron set-up's volume_shear) unless an init
/// reads an embedding an earlier init of the pass writes, which must then be
/// written at every match first. Within a pass each match runs the inits in
/// source order, and each embedding is written at the matches in the same
/// order as by a pass of its own: the same values.
std::vector<std::vector<const lower::InitPlan*>> init_passes(const InteractionPlan& plan) {
  std::vector<std::vector<const lower::InitPlan*>> passes;
  std::set<std::string> written;
  for (const lower::InitPlan& init : plan.inits) {
    bool reads_written = false;
    std::vector<ir::ExprId> roots{init.value};
    std::vector<bool> let_seen(plan.body.lets.size(), false);
    while (!roots.empty()) {
      const ir::ExprId root = roots.back();
      roots.pop_back();
      ir::visit(plan.body.graph, root, [&](const ir::Node& x) {
        if ((x.op == ir::Op::Read || x.op == ir::Op::Position || x.op == ir::Op::Velocity) &&
            written.contains(x.embedding)) {
          reads_written = true;
        }
        // A let's value is read where the let is (conservatively: any let).
        if (x.op == ir::Op::Let && x.index >= 0 && !let_seen[static_cast<std::size_t>(x.index)]) {
          let_seen[static_cast<std::size_t>(x.index)] = true;
          roots.push_back(plan.body.lets[static_cast<std::size_t>(x.index)].value);
        }
      });
    }
    if (passes.empty() || reads_written) {
      passes.emplace_back();
      written.clear();
    }
    passes.back().push_back(&init);
    written.insert(init.embedding);
  }
  return passes;
}

void write_initialise(Writer& w, const Kernel& k, const PackModel& model) {
  const InteractionPlan& plan = *k.plan;
  const ir::Body& b = plan.body;
  const std::string user = std::string("interaction '") + k.inter->name.text + "'";
  w.open("void " + k.cls + "::initialise(rift::GMap& g" +
         (hands_out_supports(k) ? ", rift::SupportSink sink" : "") + ") {");
  w.line(model.pack_namespace + "::declare_embeddings(g);");
  for (const std::string& name : plan.embeddings) {
    // Asking for a column wakes its orbit's attachment: not when nothing is stored.
    w.line(std::string(k.store_only_embeddings.contains(name) ? "if (store_) " : "") +
           embedding_var(name) + " = require_embedding<" + embedding_storage(model, name) +
           ">(g, " + quote(name) + ", " + quote(user) + ");");
  }
  if (k.inter->tagged) {
    w.line("// §3.2: the dart each element is first matched from fixes the order of its corners;");
    w.line("// only re-matching after a rewrite needs it marked.");
    w.open("if (rewrites_) {");
    w.line("tag_ = require_embedding<rift::Bool>(g, " + quote(tag_embedding(k.inter->name.text)) +
           ", " + quote(user) + ");");
    w.line("std::fill(tag_.values().begin(), tag_.values().end(), rift::Bool(false));");
    // With inits, their first pass tags each orbit's first dart before
    // matching from it: find() asks tagged_dart, which then answers that
    // dart, as after a pass of its own (one cell walk less).
    if (plan.inits.empty())
      w.line("g.for_each_cell(kSupport, [&](rift::Dart d) { tag_[d] = true; });");
    w.close("}");
  }
  RenderContext ctx;
  ctx.dart = [&b](int node) { return dart_name(b.nodes[static_cast<std::size_t>(node)]); };
  ctx.args = "p_";
  ctx.params = "pack_";
  const std::string n = std::to_string(plan.kernel.nodes.size());
  bool first_pass = true;
  for (const std::vector<const lower::InitPlan*>& group : init_passes(plan)) {
    // Only the darts these inits read or write are named.
    std::vector<bool> used(plan.kernel.nodes.size(), false);
    std::string what;
    for (const lower::InitPlan* init : group) {
      used[static_cast<std::size_t>(init->node)] = true;
      ir::visit(b.graph, init->value, [&](const ir::Node& x) {
        if ((x.op == ir::Op::Read || x.op == ir::Op::Fold) &&
            static_cast<std::size_t>(x.place.node) < used.size()) {
          used[static_cast<std::size_t>(x.place.node)] = true;
        }
      });
      what += (what.empty() ? "" : ", ") + init->embedding + "(" +
              b.nodes[static_cast<std::size_t>(init->node)] + ")";
    }
    w.line("// init " + what + ", once per match");
    if (chooses_support_dart(k)) {
      // The choice found the chosen dart's pattern already: not found again.
      w.open("g.for_each_cell(kSupport, [&](rift::Dart cell) {");
      w.line("rift::Dart darts[" + n + "];");
      w.line("const rift::Dart support = support_match(g, cell, darts);");
      w.line("if (support == rift::kNoDart) return;");
    } else {
      w.open("g.for_each_cell(kSupport, [&](rift::Dart support) {");
      if (k.inter->tagged && first_pass)
        w.line("if (rewrites_) tag_[support] = true;  // the orbit's first dart");
      w.line("rift::Dart darts[" + n + "];");
      w.line("if (!find(g, support, darts)) return;");
    }
    if (hands_out_supports(k) && first_pass) w.line("if (sink) sink(support, darts);");
    first_pass = false;
    for (std::size_t v = 0; v < used.size(); ++v) {
      if (!used[v]) continue;
      w.line("const rift::Dart " + dart_name(plan.kernel.nodes[v]) + " = darts[" +
             std::to_string(v) + "];");
    }
    for (const lower::InitPlan* init : group) {
      // Each init's locals in a block of their own when the pass runs several.
      if (group.size() > 1) w.open("{");
      BodyRenderer r(b.graph, b.sharing, ctx, {init->value});
      write_rendered(w, r, init->loc,
                     embedding_var(init->embedding) + "[" +
                         dart_name(b.nodes[static_cast<std::size_t>(init->node)]) + "] = ",
                     init->value, ";");
      if (group.size() > 1) w.close();
    }
    w.close("});");
  }
  w.close();
  w.line();
}

void write_match(Writer& w, const Kernel& k) {
  const lower::KernelPlan& plan = k.plan->kernel;
  w.open("bool " + k.cls +
         "::match(const rift::GMap& g, rift::Dart support, Match& m, Stored* s) const {");
  w.line("rift::Dart darts[" + std::to_string(plan.nodes.size()) + "];");
  w.line("if (!find(g, support, darts)) return false;");
  w.line("return match_found(g, darts, m, s);");
  w.close();
  w.line();
  // The slots of a match whose darts were found (by find, or by the inits).
  w.open("bool " + k.cls +
         "::match_found([[maybe_unused]] const rift::GMap& g, const rift::Dart* darts, Match& m, " +
         (has_stored_slots(k) ? "Stored* s" : "Stored* /*s*/") + ") const {");
  for (int pass = 0; pass < 2; ++pass) {
    // The match's slots, then (only when asked) those stores alone write.
    if (pass == 1 && has_stored_slots(k)) w.open("if (s) {");
    for (std::size_t s = 0; s < plan.slots.size(); ++s) {
      if (k.stored_only[s] != (pass == 1)) continue;
      const lower::SlotUse& u = plan.slots[s];
      std::string d = std::string("darts[") + std::to_string(u.node) + "]";
      for (int h : u.hops)
        d = std::string("g.alpha(") + d + ", " + std::to_string(h) + ")";
      w.line((pass == 1 ? "s->" : "m.") + k.slots[s] + " = " + embedding_var(u.via) + ".slot(" + d +
             ");");
    }
    if (pass == 1 && has_stored_slots(k)) w.close();
  }
  w.line("return true;");
  w.close();
  w.line();
}

// The dart a support orbit is matched from, the same for the inits and the
// simulator's match cache: the one binding the smallest vertex slots first.
// support_match also gives the pattern's darts found from it, which the inits
// would otherwise find a third time.
void write_support_dart(Writer& w, const Kernel& k) {
  const std::vector<std::string> fields = vertex_fields(k);
  const std::string n = std::to_string(k.plan->kernel.nodes.size());
  w.open("rift::Dart " + k.cls +
         "::support_match(const rift::GMap& g, rift::Dart d, rift::Dart* darts) const {");
  w.open("return smallest_support_match<" + std::to_string(fields.size()) + ", " + n +
         ">(g, d, kSupport, darts, [&](rift::Dart x, rift::Slot* key, rift::Dart* found) {");
  w.line("Match m{};");
  w.line("if (!find(g, x, found) || !match_found(g, found, m)) return false;");
  for (std::size_t i = 0; i < fields.size(); ++i)
    w.line("key[" + std::to_string(i) + "] = m." + fields[i] + ";");
  w.line("return true;");
  w.close("});");
  w.close();
  w.line();
  w.open("rift::Dart " + k.cls + "::support_dart(const rift::GMap& g, rift::Dart d) const {");
  w.line("rift::Dart darts[" + n + "];");
  w.line("const rift::Dart support = support_match(g, d, darts);");
  w.line("return support == rift::kNoDart ? d : support;");
  w.close();
  w.line();
}

void write_columns(Writer& w, const Kernel& k) {
  w.open(k.cls + "::Columns " + k.cls + "::columns() const {");
  if (k.columns.empty()) {
    w.line("return {};");
  } else {
    std::string init;
    for (const std::string& name : k.columns) {
      if (!init.empty()) init += ", ";
      init += embedding_var(name) + ".values().data()";
    }
    w.line("return {" + init + "};");
  }
  w.close();
  w.line();
}

// The body, once: lets and whens in source order, then the forces (kForces)
// or the energy. Both the force pass and energy() instantiate it inline.
void write_evaluate(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  const RenderContext ctx = loop_context(k);
  const bool has_energy = b.energy != ir::kNoExpr;
  // A let not read by every instantiation is marked so, and only then.
  std::vector<bool> by_when(b.lets.size()), by_force(b.lets.size()), by_energy(b.lets.size());
  for (const ir::Stmt& s : b.stmts)
    lets_used(b, s.cond, by_when);
  for (const ir::Force& f : b.forces)
    lets_used(b, f.value, by_force);
  lets_used(b, b.energy, by_energy);
  w.line(b.stores.empty() ? "template <bool kForces>" : "template <bool kForces, bool kStores>");
  w.open("inline bool " + k.cls + "::evaluate(" +
         std::string(k.slots.empty() ? "const Match& /*m*/" : "const Match& m") + ", " +
         (k.reads_state ? "const rift::ForceInput& in" : "const rift::ForceInput& /*in*/") + ", " +
         (k.columns.empty() ? "const Columns& /*c*/" : "const Columns& c") +
         ", Result& r) const {");
  std::vector<ir::ExprId> roots = statement_roots(b);
  for (const ir::Force& f : b.forces)
    roots.push_back(f.value);
  for (const ir::Store& st : b.stores)
    roots.push_back(st.value);
  roots.push_back(b.energy);
  BodyRenderer values(b.graph, b.sharing, ctx, roots);
  // Forces and stored values are the force pass's results (kForces).
  const bool results = !b.forces.empty() || !b.stores.empty();
  for (const ir::Stmt& s : b.stmts) {
    if (s.kind == ir::Stmt::Kind::When) {
      write_rendered(w, values, s.loc, "if (!", s.cond, ") return false;");
      continue;
    }
    const auto i = static_cast<std::size_t>(s.let);
    const ir::Let& l = b.lets[i];
    const bool in_forces = by_when[i] || by_force[i];
    const bool in_energy = by_when[i] || by_energy[i];
    const bool always = in_forces && (in_energy || !has_energy);
    write_rendered(w, values, l.loc,
                   std::string(always ? "" : "[[maybe_unused]] ") + "const " +
                       cpp_type(b.graph[l.value].type) + " " + let_name(l.name) + " = ",
                   l.value, ";");
    values.computed(l.value, let_name(l.name));
  }
  if (results && has_energy) {
    w.open("if constexpr (kForces) {");
  } else if (results) {
    w.open("{");
  }
  values.open_block();
  for (const ir::Force& f : b.forces)
    write_rendered(w, values, f.loc, "r." + force_field(b, f) + " = ", f.value, ";");
  if (!b.stores.empty()) {
    // Only on the evaluation whose forces are stored (the integrator's
    // other stages do not compute them).
    w.open("if constexpr (kStores) {");
    values.open_block();
    for (const ir::Store& st : b.stores)
      write_rendered(w, values, st.loc, "r." + store_field(b, st) + " = ", st.value, ";");
    values.close_block();
    w.close();
  }
  values.close_block();
  if (has_energy) {
    if (results) w.middle("} else {");
    if (!results) w.open("if constexpr (!kForces) {");
    values.open_block();
    write_rendered(w, values, k.inter->energy->loc, "r.energy = ", b.energy, ";");
    values.close_block();
  }
  if (results || has_energy) w.close();
  w.line("return true;");
  w.close();
  w.line();
}

// The body on rift::lanes::kWidth consecutive matches at once (lanes.hpp):
// the lets the whens and forces read, in source order, each a lane value;
// a `when` clears the lanes where it fails instead of returning. The force
// passes without stores run it over their matches kWidth at a time and add
// each lane's forces in the order of the matches, as the scalar loop does.
void write_evaluate_lanes(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  std::vector<bool> wanted(b.lets.size());
  for (const ir::Stmt& s : b.stmts)
    lets_used(b, s.cond, wanted);
  for (const ir::Force& f : b.forces)
    lets_used(b, f.value, wanted);
  std::vector<ir::ExprId> roots;
  for (const ir::Stmt& s : b.stmts) {
    if (s.kind == ir::Stmt::Kind::When) {
      roots.push_back(s.cond);
    } else if (wanted[static_cast<std::size_t>(s.let)]) {
      roots.push_back(b.lets[static_cast<std::size_t>(s.let)].value);
    }
  }
  for (const ir::Force& f : b.forces)
    roots.push_back(f.value);
  // The slots the lanes read, each gathered once from the kWidth matches.
  std::set<int> read_slots;
  for (ir::ExprId root : roots) {
    ir::visit(b.graph, root, [&](const ir::Node& n) {
      if (n.op == ir::Op::Position || n.op == ir::Op::Velocity || n.op == ir::Op::Read)
        read_slots.insert(n.place.slot);
    });
  }
  RenderContext ctx = loop_context(k);
  ctx.lanes = true;
  ctx.read = [&k](const ir::Node& n) {
    const std::string at = std::string("s_") + k.slots[static_cast<std::size_t>(n.place.slot)];
    if (n.op == ir::Op::Position) return std::string("rift::lanes::gather(in.x, ") + at + ")";
    if (n.op == ir::Op::Velocity) return std::string("rift::lanes::gather(in.v, ") + at + ")";
    return std::string("rift::lanes::gather(c.") + member_name(n.embedding) + ", " + at + ")";
  };
  w.open("inline rift::lanes::Mask " + k.cls + "::evaluate_lanes(" +
         (read_slots.empty() ? "const Match* /*ms*/" : "const Match* ms") + ", " +
         (k.reads_state ? "const rift::ForceInput& in" : "const rift::ForceInput& /*in*/") + ", " +
         (k.columns.empty() ? "const Columns& /*c*/" : "const Columns& c") +
         ", ResultLanes& r) const {");
  for (int s : read_slots) {
    const std::string& name = k.slots[static_cast<std::size_t>(s)];
    w.line(std::string("const rift::lanes::Slots s_") + name +
           " = rift::lanes::slots(ms, &Match::" + name + ");");
  }
  w.line("rift::lanes::Mask active = rift::lanes::all_true();");
  BodyRenderer values(b.graph, b.sharing, ctx, roots);
  for (const ir::Stmt& s : b.stmts) {
    if (s.kind == ir::Stmt::Kind::When) {
      write_rendered(w, values, s.loc, "active = active & rift::lanes::as_lanes(", s.cond, ");");
      continue;
    }
    const auto i = static_cast<std::size_t>(s.let);
    if (!wanted[i]) continue;
    const ir::Let& l = b.lets[i];
    write_rendered(w, values, l.loc,
                   std::string("const ") + lanes_type(b.graph[l.value].type) + " " +
                       let_name(l.name) + " = rift::lanes::as_lanes(",
                   l.value, ");");
    values.computed(l.value, let_name(l.name));
  }
  for (const ir::Force& f : b.forces) {
    write_rendered(w, values, f.loc,
                   std::string("r.") + force_field(b, f) + " = rift::lanes::as_lanes(", f.value,
                   ");");
  }
  w.line("return active;");
  w.close();
  w.line();
}

// The whole force pass: column pointers are loaded once instead of once per
// match (stores through Vec3* may alias anything, so the compiler cannot
// hoist them itself), and the body is inlined. `indexed`: the pass over
// ms[at[i]] (add_forces_at, for a block of the coloured scatter a tear left
// out of order, read in place), else over consecutive matches. Two functions
// rather than one testing `at`: the test in the loop, or a lambda over both
// whose captures the stores may alias, cost the consecutive pass 3-15 %.
// The passes over matches read the force input and each match's target
// slots through locals. Eigen stores a force as packets, which the compiler
// must assume may alias anything: without the locals it reads in.x, in.v
// and every slot after the first force again, for each match (3 to 6 of a
// spring's 85 instructions, issue 12's generated / reference row).
constexpr const char* kLocalInput =
    "const rift::ForceInput in = in_arg;  // a local: see the targets below";

// `const rift::Slot to_<slot> = m.<slot>;` for each slot a force is added at,
// once, before the first force is added; returns the target of each force.
std::vector<std::string> write_force_targets(Writer& w, const Kernel& k, const ir::Body& b) {
  std::vector<std::string> targets;
  std::set<int> declared;
  for (const ir::Force& f : b.forces) {
    const std::string& slot = k.slots[static_cast<std::size_t>(f.vertex_slot)];
    if (declared.insert(f.vertex_slot).second)
      w.line("const rift::Slot to_" + slot + " = m." + slot + ";");
    targets.push_back("f[to_" + slot + "]");
  }
  return targets;
}

// What a lanes pass writes besides the forces it adds (write_lanes_pass).
struct LanesOutputs {
  /// Groups' representatives: `count` times each force is added (counts[]),
  /// and, when `terms` is not null, each representative's forces go to it.
  bool grouped = false;
  /// A pass over matches that may store: the statement prefix that keeps the
  /// stored forces to the storing pass ("if constexpr (kStore) "); empty when
  /// nothing is stored.
  std::string if_store;
};

// The lanes part of a force pass over consecutive matches (evaluate_lanes):
// `done` counts the matches it evaluated, kWidth at a time, and the scalar
// loop that follows takes the rest. Each lane's forces are added (and
// stored, and handed out as terms) in the order of the matches, with the
// scalar loop's arithmetic and values.
void write_lanes_pass(Writer& w, const Kernel& k, const std::string& ms, const LanesOutputs& out) {
  const ir::Body& b = k.plan->body;
  const std::string n = std::to_string(b.forces.size());
  // lanes_ is read once: in the loop's condition, every store to f (which may
  // alias it) would make the compiler read it again.
  w.open("if (lanes_) {");
  w.open(std::string("for (; done + rift::lanes::kWidth <= ") + ms +
         ".size(); done += rift::lanes::kWidth) {");
  w.line(std::string("const Match* lane_ms = ") + ms + ".data() + done;");
  w.line("ResultLanes r;");
  w.line("const rift::lanes::Mask active = evaluate_lanes(lane_ms, in, c, r);");
  std::vector<std::string> raw(b.forces.size()), value(b.forces.size());
  for (std::size_t i = 0; i < b.forces.size(); ++i)
    raw[i] = value[i] = std::string("r.") + force_field(b, b.forces[i]);
  // As the scalar loops: a force that negates another is subtracted as that
  // force, except over groups when a later force negates it in turn (it is
  // then count times itself, cf<i>, as write_add_forces_grouped keeps it).
  std::vector<bool> subtracts(b.forces.size(), false);
  for (std::size_t i = 0; i < b.forces.size(); ++i)
    subtracts[i] = negated_force(b, i) >= 0;
  if (out.grouped) {
    for (std::size_t i = 0; i < b.forces.size(); ++i) {
      if (const int j = negated_force(b, i); j >= 0) subtracts[static_cast<std::size_t>(j)] = false;
    }
    w.line("const rift::lanes::Real count = rift::lanes::load(counts + done);");
    for (std::size_t i = 0; i < b.forces.size(); ++i) {
      if (subtracts[i]) continue;
      w.line(std::string("const rift::lanes::Vec3 cf") + std::to_string(i) + " = count * " +
             value[i] + ";");
      value[i] = std::string("cf") + std::to_string(i);
    }
  }
  auto stored_at = [&](const ir::Force& f) {
    return std::string("stored_") + f.embedding + "[" + slot_at(k, f.store_slot, "ss[i]") + "]";
  };
  // What a lane stores of force i: a force that negates another is stored as
  // that force's lane negated (the same bits), so that evaluate_lanes' lanes
  // of the negation are dead and a storing pass does not take them apart.
  std::vector<std::string> stored_lane(b.forces.size());
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    const int j = negated_force(b, i);
    stored_lane[i] =
        j >= 0 ? "-" + raw[static_cast<std::size_t>(j)] + ".lane(lane)" : raw[i] + ".lane(lane)";
  }
  w.open("for (int lane = 0; lane < rift::lanes::kWidth; ++lane) {");
  w.line("[[maybe_unused]] const std::size_t i = done + static_cast<std::size_t>(lane);");
  w.line("const Match& m = lane_ms[lane];");
  w.open("if (!active[lane]) {");
  if (!out.if_store.empty()) {
    w.open(out.if_store + "{");
    for (const ir::Force& f : b.forces)
      w.line(stored_at(f) + " = rift::Vec3::Zero();");
    w.close();
  }
  if (out.grouped) {
    w.line("if (terms) for (int t = 0; t < " + n + "; ++t) terms[i * " + n + " + t].setZero();");
  }
  w.line("continue;");
  w.close();
  const std::vector<std::string> targets = write_force_targets(w, k, b);
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    if (subtracts[i]) {
      const auto j = static_cast<std::size_t>(negated_force(b, i));
      w.line(targets[i] + " -= " + value[j] + ".lane(lane);");
    } else {
      w.line(targets[i] + " += " + value[i] + ".lane(lane);");
    }
    if (!out.if_store.empty())
      w.line(out.if_store + stored_at(b.forces[i]) + " = " + stored_lane[i] + ";");
  }
  if (out.grouped) {
    w.open("if (terms) {");
    for (std::size_t i = 0; i < b.forces.size(); ++i)
      w.line("terms[i * " + n + " + " + std::to_string(i) + "] = " + stored_lane[i] + ";");
    w.close();
  }
  w.close();
  w.close();
  w.close();
}

void write_add_forces_all(Writer& w, const Kernel& k, bool indexed) {
  const ir::Body& b = k.plan->body;
  const bool forces = !b.forces.empty();
  const bool stores_values = !b.stores.empty();
  const std::string ss_i = indexed ? "ss[at[i]]" : "ss[i]";
  const std::set<std::string> stores = force_embeddings(b);
  // One loop per kind of pass (storing or not), each with its own
  // instantiation of the body: the integrator's other stages run a loop
  // without stores, and without a test of `store` at each stored force
  // (3 % of the shear spring's loop).
  const bool two_passes = stores_values || !stores.empty();
  // The two passes are a lambda that takes what it reads as parameters (by
  // value) rather than captures: a capture is read through the closure, and
  // Eigen's force stores, which may alias anything, made the loop read the
  // force array's, the matches' and the stored columns' addresses again
  // after each of them. The function's own parameters are then `NAME_arg`.
  const std::string arg = two_passes ? "_arg" : "";
  const bool stored_slots = has_stored_slots(k);
  w.open("void " + k.cls +
         (indexed ? "::add_forces_at(std::span<const Match> ms" + arg +
                        ", const std::uint32_t* at" + arg + ", std::size_t n" + arg + ", "
                  : "::add_forces_all(std::span<const Match> ms" + arg + ", ") +
         (stored_slots ? "const Stored* ss" + arg : std::string("const Stored* /*ss*/")) +
         ", const rift::ForceInput& in_arg, " +
         (forces          ? "rift::Vec3* f" + arg + ", bool store"
          : stores_values ? std::string("rift::Vec3* /*f*/, bool store")
                          : std::string("rift::Vec3* /*f*/, bool /*store*/")) +
         ") {");
  // Not asked for unless storing: a column nothing reads has no storage
  // (rift::ForceModel::set_store_forces), and values() would give it some.
  auto write_stored_columns = [&](const std::string& storing, const std::string& attribute) {
    for (const std::string& e : stores)
      w.line(attribute + "rift::Vec3* const stored_" + e + " = " + storing + " ? " +
             embedding_var(e) + ".values().data() : nullptr;");
    std::set<std::string> values;
    for (const ir::Store& st : b.stores)
      if (!stores.contains(st.embedding)) values.insert(st.embedding);
    for (const std::string& e : values)
      w.line(attribute + "auto* const stored_" + e + " = " + storing + " ? " + embedding_var(e) +
             ".values().data() : nullptr;");
  };
  auto store_at = [&](const ir::Store& st) {
    return "stored_" + st.embedding + "[" + slot_at(k, st.store_slot, ss_i) + "]";
  };
  const std::string if_store = two_passes ? "if constexpr (kStore) " : "if (store) ";
  if (two_passes) {
    // With stored values not inlined: two instantiations of the body in one
    // function exceed the inliner's growth limits, and the matrix products of
    // both would be calls. Without, inlined.
    const std::string params = std::string("(std::span<const Match> ms, ") +
                               (indexed ? "const std::uint32_t* at, std::size_t n, " : "") +
                               (stored_slots ? "const Stored* ss, " : "") +
                               "const rift::ForceInput in, const Columns c" +
                               (forces ? ", rift::Vec3* f" : "") + ")";
    w.open("auto pass = [this]<bool kStore>" + params +
           (stores_values ? " __attribute__((noinline)) {" : " {"));
    write_stored_columns("kStore", "[[maybe_unused]] ");
  } else {
    w.line(kLocalInput);
    w.line("const Columns c = columns();");
    write_stored_columns("store", "");
  }
  const bool lanes = k.lanes && !indexed;
  if (lanes) {
    // kWidth matches at a time, then the rest.
    w.line("std::size_t done = 0;");
    LanesOutputs out;
    if (!stores.empty()) out.if_store = if_store;
    write_lanes_pass(w, k, "ms", out);
  }
  if (indexed) {
    w.open("for (std::size_t i = 0; i < n; ++i) {");
    w.line("const Match& m = ms[at[i]];");
  } else {
    w.open(std::string("for (std::size_t i = ") + (lanes ? "done" : "0") +
           "; i < ms.size(); ++i) {");
    w.line("const Match& m = ms[i];");
  }
  w.line("Result r;");
  if (forces || stores_values) {
    w.open(stores_values ? "if (!evaluate<true, kStore>(m, in, c, r)) {"
                         : "if (!evaluate<true>(m, in, c, r)) {");
    w.open(if_store + "{");
    for (const ir::Force& f : b.forces) {
      w.line("stored_" + f.embedding + "[" + slot_at(k, f.store_slot, ss_i) +
             "] = rift::Vec3::Zero();");
    }
    for (const ir::Store& st : b.stores) {
      // A sum skips the match (it adds nothing); a value is reset.
      if (!st.accumulate)
        w.line(store_at(st) + " = " + embedding_var(st.embedding) + ".default_value();");
    }
    w.close();
    w.line("continue;");
    w.close();
    const std::vector<std::string> targets = write_force_targets(w, k, b);
    for (std::size_t i = 0; i < b.forces.size(); ++i) {
      const ir::Force& f = b.forces[i];
      const std::string field = std::string("r.") + force_field(b, f);
      const std::string& target = targets[i];
      if (const int j = negated_force(b, i); j >= 0) {
        w.line(target + " -= r." + force_field(b, b.forces[static_cast<std::size_t>(j)]) + ";");
      } else {
        w.line(target + " += " + field + ";");
      }
      w.line(if_store + "stored_" + f.embedding + "[" + slot_at(k, f.store_slot, ss_i) +
             "] = " + field + ";");
    }
    if (stores_values) {
      w.open(if_store + "{");
      for (const ir::Store& st : b.stores)
        w.line(store_at(st) + (st.accumulate ? " += r." : " = r.") + store_field(b, st) + ";");
      w.close();
    }
  } else {
    w.line("(void)evaluate<true>(m, in, c, r);");
  }
  w.close();
  if (two_passes) {
    w.close("};");
    const std::string args = std::string("(ms_arg, ") + (indexed ? "at_arg, n_arg, " : "") +
                             (stored_slots ? "ss_arg, " : "") + "in_arg, columns()" +
                             (forces ? ", f_arg" : "") + ")";
    w.line("if (store) {");
    w.line("  pass.template operator()<true>" + args + ";");
    w.line("} else {");
    w.line("  pass.template operator()<false>" + args + ";");
    w.line("}");
  }
  w.close();
  w.line();
}

// The vertex slots each force of a match goes to, in the order add_forces_all
// adds them: rift::CachedInteraction colours blocks of matches by them
// (rift/sim/scatter_colouring.hpp) so that the blocks of one colour can
// scatter at once, in an order that does not depend on the threads.
void write_force_targets(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  if (b.forces.empty()) return;
  w.open("void " + k.cls + "::force_targets(const Match& m, rift::Slot* out) const {");
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    w.line("out[" + std::to_string(i) + "] = m." +
           k.slots[static_cast<std::size_t>(b.forces[i].vertex_slot)] + ";");
  }
  w.close();
  w.line();
}

// ---- Jacobians (lower/derivative.*): the body differentiated in the IR,
// rendered with the primal it shares its values with.

/// The force loop's context, and the seeds of tangent passes: `tx[j]`, `tv[j]`
/// for the Jacobian vertex j.
RenderContext tangent_context(const Kernel& k) {
  RenderContext ctx = loop_context(k);
  ctx.read = [&k, primal = ctx.read](const ir::Node& n) {
    if (n.op != ir::Op::PositionTangent && n.op != ir::Op::VelocityTangent) return primal(n);
    return std::string(n.op == ir::Op::PositionTangent ? "tx[" : "tv[") +
           std::to_string(k.derivative.vertex_of_slot(n.place.slot)) + "]";
  };
  return ctx;
}

/// Every root a Jacobian function renders: the primal statements, then the
/// tangents of the forces (the tangent lets they read are inside them).
std::vector<ir::ExprId> jacobian_roots(const lower::DifferentiatedBody& d) {
  std::vector<ir::ExprId> roots = statement_roots(d.body);
  for (const lower::TangentPass& p : d.passes) {
    for (ir::ExprId id : p.forces)
      if (id != ir::kNoExpr) roots.push_back(id);
  }
  return roots;
}

/// The primal body (lets and whens in source order); `on_fail` runs where a
/// `when` fails.
void write_primal(Writer& w, const Kernel& k, const ir::Body& b, BodyRenderer& values,
                  const std::string& on_fail) {
  if (!k.columns.empty()) w.line("[[maybe_unused]] const Columns c = columns();");
  for (const ir::Stmt& s : b.stmts) {
    if (s.kind == ir::Stmt::Kind::When) {
      write_rendered(w, values, s.loc, "if (!", s.cond, std::string(") ") + on_fail);
      continue;
    }
    const ir::Let& l = b.lets[static_cast<std::size_t>(s.let)];
    write_rendered(w, values, l.loc,
                   "[[maybe_unused]] const " + cpp_type(b.graph[l.value].type) + " " +
                       let_name(l.name) + " = ",
                   l.value, ";");
    values.computed(l.value, let_name(l.name));
  }
}

/// Nodes reachable from `roots` (each visited once, however shared).
std::vector<bool> reachable(const ir::Graph& g, const std::vector<ir::ExprId>& roots) {
  std::vector<bool> seen(g.size(), false);
  std::vector<ir::ExprId> stack;
  for (ir::ExprId r : roots)
    if (r != ir::kNoExpr) stack.push_back(r);
  while (!stack.empty()) {
    const ir::ExprId id = stack.back();
    stack.pop_back();
    if (seen[static_cast<std::size_t>(id)]) continue;
    seen[static_cast<std::size_t>(id)] = true;
    const ir::Node& n = g[id];
    for (std::size_t i = 0; i < n.arity(); ++i)
      stack.push_back(n.operand(i));
  }
  return seen;
}

/// Computes before the tangent loops the primal values the tangents multiply
/// by (every direction reads them): the operands of tangent nodes that do
/// not depend on a seed themselves.
void hoist_primal_factors(Writer& w, const lower::DifferentiatedBody& d, BodyRenderer& values) {
  const ir::Graph& g = d.body.graph;
  // Operands come before the nodes that use them (lower/share.hpp interns bottom-up).
  std::vector<bool> seeded(g.size(), false);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const ir::Node& n = g[static_cast<ir::ExprId>(i)];
    bool s = n.op == ir::Op::PositionTangent || n.op == ir::Op::VelocityTangent;
    for (std::size_t k = 0; k < n.arity(); ++k)
      s = s || seeded[static_cast<std::size_t>(n.operand(k))];
    seeded[i] = s;
  }
  const std::vector<bool> used = reachable(g, jacobian_roots(d));
  for (std::size_t i = 0; i < g.size(); ++i) {
    const ir::Node& n = g[static_cast<ir::ExprId>(i)];
    if (!used[i] || !seeded[i]) continue;
    for (std::size_t k = 0; k < n.arity(); ++k) {
      const ir::ExprId op = n.operand(k);
      if (!seeded[static_cast<std::size_t>(op)]) values.precompute(op);
    }
  }
  for (const std::string& local : values.take_locals())
    w.line(local);
}

/// A pass's tangent lets (those a force's tangent reads, in source order,
/// named `t_l_NAME`), then `per_force(i, id)` for each force whose tangent
/// is not identically zero.
template <class PerForce>
void write_tangents(Writer& w, const ir::Body& b, const lower::TangentPass& pass,
                    BodyRenderer& values, PerForce&& per_force) {
  const std::vector<bool> needed = reachable(b.graph, pass.forces);
  // A let only a `store` or the energy reads has no tangent to write, even
  // when its value is a node the forces' tangents share.
  std::vector<bool> by_forces(b.lets.size());
  for (const ir::Force& f : b.forces)
    lets_used(b, f.value, by_forces);
  for (const ir::Stmt& s : b.stmts)
    if (s.kind == ir::Stmt::Kind::When) lets_used(b, s.cond, by_forces);
  std::set<ir::ExprId> written;
  for (const ir::Stmt& s : b.stmts) {
    if (s.kind != ir::Stmt::Kind::Let) continue;
    const auto i = static_cast<std::size_t>(s.let);
    const ir::ExprId t = pass.lets[i];
    if (t == ir::kNoExpr || !by_forces[i] || !needed[static_cast<std::size_t>(t)] ||
        !written.insert(t).second)
      continue;
    const ir::Let& l = b.lets[i];
    const std::string name = "t_" + let_name(l.name);
    write_rendered(w, values, l.loc, "const " + cpp_type(b.graph[t].type) + " " + name + " = ", t,
                   ";");
    values.computed(t, name);
  }
  for (std::size_t i = 0; i < pass.forces.size(); ++i)
    if (pass.forces[i] != ir::kNoExpr) per_force(i, pass.forces[i]);
}

void write_vertex_slots(Writer& w, const Kernel& k) {
  w.open("void " + k.cls + "::vertex_slots(const Match& m, rift::Slot* out) const {");
  for (std::size_t j = 0; j < k.derivative.vertex_slots.size(); ++j) {
    w.line("out[" + std::to_string(j) + "] = m." +
           k.slots[static_cast<std::size_t>(k.derivative.vertex_slots[j])] + ";");
  }
  w.close();
  w.line();
}

// Dense blocks by forward mode: one tangent pass per direction (a
// coordinate of one vertex's position or velocity), each giving one column
// of the blocks of every force. The position and velocity directions are
// two loops, each seeding only its own state, so neither computes the
// tangents that only the other's seed feeds; a loop the forces do not
// depend on at all (velocities of an undamped law) is left out. The primal
// values the tangents multiply by are computed once, before the loops.
// `flatten` inlines the 3×3 products into the loop (at this size a call
// costs as much as the product), and unrolling the loop makes each seed a
// constant one-hot vector that the compiler folds into the first products.
void write_jacobian(Writer& w, const Kernel& k) {
  std::vector<lower::Seed> seeds;
  if (k.derivative.depends_on_x) seeds.push_back({true, false});
  if (k.derivative.depends_on_v) seeds.push_back({false, true});
  const lower::DifferentiatedBody d = lower::differentiate(k.plan->body, seeds);
  const ir::Body& b = d.body;
  const RenderContext ctx = tangent_context(k);
  BodyRenderer values(b.graph, b.sharing, ctx, jacobian_roots(d));
  const int n = static_cast<int>(k.derivative.vertex_slots.size());
  const std::string kk = std::to_string(n * n), k3 = std::to_string(3 * n);
  w.open("[[gnu::flatten]] void " + k.cls +
         "::jacobian([[maybe_unused]] const Match& m, [[maybe_unused]] const rift::ForceInput& in, "
         "rift::Mat3* dfdx, rift::Mat3* dfdv) {");
  w.open("for (int b = 0; b < " + kk + "; ++b) {");
  w.line("dfdx[b].setZero();");
  w.line("dfdv[b].setZero();");
  w.close();
  write_primal(w, k, b, values, "return;");
  hoist_primal_factors(w, d, values);
  for (const lower::TangentPass& pass : d.passes) {
    const std::string seed = pass.seed.x ? "tx" : "tv", out = pass.seed.x ? "dfdx" : "dfdv";
    w.line("#pragma GCC unroll " + k3);
    w.open("for (int dir = 0; dir < " + k3 + "; ++dir) {");
    values.open_block();
    w.line("const int j = dir / 3, c3 = dir % 3;");
    w.line("rift::Vec3 " + seed + "[" + std::to_string(n) + "];");
    w.open("for (int v = 0; v < " + std::to_string(n) + "; ++v) {");
    w.line(seed + "[v].setZero();");
    w.close();
    w.line(seed + "[j][c3] = 1;");
    write_tangents(w, b, pass, values, [&](std::size_t i, ir::ExprId t) {
      const ir::Force& f = b.forces[i];
      const int vi = k.derivative.vertex_of_slot(f.vertex_slot);
      write_rendered(w, values, f.loc, out + "[" + std::to_string(vi * n) + " + j].col(c3) += ", t,
                     ";");
    });
    values.close_block();
    w.close();
  }
  w.close();
  w.line();
}

// J·p in one tangent pass seeded with p's values at the match's vertices.
void write_jacobian_product(Writer& w, const Kernel& k) {
  const lower::DifferentiatedBody d = lower::differentiate(k.plan->body, {{true, true}});
  const ir::Body& b = d.body;
  const RenderContext ctx = tangent_context(k);
  BodyRenderer values(b.graph, b.sharing, ctx, jacobian_roots(d));
  const int n = static_cast<int>(k.derivative.vertex_slots.size());
  w.open("[[gnu::flatten]] void " + k.cls +
         "::jacobian_product([[maybe_unused]] const Match& m, [[maybe_unused]] const "
         "rift::ForceInput& in, [[maybe_unused]] const rift::Vec3* px, [[maybe_unused]] const "
         "rift::Vec3* pv, " +
         std::string(b.forces.empty() ? "[[maybe_unused]] " : "") + "rift::Vec3* out) {");
  write_primal(w, k, b, values, "return;");
  std::string tx = "[[maybe_unused]] const rift::Vec3 tx[" + std::to_string(n) + "] = {";
  std::string tv = "[[maybe_unused]] const rift::Vec3 tv[" + std::to_string(n) + "] = {";
  for (int j = 0; j < n; ++j) {
    const std::string at =
        "m." +
        k.slots[static_cast<std::size_t>(k.derivative.vertex_slots[static_cast<std::size_t>(j)])];
    // Appended piece by piece (GCC 12 warns of `const char* + std::string&&`).
    const char* sep = j ? ", " : "";
    tx.append(sep).append("px[").append(at).append("]");
    tv.append(sep).append("pv[").append(at).append("]");
  }
  w.line(tx + "};");
  w.line(tv + "};");
  write_tangents(w, b, d.passes[0], values, [&](std::size_t i, ir::ExprId t) {
    const ir::Force& f = b.forces[i];
    write_rendered(w, values, f.loc,
                   "out[m." + k.slots[static_cast<std::size_t>(f.vertex_slot)] + "] += ", t, ";");
  });
  w.close();
  w.line();
}

// ---- Groups of identical matches (rift/sim/match_groups.hpp): the key, one
// evaluation's forces as terms, their storage for any member, and the force
// pass over groups.

// The key: the vertex slots in the Match's order, then the bits of every
// value the forces read through the match's other slots. Equal keys: the
// same arithmetic on the same numbers (the interaction's parameters and the
// pack's are the same for every match), hence the same forces.
void write_group_key(Writer& w, const Kernel& k) {
  const lower::KernelPlan& plan = k.plan->kernel;
  w.open("void " + k.cls + "::group_key(const Match& m, std::uint64_t* out) const {");
  if (!k.reads.empty()) w.line("const Columns c = columns();");
  for (std::size_t s = 0; s < plan.slots.size(); ++s)
    if (plan.slots[s].vertex) w.line("out = rift::key_words(m." + k.slots[s] + ", out);");
  for (const auto& [name, slot] : k.reads) {
    w.line("out = rift::key_words(c." + member_name(name) + "[m." +
           k.slots[static_cast<std::size_t>(slot)] + "], out);");
  }
  w.line("(void)out;");
  w.close();
  w.line();
  // The same values, asked for ahead: a re-match on a large map computes
  // the keys of the matches it finds again, and the values behind them
  // are misses there (rift::MatchCache::prefetch_entries).
  w.open("void " + k.cls + "::prefetch_key([[maybe_unused]] const Match& m) const {");
  if (!k.reads.empty()) w.line("const Columns c = columns();");
  for (const auto& [name, slot] : k.reads) {
    w.line("rift::prefetch(c." + member_name(name) + " + m." +
           k.slots[static_cast<std::size_t>(slot)] + ");");
  }
  w.close();
  w.line();
}

void write_add_forces_grouped(Writer& w, const Kernel& k, bool indexed);

void write_group_passes(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  const std::string n = std::to_string(b.forces.size());
  w.open("bool " + k.cls +
         "::evaluate_terms(const Match& m, const rift::ForceInput& in, rift::Vec3* terms) const {");
  w.line("Result r;");
  w.open("if (!evaluate<true>(m, in, columns(), r)) {");
  w.line("for (int i = 0; i < " + n + "; ++i) terms[i].setZero();");
  w.line("return false;");
  w.close();
  for (std::size_t i = 0; i < b.forces.size(); ++i)
    w.line("terms[" + std::to_string(i) + "] = r." + force_field(b, b.forces[i]) + ";");
  w.line("return true;");
  w.close();
  w.line();
  w.open("void " + k.cls +
         "::store_terms([[maybe_unused]] const Match& m, [[maybe_unused]] const Stored& s, const "
         "rift::Vec3* terms) {");
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    const ir::Force& f = b.forces[i];
    w.line(embedding_var(f.embedding) + ".values()[" + slot_at(k, f.store_slot, "s") +
           "] = terms[" + std::to_string(i) + "];");
  }
  w.close();
  w.line();
  // The members of groups[i], i < n, store the terms of their group: the
  // walk of the groups' member lists inside the kernel, where each member's
  // stores follow its link with nothing in between (a list of entries
  // handed over in batches cost about as much again as the stores). Each
  // column's storage is asked for once (values() is an acquire load, which
  // no later load may pass), not once per member and force.
  w.open("void " + k.cls + "::store_group_terms(std::span<const Match> ms, " +
         (has_stored_slots(k) ? "const Stored* ss" : "const Stored* /*ss*/") +
         ", const std::uint32_t* head, const std::uint32_t* next, const std::uint32_t* groups, "
         "std::size_t n, const rift::Vec3* terms) {");
  const std::set<std::string> stores = force_embeddings(b);
  for (const std::string& e : stores)
    w.line("rift::Vec3* const stored_" + e + " = " + embedding_var(e) + ".values().data();");
  w.open("for (std::size_t i = 0; i < n; ++i) {");
  w.line("const rift::Vec3* const t = terms + i * " + n + ";");
  w.open("for (std::uint32_t e = head[groups[i]]; e != rift::kNoMember; e = next[e]) {");
  w.line("[[maybe_unused]] const Match& m = ms[e];");
  if (has_stored_slots(k)) w.line("[[maybe_unused]] const Stored& s = ss[e];");
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    const ir::Force& f = b.forces[i];
    w.line("stored_" + f.embedding + "[" + slot_at(k, f.store_slot, "s") + "] = t[" +
           std::to_string(i) + "];");
  }
  w.close();
  w.close();
  w.close();
  w.line();
  // As add_forces_all, each force added count times; a pass that stores
  // also keeps each group's terms, which its members' stored forces copy.
  // Over consecutive groups, and (add_forces_grouped_at) over reps[at[i]].
  for (const bool indexed : {false, true})
    write_add_forces_grouped(w, k, indexed);
}

void write_add_forces_grouped(Writer& w, const Kernel& k, bool indexed) {
  const ir::Body& b = k.plan->body;
  const std::string n = std::to_string(b.forces.size());
  w.open("void " + k.cls +
         (indexed ? "::add_forces_grouped_at(std::span<const Match> reps, const rift::Real* "
                    "counts, const std::uint32_t* at, std::size_t n, const "
                  : "::add_forces_grouped(std::span<const Match> reps, const rift::Real* "
                    "counts, const ") +
         "rift::ForceInput& in_arg, rift::Vec3* f, rift::Vec3* terms) {");
  w.line(kLocalInput);
  w.line("const Columns c = columns();");
  const bool lanes = k.lanes && !indexed;
  if (lanes) {
    // kWidth groups at a time, then the rest. Outside the loops below, whose
    // two instantiations it would make too large to inline (the closure's
    // captures are then read again after every store); `terms` is tested
    // once per lane, a test per kWidth groups.
    w.line("std::size_t done = 0;");
    LanesOutputs out;
    out.grouped = true;
    write_lanes_pass(w, k, "reps", out);
  }
  // The loop twice, with and without terms: a test of `terms` in the loop
  // was two of the stretch spring's 80 instructions.
  w.open("const auto loop = [&]<bool kTerms>(std::bool_constant<kTerms>) {");
  if (indexed) {
    w.open("for (std::size_t i = 0; i < n; ++i) {");
    w.line("const std::uint32_t e = at[i];");
    w.line("const Match& m = reps[e];");
  } else {
    w.open(std::string("for (std::size_t i = ") + (lanes ? "done" : "0") +
           "; i < reps.size(); ++i) {");
    w.line("const Match& m = reps[i];");
  }
  w.line("Result r;");
  w.open("if (!evaluate<true>(m, in, c, r)) {");
  w.line("if constexpr (kTerms) for (int t = 0; t < " + n + "; ++t) terms[i * " + n +
         " + t].setZero();");
  w.line("continue;");
  w.close();
  w.line(indexed ? "const rift::Real count = counts[e];" : "const rift::Real count = counts[i];");
  const std::vector<std::string> targets = write_force_targets(w, k, b);
  // count times each force; a force a later one negates is kept (cf<i>),
  // even when it negates an earlier one itself (`-(-fa)`).
  std::vector<bool> negated_later(b.forces.size(), false);
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    if (const int j = negated_force(b, i); j >= 0)
      negated_later[static_cast<std::size_t>(j)] = true;
  }
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    const ir::Force& f = b.forces[i];
    const std::string& target = targets[i];
    if (negated_later[i]) {
      w.line("const rift::Vec3 cf" + std::to_string(i) + " = count * r." + force_field(b, f) + ";");
      w.line(target + " += cf" + std::to_string(i) + ";");
    } else if (const int j = negated_force(b, i); j >= 0) {
      w.line(target + " -= cf" + std::to_string(j) + ";");
    } else {
      w.line(target + " += count * r." + force_field(b, f) + ";");
    }
  }
  w.open("if constexpr (kTerms) {");
  for (std::size_t i = 0; i < b.forces.size(); ++i) {
    w.line("terms[i * " + n + " + " + std::to_string(i) + "] = r." + force_field(b, b.forces[i]) +
           ";");
  }
  w.close();
  w.close();
  w.close("};");
  w.line("if (terms) loop(std::true_type{}); else loop(std::false_type{});");
  w.close();
  w.line();
}

void write_reset(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  w.open("void " + k.cls +
         "::reset_stored([[maybe_unused]] const Match& m, [[maybe_unused]] const Stored& s) {");
  for (const ir::Force& f : b.forces) {
    const std::string col = embedding_var(f.embedding) + ".values()";
    const std::string at = slot_at(k, f.store_slot, "s");
    w.line("if (" + at + " < " + col + ".size()) " + col + "[" + at + "] = rift::Vec3::Zero();");
  }
  for (const ir::Store& st : b.stores) {
    if (st.accumulate) continue;  // per vertex: reset_accumulated, by region
    const std::string col = embedding_var(st.embedding) + ".values()";
    const std::string at = slot_at(k, st.store_slot, "s");
    w.line("if (" + at + " < " + col + ".size()) " + col + "[" + at +
           "] = " + embedding_var(st.embedding) + ".default_value();");
  }
  w.close();
  w.line();
}

/// The sums of `store +=`: zeroed whole before the pass that stores (every
/// match then adds its terms), and zeroed at the vertices a rewrite touched,
/// whose elements changed, until that pass runs again.
void write_accumulated(Writer& w, const Kernel& k) {
  const ir::Body& b = k.plan->body;
  if (!accumulates(b)) return;
  std::map<std::string, ir::Type> sums;
  for (const ir::Store& st : b.stores)
    if (st.accumulate) sums.emplace(st.embedding, b.graph[st.value].type);
  w.open("void " + k.cls + "::clear_accumulated() {");
  for (const auto& [e, type] : sums) {
    w.line("std::fill(" + embedding_var(e) + ".values().begin(), " + embedding_var(e) +
           ".values().end(), " + zero_of(type) + ");");
  }
  w.close();
  w.line();
  w.open("void " + k.cls +
         "::reset_accumulated(const rift::GMap& g, std::span<const rift::Dart> region) {");
  w.open("for (const rift::Dart d : region) {");
  w.line("if (!g.is_alive(d)) continue;");
  for (const auto& [e, type] : sums) {
    const std::string col = embedding_var(e) + ".values()";
    w.line("if (const rift::Slot s = " + embedding_var(e) + ".slot(d); s < " + col + ".size()) " +
           col + "[s] = " + zero_of(type) + ";");
  }
  w.close();
  w.close();
  w.line();
}

void write_energy(Writer& w, const Kernel& k) {
  if (k.plan->body.energy == ir::kNoExpr) {
    w.line("rift::Real " + k.cls +
           "::energy(const Match& /*m*/, const rift::ForceInput& /*in*/) const { return 0; }");
    w.line();
    return;
  }
  w.open("rift::Real " + k.cls + "::energy(const Match& m, const rift::ForceInput& in) const {");
  w.line("Result r;");
  w.line("return evaluate<false>(m, in, columns(), r) ? r.energy : 0;");
  w.close();
  w.line();
}

}  // namespace

std::string tag_embedding(std::string_view interaction) {
  return std::string(interaction) + "_first_dart";
}

void declare_kernel(Writer& w, const InteractionPlan& plan, const PackModel& model) {
  const Kernel k = kernel_of(plan);
  const ast::Interaction& inter = *plan.interaction;
  const ir::Body& b = plan.body;
  const std::string params = component_params_struct(inter.name.text);
  declare_component_params(w, params, inter.params, model);
  w.line("/// Interaction '" + inter.name.text + "' on " + orbit_text(inter.support.dims) +
         (inter.tagged ? ", tagged" : "") + ": a kernel for rift::CachedInteraction.");
  w.open("class " + k.cls + " {");
  w.middle(" public:");
  w.line("/// The slots a match caches (trivially copyable, fixed size).");
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 0) {
      w.open("struct Match {");
    } else {
      w.line("/// The slots only stored forces and `store`s write: cached only when the");
      w.line("/// interaction stores (rift::CachedInteraction), beside the matches.");
      w.open("struct Stored {");
    }
    for (std::size_t s = 0; s < plan.kernel.slots.size(); ++s) {
      if (k.stored_only[s] != (pass == 1)) continue;
      const lower::SlotUse& u = plan.kernel.slots[s];
      w.line("rift::Slot " + k.slots[s] + " = rift::kNoSlot;  // " +
             (u.vertex ? std::string("vertex") : orbit_text(u.orbit)) + " of " +
             path_text(plan.kernel.nodes[static_cast<std::size_t>(u.node)], u.hops));
    }
    w.close("};");
  }
  w.line("static constexpr rift::Orbit kSupport = " + orbit_code(inter.support.dims) + ";");
  w.line("/// Links from the support dart to the farthest dart a match reads.");
  w.line("static constexpr int kRadius = " + std::to_string(plan.kernel.radius) + ";");
  const auto& reach = plan.kernel.reach;
  const bool words_fit = std::all_of(reach.begin(), reach.end(), [](const std::vector<int>& word) {
    return word.size() <= static_cast<std::size_t>(kMaxReachLinks);
  });
  if (!reach.empty() && words_fit) {
    // A re-match walks them back from each touched dart (rift/sim/reach.hpp).
    w.line(
        "/// Links from the support dart to each dart a match reads, less the first links "
        "inside the support orbit (rift/sim/reach.hpp).");
    std::string words;
    for (const std::vector<int>& word : reach) {
      std::string links;
      for (const int l : word)
        links += (links.empty() ? "" : ", ") + std::to_string(l);
      words += (words.empty() ? "" : ", ") + std::string("{") + std::to_string(word.size()) +
               ", {" + links + "}}";
    }
    w.line("static constexpr rift::ReachWord kReach[] = {" + words + "};");
  }
  w.line("static constexpr bool kTagged = " + std::string(inter.tagged ? "true" : "false") + ";");
  w.line();
  w.line("explicit " + k.cls + "(const " + params + "& p = {}, const Params& pack = {})");
  w.line("    : p_(p), pack_(pack) {}");
  w.line("const std::string& name() const { return name_; }");
  w.line("const " + params + "& params() const { return p_; }");
  w.line("/// Declares the pack's embeddings the map lacks, binds them" +
         std::string(inter.tagged ? ", tags the first dart of every support orbit" : "") +
         " and runs the interaction's inits.");
  if (hands_out_supports(k)) {
    w.line("/// sink(d, darts), when given, with each orbit's support dart as the inits choose it");
    w.line("/// and the darts they found from it (match_found takes the match from them).");
    w.line("void initialise(rift::GMap& g, rift::SupportSink sink = {});");
  } else {
    w.line("void initialise(rift::GMap& g);");
  }
  if (!k.store_only_embeddings.empty()) {
    w.line("/// Before initialise: false when nothing reads the stored forces, whose");
    w.line("/// embeddings are then left unbound.");
    w.line("void set_store_forces(bool on) { store_ = on; }");
  }
  if (k.lanes) {
    w.line("/// False: the force passes evaluate each match alone, as without lanes (to compare).");
    w.line("void set_lanes(bool on) { lanes_ = on; }");
  }
  if (inter.tagged) {
    w.line("/// Before initialise: false for a map never rewritten, whose orbits are then");
    w.line("/// matched only from the darts initialise walks: no tag is kept.");
    w.line("void set_rewrites(bool on) { rewrites_ = on; }");
  }
  w.line("/// Fills s too unless it is null.");
  w.line(
      "bool match(const rift::GMap& g, rift::Dart support, Match& m, Stored* s = nullptr) "
      "const;");
  w.line("/// The same from the pattern's darts as find gave them.");
  w.line(
      "bool match_found(const rift::GMap& g, const rift::Dart* darts, Match& m, Stored* s = "
      "nullptr) const;");
  if (chooses_support_dart(k)) {
    w.line("/// The dart of d's support orbit to match from: the one binding the smallest vertex");
    w.line("/// slots first (the inits use it, and so does the simulator for a new orbit).");
    w.line("rift::Dart support_dart(const rift::GMap& g, rift::Dart d) const;");
    w.line("/// The same, with the pattern's darts found from it in `darts`; kNoDart when no");
    w.line("/// dart of the orbit matches.");
    w.line(
        "rift::Dart support_match(const rift::GMap& g, rift::Dart d, rift::Dart* darts) "
        "const;");
  }
  w.line("/// The force pass over every match: adds each force to f (and stores it when `store`,");
  w.line("/// at the slots of ss[i], parallel to ms).");
  w.line(
      "void add_forces_all(std::span<const Match> ms, const Stored* ss, const rift::ForceInput& "
      "in, rift::Vec3* f, bool store);");
  w.line("/// The same over ms[at[i]] for i < n (ss parallel to ms): a block of matches a tear");
  w.line("/// left out of order, read in place.");
  w.line(
      "void add_forces_at(std::span<const Match> ms, const std::uint32_t* at, std::size_t n, "
      "const Stored* ss, const rift::ForceInput& in, rift::Vec3* f, bool store);");
  if (!b.forces.empty()) {
    w.line(
        "/// The vertex slots of a match's kForceTerms forces, in the order add_forces_all adds");
    w.line("/// them (the coloured scatter of several threads groups matches by them).");
    w.line("static constexpr int kForceTerms = " + std::to_string(b.forces.size()) + ";");
    w.line("void force_targets(const Match& m, rift::Slot* out) const;");
  }
  if (!b.forces.empty() && b.stores.empty()) {
    w.line("/// Matches with equal keys give equal forces and are evaluated once");
    w.line("/// (rift/sim/match_groups.hpp): the vertex slots, then the bits of the values read.");
    w.line("static constexpr int kGroupKey = " + std::to_string(group_key_words(k, model)) + ";");
    w.line("void group_key(const Match& m, std::uint64_t* out) const;");
    w.line("/// Hints: the values group_key reads through m's slots (a re-match).");
    w.line("void prefetch_key(const Match& m) const;");
    w.line("/// One match's kForceTerms forces (zero where a `when` fails; false then).");
    w.line(
        "bool evaluate_terms(const Match& m, const rift::ForceInput& in, rift::Vec3* terms) "
        "const;");
    w.line("/// Stores forces computed by evaluate_terms into m's stored-force slots.");
    w.line("void store_terms(const Match& m, const Stored& s, const rift::Vec3* terms);");
    w.line("/// store_terms for every member of groups[i], i < n (its members: e = head[g],");
    w.line("/// then next[e], until rift::kNoMember), with the terms at terms + i * kForceTerms.");
    w.line(
        "void store_group_terms(std::span<const Match> ms, const Stored* ss, const "
        "std::uint32_t* head, const std::uint32_t* next, const std::uint32_t* groups, "
        "std::size_t n, const rift::Vec3* terms);");
    w.line("/// The force pass over groups: adds counts[i] times the forces of reps[i];");
    w.line("/// unless null, terms[i * kForceTerms + t] receives reps[i]'s t-th force.");
    w.line(
        "void add_forces_grouped(std::span<const Match> reps, const rift::Real* counts, const "
        "rift::ForceInput& in, rift::Vec3* f, rift::Vec3* terms);");
    w.line("/// The same over reps[at[i]] (counts parallel to reps) for i < n.");
    w.line(
        "void add_forces_grouped_at(std::span<const Match> reps, const rift::Real* counts, "
        "const std::uint32_t* at, std::size_t n, const rift::ForceInput& in, rift::Vec3* f, "
        "rift::Vec3* terms);");
  }
  w.line("void reset_stored(const Match& m, const Stored& s);");
  if (accumulates(k.plan->body)) {
    w.line("/// The per-vertex sums of `store +=` (rift/sim/cached_interaction.hpp).");
    w.line("void clear_accumulated();");
    w.line("void reset_accumulated(const rift::GMap& g, std::span<const rift::Dart> region);");
  }
  w.line("rift::Real energy(const Match& m, const rift::ForceInput& in) const;");
  if (k.plan->body.energy != ir::kNoExpr) {
    w.line("/// The rule gives an energy (the implicit Newton line search can use it).");
    w.line("static constexpr bool kHasEnergy = true;");
  }
  if (k.derivative.available) {
    w.line("/// Jacobians derived by riftc (forward mode): the match's vertices, the blocks");
    w.line("/// df_i/dx_j and df_i/dv_j (row-major), and the product J p.");
    w.line("static constexpr int kJacobianVertices = " +
           std::to_string(k.derivative.vertex_slots.size()) + ";");
    if (k.inter->semidefinite) {
      w.line("/// The rule states -J semidefinite (`semidefinite;`): no test, no projection.");
      w.line("static constexpr bool kJacobianSemidefinite = true;");
    }
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
  w.line("/// The columns the body reads, loaded once per pass.");
  w.open("struct Columns {");
  for (const std::string& name : k.columns) {
    w.line("const " + embedding_storage(model, name) + "* " + member_name(name) + ";");
  }
  w.close("};");
  w.line("/// What one evaluation of the body gives.");
  w.open("struct Result {");
  for (const ir::Force& f : b.forces)
    w.line("rift::Vec3 " + force_field(b, f) + ";");
  for (const ir::Store& st : b.stores)
    w.line(cpp_type(b.graph[st.value].type) + " " + store_field(b, st) + "{};");
  w.line("rift::Real energy = 0;");
  w.close("};");
  w.line(
      "/// The pattern's darts from one support dart, in pattern order; false when it does not "
      "match.");
  w.line("bool find(const rift::GMap& g, rift::Dart support, rift::Dart* darts) const;");
  w.line("Columns columns() const;");
  if (k.lanes) {
    w.line("/// What evaluate_lanes gives: each force for rift::lanes::kWidth matches.");
    w.open("struct ResultLanes {");
    for (const ir::Force& f : b.forces)
      w.line(std::string("rift::lanes::Vec3 ") + force_field(b, f) + ";");
    w.close("};");
    w.line("/// The body for ms[0] .. ms[kWidth - 1] at once (rift/core/lanes.hpp): the forces");
    w.line("/// evaluate() gives each, to the bit; true in the lanes whose `when`s hold.");
    w.line(
        "[[gnu::always_inline]] inline rift::lanes::Mask evaluate_lanes(const Match* ms, const "
        "rift::ForceInput& in, const Columns& c, ResultLanes& r) const;");
  }
  w.line("/// The interaction's body; false where a `when` fails.");
  w.line(b.stores.empty() ? "template <bool kForces>"
                          : "template <bool kForces, bool kStores = false>");
  w.line(
      "[[gnu::always_inline]] inline bool evaluate(const Match& m, const rift::ForceInput& in, "
      "const Columns& c, Result& r) "
      "const;");
  w.line("std::string name_ = " + quote(inter.name.text) + ";");
  w.line(params + " p_;");
  // Not every body reads a pack-level parameter; clang warns of an unused field.
  w.line("[[maybe_unused]] Params pack_;");
  for (const std::string& name : plan.embeddings) {
    w.line("rift::Embedding<" + embedding_storage(model, name) + "> " + embedding_var(name) + ";");
  }
  if (inter.tagged) {
    w.line("rift::Embedding<rift::Bool> tag_;  ///< unbound when !rewrites_");
    w.line("bool rewrites_ = true;");
  }
  if (!k.store_only_embeddings.empty()) w.line("bool store_ = true;");
  if (k.lanes) w.line("bool lanes_ = true;");
  w.close("};");
  w.line("using " + interaction_class(inter.name.text) + " = rift::CachedInteraction<" + k.cls +
         ">;");
  w.line();
}

void emit_kernel(Writer& w, const InteractionPlan& plan, const PackModel& model) {
  const Kernel k = kernel_of(plan);
  w.line("// ---- interaction '" + k.inter->name.text + "'");
  w.line();
  write_find(w, k);
  write_initialise(w, k, model);
  write_match(w, k);
  if (chooses_support_dart(k)) write_support_dart(w, k);
  write_columns(w, k);
  write_evaluate(w, k);
  if (k.lanes) write_evaluate_lanes(w, k);
  write_add_forces_all(w, k, false);
  write_add_forces_all(w, k, true);
  write_force_targets(w, k);
  // Matches that store values are not grouped: each stores its own.
  if (!k.plan->body.forces.empty() && k.plan->body.stores.empty()) {
    write_group_key(w, k);
    write_group_passes(w, k);
  }
  write_reset(w, k);
  write_accumulated(w, k);
  write_energy(w, k);
  if (k.derivative.available) {
    write_vertex_slots(w, k);
    write_jacobian(w, k);
    write_jacobian_product(w, k);
  }
}

}  // namespace rift::emit
