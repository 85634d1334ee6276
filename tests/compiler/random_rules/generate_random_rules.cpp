// Writes a pack of random topological rules that keep every G-map valid, and
// a file of random rules that can break one, then asks riftc about both
// (issue 9, deliverable 5).
//
// A rule is built as Jerboa rules are drawn:
//   - L: one hook (a full label H, a random subset of the dimensions in a
//     random order) and a few nodes reached by explicit arcs, written as a
//     mesh has them (an arc u -i- v between nodes labelled from H only where
//     i commutes with every dimension of their labels, so that the pattern
//     can match; loops for free darts); sometimes two components (two hooks,
//     as sewing rules have; half of the time the second hook's label is the
//     first's dimensions in another order, which Jerboa allows: the rule
//     applies where the two orbits correspond after that renaming).
//   - R: L changed by 1 to 4 random edits: unsew an arc, sew two loops,
//     delete a node, drop or rename one entry of a label, create a node with
//     a random label; then every dart slot left without a link is completed
//     at random (a loop, or an arc to another node missing that dimension).
//
// Every candidate is judged by this file's own checker of the conditions of
// JERBOA_RULES.md (incident arcs; i-j-i-j cycles for i + 2 <= j, decided by
// walking i, j, i, j through labels, loops and explicit arcs while keeping the
// row as a word over the hooks' label positions, reduced in the right-angled
// Coxeter group where positions commute when some hook's dimensions there
// differ by 2 or more: every hook's orbit corresponds to the first's). Candidates it finds
// consistent go to the pack, the others (a few of each failed condition) to the file of
// inconsistent rules. riftc is then run on both: the pack keeps only what
// riftc accepts, and the report lists riftc's rejections of consistent rules
// and every inconsistent rule riftc accepted. random_rules_test.cpp reads the
// report and applies the pack's rules to random maps.
//
// Usage: generate_random_rules --dimension N --seed S --count C --bad B
//            --pack NAME --riftc PATH --out PACK.rules --bad-out BAD.rules
//            --report REPORT.txt
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Rng = std::mt19937_64;

int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}
bool chance(Rng& rng, double p) {
  return std::uniform_real_distribution<double>(0, 1)(rng) < p;
}

constexpr int kNone = -1;  // `_` in a label, or "no node" on a side

/// One side (L or R) of a rule: the label of every node present on it
/// (empty optional: absent), and its explicit arcs by (node, dimension).
struct Side {
  std::vector<std::optional<std::vector<int>>> labels;
  std::map<std::pair<int, int>, int> arcs;  // (node, dim) -> node (itself: a loop)

  bool has(int v) const { return v < static_cast<int>(labels.size()) && labels[v].has_value(); }
  const std::vector<int>& label(int v) const { return *labels[v]; }
  int arc(int v, int d) const {
    const auto it = arcs.find({v, d});
    return it == arcs.end() ? kNone : it->second;
  }
  void link(int u, int d, int v) {
    arcs[{u, d}] = v;
    arcs[{v, d}] = u;
  }
  void unlink(int u, int d) {
    const int v = arc(u, d);
    if (v == kNone) return;
    arcs.erase({u, d});
    arcs.erase({v, d});
  }
  /// The label position carrying dimension d on v, or kNone.
  int position_of(int v, int d) const {
    const auto& l = label(v);
    for (std::size_t p = 0; p < l.size(); ++p) {
      if (l[p] == d) return static_cast<int>(p);
    }
    return kNone;
  }
  /// Dimensions v has a link in (label entries and explicit arcs).
  std::set<int> dims(int v) const {
    std::set<int> out;
    for (int d : label(v)) {
      if (d != kNone) out.insert(d);
    }
    for (const auto& [key, target] : arcs) {
      if (key.first == v) out.insert(key.second);
    }
    return out;
  }
};

struct Rule {
  std::vector<int> hook_label;                // H, the first hook's label
  std::vector<std::vector<int>> hook_labels;  // every hook's, in hook order
  std::vector<int> hooks;                     // one node per left component
  int nodes = 0;
  Side left, right;
  std::string edits;      // what was done to L, for the comment
  std::string embedding;  // an embedding expression line, or empty
};

// ---- the checker ----------------------------------------------------------------------

/// Is a word over the hooks' label positions the identity in the
/// right-angled Coxeter group where positions p, q commute when some hook's
/// dimensions there differ by 2 or more (the hooks' orbits correspond
/// position by position, so a relation of one holds in all)? Tits: a word
/// that is not reduced has two equal letters with only letters commuting with
/// them in between; cancelling such pairs until none is left decides it.
bool is_identity(std::vector<int> word, const std::vector<std::vector<int>>& hooks) {
  const auto commute = [&](int p, int q) {
    if (p == q) return true;
    for (const std::vector<int>& hook : hooks) {
      if (std::abs(hook[static_cast<std::size_t>(p)] - hook[static_cast<std::size_t>(q)]) >= 2)
        return true;
    }
    return false;
  };
  bool changed = true;
  while (changed && !word.empty()) {
    changed = false;
    for (std::size_t a = 0; a < word.size() && !changed; ++a) {
      for (std::size_t b = a + 1; b < word.size(); ++b) {
        if (word[b] == word[a]) {
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(b));
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(a));
          changed = true;
          break;
        }
        if (!commute(word[a], word[b])) break;
      }
    }
  }
  return word.empty();
}

/// Does node v of `side` lie on an i-j-i-j cycle, whatever the matched orbit?
bool on_cycle(const Side& side, const std::vector<std::vector<int>>& hooks, int v, int i, int j) {
  int node = v;
  std::vector<int> word;
  for (const int d : {i, j, i, j}) {
    const int p = side.position_of(node, d);
    if (p != kNone) {
      word.push_back(p);
      continue;
    }
    const int next = side.arc(node, d);
    if (next == kNone) return false;
    node = next;
  }
  return node == v && is_identity(word, hooks);
}

/// How v is linked in dimension d: by the label position, by an arc to a
/// node (a loop is an arc to itself), or not at all.
std::pair<int, int> link_of(const Side& side, int v, int d) {
  const int p = side.position_of(v, d);
  if (p != kNone) return {0, p};
  const int target = side.arc(v, d);
  if (target != kNone) return {1, target};
  return {2, 0};
}

enum class Verdict { kConsistent, kIncident, kCycleCreated, kCyclePreserved };

/// The conditions of JERBOA_RULES.md under which a rule keeps a G-map of
/// dimension n valid. Every label and arc is well formed by construction.
Verdict check(const Rule& r, int n) {
  for (int v = 0; v < r.nodes; ++v) {
    const bool in_l = r.left.has(v), in_r = r.right.has(v);
    if (!in_l && !in_r) continue;
    // No dimension twice on one node.
    for (const Side* s : {&r.left, &r.right}) {
      if (!s->has(v)) continue;
      std::multiset<int> seen;
      for (int d : s->label(v)) {
        if (d != kNone) seen.insert(d);
      }
      for (const auto& [key, target] : s->arcs) {
        if (key.first == v) seen.insert(key.second);
      }
      if (std::set<int>(seen.begin(), seen.end()).size() != seen.size()) return Verdict::kIncident;
    }
    std::set<int> all;
    for (int d = 0; d <= n; ++d)
      all.insert(d);
    if (in_l && in_r && r.left.dims(v) != r.right.dims(v)) return Verdict::kIncident;
    if (in_l && !in_r && r.left.dims(v) != all) return Verdict::kIncident;
    if (!in_l && in_r && r.right.dims(v) != all) return Verdict::kIncident;
    for (int i = 0; i <= n; ++i) {
      for (int j = i + 2; j <= n; ++j) {
        if (!in_l && in_r && !on_cycle(r.right, r.hook_labels, v, i, j))
          return Verdict::kCycleCreated;
        if (in_l && in_r) {
          if (on_cycle(r.left, r.hook_labels, v, i, j)) {
            if (!on_cycle(r.right, r.hook_labels, v, i, j)) return Verdict::kCyclePreserved;
          } else if (link_of(r.left, v, i) != link_of(r.right, v, i) ||
                     link_of(r.left, v, j) != link_of(r.right, v, j)) {
            return Verdict::kCyclePreserved;
          }
        }
      }
    }
  }
  return Verdict::kConsistent;
}

// ---- random rules ---------------------------------------------------------------------

/// L: the hook(s) and up to three more nodes per component, linked as a mesh
/// links them (see the file comment).
void random_left(Rule& r, int n, Rng& rng) {
  std::vector<int> dims(static_cast<std::size_t>(n) + 1);
  for (int d = 0; d <= n; ++d)
    dims[static_cast<std::size_t>(d)] = d;
  std::shuffle(dims.begin(), dims.end(), rng);
  dims.resize(static_cast<std::size_t>(uniform_int(rng, 0, n)));
  if (chance(rng, 0.6)) std::sort(dims.begin(), dims.end());
  r.hook_label = dims;
  const int components = chance(rng, 0.2) ? 2 : 1;
  for (int c = 0; c < components; ++c) {
    const int hook = r.nodes++;
    std::vector<int> hook_label = r.hook_label;
    if (c > 0 && chance(rng, 0.5)) std::shuffle(hook_label.begin(), hook_label.end(), rng);
    r.hook_labels.push_back(hook_label);
    r.left.labels.resize(static_cast<std::size_t>(r.nodes));
    r.left.labels[static_cast<std::size_t>(hook)] = hook_label;
    r.hooks.push_back(hook);
    std::vector<int> members{hook};
    const int grow = uniform_int(rng, 0, 3);
    for (int attempt = 0, added = 0; attempt < 12 && added < grow; ++attempt) {
      const int u = members[static_cast<std::size_t>(
          uniform_int(rng, 0, static_cast<int>(members.size()) - 1))];
      const int i = uniform_int(rng, 0, n);
      const std::set<int> used = r.left.dims(u);
      if (used.count(i) != 0) continue;
      bool commutes = true;
      for (int d : r.left.label(u)) {
        if (d != kNone && std::abs(d - i) < 2) commutes = false;
      }
      if (chance(rng, 0.3)) {
        r.left.link(u, i, u);  // a free dart
        ++added;
        continue;
      }
      if (!commutes) continue;
      std::vector<int> label = r.left.label(u);
      for (int& d : label) {
        if (d != kNone && chance(rng, 0.25)) d = kNone;
      }
      const int v = r.nodes++;
      r.left.labels.resize(static_cast<std::size_t>(r.nodes));
      r.left.labels[static_cast<std::size_t>(v)] = label;
      r.left.link(u, i, v);
      members.push_back(v);
      ++added;
    }
  }
}

std::string text_of_label(const std::vector<int>& label) {
  std::string s = "<";
  for (std::size_t p = 0; p < label.size(); ++p) {
    if (p > 0) s += ",";
    s += label[p] == kNone ? "_" : std::to_string(label[p]);
  }
  return s + ">";
}

/// One random edit of R; false when it found nothing to do.
bool random_edit(Rule& r, int n, Rng& rng) {
  Side& right = r.right;
  std::vector<int> present;
  for (int v = 0; v < r.nodes; ++v) {
    if (right.has(v)) present.push_back(v);
  }
  const auto pick = [&](const std::vector<int>& from) {
    return from[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(from.size()) - 1))];
  };
  const auto name = [](int v) { return "n" + std::to_string(v); };
  switch (uniform_int(rng, 0, 6)) {
    case 0: {  // unsew an arc between two nodes
      std::vector<std::pair<int, int>> arcs;
      for (const auto& [key, target] : right.arcs) {
        if (target != key.first) arcs.push_back(key);
      }
      if (arcs.empty()) return false;
      const auto [u, d] =
          arcs[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(arcs.size()) - 1))];
      const int v = right.arc(u, d);
      right.unlink(u, d);
      right.link(u, d, u);
      right.link(v, d, v);
      r.edits += " unsew(" + name(u) + "," + name(v) + "," + std::to_string(d) + ")";
      return true;
    }
    case 1: {  // sew two loops of one dimension
      std::vector<std::pair<int, int>> loops;
      for (const auto& [key, target] : right.arcs) {
        if (target == key.first) loops.push_back(key);
      }
      if (loops.size() < 2) return false;
      const auto [u, d] =
          loops[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(loops.size()) - 1))];
      std::vector<int> partners;
      for (const auto& [node, dim] : loops) {
        if (dim == d && node != u) partners.push_back(node);
      }
      if (partners.empty()) return false;
      const int v = pick(partners);
      right.unlink(u, d);
      right.unlink(v, d);
      right.link(u, d, v);
      r.edits += " sew(" + name(u) + "," + name(v) + "," + std::to_string(d) + ")";
      return true;
    }
    case 2: {  // delete a node: its neighbours' links are left to the completion
      if (present.empty()) return false;
      const int v = pick(present);
      for (int d = 0; d <= n; ++d)
        right.unlink(v, d);
      right.labels[static_cast<std::size_t>(v)].reset();
      r.edits += " delete(" + name(v) + ")";
      return true;
    }
    case 5: {  // an insertion: a node drops one label entry, a created node takes the link
      if (present.empty()) return false;
      const int v = pick(present);
      auto& label = *right.labels[static_cast<std::size_t>(v)];
      std::vector<int> entries;
      for (std::size_t p = 0; p < label.size(); ++p) {
        if (label[p] != kNone) entries.push_back(static_cast<int>(p));
      }
      if (entries.empty()) return false;
      const int p = pick(entries);
      const int d = label[static_cast<std::size_t>(p)];
      label[static_cast<std::size_t>(p)] = kNone;
      std::vector<int> created(r.hook_label.size(), kNone);
      std::set<int> used{d};
      for (std::size_t q = 0; q < created.size(); ++q) {
        const int h = r.hook_label[q] + (chance(rng, 0.6) ? 1 : 0);
        if (static_cast<int>(q) != p && chance(rng, 0.8) && h <= n && used.insert(h).second)
          created[q] = h;
      }
      const int c = r.nodes++;
      r.left.labels.resize(static_cast<std::size_t>(r.nodes));
      right.labels.resize(static_cast<std::size_t>(r.nodes));
      right.labels[static_cast<std::size_t>(c)] = created;
      right.link(v, d, c);
      r.edits += " insert(" + name(v) + "," + std::to_string(p) + "," + name(c) + "," +
                 text_of_label(created) + ")";
      return true;
    }
    case 3:    // drop one label entry
    case 4: {  // or rename it to another dimension
      if (present.empty()) return false;
      const int v = pick(present);
      auto& label = *right.labels[static_cast<std::size_t>(v)];
      if (label.empty()) return false;
      const int p = uniform_int(rng, 0, static_cast<int>(label.size()) - 1);
      int to = kNone;
      if (chance(rng, 0.5)) {
        to = uniform_int(rng, 0, n);
        if (right.position_of(v, to) != kNone) return false;
        right.unlink(v, to);
      }
      r.edits += " relabel(" + name(v) + "," + std::to_string(p) + "," +
                 (to == kNone ? std::string("_") : std::to_string(to)) + ")";
      label[static_cast<std::size_t>(p)] = to;
      return true;
    }
    default: {  // create a node with a random label: each entry kept, shifted or dropped
      std::vector<int> label(r.hook_label.size(), kNone);
      std::set<int> used;
      for (std::size_t p = 0; p < label.size(); ++p) {
        const int roll = uniform_int(rng, 0, 9);
        const int h = r.hook_label[p];
        const int d = roll < 3 ? h : roll < 6 ? h + 1 : roll < 7 ? h - 1 : kNone;
        if (d >= 0 && d <= n && used.insert(d).second) label[p] = d;
      }
      const int v = r.nodes++;
      r.left.labels.resize(static_cast<std::size_t>(r.nodes));
      right.labels.resize(static_cast<std::size_t>(r.nodes));
      right.labels[static_cast<std::size_t>(v)] = label;
      r.edits += " create(" + name(v) + "," + text_of_label(label) + ")";
      return true;
    }
  }
}

/// Gives every R node the links it lacks: a preserved node the dimensions it
/// had in L, a created node every dimension. Each missing slot becomes a loop
/// or an arc to another node missing the same dimension. `skip` leaves one
/// slot open (for an inconsistent rule).
void complete(Rule& r, int n, Rng& rng, bool skip) {
  Side& right = r.right;
  bool skipped = false;
  for (int d = 0; d <= n; ++d) {
    std::vector<int> missing;
    for (int v = 0; v < r.nodes; ++v) {
      if (!right.has(v)) continue;
      const bool needs = r.left.has(v) ? r.left.dims(v).count(d) != 0 : true;
      if (needs && right.dims(v).count(d) == 0) missing.push_back(v);
    }
    std::shuffle(missing.begin(), missing.end(), rng);
    while (!missing.empty()) {
      const int u = missing.back();
      missing.pop_back();
      if (skip && !skipped) {
        skipped = true;
        continue;
      }
      if (!missing.empty() && chance(rng, 0.6)) {
        right.link(u, d, missing.back());
        missing.pop_back();
      } else {
        right.link(u, d, u);
      }
    }
  }
}

/// Sometimes an embedding expression on one created node (one per rule, so
/// never two for one orbit), read from the hook's values before the rewrite.
void random_expression(Rule& r, int n, Rng& rng) {
  std::vector<int> created;
  for (int v = 0; v < r.nodes; ++v) {
    if (r.right.has(v) && !r.left.has(v)) created.push_back(v);
  }
  if (created.empty() || !chance(rng, 0.5)) return;
  const int v =
      created[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(created.size()) - 1))];
  const std::string node = "n" + std::to_string(v), hook = "n" + std::to_string(r.hooks[0]);
  const std::string vertex = n == 2 ? "<1,2>" : "<1,2,3>";
  switch (uniform_int(rng, 0, 3)) {
    case 0:
      r.embedding = node + ".position = " + hook + ".position + vec3(0.125, 0.0, 0.0);";
      break;
    case 1:
      r.embedding = node + ".position = mean position over " + vertex + "(" + hook + ");";
      break;
    case 2:
      r.embedding = node + ".weight = " + hook + ".weight + 1.0;";
      break;
    default:
      r.embedding = node + ".count_here = count position over " + vertex + "(" + hook + ");";
      break;
  }
}

std::string text_of_side(const Side& side, int nodes) {
  std::string s;
  for (int v = 0; v < nodes; ++v) {
    if (side.has(v)) s += " n" + std::to_string(v) + " : " + text_of_label(side.label(v)) + ";";
  }
  for (const auto& [key, target] : side.arcs) {
    if (key.first <= target) {
      s += " n" + std::to_string(key.first) + " -" + std::to_string(key.second) + "- n" +
           std::to_string(target) + ";";
    }
  }
  return s;
}

/// The rule's text (its body only: the caller names it).
std::string body_of(const Rule& r) {
  std::string s = "  hook";
  for (std::size_t h = 0; h < r.hooks.size(); ++h)
    s += (h == 0 ? " n" : ", n") + std::to_string(r.hooks[h]);
  s += ";\n  left  {" + text_of_side(r.left, r.nodes) + " }\n";
  s += "  right {" + text_of_side(r.right, r.nodes);
  if (!r.embedding.empty()) s += " " + r.embedding;
  return s + " }\n";
}

std::string pack_header(const std::string& pack, int n) {
  const std::string vertex = n == 2 ? "<1,2>" : "<1,2,3>";
  const std::string edge = n == 2 ? "<0,2>" : "<0,2,3>";
  const std::string corner = n == 2 ? "<1>" : "<1,2>";
  std::string s = "pack " + pack + " dimension " + std::to_string(n) + ";\n\n";
  s += "// Embeddings on the vertex, edge, face, corner and dart orbits, each with a default\n"
       "// and a merge policy, so that a rule needs no expression to be consistent.\n";
  s += "embedding position   : vec3 on " + vertex + " = vec3(0, 0, 0) merge mean;\n";
  s += "embedding weight     : real on " + edge + " = 1.0 merge sum;\n";
  s += "embedding face_tag   : int on <0,1> = 7 merge keep;\n";
  s += "embedding corner_w   : real on " + corner + " = 0.5 merge mean;\n";
  s += "embedding count_here : int on <> = 0 merge keep;\n\n";
  return s;
}

/// The rule's kind, for a mix of them: 0 a created node linked to a
/// preserved one (insertions), 1 two hooks (sewing), 2 a deletion, 3 other.
int kind_of(const Rule& r) {
  for (const auto& [key, target] : r.right.arcs) {
    if (r.left.has(key.first) != r.left.has(target)) return 0;
  }
  if (r.hooks.size() == 2) return 1;
  for (int v = 0; v < r.nodes; ++v) {
    if (r.left.has(v) && !r.right.has(v)) return 2;
  }
  return 3;
}

struct Candidate {
  std::string body, edits;
  Verdict verdict = Verdict::kConsistent;
};

const char* to_text(Verdict v) {
  switch (v) {
    case Verdict::kConsistent:
      return "consistent";
    case Verdict::kIncident:
      return "incident arcs";
    case Verdict::kCycleCreated:
      return "cycle of a created node";
    case Verdict::kCyclePreserved:
      return "cycle of a preserved node";
  }
  return "";
}

/// Writes the rules to `path` and returns the first line of each.
std::vector<int> write_pack(const std::string& path, const std::string& header,
                            const std::vector<Candidate>& rules, const std::string& prefix) {
  std::ofstream out(path);
  out << header;
  int line = 1 + static_cast<int>(std::count(header.begin(), header.end(), '\n'));
  std::vector<int> first_lines;
  for (std::size_t k = 0; k < rules.size(); ++k) {
    out << "//" << rules[k].edits << "\n";
    ++line;
    first_lines.push_back(line);
    out << "rule " << prefix << k << " {\n" << rules[k].body << "}\n";
    line += 1 + static_cast<int>(std::count(rules[k].body.begin(), rules[k].body.end(), '\n')) + 1;
  }
  return first_lines;
}

struct Diagnostic {
  int line = 0;
  std::string text;
};

/// Runs riftc on `path` (no output: it only checks) and returns its errors.
std::vector<Diagnostic> riftc_errors(const std::string& riftc, const std::string& path) {
  const std::string command = "'" + riftc + "' '" + path + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    std::cerr << "cannot run " << command << "\n";
    std::exit(2);
  }
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr)
    output += buffer.data();
  pclose(pipe);
  std::vector<Diagnostic> errors;
  const std::regex located(":([0-9]+):[0-9]+: error: (.*)");
  std::istringstream lines(output);
  for (std::string l; std::getline(lines, l);) {
    std::smatch m;
    if (std::regex_search(l, m, located)) errors.push_back({std::stoi(m[1]), m[2]});
  }
  return errors;
}

/// The index of the rule whose text holds `line` (rules start at `first`).
int rule_at(const std::vector<int>& first, int line) {
  const auto it = std::upper_bound(first.begin(), first.end(), line);
  return static_cast<int>(it - first.begin()) - 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> args;
  for (int k = 1; k + 1 < argc; k += 2)
    args[argv[k]] = argv[k + 1];
  for (const char* key : {"--dimension", "--seed", "--count", "--bad", "--pack", "--riftc", "--out",
                          "--bad-out", "--report"}) {
    if (args.count(key) == 0) {
      std::cerr << "generate_random_rules: missing " << key << "\n";
      return 2;
    }
  }
  const int n = std::stoi(args["--dimension"]);
  const int count = std::stoi(args["--count"]), bad = std::stoi(args["--bad"]);
  Rng rng(std::stoull(args["--seed"]));

  // Candidates until `count` consistent ones and `bad` inconsistent ones (a
  // third of each failed condition) are found; duplicates are skipped.
  std::vector<Candidate> good, wrong;
  std::map<Verdict, int> wrong_by_kind;
  std::set<std::string> seen;
  std::array<int, 4> by_kind{};
  std::vector<Candidate> spare;  // kinds over their quota, to fill up with
  for (int attempt = 0; attempt < 100000; ++attempt) {
    if (static_cast<int>(good.size()) >= count && static_cast<int>(wrong.size()) >= bad) break;
    // (good fills by kind; see kind_of)
    Rule r;
    random_left(r, n, rng);
    r.right = r.left;
    const int edits = uniform_int(rng, 1, 4);
    int done = 0;
    for (int e = 0; e < 4 * edits && done < edits; ++e) {
      if (random_edit(r, n, rng)) ++done;
    }
    if (done == 0) continue;
    const bool open_slot = chance(rng, 0.1);
    complete(r, n, rng, open_slot);
    random_expression(r, n, rng);
    Candidate c{body_of(r), r.edits, check(r, n)};
    if (!seen.insert(c.body).second) continue;
    if (c.verdict == Verdict::kConsistent) {
      // A rule that changes nothing is consistent but says nothing.
      if (text_of_side(r.left, r.nodes) == text_of_side(r.right, r.nodes)) continue;
      const int kind = kind_of(r);
      if (by_kind[kind] < count / 4) {
        ++by_kind[kind];
        good.push_back(c);
      } else if (static_cast<int>(spare.size()) < count) {
        spare.push_back(c);
      }
    } else if (wrong_by_kind[c.verdict] < (bad + 2) / 3 && static_cast<int>(wrong.size()) < bad) {
      ++wrong_by_kind[c.verdict];
      c.edits += " [" + std::string(to_text(c.verdict)) + "]";
      wrong.push_back(c);
    }
  }

  for (std::size_t k = 0; k < spare.size() && static_cast<int>(good.size()) < count; ++k)
    good.push_back(spare[k]);

  const std::string pack = args["--pack"];
  const std::string header = pack_header(pack, n);
  std::ofstream report(args["--report"]);

  // Consistent rules: riftc must accept them; the pack keeps those it does.
  const std::string all_path = args["--out"] + ".all";
  const std::vector<int> first = write_pack(all_path, header, good, "rule_");
  std::set<int> rejected;
  std::ostringstream rejections;
  for (const Diagnostic& e : riftc_errors(args["--riftc"], all_path)) {
    const int k = rule_at(first, e.line);
    if (k < 0) {
      rejections << "outside any rule: line " << e.line << ": " << e.text << "\n";
      continue;
    }
    if (rejected.insert(k).second)
      rejections << "rule_" << k << " (" << good[static_cast<std::size_t>(k)].edits
                 << "): " << e.text << "\n"
                 << good[static_cast<std::size_t>(k)].body;
  }
  std::vector<Candidate> accepted;
  for (std::size_t k = 0; k < good.size(); ++k) {
    if (rejected.count(static_cast<int>(k)) == 0) accepted.push_back(good[k]);
  }
  write_pack(args["--out"], header, accepted, "rule_");

  // Inconsistent rules: riftc must reject every one.
  const std::vector<int> bad_first = write_pack(args["--bad-out"], header, wrong, "bad_");
  std::set<int> caught;
  for (const Diagnostic& e : riftc_errors(args["--riftc"], args["--bad-out"])) {
    const int k = rule_at(bad_first, e.line);
    if (k >= 0) caught.insert(k);
  }
  std::ostringstream missed;
  for (std::size_t k = 0; k < wrong.size(); ++k) {
    if (caught.count(static_cast<int>(k)) == 0)
      missed << "bad_" << k << " (" << wrong[k].edits << "):\n" << wrong[k].body;
  }

  report << "consistent_generated " << good.size() << "\n";
  report << "consistent_accepted " << accepted.size() << "\n";
  report << "inconsistent_generated " << wrong.size() << "\n";
  report << "inconsistent_rejected " << caught.size() << "\n";
  report << "---- consistent rules riftc rejected\n" << rejections.str();
  report << "---- inconsistent rules riftc accepted\n" << missed.str();
  std::cout << pack << ": " << accepted.size() << " of " << good.size()
            << " consistent rules accepted by riftc, " << caught.size() << " of " << wrong.size()
            << " inconsistent rules rejected\n";
  return 0;
}
