#include "check/topology.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <set>

#include "ast/orbit_text.hpp"
#include "check/alpha_word.hpp"
#include "check/types.hpp"

namespace rift::check {

namespace {

std::string dim_str(int d) {
  return std::to_string(d);
}

class RuleChecker {
 public:
  RuleChecker(RuleGraph& g, diag::Diagnostics& diags) : g_(g), diags_(diags) {}

  /// Every label of the rule has the length of the first one.
  void label_lengths() {
    const GraphNode* ref = nullptr;
    for (const PatternSide* side : {&g_.left, &g_.right}) {
      for (const GraphNode& n : side->nodes) {
        if (!ref) {
          ref = &n;
          g_.label_length = static_cast<int>(n.label().size());
          continue;
        }
        if (n.label().size() != ref->label().size()) {
          fail(n.decl->label.loc, "the label of '" + n.name() + "' has " +
                                      std::to_string(n.label().size()) +
                                      " entries but the labels of this rule have " +
                                      std::to_string(ref->label().size()))
              .notes.push_back({ref->decl->label.loc, "the label of '" + ref->name() + "'"});
        }
      }
    }
  }

  /// Explicit or inferred hooks: one full-label left node per left component.
  void hooks(const std::vector<ast::Ident>& explicit_hooks, const char* pattern_name) {
    const std::vector<int> comp = components(g_.left);
    std::vector<int> hook_of(g_.left.nodes.size(), -1);  // by component root
    for (const ast::Ident& h : explicit_hooks) {
      const int v = g_.left.find(h.text);
      if (v < 0) {
        fail(h.loc, "hook '" + h.text + "' is not a node of the " + pattern_name + " pattern");
        continue;
      }
      const GraphNode& node = g_.left.nodes[static_cast<std::size_t>(v)];
      if (has_underscore(node)) {
        fail(h.loc, "hook '" + h.text + "' has '_' in its label; a hook needs a full label")
            .notes.push_back({node.decl->label.loc, "label given here"});
      }
      int& slot = hook_of[static_cast<std::size_t>(comp[static_cast<std::size_t>(v)])];
      if (slot >= 0) {
        fail(h.loc, "'" + h.text + "' and '" +
                        g_.left.nodes[static_cast<std::size_t>(slot)].name() +
                        "' are two hooks in one connected component")
            .notes.push_back(
                {g_.left.nodes[static_cast<std::size_t>(slot)].decl->name.loc, "the other hook"});
        continue;
      }
      slot = v;
      g_.hooks.push_back(v);
    }
    for (std::size_t v = 0; v < g_.left.nodes.size(); ++v) {
      const auto c = static_cast<std::size_t>(comp[v]);
      if (hook_of[c] >= 0 || hook_of[c] == -2) continue;
      const GraphNode& node = g_.left.nodes[v];
      if (!explicit_hooks.empty()) {
        fail(node.decl->name.loc, "the connected component of '" + node.name() + "' has no hook")
            .notes.push_back({explicit_hooks.front().loc, "hooks are listed here"});
        hook_of[c] = -2;
        continue;
      }
      // Inferred: the first node written in the component whose label is full.
      int chosen = -1;
      for (std::size_t w = 0; w < g_.left.nodes.size() && chosen < 0; ++w) {
        if (comp[w] == comp[v] && !has_underscore(g_.left.nodes[w])) chosen = static_cast<int>(w);
      }
      if (chosen < 0) {
        fail(node.decl->name.loc, "the connected component of '" + node.name() +
                                      "' has no node with a full label to serve as its hook");
        hook_of[c] = -2;
        continue;
      }
      hook_of[c] = chosen;
      g_.hooks.push_back(chosen);
    }
    // Hooks may have different labels of one length (Jerboa's "isomorphic
    // after renaming"): the matcher walks each hook's orbit with its own
    // label and applies the rule only where they correspond position by
    // position.
    for (int h : g_.hooks)
      g_.hook_labels.push_back(g_.left.nodes[static_cast<std::size_t>(h)].label());
    if (g_.hooks.empty() && g_.left.nodes.empty() && g_.label_length > 0) {
      // A generator has a single row: implicit arcs would have nothing to follow.
      const GraphNode& n = g_.right.nodes.front();
      fail(n.decl->label.loc,
           "a rule without a left pattern has a single row; its labels must be <>");
    }
  }

  /// Dimensions used on node v: (dimension, where) for its label and arcs.
  std::vector<std::pair<int, diag::Location>> dims_of(const PatternSide& side, int v) const {
    std::vector<std::pair<int, diag::Location>> out;
    const GraphNode& n = side.nodes[static_cast<std::size_t>(v)];
    for (int d : n.label()) {
      if (d >= 0) out.emplace_back(d, n.decl->label.loc);
    }
    for (const GraphArc& arc : side.arcs) {
      if (arc.a == v || arc.b == v) out.emplace_back(arc.dim, arc.decl->dim_loc);
    }
    return out;
  }

  /// Per side: no dimension twice on a node. Returns the set of dimensions per node.
  std::vector<std::set<int>> unique_dims(const PatternSide& side) {
    std::vector<std::set<int>> result(side.nodes.size());
    for (std::size_t v = 0; v < side.nodes.size(); ++v) {
      for (const auto& [d, loc] : dims_of(side, static_cast<int>(v))) {
        if (!result[v].insert(d).second) {
          fail(loc, "dimension " + dim_str(d) + " is used twice on node '" + side.nodes[v].name() +
                        "' (label and arcs together give each dimension at most once)");
        }
      }
    }
    return result;
  }

  void incident_arcs() {
    const auto left = unique_dims(g_.left);
    const auto right = unique_dims(g_.right);
    for (std::size_t v = 0; v < g_.left.nodes.size(); ++v) {
      const GraphNode& n = g_.left.nodes[v];
      const int r = g_.right.find(n.name());
      if (r < 0) {
        require_all(left[v], n, "deleted");
        continue;
      }
      const GraphNode& rn = g_.right.nodes[static_cast<std::size_t>(r)];
      const auto& rd = right[static_cast<std::size_t>(r)];
      for (int d = 0; d <= g_.dimension; ++d) {
        const bool in_l = left[v].count(d) > 0;
        const bool in_r = rd.count(d) > 0;
        if (in_l == in_r) continue;
        const GraphNode& where = in_l ? rn : n;
        fail(where.decl->name.loc, "node '" + n.name() + "' has a " + dim_str(d) + "-arc in the " +
                                       (in_l ? "left" : "right") + " pattern but none in the " +
                                       (in_l ? "right" : "left") +
                                       " one; a preserved node keeps the same arc dimensions")
            .notes.push_back({(in_l ? n : rn).decl->name.loc,
                              std::string("the ") + (in_l ? "left" : "right") + " node"});
      }
    }
    for (std::size_t v = 0; v < g_.right.nodes.size(); ++v) {
      if (g_.left.find(g_.right.nodes[v].name()) < 0) {
        require_all(right[v], g_.right.nodes[v], "created");
      }
    }
  }

  void cycles() {
    for (int i = 0; i <= g_.dimension; ++i) {
      for (int j = i + 2; j <= g_.dimension; ++j)
        cycles(i, j);
    }
  }

  bool ok() const { return ok_; }

 private:
  static bool has_underscore(const GraphNode& n) {
    for (int d : n.label()) {
      if (d < 0) return true;
    }
    return false;
  }

  diag::Diagnostic& fail(const diag::Location& loc, std::string message) {
    ok_ = false;
    return diags_.error(loc, std::move(message));
  }

  void require_all(const std::set<int>& dims, const GraphNode& n, const char* kind) {
    for (int d = 0; d <= g_.dimension; ++d) {
      if (dims.count(d)) continue;
      fail(n.decl->name.loc, std::string(kind) + " node '" + n.name() + "' has no " + dim_str(d) +
                                 "-arc; a " + kind + " node needs one arc of every dimension 0.." +
                                 dim_str(g_.dimension));
    }
  }

  /// Walks i, j, i, j from v and tells whether it closes on v in the same row.
  bool on_cycle(const PatternSide& side, int v, int i, int j) const {
    int cur = v;
    std::vector<int> word;  // label positions of the hook links crossed, reduced as we go
    for (int d : {i, j, i, j}) {
      const auto s = step(side, cur, d);
      if (!s) return false;
      cur = s->node;
      if (s->pos < 0) continue;
      if (!word.empty() && word.back() == s->pos) {
        word.pop_back();  // each hook link is an involution
      } else {
        word.push_back(s->pos);
      }
    }
    if (cur != v) return false;
    if (word.empty()) return true;
    return word.size() == 4 && word[0] == word[2] && word[1] == word[3] &&
           rows_commute(word[0], word[1]);
  }

  /// The hook links at label positions p and q commute on the rows: a hook's
  /// alpha_a alpha_b alpha_a alpha_b is the identity when |a - b| >= 2 (the
  /// G-map condition), and every hook's orbit corresponds to the first's
  /// position by position, so one hook with such a pair is enough.
  bool rows_commute(int p, int q) const {
    for (const std::vector<int>& label : g_.hook_labels) {
      const int a = label[static_cast<std::size_t>(p)];
      const int b = label[static_cast<std::size_t>(q)];
      if (a - b >= 2 || b - a >= 2) return true;
    }
    return false;
  }

  void cycles(int i, int j) {
    const std::string ij = dim_str(i) + "-" + dim_str(j);
    for (std::size_t v = 0; v < g_.right.nodes.size(); ++v) {
      const GraphNode& rn = g_.right.nodes[v];
      const int l = g_.left.find(rn.name());
      const bool on_r = on_cycle(g_.right, static_cast<int>(v), i, j);
      if (l < 0) {
        if (!on_r) {
          fail(rn.decl->name.loc, "created node '" + rn.name() + "' does not lie on a " + ij + "-" +
                                      ij + " cycle, so alpha_" + dim_str(i) + " o alpha_" +
                                      dim_str(j) + " would not be an involution");
        }
        continue;
      }
      const GraphNode& ln = g_.left.nodes[static_cast<std::size_t>(l)];
      if (on_cycle(g_.left, l, i, j)) {
        if (!on_r) {
          fail(rn.decl->name.loc, "node '" + rn.name() + "' lies on a " + ij + "-" + ij +
                                      " cycle in the left pattern but not in the right one")
              .notes.push_back({ln.decl->name.loc, "the left node"});
        }
        continue;
      }
      for (int d : {i, j}) {
        const auto before = step(g_.left, l, d);
        const auto after = step(g_.right, static_cast<int>(v), d);
        if (same_step(before, after)) continue;
        fail(rn.decl->name.loc, "node '" + rn.name() + "' lies on no " + ij + "-" + ij +
                                    " cycle in the left pattern, so its " + dim_str(d) +
                                    "-arc must not change")
            .notes.push_back({ln.decl->name.loc, "the left node"});
      }
    }
  }

  /// Same arc before and after: same kind, same target (compared by name).
  bool same_step(const std::optional<Step>& a, const std::optional<Step>& b) const {
    if (!a || !b) return !a && !b;
    if (a->pos != b->pos) return false;
    return g_.left.nodes[static_cast<std::size_t>(a->node)].name() ==
           g_.right.nodes[static_cast<std::size_t>(b->node)].name();
  }

  RuleGraph& g_;
  diag::Diagnostics& diags_;
  bool ok_ = true;
};

}  // namespace

std::vector<CheckedRule> check_rules(const ast::Program& program, diag::Diagnostics& diags) {
  std::vector<CheckedRule> out;
  for (const ast::File& file : program.files) {
    for (const ast::Rule& rule : file.rules) {
      CheckedRule cr;
      cr.rule = &rule;
      cr.graph.dimension = program.dimension;
      const std::size_t before = diags.error_count();
      if (!rule.left.present && !rule.right.present) {
        diags.error(rule.name.loc,
                    "rule '" + rule.name.text + "' has neither a left nor a right pattern");
      }
      for (const ast::Assign& a : rule.left.assigns) {
        diags.error(a.loc, "embedding expressions belong to right nodes; move this into 'right'");
      }
      cr.graph.left = build_side(rule.left, program.dimension, diags);
      cr.graph.right = build_side(rule.right, program.dimension, diags);
      RuleChecker rc(cr.graph, diags);
      rc.label_lengths();
      rc.hooks(rule.hooks, "left");
      if (diags.error_count() == before) {
        // Arc and cycle conditions only make sense on well-formed labels and hooks.
        rc.incident_arcs();
        if (rc.ok()) rc.cycles();
      }
      cr.ok = rc.ok() && diags.error_count() == before;
      out.push_back(std::move(cr));
    }
  }
  return out;
}

namespace {

bool within(const std::vector<int>& word, const std::vector<int>& dims) {
  for (int d : word) {
    if (std::find(dims.begin(), dims.end(), d) == dims.end()) return false;
  }
  return true;
}

using ast::orbit_text;

std::string word_text(const std::vector<int>& word) {
  std::string out;
  for (int d : word) {
    out += '@';
    out += std::to_string(d);
  }
  return out;
}

/// Each stored force orbit, and each orbit a `store` writes, belongs to
/// exactly one match (matches run in parallel and write them without
/// synchronisation). A match is one
/// orbit of the support, reached from one dart c; a node of the pattern is
/// c followed by the alpha word of its path from the hook. Two matches write
/// the same place only if (a) the stored orbit is not inside the support
/// orbit, for an embedding on a non-empty orbit, or (b) for an embedding on
/// darts (<>), two nodes storing it are related by a word that leaves the
/// support: the same node of two matches is never the same dart (a word of
/// involutions is a bijection).
void check_force_ownership(const ast::Interaction& inter, const RuleGraph& g,
                           const resolve::Symbols& symbols, diag::Diagnostics& diags) {
  const PatternSide& side = g.left;
  if (g.hooks.empty()) return;
  // The word of each node from the hook, breadth-first along explicit arcs.
  // path[n]: the alpha word from the hook to node n, where reached[n].
  std::vector<std::vector<int>> path(side.nodes.size());
  std::vector<bool> reached(side.nodes.size(), false);
  std::vector<int> queue = {g.hooks[0]};
  reached[static_cast<std::size_t>(g.hooks[0])] = true;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int v = queue[q];
    for (const GraphArc& arc : side.arcs) {
      const int other = arc.a == v ? arc.b : arc.b == v ? arc.a : -1;
      if (other < 0 || reached[static_cast<std::size_t>(other)]) continue;
      std::vector<int> w = path[static_cast<std::size_t>(v)];
      w.push_back(arc.dim);
      path[static_cast<std::size_t>(other)] = w;
      reached[static_cast<std::size_t>(other)] = true;
      queue.push_back(other);
    }
  }
  const std::vector<int>& support = inter.support.dims;
  std::vector<const ast::Assign*> darts;  // stores into embeddings on <>
  std::vector<const ast::Assign*> written;
  written.reserve(inter.forces.size() + inter.stores.size());
  for (const ast::Assign& f : inter.forces)
    written.push_back(&f);
  for (const ast::Assign& st : inter.stores)
    written.push_back(&st);
  auto kind = [&](const ast::Assign& a) {
    const bool store = std::any_of(inter.stores.begin(), inter.stores.end(),
                                   [&](const ast::Assign& st) { return &st == &a; });
    return std::string(store ? "stored values" : "stored forces");
  };
  for (const ast::Assign* fp : written) {
    const ast::Assign& f = *fp;
    const ast::Embedding* target = symbols.target(f);
    if (!target) continue;
    const int node = side.find(f.node.text);
    if (node < 0 || !reached[static_cast<std::size_t>(node)]) continue;
    const std::vector<int> word = reduced_word(path[static_cast<std::size_t>(node)]);
    if (target->orbit.dims.empty()) {
      darts.push_back(&f);
      continue;
    }
    if (within(target->orbit.dims, support) && within(word, support)) continue;
    diags
        .error(f.embedding.loc,
               "'" + f.embedding.text + "' is stored per orbit " + orbit_text(target->orbit.dims) +
                   " at '" + f.node.text + "', which is not inside the support orbit " +
                   orbit_text(inter.support.dims) + " of the match: two matches could store into " +
                   "the same orbit (" + kind(f) + " are written, not added); store it on an " +
                   "orbit inside the support, or on darts")
        .notes.push_back({target->orbit.loc, "its orbit"});
  }
  for (std::size_t i = 0; i < darts.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const ast::Assign& a = *darts[j];
      const ast::Assign& b = *darts[i];
      if (a.embedding.text != b.embedding.text || a.node.text == b.node.text) continue;
      // c' with c'.w_b == c.w_a: c' = c.w_a.reverse(w_b).
      std::vector<int> w = path[static_cast<std::size_t>(side.find(a.node.text))];
      const std::vector<int>& pb = path[static_cast<std::size_t>(side.find(b.node.text))];
      w.insert(w.end(), pb.rbegin(), pb.rend());
      const std::vector<int> between = reduced_word(w);
      if (within(between, support)) continue;
      diags
          .error(b.embedding.loc,
                 "'" + b.embedding.text + "' is stored at '" + a.node.text + "' and at '" +
                     b.node.text + "', which are " + a.node.text + word_text(between) +
                     " apart, outside the support orbit " + orbit_text(inter.support.dims) +
                     ": the '" + a.node.text + "' of one match can be the '" + b.node.text +
                     "' of another, and both write it (" + kind(b) + " are written, not added)")
          .notes.push_back({a.embedding.loc, "the other store"});
    }
  }
}

}  // namespace

std::vector<CheckedInteraction> check_interactions(const ast::Program& program,
                                                   const resolve::Symbols& symbols,
                                                   diag::Diagnostics& diags) {
  std::vector<CheckedInteraction> out;
  for (const ast::File& file : program.files) {
    for (const ast::Interaction& inter : file.interactions) {
      CheckedInteraction ci;
      ci.interaction = &inter;
      ci.graph.dimension = program.dimension;
      const std::size_t before = diags.error_count();
      check_orbit_type(inter.support, program.dimension, "an interaction's support", diags);
      if (!inter.pattern.present) {
        diags.error(inter.name.loc, "interaction '" + inter.name.text + "' has no 'pattern'");
      }
      for (const ast::Assign& a : inter.pattern.assigns) {
        diags.error(a.loc, "a pattern only matches; store results with 'force'");
      }
      ci.graph.left = build_side(inter.pattern, program.dimension, diags);
      RuleChecker rc(ci.graph, diags);
      rc.label_lengths();
      rc.hooks({}, "interaction");
      if (ci.graph.hooks.size() > 1) {
        const GraphNode& second = ci.graph.left.nodes[static_cast<std::size_t>(ci.graph.hooks[1])];
        diags.error(second.decl->name.loc,
                    "node '" + second.name() + "' is not connected to '" +
                        ci.graph.left.nodes[static_cast<std::size_t>(ci.graph.hooks[0])].name() +
                        "'; an interaction pattern is reached from the support dart by explicit " +
                        "arcs");
      }
      if (rc.ok()) rc.unique_dims(ci.graph.left);
      // Interaction patterns are explicit (every node a single dart, reached
      // from the support dart by explicit arcs): a match is then a fixed-size
      // record of slots, cached and swept by a flat force loop.
      for (const GraphNode& node : ci.graph.left.nodes) {
        if (node.label().empty()) continue;
        diags
            .error(node.decl->label.loc,
                   "node '" + node.name() + "' of an interaction pattern is labelled with an " +
                       "orbit; interaction patterns are explicit: label every node <> and " +
                       "reach it with explicit arcs")
            .notes.push_back({inter.support.loc, "the support orbit, matched from one dart"});
        break;
      }
      std::string vertex = "<";
      for (int d = 1; d <= program.dimension; ++d) {
        if (d > 1) vertex += ',';
        vertex += dim_str(d);
      }
      vertex += ">";
      for (const ast::Assign& f : inter.forces) {
        const ast::Embedding* target = symbols.target(f);
        if (!target) continue;
        bool inside = true;
        for (int d : target->orbit.dims)
          inside = inside && d >= 1 && d <= program.dimension;
        if (!inside) {
          diags
              .error(f.embedding.loc, "force embedding '" + f.embedding.text +
                                          "' is not stored in a sub-orbit of the vertex orbit " +
                                          vertex + ", so it cannot be gathered per vertex")
              .notes.push_back({target->orbit.loc, "its orbit"});
        }
      }
      if (rc.ok() && diags.error_count() == before)
        check_force_ownership(inter, ci.graph, symbols, diags);
      ci.ok = rc.ok() && diags.error_count() == before;
      out.push_back(std::move(ci));
    }
  }
  return out;
}

namespace {

/// The number of hooks of the rule or script `name`, or -1 when unknown;
/// `kind` says which it is.
int hook_count(const ast::Program& program, const std::vector<CheckedRule>& rules,
               const std::string& name, diag::Location* declared, std::string* kind) {
  for (const CheckedRule& cr : rules) {
    if (cr.rule->name.text != name) continue;
    *declared = cr.rule->name.loc;
    *kind = "rule";
    return cr.ok ? static_cast<int>(cr.graph.hooks.size()) : -1;
  }
  for (const ast::File& file : program.files) {
    for (const ast::Script& s : file.scripts) {
      if (s.name.text != name) continue;
      *declared = s.name.loc;
      *kind = "script";
      return static_cast<int>(s.hooks.size());
    }
  }
  return -1;
}

void check_hook_count(const ast::Program& program, const std::vector<CheckedRule>& rules,
                      const ast::Ident& callee, std::size_t given, const diag::Location& loc,
                      diag::Diagnostics& diags) {
  diag::Location declared;
  std::string kind;
  const int want = hook_count(program, rules, callee.text, &declared, &kind);
  if (want < 0 || static_cast<std::size_t>(want) == given) return;
  diags
      .error(loc, kind + " '" + callee.text + "' has " + std::to_string(want) + " hook(s) but " +
                      std::to_string(given) + " dart(s) are given")
      .notes.push_back({declared, kind + " declared here"});
}

}  // namespace

void check_applies(const ast::Program& program, const std::vector<CheckedRule>& rules,
                   diag::Diagnostics& diags) {
  for (const ast::File& file : program.files) {
    for (const ast::Criterion& crit : file.criteria) {
      check_orbit_type(crit.orbit, program.dimension, "a criterion", diags);
      if (!crit.has_apply) continue;
      check_hook_count(program, rules, crit.rule, crit.apply_hooks.size(), crit.apply_loc, diags);
    }
    for (const ast::Script& script : file.scripts) {
      for (const ast::ScriptStmt& st : script.stmts) {
        if (st.kind != ast::ScriptStmt::Kind::Apply) continue;
        check_hook_count(program, rules, st.rule, st.hooks.size(), st.loc, diags);
      }
    }
  }
}

}  // namespace rift::check
