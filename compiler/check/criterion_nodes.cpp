#include "check/criterion_nodes.hpp"

#include <cstdlib>
#include <string>
#include <vector>

namespace rift::check {

namespace {

bool commute(int i, int j) {
  return std::abs(i - j) >= 2;
}

/// The links of `word` in the normal form of the group the alpha_i generate
/// (a right-angled Coxeter group: alpha_i^2 = 1, and alpha_i alpha_j =
/// alpha_j alpha_i when |i - j| >= 2). Two words reach the same dart from the
/// same start on every G-map iff their normal forms are equal: a word is
/// reduced once no letter meets an equal one across letters it commutes with
/// (Tits), and reduced words of one element differ by commutations only, of
/// which the lexicographically least is taken.
std::vector<int> normal_form(std::vector<int> word) {
  for (bool cancelled = true; cancelled;) {
    cancelled = false;
    for (std::size_t i = 0; i < word.size() && !cancelled; ++i) {
      for (std::size_t j = i + 1; j < word.size(); ++j) {
        if (word[j] == word[i]) {
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(j));
          word.erase(word.begin() + static_cast<std::ptrdiff_t>(i));
          cancelled = true;
          break;
        }
        if (!commute(word[j], word[i])) break;
      }
    }
  }
  std::vector<int> out;
  while (!word.empty()) {
    // The least letter that commutes with every letter before it comes first.
    std::size_t best = 0;
    for (std::size_t p = 1; p < word.size(); ++p) {
      bool movable = true;
      for (std::size_t q = 0; q < p && movable; ++q)
        movable = commute(word[q], word[p]);
      if (movable && word[p] < word[best]) best = p;
    }
    out.push_back(word[best]);
    word.erase(word.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return out;
}

std::string path_text(const std::string& from, const std::vector<int>& hops) {
  std::string s = from;
  for (int h : hops) {
    s.push_back('@');
    s.append(std::to_string(h));
  }
  return s;
}

void check_criterion(const ast::Criterion& crit, int dimension, diag::Diagnostics& diags) {
  // Each node's path from the criterion's dart, and its normal form.
  std::vector<std::string> names = {crit.dart.text};
  std::vector<std::vector<int>> words = {{}};
  std::vector<std::vector<int>> forms = {{}};
  for (const ast::CriterionNode& n : crit.nodes) {
    bool in_range = true;
    for (int h : n.hops) {
      if (h >= 0 && h <= dimension) continue;
      in_range = false;
      diags.error(n.path_loc, "link dimension " + std::to_string(h) + " is out of range 0.." +
                                  std::to_string(dimension));
    }
    std::size_t from = names.size();
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (names[k] == n.from.text) from = k;
    }
    if (from == names.size() || !in_range || n.hops.empty()) return;  // reported already
    std::vector<int> word = words[from];
    word.insert(word.end(), n.hops.begin(), n.hops.end());
    std::vector<int> form = normal_form(word);
    for (std::size_t k = 0; k < forms.size(); ++k) {
      if (forms[k] != form) continue;
      diags
          .error(n.path_loc, "node '" + n.name.text + "' is always the dart '" + names[k] + "' (" +
                                 path_text(crit.dart.text, word) + " is " +
                                 path_text(crit.dart.text, form) +
                                 "): the nodes of a criterion are distinct darts, so it would "
                                 "never hold")
          .notes.push_back({k == 0 ? crit.dart.loc : crit.nodes[k - 1].name.loc,
                            "'" + names[k] + "' declared here"});
      break;
    }
    names.push_back(n.name.text);
    words.push_back(std::move(word));
    forms.push_back(std::move(form));
  }
}

}  // namespace

void check_criterion_nodes(const ast::Program& program, diag::Diagnostics& diags) {
  for (const ast::File& file : program.files) {
    for (const ast::Criterion& crit : file.criteria)
      check_criterion(crit, program.dimension, diags);
  }
}

}  // namespace rift::check
